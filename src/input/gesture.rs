//! Gestures: timed keyframes of hands and tangibles, stored as versioned
//! TOML so that test inputs, demo recordings and study scripts are data.
//!
//! # Format (version 2; version 1 is the same without `contour`)
//!
//! ```toml
//! format = "surfacelab-gesture"   # required, exactly this
//! version = 1                     # required: 1 or 2; 2 is needed for kind = "contour"
//!
//! [[hands]]                       # one entry per touch, any number
//! id = 1                          # integer 0..=4294967295, the Hand::id
//! kind = "fingertips"             # fingertips | flat_hand | edge | fist |
//!                                 # forearm | ruler | cup | card
//! fingers = 2                     # fingertips only: 1..=5 (default 1)
//!
//! [[hands.keys]]                  # keyframes, strictly increasing t
//! t = 0.0                         # seconds from the gesture start, 0..=600
//! pos = [-0.05, 0.0]              # table metres (x right, y away), within ±100; required in the first key
//! angle_deg = 0.0                 # degrees counter-clockwise, 0 = fingers to +y; within ±36000
//! spread = 1.0                    # 0..=10; 0 = fingers together, 1 = relaxed
//! scale = 1.0                     # > 0, <= 10; 1 = adult size
//! pressure = 1.0                  # 0..=1, the grey level of the touch
//! ```
//!
//! A `kind = "contour"` hand (version 2) is an arbitrary outline, drawn as
//! it is (what a TUIO 2.0 tracker's contours describe); its keys carry the
//! outline instead of a pose:
//!
//! ```toml
//! [[hands]]
//! id = 7
//! kind = "contour"
//! keys = [
//!   { t = 0.0, points = [[-0.1, -0.05], [0.0, -0.05], [0.0, 0.05], [-0.1, 0.05]], pressure = 0.9 },
//!   { t = 0.5, points = [[0.0, -0.05], [0.1, -0.05], [0.1, 0.05], [0.0, 0.05]],
//!     holes = [[[0.04, -0.01], [0.06, -0.01], [0.05, 0.01]]] },
//! ]
//! ```
//!
//! `points` is the outer contour, in table metres (not relative to
//! anything), at least 3 points, each finite and within ±100 m; `holes`
//! (optional) are inner contours cut out of it, each of at least 3 points;
//! at most 32,768 points per key in all. The fill is even-odd, so either
//! winding works. `points` is required in the first key; a key without it
//! keeps the previous key's outline and holes (and may not give `holes`
//! alone); a key with it has exactly the holes it lists. Contour keys take
//! `pressure` and no `pos`, `angle_deg`, `spread` or `scale`.
//!
//! Keys may also be written inline, `keys = [{ t = 0.0, pos = [0.0, 0.0] }, ...]`,
//! which is what [`Gesture`]'s `Display` writes. A field left out of a key
//! keeps its value from the previous key; the first key defaults to
//! `angle_deg = 0, spread = 1, scale = 1, pressure = 1`.
//!
//! Between two keys, position, spread, scale and pressure are interpolated
//! linearly and the angle along the shorter arc (so a turn of more than
//! 180 degrees needs intermediate keys; exactly 180 turns clockwise).
//! A contour moves point by point when both keys have the same number of
//! points and of holes with the same number of points each; otherwise the
//! earlier key's outline holds until the next key (a tracker's contour of
//! a moving hand changes its point count from frame to frame, and there is
//! no faithful way to pair points of different counts).
//!
//! **Versions.** This build reads versions 1 and 2 and writes version 1
//! when no hand is a contour (so files stay readable by builds that know
//! only version 1, and writing one back gives the same text) and version 2
//! otherwise.
//!
//! **A hand is on the table only from its first key to its last**, both
//! included: before and after, it is lifted. To lift a hand and put it down
//! again, write a second `[[hands]]` entry, possibly with the same `id`, whose
//! first key comes after the first entry's last key; two entries with the
//! same id must not overlap in time. Vision will see a new contact either
//! way: ids here name the driver's hands, not the tracker's contacts.
//!
//! Floats are written with Rust's shortest round-trip formatting, so
//! writing and reading a gesture back gives the identical value.

use std::fmt;
use std::path::Path;
use std::sync::Arc;

use serde::Deserialize;
use toml::Spanned;

use crate::pipeline::surface::{Hand, HandKind, MAX_OUTLINE_POINTS, MIN_RING_POINTS, Outline, Pose};
use crate::scene::bounds;
use crate::scene::human;
use crate::scene::{FieldError, FieldReader};

/// The `format` value every gesture file carries.
pub const FORMAT: &str = "surfacelab-gesture";
/// The newest `version` this build reads and writes (it reads 1 too).
pub const VERSION: i64 = 2;
/// The version written when no hand is a contour.
const VERSION_WITHOUT_CONTOURS: i64 = 1;

