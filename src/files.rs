//! The files a user names: read with a size cap (so `/dev/urandom` or a
//! runaway file is refused instead of read without end), and written by
//! what the path is ([`write_output`]): a regular file atomically (a
//! temporary file in the same folder, fsync, rename), so a full disk or a
//! kill leaves the old file or the new one, never half of one, and no
//! temporary file behind; anything else (a FIFO, a terminal, a device,
//! standard output) straight through, because a rename would replace the
//! node itself. Like `error`, this depends on nothing in the crate; every
//! layer may use it.

pub(crate) mod fixed_arrays;

use std::io::{Read, Write};
use std::path::{Path, PathBuf};

/// Bytes read from any input file (scene, gesture, contact JSON, run.toml;
/// trials.csv excepted): the largest recording (a 25 s sorting gesture) is
/// a few hundred kilobytes. A larger file, or `/dev/urandom`, is refused after this
/// many bytes instead of read without end.
pub const MAX_INPUT_BYTES: u64 = 64 * 1024 * 1024;

/// The file's text, at most [`MAX_INPUT_BYTES`] of it. A
/// longer file, or one that is not UTF-8, is an `InvalidData` error (bad
/// input, exit 2) that says which.
pub fn read_capped(path: &Path) -> std::io::Result<String> {
    read_capped_at(path, MAX_INPUT_BYTES)
}

fn read_capped_at(path: &Path, cap: u64) -> std::io::Result<String> {
    let file = std::fs::File::open(path)?;
    let mut bytes = Vec::new();
    file.take(cap + 1).read_to_end(&mut bytes)?;
    if bytes.len() as u64 > cap {
        return Err(std::io::Error::new(
            std::io::ErrorKind::InvalidData,
            format!("larger than the {} MiB an input file may have", cap / (1024 * 1024)),
        ));
    }
    String::from_utf8(bytes).map_err(|_| std::io::Error::new(std::io::ErrorKind::InvalidData, "not UTF-8 text"))
}

/// [`read_capped`] of a path given as text (`-` is not special here).
pub fn read_capped_str(path: &str) -> std::io::Result<String> {
    read_capped(Path::new(path))
}

/// What an output path names, decided before anything is written.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum OutputTarget {
    /// `-`: standard output.
    Stdout,
    /// A regular file, or a path with nothing there yet (a dangling
    /// symlink's target counts): replaced atomically. For a symlink this
    /// is the file the link resolves to, so the link stays a link.
    File(PathBuf),
    /// A FIFO, a character or block device, a terminal or a socket: opened
    /// and written in place. A rename over it would swap the node for a
    /// regular file, and its reader (or the device) would never see the bytes.
    Stream(PathBuf),
}

impl OutputTarget {
    /// Classifies `path` by what the file system holds there, following
    /// symlinks. A folder is an error: an output is one file.
    pub fn of(path: &Path) -> std::io::Result<OutputTarget> {
        if path.as_os_str() == "-" {
            return Ok(OutputTarget::Stdout);
        }
        match std::fs::metadata(path) {
            // EISDIR (21 on Linux and macOS), worded as the OS words it.
            Ok(meta) if meta.is_dir() => Err(std::io::Error::from_raw_os_error(21)),
            Ok(meta) if meta.is_file() => {
                let is_link = std::fs::symlink_metadata(path).is_ok_and(|m| m.file_type().is_symlink());
                Ok(OutputTarget::File(if is_link { std::fs::canonicalize(path)? } else { path.to_path_buf() }))
            }
            Ok(_) => Ok(OutputTarget::Stream(path.to_path_buf())),
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => Ok(OutputTarget::File(dangling_target(path)?)),
            Err(e) => Err(e),
        }
    }
}

/// Where a path that does not exist is to be created: the path itself, or,
/// where it is a symlink to nothing yet, the end of its chain of links
/// (relative links read from the link's own folder), so the link is kept.
fn dangling_target(path: &Path) -> std::io::Result<PathBuf> {
    let mut at = path.to_path_buf();
    // A loop of links ends in ELOOP from `metadata` long before this bound.
    for _ in 0..40 {
        match std::fs::symlink_metadata(&at) {
            Ok(meta) if meta.file_type().is_symlink() => {
                let next = std::fs::read_link(&at)?;
                at = match at.parent() {
                    Some(dir) if next.is_relative() => dir.join(next),
                    _ => next,
                };
            }
            _ => return Ok(at),
        }
    }
    Err(std::io::Error::new(std::io::ErrorKind::InvalidInput, "too many levels of symbolic links"))
}

