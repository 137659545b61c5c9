//! The area right of the panel: the rendered table (a texture the 3D
//! renderer draws into each frame), the outlines of the hands on it, the
//! outline of the hand a click would put down, and banners (the scene's
//! hint, participant-mode instructions).

use super::lab::{BETWEEN_TRIALS_S, Lab};
use super::participant_mode::Phase;
use crate::pipeline::surface::{Footprint, Hand};
use crate::render::CameraMatrices;
use egui::{Color32, FontId, Pos2, Rect, Stroke, TextureId, Vec2};
use glam::Vec3;

/// Points per outline of a round shape.
const SEGMENTS: usize = 40;

/// What the view needs from the renderer for this frame.
#[derive(Debug, Clone, Copy)]
pub struct ViewFrame<'a> {
    /// The table's texture, when egui must draw it (else it is copied into
    /// the window before egui draws over it).
    pub texture: Option<TextureId>,
    /// Camera of the last prepared 3D frame, and the pixel size it was for.
    pub camera: Option<(&'a CameraMatrices, [u32; 2])>,
    /// The mouse is over the view (and not over egui): show what a click puts down.
    pub pointer_on_view: bool,
}

/// Paints the view into `rect` (points) and returns `rect`.
pub fn show(ui: &egui::Ui, rect: Rect, lab: &Lab, frame: ViewFrame<'_>) -> Rect {
    let painter = ui.painter_at(rect);
    if let Some(texture) = frame.texture {
        painter.image(texture, rect, Rect::from_min_max(Pos2::ZERO, Pos2::new(1.0, 1.0)), Color32::WHITE);
    }
    if let Some((camera, size)) = frame.camera {
        let ppp = ui.ctx().pixels_per_point();
        let project = |p: [f32; 2]| {
            camera.world_to_pixel(size, Vec3::new(p[0], p[1], 0.0)).map(|px| rect.min + Vec2::new(px.x, px.y) / ppp)
        };
        let hands = lab.input.hands(lab.session.time(), lab.table());
        // Dark lines: the tables are light.
        let solid = Stroke::new(1.5, Color32::from_rgba_unmultiplied(20, 20, 30, 200));
        for hand in &hands {
            outline_hand(&painter, hand, &project, solid);
        }
        if lab.participant.is_none()
            && frame.pointer_on_view
            && let Some(preview) = lab.input.press_preview()
        {
            let faint = Stroke::new(1.0, Color32::from_rgba_unmultiplied(20, 20, 30, 90));
            outline_hand(&painter, &preview, &project, faint);
        }
    }
    let mut banner = Vec::new();
    if let Some(trials) = &lab.participant {
        let (n, of) = trials.position();
        let condition = format!("{}, feedback {}", lab.technique(), if trials.options.feedback { "on" } else { "off" });
        match trials.phase {
            Phase::Ready => {
                banner.push(format!("Trial {n} of {of} ({condition})"));
                banner.push(lab.scene().hint.clone());
                banner.push("Touch the table to start.".into());
            }
            Phase::Running => {
                let left = f64::from(lab.scene().time_limit_s) - lab.session.time();
                banner.push(format!("Trial {n} of {of}   {}   {:.0} s left", progress_line(lab), left.max(0.0)));
            }
            Phase::Finished { completed, time_s, at } => {
                banner.push(if completed { format!("Done in {time_s:.1} s.") } else { "Time is up.".to_owned() });
                let wait = (BETWEEN_TRIALS_S - (lab.wall - at)).max(0.0);
                banner.push(if trials.done >= trials.options.repetitions {
                    "That was the last trial. Thank you!".to_owned()
                } else {
                    format!("Next trial in {wait:.0} s.")
                });
            }
            Phase::Done => banner.push("All trials done. Thank you!".into()),
        }
    } else {
        if let Some(hint) = lab.hint() {
            banner.push(hint.to_owned());
        }
        if lab.paused {
            banner.push("Paused (space resumes, N steps)".into());
        }
    }
    if !banner.is_empty() {
        draw_banner(&painter, rect, &banner);
    }
    rect
}

/// The goal's state in a few words: placed objects, waypoints, restarts.
pub fn progress_line(lab: &Lab) -> String {
    let p = lab.session.progress();
    let mut parts = Vec::new();
    if p.total > 0 {
        parts.push(format!("{}/{} placed", p.placed, p.total));
    }
    let waypoints = lab.waypoints();
    if waypoints > 0 {
        parts.push(format!("{}/{waypoints} waypoints", p.waypoints_passed));
    }
    if p.restarts > 0 {
        parts.push(format!("{} restarts", p.restarts));
    }
    if p.complete {
        parts.push("complete".into());
    }
    parts.join(", ")
}