/// Why a gesture could not be read. Every variant names the file (or the
/// origin given to [`Gesture::from_str`]); field errors name the field as a
/// path such as `hands[0].keys[2].t`, with the line when TOML knows it.
#[derive(Debug, thiserror::Error)]
pub enum GestureError {
    #[error("{origin}: cannot read the gesture file")]
    Io {
        origin: String,
        #[source]
        source: std::io::Error,
    },
    /// Neither a file nor a built-in gesture by that path or name.
    #[error("no gesture `{origin}`: looked for {tried}; give a gesture's name or the path to a gesture file")]
    NotFound { origin: String, tried: String },
    /// Saving a recording failed: the program's fault or the disk's, not the user's.
    #[error("{origin}: cannot write the gesture file")]
    Write {
        origin: String,
        #[source]
        source: std::io::Error,
    },
    /// Syntax, and values that cannot be used: file, line and field, worded
    /// as scene errors are.
    #[error(transparent)]
    Field(#[from] FieldError),
}

impl crate::error::Kind for GestureError {
    fn kind(&self) -> crate::error::ErrorKind {
        match self {
            GestureError::Io { source, .. } => crate::error::io_kind(source),
            GestureError::Write { .. } => crate::error::ErrorKind::Runtime,
            GestureError::Field(_) | GestureError::NotFound { .. } => crate::error::ErrorKind::BadInput,
        }
    }
}

/// One keyframe of one hand. Values are kept in `f64` exactly as read so
/// that writing them back is lossless; [`Hand`]s are made at sampling time.
#[derive(Debug, Clone, PartialEq)]
pub struct Key {
    pub t: f64,
    /// Where the hand is; for a contour, the middle of its outline's
    /// bounds (derived, not written).
    pub pos: [f64; 2],
    pub angle_deg: f64,
    pub spread: f64,
    pub scale: f64,
    pub pressure: f64,
    /// A contour hand's outline; `None` for every other kind.
    pub contour: Option<Arc<Contour>>,
}

/// A contour key's outline in table metres, exactly as read (see the
/// module doc). Invariant: what [`Outline::new`] accepts.
#[derive(Debug, Clone, PartialEq)]
pub struct Contour {
    /// The outer contour.
    pub points: Vec<[f64; 2]>,
    /// Inner contours cut out of it.
    pub holes: Vec<Vec<[f64; 2]>>,
}

impl Contour {
    /// The middle of the outer contour's bounds.
    fn centre(&self) -> [f64; 2] {
        let (mut lo, mut hi) = ([f64::MAX; 2], [f64::MIN; 2]);
        for p in &self.points {
            for k in 0..2 {
                lo[k] = lo[k].min(p[k]);
                hi[k] = hi[k].max(p[k]);
            }
        }
        [(lo[0] + hi[0]) * 0.5, (lo[1] + hi[1]) * 0.5]
    }

    /// The rings as an [`Outline`] (`None` only if the invariant is broken).
    fn outline(&self) -> Option<Outline> {
        let ring = |r: &[[f64; 2]]| r.iter().map(|p| [p[0] as f32, p[1] as f32]).collect::<Vec<_>>();
        Outline::new(std::iter::once(ring(&self.points)).chain(self.holes.iter().map(|h| ring(h))).collect()).ok()
    }

    /// Whether the two can be interpolated point by point.
    fn same_shape(&self, other: &Contour) -> bool {
        self.points.len() == other.points.len()
            && self.holes.len() == other.holes.len()
            && self.holes.iter().zip(&other.holes).all(|(a, b)| a.len() == b.len())
    }
}

/// One touch: a hand (or tangible) from its first key to its last.
/// Invariant: at least one key, times finite, non-negative and strictly
/// increasing, every value finite and in range.
#[derive(Debug, Clone, PartialEq)]
pub struct Track {
    id: u32,
    kind: HandKind,
    keys: Vec<Key>,
}

impl Track {
    pub fn id(&self) -> u32 {
        self.id
    }

    pub fn kind(&self) -> HandKind {
        self.kind
    }

    pub fn keys(&self) -> &[Key] {
        &self.keys
    }

    /// First and last key times: the interval in which the hand touches.
    pub fn span(&self) -> [f64; 2] {
        [self.keys[0].t, self.keys[self.keys.len() - 1].t]
    }

    /// The hand at time `t`, or `None` when it is lifted.
    pub fn sample(&self, t: f64) -> Option<Hand> {
        let [first, last] = self.span();
        if !(t >= first && t <= last) {
            return None;
        }
        let i = self.keys.partition_point(|k| k.t <= t) - 1;
        match self.keys.get(i + 1) {
            Some(next) => interpolate(&self.keys[i], next, t).hand(self.id, self.kind),
            None => self.keys[i].hand(self.id, self.kind),
        }
    }
}

impl Key {
    /// The hand this key describes: the one conversion from a file's
    /// numbers to a hand, shared by replays and [`quantized`] live input.
    /// `None` only for a contour kind whose key has no valid outline,
    /// which reading and recording never make.
    fn hand(&self, id: u32, kind: HandKind) -> Option<Hand> {
        if kind == HandKind::Contour {
            let mut hand = Hand::contour(id, &self.contour.as_ref()?.outline()?);
            hand.pressure = self.pressure as f32;
            return Some(hand);
        }
        Some(Hand {
            id,
            kind,
            pose: Pose { x: self.pos[0] as f32, y: self.pos[1] as f32, angle: self.angle_deg.to_radians() as f32 },
            spread: self.spread as f32,
            scale: self.scale as f32,
            pressure: self.pressure as f32,
            outline: None,
        })
    }

