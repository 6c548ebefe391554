//! File input and output directives, as in POV-Ray: `#fopen NAME "FILE" read|write|append`,
//! `#read (NAME, VAR, …)`, `#write (NAME, ITEM, …)` and `#fclose NAME`.
//!
//! A file opened for reading is read whole; `#read` takes its next comma-separated
//! values (floats, vectors `<…>`, strings `"…"`) into variables. When only blanks
//! and commas are left, the file is closed and its name undefined, so
//! `#while (defined(NAME))` reads to the end, as in POV-Ray.
//!
//! Written files are kept in memory until `#fclose` (or the end of the scene), then
//! stored in the evaluation's file overlay, which later `#include`s and `#fopen … read`
//! see. Only when [`crate::eval::EvalOptions::write_files`] is set (rendering) do they reach
//! the disk, so `rts check` and the editor never write files.

use super::file_data::{format_g, line_col, next_value, skip_separators, write_binary};
use super::include::show_bytes;
use super::value::Value;
use super::{Evaluator, R};
use crate::diag::{codes, Diagnostic};
use crate::files::{Kind, ReadError};
use crate::span::Span;
use crate::syntax::ast::{BinaryKind, Expr, LValue, OpenMode};
use crate::syntax::Sym;
use std::cell::RefCell;
use std::io::Write;
use std::path::{Path, PathBuf};
use std::rc::Rc;

/// A file opened by `#fopen`, shared by every copy of its identifier's value.
#[derive(Debug)]
pub struct OpenFile {
    /// Where the file is (canonical folder + file name).
    path: PathBuf,
    /// The file name as the scene wrote it.
    shown: String,
    state: FileState,
}

#[derive(Debug)]
enum FileState {
    /// Reading: the whole text and how far `#read` has come.
    Read { data: Rc<[u8]>, pos: usize },
    /// Writing: everything the file will hold.
    Write { buf: Vec<u8> },
    /// Closed by `#fclose` or at the end of the data.
    Closed,
}

/// Files written during one evaluation, by path (see the module documentation).
pub(crate) type Overlay = rustc_hash::FxHashMap<PathBuf, Rc<[u8]>>;

/// Where `name` in `dir` is, with the folder made canonical (the file itself need not
/// exist).
pub(crate) fn overlay_key(dir: &Path, name: &str) -> Option<PathBuf> {
    let p = dir.join(name);
    let parent = p.parent()?.canonicalize().ok()?;
    Some(parent.join(p.file_name()?))
}

