//! TUIO input: the OSC packets a tracker sends (a touch table's own
//! server, reacTIVision, CCV, a phone app) decoded into [`Hand`]s. Pure:
//! bytes in, hands out. The app owns the UDP socket and the clock.
//!
//! One [`TuioState`] serves TUIO 1.1 and TUIO 2.0 on the same port: a
//! packet with any `/tuio2/` message is TUIO 2.0 and goes to
//! [`super::tuio2`] (its `/tuio/` messages ignored); any other is TUIO 1.1,
//! below. Each version keeps its own sources and sessions; the hands are
//! both versions' together.
//!
//! TUIO 1.1:
//!
//! | profile | message | becomes |
//! |---|---|---|
//! | `/tuio/2Dcur` | `set s x y X Y m` | one fingertip at (x, y) |
//! | `/tuio/2Dblb` | `set s x y a w h f X Y A m r` | the hand kind whose footprint best fits the blob, scaled to its long side and turned to its angle |
//! | both | `alive s...`, `fseq f`, `source name` | frame bookkeeping (below) |
//!
//! Other profiles (`2Dobj`, `25D*`, `3D*`, custom) are counted as ignored.
//!
//! **Frames.** `set` and `alive` messages are held until the profile's
//! `fseq`; then the `set`s are applied and every session id missing from
//! `alive` is removed, as the TUIO 1.1 reference client does. A positive
//! frame id lower than the last accepted one (by at most 100) is a late
//! UDP packet and its frame is dropped; ids <= 0 are always accepted.
//! Each `source` keeps its own sessions and frame counter; a source that
//! has sent nothing for [`STALE_AFTER_S`] seconds (a tracker that crashed
//! with fingers down) contributes no hands.
//!
//! **Coordinates.** TUIO's (x, y) are 0..1 with the origin at the top left
//! of the surface and y down; the table has its origin in the middle and y
//! away from the viewer (up the screen), so `x_table = (x - 0.5) * width`
//! and `y_table = (0.5 - y) * depth`. TUIO angles turn from +x towards +y
//! (clockwise on screen); table angles turn counter-clockwise, so lengths
//! and angles of a blob are taken from its axis vectors mapped to the table.
//!
//! **Malformed packets** (not OSC, nested deeper than [`MAX_BUNDLE_DEPTH`],
//! wrong argument types, non-finite or absurd values) are rejected whole:
//! nothing of them is applied, [`TuioStats::malformed`] counts them, and
//! [`TuioState::receive`] says why. It never panics on any input.
//!
//! **Hand ids.** Cursors get `0x2000_0000 | source << 24 | s`, blobs
//! `0x4000_0000 | source << 24 | s` (`s` is the low 24 bits of the session
//! id, `source` the index of the source in order of appearance, mod 32),
//! so TUIO hands never share an id with mouse or touch hands.

use super::protocol::{
    COORD_MARGIN, Commit, MAX_BUNDLE_DEPTH, STALE_AFTER_S, TuioError, TuioStats, float, frame_order, shown, to_table,
};
use super::tuio2::{self, Op2, State2, Token};
use crate::pipeline::surface::{Footprint, Patch};
use crate::pipeline::surface::{Hand, HandKind};

/// The port TUIO trackers send to by default.
pub const DEFAULT_PORT: u16 = 3333;
/// Deepest OSC array nesting accepted in a message's type tags.
const MAX_ARRAY_DEPTH: usize = 4;

/// Hand-id namespaces (see the module doc).
pub const CURSOR_ID_BASE: u32 = 0x2000_0000;
pub const BLOB_ID_BASE: u32 = 0x4000_0000;

/// A `/tuio/2Dcur` cursor: a point touch, normalized coordinates.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Cursor {
    pub session: i32,
    pub x: f32,
    pub y: f32,
}

/// A `/tuio/2Dblb` blob: an oriented ellipse (or box), normalized
/// coordinates; `width` lies along the blob's own x axis, turned by `angle`
/// radians from the surface's +x towards its +y.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TuioBlob {
    pub session: i32,
    pub x: f32,
    pub y: f32,
    pub angle: f32,
    pub width: f32,
    pub height: f32,
}

/// Sessions of one profile of one source.
#[derive(Debug, Clone)]
struct Profile<T> {
    live: Vec<T>,
    pending_alive: Option<Vec<i32>>,
    pending_set: Vec<T>,
    last_frame: i64,
}

impl<T> Default for Profile<T> {
    fn default() -> Self {
        Self { live: Vec::new(), pending_alive: None, pending_set: Vec::new(), last_frame: 0 }
    }
}

trait Session: Copy {
    fn session(&self) -> i32;
}

impl Session for Cursor {
    fn session(&self) -> i32 {
        self.session
    }
}

impl Session for TuioBlob {
    fn session(&self) -> i32 {
        self.session
    }
}

