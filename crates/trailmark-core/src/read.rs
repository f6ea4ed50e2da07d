//! Reading a named file into memory with a size cap, refusing what is not a regular file.
//!
//! A path that comes from a user (a command-line argument, a map named by a problem document)
//! may name anything: a FIFO, whose opening blocks until someone writes to it; `/dev/zero` or
//! `/dev/urandom`, which never end; a directory; or a regular file of many gigabytes.
//! [`read_to_string_capped`] refuses all of them with a typed [`ReadFileError`] and never reads
//! more than its cap (plus one byte, to tell that a file is larger). Its errors name the path
//! but never quote the file's content.
//!
//! The caps used across trailmark: [`MAX_DOCUMENT_BYTES`] for JSON documents (problems,
//! results, terrains), and [`crate::movingai::MAX_MAP_FILE_BYTES`] /
//! [`crate::movingai::MAX_SCENARIO_FILE_BYTES`] for MovingAI benchmark files.
//!
//! ```
//! use trailmark_core::read::{ReadFileError, read_to_string_capped};
//!
//! let dir = std::env::temp_dir();
//! assert!(matches!(read_to_string_capped(&dir, 1 << 20), Err(ReadFileError::NotAFile { .. })));
//! # let file = dir.join(format!("trailmark-read-doc-{}", std::process::id()));
//! # std::fs::write(&file, "height 1\n").unwrap();
//! assert_eq!(read_to_string_capped(&file, 9)?, "height 1\n");
//! assert!(matches!(read_to_string_capped(&file, 8), Err(ReadFileError::TooLarge { max_bytes: 8, .. })));
//! # std::fs::remove_file(&file).unwrap();
//! # Ok::<(), ReadFileError>(())
//! ```

use std::fs::{File, Metadata};
use std::io::Read;
use std::path::{Path, PathBuf};

use thiserror::Error;

/// The cap for a JSON document read from a file (a problem, a result, a terrain): 64 MiB.
///
/// A grid of 4096 x 4096 cells given inline as rows takes some 17 MB of JSON; a larger grid
/// belongs in a `.map` file, which has its own cap. Parsing JSON into values takes several times
/// the text's size in memory, so a document cap well below the map cap keeps that bounded too.
pub const MAX_DOCUMENT_BYTES: u64 = 64 << 20;

/// Why a file could not be read.
#[derive(Debug, Error)]
pub enum ReadFileError {
    /// The file could not be opened or read (it does not exist, permission denied, ...).
    #[error("cannot read {}: {source}", path.display())]
    Io {
        /// The file.
        path: PathBuf,
        /// The I/O error.
        source: std::io::Error,
    },
    /// The path names something other than a regular file: a directory, a FIFO, a device, a
    /// socket.
    #[error("cannot read {}: it is {kind}, not a regular file", path.display())]
    NotAFile {
        /// The path.
        path: PathBuf,
        /// What it is: `"a directory"`, `"a FIFO"`, `"a character device"`, `"a block device"`,
        /// `"a socket"` or `"not a regular file"`.
        kind: &'static str,
    },
    /// The file is larger than the cap.
    #[error("cannot read {}: it is larger than {max_bytes} bytes, the most accepted", path.display())]
    TooLarge {
        /// The file.
        path: PathBuf,
        /// The cap, in bytes.
        max_bytes: u64,
    },
    /// The file is not UTF-8 text.
    #[error("cannot read {}: it is not UTF-8 text", path.display())]
    NotUtf8 {
        /// The file.
        path: PathBuf,
    },
}

/// What `metadata` describes, when it is not a regular file.
fn not_a_file(metadata: &Metadata) -> Option<&'static str> {
    let kind = metadata.file_type();
    if kind.is_file() {
        return None;
    }
    if kind.is_dir() {
        return Some("a directory");
    }
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileTypeExt;
        if kind.is_fifo() {
            return Some("a FIFO");
        }
        if kind.is_char_device() {
            return Some("a character device");
        }
        if kind.is_block_device() {
            return Some("a block device");
        }
        if kind.is_socket() {
            return Some("a socket");
        }
    }
    Some("not a regular file")
}

/// Opens `path` for reading. On Linux it is opened non-blocking, so that a FIFO put in place of
/// the checked file between the check and the open cannot block the open (reads of a regular
/// file are unaffected by the flag).
fn open(path: &Path) -> std::io::Result<File> {
    let mut options = std::fs::OpenOptions::new();
    options.read(true);
    #[cfg(all(
        target_os = "linux",
        any(
            target_arch = "x86_64",
            target_arch = "x86",
            target_arch = "aarch64",
            target_arch = "arm",
            target_arch = "riscv64"
        )
    ))]
    {
        use std::os::unix::fs::OpenOptionsExt;
        /// `O_NONBLOCK` on these architectures.
        const O_NONBLOCK: i32 = 0o4000;
        options.custom_flags(O_NONBLOCK);
    }
    options.open(path)
}

