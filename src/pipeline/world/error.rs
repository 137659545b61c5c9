//! Errors at the world's border.

use crate::scene::Effect;

#[derive(Debug, thiserror::Error)]
pub enum WorldError {
    #[error("scene `{scene}` does not declare the `{effect}` effect, which {what} needs")]
    EffectNotDeclared { scene: String, effect: Effect, what: String },
}