impl<T: Session> Profile<T> {
    /// Ends a frame that arrived `gap` seconds after the source's previous
    /// packet.
    fn commit(&mut self, frame: i32, gap: f64) -> Commit {
        let frame = i64::from(frame);
        let outcome = frame_order(frame, self.last_frame, gap);
        if outcome == Commit::Restarted {
            self.live.clear();
            self.last_frame = 0;
        }
        if outcome != Commit::Late {
            if frame > 0 {
                self.last_frame = frame;
            }
            for item in self.pending_set.drain(..) {
                match self.live.iter_mut().find(|l| l.session() == item.session()) {
                    Some(l) => *l = item,
                    None => self.live.push(item),
                }
            }
            if let Some(alive) = self.pending_alive.take() {
                self.live.retain(|l| alive.contains(&l.session()));
            }
        }
        self.pending_set.clear();
        self.pending_alive = None;
        outcome
    }

    /// Forgets everything (a source that came back after silence).
    fn reset(&mut self) {
        self.live.clear();
        self.pending_alive = None;
        self.pending_set.clear();
        self.last_frame = 0;
    }
}

#[derive(Debug, Clone)]
struct Source {
    name: String,
    index: u32,
    last_seen: f64,
    cursors: Profile<Cursor>,
    blobs: Profile<TuioBlob>,
}

/// Which profile a message addresses.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Kind {
    Cursor,
    Blob,
}

/// One decoded message, before anything is applied.
#[derive(Debug, Clone, PartialEq)]
enum Op {
    Source(String),
    Alive(Kind, Vec<i32>),
    SetCursor(Cursor),
    SetBlob(TuioBlob),
    Fseq(Kind, i32),
    Ignored,
}

/// Everything received so far, per source.
#[derive(Debug, Clone, Default)]
pub struct TuioState {
    sources: Vec<Source>,
    /// TUIO 2.0 sources.
    v2: State2,
    stats: TuioStats,
}

impl TuioState {
    pub fn new() -> Self {
        Self::default()
    }

    /// Decodes one UDP datagram received at `now` (seconds, any origin,
    /// not decreasing) and applies it, or rejects it whole.
    pub fn receive(&mut self, packet: &[u8], now: f64) -> Result<(), TuioError> {
        self.stats.packets += 1;
        let decoded = decode(packet);
        match decoded {
            Ok(Decoded::V1(ops)) => self.apply(&ops, now),
            Ok(Decoded::V2(ops)) => {
                if !ops.is_empty() && ops.iter().all(|op| *op == Op2::Ignored) {
                    self.stats.unknown_profile += 1;
                }
                self.v2.apply(ops, now, &mut self.stats);
            }
            Err(e) => {
                self.stats.malformed += 1;
                return Err(e);
            }
        }
        Ok(())
    }

    /// Live (cursors, blobs) now: TUIO 1.1 cursors and 2.0 pointers
    /// without a shape; 1.1 blobs and 2.0 components with one.
    pub fn counts(&self, now: f64) -> (usize, usize) {
        let (c, b) = self.live(now);
        let (p, s) = self.v2.counts(now);
        (c.len() + p, b.len() + s)
    }

    /// Live TUIO 2.0 tokens (`tok`): hand id, the token, its table point.
    pub fn tokens(&self, table: [f32; 2], now: f64) -> Vec<(u32, Token, [f32; 2])> {
        self.v2.tokens(table, now)
    }

    /// Live TUIO 2.0 skeletons (`skg`): hand id and the skeleton's edges
    /// on a table of [width, depth] metres.
    pub fn skeletons(&self, table: [f32; 2], now: f64) -> Vec<(u32, Vec<[[f32; 2]; 2]>)> {
        self.v2.skeletons(table, now)
    }

    pub fn stats(&self) -> TuioStats {
        self.stats
    }

    /// Live TUIO 1.1 cursors and blobs of sources heard from in the last
    /// [`STALE_AFTER_S`] seconds.
    pub fn live(&self, now: f64) -> (Vec<Cursor>, Vec<TuioBlob>) {
        let fresh = self.sources.iter().filter(|s| now - s.last_seen <= STALE_AFTER_S);
        let mut cursors = Vec::new();
        let mut blobs = Vec::new();
        for s in fresh {
            cursors.extend_from_slice(&s.cursors.live);
            blobs.extend_from_slice(&s.blobs.live);
        }
        (cursors, blobs)
    }

    /// The hands touching a table of `table` = [width, depth] metres now.
    pub fn hands(&self, table: [f32; 2], now: f64) -> Vec<Hand> {
        let mut out = Vec::new();
        for s in self.sources.iter().filter(|s| now - s.last_seen <= STALE_AFTER_S) {
            let ns = (s.index % 32) << 24;
            for c in &s.cursors.live {
                out.push(cursor_hand(c, table, CURSOR_ID_BASE | ns | (c.session as u32 & 0x00FF_FFFF)));
            }
            for b in &s.blobs.live {
                out.push(blob_hand(b, table, BLOB_ID_BASE | ns | (b.session as u32 & 0x00FF_FFFF)));
            }
        }
        self.v2.hands(table, now, &mut out);
        out
    }

    fn source_mut(&mut self, name: &str) -> &mut Source {
        let i = if let Some(i) = self.sources.iter().position(|s| s.name == name) {
            i
        } else {
            self.sources.push(Source {
                name: name.to_owned(),
                index: self.sources.len() as u32,
                last_seen: f64::NEG_INFINITY,
                cursors: Profile::default(),
                blobs: Profile::default(),
            });
            self.sources.len() - 1
        };
        &mut self.sources[i]
    }

