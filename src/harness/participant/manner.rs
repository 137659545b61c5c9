//! The manners a scripted participant can move objects in, and which of
//! them a situation allows.
//!
//! Which manners apply depends only on the goal and the scene's geometry
//! (object sizes, how many objects share a destination nearby) — never on
//! the technique. Whether a manner *works* under a technique is left to the
//! physics and to what the participant learns ([`super::learner`]).

use crate::pipeline::surface::HandKind;
use std::fmt;

/// One way of moving objects with the hands.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Manner {
    /// 1–3 fingertips pressed on top of the object, dragging it.
    Fingertips(u8),
    /// Thumb and index on opposite sides of the object, dragging it.
    Pinch,
    /// The flat hand pressed on the object, dragging it.
    FlatHand,
    /// A fingertip on the table behind the object, pushing it.
    PushFingertip,
    /// The side of the hand on the table behind the object, pushing it.
    PushEdge,
    /// The side of the hand behind a cluster bound for the same zone,
    /// sweeping it there.
    EdgeSweep,
    /// Both hands' sides behind a cluster, angled inward like a scoop,
    /// gathering it towards the zone.
    TwoHandGather,
    /// Each hand drags its own object at the same time (fingertip drags).
    BimanualDrag,
    /// The forearm laid behind a cluster, sweeping it towards the zone.
    ForearmSweep,
}

impl Manner {
    /// Every manner, in the order files list them.
    pub const ALL: [Manner; 11] = [
        Manner::Fingertips(1),
        Manner::Fingertips(2),
        Manner::Fingertips(3),
        Manner::Pinch,
        Manner::FlatHand,
        Manner::PushFingertip,
        Manner::PushEdge,
        Manner::EdgeSweep,
        Manner::TwoHandGather,
        Manner::BimanualDrag,
        Manner::ForearmSweep,
    ];

    /// Whether every situation allows it: a repertoire needs one such
    /// manner to fall back on (the sweeps need a cluster, the bimanual drag
    /// two objects, the pinch an object narrow enough to grip).
    pub fn works_anywhere(self) -> bool {
        matches!(self, Manner::Fingertips(_) | Manner::FlatHand | Manner::PushFingertip | Manner::PushEdge)
    }

    /// The name written to `trials.csv` and `strategies.csv`.
    pub fn name(self) -> &'static str {
        match self {
            Manner::Fingertips(1) => "fingertip_1",
            Manner::Fingertips(2) => "fingertip_2",
            Manner::Fingertips(_) => "fingertip_3",
            Manner::Pinch => "pinch",
            Manner::FlatHand => "flat_hand",
            Manner::PushFingertip => "push_fingertip",
            Manner::PushEdge => "push_edge",
            Manner::EdgeSweep => "edge_sweep",
            Manner::TwoHandGather => "two_hand_gather",
            Manner::BimanualDrag => "bimanual_drag",
            Manner::ForearmSweep => "forearm_sweep",
        }
    }

    /// Index into [`Manner::ALL`].
    pub fn index(self) -> usize {
        Manner::ALL.iter().position(|&m| m == self).unwrap_or(0)
    }

    /// The hand model each hand of this manner uses.
    pub fn hand_kind(self) -> HandKind {
        match self {
            Manner::Fingertips(n) => HandKind::Fingertips(n.clamp(1, 3)),
            Manner::Pinch => HandKind::Fingertips(2),
            Manner::FlatHand => HandKind::FlatHand,
            Manner::PushFingertip | Manner::BimanualDrag => HandKind::Fingertips(1),
            Manner::PushEdge | Manner::EdgeSweep | Manner::TwoHandGather => HandKind::Edge,
            Manner::ForearmSweep => HandKind::Forearm,
        }
    }

    /// Hands this manner puts on the table.
    pub fn hands(self) -> usize {
        if matches!(self, Manner::TwoHandGather | Manner::BimanualDrag) { 2 } else { 1 }
    }
}

impl fmt::Display for Manner {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// Fingertips touching the glass in a hand of this kind (for `fingers_max`):
/// a flat hand touches with all five; sides of hands and arms with none.
pub fn fingers(kind: HandKind) -> u32 {
    match kind {
        HandKind::Fingertips(n) => u32::from(n),
        HandKind::FlatHand => 5,
        _ => 0,
    }
}

/// The geometry a choice is made from.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Situation {
    /// Open objects bound for the seed's destination within a hand's reach
    /// of each other (the seed included).
    pub cluster: usize,
    /// The seed object's footprint radius (m).
    pub footprint: f32,
    /// Another open object lies elsewhere for a second hand to take.
    pub second_object: bool,
}

/// The widest object a thumb and index can span from its sides (m radius):
/// a relaxed grip opens about 9 cm.
const PINCH_MAX_RADIUS: f32 = 0.045;
/// Objects a forearm sweep is worth laying the arm down for: it covers ~25 cm.
const FOREARM_MIN_CLUSTER: usize = 3;

/// The manners this situation allows, in [`Manner::ALL`] order.
pub fn applicable(s: Situation) -> Vec<Manner> {
    Manner::ALL
        .into_iter()
        .filter(|m| match m {
            Manner::Pinch => s.footprint <= PINCH_MAX_RADIUS,
            Manner::EdgeSweep | Manner::TwoHandGather => s.cluster >= 2,
            Manner::ForearmSweep => s.cluster >= FOREARM_MIN_CLUSTER,
            Manner::BimanualDrag => s.second_object,
            _ => true,
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_are_distinct_and_indices_round_trip() {
        let mut names: Vec<_> = Manner::ALL.iter().map(|m| m.name()).collect();
        names.sort_unstable();
        names.dedup();
        assert_eq!(names.len(), Manner::ALL.len());
        for (k, m) in Manner::ALL.iter().enumerate() {
            assert_eq!(m.index(), k);
        }
    }

    #[test]
    fn sweeps_need_a_cluster_and_pinch_a_small_object() {
        let lone = Situation { cluster: 1, footprint: 0.03, second_object: false };
        let m = applicable(lone);
        assert!(m.contains(&Manner::Pinch) && m.contains(&Manner::PushEdge));
        assert!(!m.iter().any(|m| matches!(m, Manner::EdgeSweep | Manner::TwoHandGather | Manner::ForearmSweep)));
        assert!(!m.contains(&Manner::BimanualDrag));
        let big = Situation { cluster: 3, footprint: 0.06, second_object: true };
        let m = applicable(big);
        assert!(!m.contains(&Manner::Pinch));
        assert!(m.contains(&Manner::ForearmSweep) && m.contains(&Manner::BimanualDrag));
        let pair = Situation { cluster: 2, ..big };
        assert!(applicable(pair).contains(&Manner::EdgeSweep) && !applicable(pair).contains(&Manner::ForearmSweep));
    }
}
