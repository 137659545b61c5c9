//! The paper's Figure 9 redrawn from `summary.csv`: completion time, one
//! panel per task, bars grouped by technique, feedback on and off side by
//! side in two colours, whiskers for the within-subject (Cousineau–Morey)
//! 95% CI — the interval that matches the repeated-measures tests; the
//! between-subject one stays in `summary.csv`.
//!
//! A cell with failed trials (time limit or runner failure) gets its count
//! over the bar in red: a timed-out trial enters at the time limit, so
//! that bar's mean is a lower bound, which the note under the panels says.
//!
//! Each panel has its own time axis (steering takes far longer than the
//! others; a shared axis would flatten the other two). Conditions with no
//! timed trial get no bar; conditions with one participant get no whisker;
//! a whisker reaching below zero is cut at zero (times are positive).
//!
//! Text needs a font: plotters' `ab_glyph` backend only knows registered
//! fonts, so "sans-serif" is bound to Ubuntu Light, which ships with egui
//! (crate `epaint_default_fonts`) and so costs no extra file.

use super::design::StudyDesign;
use super::error::StudyError;
use super::summary::SummaryRow;
use crate::pipeline::technique::TechniqueKind;
use plotters::coord::Shift;
use plotters::coord::ranged1d::{DefaultFormatting, KeyPointHint, Ranged};
use plotters::coord::types::RangedCoordf64;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};
use std::path::Path;

/// Colour of the bars with visual feedback ("FB" in the paper's figure).
const FEEDBACK_ON: RGBColor = RGBColor(31, 119, 180);
const FEEDBACK_OFF: RGBColor = RGBColor(255, 127, 14);
/// Colour of the failure counts over the bars.
const FAILED: RGBColor = RGBColor(200, 20, 20);
use crate::harness::plot_font::FONT;
use crate::harness::plot_png;
pub(super) const PANEL_WIDTH: u32 = 440;
pub(super) const HEIGHT: u32 = 600;
/// The title and the failure note at their sizes need about 880 px.
const MIN_WIDTH: u32 = 900;
// Text sizes. plotters' ab_glyph renderer drops each glyph's left side
// bearing, which makes small text look badly kerned ("Partide"); at 20 px
// and up Ubuntu Light reads cleanly.
pub(super) const TITLE_SIZE: u32 = 30;
pub(super) const CAPTION_SIZE: u32 = 26;
pub(super) const TEXT_SIZE: u32 = 21;

/// Writes the figure as PNG and SVG.
pub fn write_figure(design: &StudyDesign, summary: &[SummaryRow], png: &Path, svg: &Path) -> Result<(), StudyError> {
    ensure_font(png)?;
    let size = (figure_width(design.tasks.len()), HEIGHT);
    let plot_err = |path: &Path| {
        let path = path.to_owned();
        move |message: String| StudyError::Plot { path, message }
    };
    let png_bytes = plot_png::png_bytes(size, |area| draw(area, design, summary)).map_err(plot_err(png))?;
    let svg_text = plot_png::svg_text(size, |area| draw(area, design, summary)).map_err(plot_err(svg))?;
    super::output::write_atomically(png, &png_bytes)?;
    super::output::write_atomically(svg, svg_text.as_bytes())
}

/// One panel per task, but never narrower than the title and the note need.
pub(super) fn figure_width(tasks: usize) -> u32 {
    (PANEL_WIDTH * tasks.max(1) as u32).max(MIN_WIDTH)
}

pub(super) fn ensure_font(path: &Path) -> Result<(), StudyError> {
    if crate::harness::plot_font::ensure_font() {
        Ok(())
    } else {
        Err(StudyError::Plot { path: path.to_owned(), message: "the bundled font did not load".into() })
    }
}

/// `sorting` → `Sorting`, for panel captions.
pub(super) fn capitalized(s: &str) -> String {
    let mut chars = s.chars();
    chars.next().map(|c| c.to_uppercase().chain(chars).collect()).unwrap_or_default()
}

pub(super) fn feedback_style(on: bool) -> (RGBColor, &'static str) {
    if on { (FEEDBACK_ON, "Feedback on (FB)") } else { (FEEDBACK_OFF, "Feedback off") }
}

fn draw<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    design: &StudyDesign,
    summary: &[SummaryRow],
) -> Result<(), String> {
    let e = |e: DrawingAreaErrorKind<DB::ErrorType>| e.to_string();
    let title = "Completion time: mean, within-subject 95% CI (Cousineau-Morey)";
    let (panels, legend) = page(root, title, design.tasks.len(), 84)?;

    let techniques = &design.techniques;
    let levels = &design.feedback;

    for (panel, task) in panels.iter().zip(&design.tasks) {
        let cell = |t, fb| summary.iter().find(|r| r.task == *task && r.technique == t && r.feedback == fb);
        let top = summary
            .iter()
            .filter(|r| r.task == *task)
            .filter_map(|r| r.ci95_within_high_s.or(r.mean_s))
            .fold(0.0f64, f64::max);
        let y_max = if top > 0.0 { top * 1.12 } else { 1.0 };
        let mut chart = task_chart(panel, task, techniques, y_max)?;

        for (ti, &technique) in techniques.iter().enumerate() {
            for (li, &fb) in levels.iter().enumerate() {
                let Some(row) = cell(technique, fb) else { continue };
                let Some(mean) = row.mean_s else { continue };
                let (x0, x1) = bar_span(ti, li, levels.len());
                let (color, _) = feedback_style(fb);
                chart
                    .draw_series(std::iter::once(Rectangle::new([(x0, 0.0), (x1, mean)], color.filled())))
                    .map_err(e)?;
                if row.failed > 0 {
                    let style = TextStyle::from((FONT, TEXT_SIZE).into_font())
                        .color(&FAILED)
                        .pos(Pos::new(HPos::Center, VPos::Bottom));
                    let top = row.ci95_within_high_s.unwrap_or(mean).max(mean);
                    let at = (f64::midpoint(x0, x1), top + y_max * 0.01);
                    chart.draw_series(std::iter::once(Text::new(row.failed.to_string(), at, style))).map_err(e)?;
                }
                if let (Some(lo), Some(hi)) = (row.ci95_within_low_s, row.ci95_within_high_s) {
                    let xc = f64::midpoint(x0, x1);
                    let cap = (x1 - x0) * 0.25;
                    let style = BLACK.stroke_width(2);
                    let lo = lo.max(0.0);
                    let whisker = [
                        vec![(xc, lo), (xc, hi)],
                        vec![(xc - cap, lo), (xc + cap, lo)],
                        vec![(xc - cap, hi), (xc + cap, hi)],
                    ];
                    chart.draw_series(whisker.into_iter().map(|p| PathElement::new(p, style))).map_err(e)?;
                }
            }
        }
    }

    draw_legend(&legend, levels, 1.0, summary.iter().any(|r| r.failed > 0))?;
    root.present().map_err(e)
}

