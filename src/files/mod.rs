//! Opening the files a scene or a render reads and writes so that none of them can
//! hurt the user (used by every stage; it imports none of them).
//!
//! - Reads ([`open_regular`], [`read_regular`]) take regular files only: a FIFO,
//!   a device or a folder is refused before it is opened (and checked again on
//!   the open handle), so a read never blocks on a pipe nor grows without end on
//!   `/dev/zero`, and a size limit bounds what is read.
//! - Writes ([`create`]) go to a temporary file created exclusively, under an
//!   unpredictable name, in the target's folder, renamed over the target once
//!   complete: a killed run never leaves half a file under the target's name, and
//!   the rename replaces a link instead of writing through it. What happens at a
//!   target that is not a regular file (stream into a FIFO or character device,
//!   or refuse) is the caller's [`Policy`].
//! - Temporary files still being written are listed, so an interrupted run can
//!   remove them before it exits ([`remove_temporaries_and_exit`]).

mod kind;
mod read;
mod write;

pub use kind::Kind;
pub use read::{open_regular, open_regular_no_link, read_all, read_regular, ReadError};
pub use write::{create, prepare, remove_temporaries_and_exit, target, OutputFile, Policy, Target};
