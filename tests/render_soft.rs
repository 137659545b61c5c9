//! Golden images of the soft-body scenes, drawn through the same
//! session → draw-list path as the demo: rapier's particles and surface
//! triangles become `DeformableDraw`s every frame, torn pieces included.
//!
//! References live in `tests/snapshots/`; a failing run writes
//! `NAME.new.png` and `NAME.diff.png` beside them; `UPDATE_SNAPSHOTS=1`
//! refreshes them.

mod common;

use common::asset;
use surfacelab::app::{ViewOptions, draw_list};
use surfacelab::input::Gesture;
use surfacelab::pipeline::technique::TechniqueKind;
use surfacelab::render::{self, GpuContext};
use surfacelab::render::{SnapshotDir, Tolerance};
use surfacelab::scene;
use surfacelab::scene::SoftId;
use surfacelab::session::{Session, SessionOptions};

/// Set on lavapipe, "llvmpipe (LLVM 15.0.6, 256 bits)", as in `render_scenes.rs`.
const TOLERANCE: Tolerance = Tolerance { per_pixel: 12, max_differing_share: 0.005 };
const SIZE: (u32, u32) = (480, 360);

fn gpu() -> GpuContext {
    GpuContext::new_headless()
        .unwrap_or_else(|e| panic!("these tests need a GPU adapter: {}", surfacelab::error::chain(&e)))
}

fn session_at(task: &str, gesture: Option<&str>, at: f64) -> Session {
    let scene = scene::load(&asset(task)).expect("scene");
    let mut s = Session::new(&scene, TechniqueKind::PARTICLE, SessionOptions::default()).expect("session");
    let g = gesture.map(|g| Gesture::load(asset(g)).expect("gesture")).unwrap_or_default();
    s.replay_until(&g, at).expect("replay");
    s
}

#[test]
fn the_crumpled_cloth_matches_its_golden_image() {
    let s = session_at("tasks/cloth.toml", None, 0.5);
    let list = draw_list(&s, ViewOptions::default());
    assert_eq!(list.deformables.len(), 1, "one cloth");
    assert_eq!(list.deformables[0].positions.len(), 16 * 16);
    let img = render::render_to_image(&gpu(), &list, SIZE.0, SIZE.1).expect("render");
    SnapshotDir::new(asset("tests/snapshots"))
        .check("soft_cloth", &img, TOLERANCE)
        .unwrap_or_else(|e| panic!("{}", surfacelab::error::chain(&e)));
}

#[test]
fn the_torn_paper_draws_both_pieces() {
    // Two hands pulling the paper apart, shortly after it tore; contact
    // shadows on so the hands show.
    let s = session_at("tasks/tear.toml", Some("assets/gestures/tear_two_hands.toml"), 1.4);
    assert!(s.world().soft_piece_masses(SoftId::new(0)).len() >= 2, "the paper should have torn by 1.4 s");
    let list = draw_list(&s, ViewOptions { feedback: false, contact_overlay: true });
    assert!(list.deformables.len() >= 2, "every piece is drawn: {}", list.deformables.len());
    let img = render::render_to_image(&gpu(), &list, SIZE.0, SIZE.1).expect("render");
    SnapshotDir::new(asset("tests/snapshots"))
        .check("soft_tear", &img, TOLERANCE)
        .unwrap_or_else(|e| panic!("{}", surfacelab::error::chain(&e)));
}
