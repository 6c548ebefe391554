//! `#include`: finding files (the including file's folder, then `-I` folders, then the
//! built-in library), the read sandbox, cycles and depth.

use super::cursor::Sink;
use super::{Evaluator, R};
use crate::diag::{codes, did_you_mean, Diagnostic, Label};
use crate::files::Kind;
use crate::source::{FileAccess, SourceMap};
use crate::span::{FileId, Span};
use std::path::{Path, PathBuf};

/// The built-in include files: name and text.
pub const STDLIB: &[(&str, &str)] = &[
    ("arrays.inc", include_str!("../../stdlib/arrays.inc")),
    ("colors.inc", include_str!("../../stdlib/colors.inc")),
    ("consts.inc", include_str!("../../stdlib/consts.inc")),
    ("debug.inc", include_str!("../../stdlib/debug.inc")),
    ("finish.inc", include_str!("../../stdlib/finish.inc")),
    ("functions.inc", include_str!("../../stdlib/functions.inc")),
    ("glass.inc", include_str!("../../stdlib/glass.inc")),
    ("golds.inc", include_str!("../../stdlib/golds.inc")),
    ("math.inc", include_str!("../../stdlib/math.inc")),
    ("metals.inc", include_str!("../../stdlib/metals.inc")),
    ("rad_def.inc", include_str!("../../stdlib/rad_def.inc")),
    ("rand.inc", include_str!("../../stdlib/rand.inc")),
    ("shapes.inc", include_str!("../../stdlib/shapes.inc")),
    ("shapes2.inc", include_str!("../../stdlib/shapes2.inc")),
    (
        "shapes_old.inc",
        include_str!("../../stdlib/shapes_old.inc"),
    ),
    ("shapesq.inc", include_str!("../../stdlib/shapesq.inc")),
    ("skies.inc", include_str!("../../stdlib/skies.inc")),
    ("stdinc.inc", include_str!("../../stdlib/stdinc.inc")),
    ("stones.inc", include_str!("../../stdlib/stones.inc")),
    ("strings.inc", include_str!("../../stdlib/strings.inc")),
    ("textures.inc", include_str!("../../stdlib/textures.inc")),
    (
        "transforms.inc",
        include_str!("../../stdlib/transforms.inc"),
    ),
    ("woodmaps.inc", include_str!("../../stdlib/woodmaps.inc")),
    ("woods.inc", include_str!("../../stdlib/woods.inc")),
];

/// The folders a file named in the scene is searched in: the including file's folder
/// (`here`), the scene's folder (POV-Ray resolves relative to the scene), then the -I
/// folders. An absolute name is used as it is.
pub fn search_dirs(
    name: &str,
    here: Option<&Path>,
    scene_dir: Option<&Path>,
    access: &FileAccess,
) -> Vec<PathBuf> {
    if Path::new(name).is_absolute() {
        return vec![PathBuf::new()];
    }
    let mut dirs: Vec<PathBuf> = Vec::new();
    if let Some(d) = here {
        dirs.push(d.to_path_buf());
    }
    if let Some(d) = scene_dir {
        if !dirs.iter().any(|x| x == d) {
            dirs.push(d.to_path_buf());
        }
    }
    dirs.extend(access.include_dirs.iter().cloned());
    dirs
}

/// Where `#include "name"` leads, searched as evaluation does (for editors): the
/// canonical path of a permitted file in [`search_dirs`], else the name of a built-in
/// library file (`<stdlib>/name`), else `None`.
pub fn find_include(
    name: &str,
    here: Option<&Path>,
    scene_dir: Option<&Path>,
    access: &FileAccess,
) -> Option<PathBuf> {
    for dir in search_dirs(name, here, scene_dir, access) {
        let path = dir.join(name);
        if path.is_file() {
            let canon = path.canonicalize().unwrap_or(path);
            return access
                .permits_in(&dir, name, &canon, scene_dir)
                .then_some(canon);
        }
    }
    STDLIB
        .iter()
        .find(|(n, _)| *n == name)
        .map(|(n, _)| PathBuf::from(format!("<stdlib>/{n}")))
}

