//! TUIO 2.0 input (the 2014 specification, <http://www.tuio.org/?tuio20>):
//! a tracker's components (pointers, tokens, bounds, contours, area spans,
//! skeletons) decoded into [`Hand`]s. Pure, like the 1.1 decoder it sits
//! beside; [`super::TuioState`] sends each packet here when any of its
//! messages is `/tuio2/...` (version detected per packet).
//!
//! | message | arguments | becomes |
//! |---|---|---|
//! | `frm` | `f_id time [dim source]` | opens a frame of the source named `source` (`""` when left out) |
//! | `alv` | `s_id...` | closes the frame: its messages are applied, sessions not listed are removed |
//! | `ptr` | `s_id tu_id c_id x y angle shear radius press [5 speeds]` | a fingertip at (x, y) when the session has no shape; its pressure is the session's grey level |
//! | `tok` | `s_id tu_id c_id x y angle [5 speeds]` | kept ([`TuioState::tokens`]): a token's footprint is unknown, so it is drawn only through its `bnd`/`ocg`/`arg` |
//! | `bnd` | `s_id x y angle width height area [5 speeds]` | without a contour or spans: the ellipse inside the bounding box (a 48-gon) |
//! | `ocg` | `s_id x0 y0 ... xn yn` | the outer contour, filled, drawn as it is |
//! | `icg` | `s_id x0 y0 ... [true x0 y0 ...]` | inner contours (`true` separates them), cut out of the outer one |
//! | `arg` | `s_id x0 y0 w0 ... xn yn wn` | without a contour: the spans filled, each one sensor row high |
//! | `skg` | `s_id x0 y0 x1 y1 [node] ...` | decoded and checked, kept as metadata ([`TuioState::skeletons`]), not drawn |
//!
//! Other `/tuio2/` messages (`sym`, `ctl`, `dat`, `lia`, `chg`, ...) and
//! `/tuio/` messages inside a 2.0 packet are counted as ignored.
//!
//! **Shapes.** A session is one hand: its `ocg` (with its `icg` holes) if it
//! has one, else its `arg` spans, else its `bnd` ellipse, else its `ptr`
//! fingertip. Shapes become [`HandKind::Contour`] hands, rasterized as
//! they are (even-odd, so holes work whichever way a tracker winds them).
//! A `ptr` of the same session gives the grey level: `press` in (0, 1] as
//! is; 0, which the specification's own examples send for "no pressure
//! data", as full pressure; below 0 (hovering, per the specification) as
//! not touching. Attributes persist until sent again, as the specification
//! has servers send only what changed; an `ocg` drops the session's old
//! `icg` unless the same frame sends new ones (holes belong to their
//! contour). An `arg` span is one sensor row high: `1 / height` from the
//! frame's `dim` (width in the high 16 bits, height in the low), or the
//! smallest gap between the spans' rows when that is smaller or `dim` is 0.
//!
//! **Skeletons** (`skg`) are a tree of points with no width: the spec's
//! point list walks from a leaf, and an integer `n` steps back `n` nodes
//! before the next branch (`n` less than the nodes on the walk). The contact
//! image shows area, which a skeleton does not give, so it is not drawn;
//! it is kept so that an application can show it.
//!
//! **Frames** follow the reference client: a frame is `frm`, then the
//! components, then `alv`; it may span packets. Per source, a frame id
//! below the last one is a late packet and the frame is dropped, unless it
//! is far below or comes after a pause: then the tracker restarted and its
//! old sessions are dropped (the same rule as TUIO 1.1, see
//! [`super::decode`]). Frame id 0 is reserved and always accepted. A `frm`
//! arriving while a frame is open drops the open one (its `alv` was lost).
//! Components outside a frame are ignored.
//!
//! **Hand ids**: `0x8000_0000 | source << 24 | s` (`s` the low 24 bits of
//! the session id), apart from the 1.1 ranges.

use std::sync::Arc;

use rosc::{OscMessage, OscType};

use super::protocol::{COORD_MARGIN, Commit, STALE_AFTER_S, TuioError, TuioStats, float, frame_order, shown, to_table};
use crate::pipeline::surface::{Hand, HandKind, Outline};

/// Hand-id namespace of TUIO 2.0 sessions (module doc).
pub const TUIO2_ID_BASE: u32 = 0x8000_0000;
/// Sides of the polygon a `bnd` ellipse is drawn as: within 0.2 % of the
/// ellipse's radius, a hundredth of a pixel for a 5 cm blob.
const ELLIPSE_SIDES: usize = 48;
/// Rows assumed for `arg` spans when neither `dim` nor the spans say.
const DEFAULT_ROWS: f32 = 480.0;

/// A `/tuio2/ptr` pointer, normalized coordinates.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Pointer {
    pub session: u32,
    pub type_user: u32,
    pub component: u32,
    pub x: f32,
    pub y: f32,
    pub angle: f32,
    pub shear: f32,
    pub radius: f32,
    pub pressure: f32,
}

/// A `/tuio2/tok` token (a tagged object), normalized coordinates.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Token {
    pub session: u32,
    pub type_user: u32,
    pub component: u32,
    pub x: f32,
    pub y: f32,
    pub angle: f32,
}

/// A `/tuio2/bnd` bounding ellipse: centre, the angle of its major axis
/// (from +x towards +y of the surface), its axes' full lengths and area,
/// normalized.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Bounds {
    pub x: f32,
    pub y: f32,
    pub angle: f32,
    pub width: f32,
    pub height: f32,
    pub area: f32,
}

/// One `/tuio2/arg` span: a row from (x, y) to (x + width, y), normalized.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Span {
    pub x: f32,
    pub y: f32,
    pub width: f32,
}

/// A `/tuio2/skg` skeleton: its nodes (normalized) and the edges between
/// them (node indices).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Skeleton {
    pub nodes: Vec<[f32; 2]>,
    pub edges: Vec<[usize; 2]>,
}

/// One decoded 2.0 message, before anything is applied.
#[derive(Debug, Clone, PartialEq)]
pub(super) enum Op2 {
    Frame { frame: u32, dim: u32, source: String },
    Alive(Vec<u32>),
    Pointer(Pointer),
    Token(Token),
    Bounds(u32, Bounds),
    Outer(u32, Vec<[f32; 2]>),
    Inner(u32, Vec<Vec<[f32; 2]>>),
    Area(u32, Vec<Span>),
    Skeleton(u32, Skeleton),
    Ignored,
}

