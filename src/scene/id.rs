//! Typed ids for what a scene declares. Every layer below the scene
//! addresses objects and soft bodies by these, never by a bare index, so
//! an object index cannot be passed where a soft body's is meant.

/// A scene object: its index in the scene's `objects`, stable for the
/// world's life (a removed object keeps its id).
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct ObjectId(usize);

impl ObjectId {
    pub fn new(index: usize) -> ObjectId {
        ObjectId(index)
    }

    /// The object's index in the scene's `objects`.
    pub fn index(self) -> usize {
        self.0
    }
}

/// A declared soft body: its index in the scene's `soft_bodies`, stable
/// for the world's life (torn pieces keep their body's id).
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct SoftId(usize);

impl SoftId {
    pub fn new(index: usize) -> SoftId {
        SoftId(index)
    }

    /// The soft body's index in the scene's `soft_bodies`.
    pub fn index(self) -> usize {
        self.0
    }
}
