//! `surfacelab bench`: every curve measured, then `scaling.csv`,
//! `scaling.md` and `scaling.png` written to the output folder.

use super::curve::{Curve, ScalingRow};
use super::frame::Workload;
use super::participants::{TRIAL_LIMIT_S, measure_study};
use super::plot;
use crate::contact::log_log_slope;
use crate::harness::csv_file::write_csv;
use anyhow::Context;
use std::fmt::Write as _;
use std::path::PathBuf;

/// What `surfacelab bench` measures and where it writes.
#[derive(Debug, Clone)]
pub struct BenchOptions {
    pub out: PathBuf,
    /// Fewer frames per point and no 10,000-object point.
    pub quick: bool,
    /// The participants curve's points; empty leaves the curve out.
    pub participants: Vec<u32>,
    /// Print each point to standard error as it is measured.
    pub progress: bool,
    /// Measure this one frame point alone (for a profiler), no study.
    pub point: Option<(Curve, f64)>,
}

/// One curve's fit: its log-log slope and what costs most at its large end.
#[derive(Debug, Clone, PartialEq)]
pub struct CurveSummary {
    pub curve: Curve,
    pub slope: Option<f64>,
    pub largest_x: f64,
    /// The dominant frame stage at the largest point and its share of the frame.
    pub dominant: Option<(&'static str, f64)>,
}

/// The points of each frame curve.
fn frame_points(curve: Curve, quick: bool) -> &'static [f64] {
    match (curve, quick) {
        (Curve::Hands, _) => &[1.0, 2.0, 4.0, 8.0],
        (Curve::Objects, false) => &[10.0, 100.0, 1000.0, 10_000.0],
        (Curve::Objects, true) => &[10.0, 100.0, 1000.0],
        (Curve::RateHz, _) => &[60.0, 120.0, 240.0],
        (Curve::ImageSide, _) => &[256.0, 512.0, 768.0, 1024.0],
        (Curve::Participants, _) => &[],
    }
}

/// Measures every curve and writes the three files.
pub fn run_bench(options: &BenchOptions) -> anyhow::Result<(Vec<ScalingRow>, Vec<CurveSummary>)> {
    std::fs::create_dir_all(&options.out).with_context(|| format!("creating {}", options.out.display()))?;
    let (warmup, frames) = if options.quick { (10, 40) } else { (30, 150) };
    let mut rows = Vec::new();
    let points: Vec<(Curve, f64)> = match options.point {
        Some(point) => vec![point],
        None => [Curve::Hands, Curve::Objects, Curve::RateHz, Curve::ImageSide]
            .into_iter()
            .flat_map(|c| frame_points(c, options.quick).iter().map(move |&x| (c, x)))
            .collect(),
    };
    {
        for (curve, x) in points {
            let m =
                Workload::at(curve, x)?.measure(warmup, frames).with_context(|| format!("{} = {x}", curve.name()))?;
            let row = ScalingRow::frame(curve, x, m);
            if options.progress {
                eprintln!("surfacelab bench: {} = {x}: {:.0} µs a frame", curve.name(), row.total_us.unwrap_or(0.0));
            }
            rows.push(row);
        }
    }
    let exe = std::env::current_exe().context("finding this program to run the studies")?;
    let studies = if options.point.is_some() { &[][..] } else { &options.participants[..] };
    for &n in studies {
        let (wall, peak) = measure_study(&exe, n, &options.out)?;
        if options.progress {
            eprintln!("surfacelab bench: participants = {n}: {wall:.1} s, peak {peak:.1} MB");
        }
        rows.push(ScalingRow::study(f64::from(n), wall, peak));
    }
    let summaries = summarize(&rows);
    write_csv(&options.out.join("scaling.csv"), &rows)?;
    let md = markdown(&rows, &summaries);
    crate::files::write_output(&options.out.join("scaling.md"), md.as_bytes())
        .with_context(|| format!("writing {}", options.out.join("scaling.md").display()))?;
    let png = plot::png(&rows).map_err(|e| anyhow::anyhow!("drawing scaling.png: {e}"))?;
    let path = options.out.join("scaling.png");
    crate::files::write_output(&path, &png).with_context(|| format!("writing {}", path.display()))?;
    Ok((rows, summaries))
}

/// Each measured curve's slope and the dominant stage at its largest point.
pub fn summarize(rows: &[ScalingRow]) -> Vec<CurveSummary> {
    Curve::ALL
        .into_iter()
        .filter_map(|curve| {
            let mine: Vec<&ScalingRow> = rows.iter().filter(|r| r.curve == curve).collect();
            let largest = mine.iter().max_by(|a, b| a.x.total_cmp(&b.x))?;
            Some(CurveSummary {
                curve,
                slope: log_log_slope(&mine.iter().filter_map(|r| Some((r.x, r.cost()?))).collect::<Vec<_>>()),
                largest_x: largest.x,
                dominant: largest.dominant_stage(),
            })
        })
        .collect()
}

fn opt(v: Option<f64>, digits: usize) -> String {
    v.map_or_else(String::new, |v| format!("{v:.digits$}"))
}

/// The tables of `scaling.md`: every point, then each curve's slope.
pub fn markdown(rows: &[ScalingRow], summaries: &[CurveSummary]) -> String {
    let mut s = String::from(
        "| curve | x | contact px | technique bodies | rasterize µs | vision µs | technique µs | step µs | total µs | wall s | peak MB |\n|---|---|---|---|---|---|---|---|---|---|---|\n",
    );
    for r in rows {
        let _ = writeln!(
            s,
            "| {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |",
            r.curve.name(),
            r.x,
            opt(r.contact_pixels, 0),
            opt(r.technique_bodies, 0),
            opt(r.rasterize_us, 0),
            opt(r.vision_us, 0),
            opt(r.technique_us, 0),
            opt(r.step_us, 0),
            opt(r.total_us, 0),
            opt(r.wall_s, 1),
            opt(r.peak_rss_mb, 1),
        );
    }
    s.push_str("\n| curve | cost | log-log slope | at the largest x | dominant stage there |\n|---|---|---|---|---|\n");
    for c in summaries {
        let dominant = c.dominant.map_or_else(
            || if c.curve == Curve::Participants { "trials (one process)".to_string() } else { String::new() },
            |(stage, share)| format!("{stage} ({:.0}%)", 100.0 * share),
        );
        let _ = writeln!(
            s,
            "| {} | {} | {} | {} | {} |",
            c.curve.name(),
            c.curve.cost(),
            opt(c.slope, 2),
            c.largest_x,
            dominant
        );
    }
    if summaries.iter().any(|c| c.curve == Curve::Participants) {
        let _ = writeln!(s, "\nStudies run on one worker with a {TRIAL_LIMIT_S} s limit per trial.");
    }
    s
}
