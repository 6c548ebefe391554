//! Loaded source files and the rules for which files a scene may read.

use crate::span::{FileId, Span};
use std::path::{Path, PathBuf};

/// One loaded file: its name as shown to users, its path and its text.
#[derive(Debug)]
pub struct SourceFile {
    /// Name shown in diagnostics (the path as given, or `<stdlib>/colors.inc`).
    pub name: String,
    /// Where it was read from; `None` for built-in and in-memory sources.
    pub path: Option<PathBuf>,
    /// The text.
    pub text: String,
    line_starts: Vec<usize>,
}

impl SourceFile {
    fn new(name: String, path: Option<PathBuf>, text: String) -> SourceFile {
        let mut line_starts = vec![0];
        line_starts.extend(text.match_indices('\n').map(|(i, _)| i + 1));
        SourceFile {
            name,
            path,
            text,
            line_starts,
        }
    }

    /// 1-based line and column (in characters) of byte `offset`.
    pub fn line_col(&self, offset: usize) -> (usize, usize) {
        let offset = offset.min(self.text.len());
        let line = match self.line_starts.binary_search(&offset) {
            Ok(l) => l,
            Err(l) => l - 1,
        };
        let start = self.line_starts[line];
        let mut end = offset;
        while !self.text.is_char_boundary(end) {
            end -= 1;
        }
        let col = self.text[start..end].chars().count();
        (line + 1, col + 1)
    }

    /// Byte offset where 0-based `line` starts; the text's length past the last
    /// line.
    pub fn line_start(&self, line: usize) -> usize {
        self.line_starts
            .get(line)
            .copied()
            .unwrap_or(self.text.len())
    }

    /// The directory relative includes are resolved against.
    pub fn dir(&self) -> Option<&Path> {
        // `Path::new("a.rts").parent()` is `""`: that is the current folder.
        self.path.as_deref().and_then(Path::parent).map(|d| {
            if d.as_os_str().is_empty() {
                Path::new(".")
            } else {
                d
            }
        })
    }
}

/// All files loaded for one run, indexed by [`FileId`].
#[derive(Debug, Default)]
pub struct SourceMap {
    files: Vec<SourceFile>,
}

impl SourceMap {
    /// An empty map.
    pub fn new() -> SourceMap {
        SourceMap::default()
    }

    /// Adds a file and returns its id.
    pub fn add(&mut self, name: impl Into<String>, path: Option<PathBuf>, text: String) -> FileId {
        let id = FileId(self.files.len() as u32);
        self.files.push(SourceFile::new(name.into(), path, text));
        id
    }

    /// The file with id `id`.
    pub fn get(&self, id: FileId) -> &SourceFile {
        &self.files[id.0 as usize]
    }

    /// The id of an already loaded file with this path, if any.
    pub fn find_path(&self, path: &Path) -> Option<FileId> {
        self.files
            .iter()
            .position(|f| f.path.as_deref() == Some(path))
            .map(|i| FileId(i as u32))
    }

    /// The text a span covers.
    pub fn snippet(&self, span: Span) -> &str {
        let text = &self.get(span.file).text;
        text.get(span.range()).unwrap_or("")
    }

    /// All loaded files.
    pub fn files(&self) -> impl Iterator<Item = (FileId, &SourceFile)> {
        self.files
            .iter()
            .enumerate()
            .map(|(i, f)| (FileId(i as u32), f))
    }
}

/// Which folders a scene may read files from: its own folder, the `-I` folders and
/// whatever the user allowed with `--allow-path`.
#[derive(Clone, Debug, Default)]
pub struct FileAccess {
    /// `-I DIR` search folders, in order.
    pub include_dirs: Vec<PathBuf>,
    /// Extra folders the user allowed reads from (`--allow-path DIR`).
    pub allowed: Vec<PathBuf>,
    /// Allow reading any file (`--allow-any-path`).
    pub unrestricted: bool,
}

impl FileAccess {
    /// Whether `path` (canonical) lies under a folder scenes may read, given the
    /// folder of the main scene file.
    pub fn permits(&self, path: &Path, scene_dir: Option<&Path>) -> bool {
        if self.unrestricted {
            return true;
        }
        // A folder that cannot be resolved permits nothing (an empty path would
        // otherwise be a prefix of every path).
        let canon = |p: &Path| p.canonicalize().ok();
        scene_dir
            .into_iter()
            .filter_map(canon)
            .chain(self.include_dirs.iter().filter_map(|p| canon(p)))
            .chain(self.allowed.iter().filter_map(|p| canon(p)))
            .any(|dir| path.starts_with(dir))
    }

    /// Whether `name`, found in search folder `dir` and resolving to `canon`, may be
    /// read: as [`Self::permits`], or when `dir` is a folder the user named (`-I`,
    /// `--allow-path`) and `name` stays inside it as written (no `..`): links in a
    /// folder the user chose are followed (POV-Ray's include folder links its fonts
    /// from elsewhere), while links in the scene's own folder are not.
    pub fn permits_in(
        &self,
        dir: &Path,
        name: &str,
        canon: &Path,
        scene_dir: Option<&Path>,
    ) -> bool {
        if self.permits(canon, scene_dir) {
            return true;
        }
        let plain = Path::new(name).is_relative()
            && Path::new(name).components().all(|c| {
                matches!(
                    c,
                    std::path::Component::Normal(_) | std::path::Component::CurDir
                )
            });
        let canon_dir = dir.canonicalize().ok();
        plain
            && canon_dir.is_some()
            && self
                .include_dirs
                .iter()
                .chain(&self.allowed)
                .any(|d| d.canonicalize().ok() == canon_dir)
    }
}
