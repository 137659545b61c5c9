//! Small scenes stated in a few lines, through the library's own
//! [`SceneBuilder`] (so a test scene is validated exactly as a scene file is).

use surfacelab::scene::{Effect, Scene, SceneBuilder, ShapeSpec};

/// A scene on the default 1.0 × 0.75 m table with gravity and friction, the
/// effects a resting object needs; add objects with [`SceneBuilder::object`].
pub fn table(name: &str) -> SceneBuilder {
    SceneBuilder::new(name).effects(&[Effect::Gravity, Effect::Friction])
}

/// A box of full width, depth and height (m).
pub fn cuboid(width: f32, depth: f32, height: f32) -> ShapeSpec {
    ShapeSpec::Box { size: [width, depth, height] }
}

/// An upright cylinder of `radius` and full `height` (m).
pub fn disc(radius: f32, height: f32) -> ShapeSpec {
    ShapeSpec::Cylinder { radius, height }
}

/// The scene built and validated; a test scene that does not validate is a
/// broken test.
pub fn build(b: &SceneBuilder) -> Scene {
    b.build().unwrap_or_else(|e| panic!("test scene: {e}"))
}