/// What a session has said about itself.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Component {
    pub pointer: Option<Pointer>,
    pub token: Option<Token>,
    pub bounds: Option<Bounds>,
    pub outer: Option<Arc<Vec<[f32; 2]>>>,
    pub inner: Arc<Vec<Vec<[f32; 2]>>>,
    pub area: Option<Arc<Vec<Span>>>,
    /// Height of one `arg` span (normalized), fixed when the spans arrived.
    pub row: f32,
    pub skeleton: Option<Arc<Skeleton>>,
}

impl Component {
    /// Whether it has a shape to draw (else it is a pointer, or nothing).
    pub fn has_shape(&self) -> bool {
        self.outer.is_some() || self.area.is_some() || self.bounds.is_some()
    }
}

#[derive(Debug, Clone)]
struct Source {
    name: String,
    index: u32,
    last_seen: f64,
    last_frame: i64,
    sessions: Vec<(u32, Component)>,
}

/// A frame between its `frm` and its `alv`.
#[derive(Debug, Clone)]
struct Open {
    source: usize,
    frame: i64,
    /// Sensor rows from `dim` (0: not given).
    rows: u32,
    /// Seconds since the source's previous frame.
    gap: f64,
    pending: Vec<Op2>,
}

/// Every TUIO 2.0 source heard so far.
#[derive(Debug, Clone, Default)]
pub(super) struct State2 {
    sources: Vec<Source>,
    open: Option<Open>,
}

impl State2 {
    /// Applies the decoded messages of one packet that arrived at `now`.
    pub(super) fn apply(&mut self, ops: Vec<Op2>, now: f64, stats: &mut TuioStats) {
        for op in ops {
            match op {
                Op2::Frame { frame, dim, source } => {
                    if self.open.take().is_some() {
                        stats.incomplete_frames += 1;
                        tracing::debug!("TUIO 2.0: a frame ended without its alv and was dropped");
                    }
                    let index = self.source_index(&source);
                    let s = &mut self.sources[index];
                    let gap = now - s.last_seen;
                    if s.last_seen.is_finite() && gap > STALE_AFTER_S {
                        tracing::info!(
                            "TUIO 2.0 source '{source}' is back after {gap:.1} s: its old touches are dropped"
                        );
                        s.sessions.clear();
                        s.last_frame = 0;
                        stats.restarts += 1;
                    }
                    s.last_seen = now;
                    self.open = Some(Open {
                        source: index,
                        frame: i64::from(frame),
                        rows: dim & 0xFFFF,
                        gap,
                        pending: Vec::new(),
                    });
                }
                Op2::Alive(alive) => match self.open.take() {
                    Some(open) => self.commit(open, &alive, stats),
                    None => stats.ignored_messages += 1,
                },
                Op2::Ignored => stats.ignored_messages += 1,
                component => match &mut self.open {
                    Some(open) => open.pending.push(component),
                    None => stats.ignored_messages += 1,
                },
            }
        }
    }

    fn source_index(&mut self, name: &str) -> usize {
        if let Some(i) = self.sources.iter().position(|s| s.name == name) {
            return i;
        }
        self.sources.push(Source {
            name: name.to_owned(),
            index: self.sources.len() as u32,
            last_seen: f64::NEG_INFINITY,
            last_frame: 0,
            sessions: Vec::new(),
        });
        self.sources.len() - 1
    }

    /// Ends a frame with its alive list.
    fn commit(&mut self, open: Open, alive: &[u32], stats: &mut TuioStats) {
        let source = &mut self.sources[open.source];
        match frame_order(open.frame, source.last_frame, open.gap) {
            Commit::Late => {
                stats.late_frames += 1;
                tracing::debug!("TUIO 2.0 source '{}': frame {} came late and was dropped", source.name, open.frame);
                return;
            }
            Commit::Restarted => {
                stats.restarts += 1;
                tracing::info!("TUIO 2.0 source '{}' restarted (frame {})", source.name, open.frame);
                source.sessions.clear();
            }
            Commit::Applied => {}
        }
        if open.frame > 0 {
            source.last_frame = open.frame;
        }
        // An ocg without icg in the same frame drops the old holes.
        let mut new_outer: Vec<u32> = Vec::new();
        for op in open.pending {
            let session = match &op {
                Op2::Pointer(p) => p.session,
                Op2::Token(t) => t.session,
                Op2::Bounds(s, _) | Op2::Outer(s, _) | Op2::Inner(s, _) | Op2::Area(s, _) | Op2::Skeleton(s, _) => *s,
                Op2::Frame { .. } | Op2::Alive(_) | Op2::Ignored => continue,
            };
            let i = source.sessions.iter().position(|(s, _)| *s == session).unwrap_or_else(|| {
                source.sessions.push((session, Component::default()));
                source.sessions.len() - 1
            });
            let c = &mut source.sessions[i].1;
            match op {
                Op2::Pointer(p) => c.pointer = Some(p),
                Op2::Token(t) => c.token = Some(t),
                Op2::Bounds(_, b) => c.bounds = Some(b),
                Op2::Outer(_, points) => {
                    c.outer = Some(Arc::new(points));
                    if !new_outer.contains(&session) {
                        c.inner = Arc::default();
                        new_outer.push(session);
                    }
                }
                Op2::Inner(_, rings) => {
                    let mut all = if new_outer.contains(&session) { (*c.inner).clone() } else { Vec::new() };
                    all.extend(rings);
                    c.inner = Arc::new(all);
                    new_outer.push(session);
                }
                Op2::Area(_, spans) => {
                    c.row = row_height(&spans, open.rows);
                    c.area = Some(Arc::new(spans));
                }
                Op2::Skeleton(_, skeleton) => c.skeleton = Some(Arc::new(skeleton)),
                Op2::Frame { .. } | Op2::Alive(_) | Op2::Ignored => {}
            }
        }
        source.sessions.retain(|(s, _)| alive.contains(s));
    }

    /// Live components of sources heard from in the last [`STALE_AFTER_S`]
    /// seconds, with their hand ids.
    fn live(&self, now: f64) -> impl Iterator<Item = (u32, &Component)> {
        self.sources.iter().filter(move |s| now - s.last_seen <= STALE_AFTER_S).flat_map(|s| {
            let ns = (s.index % 32) << 24;
            s.sessions.iter().map(move |(session, c)| (TUIO2_ID_BASE | ns | (session & 0x00FF_FFFF), c))
        })
    }

    pub(super) fn hands(&self, table: [f32; 2], now: f64, out: &mut Vec<Hand>) {
        out.extend(self.live(now).filter_map(|(id, c)| component_hand(c, table, id)));
    }

