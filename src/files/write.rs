//! Writing files: a temporary file renamed over the target, or straight into a
//! stream; the list of temporary files an interrupted run removes.

use super::Kind;
use std::collections::BTreeMap;
use std::fs::{File, OpenOptions};
use std::io::{self, BufWriter, Seek, SeekFrom, Write};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Mutex, MutexGuard, PoisonError};
use tempfile::NamedTempFile;

/// What [`create`] may do with a target that is not a regular file.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Policy {
    /// Write straight into a FIFO or a character device (`/dev/null`), with no
    /// temporary file, and take `-` as standard output; a link is followed. For
    /// one picture or statistics.
    Stream,
    /// Regular files only; a link to one is followed and the file it leads to
    /// replaced. For frames of a sequence, checkpoints, manifests.
    FileOnly,
    /// Regular files only, and a link at the target's name is refused: for the
    /// files a scene names.
    FileNoLink,
}

/// Where writing a path goes.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Target {
    /// Standard output (`-`).
    Stdout,
    /// A FIFO or character device, written directly.
    Stream(PathBuf),
    /// A regular file at this path (or none yet), replaced by a rename.
    File(PathBuf),
}

fn refused(kind: Kind, policy: Policy) -> io::Error {
    let why = match (kind, policy) {
        (Kind::Link, _) => "it is a symbolic link, and a scene may not write through a link".into(),
        (k, Policy::Stream) => format!(
            "it is {}; rts writes regular files, FIFOs and character devices",
            k.describe()
        ),
        (k, _) if k.is_stream() => format!(
            "it is {}, and this is written to regular files only",
            k.describe()
        ),
        (k, _) => format!("it is {}, not a regular file", k.describe()),
    };
    io::Error::new(io::ErrorKind::InvalidInput, why)
}

/// Where writing `path` goes under `policy`, or why it may not be written.
/// Nothing is created. `-` is standard output under [`Policy::Stream`] only (a
/// file named `-` otherwise).
pub fn target(path: &Path, policy: Policy) -> io::Result<Target> {
    if path.as_os_str() == "-" && policy == Policy::Stream {
        return Ok(Target::Stdout);
    }
    let own = Kind::of(path)?;
    let kind = match own {
        Kind::Link if policy == Policy::FileNoLink => return Err(refused(Kind::Link, policy)),
        Kind::Link => Kind::followed(path)?,
        k => k,
    };
    match kind {
        // A link that leads nowhere is replaced, as a missing file is created.
        Kind::Missing => Ok(Target::File(path.to_path_buf())),
        Kind::Regular if own == Kind::Link => Ok(Target::File(path.canonicalize()?)),
        Kind::Regular => Ok(Target::File(path.to_path_buf())),
        k if k.is_stream() && policy == Policy::Stream => Ok(Target::Stream(path.to_path_buf())),
        k => Err(refused(k, policy)),
    }
}

/// A file being written (see [`create`]). Dropped without
/// [`OutputFile::commit`], its temporary file is removed and the target is left
/// as it was.
#[derive(Debug)]
pub struct OutputFile {
    sink: Sink,
}

#[derive(Debug)]
enum Sink {
    Temp {
        out: Option<BufWriter<NamedTempFile>>,
        id: u64,
        target: PathBuf,
    },
    Stream(BufWriter<File>),
    Stdout(BufWriter<io::Stdout>),
}

/// Temporary files being written, by id: what [`remove_temporaries_and_exit`]
/// removes.
static LIVE: Mutex<BTreeMap<u64, PathBuf>> = Mutex::new(BTreeMap::new());
static NEXT_ID: AtomicU64 = AtomicU64::new(0);

fn live() -> MutexGuard<'static, BTreeMap<u64, PathBuf>> {
    LIVE.lock().unwrap_or_else(PoisonError::into_inner)
}

fn folder_of(path: &Path) -> &Path {
    match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => Path::new("."),
    }
}

/// A new temporary file `.NAME.XXXXXX.tmp` beside `target` (created exclusively,
/// the `X`s random), listed in [`LIVE`].
fn temporary(target: &Path) -> io::Result<(NamedTempFile, u64)> {
    // Short enough that the temporary name stays within a file name's limit.
    let name: String = target
        .file_name()
        .map_or_else(|| "out".into(), |n| n.to_string_lossy().into_owned())
        .chars()
        .take(120)
        .collect();
    let prefix = format!(".{name}.");
    let mut builder = tempfile::Builder::new();
    builder.prefix(&prefix).suffix(".tmp");
    #[cfg(unix)]
    {
        // As a file made by File::create: the umask decides (tempfile's own
        // default is owner-only).
        use std::os::unix::fs::PermissionsExt;
        builder.permissions(std::fs::Permissions::from_mode(0o666));
    }
    let mut live = live();
    let file = builder.tempfile_in(folder_of(target))?;
    let id = NEXT_ID.fetch_add(1, Ordering::Relaxed);
    live.insert(id, file.path().to_path_buf());
    Ok((file, id))
}