    fn apply(&mut self, ops: &[Op], now: f64) {
        if !ops.is_empty() && ops.iter().all(|op| *op == Op::Ignored) {
            self.stats.unknown_profile += 1;
            self.stats.ignored_messages += ops.len() as u64;
            return;
        }
        // Messages before any `source` message belong to the unnamed source.
        let mut current = String::new();
        // Seconds since each source touched in this packet last spoke.
        let mut gaps: Vec<(String, f64)> = Vec::new();
        for op in ops {
            if let Op::Source(name) = op {
                current.clone_from(name);
            }
            let source = self.source_mut(&current);
            let gap = if let Some(g) = gaps.iter().find(|g| g.0 == current) {
                g.1
            } else {
                let gap = now - source.last_seen;
                if source.last_seen.is_finite() && gap > STALE_AFTER_S {
                    // Back after silence: what it said before is stale.
                    tracing::info!("TUIO source '{current}' is back after {gap:.1} s: its old touches are dropped");
                    source.cursors.reset();
                    source.blobs.reset();
                    self.stats.restarts += 1;
                }
                gaps.push((current.clone(), gap));
                gap
            };
            let source = self.source_mut(&current);
            source.last_seen = now;
            match op {
                Op::Source(_) => {}
                Op::Alive(Kind::Cursor, ids) => source.cursors.pending_alive = Some(ids.clone()),
                Op::Alive(Kind::Blob, ids) => source.blobs.pending_alive = Some(ids.clone()),
                Op::SetCursor(c) => source.cursors.pending_set.push(*c),
                Op::SetBlob(b) => source.blobs.pending_set.push(*b),
                Op::Fseq(kind, frame) => {
                    let outcome = match kind {
                        Kind::Cursor => source.cursors.commit(*frame, gap),
                        Kind::Blob => source.blobs.commit(*frame, gap),
                    };
                    match outcome {
                        Commit::Applied => {}
                        Commit::Late => {
                            self.stats.late_frames += 1;
                            tracing::debug!("TUIO source '{current}': frame {frame} came late and was dropped");
                        }
                        Commit::Restarted => {
                            self.stats.restarts += 1;
                            tracing::info!(
                                "TUIO source '{current}' restarted (frame {frame}): its old touches are dropped"
                            );
                        }
                    }
                }
                Op::Ignored => self.stats.ignored_messages += 1,
            }
        }
    }
}

/// A cursor as a fingertip.
pub fn cursor_hand(c: &Cursor, table: [f32; 2], id: u32) -> Hand {
    let [x, y] = to_table([c.x, c.y], table);
    Hand::new(id, HandKind::Fingertips(1), x, y)
}

/// The footprint of `kind` at scale 1 in its local frame: its long side
/// (metres), its centroid, and whether the long side lies along local y.
fn footprint(kind: HandKind) -> (f32, [f32; 2], bool) {
    let patches = Hand::new(0, kind, 0.0, 0.0).patches();
    let mut lo = [f32::MAX; 2];
    let mut hi = [f32::MIN; 2];
    for p in &patches {
        let [a, b] = p.shape.bounds();
        for k in 0..2 {
            lo[k] = lo[k].min(a[k]);
            hi[k] = hi[k].max(b[k]);
        }
    }
    let size = [hi[0] - lo[0], hi[1] - lo[1]];
    (size[0].max(size[1]), centroid(&patches), size[1] >= size[0])
}

/// Area-weighted centroid of patches (overlaps counted twice: close
/// enough to match a tracker's blob centre).
pub fn centroid(patches: &[Patch]) -> [f32; 2] {
    let mut sum = [0.0f32; 2];
    let mut total = 0.0f32;
    for p in patches {
        let c = match p.shape {
            Footprint::Ellipse { centre, .. }
            | Footprint::RoundedRect { centre, .. }
            | Footprint::Ring { centre, .. } => centre,
            Footprint::Capsule { a, b, .. } => [(a[0] + b[0]) * 0.5, (a[1] + b[1]) * 0.5],
        };
        let area = p.shape.area();
        sum[0] += c[0] * area;
        sum[1] += c[1] * area;
        total += area;
    }
    if total > 0.0 { [sum[0] / total, sum[1] / total] } else { [0.0, 0.0] }
}

/// Which hand a blob of this long side and aspect (long / short) is: small
/// blobs are fingertips, long thin ones the edge of a hand or a forearm,
/// large ones a flat hand, the rest a fist.
pub fn blob_kind(long_m: f32, aspect: f32) -> HandKind {
    if long_m < 0.03 {
        HandKind::Fingertips(1)
    } else if aspect >= 2.2 {
        if long_m >= 0.17 { HandKind::Forearm } else { HandKind::Edge }
    } else if long_m >= 0.11 {
        HandKind::FlatHand
    } else {
        HandKind::Fist
    }
}

