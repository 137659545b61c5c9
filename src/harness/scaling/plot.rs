//! `scaling.png`: one log-log panel per curve, the frame's stages and its
//! total (or the study's wall time) against what the curve varies. On
//! log-log axes a power law is a straight line whose slope is its exponent.

use super::curve::{Curve, ScalingRow};
use crate::contact::log_log_slope;
use crate::harness::plot_font::{FONT, ensure_font};
use plotters::coord::Shift;
use plotters::prelude::*;

type Series = (&'static str, RGBColor, fn(&ScalingRow) -> Option<f64>);

const SERIES: [Series; 6] = [
    ("total", RGBColor(0, 0, 0), |r| r.total_us),
    ("rasterize", RGBColor(31, 119, 180), |r| r.rasterize_us),
    ("vision", RGBColor(255, 127, 14), |r| r.vision_us),
    ("technique", RGBColor(44, 160, 44), |r| r.technique_us),
    ("step", RGBColor(214, 39, 40), |r| r.step_us),
    ("study wall time", RGBColor(0, 0, 0), |r| r.wall_s),
];

/// The PNG bytes of the figure.
pub fn png(rows: &[ScalingRow]) -> Result<Vec<u8>, String> {
    if !ensure_font() {
        return Err("the plot font could not be registered".into());
    }
    let curves: Vec<Curve> = Curve::ALL.into_iter().filter(|c| rows.iter().any(|r| r.curve == *c)).collect();
    crate::harness::plot_png::png_bytes((1500, 900), |root| {
        root.fill(&WHITE).map_err(|e| e.to_string())?;
        let panels = root.split_evenly((2, 3));
        for (curve, area) in curves.iter().zip(&panels) {
            let mine: Vec<&ScalingRow> = rows.iter().filter(|r| r.curve == *curve).collect();
            panel(area, *curve, &mine)?;
        }
        Ok(())
    })
}

fn panel(area: &DrawingArea<BitMapBackend<'_>, Shift>, curve: Curve, rows: &[&ScalingRow]) -> Result<(), String> {
    let e = |e: DrawingAreaErrorKind<_>| e.to_string();
    let values: Vec<f64> =
        rows.iter().flat_map(|r| SERIES.iter().filter_map(|s| (s.2)(r))).filter(|v| *v > 0.0).collect();
    let (lo, hi) = values.iter().fold((f64::MAX, f64::MIN), |(a, b), v| (a.min(*v), b.max(*v)));
    let (x_lo, x_hi) = rows.iter().fold((f64::MAX, f64::MIN), |(a, b), r| (a.min(r.x), b.max(r.x)));
    if values.is_empty() || x_lo <= 0.0 {
        return Ok(());
    }
    let slope = log_log_slope(&rows.iter().filter_map(|r| Some((r.x, r.cost()?))).collect::<Vec<_>>());
    let title = format!("{}: slope {}", curve.name(), slope.map_or("-".to_string(), |b| format!("{b:.2}")));
    let mut chart = ChartBuilder::on(area)
        .caption(title, (FONT, 24))
        .margin(12)
        .x_label_area_size(40)
        .y_label_area_size(60)
        // Headroom above the data keeps the legend off the lines.
        .build_cartesian_2d((x_lo * 0.7..x_hi * 1.4).log_scale(), (lo * 0.5..hi * 8.0).log_scale())
        .map_err(e)?;
    chart
        .configure_mesh()
        .x_desc(curve.name())
        .y_desc(curve.cost())
        .x_labels(12)
        .x_label_formatter(&|x| format!("{x:.0}"))
        .y_label_formatter(&|y| if *y >= 10.0 { format!("{y:.0}") } else { format!("{y:.1}") })
        .label_style((FONT, 15))
        .axis_desc_style((FONT, 17))
        .draw()
        .map_err(e)?;
    for (name, color, get) in SERIES {
        let points: Vec<(f64, f64)> = rows.iter().filter_map(|r| Some((r.x, get(r)?))).filter(|p| p.1 > 0.0).collect();
        if points.is_empty() {
            continue;
        }
        let width = if name == "total" || name == "study wall time" { 3 } else { 2 };
        chart
            .draw_series(LineSeries::new(points.clone(), color.stroke_width(width)))
            .map_err(e)?
            .label(name)
            .legend(move |(x, y)| PathElement::new([(x, y), (x + 18, y)], color.stroke_width(3)));
        chart.draw_series(points.iter().map(|&p| Circle::new(p, 4, color.filled()))).map_err(e)?;
    }
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::UpperLeft)
        .label_font((FONT, 14))
        .background_style(WHITE.mix(0.8))
        .border_style(BLACK)
        .draw()
        .map_err(e)?;
    Ok(())
}
