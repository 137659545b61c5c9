//! Errors at the world's border.

#[derive(Debug, thiserror::Error)]
pub enum WorldError {
    #[error("scene `{scene}` does not declare the `{effect}` effect, which {what} needs")]
    EffectNotDeclared { scene: String, effect: &'static str, what: String },
}