/// A blob as the hand whose footprint fits it: [`blob_kind`] picks the
/// kind, its scale makes the footprint's long side the blob's, and it is
/// turned so the long sides agree and centred on the blob's centre.
pub fn blob_hand(b: &TuioBlob, table: [f32; 2], id: u32) -> Hand {
    let [cx, cy] = to_table([b.x, b.y], table);
    let (sin, cos) = b.angle.sin_cos();
    // The blob's axes, normalized screen vectors mapped to table metres.
    let width_axis = [b.width * cos * table[0], -b.width * sin * table[1]];
    let height_axis = [-b.height * sin * table[0], -b.height * cos * table[1]];
    let len = |v: [f32; 2]| v[0].hypot(v[1]);
    let (long, short) =
        if len(width_axis) >= len(height_axis) { (width_axis, height_axis) } else { (height_axis, width_axis) };
    let long_m = len(long);
    let kind = blob_kind(long_m, long_m / len(short).max(1e-6));
    let (nominal, centre, along_y) = footprint(kind);
    let scale = (long_m / nominal).clamp(0.4, 2.5);
    // A long axis has two ends. A hand lying along it (fingers to local +y)
    // is taken to reach in from the user's side of the table: its fingers
    // point away from the user (table +y), never down the screen.
    let long = if along_y && long[1] < 0.0 { [-long[0], -long[1]] } else { long };
    let direction = long[1].atan2(long[0]);
    // Local +y points along angle + 90°; local +x along the angle itself.
    let angle = if along_y { direction - std::f32::consts::FRAC_PI_2 } else { direction };
    let (s, c) = angle.sin_cos();
    let offset = [(centre[0] * c - centre[1] * s) * scale, (centre[0] * s + centre[1] * c) * scale];
    Hand::new(id, kind, cx - offset[0], cy - offset[1]).with_angle(angle).with_scale(scale)
}

// ---------------------------------------------------------------------------
// Decoding.

/// A packet's operations, of the version it was detected as.
enum Decoded {
    V1(Vec<Op>),
    V2(Vec<Op2>),
}

/// Decodes a datagram into operations, checking everything first; a
/// `/tuio2/` message anywhere makes it TUIO 2.0.
fn decode(packet: &[u8]) -> Result<Decoded, TuioError> {
    check_nesting(packet, 0)?;
    let (_, osc) = rosc::decoder::decode_udp(packet).map_err(|e| TuioError::Osc(e.to_string()))?;
    let mut messages = Vec::new();
    flatten(osc, &mut messages);
    if messages.iter().any(|m| m.addr.starts_with("/tuio2/")) {
        messages.iter().map(tuio2::op).collect::<Result<_, _>>().map(Decoded::V2)
    } else {
        messages.iter().map(op).collect::<Result<_, _>>().map(Decoded::V1)
    }
}

fn flatten(packet: rosc::OscPacket, out: &mut Vec<rosc::OscMessage>) {
    match packet {
        rosc::OscPacket::Message(m) => out.push(m),
        // Depth was bounded by `check_nesting`.
        rosc::OscPacket::Bundle(b) => b.content.into_iter().for_each(|p| flatten(p, out)),
    }
}

/// Walks the raw bundle structure (without decoding values) so that deep
/// nesting is refused before the recursive decoder sees it; also bounds
/// array nesting in type tags. Anything else odd is left to the decoder.
fn check_nesting(bytes: &[u8], depth: usize) -> Result<(), TuioError> {
    const BUNDLE: &[u8] = b"#bundle\0";
    if bytes.starts_with(BUNDLE) {
        if depth >= MAX_BUNDLE_DEPTH {
            return Err(TuioError::TooDeep);
        }
        // "#bundle\0", an 8-byte time tag, then (size, element) pairs.
        let mut rest = bytes.get(16..).unwrap_or_default();
        while !rest.is_empty() {
            let size = match rest.get(..4) {
                Some(b) => u32::from_be_bytes([b[0], b[1], b[2], b[3]]) as usize,
                None => {
                    return Err(TuioError::Osc(format!("{} stray bytes after the last bundle element", rest.len())));
                }
            };
            // OSC elements are whole 32-bit words; a size past the end or
            // off the word grid is a damaged packet, not one to half-apply.
            let Some(element) = rest.get(4..4 + size).filter(|_| size % 4 == 0) else {
                return Err(TuioError::Osc(format!(
                    "bundle element of {size} bytes with {} left in the packet",
                    rest.len() - 4
                )));
            };
            check_nesting(element, depth + 1)?;
            rest = &rest[4 + size..];
        }
        return Ok(());
    }
    // A message: address, then the type-tag string starting with ','.
    let after_address = bytes.iter().position(|&b| b == 0).map_or(bytes.len(), |i| (i + 4) & !3);
    let tags = bytes.get(after_address..).unwrap_or_default();
    let tags = &tags[..tags.iter().position(|&b| b == 0).unwrap_or(tags.len())];
    let mut level = 0usize;
    for &t in tags {
        match t {
            b'[' => {
                level += 1;
                if level > MAX_ARRAY_DEPTH {
                    return Err(TuioError::Message {
                        address: String::from_utf8_lossy(&bytes[..after_address.min(bytes.len())])
                            .trim_end_matches('\0')
                            .to_owned(),
                        problem: format!("arrays nested deeper than {MAX_ARRAY_DEPTH}"),
                    });
                }
            }
            b']' => level = level.saturating_sub(1),
            _ => {}
        }
    }
    Ok(())
}

