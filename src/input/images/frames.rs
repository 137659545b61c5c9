//! Which camera frame shows at which time: a folder of PNGs, in name
//! order at the scene's rate, or timed by the folder's `frames.csv`.

use super::{BitDepth, CameraImage, CameraKind, ImagesError};
use crate::scene::bounds;
use std::path::{Path, PathBuf};

/// The optional timing file in a frames folder.
pub const FRAMES_CSV: &str = "frames.csv";

/// A checked list of frames. Invariants: at least one frame; every file
/// exists and is a grey PNG of the calibration's size and an accepted bit
/// depth (its header was read); times, when given, are finite, within
/// `0..=DURATION_S` and strictly increasing.
#[derive(Debug, Clone, PartialEq)]
pub struct FrameList {
    frames: Vec<PathBuf>,
    /// Seconds per frame from `frames.csv`; `None`: one frame per physics step.
    times: Option<Vec<f64>>,
}

impl FrameList {
    /// Lists `dir`'s frames: the rows of `frames.csv` when there is one
    /// (`file, t_s`, a header row, files relative to `dir`; other files in
    /// the folder are ignored), otherwise every `*.png` in byte order of
    /// the file name (so `frame_00010.png` after `frame_00009.png`; pad
    /// numbers with zeros), except `skip` (the background image, when it
    /// lies in the same folder). Every frame's header is read now, so a
    /// missing, unreadable, wrong-sized or wrong-depth frame is reported,
    /// by name, before the first one plays.
    pub fn open(dir: &Path, kind: CameraKind, size: [u32; 2], skip: Option<&Path>) -> Result<FrameList, ImagesError> {
        let csv = dir.join(FRAMES_CSV);
        let (frames, times) = if csv.is_file() {
            let (frames, times) = read_csv(&csv, dir)?;
            (frames, Some(times))
        } else {
            (list_pngs(dir, skip)?, None)
        };
        if frames.is_empty() {
            return Err(ImagesError::NoFrames { dir: dir.display().to_string() });
        }
        for path in &frames {
            check_frame(path, kind, size)?;
        }
        Ok(FrameList { frames, times })
    }

    pub fn len(&self) -> usize {
        self.frames.len()
    }

    pub fn is_empty(&self) -> bool {
        self.frames.is_empty()
    }

    pub fn path(&self, i: usize) -> &Path {
        &self.frames[i]
    }

    /// When frame `i` shows, seconds, with `dt` the physics step.
    pub fn time(&self, i: usize, dt: f64) -> f64 {
        match &self.times {
            Some(t) => t[i],
            None => i as f64 * dt,
        }
    }

    /// The time of the last frame: the sequence's length.
    pub fn duration(&self, dt: f64) -> f64 {
        self.time(self.frames.len() - 1, dt)
    }

    /// The frame the physics step at time `t` sees: the latest one due by
    /// then (within half a step, as gesture replays sample). `None` before
    /// the first frame and after the last one's step: the glass is empty.
    /// A frame is held until the next is due.
    pub fn at(&self, t: f64, dt: f64) -> Option<usize> {
        let due = t + 0.5 * dt;
        let i = match &self.times {
            Some(times) => times.partition_point(|&ti| ti <= due).checked_sub(1)?,
            None => (due / dt).floor() as usize,
        };
        (i < self.frames.len() && t < self.duration(dt) + 0.5 * dt).then_some(i)
    }
}

/// The first frame `FrameList::open` would play (the first row of
/// `frames.csv`, or the first PNG by name but `skip`), unchecked: what
/// `calibrate` reads the image size and bit depth from.
pub fn first_frame(dir: &Path, skip: Option<&Path>) -> Result<PathBuf, ImagesError> {
    let csv = dir.join(FRAMES_CSV);
    let frames = if csv.is_file() { read_csv(&csv, dir)?.0 } else { list_pngs(dir, skip)? };
    frames.into_iter().next().ok_or_else(|| ImagesError::NoFrames { dir: dir.display().to_string() })
}