impl Evaluator<'_> {
    /// `#fopen NAME "FILE" MODE`.
    pub(crate) fn fopen(
        &mut self,
        name: Sym,
        name_span: Span,
        file: &Expr,
        mode: OpenMode,
    ) -> R<()> {
        self.moving();
        if name.is_builtin() {
            return Err(self.reserved(name_span, &name.name()));
        }
        if let Some(Value::File(f)) = self.scope.get(name).map(|b| &b.value) {
            if !matches!(f.borrow().state, FileState::Closed) {
                return Err(Diagnostic::error(
                    codes::FILE_IO,
                    name_span,
                    format!("`{name}` is already an open file"),
                )
                .with_label("opened again here")
                .with_help(format!(
                    "close it first with `#fclose {name}`, or use another name"
                ))
                .into());
            }
        }
        let v = self.expr(file)?;
        let fname = self.to_str(&v, file.span)?;
        self.files_seen.insert(name);
        let (path, state) = match self.open_state(&fname, file.span, mode) {
            Ok(opened) => opened,
            Err(e) => {
                // Reported here: its #read, #write and #fclose say nothing more.
                self.files_failed.insert(name);
                return Err(e);
            }
        };
        self.files_failed.remove(&name);
        let f = Rc::new(RefCell::new(OpenFile {
            path,
            shown: fname.to_string(),
            state,
        }));
        self.scope.declare(name, Value::File(f.clone()), name_span);
        if mode == OpenMode::Read {
            // An empty file is at its end at once.
            self.close_at_end(name, &f);
        } else {
            self.open_writes.push(f);
        }
        Ok(())
    }

    /// Where a file `#fopen` opens is, and what it starts with.
    fn open_state(&mut self, fname: &str, span: Span, mode: OpenMode) -> R<(PathBuf, FileState)> {
        Ok(match mode {
            OpenMode::Read => {
                let (path, data) = self.read_whole(fname, span)?;
                (path, FileState::Read { data, pos: 0 })
            }
            OpenMode::Write => (
                self.write_path(fname, span)?,
                FileState::Write { buf: Vec::new() },
            ),
            OpenMode::Append => {
                let path = self.write_path(fname, span)?;
                let buf = match self.written.get(&path) {
                    Some(d) => d.to_vec(),
                    None => self.read_for_append(&path, fname, span)?,
                };
                (path, FileState::Write { buf })
            }
        })
    }

    /// `#fclose NAME`. Closing a file already closed at the end of its data is
    /// allowed, as in POV-Ray.
    pub(crate) fn fclose(&mut self, name: Sym, span: Span) -> R<()> {
        self.moving();
        match self.scope.get(name).map(|b| b.value.clone()) {
            Some(Value::File(f)) => {
                self.close_file(&f, span)?;
                self.scope.undef(name);
                Ok(())
            }
            Some(other) => Err(not_a_file(name, span, other.kind()).into()),
            None if self.files_seen.contains(&name) => Ok(()),
            None => Err(self.not_open(name, span).into()),
        }
    }

    /// `#read (NAME, VAR, …)`.
    pub(crate) fn read_values(&mut self, name: Sym, span: Span, targets: &[LValue]) -> R<()> {
        self.moving();
        let f = self.file_value(name, span)?;
        for t in targets {
            let item = {
                let mut file = f.borrow_mut();
                let shown = file.shown.clone();
                let FileState::Read { data, pos } = &mut file.state else {
                    return Err(Diagnostic::error(
                        codes::FILE_IO,
                        span,
                        format!("`{name}` was not opened for reading"),
                    )
                    .with_help(format!("open it with `#fopen {name} \"{shown}\" read`"))
                    .into());
                };
                match next_value(data, pos) {
                    Ok(Some(v)) => v,
                    // The data ended: the remaining variables stay as they were.
                    Ok(None) => break,
                    Err((at, what)) => {
                        let (line, col) = line_col(data, at);
                        return Err(Diagnostic::error(
                            codes::FILE_IO,
                            span,
                            format!("cannot read `{shown}` at line {line}, column {col}: {what}"),
                        )
                        .with_label("reading this file")
                        .with_help("#read takes floats, vectors `<…>` and strings `\"…\"` separated by commas")
                        .into());
                    }
                }
            };
            self.bind(false, t, item, t.name_span)?;
        }
        self.close_at_end(name, &f);
        Ok(())
    }

    /// `#write (NAME, ITEM, …)`.
    pub(crate) fn write_values(
        &mut self,
        name: Sym,
        span: Span,
        items: &[(Option<BinaryKind>, Expr)],
    ) -> R<()> {
        self.moving();
        let f = self.file_value(name, span)?;
        let mut out = Vec::new();
        for (kind, e) in items {
            let v = self.expr(e)?;
            match (kind, &v) {
                (Some(k), _) => {
                    let x = self.to_float(&v, e.span)?;
                    write_binary(&mut out, *k, x);
                }
                (None, Value::Str(s)) => out.extend_from_slice(s.as_bytes()),
                (None, Value::Float(x)) => out.extend_from_slice(format_g(*x).as_bytes()),
                (None, Value::Vector(vec)) => {
                    let parts: Vec<String> = vec.as_slice().iter().map(|x| format_g(*x)).collect();
                    // POV-Ray writes a blank after a vector.
                    out.extend_from_slice(format!("<{}> ", parts.join(",")).as_bytes());
                }
                (None, other) => {
                    return Err(Diagnostic::error(
                        codes::TYPE_MISMATCH,
                        e.span,
                        format!(
                            "#write takes strings, floats and vectors, not {}",
                            other.kind()
                        ),
                    )
                    .with_help("write its parts, e.g. `vstr(3, V, \",\", 0, 6)` or `C.red`")
                    .into());
                }
            }
        }
        let mut file = f.borrow_mut();
        let shown = file.shown.clone();
        let FileState::Write { buf } = &mut file.state else {
            return Err(Diagnostic::error(
                codes::FILE_IO,
                span,
                format!("`{name}` was not opened for writing"),
            )
            .with_help(format!(
                "open it with `#fopen {name} \"{shown}\" write` (or `append`)"
            ))
            .into());
        };
        let max = self.options.max_write;
        if self.written_bytes.saturating_add(out.len() as u64) > max {
            self.stopped = true;
            return Err(Diagnostic::error(
                codes::WRITE_SIZE,
                span,
                format!(
                    "this #write would take the files the scene writes past {} in all (writing `{shown}`)",
                    show_bytes(max)
                ),
            )
            .with_label("the write that crossed the limit")
            .with_help("check the loop that writes; raise the limit with --max-write SIZE (e.g. --max-write 1G)")
            .into());
        }
        self.written_bytes += out.len() as u64;
        buf.extend_from_slice(&out);
        Ok(())
    }

    /// What a file opened for `append` already holds on disk: nothing when it
    /// does not exist; read without following a link and within what is left of
    /// `--max-write` (it is written again when closed).
    fn read_for_append(&mut self, path: &Path, shown: &str, span: Span) -> R<Vec<u8>> {
        let left = self.options.max_write.saturating_sub(self.written_bytes);
        let data = match crate::files::open_regular_no_link(path)
            .and_then(|f| crate::files::read_all(f, left))
        {
            Ok(d) => d,
            Err(ReadError::Io(e)) if e.kind() == std::io::ErrorKind::NotFound => Vec::new(),
            Err(ReadError::NotRegular(k)) => return Err(not_writable(shown, k, span).into()),
            Err(ReadError::TooLarge { .. }) => {
                self.stopped = true;
                return Err(Diagnostic::error(
                    codes::WRITE_SIZE,
                    span,
                    format!(
                        "`{shown}` already holds more than the {} the scene may still write (appending rewrites it)",
                        show_bytes(left)
                    ),
                )
                .with_label("appended to here")
                .with_help("write a new file instead, or raise the limit with --max-write SIZE (e.g. --max-write 1G)")
                .into());
            }
            Err(e) => {
                return Err(Diagnostic::error(
                    codes::FILE_IO,
                    span,
                    format!("cannot read `{shown}` to append to it: {e}"),
                )
                .into())
            }
        };
        self.written_bytes += data.len() as u64;
        Ok(data)
    }

    /// When only blanks and commas are left of a file being read, closes it and
    /// undefines its name (so `#while (defined(NAME))` ends), as POV-Ray does.
    fn close_at_end(&mut self, name: Sym, f: &Rc<RefCell<OpenFile>>) {
        if at_end(&f.borrow()) {
            f.borrow_mut().state = FileState::Closed;
            self.scope.undef(name);
        }
    }

    /// Closes every file still open for writing (at the end of the scene).
    pub(crate) fn close_all_files(&mut self, span: Span) {
        for f in std::mem::take(&mut self.open_writes) {
            if let Err(e) = self.close_file(&f, span) {
                self.report(e);
            }
        }
    }

    /// Closes a file; a written one is stored in the overlay and, when rendering,
    /// on disk.
    fn close_file(&mut self, f: &Rc<RefCell<OpenFile>>, span: Span) -> R<()> {
        let state = std::mem::replace(&mut f.borrow_mut().state, FileState::Closed);
        let FileState::Write { buf } = state else {
            return Ok(());
        };
        let file = f.borrow();
        if self.options.write_files {
            // A temporary file renamed over the name: a link or FIFO put there
            // since #fopen is replaced, never written through.
            let written = crate::files::create(&file.path, crate::files::Policy::FileNoLink)
                .and_then(|mut out| {
                    out.write_all(&buf)?;
                    out.commit()
                });
            if let Err(e) = written {
                return Err(Diagnostic::error(
                    codes::FILE_IO,
                    span,
                    format!("cannot write `{}`: {e}", file.path.display()),
                )
                .into());
            }
        }
        self.written.insert(file.path.clone(), buf.into());
        Ok(())
    }

    /// The open file `name` stands for.
    fn file_value(&mut self, name: Sym, span: Span) -> R<Rc<RefCell<OpenFile>>> {
        if self.files_failed.contains(&name) {
            return Err(super::Fail::silent());
        }
        match self.scope.get(name).map(|b| b.value.clone()) {
            Some(Value::File(f)) if !matches!(f.borrow().state, FileState::Closed) => Ok(f),
            Some(Value::File(_)) => Err(self.not_open(name, span).into()),
            Some(other) => Err(not_a_file(name, span, other.kind()).into()),
            None => Err(self.not_open(name, span).into()),
        }
    }

    fn not_open(&self, name: Sym, span: Span) -> Diagnostic {
        let d = Diagnostic::error(
            codes::FILE_IO,
            span,
            format!("`{name}` is not an open file"),
        );
        if self.files_seen.contains(&name) {
            return d.with_label("closed already").with_help(
                "it was closed by #fclose, or at the end of its data when read (test `defined(NAME)` before reading); open it again with #fopen",
            );
        }
        let mut names: Vec<String> = self.files_seen.iter().map(|s| s.to_string()).collect();
        names.sort();
        let d = d.with_label("no #fopen for this name");
        match crate::diag::did_you_mean(&name.name(), names.iter().map(String::as_str)) {
            Some(s) => d.with_help(format!("did you mean `{s}`?")),
            None => d.with_help(format!("open it first: `#fopen {name} \"file.txt\" read`")),
        }
    }

    /// Finds a file to read (written ones first, then the include search folders)
    /// and reads it whole.
    fn read_whole(&mut self, name: &str, span: Span) -> R<(PathBuf, Rc<[u8]>)> {
        self.moving();
        if let Some(found) = self.overlay_find(name) {
            return Ok(found);
        }
        let mut tried = Vec::new();
        let Some((path, _)) = self.search(name, span, &mut tried)? else {
            return Err(Diagnostic::error(
                codes::FILE_NOT_FOUND,
                span,
                format!("file `{name}` not found"),
            )
            .with_label("no such file")
            .with_note(format!("tried: {}", tried.join(", ")))
            .with_help("check the file name, or add its folder with -I DIR")
            .into());
        };
        match crate::files::read_regular(&path, self.options.max_source_size) {
            Ok(d) => {
                self.data_files.borrow_mut().push(path.clone());
                Ok((path, d.into()))
            }
            Err(ReadError::NotRegular(k)) => Err(super::include::not_regular(name, k, span).into()),
            Err(ReadError::TooLarge { limit }) => {
                Err(super::include::too_large(name, limit, span).into())
            }
            Err(e) => Err(Diagnostic::error(
                codes::FILE_NOT_FOUND,
                span,
                format!("cannot read `{name}`: {e}"),
            )
            .into()),
        }
    }

    /// A file of this name written earlier in this evaluation, looked for in the
    /// include search folders.
    pub(crate) fn overlay_find(&self, name: &str) -> Option<(PathBuf, Rc<[u8]>)> {
        if self.written.is_empty() {
            return None;
        }
        self.moving();
        self.search_dirs(name)
            .iter()
            .filter_map(|d| overlay_key(d, name))
            .find_map(|k| self.written.get(&k).map(|d| (k, d.clone())))
    }

    /// Where a file written as `name` goes: relative names are taken from the scene's
    /// folder; the folder must exist and lie where the scene may write (its own
    /// folder and `--allow-path` folders, or anywhere with `--allow-any-path`).
    fn write_path(&self, name: &str, span: Span) -> R<PathBuf> {
        // The scene's folder ("." for a scene named without a folder); a scene with
        // no file (an unsaved editor buffer) may write only to --allow-path folders.
        let scene_base = self.scene_dir.as_deref().map(|d| {
            if d.as_os_str().is_empty() {
                Path::new(".")
            } else {
                d
            }
        });
        let base = scene_base.unwrap_or(Path::new("."));
        let Some(path) = overlay_key(base, name) else {
            let p = base.join(name);
            let folder = p
                .parent()
                .map(|p| p.display().to_string())
                .unwrap_or_default();
            return Err(Diagnostic::error(
                codes::FILE_IO,
                span,
                format!("cannot write `{name}`: no folder `{folder}`"),
            )
            .with_help("create the folder first, or write into the scene's folder")
            .into());
        };
        let access = &self.options.access;
        let canon = |p: &Path| p.canonicalize().ok();
        let permitted = access.unrestricted
            || scene_base
                .into_iter()
                .filter_map(canon)
                .chain(access.allowed.iter().filter_map(|p| canon(p)))
                .any(|d| path.starts_with(d));
        if !permitted {
            return Err(Diagnostic::error(
                codes::FILE_NOT_ALLOWED,
                span,
                format!(
                    "`{}` is outside the folders this scene may write",
                    path.display()
                ),
            )
            .with_label("outside the scene's folder")
            .with_help("scenes write only under their own folder; allow more with --allow-path DIR")
            .into());
        }
        // The folder is canonical, so `..` and links there cannot leave it; the
        // last name must not be a link (out of the folder) or a FIFO or device.
        match Kind::of(&path) {
            Ok(Kind::Missing | Kind::Regular) => Ok(path),
            Ok(k) => Err(not_writable(name, k, span).into()),
            Err(e) => {
                Err(
                    Diagnostic::error(codes::FILE_IO, span, format!("cannot write `{name}`: {e}"))
                        .into(),
                )
            }
        }
    }
}

