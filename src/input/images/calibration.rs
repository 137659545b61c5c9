//! The calibration of a camera over (or under) the table: where four table
//! points appear in its image, and how its grey levels become the contact
//! image's.
//!
//! # Format (version 1)
//!
//! ```toml
//! format = "surfacelab-calibration"   # required, exactly this
//! version = 1                         # required
//! kind = "ir"                         # "ir" or "depth"
//! image_size = [640, 480]             # the frames' size in pixels, each 2..=16384
//! image_points = [[x, y], [x, y], [x, y], [x, y]]   # pixels, integers at pixel centres
//! table_points = [[x, y], [x, y], [x, y], [x, y]]   # table metres, same order
//! # kind = "ir" only:
//! background = "background.png"       # optional; relative to this file's folder
//! threshold = 40                      # 0..=254 grey levels (default 40)
//! # kind = "depth" only:
//! table_depth_mm = 1200.0             # required; the table plane's distance from the camera
//! touch_band_mm = [4.0, 30.0]         # default [4, 30]; 0 <= near < far < table_depth_mm
//! ```
//!
//! Both point lists must be convex quadrilaterals in order round them (no
//! three on a line): the corners of the table, or any four marks on it.
//!
//! # Grey levels
//!
//! - `ir`: bright means near the glass. An 8-bit level `p` (a 16-bit one
//!   divided by 257) less the background's level `b` at that pixel (0 with
//!   no background) and less `threshold` is stretched back to full scale:
//!   `grey = 255 · (p − b − threshold) / (255 − threshold)`, 0 below.
//! - `depth`: 16-bit millimetres from the camera, 0 meaning no reading.
//!   Height above the table `h = table_depth_mm − d`; a pixel touches when
//!   `near ≤ h ≤ far`, with `grey = 255 · (far − h) / (far − near)`: 255 at
//!   the near edge of the band, falling to 0 at the far edge; 0 outside it.
//!
//! The vision stage's own threshold (48 of 255) then applies to that grey.

use super::{BitDepth, CameraImage, Homography, ImagesError, convex_in_order};
use crate::scene::bounds;
use crate::scene::{FieldError, FieldReader};
use serde::Deserialize;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use toml::Spanned;

/// The `format` value every calibration file carries.
pub const FORMAT: &str = "surfacelab-calibration";
/// The only `version` this build reads and writes.
pub const VERSION: i64 = 1;
/// `threshold` when none is given (grey levels above the background).
pub const DEFAULT_THRESHOLD: u8 = 40;
/// `touch_band_mm` when none is given: a fingertip's top lies about this
/// far above the table when it touches (Wilson, ITS 2010).
pub const DEFAULT_TOUCH_BAND_MM: [f32; 2] = [4.0, 30.0];
/// The largest side of a camera image this build accepts.
pub const MAX_SIDE_PX: u32 = 16384;

/// What the camera measures.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum CameraKind {
    /// Infrared brightness: bright is near the glass (FTIR, DI, DSI rigs).
    Ir,
    /// Distance from the camera in millimetres (a depth camera above the table).
    Depth,
}

impl CameraKind {
    pub fn name(self) -> &'static str {
        match self {
            CameraKind::Ir => "ir",
            CameraKind::Depth => "depth",
        }
    }

    /// The bit depth its frames must have: IR frames may be 8- or 16-bit,
    /// depth frames only 16-bit (millimetres do not fit in 8 bits).
    pub fn accepts(self, depth: BitDepth) -> bool {
        self == CameraKind::Ir || depth == BitDepth::Sixteen
    }
}

/// How camera levels become contact-image grey (see the module docs).
#[derive(Debug, Clone, PartialEq)]
pub enum Conversion {
    Ir { threshold: u8, background: Option<Background> },
    Depth { table_depth_mm: f32, touch_band_mm: [f32; 2] },
}

/// The IR camera's view of the empty table, subtracted from every frame.
#[derive(Debug, Clone, PartialEq)]
pub struct Background {
    /// As written in the file (relative to its folder).
    pub name: String,
    pub image: CameraImage,
}

/// A checked calibration. Invariants: both point sets are convex
/// quadrilaterals in order, the homography between them exists, the sizes
/// and levels are in range, a background has `image_size`.
#[derive(Debug, Clone, PartialEq)]
pub struct Calibration {
    pub image_size: [u32; 2],
    pub image_points: [[f64; 2]; 4],
    pub table_points: [[f64; 2]; 4],
    pub conversion: Conversion,
    /// Camera pixels to table metres.
    image_to_table: Homography,
}