/// A frame's header: it exists, is a grey PNG, has the calibration's size
/// and a bit depth the camera kind accepts.
pub fn check_frame(path: &Path, kind: CameraKind, size: [u32; 2]) -> Result<BitDepth, ImagesError> {
    let (w, h, depth) = CameraImage::probe(path)?;
    let problem = if [w, h] != size {
        format!("{w}x{h} pixels; the calibration's image_size is {}x{}", size[0], size[1])
    } else if !kind.accepts(depth) {
        format!("{}-bit grey; {} frames must be 16-bit millimetres", depth.bits(), kind.name())
    } else {
        return Ok(depth);
    };
    Err(ImagesError::Frame { path: path.display().to_string(), problem })
}

fn list_pngs(dir: &Path, skip: Option<&Path>) -> Result<Vec<PathBuf>, ImagesError> {
    let io = |source| ImagesError::Io { path: dir.display().to_string(), source };
    let skip = skip.and_then(|p| p.canonicalize().ok());
    let mut frames = Vec::new();
    for entry in std::fs::read_dir(dir).map_err(io)? {
        let path = entry.map_err(io)?.path();
        let png = path.extension().is_some_and(|e| e.eq_ignore_ascii_case("png"));
        if png && path.is_file() && (skip.is_none() || path.canonicalize().ok() != skip) {
            frames.push(path);
        }
    }
    frames.sort_by(|a, b| a.file_name().cmp(&b.file_name()));
    Ok(frames)
}

#[derive(serde::Deserialize)]
struct Row {
    file: String,
    t_s: f64,
}

fn read_csv(csv: &Path, dir: &Path) -> Result<(Vec<PathBuf>, Vec<f64>), ImagesError> {
    let origin = csv.display().to_string();
    let text = crate::files::read_capped(csv).map_err(|source| ImagesError::Io { path: origin.clone(), source })?;
    let mut reader = csv::ReaderBuilder::new().trim(csv::Trim::All).from_reader(text.as_bytes());
    let (mut frames, mut times) = (Vec::new(), Vec::<f64>::new());
    let bad = |line: u64, problem: String| ImagesError::FrameList { path: origin.clone(), line, problem };
    let headers = reader.headers().map_err(|e| bad(1, e.to_string()))?.clone();
    if headers.iter().collect::<Vec<_>>() != ["file", "t_s"] {
        return Err(bad(
            1,
            format!("the header must be `file,t_s`, found `{}`", headers.iter().collect::<Vec<_>>().join(",")),
        ));
    }
    for row in reader.deserialize::<Row>() {
        let row = row.map_err(|e| {
            let line = e.position().map_or(0, csv::Position::line);
            let problem = match e.kind() {
                csv::ErrorKind::Deserialize { err, .. } => format!("{err}"),
                _ => e.to_string(),
            };
            bad(line, problem)
        })?;
        // Header is line 1; the next row is line 2.
        let line = frames.len() as u64 + 2;
        let max = f64::from(bounds::DURATION_S);
        if !row.t_s.is_finite() || !(0.0..=max).contains(&row.t_s) {
            return Err(bad(line, format!("t_s {} is out of range (0..={max} seconds)", row.t_s)));
        }
        if let Some(&last) = times.last()
            && row.t_s <= last
        {
            return Err(bad(line, format!("t_s {} does not come after the previous row's {last}", row.t_s)));
        }
        if row.file.is_empty() {
            return Err(bad(line, "empty file name".into()));
        }
        frames.push(dir.join(&row.file));
        times.push(row.t_s);
    }
    Ok((frames, times))
}

#[cfg(test)]
mod tests {
    use super::super::Pixels;
    use super::*;

    fn write(dir: &Path, name: &str, w: u32, h: u32) {
        CameraImage { width: w, height: h, pixels: Pixels::Grey8(vec![0; (w * h) as usize]) }
            .write(&dir.join(name))
            .expect("write");
    }