    /// A hand's values at time `t` as a file stores them: rounded to 1 µm,
    /// 1e-4 degree and 1e-4 of spread, scale and pressure (far below a
    /// pixel), out-of-range values clamped. A contour hand's outline is
    /// stored on the table (its rings placed by its pose), rounded to 1 µm.
    fn of_hand(t: f64, hand: &Hand) -> Key {
        let um = |v: f32| round_to(f64::from(v), 1e-6);
        let contour = hand.outline_rings().filter(|_| hand.kind == HandKind::Contour).and_then(|rings| {
            let mut rings = rings.into_iter().map(|r| r.into_iter().map(|p| [um(p[0]), um(p[1])]).collect());
            let points = rings.next()?;
            Some(Arc::new(Contour { points, holes: rings.collect() }))
        });
        let mut key = Key {
            t,
            pos: [um(hand.pose.x), um(hand.pose.y)],
            angle_deg: round_to(f64::from(hand.pose.angle).to_degrees(), 1e-4),
            spread: round_to(f64::from(hand.spread).max(0.0), 1e-4),
            scale: round_to(f64::from(hand.scale), 1e-4).max(1e-4),
            pressure: round_to(f64::from(hand.pressure).clamp(0.0, 1.0), 1e-4),
            contour: None,
        };
        if let Some(c) = contour {
            key = Key { pos: c.centre(), angle_deg: 0.0, spread: 1.0, scale: 1.0, contour: Some(c), ..key };
        }
        key
    }
}

/// A hand exactly as a recording of it replays: live input that goes
/// through this steps the physics with the very numbers a gesture file
/// holds, so a replay reproduces the live run bit for bit (rounding only
/// the file would let a 25 s sorting recording drift: objects end far
/// from where the live run left them). Idempotent for tables
/// smaller than a few metres (f32 keeps 1 µm there).
/// A contour hand without a usable outline touches nothing and comes back
/// unchanged.
pub fn quantized(hand: &Hand) -> Hand {
    let kind = match hand.kind {
        HandKind::Fingertips(n) => HandKind::Fingertips(n.clamp(1, 5)),
        k => k,
    };
    Key::of_hand(0.0, hand).hand(hand.id, kind).unwrap_or_else(|| hand.clone())
}

fn interpolate(a: &Key, b: &Key, t: f64) -> Key {
    let s = (t - a.t) / (b.t - a.t);
    let lerp = |x: f64, y: f64| x + (y - x) * s;
    let turn = (b.angle_deg - a.angle_deg + 180.0).rem_euclid(360.0) - 180.0;
    let contour = match (&a.contour, &b.contour) {
        (Some(ca), Some(cb)) if ca.same_shape(cb) => {
            let ring = |x: &[[f64; 2]], y: &[[f64; 2]]| {
                x.iter().zip(y).map(|(p, q)| [lerp(p[0], q[0]), lerp(p[1], q[1])]).collect::<Vec<_>>()
            };
            Some(Arc::new(Contour {
                points: ring(&ca.points, &cb.points),
                holes: ca.holes.iter().zip(&cb.holes).map(|(x, y)| ring(x, y)).collect(),
            }))
        }
        (held, _) => held.clone(),
    };
    Key {
        t,
        pos: [lerp(a.pos[0], b.pos[0]), lerp(a.pos[1], b.pos[1])],
        angle_deg: a.angle_deg + turn * s,
        spread: lerp(a.spread, b.spread),
        scale: lerp(a.scale, b.scale),
        pressure: lerp(a.pressure, b.pressure),
        contour,
    }
}

/// A scripted or recorded sequence of touches.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Gesture {
    tracks: Vec<Track>,
}

impl Gesture {
    /// Parses gesture text; `origin` (usually the file name) prefixes every
    /// error message.
    pub fn from_str(text: &str, origin: &str) -> Result<Self, GestureError> {
        parse(text, origin)
    }

    /// Reads and parses a gesture by path or by name, the way scenes are
    /// found: the path on disk, else `assets/gestures/NAME.toml` on disk
    /// (`flick`, `behaviours/flick_fast`), else the built-in copy of
    /// either, so a repository path or name works outside a checkout too.
    pub fn load(path: impl AsRef<Path>) -> Result<Self, GestureError> {
        let path = path.as_ref();
        let origin = path.display().to_string();
        let by_name = (!path.is_absolute() && path.extension().is_none())
            .then(|| Path::new("assets/gestures").join(format!("{origin}.toml")));
        for candidate in std::iter::once(path).chain(by_name.as_deref()) {
            match crate::files::read_capped(candidate) {
                Ok(text) => return parse(&text, &candidate.display().to_string()),
                Err(source) if source.kind() == std::io::ErrorKind::NotFound => {}
                Err(source) => return Err(GestureError::Io { origin: candidate.display().to_string(), source }),
            }
        }
        for candidate in std::iter::once(path).chain(by_name.as_deref()) {
            if let Some(text) = crate::scene::builtin::file(candidate) {
                return parse(text, &format!("{} (built in)", candidate.display()));
            }
        }
        let tried = by_name.map_or_else(String::new, |p| format!(", {}", p.display()));
        Err(GestureError::NotFound {
            tried: format!(
                "{origin}{tried}, the built-in gestures ({}, and behaviours/NAME: `surfacelab run --list`)",
                crate::scene::builtin::gesture_names().filter(|n| !n.contains('/')).collect::<Vec<_>>().join(", ")
            ),
            origin,
        })
    }

    /// Writes the gesture: version 1 without contours, 2 with (module doc).
    pub fn save(&self, path: impl AsRef<Path>) -> Result<(), GestureError> {
        let path = path.as_ref();
        crate::files::write_output(path, self.to_string().as_bytes())
            .map_err(|source| GestureError::Write { origin: path.display().to_string(), source })
    }

    pub fn tracks(&self) -> &[Track] {
        &self.tracks
    }

    /// Time of the last key of any hand, seconds (0 when empty).
    pub fn duration(&self) -> f64 {
        self.tracks.iter().map(|t| t.span()[1]).fold(0.0, f64::max)
    }

    /// The hands touching at time `t`, in file order.
    pub fn sample(&self, t: f64) -> Vec<Hand> {
        self.tracks.iter().filter_map(|track| track.sample(t)).collect()
    }
}

