//! [`Push`]: how a technique holds a body it may push but not move, remove
//! or disable (a scene object's rigid body, a soft body).

/// A body, to push: it reads as the body itself, and its own `impl` (beside
/// the world's accessor for that kind of body) offers only forces,
/// impulses and velocities.
#[derive(Debug)]
pub struct Push<'w, B>(pub(super) &'w mut B);

impl<B> std::ops::Deref for Push<'_, B> {
    type Target = B;

    fn deref(&self) -> &B {
        self.0
    }
}