/// `#fopen … write` or `append` at a link, a FIFO, a device or a folder.
fn not_writable(name: &str, kind: Kind, span: Span) -> Diagnostic {
    let d = Diagnostic::error(
        codes::NOT_REGULAR_FILE,
        span,
        format!("`{name}` is {}, not a regular file", kind.describe()),
    );
    if kind == Kind::Link {
        d.with_label("a link: writing it could change a file elsewhere")
            .with_help(
                "a scene writes only regular files; remove the link, or write to another name",
            )
    } else {
        d.with_label("not a file a scene may write")
            .with_help("a scene writes only regular files; remove it, or write to another name")
    }
}

fn not_a_file(name: Sym, span: Span, kind: &str) -> Diagnostic {
    Diagnostic::error(
        codes::TYPE_MISMATCH,
        span,
        format!("`{name}` is {kind}, not a file opened by #fopen"),
    )
    .with_help(format!(
        "open a file first: `#fopen {name} \"file.txt\" read`"
    ))
}

/// Whether only blanks and commas are left to read.
fn at_end(f: &OpenFile) -> bool {
    match &f.state {
        FileState::Read { data, pos } => {
            let mut p = *pos;
            skip_separators(data, &mut p);
            p >= data.len()
        }
        _ => false,
    }
}