/// The text of the regular file at `path`, at most `max_bytes` bytes of UTF-8.
///
/// Errors, each naming the path and never the content:
/// - [`ReadFileError::NotAFile`] for a directory, FIFO, device or socket (checked before the
///   file is opened, so a FIFO cannot block it, and again on the opened file);
/// - [`ReadFileError::TooLarge`] for a file of more than `max_bytes` bytes (at most
///   `max_bytes + 1` bytes are ever read, whatever the file's reported size);
/// - [`ReadFileError::NotUtf8`] and [`ReadFileError::Io`] otherwise.
///
/// Symbolic links are followed: what they point to is checked.
pub fn read_to_string_capped(path: impl AsRef<Path>, max_bytes: u64) -> Result<String, ReadFileError> {
    let path = path.as_ref();
    let bytes = read_capped(path, max_bytes)?;
    String::from_utf8(bytes).map_err(|_| ReadFileError::NotUtf8 { path: path.to_path_buf() })
}

/// The bytes of the regular file at `path`, at most `max_bytes` of them: the same checks and
/// errors as [`read_to_string_capped`], for binary files (images).
pub fn read_capped(path: impl AsRef<Path>, max_bytes: u64) -> Result<Vec<u8>, ReadFileError> {
    let path = path.as_ref();
    let io = |source| ReadFileError::Io { path: path.to_path_buf(), source };
    let check = |metadata: &Metadata| match not_a_file(metadata) {
        Some(kind) => Err(ReadFileError::NotAFile { path: path.to_path_buf(), kind }),
        None if metadata.len() > max_bytes => {
            Err(ReadFileError::TooLarge { path: path.to_path_buf(), max_bytes })
        }
        None => Ok(()),
    };
    check(&std::fs::metadata(path).map_err(io)?)?;
    let file = open(path).map_err(io)?;
    let metadata = file.metadata().map_err(io)?;
    check(&metadata)?;
    // The reported size is only a hint (files in /proc report 0, a file may grow): reserve no
    // more than the cap allows, and read at most one byte beyond it.
    let hint = metadata.len().min(max_bytes).saturating_add(1);
    let mut bytes = Vec::with_capacity(usize::try_from(hint).unwrap_or(0));
    file.take(max_bytes.saturating_add(1)).read_to_end(&mut bytes).map_err(io)?;
    if u64::try_from(bytes.len()).map_or(true, |n| n > max_bytes) {
        return Err(ReadFileError::TooLarge { path: path.to_path_buf(), max_bytes });
    }
    Ok(bytes)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scratch(name: &str) -> PathBuf {
        let dir = std::env::temp_dir().join(format!("trailmark-read-{}-{name}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        dir
    }

    #[test]
    fn caps_are_exact() {
        let dir = scratch("caps");
        let file = dir.join("ten");
        std::fs::write(&file, "0123456789").unwrap();
        assert_eq!(read_to_string_capped(&file, 10).unwrap(), "0123456789");
        assert_eq!(read_to_string_capped(&file, u64::MAX).unwrap(), "0123456789");
        assert!(matches!(read_to_string_capped(&file, 9), Err(ReadFileError::TooLarge { max_bytes: 9, .. })));
        assert!(matches!(read_to_string_capped(&file, 0), Err(ReadFileError::TooLarge { .. })));
        std::fs::write(&file, "").unwrap();
        assert_eq!(read_to_string_capped(&file, 0).unwrap(), "");
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn what_is_not_a_regular_file_is_refused() {
        let dir = scratch("kinds");
        assert!(matches!(
            read_to_string_capped(&dir, 100),
            Err(ReadFileError::NotAFile { kind: "a directory", .. })
        ));
        assert!(matches!(read_to_string_capped(dir.join("missing"), 100), Err(ReadFileError::Io { .. })));
        let bad = dir.join("latin1");
        std::fs::write(&bad, b"caf\xe9").unwrap();
        let e = read_to_string_capped(&bad, 100).unwrap_err();
        assert!(matches!(e, ReadFileError::NotUtf8 { .. }));
        assert!(!e.to_string().contains("caf"), "{e}");
        std::fs::remove_dir_all(&dir).unwrap();
        #[cfg(unix)]
        for device in ["/dev/zero", "/dev/null", "/dev/urandom"] {
            if std::path::Path::new(device).exists() {
                assert!(matches!(
                    read_to_string_capped(device, 100),
                    Err(ReadFileError::NotAFile { kind: "a character device", .. })
                ));
            }
        }
    }
}