impl Calibration {
    /// A calibration from values already checked by the caller's own flags
    /// (`calibrate`, `synth-images`); the same rules as a file, with
    /// `origin` naming where the values came from.
    pub fn new(
        conversion: Conversion,
        image_size: [u32; 2],
        image_points: [[f64; 2]; 4],
        table_points: [[f64; 2]; 4],
        origin: &str,
    ) -> Result<Calibration, ImagesError> {
        // The values go through the file's own checks, so a calibration made
        // from flags obeys exactly the rules of one read from a file.
        let text = to_toml(&conversion, image_size, &image_points, &table_points);
        let r = FieldReader::new(&text, origin);
        let mut c = check(&r, &r.parse()?, None)?;
        if let Conversion::Ir { background: Some(b), .. } = &conversion
            && [b.image.width, b.image.height] != image_size
        {
            let problem = format!(
                "{}x{} pixels; image_size is {}x{}",
                b.image.width, b.image.height, image_size[0], image_size[1]
            );
            return Err(r.error(None, "background", problem).into());
        }
        // Equal to what was checked but for the background, which the text
        // only names.
        c.conversion = conversion;
        Ok(c)
    }

    /// Reads a calibration file; a `background` is read from the file's folder.
    pub fn load(path: &Path) -> Result<Calibration, ImagesError> {
        let origin = path.display().to_string();
        let text =
            crate::files::read_capped(path).map_err(|source| ImagesError::Io { path: origin.clone(), source })?;
        let dir = path.parent().map_or_else(|| PathBuf::from("."), Path::to_path_buf);
        Self::from_str(&text, &origin, &dir)
    }

    /// Parses calibration text; `dir` is where a `background` is looked for.
    pub fn from_str(text: &str, origin: &str, dir: &Path) -> Result<Calibration, ImagesError> {
        let r = FieldReader::new(text, origin);
        let raw: RawCalibration = r.parse()?;
        check(&r, &raw, Some(dir))
    }

    pub fn kind(&self) -> CameraKind {
        match self.conversion {
            Conversion::Ir { .. } => CameraKind::Ir,
            Conversion::Depth { .. } => CameraKind::Depth,
        }
    }

    /// Camera pixels (integers at pixel centres) to table metres.
    pub fn image_to_table(&self) -> Homography {
        self.image_to_table
    }

    /// The file's text, which [`Calibration::load`] reads back as this
    /// calibration (floats in Rust's shortest round-trip digits).
    pub fn to_toml(&self) -> String {
        to_toml(&self.conversion, self.image_size, &self.image_points, &self.table_points)
    }
}

