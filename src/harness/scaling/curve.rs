//! The curves `surfacelab bench` measures and one row of `scaling.csv`.

use crate::session::StageTimes;
use serde::{Deserialize, Serialize};

/// What a curve varies; everything else stays at the reference workload
/// (the sorting scene, two flat hands sliding over its pieces, Particle,
/// 640 × 480 contact image, 60 Hz physics).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Curve {
    /// Flat hands on the table (1, 2, 4, 8).
    Hands,
    /// Boxes on the table, on a grid two flat hands slide over.
    Objects,
    /// Physics steps per second (each frame is one step).
    RateHz,
    /// The contact image's side in pixels (square images).
    ImageSide,
    /// Participants in a study (wall time and peak memory of the process).
    Participants,
}

impl Curve {
    pub const ALL: [Curve; 5] = [Curve::Hands, Curve::Objects, Curve::RateHz, Curve::ImageSide, Curve::Participants];

    pub fn name(self) -> &'static str {
        match self {
            Curve::Hands => "hands",
            Curve::Objects => "objects",
            Curve::RateHz => "rate_hz",
            Curve::ImageSide => "image_side",
            Curve::Participants => "participants",
        }
    }

    /// The points `surfacelab bench --point` measures: wide enough to go past
    /// the curve's own ends, bounded so that one point stays a frame (a
    /// 2048² image is 4 MB, 20,000 boxes are twice the 10,000-box point).
    pub fn point_range(self) -> (f64, f64) {
        match self {
            Curve::Hands => (1.0, 16.0),
            Curve::Objects => (1.0, 20_000.0),
            Curve::RateHz => (30.0, 1000.0),
            Curve::ImageSide => (64.0, 2048.0),
            Curve::Participants => (1.0, f64::from(crate::scene::bounds::MAX_PARTICIPANTS)),
        }
    }

    /// The measured quantity whose growth the curve's slope gives.
    pub fn cost(self) -> &'static str {
        match self {
            Curve::Participants => "study wall time (s)",
            _ => "frame time (µs)",
        }
    }
}

/// One point: a frame curve's stage means, or a study's wall time and peak
/// resident memory. The other columns are empty.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ScalingRow {
    pub curve: Curve,
    pub x: f64,
    /// Mean non-zero pixels of the contact image per frame.
    pub contact_pixels: Option<f64>,
    /// Mean bodies the technique keeps in the world per frame.
    pub technique_bodies: Option<f64>,
    pub rasterize_us: Option<f64>,
    pub vision_us: Option<f64>,
    pub technique_us: Option<f64>,
    pub step_us: Option<f64>,
    pub total_us: Option<f64>,
    pub wall_s: Option<f64>,
    pub peak_rss_mb: Option<f64>,
}

/// What a frame point measures: the mean a frame of each stage, of the
/// contact image's non-zero pixels and of the technique's bodies.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Measured {
    pub times: StageTimes,
    pub contact_pixels: f64,
    pub technique_bodies: f64,
}

impl ScalingRow {
    pub fn frame(curve: Curve, x: f64, m: Measured) -> ScalingRow {
        ScalingRow {
            curve,
            x,
            contact_pixels: Some(m.contact_pixels),
            technique_bodies: Some(m.technique_bodies),
            rasterize_us: Some(m.times.rasterize_us),
            vision_us: Some(m.times.vision_us),
            technique_us: Some(m.times.technique_us),
            step_us: Some(m.times.step_us),
            total_us: Some(m.times.total_us()),
            wall_s: None,
            peak_rss_mb: None,
        }
    }

    pub fn study(x: f64, wall_s: f64, peak_rss_mb: f64) -> ScalingRow {
        ScalingRow {
            curve: Curve::Participants,
            x,
            contact_pixels: None,
            technique_bodies: None,
            rasterize_us: None,
            vision_us: None,
            technique_us: None,
            step_us: None,
            total_us: None,
            wall_s: Some(wall_s),
            peak_rss_mb: Some(peak_rss_mb),
        }
    }

    /// The cost the curve's slope is fitted to.
    pub fn cost(&self) -> Option<f64> {
        self.total_us.or(self.wall_s)
    }

    /// The frame stage that costs most at this point, with its share.
    pub fn dominant_stage(&self) -> Option<(&'static str, f64)> {
        let stages = [
            ("rasterize", self.rasterize_us?),
            ("vision", self.vision_us?),
            ("technique", self.technique_us?),
            ("step", self.step_us?),
        ];
        let total = self.total_us?;
        let (name, us) = stages.into_iter().max_by(|a, b| a.1.total_cmp(&b.1))?;
        Some((name, if total > 0.0 { us / total } else { 0.0 }))
    }
}
