//! `seeds.png`: the cell means of many seeds in one figure — one panel per
//! task, a bar per technique × feedback at the mean over seeds, and a dot per
//! seed at that seed's cell mean, so the spread between independent studies
//! shows next to the effect sizes.

use super::design::StudyDesign;
use super::error::StudyError;
use super::figure::{
    CAPTION_SIZE, CategoryAxis, HEIGHT, TEXT_SIZE, TITLE_SIZE, capitalized, ensure_font, feedback_style, figure_width,
};
use super::summary::SummaryRow;
use crate::harness::plot_font::FONT;
use plotters::coord::Shift;
use plotters::prelude::*;
use std::path::Path;

/// Draws the figure for the per-seed summaries of one design.
pub fn write_seeds_figure(design: &StudyDesign, per_seed: &[Vec<SummaryRow>], png: &Path) -> Result<(), StudyError> {
    ensure_font(png)?;
    let size = (figure_width(design.tasks.len()), HEIGHT);
    let bytes = crate::harness::plot_png::png_bytes(size, |area| draw(area, design, per_seed))
        .map_err(|message| StudyError::Plot { path: png.to_owned(), message })?;
    super::output::write_atomically(png, &bytes)
}

fn draw<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    design: &StudyDesign,
    per_seed: &[Vec<SummaryRow>],
) -> Result<(), String> {
    let e = |e: DrawingAreaErrorKind<DB::ErrorType>| e.to_string();
    root.fill(&WHITE).map_err(e)?;
    let title = format!("Cell means of {} seeds (bars: their mean; dots: one seed each)", per_seed.len());
    let root = root.titled(&title, (FONT, TITLE_SIZE)).map_err(e)?;
    let (_, height) = root.dim_in_pixel();
    let (plots, legend) = root.split_vertically(height.saturating_sub(52));
    let panels = plots.split_evenly((1, design.tasks.len().max(1)));
    let techniques = &design.techniques;
    let levels = &design.feedback;
    let group_width = 0.76;
    let bar_width = group_width / levels.len().max(1) as f64;
    for (panel, task) in panels.iter().zip(&design.tasks) {
        let means = |t, fb| -> Vec<f64> {
            per_seed
                .iter()
                .filter_map(|rows| rows.iter().find(|r| r.task == *task && r.technique == t && r.feedback == fb))
                .filter_map(|r| r.mean_s)
                .collect()
        };
        let top =
            techniques.iter().flat_map(|&t| levels.iter().flat_map(move |&fb| means(t, fb))).fold(0.0f64, f64::max);
        let y_max = if top > 0.0 { top * 1.1 } else { 1.0 };
        let n = techniques.len();
        let mut chart = ChartBuilder::on(panel)
            .caption(capitalized(task), (FONT, CAPTION_SIZE))
            .margin(12)
            .x_label_area_size(60)
            .y_label_area_size(78)
            .build_cartesian_2d(CategoryAxis { n }, 0.0..y_max)
            .map_err(e)?;
        let label = |x: &f64| {
            let i = x.round();
            if (x - i).abs() < 1e-6 && i >= 0.0 && (i as usize) < n {
                techniques[i as usize].label().to_owned()
            } else {
                String::new()
            }
        };
        chart
            .configure_mesh()
            .disable_x_mesh()
            .light_line_style(WHITE)
            .bold_line_style(BLACK.mix(0.12))
            .x_labels(n)
            .x_label_formatter(&label)
            .y_label_formatter(&|y| format!("{y:.0}"))
            .x_desc("Technique")
            .y_desc("Completion time (s)")
            .label_style((FONT, TEXT_SIZE))
            .axis_desc_style((FONT, TEXT_SIZE))
            .draw()
            .map_err(e)?;
        for (ti, &technique) in techniques.iter().enumerate() {
            for (li, &fb) in levels.iter().enumerate() {
                let values = means(technique, fb);
                if values.is_empty() {
                    continue;
                }
                let mean = values.iter().sum::<f64>() / values.len() as f64;
                let x0 = ti as f64 - group_width / 2.0 + li as f64 * bar_width;
                let (x0, x1) = (x0 + 0.02, x0 + bar_width - 0.02);
                let (color, _) = feedback_style(fb);
                chart
                    .draw_series(std::iter::once(Rectangle::new([(x0, 0.0), (x1, mean)], color.mix(0.55).filled())))
                    .map_err(e)?;
                let xc = f64::midpoint(x0, x1);
                chart.draw_series(values.iter().map(|&v| Circle::new((xc, v), 4, BLACK.filled()))).map_err(e)?;
            }
        }
    }
    let (width, _) = legend.dim_in_pixel();
    let entry_width = 240i32;
    let mut x = (width as i32 - entry_width * levels.len() as i32) / 2;
    for &fb in levels {
        let (color, text) = feedback_style(fb);
        legend.draw(&Rectangle::new([(x, 12), (x + 22, 34)], color.mix(0.55).filled())).map_err(e)?;
        legend.draw(&Text::new(text, (x + 30, 14), (FONT, TEXT_SIZE))).map_err(e)?;
        x += entry_width;
    }
    root.present().map_err(e)
}
