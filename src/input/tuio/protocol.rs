//! What both TUIO versions share: the limits, the errors and counters a
//! packet can produce, the rule that orders a source's frames, and how
//! coordinates and OSC arguments are read. [`super::decode`] (1.1, and the
//! state both versions feed) and [`super::tuio2`] build on it.

/// A source silent this long (seconds) is assumed gone.
pub const STALE_AFTER_S: f64 = 2.0;

/// Deepest bundle nesting accepted. Real trackers send one level; the
/// limit keeps a hostile packet from recursing through the decoder.
pub const MAX_BUNDLE_DEPTH: usize = 4;

/// Late-frame window of the reference client: a frame id this far below
/// the last one means the tracker restarted, not a late packet.
const LATE_WINDOW: i64 = 100;
/// A frame id below the last one, arriving after the source was silent
/// this long (seconds), is a restarted tracker counting from 1 again, not a
/// late packet: UDP reordering happens within a steady stream (trackers
/// send 30-60 frames a second), a restart takes a pause. Without this, a
/// tracker that restarted within 100 frames would have its new frames
/// dropped as late while its old cursors stayed on the table as ghosts.
const RESTART_GAP_S: f64 = 0.25;

/// Normalized coordinates beyond this margin around 0..1 are rejected.
pub(super) const COORD_MARGIN: f32 = 1.0;

/// Why a packet was rejected.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum TuioError {
    #[error("not an OSC packet: {0}")]
    Osc(String),
    #[error("bundles nested deeper than {MAX_BUNDLE_DEPTH} levels")]
    TooDeep,
    #[error("{address}: {problem}")]
    Message { address: String, problem: String },
}

/// Counters shown in the demo's panel.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct TuioStats {
    /// Packets received, malformed ones included.
    pub packets: u64,
    /// Packets rejected whole.
    pub malformed: u64,
    /// Frames dropped because their `fseq` came too late.
    pub late_frames: u64,
    /// Messages of other profiles or commands, skipped.
    pub ignored_messages: u64,
    /// Packets that held only messages of other profiles (`/tuio/2Dobj`,
    /// TUIO 2.0's `/tuio2/*`, custom ones): well-formed but of no use here.
    pub unknown_profile: u64,
    /// Times a source's state was thrown away because its tracker
    /// restarted or came back after [`STALE_AFTER_S`] of silence.
    pub restarts: u64,
    /// TUIO 2.0 frames dropped because the next `frm` came before their
    /// `alv` (a lost packet).
    pub incomplete_frames: u64,
}

/// What ending a frame did.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Commit {
    Applied,
    /// Dropped: it came after a later frame.
    Late,
    /// The tracker restarted: its old sessions were dropped, then the frame applied.
    Restarted,
}

/// Whether frame `frame` of a source whose last accepted frame was `last`,
/// arriving `gap` seconds after its previous packet, is applied, late or
/// from a restarted tracker (the rules of the module doc; shared by TUIO
/// 1.1 and 2.0). Ids <= 0 are always applied.
pub(super) fn frame_order(frame: i64, last: i64, gap: f64) -> Commit {
    let backwards = frame > 0 && frame < last;
    if backwards && (last - frame > LATE_WINDOW || gap >= RESTART_GAP_S) {
        Commit::Restarted
    } else if backwards {
        Commit::Late
    } else {
        Commit::Applied
    }
}

/// Normalized TUIO coordinates (y down) to table metres (y away from the
/// viewer, centred).
pub(super) fn to_table(p: [f32; 2], table: [f32; 2]) -> [f32; 2] {
    [(p[0] - 0.5) * table[0], (0.5 - p[1]) * table[1]]
}

/// An OSC argument for an error message. rosc's `Display` of a time tag
/// converts it to a `SystemTime` and panics on one before 1970 or past
/// 2106 (found by `tests/fuzz.rs`), so time tags are shown raw.
pub(super) fn shown(a: &rosc::OscType) -> String {
    match a {
        rosc::OscType::Time(t) => format!("time tag {}.{}", t.seconds, t.fractional),
        other => other.to_string(),
    }
}

/// A finite number; trackers send float32, some double.
pub(super) fn float(a: &rosc::OscType) -> Option<f32> {
    let v = match a {
        rosc::OscType::Float(f) => *f,
        rosc::OscType::Double(d) => *d as f32,
        rosc::OscType::Int(i) => *i as f32,
        _ => return None,
    };
    v.is_finite().then_some(v)
}
