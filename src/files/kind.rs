//! What a path names: a regular file, a folder, a link, a FIFO, a device.

use std::fs::{FileType, Metadata};
use std::io;
use std::path::Path;

/// What a path names.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// Nothing (or, followed, a link that leads nowhere).
    Missing,
    /// A regular file.
    Regular,
    /// A folder.
    Folder,
    /// A symbolic link (only when links are not followed).
    Link,
    /// A FIFO (named pipe).
    Fifo,
    /// A character device (`/dev/null`, a terminal).
    CharDevice,
    /// A block device (a disk).
    BlockDevice,
    /// A Unix socket.
    Socket,
    /// Anything else the system has.
    Other,
}

impl Kind {
    /// What `path` names itself: a link is [`Kind::Link`].
    pub fn of(path: &Path) -> io::Result<Kind> {
        from_metadata(std::fs::symlink_metadata(path))
    }

    /// What `path` leads to, links followed (a link to nothing is [`Kind::Missing`]).
    pub fn followed(path: &Path) -> io::Result<Kind> {
        from_metadata(std::fs::metadata(path))
    }

    /// The kind of a file type.
    pub fn from_type(t: FileType) -> Kind {
        if t.is_file() {
            return Kind::Regular;
        }
        if t.is_dir() {
            return Kind::Folder;
        }
        if t.is_symlink() {
            return Kind::Link;
        }
        #[cfg(unix)]
        {
            use std::os::unix::fs::FileTypeExt;
            if t.is_fifo() {
                return Kind::Fifo;
            }
            if t.is_char_device() {
                return Kind::CharDevice;
            }
            if t.is_block_device() {
                return Kind::BlockDevice;
            }
            if t.is_socket() {
                return Kind::Socket;
            }
        }
        Kind::Other
    }

    /// Whether a picture or statistics may be streamed into it (a FIFO or a
    /// character device such as `/dev/null`).
    pub fn is_stream(self) -> bool {
        matches!(self, Kind::Fifo | Kind::CharDevice)
    }

    /// The kind in words, with its article: "a FIFO (named pipe)".
    pub fn describe(self) -> &'static str {
        match self {
            Kind::Missing => "missing",
            Kind::Regular => "a regular file",
            Kind::Folder => "a folder",
            Kind::Link => "a symbolic link",
            Kind::Fifo => "a FIFO (named pipe)",
            Kind::CharDevice => "a character device",
            Kind::BlockDevice => "a block device",
            Kind::Socket => "a socket",
            Kind::Other => "not a regular file",
        }
    }
}

fn from_metadata(m: io::Result<Metadata>) -> io::Result<Kind> {
    match m {
        Ok(m) => Ok(Kind::from_type(m.file_type())),
        Err(e) if e.kind() == io::ErrorKind::NotFound => Ok(Kind::Missing),
        Err(e) => Err(e),
    }
}
