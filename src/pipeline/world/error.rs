//! Errors at the world's border.

use crate::scene::Effect;

#[derive(Debug, thiserror::Error)]
pub enum WorldError {
    #[error("scene `{scene}` does not declare the `{effect}` effect, which {what} needs")]
    EffectNotDeclared { scene: String, effect: Effect, what: String },
}

impl crate::error::Kind for WorldError {
    /// A scene and technique that do not fit together were the user's choice.
    fn kind(&self) -> crate::error::ErrorKind {
        match self {
            WorldError::EffectNotDeclared { .. } => crate::error::ErrorKind::BadInput,
        }
    }
}
