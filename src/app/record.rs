//! Recording the live input as a gesture file that `surfacelab run` and
//! `surfacelab study --replay` replay. A recording starts from a freshly
//! reset scene, so the file replays from the state it was made in.

use crate::pipeline::surface::Hand;

use crate::input::{Gesture, GestureRecorder};
use anyhow::Context;
use std::path::{Path, PathBuf};
use std::time::{SystemTime, UNIX_EPOCH};

/// A recording in progress.
#[derive(Debug)]
pub struct Recording {
    recorder: GestureRecorder,
    path: PathBuf,
    /// Session times of the first and the last step recorded.
    span: Option<[f64; 2]>,
}

impl Recording {
    pub fn new(path: PathBuf) -> Self {
        Self { recorder: GestureRecorder::new(), path, span: None }
    }

    pub fn path(&self) -> &Path {
        &self.path
    }

    /// Adds the hands of one step at session time `t`.
    pub fn record(&mut self, t: f64, hands: &[Hand]) {
        if self.recorder.record(t, hands) {
            let first = self.span.map_or(t, |s| s[0]);
            self.span = Some([first, t]);
        }
    }

    /// Seconds recorded so far (hands down or not).
    pub fn duration(&self) -> f64 {
        self.span.map_or(0.0, |[a, b]| b - a)
    }

    /// Writes the file (creating its folder); returns the path and the gesture.
    pub fn save(self) -> anyhow::Result<(PathBuf, Gesture)> {
        let gesture = self.recorder.finish();
        if let Some(dir) = self.path.parent().filter(|d| !d.as_os_str().is_empty()) {
            std::fs::create_dir_all(dir).with_context(|| format!("creating {}", dir.display()))?;
        }
        gesture.save(&self.path)?;
        Ok((self.path, gesture))
    }
}

/// The short name of a task given as a name or a path (`tasks/cases/ball.toml` → `ball`).
pub fn task_stem(task: &str) -> String {
    Path::new(task).file_stem().map_or_else(|| task.to_owned(), |s| s.to_string_lossy().into_owned())
}

/// `dir/<task>_<YYYYmmdd-HHMMSS>.<ext>` (UTC) for a file made now.
pub fn timestamped(dir: &Path, task: &str, ext: &str) -> PathBuf {
    let secs = SystemTime::now().duration_since(UNIX_EPOCH).map_or(0, |d| d.as_secs());
    dir.join(format!("{}_{}.{ext}", task_stem(task), timestamp(secs)))
}

/// `YYYYmmdd-HHMMSS` of a Unix time, UTC (civil-from-days, proleptic Gregorian).
pub fn timestamp(unix_secs: u64) -> String {
    let days = (unix_secs / 86_400) as i64;
    let rem = unix_secs % 86_400;
    let z = days + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z.rem_euclid(146_097);
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let day = doy - (153 * mp + 2) / 5 + 1;
    let month = if mp < 10 { mp + 3 } else { mp - 9 };
    let year = yoe + era * 400 + i64::from(month <= 2);
    format!("{year:04}{month:02}{day:02}-{:02}{:02}{:02}", rem / 3600, rem % 3600 / 60, rem % 60)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::pipeline::surface::HandKind;

    #[test]
    fn timestamps_are_utc_calendar_dates() {
        assert_eq!(timestamp(0), "19700101-000000");
        assert_eq!(timestamp(951_782_400), "20000229-000000");
        assert_eq!(timestamp(1_763_733_845), "20251121-140405");
        assert_eq!(task_stem("tasks/cases/ball.toml"), "ball");
        assert_eq!(task_stem("sorting"), "sorting");
    }

    #[test]
    fn a_saved_recording_replays() {
        let dir = std::env::temp_dir().join(format!("surfacelab-record-{}", std::process::id()));
        let mut r = Recording::new(dir.join("sub").join("g.toml"));
        let hand = Hand::new(3, HandKind::FlatHand, 0.1, 0.0);
        for i in 0..30 {
            r.record(10.0 + f64::from(i) / 60.0, std::slice::from_ref(&hand));
        }
        assert!((r.duration() - 29.0 / 60.0).abs() < 1e-9);
        let (path, gesture) = r.save().expect("saves");
        let back = Gesture::load(&path).expect("reads back");
        assert_eq!(back, gesture);
        assert_eq!(back.sample(0.0)[0].kind, HandKind::FlatHand);
        let _ = std::fs::remove_dir_all(dir);
    }
}
