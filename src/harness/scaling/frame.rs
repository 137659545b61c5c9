//! The frame curves' workloads and how a point is measured.
//!
//! Every point runs the whole frame — rasterise the hands, vision,
//! technique, one physics step — through [`Session::step`], so a point's
//! stages add up to what the demo and the study pay per frame.

use super::curve::{Curve, Measured};
use crate::pipeline::surface::{Hand, HandKind};
use crate::pipeline::technique::TechniqueKind;
use crate::scene::{self, Effect, Scene, SceneBuilder, ShapeSpec};
use crate::session::{Session, SessionOptions};

/// Side of the objects curve's boxes (m) and their spacing on the grid:
/// up to 1,000 boxes fit the reference 1 × 0.75 m table, so the hands press
/// the same pixels along the curve until its 10,000-box point.
const BOX_SIDE: f32 = 0.015;
const BOX_PITCH: f32 = 0.025;

/// One frame workload.
#[derive(Debug, Clone)]
pub struct Workload {
    pub scene: Scene,
    pub hands: usize,
    pub sensor_px: (u32, u32),
}

impl Workload {
    /// The reference: two flat hands on the sorting scene, 640 × 480, 60 Hz.
    fn reference() -> anyhow::Result<Workload> {
        Ok(Workload { scene: scene::load("sorting")?, hands: 2, sensor_px: (640, 480) })
    }

    /// The workload of `curve` at `x`.
    pub fn at(curve: Curve, x: f64) -> anyhow::Result<Workload> {
        let mut w = Workload::reference()?;
        match curve {
            Curve::Hands => w.hands = x as usize,
            Curve::Objects => w.scene = box_grid(x as usize)?,
            Curve::RateHz => w.scene.physics.dt = (1.0 / x) as f32,
            Curve::ImageSide => w.sensor_px = (x as u32, x as u32),
            Curve::Participants => anyhow::bail!("participants is not a frame curve"),
        }
        Ok(w)
    }

    /// The hands at frame `k`: flat hands in rows of four over the table's
    /// middle, each sliding 4 cm to and fro (as in `cargo bench --bench
    /// frame`), pressing fully.
    fn hands_at(&self, k: usize) -> Vec<Hand> {
        let t = k as f32 / 60.0;
        let per_row = self.hands.clamp(1, 4);
        (0..self.hands)
            .map(|i| {
                let (col, row) = ((i % per_row) as f32, (i / per_row) as f32);
                let x = (col - 0.5 * (per_row as f32 - 1.0)) * 0.22;
                let y = 0.1 - 0.22 * row;
                let slide = 0.04 * (t * 0.7 + i as f32).sin();
                Hand::new(i as u32 + 1, HandKind::FlatHand, x + slide, y).with_angle(0.2 * i as f32).with_pressure(1.0)
            })
            .collect()
    }

    /// Per-frame means over `frames` frames after `warmup` frames.
    pub fn measure(&self, warmup: usize, frames: usize) -> anyhow::Result<Measured> {
        let options = SessionOptions { sensor_px: self.sensor_px, ..SessionOptions::default() };
        let mut s = Session::new(&self.scene, TechniqueKind::PARTICLE, options)?;
        for k in 0..warmup {
            s.step(&self.hands_at(k))?;
        }
        let mut sum = Measured::default();
        for k in warmup..warmup + frames {
            s.step(&self.hands_at(k))?;
            sum.times.add(&s.last_times());
            sum.contact_pixels += s.image().pixels.iter().filter(|&&p| p > 0).count() as f64;
            sum.technique_bodies += s.counts().bodies as f64;
        }
        let n = frames.max(1) as f64;
        Ok(Measured {
            times: sum.times.per_frame(frames as u64),
            contact_pixels: sum.contact_pixels / n,
            technique_bodies: sum.technique_bodies / n,
        })
    }
}

/// `n` boxes on a grid, on a 4:3 table just large enough (at least the
/// reference 1 × 0.75 m). Scene files stop at
/// [`MAX_OBJECTS`](crate::scene::bounds::MAX_OBJECTS); the curve's largest
/// points go past it on purpose, so the grid is built from one validated
/// box.
fn box_grid(n: usize) -> anyhow::Result<Scene> {
    let cols = ((n as f32 * 4.0 / 3.0).sqrt().ceil() as usize).max(1);
    let rows = n.div_ceil(cols);
    let width = (cols as f32 * BOX_PITCH + 0.05).max(1.0);
    let depth = (rows as f32 * BOX_PITCH + 0.05).max(0.75 * width);
    let template = SceneBuilder::new(&format!("grid_{n}"))
        .effects(&[Effect::Gravity, Effect::Friction])
        .table(width, depth)
        .object("box", ShapeSpec::Box { size: [BOX_SIDE; 3] }, [0.0, 0.0], 0.05, "blue")
        .build()?;
    let mut scene = template.clone();
    let one = template.objects[0].clone();
    scene.objects = (0..n)
        .map(|i| {
            let mut o = one.clone();
            o.name = format!("box{i}");
            o.position.x = ((i % cols) as f32 - 0.5 * (cols as f32 - 1.0)) * BOX_PITCH;
            o.position.y = ((i / cols) as f32 - 0.5 * (rows as f32 - 1.0)) * BOX_PITCH;
            o
        })
        .collect();
    Ok(scene)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_box_grid_fits_its_table_and_spaces_its_boxes() {
        for n in [10, 100, 1000, 10_000] {
            let s = box_grid(n).expect("grid");
            assert_eq!(s.objects.len(), n);
            let (hw, hd) = (0.5 * s.table.width, 0.5 * s.table.depth);
            for o in &s.objects {
                assert!(o.position.x.abs() + 0.5 * BOX_SIDE < hw && o.position.y.abs() + 0.5 * BOX_SIDE < hd, "{n}");
            }
            if n <= 1000 {
                assert_eq!((s.table.width, s.table.depth), (1.0, 0.75), "{n} boxes fit the reference table");
            }
            let (a, b) = (s.objects[0].position, s.objects[1].position);
            assert!(((b - a).length() - BOX_PITCH).abs() < 1e-5);
        }
    }

    #[test]
    fn more_hands_press_more_pixels() {
        let one = Workload::at(Curve::Hands, 1.0).expect("workload").measure(0, 3).expect("one hand");
        let four = Workload::at(Curve::Hands, 4.0).expect("workload").measure(0, 3).expect("four hands");
        // Four separate flat hands cover four times one hand's pixels.
        let ratio = four.contact_pixels / one.contact_pixels;
        assert!((3.8..4.2).contains(&ratio), "{ratio}");
    }
}