fn op(m: &rosc::OscMessage) -> Result<Op, TuioError> {
    let kind = match m.addr.as_str() {
        "/tuio/2Dcur" => Kind::Cursor,
        "/tuio/2Dblb" => Kind::Blob,
        _ => return Ok(Op::Ignored),
    };
    let bad = |problem: String| TuioError::Message { address: m.addr.clone(), problem };
    let Some(command) = m.args.first() else {
        return Err(bad("no command (expected source, alive, set or fseq)".into()));
    };
    let rosc::OscType::String(command) = command else {
        return Err(bad(format!("the first argument must be the command string, found {}", shown(command))));
    };
    let args = &m.args[1..];
    match command.as_str() {
        "source" => match args {
            [rosc::OscType::String(name)] => Ok(Op::Source(name.clone())),
            _ => Err(bad("`source` takes one string".into())),
        },
        "alive" => {
            let ids = args.iter().enumerate().map(|(i, a)| {
                int(a).ok_or_else(|| bad(format!("alive: argument {i} is not an int32 session id ({})", shown(a))))
            });
            Ok(Op::Alive(kind, ids.collect::<Result<_, _>>()?))
        }
        "fseq" => match args {
            [a] => int(a)
                .map(|f| Op::Fseq(kind, f))
                .ok_or_else(|| bad(format!("fseq: {} is not an int32 frame id", shown(a)))),
            _ => Err(bad(format!("fseq takes one frame id, found {} arguments", args.len()))),
        },
        "set" => {
            let need = if kind == Kind::Cursor { 3 } else { 6 };
            if args.len() < need {
                return Err(bad(format!(
                    "set needs at least {need} arguments (s x y{}), found {}",
                    if need == 6 { " a w h" } else { "" },
                    args.len()
                )));
            }
            let session =
                int(&args[0]).ok_or_else(|| bad(format!("set: session id {} is not an int32", shown(&args[0]))))?;
            let mut v = [0.0f32; 5];
            for (i, slot) in v.iter_mut().enumerate().take(need - 1) {
                *slot = float(&args[i + 1]).ok_or_else(|| {
                    bad(format!("set: argument {} ({}) is not a finite number", i + 1, shown(&args[i + 1])))
                })?;
            }
            let coord_ok = |c: f32| (-COORD_MARGIN..=1.0 + COORD_MARGIN).contains(&c);
            if !coord_ok(v[0]) || !coord_ok(v[1]) {
                return Err(bad(format!("set: position ({}, {}) is far outside 0..1", v[0], v[1])));
            }
            Ok(match kind {
                Kind::Cursor => Op::SetCursor(Cursor { session, x: v[0], y: v[1] }),
                Kind::Blob => {
                    let [x, y, angle, width, height] = v;
                    if !(width > 0.0 && width <= 2.0 && height > 0.0 && height <= 2.0) {
                        return Err(bad(format!("set: blob size {width} x {height} is not in (0, 2]")));
                    }
                    Op::SetBlob(TuioBlob { session, x, y, angle, width, height })
                }
            })
        }
        _ => Ok(Op::Ignored),
    }
}

