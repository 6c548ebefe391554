//! Reading regular files only, never blocking on a FIFO, never reading past a limit.

use super::Kind;
use std::fmt;
use std::fs::{File, OpenOptions};
use std::io::{self, Read};
use std::path::Path;

/// Why a file could not be read.
#[derive(Debug)]
pub enum ReadError {
    /// The path names something other than a regular file: a FIFO, a device, a
    /// folder, or (where links are not followed) a link.
    NotRegular(Kind),
    /// The file holds more than the limit (bytes).
    TooLarge {
        /// The limit.
        limit: u64,
    },
    /// The system's error.
    Io(io::Error),
}

impl fmt::Display for ReadError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ReadError::NotRegular(k) => write!(f, "it is {}, not a regular file", k.describe()),
            ReadError::TooLarge { limit } => write!(f, "it is larger than {limit} bytes"),
            ReadError::Io(e) => write!(f, "{e}"),
        }
    }
}

impl std::error::Error for ReadError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            ReadError::Io(e) => Some(e),
            _ => None,
        }
    }
}

impl From<io::Error> for ReadError {
    fn from(e: io::Error) -> ReadError {
        ReadError::Io(e)
    }
}

/// Opens `path` for reading when it leads to a regular file (links followed).
/// Anything else is refused before it is opened (opening some devices does
/// something), and the open handle is checked again, so a FIFO put in the file's
/// place meanwhile is refused too instead of blocking.
pub fn open_regular(path: &Path) -> Result<File, ReadError> {
    open(path, false)
}

/// As [`open_regular`], but a link at the last component of `path` is refused
/// too ([`Kind::Link`]).
pub fn open_regular_no_link(path: &Path) -> Result<File, ReadError> {
    open(path, true)
}

fn open(path: &Path, no_link: bool) -> Result<File, ReadError> {
    let kind = if no_link {
        Kind::of(path)?
    } else {
        Kind::followed(path)?
    };
    if !matches!(kind, Kind::Regular | Kind::Missing) {
        // A missing file is left to the open below, for the system's own message.
        return Err(ReadError::NotRegular(kind));
    }
    let mut options = OpenOptions::new();
    options.read(true);
    #[cfg(unix)]
    {
        use std::os::unix::fs::OpenOptionsExt;
        // Non-blocking: opening a FIFO that took the file's place returns at once
        // (and is refused below); no terminal becomes the controlling one.
        let mut flags = libc::O_NONBLOCK | libc::O_NOCTTY;
        if no_link {
            flags |= libc::O_NOFOLLOW;
        }
        options.custom_flags(flags);
    }
    let file = match options.open(path) {
        Ok(f) => f,
        #[cfg(unix)]
        Err(e) if no_link && e.raw_os_error() == Some(libc::ELOOP) => {
            return Err(ReadError::NotRegular(Kind::Link))
        }
        Err(e) => return Err(ReadError::Io(e)),
    };
    let meta = file.metadata()?;
    if !meta.is_file() {
        return Err(ReadError::NotRegular(Kind::from_type(meta.file_type())));
    }
    Ok(file)
}

/// Reads the whole of `file`, refusing it when it holds more than `limit` bytes
/// (however it grows while being read).
pub fn read_all(file: File, limit: u64) -> Result<Vec<u8>, ReadError> {
    let len = file.metadata().map_or(0, |m| m.len());
    if len > limit {
        return Err(ReadError::TooLarge { limit });
    }
    let mut buf = Vec::with_capacity(usize::try_from(len).unwrap_or(0));
    file.take(limit.saturating_add(1)).read_to_end(&mut buf)?;
    if buf.len() as u64 > limit {
        return Err(ReadError::TooLarge { limit });
    }
    Ok(buf)
}

/// Reads the regular file at `path` (see [`open_regular`]) whole, refusing it when
/// it holds more than `limit` bytes.
pub fn read_regular(path: &Path, limit: u64) -> Result<Vec<u8>, ReadError> {
    read_all(open_regular(path)?, limit)
}

#[cfg(all(test, unix))]
mod tests {
    use super::*;

    fn dir(name: &str) -> std::path::PathBuf {
        let d = std::env::temp_dir().join(format!("rts-files-read-{}-{name}", std::process::id()));
        let _ = std::fs::remove_dir_all(&d);
        std::fs::create_dir_all(&d).unwrap();
        d
    }

    #[test]
    fn regular_files_are_read_within_the_limit() {
        let d = dir("limit");
        let p = d.join("a.txt");
        std::fs::write(&p, "0123456789").unwrap();
        assert_eq!(read_regular(&p, 10).unwrap(), b"0123456789");
        assert!(matches!(
            read_regular(&p, 9),
            Err(ReadError::TooLarge { limit: 9 })
        ));
        assert!(matches!(
            read_regular(&d.join("missing"), 9),
            Err(ReadError::Io(e)) if e.kind() == io::ErrorKind::NotFound
        ));
    }

    #[test]
    fn devices_folders_and_fifos_are_refused_without_blocking() {
        let d = dir("kinds");
        assert!(matches!(
            read_regular(Path::new("/dev/zero"), 1 << 20),
            Err(ReadError::NotRegular(Kind::CharDevice))
        ));
        assert!(matches!(
            read_regular(&d, 10),
            Err(ReadError::NotRegular(Kind::Folder))
        ));
        let fifo = d.join("pipe");
        let made = std::process::Command::new("mkfifo")
            .arg(&fifo)
            .status()
            .unwrap();
        assert!(made.success());
        assert!(matches!(
            read_regular(&fifo, 10),
            Err(ReadError::NotRegular(Kind::Fifo))
        ));
        // A link to a regular file is followed, unless links are refused.
        let target = d.join("t.txt");
        std::fs::write(&target, "x").unwrap();
        let link = d.join("link.txt");
        std::os::unix::fs::symlink(&target, &link).unwrap();
        assert_eq!(read_regular(&link, 10).unwrap(), b"x");
        assert!(matches!(
            open_regular_no_link(&link),
            Err(ReadError::NotRegular(Kind::Link))
        ));
    }
}
