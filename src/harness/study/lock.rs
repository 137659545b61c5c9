//! One writer per run folder. A study, a resume or a merge holds an
//! exclusive lock on `DIR/.lock` for as long as it writes there, so a resume
//! started while the run is still going is refused instead of appending a
//! second copy of every trial (which once left trials.csv with 33 rows for
//! 18 trials and every later resume failing).
//!
//! The lock is the operating system's advisory file lock (`flock` on Unix,
//! through `std::fs::File::try_lock`), not the file's existence: the kernel
//! drops it when its process dies, however it dies, so a lock left by a
//! killed run is stale by construction and the next writer takes it over.
//! The file itself stays (deleting it would let two writers lock two
//! different files); while held it names its holder, so a refused writer
//! can say who holds it.

use super::StudyError;
use std::fs::{File, OpenOptions, TryLockError};
use std::io::{Read, Seek, SeekFrom, Write};
use std::path::Path;

/// Name of the lock file inside a run folder.
pub const LOCK_FILE: &str = ".lock";

/// An exclusive hold on a run folder, released when dropped.
#[derive(Debug)]
pub struct RunLock {
    file: File,
}

impl RunLock {
    /// Takes the lock of run folder `dir` (which must exist), or says which
    /// process holds it. A holder that died left only a stale note behind:
    /// it is taken over with a log line naming it.
    pub fn acquire(dir: &Path) -> Result<RunLock, StudyError> {
        let path = dir.join(LOCK_FILE);
        let mut file = OpenOptions::new()
            .read(true)
            .write(true)
            .create(true)
            .truncate(false)
            .open(&path)
            .map_err(StudyError::io(&path))?;
        match file.try_lock() {
            Ok(()) => {}
            Err(TryLockError::WouldBlock) => {
                return Err(StudyError::Locked { path: dir.to_owned(), holder: holder(&mut file) });
            }
            Err(TryLockError::Error(e)) => return Err(StudyError::Io { path, source: e }),
        }
        let stale = holder(&mut file);
        if !stale.is_empty() {
            tracing::info!("{}: taking over the lock left by {stale}, which is no longer running", dir.display());
        }
        let note = format!("pid {} (surfacelab {})\n", std::process::id(), env!("CARGO_PKG_VERSION"));
        let write = |f: &mut File| -> std::io::Result<()> {
            f.set_len(0)?;
            f.seek(SeekFrom::Start(0))?;
            f.write_all(note.as_bytes())?;
            f.sync_data()
        };
        write(&mut file).map_err(StudyError::io(&path))?;
        Ok(RunLock { file })
    }
}

impl Drop for RunLock {
    fn drop(&mut self) {
        // Cleared before the kernel lock goes, so a note found later always
        // belongs to a writer that died holding it.
        let _ = self.file.set_len(0);
    }
}

/// What the lock file says about its holder ("pid 1234 (surfacelab 0.2.0)").
fn holder(file: &mut File) -> String {
    let mut text = String::new();
    let _ = file.seek(SeekFrom::Start(0)).and_then(|_| file.take(256).read_to_string(&mut text));
    text.trim().to_owned()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn temp_dir(name: &str) -> std::path::PathBuf {
        let dir = std::env::temp_dir().join(format!("surfacelab-lock-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).expect("temp dir");
        dir
    }

    #[test]
    fn a_second_writer_is_refused_and_told_who_holds_the_folder() {
        let dir = temp_dir("second");
        let first = RunLock::acquire(&dir).expect("free folder");
        let err = RunLock::acquire(&dir).expect_err("held");
        let message = err.to_string();
        assert!(message.contains(&format!("pid {}", std::process::id())), "{message}");
        assert!(message.contains(&dir.display().to_string()), "{message}");
        drop(first);
        let again = RunLock::acquire(&dir).expect("released on drop");
        drop(again);
        let _ = std::fs::remove_dir_all(dir);
    }

    #[test]
    fn a_lock_left_by_a_dead_process_is_taken_over() {
        let dir = temp_dir("stale");
        // What a killed run leaves: its note, and no kernel lock.
        std::fs::write(dir.join(LOCK_FILE), "pid 4000000 (surfacelab 0.0.0)\n").expect("write");
        let lock = RunLock::acquire(&dir).expect("stale lock taken over");
        let note = std::fs::read_to_string(dir.join(LOCK_FILE)).expect("read");
        assert_eq!(note, format!("pid {} (surfacelab {})\n", std::process::id(), env!("CARGO_PKG_VERSION")));
        drop(lock);
        assert_eq!(std::fs::read_to_string(dir.join(LOCK_FILE)).expect("read"), "", "cleared on release");
        let _ = std::fs::remove_dir_all(dir);
    }
}