/// Why a source file could not be loaded.
#[derive(Debug)]
pub enum LoadError {
    /// The file could not be read.
    Io(std::io::Error),
    /// The path leads to a FIFO, a device or a folder, not a regular file.
    NotRegular(crate::files::Kind),
    /// The file is larger than the limit (bytes; `--max-source-size`).
    TooLarge(u64),
    /// The file is not UTF-8; it was added to the map (lossily) so the diagnostic can
    /// show it, and this is the ready diagnostic.
    Utf8(Box<Diagnostic>),
}

/// The largest source file [`load_file`] reads (256 MiB; `--max-source-size`).
pub const MAX_SOURCE_SIZE: u64 = 256 << 20;

/// Reads a file of at most [`MAX_SOURCE_SIZE`] bytes into the source map (see
/// [`load_file_limited`]).
pub fn load_file(sources: &mut SourceMap, path: &Path, name: String) -> Result<FileId, LoadError> {
    load_file_limited(sources, path, name, MAX_SOURCE_SIZE)
}

/// Reads a file into the source map, checking that it is a regular file of at most
/// `limit` bytes (a FIFO or device is refused without waiting on it) and UTF-8.
pub fn load_file_limited(
    sources: &mut SourceMap,
    path: &Path,
    name: String,
    limit: u64,
) -> Result<FileId, LoadError> {
    use crate::files::ReadError;
    let bytes = crate::files::read_regular(path, limit).map_err(|e| match e {
        ReadError::NotRegular(k) => LoadError::NotRegular(k),
        ReadError::TooLarge { limit } => LoadError::TooLarge(limit),
        ReadError::Io(e) => LoadError::Io(e),
    })?;
    match String::from_utf8(bytes) {
        Ok(text) => Ok(sources.add(name, Some(path.to_path_buf()), text)),
        Err(e) => {
            let offset = e.utf8_error().valid_up_to();
            let text = String::from_utf8_lossy(e.as_bytes()).into_owned();
            // Map the byte offset into the lossy text (same up to the first bad byte).
            let id = sources.add(name, Some(path.to_path_buf()), text);
            let d = Diagnostic::error(
                codes::INVALID_UTF8,
                Span::new(id, offset, offset + 1),
                format!("the file is not valid UTF-8 (first bad byte at offset {offset})"),
            )
            .with_label("invalid byte here")
            .with_help("save the file as UTF-8");
            Err(LoadError::Utf8(Box::new(d)))
        }
    }
}

/// A file the scene names that is a FIFO, a device or something else that is not a
/// regular file.
pub(crate) fn not_regular(shown: &str, kind: Kind, span: Span) -> Diagnostic {
    Diagnostic::error(
        codes::NOT_REGULAR_FILE,
        span,
        format!("`{shown}` is {}, not a regular file", kind.describe()),
    )
    .with_label("not a file rts reads")
    .with_help("name a regular file: rts does not read from pipes, devices or folders")
}

/// A source file (or a file `#fopen` reads) larger than `--max-source-size`.
pub(crate) fn too_large(shown: &str, limit: u64, span: Span) -> Diagnostic {
    Diagnostic::error(
        codes::SOURCE_SIZE,
        span,
        format!("`{shown}` is larger than {}", show_bytes(limit)),
    )
    .with_label("too large to read")
    .with_help(
        "check that this is the file meant; raise the limit with --max-source-size SIZE (e.g. 1G)",
    )
}

/// `bytes` in MiB when it is a whole number of them, else in bytes.
pub(crate) fn show_bytes(bytes: u64) -> String {
    if bytes >= 1 << 20 && bytes.is_multiple_of(1 << 20) {
        format!("{} MiB", bytes >> 20)
    } else {
        format!("{bytes} bytes")
    }
}