/// Formats a float so that TOML reads it back as the same float: Rust's
/// shortest round-trip digits, always with a `.0` or an exponent so TOML
/// sees a float and not an integer.
struct Float(f64);

impl fmt::Display for Float {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{:?}", self.0)
    }
}

/// A list of points as TOML: `[[x, y], ...]`.
struct Points<'a>(&'a [[f64; 2]]);

impl fmt::Display for Points<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("[")?;
        for (i, p) in self.0.iter().enumerate() {
            let sep = if i == 0 { "" } else { ", " };
            write!(f, "{sep}[{}, {}]", Float(p[0]), Float(p[1]))?;
        }
        f.write_str("]")
    }
}

impl fmt::Display for Gesture {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let version =
            if self.tracks.iter().any(|t| t.kind == HandKind::Contour) { VERSION } else { VERSION_WITHOUT_CONTOURS };
        writeln!(f, "# surfacelab gesture; format described in src/input/gesture.rs")?;
        writeln!(f, "format = \"{FORMAT}\"")?;
        writeln!(f, "version = {version}")?;
        for track in &self.tracks {
            writeln!(f)?;
            writeln!(f, "[[hands]]")?;
            writeln!(f, "id = {}", track.id)?;
            writeln!(f, "kind = \"{}\"", track.kind.name())?;
            if let HandKind::Fingertips(n) = track.kind {
                writeln!(f, "fingers = {n}")?;
            }
            writeln!(f, "keys = [")?;
            for k in &track.keys {
                if let Some(c) = &k.contour {
                    write!(f, "  {{ t = {}, points = {}", Float(k.t), Points(&c.points))?;
                    if !c.holes.is_empty() {
                        f.write_str(", holes = [")?;
                        for (i, h) in c.holes.iter().enumerate() {
                            write!(f, "{}{}", if i == 0 { "" } else { ", " }, Points(h))?;
                        }
                        f.write_str("]")?;
                    }
                    writeln!(f, ", pressure = {} }},", Float(k.pressure))?;
                    continue;
                }
                writeln!(
                    f,
                    "  {{ t = {}, pos = [{}, {}], angle_deg = {}, spread = {}, scale = {}, pressure = {} }},",
                    Float(k.t),
                    Float(k.pos[0]),
                    Float(k.pos[1]),
                    Float(k.angle_deg),
                    Float(k.spread),
                    Float(k.scale),
                    Float(k.pressure)
                )?;
            }
            writeln!(f, "]")?;
        }
        Ok(())
    }
}

// ---------------------------------------------------------------------------
// Reading. Serde does the syntax; every rule about values is checked here, by
// hand, so that each error can name its field and line.

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawFile {
    format: Option<Spanned<toml::Value>>,
    version: Option<Spanned<toml::Value>>,
    #[serde(default)]
    hands: Vec<RawHand>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawHand {
    id: Spanned<i64>,
    kind: Spanned<String>,
    fingers: Option<Spanned<i64>>,
    keys: Spanned<Vec<RawKey>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawKey {
    t: Spanned<f64>,
    #[serde(default, deserialize_with = "crate::files::fixed_arrays::exactly")]
    pos: Option<Spanned<[f64; 2]>>,
    angle_deg: Option<Spanned<f64>>,
    spread: Option<Spanned<f64>>,
    scale: Option<Spanned<f64>>,
    pressure: Option<Spanned<f64>>,
    #[serde(default, deserialize_with = "crate::files::fixed_arrays::exactly")]
    points: Option<Spanned<Vec<[f64; 2]>>>,
    #[serde(default, deserialize_with = "crate::files::fixed_arrays::exactly")]
    holes: Option<Spanned<Vec<Vec<[f64; 2]>>>>,
}

/// The gesture's checks; the wording of every error is [`FieldReader`]'s.
struct Reader<'a> {
    fields: FieldReader<'a>,
}

impl Reader<'_> {
    fn field<T>(&self, field: impl Into<String>, at: Option<&Spanned<T>>, problem: impl Into<String>) -> GestureError {
        self.fields.error(at.map(|s| s.span().start), field, problem).into()
    }

    /// An error at byte `offset` of the text (its line is reported).
    fn error_at(&self, offset: Option<usize>, field: impl Into<String>, problem: impl Into<String>) -> GestureError {
        self.fields.error(offset, field, problem).into()
    }

    /// A float field: finite and within `lo..=hi`.
    fn number(&self, field: &str, value: &Spanned<f64>, lo: f64, hi: f64) -> Result<f64, GestureError> {
        Ok(self.fields.number(Some(value.span().start), field, *value.get_ref(), lo, hi)?)
    }

    /// A float field: finite and greater than 0.
    fn positive(&self, field: &str, value: &Spanned<f64>) -> Result<f64, GestureError> {
        Ok(self.fields.positive(Some(value.span().start), field, *value.get_ref())?)
    }
}