fn to_toml(conversion: &Conversion, size: [u32; 2], image: &[[f64; 2]; 4], table: &[[f64; 2]; 4]) -> String {
    let points = |p: &[[f64; 2]; 4]| {
        let v: Vec<String> = p.iter().map(|[x, y]| format!("[{x:?}, {y:?}]")).collect();
        format!("[{}]", v.join(", "))
    };
    let mut s = String::new();
    let _ = writeln!(s, "# surfacelab camera calibration; format described in src/input/images/calibration.rs");
    let _ = writeln!(s, "format = \"{FORMAT}\"\nversion = {VERSION}");
    let kind = match conversion {
        Conversion::Ir { .. } => CameraKind::Ir,
        Conversion::Depth { .. } => CameraKind::Depth,
    };
    let _ = writeln!(s, "kind = \"{}\"", kind.name());
    let _ = writeln!(s, "image_size = [{}, {}]", size[0], size[1]);
    let _ = writeln!(s, "image_points = {}", points(image));
    let _ = writeln!(s, "table_points = {}", points(table));
    match conversion {
        Conversion::Ir { threshold, background } => {
            if let Some(b) = background {
                let _ = writeln!(s, "background = {}", toml::Value::String(b.name.clone()));
            }
            let _ = writeln!(s, "threshold = {threshold}");
        }
        Conversion::Depth { table_depth_mm, touch_band_mm: [a, b] } => {
            let _ = writeln!(s, "table_depth_mm = {:?}", f64::from(*table_depth_mm));
            let _ = writeln!(s, "touch_band_mm = [{:?}, {:?}]", f64::from(*a), f64::from(*b));
        }
    }
    s
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawCalibration {
    format: Option<Spanned<toml::Value>>,
    version: Option<Spanned<toml::Value>>,
    kind: Spanned<String>,
    #[serde(deserialize_with = "crate::files::fixed_arrays::exactly")]
    image_size: Spanned<[i64; 2]>,
    #[serde(deserialize_with = "crate::files::fixed_arrays::exactly")]
    image_points: Spanned<Vec<[f64; 2]>>,
    #[serde(deserialize_with = "crate::files::fixed_arrays::exactly")]
    table_points: Spanned<Vec<[f64; 2]>>,
    background: Option<Spanned<String>>,
    threshold: Option<Spanned<i64>>,
    table_depth_mm: Option<Spanned<f64>>,
    #[serde(default, deserialize_with = "crate::files::fixed_arrays::exactly")]
    touch_band_mm: Option<Spanned<[f64; 2]>>,
}

fn offset<T>(s: &Spanned<T>) -> usize {
    s.span().start
}

/// The file's `format` and `version`: this build's, or an error naming
/// what it found.
fn check_header(r: &FieldReader<'_>, raw: &RawCalibration) -> Result<(), ImagesError> {
    match &raw.format {
        None => return Err(r.error(None, "format", format!("missing; expected \"{FORMAT}\"")).into()),
        Some(f) if f.get_ref().as_str() != Some(FORMAT) => {
            return Err(r
                .error(Some(offset(f)), "format", format!("expected \"{FORMAT}\", found {}", f.get_ref()))
                .into());
        }
        Some(_) => {}
    }
    match &raw.version {
        None => return Err(r.error(None, "version", format!("missing; this build reads version {VERSION}")).into()),
        Some(v) if v.get_ref().as_integer() != Some(VERSION) => {
            let problem = format!("unsupported version {}; this build reads version {VERSION}", v.get_ref());
            return Err(r.error(Some(offset(v)), "version", problem).into());
        }
        Some(_) => {}
    }
    Ok(())
}

/// Every rule of the format; `dir`: where to read a background (`None`:
/// the caller supplies it).
fn check(r: &FieldReader<'_>, raw: &RawCalibration, dir: Option<&Path>) -> Result<Calibration, ImagesError> {
    check_header(r, raw)?;
    let kind = match raw.kind.get_ref().as_str() {
        "ir" => CameraKind::Ir,
        "depth" => CameraKind::Depth,
        other => {
            return Err(r
                .error(Some(offset(&raw.kind)), "kind", format!("unknown kind \"{other}\"; expected ir or depth"))
                .into());
        }
    };
    let mut image_size = [0u32; 2];
    for (i, v) in raw.image_size.get_ref().iter().enumerate() {
        let field = format!("image_size[{i}]");
        image_size[i] = r.in_range(Some(offset(&raw.image_size)), &field, *v, 2, i64::from(MAX_SIDE_PX))? as u32;
    }
    let image_points = four(r, "image_points", &raw.image_points, f64::from(MAX_SIDE_PX) * 4.0)?;
    let table_points = four(r, "table_points", &raw.table_points, f64::from(bounds::POSITION_M))?;
    // Each corner's triangle at least a pixel, or a square millimetre.
    if !convex_in_order(&image_points, 1.0) {
        return Err(not_convex(r, "image_points", &raw.image_points));
    }
    if !convex_in_order(&table_points, 1e-6) {
        return Err(not_convex(r, "table_points", &raw.table_points));
    }
    let image_to_table = Homography::from_points(&image_points, &table_points).ok_or_else(|| {
        r.error(Some(offset(&raw.image_points)), "image_points", "the points fix no homography onto table_points")
    })?;

    let wrong_kind = |field: &str, s: Option<usize>| -> FieldError {
        r.error(s, field, format!("only kind \"{}\" takes `{field}`", other(kind).name()))
    };
    let conversion = match kind {
        CameraKind::Ir => {
            if let Some(v) = &raw.table_depth_mm {
                return Err(wrong_kind("table_depth_mm", Some(offset(v))).into());
            }
            if let Some(v) = &raw.touch_band_mm {
                return Err(wrong_kind("touch_band_mm", Some(offset(v))).into());
            }
            let threshold = match &raw.threshold {
                Some(t) => r.in_range(Some(offset(t)), "threshold", *t.get_ref(), 0, 254)? as u8,
                None => DEFAULT_THRESHOLD,
            };
            let background = match (&raw.background, dir) {
                (Some(name), Some(dir)) => Some(background(r, name, dir, image_size)?),
                _ => None,
            };
            Conversion::Ir { threshold, background }
        }
        CameraKind::Depth => {
            if let Some(v) = &raw.threshold {
                return Err(wrong_kind("threshold", Some(offset(v))).into());
            }
            if let Some(v) = &raw.background {
                return Err(wrong_kind("background", Some(offset(v))).into());
            }
            let Some(d) = &raw.table_depth_mm else {
                return Err(r
                    .error(None, "table_depth_mm", "missing; kind \"depth\" needs the table's distance")
                    .into());
            };
            let table_depth_mm = r.number(Some(offset(d)), "table_depth_mm", *d.get_ref(), 1.0, 65535.0)? as f32;
            let touch_band_mm = match &raw.touch_band_mm {
                Some(b) => {
                    let [near, far] = *b.get_ref();
                    let far_max = f64::from(table_depth_mm);
                    let near = r.number(Some(offset(b)), "touch_band_mm[0]", near, 0.0, far_max)?;
                    let far = r.number(Some(offset(b)), "touch_band_mm[1]", far, 0.0, far_max)?;
                    if far <= near {
                        return Err(r
                            .error(
                                Some(offset(b)),
                                "touch_band_mm",
                                format!("[{near}, {far}]: the far edge must exceed the near"),
                            )
                            .into());
                    }
                    [near as f32, far as f32]
                }
                None => DEFAULT_TOUCH_BAND_MM,
            };
            if touch_band_mm[1] >= table_depth_mm {
                let s = raw.touch_band_mm.as_ref().map(offset);
                return Err(r.error(s, "touch_band_mm", "reaches the camera: it must end below table_depth_mm").into());
            }
            Conversion::Depth { table_depth_mm, touch_band_mm }
        }
    };
    Ok(Calibration { image_size, image_points, table_points, conversion, image_to_table })
}

fn other(kind: CameraKind) -> CameraKind {
    match kind {
        CameraKind::Ir => CameraKind::Depth,
        CameraKind::Depth => CameraKind::Ir,
    }
}

fn four(
    r: &FieldReader<'_>,
    field: &str,
    raw: &Spanned<Vec<[f64; 2]>>,
    far: f64,
) -> Result<[[f64; 2]; 4], ImagesError> {
    let v = raw.get_ref();
    if v.len() != 4 {
        return Err(r.error(Some(offset(raw)), field, format!("needs exactly 4 points, found {}", v.len())).into());
    }
    let mut out = [[0.0; 2]; 4];
    for (i, p) in v.iter().enumerate() {
        for (j, c) in p.iter().enumerate() {
            out[i][j] = r.number(Some(offset(raw)), &format!("{field}[{i}][{j}]"), *c, -far, far)?;
        }
    }
    Ok(out)
}

fn not_convex(r: &FieldReader<'_>, field: &str, raw: &Spanned<Vec<[f64; 2]>>) -> ImagesError {
    r.error(
        Some(offset(raw)),
        field,
        "the 4 points must be the corners of a convex quadrilateral, in order round it, no three on a line",
    )
    .into()
}

fn background(
    r: &FieldReader<'_>,
    name: &Spanned<String>,
    dir: &Path,
    size: [u32; 2],
) -> Result<Background, ImagesError> {
    let path = dir.join(name.get_ref());
    let image =
        CameraImage::read(&path).map_err(|e| r.error(Some(offset(name)), "background", crate::error::chain(&e)))?;
    if [image.width, image.height] != size {
        let problem = format!(
            "{} is {}x{} pixels; image_size is {}x{}",
            path.display(),
            image.width,
            image.height,
            size[0],
            size[1]
        );
        return Err(r.error(Some(offset(name)), "background", problem).into());
    }
    Ok(Background { name: name.get_ref().clone(), image })
}

#[cfg(test)]
mod tests {
    use super::*;

    const IR: &str = r#"format = "surfacelab-calibration"
version = 1
kind = "ir"
image_size = [640, 480]
image_points = [[70, 40], [590, 60], [620, 450], [30, 430]]
table_points = [[-0.5, 0.375], [0.5, 0.375], [0.5, -0.375], [-0.5, -0.375]]
threshold = 30
"#;

    fn parse(text: &str) -> Result<Calibration, String> {
        Calibration::from_str(text, "c.toml", Path::new(".")).map_err(|e| crate::error::chain(&e))
    }

    #[test]
    fn a_valid_file_reads_and_writes_back() {
        let c = parse(IR).expect("valid");
        assert_eq!(c.kind(), CameraKind::Ir);
        assert_eq!(c.conversion, Conversion::Ir { threshold: 30, background: None });
        let corner = c.image_to_table().apply([620.0, 450.0]).expect("finite");
        assert!((corner[0] - 0.5).abs() < 1e-9 && (corner[1] + 0.375).abs() < 1e-9, "{corner:?}");
        assert_eq!(parse(&c.to_toml()).expect("round trip"), c);

        let depth = IR.replace("\"ir\"", "\"depth\"").replace("threshold = 30", "table_depth_mm = 1200.0");
        let d = parse(&depth).expect("depth");
        assert_eq!(d.conversion, Conversion::Depth { table_depth_mm: 1200.0, touch_band_mm: [4.0, 30.0] });
        assert_eq!(parse(&d.to_toml()).expect("round trip"), d);
    }

    #[test]
    fn bad_values_name_their_line_and_field() {
        let cases = [
            (IR.replace("[30, 430]]", "]"), "c.toml:5: field `image_points`: needs exactly 4 points, found 3"),
            (
                IR.replace("[620, 450], [30, 430]", "[30, 430], [620, 450]"),
                "c.toml:5: field `image_points`: the 4 points must be the corners of a convex quadrilateral, in order round it, no three on a line",
            ),
            (
                IR.replace("[0.5, -0.375]", "[0.0, 0.375]"),
                "c.toml:6: field `table_points`: the 4 points must be the corners of a convex quadrilateral, in order round it, no three on a line",
            ),
            (IR.replace("[640, 480]", "[0, 480]"), "c.toml:4: field `image_size[0]`: 0 is out of range (2..=16384)"),
            (IR.replace("= 30", "= 255"), "c.toml:7: field `threshold`: 255 is out of range (0..=254)"),
            (IR.replace("\"ir\"", "\"rgb\""), "c.toml:3: field `kind`: unknown kind \"rgb\"; expected ir or depth"),
            (
                IR.replace("threshold = 30", "table_depth_mm = 900.0"),
                "c.toml:7: field `table_depth_mm`: only kind \"depth\" takes `table_depth_mm`",
            ),
            (
                IR.replace("\"ir\"", "\"depth\"").replace("threshold = 30", ""),
                "c.toml: field `table_depth_mm`: missing; kind \"depth\" needs the table's distance",
            ),
            (
                IR.replace("\"ir\"", "\"depth\"")
                    .replace("threshold = 30", "table_depth_mm = 900.0\ntouch_band_mm = [30.0, 4.0]"),
                "c.toml:8: field `touch_band_mm`: [30, 4]: the far edge must exceed the near",
            ),
            (
                IR.replace("version = 1", "version = 2"),
                "c.toml:2: field `version`: unsupported version 2; this build reads version 1",
            ),
        ];
        for (text, want) in cases {
            assert_eq!(parse(&text).expect_err(want), want);
        }
        let unknown = parse(&format!("{IR}treshold = 3\n")).expect_err("unknown field");
        assert!(unknown.starts_with("c.toml:8: unknown field `treshold`"), "{unknown}");
    }

    #[test]
    fn a_background_is_read_beside_the_file_and_must_fit() {
        let dir = tempfile::tempdir().expect("dir");
        let bg = CameraImage { width: 640, height: 480, pixels: super::super::Pixels::Grey8(vec![9; 640 * 480]) };
        bg.write(&dir.path().join("bg.png")).expect("write");
        let text = format!("{IR}background = \"bg.png\"\n");
        let c = Calibration::from_str(&text, "c.toml", dir.path()).expect("valid");
        let Conversion::Ir { background: Some(b), .. } = &c.conversion else { panic!("no background: {c:?}") };
        assert_eq!(b.image, bg);
        let small = text
            .replace("[640, 480]", "[320, 240]")
            .replace("[620, 450]", "[300, 200]")
            .replace("[590, 60]", "[300, 20]")
            .replace("[30, 430]", "[20, 220]")
            .replace("[70, 40]", "[20, 20]");
        let e = Calibration::from_str(&small, "c.toml", dir.path()).map_err(|e| e.to_string()).expect_err("size");
        assert!(
            e.starts_with("c.toml:8: field `background`: ")
                && e.ends_with("bg.png is 640x480 pixels; image_size is 320x240"),
            "{e}"
        );
        let missing = Calibration::from_str(&text.replace("bg.png", "none.png"), "c.toml", dir.path())
            .map_err(|e| e.to_string())
            .expect_err("missing");
        assert!(
            missing.starts_with("c.toml:8: field `background`: ") && missing.contains("none.png: cannot read"),
            "{missing}"
        );
    }
}
