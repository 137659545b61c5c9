//! The typed id of a tracked contact. Tracking hands it out, and every
//! stage after vision keys a contact's state by it, so a contact's id
//! cannot be mixed up with a count, a grey level or a particle index.

use std::fmt;

/// A contact tracked from frame to frame: stable while the contact lasts,
/// never re-used within a pipeline's life.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, serde::Serialize, serde::Deserialize)]
#[serde(transparent)]
pub struct ContactId(u32);

impl ContactId {
    pub const fn new(id: u32) -> ContactId {
        ContactId(id)
    }

    /// The id as a number (TUIO session ids, logs).
    pub const fn get(self) -> u32 {
        self.0
    }
}

impl fmt::Display for ContactId {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        self.0.fmt(f)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_contact_id_reads_and_writes_as_its_number() {
        let id = ContactId::new(7);
        assert_eq!(id.to_string(), "7");
        assert_eq!(serde_json::to_string(&id).expect("json"), "7");
        assert_eq!(serde_json::from_str::<ContactId>("7").expect("json"), id);
        assert!(id < ContactId::new(8));
    }
}
