//! Which manners a simulated participant may use: the whole repertoire, or a
//! restriction of it (the study's ablation factor, `study --manners`).
//!
//! The paper explains its results by strategy: Joint "led users to
//! predominately interact with a single finger" while particles invited
//! whole-hand sweeps. Restricting every participant under every technique to
//! the same subset tests that account: if a finding holds under the full
//! repertoire and goes under the restriction, the strategies made it.

use super::manner::Manner;
use std::fmt;

/// A set of manners, by position in [`Manner::ALL`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct Repertoire(u16);

/// Named restrictions, for `--manners NAME`.
pub const PRESETS: [(&str, &[&str]); 4] = [
    ("full", &[]),
    ("single-finger", &["fingertip_1"]),
    ("fingertips", &["fingertip_1", "fingertip_2", "fingertip_3"]),
    (
        "one-hand",
        &[
            "fingertip_1",
            "fingertip_2",
            "fingertip_3",
            "pinch",
            "flat_hand",
            "push_fingertip",
            "push_edge",
            "edge_sweep",
            "forearm_sweep",
        ],
    ),
];

/// A restriction that cannot be used.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum RepertoireError {
    #[error("unknown manner or preset `{0}` (manners: {manners}; presets: {presets})", manners = manner_names(), presets = preset_names())]
    Unknown(String),
    #[error(
        "`{0}` leaves no manner that works in every situation: include one of fingertip_1, fingertip_2, fingertip_3, flat_hand, push_fingertip or push_edge"
    )]
    NoFallback(String),
}

impl crate::error::Kind for RepertoireError {
    fn kind(&self) -> crate::error::ErrorKind {
        crate::error::ErrorKind::BadInput
    }
}

fn manner_names() -> String {
    Manner::ALL.iter().map(|m| m.name()).collect::<Vec<_>>().join(", ")
}

fn preset_names() -> String {
    PRESETS.iter().map(|(n, _)| *n).collect::<Vec<_>>().join(", ")
}

impl Repertoire {
    /// Every manner.
    pub const FULL: Repertoire = Repertoire((1 << Manner::ALL.len()) - 1);

    /// Just one manner.
    pub fn only(m: Manner) -> Repertoire {
        Repertoire(1 << m.index())
    }

    /// Whether `m` may be used.
    pub fn allows(self, m: Manner) -> bool {
        self.0 & (1 << m.index()) != 0
    }

    /// The manners allowed, in [`Manner::ALL`] order.
    pub fn manners(self) -> impl Iterator<Item = Manner> {
        Manner::ALL.into_iter().filter(move |&m| self.allows(m))
    }

    pub fn is_full(self) -> bool {
        self == Repertoire::FULL
    }

    /// Parses a preset name (`single-finger`) or comma-separated manner
    /// names (`fingertip_1,pinch`). Every situation must leave a manner:
    /// the set must hold one that applies whatever the scene (a fingertip
    /// drag, a flat hand, a push), or a participant could stand idle.
    pub fn parse(spec: &str) -> Result<Repertoire, RepertoireError> {
        let spec = spec.trim();
        let names: Vec<&str> = match PRESETS.iter().find(|(n, _)| *n == spec) {
            Some((_, [])) => return Ok(Repertoire::FULL),
            Some((_, list)) => list.to_vec(),
            None => spec.split(',').map(str::trim).collect(),
        };
        let mut bits = 0u16;
        for name in names {
            let m = Manner::ALL
                .into_iter()
                .find(|m| m.name() == name)
                .ok_or_else(|| RepertoireError::Unknown(name.to_owned()))?;
            bits |= 1 << m.index();
        }
        let set = Repertoire(bits);
        if Manner::ALL.into_iter().any(|m| m.works_anywhere() && set.allows(m)) {
            Ok(set)
        } else {
            Err(RepertoireError::NoFallback(spec.to_owned()))
        }
    }

    /// The name a folder or a report uses: the preset's, else the manners
    /// joined by `+`.
    pub fn label(self) -> String {
        PRESETS
            .iter()
            .find(|(_, list)| {
                Repertoire::parse(&list.join(",")).ok() == Some(self) || (list.is_empty() && self.is_full())
            })
            .map_or_else(|| self.manners().map(Manner::name).collect::<Vec<_>>().join("+"), |(n, _)| (*n).to_owned())
    }
}

impl Default for Repertoire {
    fn default() -> Self {
        Repertoire::FULL
    }
}

impl fmt::Display for Repertoire {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.label())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn presets_and_lists_parse() {
        assert_eq!(Repertoire::parse("full"), Ok(Repertoire::FULL));
        let single = Repertoire::parse("single-finger").expect("preset");
        assert_eq!(single.manners().collect::<Vec<_>>(), [Manner::Fingertips(1)]);
        assert_eq!(single.label(), "single-finger");
        let two = Repertoire::parse(" fingertip_1, pinch ").expect("list");
        assert!(two.allows(Manner::Pinch) && two.allows(Manner::Fingertips(1)) && !two.allows(Manner::FlatHand));
        assert_eq!(two.label(), "fingertip_1+pinch");
        assert_eq!(Repertoire::FULL.manners().count(), Manner::ALL.len());
        assert_eq!(Repertoire::FULL.label(), "full");
        let one_hand = Repertoire::parse("one-hand").expect("preset");
        assert!(!one_hand.allows(Manner::BimanualDrag) && !one_hand.allows(Manner::TwoHandGather));
    }

    #[test]
    fn bad_restrictions_are_refused() {
        assert!(matches!(Repertoire::parse("fingertip_9"), Err(RepertoireError::Unknown(n)) if n == "fingertip_9"));
        // A pinch only works on small objects: a participant could be left idle.
        assert!(matches!(Repertoire::parse("pinch"), Err(RepertoireError::NoFallback(_))));
    }
}