fn open_stream(path: &Path) -> io::Result<File> {
    let mut options = OpenOptions::new();
    // Neither created nor truncated: a FIFO or device is written as it is.
    options.write(true);
    #[cfg(unix)]
    {
        use std::os::unix::fs::OpenOptionsExt;
        options.custom_flags(libc::O_NOCTTY);
    }
    let file = options.open(path)?;
    if !Kind::from_type(file.metadata()?.file_type()).is_stream() {
        return Err(io::Error::other(
            "it stopped being a FIFO or device while being opened",
        ));
    }
    Ok(file)
}

/// Starts writing `path` under `policy` (see [`target`]). A regular file is
/// written to a temporary file `.NAME.XXXXXX.tmp` created exclusively in its
/// folder (the `X`s random), which [`OutputFile::commit`] renames over it; a
/// stream is opened for writing (a FIFO waits for its reader) and written
/// directly.
pub fn create(path: &Path, policy: Policy) -> io::Result<OutputFile> {
    let sink = match target(path, policy)? {
        Target::Stdout => Sink::Stdout(BufWriter::new(io::stdout())),
        Target::Stream(p) => Sink::Stream(BufWriter::new(open_stream(&p)?)),
        Target::File(t) => {
            let (file, id) = temporary(&t)?;
            Sink::Temp {
                out: Some(BufWriter::with_capacity(1 << 16, file)),
                id,
                target: t,
            }
        }
    };
    Ok(OutputFile { sink })
}

/// Checks before a long job that `path` can be written under `policy`: a regular
/// file's folder is created when missing, and a temporary file is made there and
/// removed, so a folder that cannot be written fails now. A stream is not opened
/// (a FIFO would wait for its reader).
pub fn prepare(path: &Path, policy: Policy) -> io::Result<Target> {
    let t = target(path, policy)?;
    if let Target::File(f) = &t {
        std::fs::create_dir_all(folder_of(f))?;
        let (probe, id) = temporary(f)?;
        let mut live = live();
        drop(probe);
        live.remove(&id);
    }
    Ok(t)
}

impl OutputFile {
    /// Whether this writes straight into a stream (standard output, a FIFO, a
    /// device) rather than a regular file.
    pub fn is_stream(&self) -> bool {
        !matches!(self.sink, Sink::Temp { .. })
    }

    /// Finishes the file: flushes it and, for a regular file, makes the
    /// temporary file durable and renames it over the target.
    pub fn commit(mut self) -> io::Result<()> {
        match &mut self.sink {
            Sink::Stdout(w) => w.flush(),
            Sink::Stream(w) => w.flush(),
            Sink::Temp { out, id, target } => {
                let Some(w) = out.take() else {
                    return Ok(());
                };
                let file = w.into_inner().map_err(|e| e.into_error())?;
                file.as_file().sync_all()?;
                let mut live = live();
                // On failure the temporary file is removed (dropped) before it
                // leaves the list.
                let r = file.persist(&*target).map(|_| ()).map_err(|e| e.error);
                live.remove(id);
                r
            }
        }
    }
}

impl Write for OutputFile {
    fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
        match &mut self.sink {
            Sink::Temp { out: Some(w), .. } => w.write(buf),
            Sink::Temp { out: None, .. } => Err(io::Error::other("the file is closed")),
            Sink::Stream(w) => w.write(buf),
            Sink::Stdout(w) => w.write(buf),
        }
    }

    fn flush(&mut self) -> io::Result<()> {
        match &mut self.sink {
            Sink::Temp { out: Some(w), .. } => w.flush(),
            Sink::Temp { out: None, .. } => Ok(()),
            Sink::Stream(w) => w.flush(),
            Sink::Stdout(w) => w.flush(),
        }
    }
}

/// A regular file can be written out of order (as OpenEXR is); a stream cannot.
impl Seek for OutputFile {
    fn seek(&mut self, pos: SeekFrom) -> io::Result<u64> {
        match &mut self.sink {
            Sink::Temp { out: Some(w), .. } => w.seek(pos),
            _ => Err(io::Error::new(
                io::ErrorKind::Unsupported,
                "this format is written out of order and needs a regular file, not a stream",
            )),
        }
    }
}

impl Drop for OutputFile {
    fn drop(&mut self) {
        if let Sink::Temp { out, id, .. } = &mut self.sink {
            let mut live = live();
            // Removes the temporary file (if not committed) while it is listed.
            drop(out.take());
            live.remove(id);
        }
    }
}

/// Removes every temporary file still being written and ends the process with
/// `code`: for a handler of Ctrl-C and `kill`. The list stays locked, so no new
/// temporary file starts meanwhile.
pub fn remove_temporaries_and_exit(code: i32) -> ! {
    let live = live();
    for p in live.values() {
        let _ = std::fs::remove_file(p);
    }
    std::process::exit(code)
}

