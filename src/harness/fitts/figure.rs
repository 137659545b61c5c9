//! `fitts.png`: movement time against the index of difficulty, one dot per
//! condition mean, with the fitted line.

use super::FittsRow;
use super::fit::{FittsFit, condition_means};
use crate::harness::plot_font::FONT;
use plotters::prelude::*;

/// The PNG bytes of the plot.
pub fn png(rows: &[FittsRow], fit: &FittsFit, technique: &str) -> Result<Vec<u8>, String> {
    if !crate::harness::plot_font::ensure_font() {
        return Err("the plot font could not be registered".into());
    }
    let means = condition_means(rows);
    let x_max = means.iter().map(|m| m.2).fold(1.0f64, f64::max) * 1.1;
    let y_max = means.iter().map(|m| m.3).fold(0.5f64, f64::max) * 1.15;
    crate::harness::plot_png::png_bytes((800, 560), |root| {
        root.fill(&WHITE).map_err(|e| e.to_string())?;
        let title = format!(
            "Drag movement time, {technique}: MT = {:.2} + {:.2} ID s, R² = {:.2}, TP = {:.2} bits/s",
            fit.a_s, fit.b_s_per_bit, fit.r2, fit.throughput_bits_s
        );
        let mut chart = ChartBuilder::on(root)
            .caption(title, (FONT, 22))
            .margin(16)
            .x_label_area_size(44)
            .y_label_area_size(56)
            .build_cartesian_2d(0.0..x_max, 0.0..y_max)
            .map_err(|e| e.to_string())?;
        chart
            .configure_mesh()
            .x_desc("index of difficulty, log2(D/W + 1) (bits)")
            .y_desc("movement time (s)")
            .label_style((FONT, 16))
            .axis_desc_style((FONT, 18))
            .draw()
            .map_err(|e| e.to_string())?;
        chart
            .draw_series(means.iter().map(|m| Circle::new((m.2, m.3), 5, BLUE.filled())))
            .map_err(|e| e.to_string())?;
        chart
            .draw_series(LineSeries::new([0.0, x_max].map(|x| (x, fit.a_s + fit.b_s_per_bit * x)), RED.stroke_width(2)))
            .map_err(|e| e.to_string())?;
        Ok(())
    })
}