fn parse(text: &str, origin: &str) -> Result<Gesture, GestureError> {
    let r = Reader { fields: FieldReader::new(text, origin) };
    let raw: RawFile = r.fields.parse()?;

    match &raw.format {
        None => {
            return Err(r.field("format", None::<&Spanned<()>>, format!("missing; expected \"{FORMAT}\"")));
        }
        Some(f) if f.get_ref().as_str() != Some(FORMAT) => {
            return Err(r.field("format", Some(f), format!("expected \"{FORMAT}\", found {}", f.get_ref())));
        }
        Some(_) => {}
    }
    match &raw.version {
        None => {
            return Err(r.field(
                "version",
                None::<&Spanned<()>>,
                format!("missing; this build reads versions 1 to {VERSION}"),
            ));
        }
        Some(v) if !matches!(v.get_ref().as_integer(), Some(1..=VERSION)) => {
            return Err(r.field(
                "version",
                Some(v),
                format!("unsupported version {}; this build reads versions 1 to {VERSION}", v.get_ref()),
            ));
        }
        Some(_) => {}
    }
    let version = raw.version.as_ref().and_then(|v| v.get_ref().as_integer()).unwrap_or(VERSION);

    let mut tracks = Vec::with_capacity(raw.hands.len());
    for (i, hand) in raw.hands.iter().enumerate() {
        tracks.push(read_hand(&r, i, hand, version)?);
    }

    // Two entries for the same id must not touch at the same time.
    let mut order: Vec<usize> = (0..tracks.len()).collect();
    order.sort_by(|&a, &b| {
        (tracks[a].id, tracks[a].span()[0])
            .partial_cmp(&(tracks[b].id, tracks[b].span()[0]))
            .unwrap_or(std::cmp::Ordering::Equal)
    });
    for w in order.windows(2) {
        let (a, b) = (&tracks[w[0]], &tracks[w[1]]);
        if a.id == b.id && b.span()[0] <= a.span()[1] {
            let key = &raw.hands[w[1]].keys.get_ref()[0].t;
            return Err(r.field(
                format!("hands[{}].keys[0].t", w[1]),
                Some(key),
                format!(
                    "hand id {} is still on the table until t = {} (entry hands[{}]); lift it first",
                    a.id,
                    a.span()[1],
                    w[0]
                ),
            ));
        }
    }
    Ok(Gesture { tracks })
}

fn read_hand(r: &Reader<'_>, i: usize, hand: &RawHand, version: i64) -> Result<Track, GestureError> {
    let path = format!("hands[{i}]");
    let id = u32::try_from(*hand.id.get_ref()).map_err(|_| {
        r.field(format!("{path}.id"), Some(&hand.id), format!("{} is out of range (0..=4294967295)", hand.id.get_ref()))
    })?;
    let kind = read_kind(r, &path, hand, version)?;

    let raw_keys = hand.keys.get_ref();
    if raw_keys.is_empty() {
        return Err(r.field(format!("{path}.keys"), Some(&hand.keys), "needs at least one key"));
    }
    let mut keys: Vec<Key> = Vec::with_capacity(raw_keys.len());
    for (j, k) in raw_keys.iter().enumerate() {
        let at = |name: &str| format!("{path}.keys[{j}].{name}");
        let t = r.number(&at("t"), &k.t, 0.0, f64::from(bounds::DURATION_S))?;
        let previous = keys.last();
        if let Some(p) = previous
            && t <= p.t
        {
            return Err(r.field(
                at("t"),
                Some(&k.t),
                format!("keys out of time order: t = {t} does not come after the previous key's t = {}", p.t),
            ));
        }
        if kind == HandKind::Contour {
            keys.push(read_contour_key(r, &at, t, k, previous)?);
            continue;
        }
        for (name, given) in
            [("points", k.points.as_ref().map(Spanned::span)), ("holes", k.holes.as_ref().map(Spanned::span))]
        {
            if let Some(span) = given {
                return Err(r.error_at(
                    Some(span.start),
                    at(name),
                    format!("only kind \"contour\" takes `{name}`, not \"{name_of}\"", name_of = kind.name()),
                ));
            }
        }
        let pos = read_pos(r, &at, k, previous)?;
        let or = |v: &Option<Spanned<f64>>, name: &str, lo: f64, hi: f64, default: f64| match v {
            Some(v) => r.number(&at(name), v, lo, hi),
            None => Ok(default),
        };
        let base = previous.cloned().unwrap_or(Key {
            t,
            pos,
            angle_deg: 0.0,
            spread: 1.0,
            scale: 1.0,
            pressure: 1.0,
            contour: None,
        });
        let scale = match &k.scale {
            Some(v) => {
                r.positive(&at("scale"), v)?;
                r.number(&at("scale"), v, 0.0, bounds::GESTURE_SCALE)?
            }
            None => base.scale,
        };
        keys.push(Key {
            t,
            pos,
            angle_deg: or(
                &k.angle_deg,
                "angle_deg",
                -bounds::GESTURE_ANGLE_DEG,
                bounds::GESTURE_ANGLE_DEG,
                base.angle_deg,
            )?,
            spread: or(&k.spread, "spread", 0.0, bounds::GESTURE_SPREAD, base.spread)?,
            scale,
            pressure: or(&k.pressure, "pressure", 0.0, 1.0, base.pressure)?,
            contour: None,
        });
    }
    Ok(Track { id, kind, keys })
}

/// A hand's kind, with its finger count, refused where the file's version
/// or the kind does not allow it.
fn read_kind(r: &Reader<'_>, path: &str, hand: &RawHand, version: i64) -> Result<HandKind, GestureError> {
    let name = hand.kind.get_ref().as_str();
    let mut kind = HandKind::from_name(name).ok_or_else(|| {
        let known: Vec<&str> = HandKind::ALL.iter().chain(&[HandKind::Contour]).map(|k| k.name()).collect();
        r.field(
            format!("{path}.kind"),
            Some(&hand.kind),
            format!("unknown hand kind \"{name}\"; expected one of {}", known.join(", ")),
        )
    })?;
    match (&mut kind, &hand.fingers) {
        (HandKind::Fingertips(n), Some(f)) => {
            *n = u8::try_from(*f.get_ref()).ok().filter(|n| (1..=5).contains(n)).ok_or_else(|| {
                r.field(format!("{path}.fingers"), Some(f), format!("{} is out of range (1..=5)", f.get_ref()))
            })?;
        }
        (_, Some(f)) => {
            return Err(r.field(
                format!("{path}.fingers"),
                Some(f),
                format!("only kind \"fingertips\" takes `fingers`, not \"{name}\""),
            ));
        }
        (_, None) => {}
    }
    if kind == HandKind::Contour && version < 2 {
        return Err(r.field(
            format!("{path}.kind"),
            Some(&hand.kind),
            format!("kind \"contour\" needs version 2 (this file says version {version})"),
        ));
    }
    Ok(kind)
}

