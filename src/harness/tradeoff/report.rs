//! Runs every sweep and writes `tradeoff.csv`, one plot per knob
//! (`<knob>.png`: time against error, the Pareto front joined, the default
//! ringed) and `tradeoff.md`, which says for each knob whether its default
//! sits on the front.

use super::pareto::{Point, pareto_front};
use super::row::Row;
use super::{geometry, pipeline};
use crate::harness::csv_file::write_csv;
use crate::harness::plot_font::{FONT, ensure_font};
use crate::input::Gesture;
use anyhow::Context;
use indicatif::{ProgressBar, ProgressStyle};
use plotters::coord::Shift;
use plotters::prelude::*;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

#[derive(Debug, Clone)]
pub struct TradeoffOptions {
    pub out: PathBuf,
    /// Fewer values and repeats: under two minutes here.
    pub quick: bool,
    pub progress: bool,
}

/// Runs the whole report.
pub fn run_tradeoff(options: &TradeoffOptions) -> anyhow::Result<Vec<Row>> {
    std::fs::create_dir_all(&options.out).with_context(|| format!("creating {}", options.out.display()))?;
    let gesture_path = Path::new(env!("CARGO_MANIFEST_DIR")).join(pipeline::FIXTURE_GESTURE);
    let gesture = Gesture::load(&gesture_path)?;
    let knobs = pipeline::knobs(options.quick)?;
    let total = knobs.iter().map(|k| k.values.len()).sum::<usize>() + 2;
    let bar = if options.progress { ProgressBar::new(total as u64) } else { ProgressBar::hidden() };
    bar.set_style(
        ProgressStyle::with_template("{bar:40} {pos}/{len} {msg} (eta {eta})")
            .unwrap_or_else(|_| ProgressStyle::default_bar()),
    );
    let repeats = if options.quick { 1 } else { 3 };
    let mut rows = Vec::new();
    for knob in &knobs {
        bar.set_message(knob.name);
        rows.extend(pipeline::measure(knob, &gesture, repeats, || bar.inc(1))?);
    }
    bar.set_message("circle_segments");
    rows.extend(geometry::circle_segments(options.quick));
    bar.inc(1);
    bar.set_message("contact_method");
    rows.extend(geometry::contact_methods(options.quick));
    bar.inc(1);
    bar.finish_and_clear();

    mark_fronts(&mut rows);
    write_csv(&options.out.join("tradeoff.csv"), &rows)?;
    for knob in knob_names(&rows) {
        let of: Vec<&Row> = rows.iter().filter(|r| r.knob == knob).collect();
        plot(&options.out.join(format!("{knob}.png")), &knob, &of)?;
    }
    crate::files::write_output(&options.out.join("tradeoff.md"), summary(&rows).as_bytes())
        .context("writing tradeoff.md")?;
    Ok(rows)
}

fn knob_names(rows: &[Row]) -> Vec<String> {
    let mut names: Vec<String> = Vec::new();
    for r in rows {
        if !names.contains(&r.knob) {
            names.push(r.knob.clone());
        }
    }
    names
}

/// Sets `on_front` per knob. The contact methods are compared per size.
fn mark_fronts(rows: &mut [Row]) {
    let groups: Vec<String> = rows.iter().map(group_of).collect();
    let mut seen: Vec<&String> = Vec::new();
    for g in &groups {
        if seen.contains(&g) {
            continue;
        }
        seen.push(g);
        let idx: Vec<usize> = (0..rows.len()).filter(|&i| &groups[i] == g).collect();
        let pts: Vec<Point> = idx
            .iter()
            .map(|&i| Point { label: rows[i].value.clone(), time: rows[i].time, error: rows[i].error })
            .collect();
        for k in pareto_front(&pts) {
            rows[idx[k]].on_front = true;
        }
    }
}

fn group_of(r: &Row) -> String {
    match r.value.split_once(" n=") {
        Some((_, n)) if r.knob == "contact_method" => format!("{} n={n}", r.knob),
        _ => r.knob.clone(),
    }
}