/// Writes `bytes` to the output `path` names, by what it is
/// ([`OutputTarget`]): `-` to standard output, a regular file (or a new
/// path, or a symlink's target) atomically with [`write_atomic`], and a
/// FIFO, device or terminal straight through. A device node, FIFO or
/// symlink is never replaced. The error is the OS error (ENOSPC from a full
/// device, EPIPE once a pipe's reader has gone); callers name the path.
pub fn write_output(path: &Path, bytes: &[u8]) -> std::io::Result<()> {
    match OutputTarget::of(path)? {
        OutputTarget::Stdout => {
            let mut out = std::io::stdout().lock();
            out.write_all(bytes)?;
            out.flush()
        }
        OutputTarget::File(file) => write_atomic(&file, bytes),
        OutputTarget::Stream(node) => {
            // No create, no truncate: the node exists and is not a file.
            let mut stream = std::fs::OpenOptions::new().write(true).open(node)?;
            stream.write_all(bytes)?;
            stream.flush()
        }
    }
}

/// Replaces the regular file `path` with `bytes` atomically: a temporary
/// file beside it (same folder, so the rename cannot cross file systems),
/// fsync, rename. On any failure the temporary file is removed and the old
/// `path`, if any, is untouched. The error is the OS error; callers name
/// the path. A missing parent folder is created first. Outputs a user
/// names go through [`write_output`], which calls this for regular files.
pub fn write_atomic(path: &Path, bytes: &[u8]) -> std::io::Result<()> {
    let dir = match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => Path::new("."),
    };
    std::fs::create_dir_all(dir)?;
    let name = path.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
    let prefix = format!(".{name}.");
    let mut builder = tempfile::Builder::new();
    builder.prefix(&prefix).suffix(".tmp");
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt as _;
        // The mode a plain `File::create` gives under the usual umask,
        // not tempfile's private 0600.
        builder.permissions(std::fs::Permissions::from_mode(0o644));
    }
    // Dropped on any early return: the temporary file is deleted.
    let mut tmp = builder.tempfile_in(dir)?;
    tmp.write_all(bytes)?;
    tmp.as_file().sync_all()?;
    tmp.persist(path).map_err(|e| e.error)?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_endless_file_is_refused_after_the_cap() {
        let e = read_capped_at(Path::new("/dev/zero"), 8 * 1024 * 1024).expect_err("endless");
        assert_eq!(e.kind(), std::io::ErrorKind::InvalidData);
        assert_eq!(e.to_string(), "larger than the 8 MiB an input file may have");
    }

    #[test]
    fn binary_is_not_text() {
        let p = std::env::temp_dir().join(format!("surfacelab-read-{}.bin", std::process::id()));
        std::fs::write(&p, [0xff_u8, 0xfe, 0x00]).expect("write");
        let e = read_capped(&p).expect_err("binary");
        std::fs::remove_file(&p).ok();
        assert_eq!((e.kind(), e.to_string().as_str()), (std::io::ErrorKind::InvalidData, "not UTF-8 text"));
    }

    #[test]
    fn an_atomic_write_replaces_the_file_and_a_failed_one_leaves_nothing() {
        let dir = std::env::temp_dir().join(format!("surfacelab-files-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        let path = dir.join("sub").join("a.json");
        write_atomic(&path, b"one").expect("write");
        write_atomic(&path, b"two").expect("rewrite");
        assert_eq!(std::fs::read(&path).expect("read"), b"two");
        // A folder where the file should be: the rename fails, the folder
        // stays, and no temporary file is left beside it.
        let blocked = dir.join("sub").join("blocked");
        std::fs::create_dir_all(blocked.join("x")).expect("dir");
        let e = write_atomic(&blocked, b"three").expect_err("a folder is in the way");
        assert!(blocked.join("x").is_dir(), "{e}");
        let names: Vec<String> = std::fs::read_dir(dir.join("sub"))
            .expect("list")
            .map(|e| e.expect("entry").file_name().to_string_lossy().into_owned())
            .collect();
        let mut names = names;
        names.sort();
        assert_eq!(names, ["a.json", "blocked"]);
        std::fs::remove_dir_all(&dir).ok();
    }

    #[test]
    fn an_output_path_is_classified_by_what_it_names() {
        let dir = tempfile::tempdir().expect("tmp");
        assert_eq!(OutputTarget::of(Path::new("-")).expect("dash"), OutputTarget::Stdout);
        assert_eq!(OutputTarget::of(Path::new("/dev/null")).expect("device"), OutputTarget::Stream("/dev/null".into()));
        let e = OutputTarget::of(dir.path()).expect_err("a folder");
        assert_eq!(e.kind(), std::io::ErrorKind::IsADirectory);
        let new = dir.path().join("new.json");
        assert_eq!(OutputTarget::of(&new).expect("new"), OutputTarget::File(new.clone()));
        // A chain of two links, the last dangling: the file at its end.
        std::os::unix::fs::symlink("b.json", dir.path().join("a.json")).expect("a");
        std::os::unix::fs::symlink("sub/c.json", dir.path().join("b.json")).expect("b");
        let end = dir.path().join("sub/c.json");
        assert_eq!(OutputTarget::of(&dir.path().join("a.json")).expect("chain"), OutputTarget::File(end.clone()));
        write_output(&dir.path().join("a.json"), b"x").expect("write through the chain");
        assert_eq!(std::fs::read(&end).expect("end"), b"x");
    }
}