/// A template key's position: given (finite, near the table) or the
/// previous key's; the first key must give one.
fn read_pos(
    r: &Reader<'_>,
    at: &dyn Fn(&str) -> String,
    k: &RawKey,
    previous: Option<&Key>,
) -> Result<[f64; 2], GestureError> {
    match (&k.pos, previous) {
        (Some(p), _) => {
            let v = *p.get_ref();
            if !v.iter().all(|c| c.is_finite()) {
                return Err(r.field(at("pos"), Some(p), format!("must be finite, found [{}, {}]", v[0], v[1])));
            }
            let far = f64::from(bounds::POSITION_M);
            if v.iter().any(|c| c.abs() > far) {
                return Err(r.field(
                    at("pos"),
                    Some(p),
                    format!("[{}, {}] is out of range (within ±{far} m of the table centre)", human(v[0]), human(v[1])),
                ));
            }
            Ok(v)
        }
        (None, Some(prev)) => Ok(prev.pos),
        (None, None) => Err(r.field(at("pos"), Some(&k.t), "missing in the first key")),
    }
}

/// One key of a contour hand: `points` (and `holes`) or the previous key's,
/// and `pressure`; the pose fields of the templates are refused.
fn read_contour_key(
    r: &Reader<'_>,
    at: &dyn Fn(&str) -> String,
    t: f64,
    k: &RawKey,
    previous: Option<&Key>,
) -> Result<Key, GestureError> {
    for (name, given) in [
        ("pos", &k.pos.as_ref().map(Spanned::span)),
        ("angle_deg", &k.angle_deg.as_ref().map(Spanned::span)),
        ("spread", &k.spread.as_ref().map(Spanned::span)),
        ("scale", &k.scale.as_ref().map(Spanned::span)),
    ] {
        if let Some(span) = given {
            return Err(r.error_at(
                Some(span.start),
                at(name),
                format!("kind \"contour\" takes `points` (and `holes`), not `{name}`"),
            ));
        }
    }
    let contour = match (&k.points, previous.and_then(|p| p.contour.clone())) {
        (Some(points), _) => {
            let mut rings = vec![(at("points"), points.span().start, points.get_ref().clone())];
            if let Some(holes) = &k.holes {
                for (h, ring) in holes.get_ref().iter().enumerate() {
                    rings.push((at(&format!("holes[{h}]")), holes.span().start, ring.clone()));
                }
            }
            let total: usize = rings.iter().map(|r| r.2.len()).sum();
            if total > MAX_OUTLINE_POINTS {
                return Err(r.error_at(
                    Some(points.span().start),
                    at("points"),
                    format!("{total} points with the holes; at most {MAX_OUTLINE_POINTS}"),
                ));
            }
            let far = f64::from(bounds::POSITION_M);
            for (field, line, ring) in &rings {
                if ring.len() < MIN_RING_POINTS {
                    return Err(r.error_at(
                        Some(*line),
                        field.clone(),
                        format!("{} points; a contour needs at least {MIN_RING_POINTS}", ring.len()),
                    ));
                }
                for (n, p) in ring.iter().enumerate() {
                    if !p.iter().all(|c| c.is_finite()) {
                        return Err(r.error_at(
                            Some(*line),
                            format!("{field}[{n}]"),
                            format!("must be finite, found [{}, {}]", p[0], p[1]),
                        ));
                    }
                    if p.iter().any(|c| c.abs() > far) {
                        return Err(r.error_at(
                            Some(*line),
                            format!("{field}[{n}]"),
                            format!(
                                "[{}, {}] is out of range (within ±{far} m of the table centre)",
                                human(p[0]),
                                human(p[1])
                            ),
                        ));
                    }
                }
            }
            let mut rings = rings.into_iter().map(|r| r.2);
            let points = rings.next().unwrap_or_default();
            Arc::new(Contour { points, holes: rings.collect() })
        }
        (None, Some(held)) => {
            if let Some(holes) = &k.holes {
                return Err(r.error_at(
                    Some(holes.span().start),
                    at("holes"),
                    "`holes` without `points`: give the outer contour with its holes",
                ));
            }
            held
        }
        (None, None) => return Err(r.field(at("points"), Some(&k.t), "missing in the first key of a contour")),
    };
    let pressure = match &k.pressure {
        Some(v) => r.number(&at("pressure"), v, 0.0, 1.0)?,
        None => previous.map_or(1.0, |p| p.pressure),
    };
    Ok(Key { t, pos: contour.centre(), angle_deg: 0.0, spread: 1.0, scale: 1.0, pressure, contour: Some(contour) })
}

// ---------------------------------------------------------------------------

