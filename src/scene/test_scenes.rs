//! Scenes the unit tests share, read from `tests/scenes/` (the integration
//! tests include the same files).

use super::{Scene, load};

/// `tests/scenes/NAME.toml`, loaded and validated; a fixture that does not
/// load is a broken test.
pub fn fixture(name: &str) -> Scene {
    load(&format!("{}/tests/scenes/{name}.toml", env!("CARGO_MANIFEST_DIR"))).unwrap_or_else(|e| panic!("{e}"))
}