    #[test]
    fn name_order_at_the_step_rate() {
        let d = tempfile::tempdir().expect("dir");
        for name in ["f_002.png", "f_000.png", "bg.png", "f_001.png"] {
            write(d.path(), name, 4, 3);
        }
        std::fs::write(d.path().join("notes.txt"), "x").expect("write");
        let list = FrameList::open(d.path(), CameraKind::Ir, [4, 3], Some(&d.path().join("bg.png"))).expect("valid");
        let names: Vec<_> = (0..list.len()).map(|i| list.path(i).file_name().expect("name").to_owned()).collect();
        assert_eq!(names, ["f_000.png", "f_001.png", "f_002.png"]);
        let dt = 0.02;
        assert_eq!(
            [list.at(0.0, dt), list.at(0.02, dt), list.at(0.04, dt), list.at(0.06, dt)],
            [Some(0), Some(1), Some(2), None]
        );
        assert!((list.duration(dt) - 0.04).abs() < 1e-12);
    }

    #[test]
    fn frames_csv_times_frames_and_each_is_held() {
        let d = tempfile::tempdir().expect("dir");
        write(d.path(), "a.png", 4, 3);
        write(d.path(), "b.png", 4, 3);
        write(d.path(), "unused.png", 9, 9);
        std::fs::write(d.path().join(FRAMES_CSV), "file, t_s\na.png, 0.1\nb.png, 0.3\n").expect("write");
        let list = FrameList::open(d.path(), CameraKind::Ir, [4, 3], None).expect("valid");
        let dt = 0.1;
        let seen: Vec<_> = (0..6).map(|k| list.at(f64::from(k) * dt, dt)).collect();
        assert_eq!(seen, [None, Some(0), Some(0), Some(1), None, None]);
    }

    #[test]
    fn bad_frames_are_named() {
        let d = tempfile::tempdir().expect("dir");
        write(d.path(), "a.png", 4, 3);
        write(d.path(), "b.png", 5, 3);
        let e = FrameList::open(d.path(), CameraKind::Ir, [4, 3], None).expect_err("size").to_string();
        assert!(e.ends_with("b.png: 5x3 pixels; the calibration's image_size is 4x3"), "{e}");
        let e = FrameList::open(d.path(), CameraKind::Depth, [4, 3], None).expect_err("depth").to_string();
        assert!(e.ends_with("a.png: 8-bit grey; depth frames must be 16-bit millimetres"), "{e}");
        std::fs::write(d.path().join(FRAMES_CSV), "file,t_s\na.png,0\ngone.png,0.5\n").expect("write");
        let e = FrameList::open(d.path(), CameraKind::Ir, [4, 3], None).expect_err("missing");
        assert!(e.to_string().ends_with("gone.png: cannot read"), "{e}");
        assert_eq!(crate::error::Kind::kind(&e), crate::error::ErrorKind::BadInput);
        std::fs::write(d.path().join(FRAMES_CSV), "file,t_s\na.png,0.5\na.png,0.5\n").expect("write");
        let e = FrameList::open(d.path(), CameraKind::Ir, [4, 3], None).expect_err("order").to_string();
        assert!(e.ends_with("frames.csv:3: t_s 0.5 does not come after the previous row's 0.5"), "{e}");
        std::fs::write(d.path().join(FRAMES_CSV), "file,t_s\na.png,soon\n").expect("write");
        let e = FrameList::open(d.path(), CameraKind::Ir, [4, 3], None).expect_err("number").to_string();
        assert!(e.contains("frames.csv:2: "), "{e}");
        let empty = tempfile::tempdir().expect("dir");
        let e = FrameList::open(empty.path(), CameraKind::Ir, [4, 3], None).expect_err("empty").to_string();
        assert!(e.ends_with("no frames (no *.png files) in the folder"), "{e}");
        let e = FrameList::open(&empty.path().join("nope"), CameraKind::Ir, [4, 3], None).expect_err("no dir");
        assert_eq!(crate::error::Kind::kind(&e), crate::error::ErrorKind::BadInput, "{e}");
    }
}
