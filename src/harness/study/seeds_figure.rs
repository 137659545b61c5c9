//! `seeds.png`: the cell means of many seeds in one figure — one panel per
//! task, a bar per technique × feedback at the mean over seeds, and a dot per
//! seed at that seed's cell mean, so the spread between independent studies
//! shows next to the effect sizes.

use super::design::StudyDesign;
use super::error::StudyError;
use super::figure::{HEIGHT, bar_span, draw_legend, ensure_font, feedback_style, figure_width, page, task_chart};
use super::summary::SummaryRow;
use plotters::coord::Shift;
use plotters::prelude::*;
use std::path::Path;

/// Opacity of the bars, so the dots over them show.
const BAR_ALPHA: f64 = 0.55;

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
    let title = format!("Cell means of {} seeds (bars: their mean; dots: one seed each)", per_seed.len());
    let (panels, legend) = page(root, &title, design.tasks.len(), 52)?;
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
                    .draw_series(std::iter::once(Rectangle::new(
                        [(x0, 0.0), (x1, mean)],
                        color.mix(BAR_ALPHA).filled(),
                    )))
                    .map_err(e)?;
                let xc = f64::midpoint(x0, x1);
                chart.draw_series(values.iter().map(|&v| Circle::new((xc, v), 4, BLACK.filled()))).map_err(e)?;
            }
        }
    }
    draw_legend(&legend, levels, BAR_ALPHA, false)?;
    root.present().map_err(e)
}