fn int(a: &rosc::OscType) -> Option<i32> {
    match a {
        rosc::OscType::Int(i) => Some(*i),
        rosc::OscType::Long(l) => i32::try_from(*l).ok(),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rosc::{OscBundle, OscMessage, OscPacket, OscTime, OscType, encoder};

    const TABLE: [f32; 2] = [1.0, 0.75];

    fn msg(addr: &str, args: Vec<OscType>) -> OscPacket {
        OscPacket::Message(OscMessage { addr: addr.into(), args })
    }

    fn bundle(content: Vec<OscPacket>) -> Vec<u8> {
        encoder::encode(&OscPacket::Bundle(OscBundle { timetag: OscTime { seconds: 0, fractional: 1 }, content }))
            .expect("encodes")
    }

    fn s(v: &str) -> OscType {
        OscType::String(v.into())
    }

    fn cursor_frame(frame: i32, cursors: &[(i32, f32, f32)]) -> Vec<u8> {
        let mut content = vec![msg(
            "/tuio/2Dcur",
            std::iter::once(s("alive")).chain(cursors.iter().map(|c| OscType::Int(c.0))).collect(),
        )];
        for &(id, x, y) in cursors {
            content.push(msg(
                "/tuio/2Dcur",
                vec![
                    s("set"),
                    OscType::Int(id),
                    OscType::Float(x),
                    OscType::Float(y),
                    OscType::Float(0.0),
                    OscType::Float(0.0),
                    OscType::Float(0.0),
                ],
            ));
        }
        content.push(msg("/tuio/2Dcur", vec![s("fseq"), OscType::Int(frame)]));
        bundle(content)
    }

    #[test]
    fn cursors_become_fingertips_where_they_touch() {
        let mut t = TuioState::new();
        t.receive(&cursor_frame(1, &[(7, 0.5, 0.5), (8, 0.0, 0.0)]), 0.0).expect("valid");
        let hands = t.hands(TABLE, 0.0);
        assert_eq!(hands.len(), 2);
        assert!(hands.iter().all(|h| h.kind == HandKind::Fingertips(1)));
        assert_eq!([hands[0].pose.x, hands[0].pose.y], [0.0, 0.0]);
        // Top left of the surface = left, far edge of the table.
        assert_eq!([hands[1].pose.x, hands[1].pose.y], [-0.5, 0.375]);
        assert_eq!(hands[0].id, CURSOR_ID_BASE | 7);
    }

    #[test]
    fn alive_removes_and_set_waits_for_fseq() {
        let mut t = TuioState::new();
        t.receive(&cursor_frame(1, &[(1, 0.2, 0.2), (2, 0.8, 0.8)]), 0.0).expect("valid");
        // Only alive, no fseq yet: nothing changes.
        t.receive(&bundle(vec![msg("/tuio/2Dcur", vec![s("alive"), OscType::Int(2)])]), 0.1).expect("valid");
        assert_eq!(t.hands(TABLE, 0.1).len(), 2);
        t.receive(&bundle(vec![msg("/tuio/2Dcur", vec![s("fseq"), OscType::Int(2)])]), 0.1).expect("valid");
        let hands = t.hands(TABLE, 0.1);
        assert_eq!(hands.len(), 1);
        assert_eq!(hands[0].id & 0xFF_FFFF, 2);
        // An empty alive lifts everything.
        t.receive(&cursor_frame(3, &[]), 0.2).expect("valid");
        assert!(t.hands(TABLE, 0.2).is_empty());
    }

    #[test]
    fn late_frames_are_dropped_and_restarts_accepted() {
        let mut t = TuioState::new();
        t.receive(&cursor_frame(500, &[(1, 0.5, 0.5)]), 0.0).expect("valid");
        t.receive(&cursor_frame(499, &[(1, 0.9, 0.9)]), 0.0).expect("valid");
        assert_eq!(t.stats().late_frames, 1);
        assert_eq!(t.hands(TABLE, 0.0)[0].pose.x, 0.0);
        // Far lower: the tracker restarted.
        t.receive(&cursor_frame(3, &[(1, 0.9, 0.5)]), 0.0).expect("valid");
        assert!((t.hands(TABLE, 0.0)[0].pose.x - 0.4).abs() < 1e-6);
        // -1 is always applied.
        t.receive(&cursor_frame(-1, &[(1, 0.5, 0.5)]), 0.0).expect("valid");
        assert_eq!(t.hands(TABLE, 0.0)[0].pose.x, 0.0);
    }

    #[test]
    fn a_tracker_restarting_within_the_late_window_is_not_late() {
        let mut t = TuioState::new();
        for f in 1..=40 {
            t.receive(&cursor_frame(f, &[(7, 0.2, 0.5)]), f64::from(f) / 60.0).expect("valid");
        }
        // A late packet within the stream is still late.
        t.receive(&cursor_frame(38, &[(7, 0.9, 0.9)]), 41.0 / 60.0).expect("valid");
        assert_eq!(t.stats().late_frames, 1);
        // Restarted after a pause of a second: counting from 1, a new
        // session; the old cursor 7 must not come back as a ghost.
        t.receive(&cursor_frame(1, &[(1, 0.8, 0.5)]), 1.7).expect("valid");
        let hands = t.hands(TABLE, 1.7);
        assert_eq!(hands.len(), 1, "{hands:?}");
        assert!((hands[0].pose.x - 0.3).abs() < 1e-6);
        assert_eq!(t.stats().late_frames, 1);
        assert_eq!(t.stats().restarts, 1);
    }

    #[test]
    fn a_source_back_after_silence_starts_afresh() {
        let mut t = TuioState::new();
        t.receive(&cursor_frame(900, &[(1, 0.2, 0.5), (2, 0.4, 0.5)]), 0.0).expect("valid");
        // Five seconds later, frame 901 with only a `set` for session 3 and
        // no alive list: sessions 1 and 2 are from before the silence.
        let set_only = bundle(vec![
            msg("/tuio/2Dcur", vec![s("set"), OscType::Int(3), OscType::Float(0.6), OscType::Float(0.5)]),
            msg("/tuio/2Dcur", vec![s("fseq"), OscType::Int(901)]),
        ]);
        t.receive(&set_only, 5.0).expect("valid");
        assert_eq!(t.hands(TABLE, 5.0).len(), 1);
        assert_eq!(t.stats().restarts, 1);
    }

    #[test]
    fn other_profiles_and_damaged_bundles_are_counted() {
        let mut t = TuioState::new();
        t.receive(&bundle(vec![msg("/tuio/2Dobj", vec![s("fseq"), OscType::Int(1)])]), 0.0).expect("valid");
        t.receive(&bundle(vec![msg("/tuio2/sym", vec![OscType::Int(1)])]), 0.0).expect("valid");
        assert_eq!(t.stats().unknown_profile, 2);
        let mut packet = cursor_frame(5, &[(1, 0.5, 0.5)]);
        // The first element (its size at byte 16) claims a word more than
        // the packet holds after it.
        let claimed = (packet.len() - 20 + 4) as u32;
        packet[16..20].copy_from_slice(&claimed.to_be_bytes());
        assert!(t.receive(&packet, 0.1).is_err());
        let mut packet = cursor_frame(5, &[(1, 0.5, 0.5)]);
        packet.extend_from_slice(&[0, 0]);
        assert!(t.receive(&packet, 0.1).is_err(), "stray bytes after the last element");
        assert_eq!(t.stats().malformed, 2);
        assert!(t.hands(TABLE, 0.1).is_empty(), "nothing of them applied");
    }

    #[test]
    fn sources_are_separate_and_go_stale() {
        let mut t = TuioState::new();
        let from = |name: &str, id: i32, x: f32| {
            bundle(vec![
                msg("/tuio/2Dcur", vec![s("source"), s(name)]),
                msg("/tuio/2Dcur", vec![s("alive"), OscType::Int(id)]),
                msg("/tuio/2Dcur", vec![s("set"), OscType::Int(id), OscType::Float(x), OscType::Float(0.5)]),
                msg("/tuio/2Dcur", vec![s("fseq"), OscType::Int(10)]),
            ])
        };
        t.receive(&from("a@host", 1, 0.1), 0.0).expect("valid");
        t.receive(&from("b@host", 1, 0.9), 1.0).expect("valid");
        let hands = t.hands(TABLE, 1.0);
        assert_eq!(hands.len(), 2, "same session id, two sources");
        assert_ne!(hands[0].id, hands[1].id);
        // Source a last spoke at 0.0: gone after STALE_AFTER_S.
        assert_eq!(t.hands(TABLE, 2.5).len(), 1);
        assert!(t.hands(TABLE, 3.5).is_empty());
    }

    #[test]
    fn blobs_become_hands_of_their_size_and_angle() {
        let blob = |w: f32, h: f32, angle: f32| TuioBlob { session: 1, x: 0.5, y: 0.5, angle, width: w, height: h };
        // 1.5 cm across: a fingertip.
        let tip = blob_hand(&blob(0.015, 0.02, 0.0), TABLE, 1);
        assert_eq!(tip.kind, HandKind::Fingertips(1));
        // 25 x 7 cm along the table's x: a forearm lying across, length kept.
        let arm = blob_hand(&blob(0.25, 0.07 / 0.75, 0.0), TABLE, 1);
        assert_eq!(arm.kind, HandKind::Forearm);
        assert!((arm.scale - 1.0).abs() < 0.02, "{}", arm.scale);
        let [lo, hi] = extent(&arm);
        assert!((hi[0] - lo[0] - 0.25).abs() < 0.01 && hi[1] - lo[1] < 0.09, "{lo:?} {hi:?}");
        // Centred on the blob even though the arm's footprint is not
        // centred on its pose.
        assert!(centroid(&arm.patches())[0].abs() < 1e-4);
        // Turned a quarter (clockwise on screen): along the table's y,
        // where a normalized unit is the table's depth.
        let arm = blob_hand(&blob(0.25 / 0.75, 0.07, std::f32::consts::FRAC_PI_2), TABLE, 1);
        let [lo, hi] = extent(&arm);
        assert!((hi[1] - lo[1] - 0.25).abs() < 0.01 && hi[0] - lo[0] < 0.09, "{lo:?} {hi:?}");
        // A large roundish blob: a flat hand, centred.
        let hand = blob_hand(&blob(0.12, 0.18 / 0.75, 0.3), TABLE, 1);
        assert_eq!(hand.kind, HandKind::FlatHand);
        let c = centroid(&hand.patches());
        assert!(c[0].abs() < 1e-4 && c[1].abs() < 1e-4, "{c:?}");
        // Short and thin: the edge of a hand.
        assert_eq!(blob_hand(&blob(0.1, 0.02 / 0.75, 0.0), TABLE, 1).kind, HandKind::Edge);
    }

    /// A flat-hand blob is turned by its angle, fingers away from the user
    /// (table +y) whichever end of its long axis the angle names.
    #[test]
    fn a_flat_hand_blob_points_its_fingers_away_from_the_user() {
        let hand = |deg: f32| {
            let b = TuioBlob { session: 1, x: 0.5, y: 0.5, angle: deg.to_radians(), width: 0.12, height: 0.18 / 0.75 };
            let h = blob_hand(&b, TABLE, 1);
            assert_eq!(h.kind, HandKind::FlatHand, "{deg}°");
            // Fingers along local +y: (-sin, cos) of the hand's angle.
            [-h.pose.angle.sin(), h.pose.angle.cos()]
        };
        // Upright on screen (angle 0): fingers straight up the table.
        let up = hand(0.0);
        assert!(up[1] > 0.999, "{up:?}");
        for deg in [0.0_f32, 20.0, -30.0, 10.0] {
            let (a, b) = (hand(deg), hand(deg + 180.0));
            assert!(a[1] > 0.0, "{deg}°: fingers {a:?}");
            assert!((a[0] - b[0]).abs() < 1e-4 && (a[1] - b[1]).abs() < 1e-4, "{deg}°: {a:?} against {b:?}");
        }
        // Turned clockwise on screen: fingers lean right (+x); anticlockwise, left.
        assert!(hand(20.0)[0] > 0.2 && hand(-30.0)[0] < -0.3, "{:?} {:?}", hand(20.0), hand(-30.0));
    }

    fn extent(hand: &Hand) -> [[f32; 2]; 2] {
        hand.bounds()
    }

    #[test]
    fn blob_frames_apply_like_cursor_frames() {
        let mut t = TuioState::new();
        let set = msg(
            "/tuio/2Dblb",
            [s("set"), OscType::Int(5)]
                .into_iter()
                .chain([0.25f32, 0.5, 0.0, 0.2, 0.05, 0.01, 0.0, 0.0, 0.0, 0.0, 0.0].map(OscType::Float))
                .collect(),
        );
        let packet = bundle(vec![
            msg("/tuio/2Dblb", vec![s("alive"), OscType::Int(5)]),
            set,
            msg("/tuio/2Dblb", vec![s("fseq"), OscType::Int(1)]),
        ]);
        t.receive(&packet, 0.0).expect("valid");
        let hands = t.hands(TABLE, 0.0);
        assert_eq!(hands.len(), 1);
        assert_eq!(hands[0].id, BLOB_ID_BASE | 5);
        assert_eq!(hands[0].kind, HandKind::Forearm);
    }

    #[test]
    fn malformed_packets_are_counted_and_change_nothing() {
        let mut t = TuioState::new();
        t.receive(&cursor_frame(1, &[(1, 0.5, 0.5)]), 0.0).expect("valid");
        let bad: Vec<Vec<u8>> = vec![
            Vec::new(),
            b"garbage".to_vec(),
            vec![0xFF; 64],
            // A valid alive, then a set with a string where x goes: the whole packet is refused.
            bundle(vec![
                msg("/tuio/2Dcur", vec![s("alive")]),
                msg("/tuio/2Dcur", vec![s("set"), OscType::Int(1), s("x"), OscType::Float(0.5)]),
                msg("/tuio/2Dcur", vec![s("fseq"), OscType::Int(2)]),
            ]),
            bundle(vec![msg(
                "/tuio/2Dcur",
                vec![s("set"), OscType::Int(1), OscType::Float(f32::NAN), OscType::Float(0.5)],
            )]),
            bundle(vec![msg("/tuio/2Dcur", vec![s("set"), OscType::Int(1), OscType::Float(1e9), OscType::Float(0.5)])]),
            bundle(vec![msg(
                "/tuio/2Dblb",
                vec![
                    s("set"),
                    OscType::Int(1),
                    OscType::Float(0.5),
                    OscType::Float(0.5),
                    OscType::Float(0.0),
                    OscType::Float(-1.0),
                    OscType::Float(0.1),
                ],
            )]),
            bundle(vec![msg("/tuio/2Dcur", vec![s("fseq")])]),
            bundle(vec![msg("/tuio/2Dcur", vec![OscType::Int(3)])]),
            bundle(vec![msg("/tuio/2Dcur", vec![])]),
        ];
        for (i, p) in bad.iter().enumerate() {
            assert!(t.receive(p, 0.0).is_err(), "packet {i} should be refused");
        }
        assert_eq!(t.stats().malformed, bad.len() as u64);
        assert_eq!(t.hands(TABLE, 0.0).len(), 1, "nothing of a refused packet is applied");
        // Truncations of a valid packet never panic.
        let good = cursor_frame(9, &[(1, 0.1, 0.1), (2, 0.3, 0.3)]);
        for n in 0..good.len() {
            let _ = t.receive(&good[..n], 0.0);
        }
        // Other profiles and commands are skipped, not refused.
        t.receive(&bundle(vec![msg("/tuio/2Dobj", vec![s("alive")]), msg("/tuio/2Dcur", vec![s("hello")])]), 0.0)
            .expect("valid");
        assert_eq!(t.stats().ignored_messages, 2);
    }

    #[test]
    fn deep_nesting_is_refused_before_decoding() {
        let mut packet = encoder::encode(&msg("/tuio/2Dcur", vec![s("fseq"), OscType::Int(1)])).expect("encodes");
        for _ in 0..50 {
            let mut b = b"#bundle\0".to_vec();
            b.extend_from_slice(&[0, 0, 0, 0, 0, 0, 0, 1]);
            b.extend_from_slice(&(packet.len() as u32).to_be_bytes());
            b.extend_from_slice(&packet);
            packet = b;
        }
        let mut t = TuioState::new();
        assert_eq!(t.receive(&packet, 0.0), Err(TuioError::TooDeep));
        // Deeply nested arrays in the type tags.
        let mut m = b"/tuio/2Dcur\0,".to_vec();
        m.extend(std::iter::repeat_n(b'[', 10_000));
        m.extend(std::iter::repeat_n(b']', 10_000));
        m.extend_from_slice(b"\0\0\0\0");
        assert!(t.receive(&m, 0.0).is_err());
        assert_eq!(t.stats().malformed, 2);
    }
}