    /// Live (pointers without a shape, components with one).
    pub(super) fn counts(&self, now: f64) -> (usize, usize) {
        self.live(now).fold(
            (0, 0),
            |(p, s), (_, c)| {
                if c.has_shape() { (p, s + 1) } else { (p + usize::from(c.pointer.is_some()), s) }
            },
        )
    }

    pub(super) fn tokens(&self, table: [f32; 2], now: f64) -> Vec<(u32, Token, [f32; 2])> {
        self.live(now).filter_map(|(id, c)| c.token.map(|t| (id, t, to_table([t.x, t.y], table)))).collect()
    }

    pub(super) fn skeletons(&self, table: [f32; 2], now: f64) -> Vec<(u32, Vec<[[f32; 2]; 2]>)> {
        self.live(now)
            .filter_map(|(id, c)| {
                let s = c.skeleton.as_ref()?;
                let at = |i: usize| to_table(s.nodes[i], table);
                Some((id, s.edges.iter().map(|&[a, b]| [at(a), at(b)]).collect()))
            })
            .collect()
    }
}

/// The grey level a pointer's `press` stands for (module doc); `None`:
/// hovering.
fn pointer_pressure(press: f32) -> Option<f32> {
    if press > 0.0 {
        Some(press.min(1.0))
    } else if press == 0.0 {
        Some(1.0)
    } else {
        None
    }
}

/// The height of one span row (module doc).
fn row_height(spans: &[Span], rows: u32) -> f32 {
    let mut ys: Vec<f32> = spans.iter().map(|s| s.y).collect();
    ys.sort_unstable_by(f32::total_cmp);
    let gap = ys.windows(2).map(|w| w[1] - w[0]).filter(|&g| g > 1e-7).fold(f32::INFINITY, f32::min);
    let from_dim = if rows > 0 { 1.0 / rows as f32 } else { f32::INFINITY };
    let row = gap.min(from_dim);
    if row.is_finite() { row } else { 1.0 / DEFAULT_ROWS }
}

/// The hand a session is (module doc), or `None` when it draws nothing.
fn component_hand(c: &Component, table: [f32; 2], id: u32) -> Option<Hand> {
    let pressure = match &c.pointer {
        Some(p) => pointer_pressure(p.pressure)?,
        None => 1.0,
    };
    let normalized: Option<Vec<Vec<[f32; 2]>>> = if let Some(outer) = &c.outer {
        Some(std::iter::once(outer.to_vec()).chain(c.inner.iter().cloned()).collect())
    } else if let Some(spans) = &c.area {
        Some(span_rings(spans, c.row))
    } else {
        c.bounds.map(|b| vec![ellipse(&b)])
    };
    match normalized {
        Some(rings) => {
            let rings = rings.into_iter().map(|r| r.into_iter().map(|p| to_table(p, table)).collect()).collect();
            match Outline::new(rings) {
                Ok(outline) => Some(Hand::contour(id, &outline).with_pressure(pressure)),
                Err(e) => {
                    tracing::debug!("TUIO 2.0 session {id:#x}: shape not drawn: {e}");
                    None
                }
            }
        }
        None => c.pointer.map(|p| {
            let [x, y] = to_table([p.x, p.y], table);
            Hand::new(id, HandKind::Fingertips(1), x, y).with_pressure(pressure)
        }),
    }
}

/// The boundary of the spans' union as rings (normalized coordinates).
///
/// Not one rectangle per span: the rasterizer's soft edge comes from the
/// distance to the nearest edge, and the edges between stacked rows would
/// darken every row boundary inside the shape. Each row's spans are
/// joined; a row's top edge is kept only where the row above does not
/// cover it, its bottom edge only where the row below does not; the
/// remaining edges, all running clockwise on the screen, are chained into
/// rings.
fn span_rings(spans: &[Span], row: f32) -> Vec<Vec<[f32; 2]>> {
    let mut sorted = spans.to_vec();
    sorted.sort_unstable_by(|a, b| a.y.total_cmp(&b.y).then(a.x.total_cmp(&b.x)));
    // (y, joined intervals) per row, rows in order.
    let mut rows: Vec<(f32, Vec<[f32; 2]>)> = Vec::new();
    for s in sorted.into_iter().filter(|s| s.width > 0.0) {
        let (a, b) = (s.x, s.x + s.width);
        match rows.last_mut() {
            Some((y, intervals)) if *y == s.y => match intervals.last_mut() {
                Some(last) if a <= last[1] => last[1] = last[1].max(b),
                _ => intervals.push([a, b]),
            },
            _ => rows.push((s.y, vec![[a, b]])),
        }
    }
    // Rows closer than a row and a half are neighbours, sharing one y.
    let adjacent = |i: usize, j: usize| (rows[j].0 - rows[i].0 - row).abs() < 0.5 * row;
    let mut edges: Vec<[[f32; 2]; 2]> = Vec::new();
    for i in 0..rows.len() {
        let top = rows[i].0;
        let below = (i + 1 < rows.len() && adjacent(i, i + 1)).then(|| i + 1);
        let above = (i > 0 && adjacent(i - 1, i)).then(|| i - 1);
        let bottom = below.map_or(top + row, |j| rows[j].0);
        let none: &[[f32; 2]] = &[];
        let over = above.map_or(none, |j| &rows[j].1[..]);
        let under = below.map_or(none, |j| &rows[j].1[..]);
        for &[a, b] in &rows[i].1 {
            edges.push([[b, top], [b, bottom]]);
            edges.push([[a, bottom], [a, top]]);
            for [x0, x1] in minus([a, b], over) {
                edges.push([[x0, top], [x1, top]]);
            }
            for [x0, x1] in minus([a, b], under) {
                edges.push([[x1, bottom], [x0, bottom]]);
            }
        }
    }
    chain(&edges)
}

/// `[a, b]` minus the sorted, disjoint `cut` intervals.
fn minus([a, b]: [f32; 2], cut: &[[f32; 2]]) -> Vec<[f32; 2]> {
    let mut out = Vec::new();
    let mut from = a;
    for &[c, d] in cut {
        if d <= from || c >= b {
            continue;
        }
        if c > from {
            out.push([from, c]);
        }
        from = from.max(d);
    }
    if from < b {
        out.push([from, b]);
    }
    out
}