fn draw_banner(painter: &egui::Painter, rect: Rect, lines: &[String]) {
    let font = FontId::proportional(18.0);
    let galleys: Vec<_> =
        lines.iter().map(|l| painter.layout_no_wrap(l.clone(), font.clone(), Color32::WHITE)).collect();
    let width = galleys.iter().map(|g| g.size().x).fold(0.0, f32::max) + 32.0;
    let height = galleys.iter().map(|g| g.size().y + 4.0).sum::<f32>() + 16.0;
    let bg = Rect::from_center_size(
        Pos2::new(rect.center().x, rect.top() + 16.0 + height / 2.0),
        Vec2::new(width.min(rect.width()), height),
    );
    painter.rect_filled(bg, 8.0, Color32::from_black_alpha(170));
    let mut y = bg.top() + 8.0;
    for g in galleys {
        let h = g.size().y;
        painter.galley(Pos2::new(bg.center().x - g.size().x / 2.0, y), g, Color32::WHITE);
        y += h + 4.0;
    }
}

fn outline_hand(painter: &egui::Painter, hand: &Hand, project: &impl Fn([f32; 2]) -> Option<Pos2>, stroke: Stroke) {
    // A contour hand (TUIO 2.0 shapes) is its own outline; templates are their patches'.
    let contour = hand.outline_rings().unwrap_or_default();
    for ring in hand.patches().iter().flat_map(|p| outline(&p.shape)).chain(contour) {
        let points: Option<Vec<Pos2>> = ring.into_iter().map(project).collect();
        if let Some(points) = points {
            painter.add(egui::Shape::closed_line(points, stroke));
        }
    }
}

/// Closed polylines around a footprint, table metres (a ring has two).
pub fn outline(shape: &Footprint) -> Vec<Vec<[f32; 2]>> {
    use std::f32::consts::{FRAC_PI_2, PI, TAU};
    let rot = |p: [f32; 2], angle: f32, c: [f32; 2]| {
        let (s, k) = angle.sin_cos();
        [c[0] + p[0] * k - p[1] * s, c[1] + p[0] * s + p[1] * k]
    };
    let arc = |out: &mut Vec<[f32; 2]>, c: [f32; 2], r: f32, from: f32, sweep: f32, n: usize| {
        for i in 0..=n {
            let t = from + sweep * i as f32 / n as f32;
            out.push([c[0] + r * t.cos(), c[1] + r * t.sin()]);
        }
    };
    match *shape {
        Footprint::Ellipse { centre, radii, angle } => vec![
            (0..SEGMENTS)
                .map(|i| {
                    let t = TAU * i as f32 / SEGMENTS as f32;
                    rot([radii[0] * t.cos(), radii[1] * t.sin()], angle, centre)
                })
                .collect(),
        ],
        Footprint::Capsule { a, b, radius } => {
            let d = [b[0] - a[0], b[1] - a[1]];
            let heading = if d[0].hypot(d[1]) > 1e-9 { d[1].atan2(d[0]) } else { FRAC_PI_2 };
            let mut out = Vec::with_capacity(SEGMENTS + 2);
            arc(&mut out, b, radius, heading - FRAC_PI_2, PI, SEGMENTS / 2);
            arc(&mut out, a, radius, heading + FRAC_PI_2, PI, SEGMENTS / 2);
            vec![out]
        }
        Footprint::RoundedRect { centre, half, angle, corner } => {
            let c = corner.clamp(0.0, half[0].min(half[1]));
            let inner = [half[0] - c, half[1] - c];
            let mut local = Vec::with_capacity(SEGMENTS + 4);
            for (k, (sx, sy)) in [(1.0, 1.0), (-1.0, 1.0), (-1.0, -1.0), (1.0, -1.0)].into_iter().enumerate() {
                arc(&mut local, [sx * inner[0], sy * inner[1]], c, k as f32 * FRAC_PI_2, FRAC_PI_2, SEGMENTS / 4);
            }
            vec![local.into_iter().map(|p| rot(p, angle, centre)).collect()]
        }
        Footprint::Ring { centre, radius, half_width } => [radius + half_width, radius - half_width]
            .into_iter()
            .filter(|r| *r > 0.0)
            .map(|r| {
                let mut out = Vec::with_capacity(SEGMENTS + 1);
                arc(&mut out, centre, r, 0.0, TAU, SEGMENTS);
                out
            })
            .collect(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every outline point lies on the shape's boundary (signed distance 0).
    #[test]
    fn outlines_lie_on_the_boundary() {
        let shapes = [
            Footprint::Ellipse { centre: [0.1, 0.2], radii: [0.02, 0.01], angle: 0.7 },
            Footprint::Capsule { a: [0.0, 0.0], b: [0.05, 0.03], radius: 0.01 },
            Footprint::RoundedRect { centre: [-0.1, 0.0], half: [0.04, 0.02], angle: -0.4, corner: 0.005 },
            Footprint::Ring { centre: [0.0, 0.0], radius: 0.035, half_width: 0.003 },
        ];
        for s in shapes {
            let rings = outline(&s);
            assert!(!rings.is_empty());
            for p in rings.into_iter().flatten() {
                assert!(s.distance(p).abs() < 2e-4, "{s:?} at {p:?}: {}", s.distance(p));
            }
        }
    }
}