/// The Markdown table of docs/performance.md: what each knob costs and buys.
pub fn summary(rows: &[Row]) -> String {
    let mut s = String::from("| knob | value | time | error | on front |\n|---|---|---|---|---|\n");
    for r in rows {
        let mark = if r.default { " (default)" } else { "" };
        let _ = writeln!(
            s,
            "| {} | {}{} | {:.1} {} | {:.4} {} | {} |",
            r.knob,
            r.value,
            mark,
            r.time,
            r.time_unit,
            r.error,
            r.error_unit,
            if r.on_front { "yes" } else { "no" }
        );
    }
    s.push_str("\nDefaults off their front:\n");
    let off: Vec<&Row> = rows.iter().filter(|r| r.default && !r.on_front).collect();
    if off.is_empty() {
        s.push_str("- none\n");
    }
    for r in off {
        let _ = writeln!(s, "- {} = {}", r.knob, r.value);
    }
    s
}

fn plot(path: &Path, knob: &str, rows: &[&Row]) -> anyhow::Result<()> {
    anyhow::ensure!(ensure_font(), "the bundled plot font did not load");
    let png = crate::harness::plot_png::png_bytes((900, 640), |area| draw(area, knob, rows))
        .map_err(|m| anyhow::anyhow!("plotting {}: {m}", path.display()))?;
    crate::files::write_output(path, &png).with_context(|| format!("writing {}", path.display()))
}

fn draw<DB: DrawingBackend>(area: &DrawingArea<DB, Shift>, knob: &str, rows: &[&Row]) -> Result<(), String> {
    let e = |e: DrawingAreaErrorKind<DB::ErrorType>| e.to_string();
    area.fill(&WHITE).map_err(e)?;
    let (tmin, tmax) = rows.iter().fold((f64::MAX, f64::MIN), |(a, b), r| (a.min(r.time), b.max(r.time)));
    let (emin, emax) = rows.iter().fold((f64::MAX, f64::MIN), |(a, b), r| (a.min(r.error), b.max(r.error)));
    let pad = |lo: f64, hi: f64| {
        let d = (hi - lo).abs().max(hi.abs() * 0.1).max(1e-12);
        (lo - d * 0.1, hi + d * 0.15)
    };
    let (x0, x1) = pad(tmin, tmax);
    let (y0, y1) = pad(emin.min(0.0), emax);
    let unit_t = rows.first().map_or("", |r| r.time_unit.as_str());
    let unit_e = rows.first().map_or("", |r| r.error_unit.as_str());
    let mut chart = ChartBuilder::on(area)
        .caption(format!("{knob}: time against error"), (FONT, 30))
        .margin(20)
        .x_label_area_size(55)
        .y_label_area_size(90)
        .build_cartesian_2d(x0..x1, y0..y1)
        .map_err(e)?;
    chart
        .configure_mesh()
        .x_desc(format!("time ({unit_t})"))
        .y_desc(format!("error ({unit_e}), against {}", rows.first().map_or("", |r| r.reference.as_str())))
        .label_style((FONT, 20))
        .axis_desc_style((FONT, 22))
        .draw()
        .map_err(e)?;
    let mut front: Vec<&&Row> = rows.iter().filter(|r| r.on_front).collect();
    front.sort_by(|a, b| a.time.total_cmp(&b.time));
    chart
        .draw_series(LineSeries::new(
            front.iter().map(|r| (r.time, r.error)),
            ShapeStyle::from(&RGBColor(31, 119, 180)).stroke_width(3),
        ))
        .map_err(e)?;
    for r in rows {
        let color = if r.on_front { RGBColor(31, 119, 180) } else { RGBColor(150, 150, 150) };
        chart.draw_series(std::iter::once(Circle::new((r.time, r.error), 7, color.filled()))).map_err(e)?;
        if r.default {
            chart
                .draw_series(std::iter::once(Circle::new(
                    (r.time, r.error),
                    14,
                    ShapeStyle::from(&RGBColor(214, 39, 40)).stroke_width(3),
                )))
                .map_err(e)?;
        }
        let label = if r.default { format!("{} (default)", r.value) } else { r.value.clone() };
        chart.draw_series(std::iter::once(Text::new(label, (r.time, r.error), (FONT, 20).into_font()))).map_err(e)?;
    }
    Ok(())
}