/// Directed edges, each ending where another starts, joined into rings.
fn chain(edges: &[[[f32; 2]; 2]]) -> Vec<Vec<[f32; 2]>> {
    let key = |p: [f32; 2]| (p[0].to_bits(), p[1].to_bits());
    let mut starting: std::collections::HashMap<(u32, u32), Vec<usize>> = std::collections::HashMap::new();
    for (i, e) in edges.iter().enumerate() {
        starting.entry(key(e[0])).or_default().push(i);
    }
    let mut used = vec![false; edges.len()];
    let mut rings = Vec::new();
    for first in 0..edges.len() {
        if used[first] {
            continue;
        }
        let mut ring = Vec::new();
        let mut at = first;
        loop {
            used[at] = true;
            ring.push(edges[at][0]);
            let next = starting.get(&key(edges[at][1])).and_then(|c| c.iter().copied().find(|&j| !used[j]));
            match next {
                Some(j) => at = j,
                None => break,
            }
        }
        if ring.len() >= crate::pipeline::surface::MIN_RING_POINTS {
            rings.push(ring);
        }
    }
    rings
}

/// The ellipse inside a bounding box as a polygon, normalized coordinates
/// (axes turned in the surface's own frame, as `2Dblb` blobs are).
fn ellipse(b: &Bounds) -> Vec<[f32; 2]> {
    let (sin, cos) = b.angle.sin_cos();
    (0..ELLIPSE_SIDES)
        .map(|i| {
            let t = std::f32::consts::TAU * i as f32 / ELLIPSE_SIDES as f32;
            let (u, v) = (0.5 * b.width * t.cos(), 0.5 * b.height * t.sin());
            [b.x + u * cos - v * sin, b.y + u * sin + v * cos]
        })
        .collect()
}

// ---------------------------------------------------------------------------
// Decoding: every argument checked, so that a packet is applied whole or not
// at all.

/// One TUIO 2.0 message decoded into an operation.
///
/// One piece on purpose: a decoder, one match arm per message of the
/// specification, each checking its own arguments; split, a message's
/// layout would be spread over helpers that each know one field.
#[allow(clippy::too_many_lines, reason = "a decoder: one arm per TUIO 2.0 message")]
pub(super) fn op(m: &OscMessage) -> Result<Op2, TuioError> {
    let Some(name) = m.addr.strip_prefix("/tuio2/") else {
        return Ok(Op2::Ignored);
    };
    let bad = |problem: String| TuioError::Message { address: m.addr.clone(), problem };
    let args = &m.args;
    let session = || match args.first() {
        Some(a) => id(a).ok_or_else(|| bad(format!("the session id must be an int32, found {}", shown(a)))),
        None => Err(bad("no arguments; the session id comes first".into())),
    };
    // The type/user id and component id after the session id (ptr, tok).
    let type_user_component = || match [1, 2].map(|i| args.get(i).and_then(id)) {
        [Some(type_user), Some(component)] => Ok((type_user, component)),
        _ => Err(bad("tu_id and c_id must be int32".into())),
    };
    // Floats at `range` of the arguments, each finite.
    let floats = |range: std::ops::Range<usize>| -> Result<Vec<f32>, TuioError> {
        range
            .map(|i| {
                let a = &args[i];
                float(a).ok_or_else(|| bad(format!("argument {i} ({}) is not a finite number", shown(a))))
            })
            .collect()
    };
    let position = |x: f32, y: f32| {
        let ok = |c: f32| (-COORD_MARGIN..=1.0 + COORD_MARGIN).contains(&c);
        if ok(x) && ok(y) { Ok(()) } else { Err(bad(format!("position ({x}, {y}) is far outside 0..1"))) }
    };
    // Fixed arguments, then either nothing or exactly the optional ones.
    let count = |fixed: usize, optional: usize, names: &str| {
        if args.len() == fixed || args.len() == fixed + optional {
            Ok(())
        } else {
            Err(bad(format!(
                "takes {fixed} arguments ({names}){}, found {}",
                if optional > 0 { format!(" or {} with speeds", fixed + optional) } else { String::new() },
                args.len()
            )))
        }
    };
    match name {
        "frm" => {
            let Some(first) = args.first() else {
                return Err(bad("no frame id".into()));
            };
            let frame = id(first).ok_or_else(|| bad(format!("frame id {} is not an int32", shown(first))))?;
            if let Some(t) = args.get(1).filter(|a| !matches!(a, OscType::Time(_))) {
                return Err(bad(format!("argument 1 must be the OSC time tag, found {}", shown(t))));
            }
            let dim = match args.get(2) {
                None => 0,
                Some(a) => id(a).ok_or_else(|| bad(format!("dimension {} is not an int32", shown(a))))?,
            };
            let source = match args.get(3) {
                None => String::new(),
                Some(OscType::String(s)) => s.clone(),
                Some(a) => return Err(bad(format!("the source must be a string, found {}", shown(a)))),
            };
            if args.len() > 4 {
                return Err(bad(format!("takes at most 4 arguments (f_id time dim source), found {}", args.len())));
            }
            Ok(Op2::Frame { frame, dim, source })
        }
        "alv" => args
            .iter()
            .enumerate()
            .map(|(i, a)| id(a).ok_or_else(|| bad(format!("argument {i} ({}) is not an int32 session id", shown(a)))))
            .collect::<Result<_, _>>()
            .map(Op2::Alive),
        "ptr" => {
            count(9, 5, "s_id tu_id c_id x y angle shear radius press")?;
            let s = session()?;
            let (type_user, component) = type_user_component()?;
            let v = floats(3..args.len())?;
            position(v[0], v[1])?;
            if !(0.0..=2.0).contains(&v[4]) {
                return Err(bad(format!("radius {} is not in 0..=2", v[4])));
            }
            Ok(Op2::Pointer(Pointer {
                session: s,
                type_user,
                component,
                x: v[0],
                y: v[1],
                angle: v[2],
                shear: v[3],
                radius: v[4],
                pressure: v[5],
            }))
        }
        "tok" => {
            count(6, 5, "s_id tu_id c_id x y angle")?;
            let s = session()?;
            let (type_user, component) = type_user_component()?;
            let v = floats(3..args.len())?;
            position(v[0], v[1])?;
            Ok(Op2::Token(Token { session: s, type_user, component, x: v[0], y: v[1], angle: v[2] }))
        }
        "bnd" => {
            count(7, 5, "s_id x y angle width height area")?;
            let s = session()?;
            let v = floats(1..args.len())?;
            position(v[0], v[1])?;
            let (width, height) = (v[3], v[4]);
            if !(width > 0.0 && width <= 2.0 && height > 0.0 && height <= 2.0) {
                return Err(bad(format!("size {width} x {height} is not in (0, 2]")));
            }
            Ok(Op2::Bounds(s, Bounds { x: v[0], y: v[1], angle: v[2], width, height, area: v[5] }))
        }
        "ocg" => {
            let s = session()?;
            let points = pairs(&args[1..], &bad)?;
            ring(&points, "the contour", &bad)?;
            points.iter().try_for_each(|p| position(p[0], p[1]))?;
            Ok(Op2::Outer(s, points))
        }
        "icg" => {
            let s = session()?;
            let mut rings = Vec::new();
            for part in args[1..].split(|a| matches!(a, OscType::Bool(true))) {
                let points = pairs(part, &bad)?;
                ring(&points, &format!("inner contour {}", rings.len()), &bad)?;
                points.iter().try_for_each(|p| position(p[0], p[1]))?;
                rings.push(points);
            }
            Ok(Op2::Inner(s, rings))
        }
        "arg" => {
            let s = session()?;
            let rest = &args[1..];
            if rest.is_empty() || !rest.len().is_multiple_of(3) {
                return Err(bad(format!("spans come as x y w triples; found {} numbers", rest.len())));
            }
            let v = floats(1..args.len())?;
            let spans: Vec<Span> = v.chunks_exact(3).map(|c| Span { x: c[0], y: c[1], width: c[2] }).collect();
            for sp in &spans {
                position(sp.x, sp.y)?;
                if !(sp.width >= 0.0 && sp.width <= 2.0) {
                    return Err(bad(format!("span width {} is not in 0..=2", sp.width)));
                }
            }
            if spans.len() * 4 > crate::pipeline::surface::MAX_OUTLINE_POINTS {
                return Err(bad(format!(
                    "{} spans; at most {}",
                    spans.len(),
                    crate::pipeline::surface::MAX_OUTLINE_POINTS / 4
                )));
            }
            Ok(Op2::Area(s, spans))
        }
        "skg" => {
            let s = session()?;
            let skeleton = skeleton(&args[1..], &bad)?;
            skeleton.nodes.iter().try_for_each(|p| position(p[0], p[1]))?;
            Ok(Op2::Skeleton(s, skeleton))
        }
        _ => Ok(Op2::Ignored),
    }
}