/// A part of a figure's drawing.
type Area<DB> = DrawingArea<DB, Shift>;

/// What both this figure and `seeds.png` draw on: a white page titled
/// `title`, a panel per task side by side, and under them a strip
/// `legend_height` pixels high for the legend.
pub(super) fn page<DB: DrawingBackend>(
    root: &Area<DB>,
    title: &str,
    tasks: usize,
    legend_height: u32,
) -> Result<(Vec<Area<DB>>, Area<DB>), String> {
    let e = |e: DrawingAreaErrorKind<DB::ErrorType>| e.to_string();
    root.fill(&WHITE).map_err(e)?;
    let root = root.titled(title, (FONT, TITLE_SIZE)).map_err(e)?;
    let (_, height) = root.dim_in_pixel();
    let (plots, legend) = root.split_vertically(height.saturating_sub(legend_height));
    Ok((plots.split_evenly((1, tasks.max(1))), legend))
}

/// Width of a technique's group of bars, in categories.
const GROUP_WIDTH: f64 = 0.76;

/// A task's panel, with its caption, the techniques along x and completion
/// time from 0 to `y_max` along y: what both this figure and `seeds.png`
/// draw their bars on.
pub(super) fn task_chart<'a, DB: DrawingBackend>(
    panel: &'a DrawingArea<DB, Shift>,
    task: &str,
    techniques: &'a [TechniqueKind],
    y_max: f64,
) -> Result<ChartContext<'a, DB, Cartesian2d<CategoryAxis, RangedCoordf64>>, String> {
    let e = |e: DrawingAreaErrorKind<DB::ErrorType>| e.to_string();
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
    Ok(chart)
}

/// The x range of the bar for technique `ti` and feedback level `li` of
/// `levels`: the group centred on the technique, a small gap either side.
pub(super) fn bar_span(ti: usize, li: usize, levels: usize) -> (f64, f64) {
    let bar_width = GROUP_WIDTH / levels.max(1) as f64;
    let x0 = ti as f64 - GROUP_WIDTH / 2.0 + li as f64 * bar_width;
    (x0 + 0.02, x0 + bar_width - 0.02)
}

/// One legend for all panels, centred under them, its swatches at the
/// bars' opacity `alpha`; a note in red when some trials failed.
pub(super) fn draw_legend<DB: DrawingBackend>(
    legend: &DrawingArea<DB, Shift>,
    levels: &[bool],
    alpha: f64,
    any_failed: bool,
) -> Result<(), String> {
    let e = |e: DrawingAreaErrorKind<DB::ErrorType>| e.to_string();
    let (width, _) = legend.dim_in_pixel();
    let entry_width = 240i32;
    let mut x = (width as i32 - entry_width * levels.len() as i32) / 2;
    for &fb in levels {
        let (color, text) = feedback_style(fb);
        legend.draw(&Rectangle::new([(x, 12), (x + 22, 34)], color.mix(alpha).filled())).map_err(e)?;
        legend.draw(&Text::new(text, (x + 30, 14), (FONT, TEXT_SIZE))).map_err(e)?;
        x += entry_width;
    }
    if any_failed {
        let note = "Red: failed trials, counted at the time limit (so those means are lower bounds)";
        let (w, _) = legend.dim_in_pixel();
        let style =
            TextStyle::from((FONT, TEXT_SIZE).into_font()).color(&FAILED).pos(Pos::new(HPos::Center, VPos::Top));
        legend.draw(&Text::new(note, (w as i32 / 2, 46), style)).map_err(e)?;
    }
    Ok(())
}

/// A categorical x axis for bar groups: category `i` is centred on `i` over
/// `-0.5..n-0.5`, ticks and labels at the centres only (plotters' f64 axis
/// would put ticks at "nice" numbers, not at the categories).
pub(super) struct CategoryAxis {
    pub(super) n: usize,
}

impl Ranged for CategoryAxis {
    type FormatOption = DefaultFormatting;
    type ValueType = f64;

    fn map(&self, value: &f64, limit: (i32, i32)) -> i32 {
        let r = self.range();
        let t = (value - r.start) / (r.end - r.start);
        limit.0 + (t * f64::from(limit.1 - limit.0)).round() as i32
    }

    fn key_points<Hint: KeyPointHint>(&self, _hint: Hint) -> Vec<f64> {
        (0..self.n).map(|i| i as f64).collect()
    }

    fn range(&self) -> std::ops::Range<f64> {
        -0.5..self.n.max(1) as f64 - 0.5
    }
}