/// Builds a [`Gesture`] from hands sampled over time (the demo's record
/// button, or a test driving the mouse model).
///
/// Each call to [`GestureRecorder::record`] adds one key per hand. A hand
/// that is missing from a sample has been lifted: its entry ends at its last
/// key, and if the same id comes back it starts a new entry (as does a
/// change of kind). Times are stored relative to the first sample.
/// Values are rounded as [`quantized`] rounds them, far below a pixel, so
/// the written file stays readable; live input that went through
/// [`quantized`] replays exactly.
#[derive(Debug, Clone, Default)]
pub struct GestureRecorder {
    tracks: Vec<Track>,
    /// Hand id -> index in `tracks` of hands present in the last sample.
    open: Vec<(u32, usize)>,
    start: Option<f64>,
    last: Option<f64>,
}

fn round_to(v: f64, step: f64) -> f64 {
    (v / step).round() * step
}

impl GestureRecorder {
    pub fn new() -> Self {
        Self::default()
    }

    /// Adds the hands touching at time `t` (seconds, any origin). Returns
    /// false, recording nothing, when `t` is not finite or not after the
    /// previous sample. Hands with non-finite values and repeated ids in one
    /// sample are skipped; out-of-range values are clamped so that the
    /// result always reads back.
    pub fn record(&mut self, t: f64, hands: &[Hand]) -> bool {
        if !t.is_finite() || self.last.is_some_and(|last| t <= last) {
            return false;
        }
        self.last = Some(t);
        let t = t - *self.start.get_or_insert(t);
        let mut open = Vec::with_capacity(hands.len());
        for hand in hands {
            let values = [hand.pose.x, hand.pose.y, hand.pose.angle, hand.spread, hand.scale, hand.pressure];
            if !values.iter().all(|v| v.is_finite()) || open.iter().any(|&(id, _)| id == hand.id) {
                continue;
            }
            let key = Key::of_hand(t, hand);
            // A contour hand whose outline would not read back (none, or
            // placed out of bounds) touches nothing here either.
            if hand.kind == HandKind::Contour && key.contour.as_ref().and_then(|c| c.outline()).is_none() {
                continue;
            }
            let kind = match hand.kind {
                HandKind::Fingertips(n) => HandKind::Fingertips(n.clamp(1, 5)),
                k => k,
            };
            let existing =
                self.open.iter().find(|&&(id, i)| id == hand.id && self.tracks[i].kind == kind).map(|&(_, i)| i);
            let index = if let Some(i) = existing {
                self.tracks[i].keys.push(key);
                i
            } else {
                self.tracks.push(Track { id: hand.id, kind, keys: vec![key] });
                self.tracks.len() - 1
            };
            open.push((hand.id, index));
        }
        self.open = open;
        true
    }

    /// True when nothing has been recorded.
    pub fn is_empty(&self) -> bool {
        self.tracks.is_empty()
    }

    /// The gesture recorded so far.
    pub fn gesture(&self) -> Gesture {
        Gesture { tracks: self.tracks.clone() }
    }