/// An id (session, frame, dimension): an int32 read as the unsigned value
/// the specification means.
fn id(a: &OscType) -> Option<u32> {
    match a {
        OscType::Int(i) => Some(*i as u32),
        OscType::Long(l) => u32::try_from(*l).ok(),
        _ => None,
    }
}

/// Coordinates as (x, y) pairs, each finite.
fn pairs(args: &[OscType], bad: &dyn Fn(String) -> TuioError) -> Result<Vec<[f32; 2]>, TuioError> {
    if !args.len().is_multiple_of(2) {
        return Err(bad(format!("coordinates come in x y pairs; found {} numbers", args.len())));
    }
    args.chunks_exact(2)
        .map(|c| match (float(&c[0]), float(&c[1])) {
            (Some(x), Some(y)) => Ok([x, y]),
            _ => Err(bad(format!("point ({}, {}) is not two finite numbers", shown(&c[0]), shown(&c[1])))),
        })
        .collect()
}

fn ring(points: &[[f32; 2]], what: &str, bad: &dyn Fn(String) -> TuioError) -> Result<(), TuioError> {
    use crate::pipeline::surface::{MAX_OUTLINE_POINTS, MIN_RING_POINTS};
    if points.len() < MIN_RING_POINTS {
        return Err(bad(format!("{what} has {} points; at least {MIN_RING_POINTS}", points.len())));
    }
    if points.len() > MAX_OUTLINE_POINTS {
        return Err(bad(format!("{what} has {} points; at most {MAX_OUTLINE_POINTS}", points.len())));
    }
    Ok(())
}

/// The skeleton's walk (module doc): float pairs are nodes joined to the
/// node before them on the walk; an int steps back that many nodes.
fn skeleton(args: &[OscType], bad: &dyn Fn(String) -> TuioError) -> Result<Skeleton, TuioError> {
    let mut s = Skeleton::default();
    let mut walk: Vec<usize> = Vec::new();
    let mut i = 0;
    while i < args.len() {
        match &args[i] {
            OscType::Int(n) => {
                let n = usize::try_from(*n).ok().filter(|&n| n < walk.len()).ok_or_else(|| {
                    bad(format!("node {n} at argument {}: steps back past the walk's {} nodes", i + 1, walk.len()))
                })?;
                walk.truncate(walk.len() - n);
                i += 1;
            }
            OscType::Float(_) | OscType::Double(_) => {
                let (Some(x), Some(y)) = (float(&args[i]), args.get(i + 1).and_then(float)) else {
                    return Err(bad(format!("argument {}: a node needs two finite numbers", i + 1)));
                };
                let node = s.nodes.len();
                s.nodes.push([x, y]);
                if let Some(&from) = walk.last() {
                    s.edges.push([from, node]);
                }
                walk.push(node);
                i += 2;
            }
            other => {
                return Err(bad(format!("argument {}: {} is neither a coordinate nor a node", i + 1, shown(other))));
            }
        }
    }
    if s.nodes.len() < 2 {
        return Err(bad(format!("{} nodes; a skeleton needs at least 2", s.nodes.len())));
    }
    if s.nodes.len() > crate::pipeline::surface::MAX_OUTLINE_POINTS {
        return Err(bad(format!("{} nodes; at most {}", s.nodes.len(), crate::pipeline::surface::MAX_OUTLINE_POINTS)));
    }
    Ok(s)
}

#[cfg(test)]
mod tests {
    use super::super::TuioState;
    use super::*;
    use crate::pipeline::surface::{RasterParams, Sensor, rasterize};
    use rosc::{OscBundle, OscPacket, OscTime, encoder};

    const TABLE: [f32; 2] = [1.0, 0.75];

    fn msg(addr: &str, args: Vec<OscType>) -> OscPacket {
        OscPacket::Message(OscMessage { addr: format!("/tuio2/{addr}"), args })
    }

    fn bundle(content: Vec<OscPacket>) -> Vec<u8> {
        encoder::encode(&OscPacket::Bundle(OscBundle { timetag: OscTime { seconds: 0, fractional: 1 }, content }))
            .expect("encodes")
    }

    fn frm(frame: i32, source: &str) -> OscPacket {
        msg(
            "frm",
            vec![
                OscType::Int(frame),
                OscType::Time(OscTime { seconds: 0, fractional: 1 }),
                OscType::Int((640 << 16) | 0x1E0),
                OscType::String(source.into()),
            ],
        )
    }

