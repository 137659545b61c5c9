//! Small gestures stated in a few lines: each hand a kind and its keys,
//! written in the gesture file format and read by the library's own parser.

use std::fmt::Write as _;
use surfacelab::input::Gesture;

/// One hand of a gesture: its id, its kind as a gesture file names it
/// (with `fingers` for fingertips) and its keys, `(t, [x, y])` in seconds
/// and table metres.
pub struct HandKeys<'a> {
    pub id: u32,
    pub kind: &'a str,
    pub fingers: Option<u32>,
    pub keys: &'a [(f64, [f64; 2])],
}

/// A single fingertip's keys.
pub fn fingertip(id: u32, keys: &[(f64, [f64; 2])]) -> HandKeys<'_> {
    HandKeys { id, kind: "fingertips", fingers: Some(1), keys }
}

/// A hand of `kind` (`edge`, `flat`, …) and its keys.
pub fn hand<'a>(id: u32, kind: &'a str, keys: &'a [(f64, [f64; 2])]) -> HandKeys<'a> {
    HandKeys { id, kind, fingers: None, keys }
}

/// The gesture file's text for these hands.
pub fn text(hands: &[HandKeys<'_>]) -> String {
    let mut s = String::from("format = \"surfacelab-gesture\"\nversion = 1\n");
    for h in hands {
        let _ = write!(s, "[[hands]]\nid = {}\nkind = \"{}\"\n", h.id, h.kind);
        if let Some(n) = h.fingers {
            let _ = writeln!(s, "fingers = {n}");
        }
        let keys: Vec<String> =
            h.keys.iter().map(|(t, [x, y])| format!("{{ t = {t:?}, pos = [{x:?}, {y:?}] }}")).collect();
        let _ = writeln!(s, "keys = [{}]", keys.join(", "));
    }
    s
}

/// The gesture, read as a gesture file is; a test gesture that does not
/// read is a broken test.
pub fn gesture(name: &str, hands: &[HandKeys<'_>]) -> Gesture {
    Gesture::from_str(&text(hands), name).unwrap_or_else(|e| panic!("test gesture {name}: {e}"))
}