    /// Ends the recording.
    pub fn finish(self) -> Gesture {
        Gesture { tracks: self.tracks }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const TWO: &str = include_str!(concat!(env!("CARGO_MANIFEST_DIR"), "/tests/gestures/two_fingertips.toml"));

    #[test]
    fn samples_interpolate_and_carry_values() {
        let g = Gesture::from_str(TWO, "two.toml").expect("parses");
        assert_eq!(g.duration(), 1.0);
        assert!(g.sample(-0.1).is_empty() && g.sample(1.01).is_empty());
        let h = g.sample(0.5).remove(0);
        assert_eq!(h.kind, HandKind::Fingertips(2));
        assert!((h.pose.x - 0.05).abs() < 1e-6 && (h.pose.y + 0.1).abs() < 1e-6);
        // Shortest arc through 180, not back through 0.
        assert!((h.pose.angle.to_degrees() - 180.0).abs() < 1e-3);
        assert!((h.pressure - 0.75).abs() < 1e-6);
        assert_eq!(h.spread, 1.0);
        assert_eq!(g.sample(1.0)[0].pressure, 0.5);
    }

    #[test]
    fn written_text_reads_back_identically() {
        let g = Gesture::from_str(TWO, "two.toml").expect("parses");
        let text = g.to_string();
        let back = Gesture::from_str(&text, "written").expect("reads back");
        assert_eq!(g, back);
        assert_eq!(text, back.to_string());
    }

    #[test]
    fn recorder_splits_lifted_hands() {
        let mut rec = GestureRecorder::new();
        let a = Hand::new(1, HandKind::Fingertips(1), 0.0, 0.0);
        let a = std::slice::from_ref(&a);
        assert!(rec.record(10.0, a));
        assert!(rec.record(10.1, a));
        assert!(!rec.record(10.1, a));
        assert!(rec.record(10.2, &[]));
        assert!(rec.record(10.3, a));
        let g = rec.finish();
        assert_eq!(g.tracks().len(), 2);
        assert_eq!(g.tracks()[0].span(), [0.0, 10.1 - 10.0]);
        assert!(g.sample(0.15).is_empty());
        let back = Gesture::from_str(&g.to_string(), "rec").expect("reads back");
        assert_eq!(g, back);
    }

    const CONTOUR: &str = include_str!(concat!(env!("CARGO_MANIFEST_DIR"), "/tests/gestures/contour.toml"));

    #[test]
    fn contours_move_point_by_point_or_hold_until_the_next_key() {
        let g = Gesture::from_str(CONTOUR, "contour.toml").expect("parses");
        // Keys 1 and 2 have the same shape: halfway, the square lies halfway.
        let h = g.sample(1.5).remove(0);
        assert_eq!(h.kind, HandKind::Contour);
        let rings = h.outline_rings().expect("an outline");
        assert_eq!(rings.len(), 2, "the outer contour and its hole");
        assert!((rings[0][0][0] - 0.15).abs() < 1e-6 && (rings[1][2][0] - 0.2).abs() < 1e-6, "{rings:?}");
        assert!((h.pressure - 0.6).abs() < 1e-6);
        // Keys 0 and 1 differ (a hole appears): key 0's outline holds, its pressure carried to key 1.
        let h = g.sample(0.9).remove(0);
        let rings = h.outline_rings().expect("an outline");
        assert_eq!(rings.len(), 1);
        assert!((rings[0][0][0] + 0.1).abs() < 1e-6, "{rings:?}");
        assert!((h.pressure - 0.8).abs() < 1e-6);
        assert!((g.sample(1.0)[0].outline_rings().expect("outline")[0][0][0] - 0.1).abs() < 1e-6);
    }

    #[test]
    fn contour_gestures_write_version_2_and_read_back_identically() {
        let g = Gesture::from_str(CONTOUR, "contour.toml").expect("parses");
        let text = g.to_string();
        assert!(text.contains("version = 2"), "{text}");
        let back = Gesture::from_str(&text, "written").expect("reads back");
        assert_eq!(g, back);
        assert_eq!(text, back.to_string());
        // Without a contour the file is written as version 1, and a version-2 file of templates reads.
        let plain = Gesture::from_str(TWO, "two.toml").expect("parses");
        assert!(plain.to_string().contains("version = 1"));
        let v2 = TWO.replace("version = 1", "version = 2");
        assert_eq!(Gesture::from_str(&v2, "v2.toml").expect("version 2 reads"), plain);
    }

    #[test]
    fn recorded_contours_replay_as_recorded() {
        let square = |x: f32| vec![[x, 0.0], [x + 0.1, 0.0], [x + 0.1, 0.08], [x, 0.08]];
        let hand = |x: f32| {
            let outline = Outline::new(vec![square(x), vec![[x + 0.04, 0.03], [x + 0.06, 0.03], [x + 0.05, 0.05]]]);
            quantized(&Hand::contour(9, &outline.expect("valid")).with_pressure(0.7))
        };
        let mut rec = GestureRecorder::new();
        let hands: Vec<Hand> = (0..5).map(|i| hand(0.012_345_7 * i as f32)).collect();
        for (i, h) in hands.iter().enumerate() {
            assert!(rec.record(i as f64 / 60.0, std::slice::from_ref(h)));
        }
        let g = rec.finish();
        let back = Gesture::from_str(&g.to_string(), "rec").expect("reads back");
        assert_eq!(g, back);
        for (i, h) in hands.iter().enumerate() {
            assert_eq!(&back.sample(i as f64 / 60.0)[0], h, "step {i}: the replay draws what was live");
            assert_eq!(&quantized(h), h, "quantized is idempotent");
        }
    }

    #[test]
    fn bad_contours_name_the_file_line_and_field() {
        let err = |text: &str| Gesture::from_str(text, "c.toml").expect_err("refused").to_string();
        let with = |key: &str| {
            CONTOUR.replace(
                "{ t = 0.0, points = [[-0.1, -0.05], [0.0, -0.05], [0.0, 0.05], [-0.1, 0.05]], pressure = 0.8 }",
                key,
            )
        };
        let e = err(&with("{ t = 0.0, points = [[0.0, 0.0], [0.1, 0.0]] }"));
        assert!(e.contains("c.toml:9:") && e.contains("hands[0].keys[0].points") && e.contains("2 points"), "{e}");
        let e = err(&with("{ t = 0.0, points = [[0.0, 0.0], [0.1, nan], [0.1, 0.1]] }"));
        assert!(e.contains("hands[0].keys[0].points[1]") && e.contains("finite"), "{e}");
        let e = err(&with("{ t = 0.0, points = [[0.0, 0.0], [0.1, 0.0], [0.1, 1e9]] }"));
        assert!(e.contains("hands[0].keys[0].points[2]") && e.contains("out of range"), "{e}");
        let e = err(&with("{ t = 0.0, points = [[0.0, 0.0], [0.1, 0.0], [0.1, 0.1]], holes = [[[0.0, 0.0]]] }"));
        assert!(e.contains("hands[0].keys[0].holes[0]") && e.contains("1 points"), "{e}");
        let e = err(&with("{ t = 0.0, pos = [0.0, 0.0] }"));
        assert!(e.contains("hands[0].keys[0].pos") && e.contains("takes `points`"), "{e}");
        let e = err(&with("{ t = 0.0, pressure = 1.0 }"));
        assert!(e.contains("hands[0].keys[0].points") && e.contains("missing"), "{e}");
        let e = err(&CONTOUR.replace(
            "holes = [[[0.14, -0.01], [0.16, -0.01], [0.15, 0.01]]] },",
            "holes = [[[0.14, -0.01], [0.16, -0.01], [0.15, 0.01]]] },\n  { t = 1.5, holes = [] },",
        ));
        assert!(e.contains("hands[0].keys[2].holes") && e.contains("without `points`"), "{e}");
        let e = err(&CONTOUR.replace("version = 2", "version = 1"));
        assert!(e.contains("hands[0].kind") && e.contains("needs version 2"), "{e}");
        let e = err(&TWO.replace("pressure = 0.5", "points = [[0.0, 0.0], [0.1, 0.0], [0.1, 0.1]]"));
        assert!(e.contains("hands[0].keys[1].points") && e.contains("only kind \"contour\""), "{e}");
        let e = err(&TWO.replace("version = 1", "version = 3"));
        assert!(e.contains("unsupported version 3"), "{e}");
    }
}