    fn alv(ids: &[i32]) -> OscPacket {
        msg("alv", ids.iter().map(|&i| OscType::Int(i)).collect())
    }

    /// One frame: `frm`, the components, `alv` of the given ids.
    fn frame(frame: i32, components: Vec<OscPacket>, alive: &[i32]) -> Vec<u8> {
        let mut content = vec![frm(frame, "test:0@0x7F000001")];
        content.extend(components);
        content.push(alv(alive));
        bundle(content)
    }

    fn ptr(s: i32, x: f32, y: f32, press: f32) -> OscPacket {
        let mut args = vec![OscType::Int(s), OscType::Int(0), OscType::Int(1)];
        args.extend([x, y, 0.0, 0.0, 0.01, press].map(OscType::Float));
        msg("ptr", args)
    }

    fn points(s: i32, pts: &[[f32; 2]]) -> Vec<OscType> {
        std::iter::once(OscType::Int(s))
            .chain(pts.iter().flat_map(|p| [OscType::Float(p[0]), OscType::Float(p[1])]))
            .collect()
    }

    /// A square in normalized coordinates, centre (x, y), half side `h`.
    fn square(x: f32, y: f32, h: f32) -> Vec<[f32; 2]> {
        vec![[x - h, y - h], [x + h, y - h], [x + h, y + h], [x - h, y + h]]
    }

    fn draw(t: &TuioState, now: f64) -> (crate::pipeline::surface::ContactImage, Sensor) {
        let sensor = Sensor::default();
        (rasterize(&t.hands(TABLE, now), &sensor, &RasterParams::default()), sensor)
    }

    fn grey(image: &crate::pipeline::surface::ContactImage, sensor: &Sensor, p: [f32; 2]) -> u8 {
        let [c, r] = sensor.to_pixel(crate::pipeline::surface::TablePoint::from(p)).to_array();
        image.pixels[r.round() as usize * image.width + c.round() as usize]
    }

    #[test]
    fn pointers_become_fingertips_with_their_pressure() {
        let mut t = TuioState::new();
        t.receive(
            &frame(1, vec![ptr(7, 0.5, 0.5, 0.5), ptr(8, 0.25, 0.0, 0.0), ptr(9, 0.7, 0.7, -0.2)], &[7, 8, 9]),
            0.0,
        )
        .expect("valid");
        let hands = t.hands(TABLE, 0.0);
        assert_eq!(hands.len(), 2, "the hovering pointer (press < 0) does not touch: {hands:?}");
        assert_eq!(hands[0].kind, HandKind::Fingertips(1));
        assert_eq!([hands[0].pose.x, hands[0].pose.y], [0.0, 0.0]);
        assert_eq!(hands[0].pressure, 0.5);
        assert_eq!(hands[0].id, TUIO2_ID_BASE | 7);
        // press 0 is "no pressure data": full pressure, at the far left edge.
        assert_eq!([hands[1].pose.x, hands[1].pose.y, hands[1].pressure], [-0.25, 0.375, 1.0]);
        assert_eq!(t.counts(0.0), (3, 0));
    }

    /// The outer contour is filled, the inner one cut out, the grey level
    /// the session's pointer pressure.
    #[test]
    fn contours_are_drawn_as_they_are_with_their_holes_and_pressure() {
        let mut t = TuioState::new();
        let outer = msg("ocg", points(3, &square(0.5, 0.5, 0.1)));
        let inner = msg("icg", points(3, &square(0.5, 0.5, 0.04)));
        t.receive(&frame(1, vec![ptr(3, 0.5, 0.5, 0.6), outer, inner], &[3]), 0.0).expect("valid");
        let hands = t.hands(TABLE, 0.0);
        assert_eq!(hands.len(), 1);
        assert_eq!(hands[0].kind, HandKind::Contour);
        let (image, sensor) = draw(&t, 0.0);
        // 0.1 normalized = 10 cm across the table's width, 7.5 cm along its depth.
        assert_eq!(grey(&image, &sensor, [0.0, 0.0]), 0, "the hole");
        assert_eq!(grey(&image, &sensor, [0.07, 0.0]), 153, "0.6 of 255 between the contours");
        assert_eq!(grey(&image, &sensor, [0.0, 0.055]), 153);
        assert_eq!(grey(&image, &sensor, [0.12, 0.0]), 0, "outside");
        assert_eq!(grey(&image, &sensor, [0.0, 0.085]), 0, "outside along y");
        // A new ocg without icg drops the hole: holes belong to their contour.
        t.receive(&frame(2, vec![msg("ocg", points(3, &square(0.5, 0.5, 0.1)))], &[3]), 0.1).expect("valid");
        let (image, sensor) = draw(&t, 0.1);
        assert_eq!(grey(&image, &sensor, [0.0, 0.0]), 153);
        // Two holes in one icg, `true` between them.
        let mut two = points(3, &square(0.45, 0.5, 0.02));
        two.push(OscType::Bool(true));
        two.extend(points(0, &square(0.55, 0.5, 0.02)).into_iter().skip(1));
        t.receive(&frame(3, vec![msg("ocg", points(3, &square(0.5, 0.5, 0.1))), msg("icg", two)], &[3]), 0.2)
            .expect("valid");
        let (image, sensor) = draw(&t, 0.2);
        assert_eq!([grey(&image, &sensor, [-0.05, 0.0]), grey(&image, &sensor, [0.05, 0.0])], [0, 0]);
        assert_eq!(grey(&image, &sensor, [0.0, 0.0]), 153);
    }

    #[test]
    fn bounds_without_a_contour_are_an_ellipse() {
        let mut t = TuioState::new();
        // 20 cm × 6 cm (0.2 of the width, 0.08 of the depth), turned a quarter:
        // the long axis along the table's depth.
        let bnd = |s: i32, angle: f32| {
            let mut args = vec![OscType::Int(s)];
            args.extend([0.5, 0.5, angle, 0.2 / 0.75, 0.06, 0.01].map(OscType::Float));
            msg("bnd", args)
        };
        t.receive(&frame(1, vec![bnd(1, std::f32::consts::FRAC_PI_2)], &[1]), 0.0).expect("valid");
        let hands = t.hands(TABLE, 0.0);
        assert_eq!(hands[0].kind, HandKind::Contour);
        let [lo, hi] = hands[0].bounds();
        assert!((hi[1] - lo[1] - 0.2).abs() < 2e-3 && (hi[0] - lo[0] - 0.06).abs() < 2e-3, "{lo:?} {hi:?}");
        let (image, sensor) = draw(&t, 0.0);
        let lit = image.pixels.iter().filter(|&&p| p >= 128).count() as f32;
        let expected = std::f32::consts::PI * 0.1 * 0.03 / sensor.metres_per_pixel().powi(2);
        assert!((lit / expected - 1.0).abs() < 0.03, "{lit} pixels, an ellipse has {expected}");
        // A contour for the same session wins over its bounds.
        t.receive(&frame(2, vec![bnd(1, 0.0), msg("ocg", points(1, &square(0.2, 0.2, 0.05)))], &[1]), 0.1)
            .expect("valid");
        let c = t.hands(TABLE, 0.1)[0].pose;
        assert!((c.x + 0.3).abs() < 1e-5 && (c.y - 0.225).abs() < 1e-5, "{c:?}");
    }

