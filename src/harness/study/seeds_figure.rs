//! `seeds.png`: the cell means of many seeds in one figure — one panel per
//! task, a bar per technique × feedback at the mean over seeds, and a dot per
//! seed at that seed's cell mean, so the spread between independent studies
//! shows next to the effect sizes.

use super::design::StudyDesign;
use super::error::StudyError;
use super::figure::{HEIGHT, TEXT_SIZE, TITLE_SIZE, bar_span, ensure_font, feedback_style, figure_width, task_chart};
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
        let mut chart = task_chart(panel, task, techniques, y_max)?;
        for (ti, &technique) in techniques.iter().enumerate() {
            for (li, &fb) in levels.iter().enumerate() {
                let values = means(technique, fb);
                if values.is_empty() {
                    continue;
                }
                let mean = values.iter().sum::<f64>() / values.len() as f64;
                let (x0, x1) = bar_span(ti, li, levels.len());
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
