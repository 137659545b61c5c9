//! Reading an input file with a size cap, so `/dev/urandom` or a
//! runaway file is refused instead of read without end.

use std::io::Read;
use std::path::Path;

/// The file's text, at most [`super::bounds::MAX_INPUT_BYTES`] of it. A
/// longer file, or one that is not UTF-8, is an `InvalidData` error (bad
/// input, exit 2) that says which.
pub fn read_capped(path: &Path) -> std::io::Result<String> {
    read_capped_at(path, super::bounds::MAX_INPUT_BYTES)
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
}