    #[test]
    fn area_spans_are_filled_one_sensor_row_high() {
        let mut t = TuioState::new();
        // 40 rows of a 480-row sensor, each span 0.1 wide; two overlapping
        // spans on one row are joined, not cancelled.
        let mut args = vec![OscType::Int(4)];
        for k in 0..40 {
            let y = 0.4 + k as f32 / 480.0;
            args.extend([0.3, y, 0.1].map(OscType::Float));
        }
        args.extend([0.35, 0.4 + 20.0 / 480.0, 0.1].map(OscType::Float));
        t.receive(&frame(1, vec![msg("arg", args)], &[4]), 0.0).expect("valid");
        let (image, sensor) = draw(&t, 0.0);
        let lit = image.pixels.iter().filter(|&&p| p >= 128).count();
        // 40 rows × 64 columns, plus row 20's extra 0.05 (32 columns).
        assert!((2560..=2680).contains(&lit), "{lit} pixels");
        assert_eq!(grey(&image, &sensor, [-0.2 + 0.005, 0.075 - 20.5 * 0.75 / 480.0]), 255, "no seams between rows");
        let y = 0.075 - 20.5 * 0.75 / 480.0;
        assert_eq!(grey(&image, &sensor, [-0.13, y]), 255, "where the two spans overlap: joined, not cancelled");
        // The part of the longer span past the block: one row high, so its soft edge shows.
        assert!(grey(&image, &sensor, [-0.07, y]) > 128);
        assert_eq!(grey(&image, &sensor, [-0.07, y + 0.004]), 0);
    }

    #[test]
    fn skeletons_are_decoded_and_kept_not_drawn() {
        let mut t = TuioState::new();
        // A palm node with two fingers: leaf → palm → leaf, step back 1, → leaf.
        let f = OscType::Float;
        let args =
            vec![OscType::Int(5), f(0.5), f(0.3), f(0.5), f(0.5), f(0.45), f(0.35), OscType::Int(1), f(0.55), f(0.35)];
        t.receive(&frame(1, vec![msg("skg", args)], &[5]), 0.0).expect("valid");
        assert!(t.hands(TABLE, 0.0).is_empty(), "a skeleton alone draws nothing");
        let skeletons = t.skeletons(TABLE, 0.0);
        assert_eq!(skeletons.len(), 1);
        let edges = &skeletons[0].1;
        assert_eq!(edges.len(), 3);
        // The third edge starts again at the palm node (0.5, 0.5) = table (0, 0).
        assert_eq!(edges[2][0], [0.0, 0.0]);
        assert!((edges[2][1][0] - 0.05).abs() < 1e-6);
        // Stepping back past the walk is refused.
        let bad = vec![OscType::Int(5), f(0.5), f(0.3), f(0.5), f(0.5), OscType::Int(2), f(0.1), f(0.1)];
        let e = t.receive(&frame(2, vec![msg("skg", bad)], &[5]), 0.1).expect_err("refused");
        assert!(e.to_string().contains("/tuio2/skg") && e.to_string().contains("steps back"), "{e}");
    }

    #[test]
    fn tokens_are_kept_and_drawn_only_through_their_geometry() {
        let mut t = TuioState::new();
        let mut args = vec![OscType::Int(2), OscType::Int(1), OscType::Int(82)];
        args.extend([0.75, 0.5, 0.3].map(OscType::Float));
        t.receive(&frame(1, vec![msg("tok", args)], &[2]), 0.0).expect("valid");
        assert!(t.hands(TABLE, 0.0).is_empty());
        let tokens = t.tokens(TABLE, 0.0);
        assert_eq!(tokens.len(), 1);
        assert_eq!((tokens[0].1.component, tokens[0].2), (82, [0.25, 0.0]));
    }

    #[test]
    fn frames_alive_lists_late_frames_and_restarts_per_source() {
        let mut t = TuioState::new();
        let at = |t: &TuioState, now: f64| t.hands(TABLE, now).iter().map(|h| h.pose.x).collect::<Vec<_>>();
        t.receive(&frame(500, vec![ptr(1, 0.5, 0.5, 1.0), ptr(2, 0.7, 0.5, 1.0)], &[1, 2]), 0.0).expect("valid");
        assert_eq!(t.hands(TABLE, 0.0).len(), 2);
        // Session 2 not alive: removed.
        t.receive(&frame(501, vec![], &[1]), 0.016).expect("valid");
        assert_eq!(at(&t, 0.016), [0.0]);
        // A late frame is dropped whole.
        t.receive(&frame(499, vec![ptr(1, 0.9, 0.5, 1.0)], &[1]), 0.02).expect("valid");
        assert_eq!((at(&t, 0.02), t.stats().late_frames), (vec![0.0], 1));
        // Frame 0 is reserved: always applied.
        t.receive(&frame(0, vec![ptr(1, 0.6, 0.5, 1.0)], &[1]), 0.03).expect("valid");
        assert!((at(&t, 0.03)[0] - 0.1).abs() < 1e-6);
        // Far below the last id: a restarted tracker; its old sessions go.
        t.receive(&frame(3, vec![ptr(9, 0.2, 0.5, 1.0)], &[9]), 0.05).expect("valid");
        assert_eq!(t.stats().restarts, 1);
        assert!((at(&t, 0.05)[0] + 0.3).abs() < 1e-6);
        // A frame may span packets: frm and ptr in one, alv in the next.
        t.receive(&bundle(vec![frm(4, "test:0@0x7F000001"), ptr(9, 0.4, 0.5, 1.0)]), 0.06).expect("valid");
        assert!((at(&t, 0.06)[0] + 0.3).abs() < 1e-6, "not applied before its alv");
        t.receive(&bundle(vec![alv(&[9])]), 0.07).expect("valid");
        assert!((at(&t, 0.07)[0] + 0.1).abs() < 1e-6);
        // A frm before the open frame's alv drops the open frame.
        t.receive(&bundle(vec![frm(5, "test:0@0x7F000001"), ptr(9, 0.9, 0.5, 1.0)]), 0.08).expect("valid");
        t.receive(&frame(6, vec![], &[9]), 0.09).expect("valid");
        assert_eq!(t.stats().incomplete_frames, 1);
        assert!((at(&t, 0.09)[0] + 0.1).abs() < 1e-6);
        // Components outside a frame are ignored.
        let ignored = t.stats().ignored_messages;
        t.receive(&bundle(vec![ptr(9, 0.1, 0.1, 1.0)]), 0.1).expect("valid");
        assert_eq!(t.stats().ignored_messages, ignored + 1);
        // Another source keeps its own sessions and frame ids; sources go stale.
        let other = bundle(vec![frm(1, "other:0@0x7F000002"), ptr(9, 0.5, 0.5, 1.0), alv(&[9])]);
        t.receive(&other, 1.0).expect("valid");
        let hands = t.hands(TABLE, 1.0);
        assert_eq!(hands.len(), 2);
        assert_ne!(hands[0].id, hands[1].id, "same session id, two sources");
        assert_eq!(t.hands(TABLE, 2.5).len(), 1, "the first source last spoke at 0.09 s");
    }