#[cfg(all(test, unix))]
mod tests {
    use super::*;
    use std::os::unix::fs::PermissionsExt;

    fn dir(name: &str) -> PathBuf {
        let d = std::env::temp_dir().join(format!("rts-files-write-{}-{name}", std::process::id()));
        let _ = std::fs::remove_dir_all(&d);
        std::fs::create_dir_all(&d).unwrap();
        d
    }

    fn names(d: &Path) -> Vec<String> {
        let mut v: Vec<String> = std::fs::read_dir(d)
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .collect();
        v.sort();
        v
    }

    #[test]
    fn a_file_appears_whole_at_commit_with_the_usual_permissions() {
        let d = dir("commit");
        let p = d.join("a.txt");
        let mut f = create(&p, Policy::FileOnly).unwrap();
        f.write_all(b"hello").unwrap();
        assert!(!p.exists(), "the target appears only at commit");
        f.commit().unwrap();
        assert_eq!(std::fs::read(&p).unwrap(), b"hello");
        assert_eq!(names(&d), ["a.txt"]);
        let plain = d.join("plain.txt");
        File::create(&plain).unwrap();
        let mode = |p: &Path| std::fs::metadata(p).unwrap().permissions().mode() & 0o777;
        assert_eq!(mode(&p), mode(&plain));
        // Dropped without commit: the old file stays, the temporary goes.
        let mut f = create(&p, Policy::FileOnly).unwrap();
        f.write_all(b"other").unwrap();
        drop(f);
        assert_eq!(std::fs::read(&p).unwrap(), b"hello");
        assert_eq!(names(&d), ["a.txt", "plain.txt"]);
    }

    #[test]
    fn temporary_names_are_new_each_time_and_listed_while_written() {
        let d = dir("names");
        let p = d.join("x.png");
        let a = create(&p, Policy::FileOnly).unwrap();
        let b = create(&p, Policy::FileOnly).unwrap();
        let temps: Vec<String> = names(&d);
        assert_eq!(temps.len(), 2, "{temps:?}");
        assert_ne!(temps[0], temps[1]);
        for t in &temps {
            assert!(t.starts_with(".x.png.") && t.ends_with(".tmp"), "{t}");
            assert!(live().values().any(|l| l.ends_with(t)), "{t} is listed");
        }
        drop((a, b));
        assert!(names(&d).is_empty());
        assert!(!live().values().any(|l| l.starts_with(&d)));
    }

    #[test]
    fn links_are_followed_or_refused_by_policy() {
        let d = dir("links");
        let real = d.join("real.txt");
        std::fs::write(&real, "old").unwrap();
        let link = d.join("link.txt");
        std::os::unix::fs::symlink(&real, &link).unwrap();
        let e = create(&link, Policy::FileNoLink).unwrap_err();
        assert!(e.to_string().contains("symbolic link"), "{e}");
        assert_eq!(std::fs::read(&real).unwrap(), b"old");
        let mut f = create(&link, Policy::FileOnly).unwrap();
        f.write_all(b"new").unwrap();
        f.commit().unwrap();
        assert_eq!(std::fs::read(&real).unwrap(), b"new");
        assert!(std::fs::symlink_metadata(&link)
            .unwrap()
            .file_type()
            .is_symlink());
    }

    #[test]
    fn streams_are_written_in_place_or_refused_and_folders_refused() {
        let d = dir("streams");
        // A private copy of /dev/null where one can be made (as root, who could
        // replace the system's own if this went wrong); else /dev/null itself.
        let private = d.join("null");
        let made = std::process::Command::new("mknod")
            .args([
                private.as_os_str(),
                "c".as_ref(),
                "1".as_ref(),
                "3".as_ref(),
            ])
            .stderr(std::process::Stdio::null())
            .status()
            .is_ok_and(|s| s.success());
        let null = if made {
            private.as_path()
        } else {
            Path::new("/dev/null")
        };
        assert!(create(null, Policy::FileOnly).is_err());
        let mut f = create(null, Policy::Stream).unwrap();
        assert!(f.is_stream());
        f.write_all(b"picture").unwrap();
        f.commit().unwrap();
        assert_eq!(Kind::of(null).unwrap(), Kind::CharDevice);
        assert_eq!(
            target(Path::new("-"), Policy::Stream).unwrap(),
            Target::Stdout
        );
        let e = create(&d, Policy::Stream).unwrap_err();
        assert!(e.to_string().contains("folder"), "{e}");
        assert!(create(&d, Policy::FileOnly).is_err());
    }

    #[test]
    fn prepare_makes_the_folder_and_leaves_nothing_else() {
        let d = dir("prepare");
        let p = d.join("new/sub/x.png");
        assert_eq!(
            prepare(&p, Policy::Stream).unwrap(),
            Target::File(p.clone())
        );
        assert!(names(&d.join("new/sub")).is_empty());
        std::fs::write(d.join("file"), "").unwrap();
        assert!(prepare(&d.join("file/x.png"), Policy::Stream).is_err());
    }
}