impl Evaluator<'_> {
    /// Runs `#include "name"` written at `span` (the directive at `dspan`).
    pub(crate) fn include(&mut self, name: &str, span: Span, dspan: Span, out: &mut Sink) -> R<()> {
        if self.include_stack.len() > self.options.max_include_depth {
            self.stopped = true;
            return Err(Diagnostic::error(
                codes::INCLUDE_DEPTH,
                span,
                format!(
                    "includes nested more than {} deep",
                    self.options.max_include_depth
                ),
            )
            .into());
        }
        let id = self.resolve(name, span)?;
        // debug.inc's Debug_Inc_Stack(): every include says which file it reads.
        let tracking = crate::syntax::intern::intern("Debug_Inc_Stack_On");
        if let Some(super::value::Value::Float(f)) = self.scope.get(tracking).map(|b| &b.value) {
            if *f != 0.0 {
                let d = Diagnostic::note(codes::USER_DEBUG, dspan, format!("including {name}\n"));
                self.warn(d);
            }
        }
        if let Some(pos) = self.include_stack.iter().position(|f| *f == id) {
            let chain: Vec<String> = self.include_stack[pos..]
                .iter()
                .map(|f| self.sources.get(*f).name.clone())
                .chain(std::iter::once(self.sources.get(id).name.clone()))
                .collect();
            return Err(Diagnostic::error(codes::INCLUDE_CYCLE, span, format!("`{name}` includes itself"))
                .with_label("this include closes a cycle")
                .with_note(format!("the cycle: {}", chain.join(" → ")))
                .with_help("guard the file with `#ifndef (My_File_Inc) #declare My_File_Inc = 1; … #end`, or remove the include")
                .into());
        }
        self.trace.push(Label {
            span: dspan,
            message: format!("in `{}` included from here", self.sources.get(id).name),
        });
        if self.include_lazily(id, out) {
            self.language_version = Some(self.language_version.unwrap_or(3.7));
            self.trace.pop();
            return Ok(());
        }
        // A file included many times (say in a loop) is parsed once; its syntax
        // errors are reported the first time.
        let parsed = match self.parsed_includes.get(&id) {
            Some(p) => p.clone(),
            None => {
                let text = self.sources.get(id).text.clone();
                let (file, diags) =
                    crate::syntax::parse_with(&text, id, 0, self.options.defer_branches);
                let ok = !crate::diag::has_errors(&diags);
                for d in diags {
                    self.report(d.into());
                }
                let p = ok.then(|| std::rc::Rc::new(file));
                self.parsed_includes.insert(id, p.clone());
                p
            }
        };
        if let Some(file) = parsed {
            self.include_stack.push(id);
            self.scope.push();
            self.expand(&file.items, out);
            self.scope.pop();
            self.include_stack.pop();
            // POV-Ray's own include files end by restoring `#version` to what it
            // was, 3.7 when the scene set none; ours stand for them.
            if self.sources.get(id).name.starts_with("<stdlib>/") {
                self.language_version = Some(self.language_version.unwrap_or(3.7));
            }
        }
        self.trace.pop();
        Ok(())
    }

    /// The folders a file named in the scene is searched in (see [`search_dirs`]).
    pub(crate) fn search_dirs(&self, name: &str) -> Vec<PathBuf> {
        let here = self.include_stack.last().copied().unwrap_or(FileId(0));
        search_dirs(
            name,
            self.sources.get(here).dir(),
            self.scene_dir.as_deref(),
            &self.options.access,
        )
    }

    /// Searches the folders of [`Self::search_dirs`] for `name` (written at `span`):
    /// `Ok(Some((canonical path, path as shown)))` when found inside the read
    /// sandbox, `Ok(None)` with the paths tried in `tried` when not found, and a
    /// `rts::io::file_not_allowed` error when found outside the sandbox.
    pub(crate) fn search(
        &self,
        name: &str,
        span: Span,
        tried: &mut Vec<String>,
    ) -> R<Option<(PathBuf, String)>> {
        for dir in &self.search_dirs(name) {
            let path = dir.join(name);
            let shown = path.display().to_string();
            let shown = shown.strip_prefix("./").unwrap_or(&shown).to_string();
            tried.push(shown.clone());
            // Missing files and folders are passed over; a FIFO or device found
            // here is refused below (once it is known to be in the sandbox).
            let kind = crate::files::Kind::followed(&path);
            if matches!(kind, Ok(Kind::Missing | Kind::Folder) | Err(_)) {
                continue;
            }
            let canon = path.canonicalize().unwrap_or(path.clone());
            if !self
                .options
                .access
                .permits_in(dir, name, &canon, self.scene_dir.as_deref())
            {
                return Err(Diagnostic::error(
                    codes::FILE_NOT_ALLOWED,
                    span,
                    format!("`{}` is outside the folders this scene may read", canon.display()),
                )
                .with_label("outside the scene's folders")
                .with_help("scenes read only from their own folder, -I folders and the built-in library; allow more with --allow-path DIR")
                .into());
            }
            if let Ok(k) = kind {
                if k != Kind::Regular {
                    return Err(not_regular(&shown, k, span).into());
                }
            }
            return Ok(Some((canon, shown)));
        }
        Ok(None)
    }

    /// The path of a data file (mesh, image, height map) called `name`, written at
    /// `span`; `what` names it in the error ("image", "mesh file", …).
    pub(crate) fn data_file(&self, name: &str, span: Span, what: &str) -> R<PathBuf> {
        let mut tried = Vec::new();
        match self.search(name, span, &mut tried)? {
            Some((canon, _)) => {
                self.data_files.borrow_mut().push(canon.clone());
                Ok(canon)
            }
            None => Err(Diagnostic::error(
                codes::FILE_NOT_FOUND,
                span,
                format!("{what} `{name}` not found"),
            )
            .with_label("no such file")
            .with_note(format!("tried: {}", tried.join(", ")))
            .with_help("check the file name, or add its folder with -I DIR")
            .into()),
        }
    }

    /// Finds and loads an include file.
    fn resolve(&mut self, name: &str, span: Span) -> R<FileId> {
        // A file this scene wrote (#write) is read as written, even when the disk is
        // not written (`rts check`).
        if let Some((path, data)) = self.overlay_find(name) {
            let text = String::from_utf8_lossy(&data).into_owned();
            let same = self
                .sources
                .files()
                .find(|(_, f)| f.path.as_deref() == Some(path.as_path()) && f.text == text)
                .map(|(id, _)| id);
            return Ok(same.unwrap_or_else(|| self.sources.add(name.to_string(), Some(path), text)));
        }
        let mut tried = Vec::new();
        if let Some((canon, shown)) = self.search(name, span, &mut tried)? {
            if let Some(id) = self.sources.find_path(&canon) {
                return Ok(id);
            }
            let limit = self.options.max_source_size;
            return match load_file_limited(self.sources, &canon, shown.clone(), limit) {
                Ok(id) => Ok(id),
                Err(LoadError::Utf8(d)) => Err((*d).into()),
                Err(LoadError::NotRegular(k)) => Err(not_regular(&shown, k, span).into()),
                Err(LoadError::TooLarge(limit)) => Err(too_large(&shown, limit, span).into()),
                Err(LoadError::Io(e)) => Err(Diagnostic::error(
                    codes::FILE_NOT_FOUND,
                    span,
                    format!("cannot read `{shown}`: {e}"),
                )
                .into()),
            };
        }
        let dirs = self.search_dirs(name);
        if let Some((lib, text)) = STDLIB.iter().find(|(n, _)| *n == name) {
            let path = PathBuf::from(format!("<stdlib>/{lib}"));
            if let Some(id) = self.sources.find_path(&path) {
                return Ok(id);
            }
            return Ok(self.sources.add(
                format!("<stdlib>/{lib}"),
                Some(path),
                (*text).to_string(),
            ));
        }
        let mut known: Vec<String> = STDLIB.iter().map(|(n, _)| n.to_string()).collect();
        for dir in &dirs {
            if let Ok(rd) = std::fs::read_dir(dir) {
                known.extend(
                    rd.flatten()
                        .map(|e| e.file_name().to_string_lossy().into_owned()),
                );
            }
        }
        let mut d = Diagnostic::error(codes::FILE_NOT_FOUND, span, format!("include file `{name}` not found"))
            .with_label("no such file")
            .with_note(format!("tried: {}", tried.join(", ")))
            .with_note(format!(
                "search folders: the including file's folder, the scene's folder, then -I folders ({}), then the built-in library ({})",
                if self.options.access.include_dirs.is_empty() {
                    "none given".to_string()
                } else {
                    self.options
                        .access
                        .include_dirs
                        .iter()
                        .map(|p| p.display().to_string())
                        .collect::<Vec<_>>()
                        .join(", ")
                },
                STDLIB.iter().map(|(n, _)| *n).collect::<Vec<_>>().join(", ")
            ));
        if let Some(s) = did_you_mean(name, known.iter().map(String::as_str)) {
            d = d.with_help(format!("did you mean `{s}`?"));
        } else {
            d = d.with_help("check the file name, or add its folder with -I DIR");
        }
        Err(d.into())
    }
}