    #[test]
    fn tuio_1_1_and_2_0_share_one_state() {
        let mut t = TuioState::new();
        let cursor = |f: i32, x: f32| {
            let m = |args: Vec<OscType>| OscPacket::Message(OscMessage { addr: "/tuio/2Dcur".into(), args });
            bundle(vec![
                m(vec![OscType::String("alive".into()), OscType::Int(1)]),
                m(vec![OscType::String("set".into()), OscType::Int(1), OscType::Float(x), OscType::Float(0.5)]),
                m(vec![OscType::String("fseq".into()), OscType::Int(f)]),
            ])
        };
        t.receive(&cursor(10, 0.2), 0.0).expect("valid");
        t.receive(&frame(10, vec![ptr(1, 0.8, 0.5, 1.0)], &[1]), 0.0).expect("valid");
        let hands = t.hands(TABLE, 0.0);
        assert_eq!(hands.len(), 2, "{hands:?}");
        assert_eq!(hands[0].id, super::super::CURSOR_ID_BASE | 1);
        assert_eq!(hands[1].id, TUIO2_ID_BASE | 1);
        // Each version keeps its own frame ids: a 1.1 frame 11 after a 2.0
        // frame 10, then a 2.0 frame 11, are both applied, neither late.
        t.receive(&cursor(11, 0.3), 0.016).expect("valid");
        t.receive(&frame(11, vec![], &[]), 0.016).expect("valid");
        let hands = t.hands(TABLE, 0.016);
        assert_eq!(hands.len(), 1);
        assert!((hands[0].pose.x + 0.2).abs() < 1e-6);
        assert_eq!(t.stats().late_frames, 0);
        // A 2.0 packet's stray 1.1 message is ignored, not decoded.
        let mixed = bundle(vec![
            frm(12, "test:0@0x7F000001"),
            OscPacket::Message(OscMessage { addr: "/tuio/2Dcur".into(), args: vec![] }),
            alv(&[]),
        ]);
        t.receive(&mixed, 0.03).expect("a 2.0 packet");
        assert_eq!(t.hands(TABLE, 0.03).len(), 1);
    }

    #[test]
    fn malformed_tuio_2_messages_are_refused_whole_with_the_reason() {
        let mut t = TuioState::new();
        t.receive(&frame(1, vec![ptr(1, 0.5, 0.5, 1.0)], &[1]), 0.0).expect("valid");
        let f = OscType::Float;
        let cases: Vec<(OscPacket, &str)> = vec![
            (msg("ptr", vec![OscType::Int(1), OscType::Int(0), OscType::Int(0), f(0.5), f(0.5)]), "takes 9 arguments"),
            (
                msg(
                    "ptr",
                    [OscType::Int(1), OscType::Int(0), OscType::Int(0)]
                        .into_iter()
                        .chain([0.5, f32::NAN, 0.0, 0.0, 0.01, 1.0].map(f))
                        .collect(),
                ),
                "not a finite number",
            ),
            (msg("ptr", [OscType::String("a".into())].into_iter().chain([0.5; 8].map(f)).collect()), "session id"),
            (msg("ocg", points(1, &[[0.1, 0.1], [0.2, 0.1]])), "2 points"),
            (msg("ocg", vec![OscType::Int(1), f(0.1), f(0.1), f(0.2)]), "pairs"),
            (msg("ocg", points(1, &[[0.1, 0.1], [0.2, 0.1], [9.0, 0.2]])), "far outside"),
            (
                msg("icg", points(1, &square(0.5, 0.5, 0.1)).into_iter().chain([OscType::Bool(true)]).collect()),
                "0 points",
            ),
            (msg("arg", vec![OscType::Int(1), f(0.1), f(0.1)]), "triples"),
            (msg("arg", vec![OscType::Int(1), f(0.1), f(0.1), f(-0.5)]), "span width"),
            (msg("bnd", [OscType::Int(1)].into_iter().chain([0.5, 0.5, 0.0, 0.0, 0.1, 0.01].map(f)).collect()), "size"),
            (msg("skg", vec![OscType::Int(1), f(0.1), f(0.1)]), "at least 2"),
            (msg("skg", vec![OscType::Int(1), OscType::String("x".into())]), "neither"),
            (msg("frm", vec![OscType::String("1".into())]), "frame id"),
            (msg("frm", vec![OscType::Int(1), OscType::Int(2)]), "time tag"),
            (msg("alv", vec![f(1.0)]), "session id"),
            (msg("tok", vec![OscType::Int(1)]), "takes 6 arguments"),
        ];
        for (i, (m, why)) in cases.into_iter().enumerate() {
            let addr = match &m {
                OscPacket::Message(m) => m.addr.clone(),
                OscPacket::Bundle(_) => unreachable!(),
            };
            let e = t.receive(&frame(2 + i as i32, vec![ptr(1, 0.1, 0.1, 1.0), m], &[]), 0.01).expect_err(why);
            let text = e.to_string();
            assert!(text.starts_with(&addr) && text.contains(why), "case {i}: {text}");
        }
        // Nothing of them applied: the pointer is where frame 1 put it.
        let hands = t.hands(TABLE, 0.01);
        assert_eq!([hands.len(), t.stats().malformed as usize], [1, 16]);
        assert_eq!(hands[0].pose.x, 0.0);
    }
}
