//! The manifest next to a frame sequence: which frames are complete, and for which
//! scene (the text of the scene file and of every file it included) and options.
//! A re-run skips the frames a manifest with the same key lists, when the frame
//! file is still the one recorded (same size and hash), and renders the rest.
//!
//! Each run writes its own manifest (`shot_####.png.manifest.json`, or
//! `shot_####.png.shard-2-of-3.manifest.json` for `--shard 2/3`), so shards that
//! share a folder never write the same file; a run reads them all.

use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// The largest manifest read (one of a million frames takes about 100 MiB).
const MAX_MANIFEST: u64 = 256 << 20;

/// 64-bit FNV-1a: stable across runs, platforms and Rust versions.
pub fn fnv64(bytes: &[u8]) -> u64 {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for b in bytes {
        h ^= u64::from(*b);
        h = h.wrapping_mul(0x0100_0000_01b3);
    }
    h
}

/// Hash of every source text the scene read (the scene file, its includes, `-D`
/// definitions), in the order they were read, and of the bytes of every data file
/// it read (meshes, height fields, images).
pub fn scene_hash<'a>(
    sources: &rts::source::SourceMap,
    data_files: impl Iterator<Item = &'a Path>,
) -> u64 {
    let mut all = Vec::new();
    for (_, f) in sources.files() {
        all.extend_from_slice(&(f.text.len() as u64).to_le_bytes());
        all.extend_from_slice(f.text.as_bytes());
    }
    for path in data_files {
        let bytes = rts::files::read_regular(path, u64::MAX).unwrap_or_default();
        all.extend_from_slice(path.to_string_lossy().as_bytes());
        all.extend_from_slice(&fnv64(&bytes).to_le_bytes());
    }
    fnv64(&all)
}

/// One finished frame.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct FrameRecord {
    /// The frame's file name (in the manifest's folder).
    pub file: String,
    /// Its size in bytes.
    pub bytes: u64,
    /// FNV-1a of its bytes, hex.
    pub hash: String,
}

/// A manifest file.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct Manifest {
    /// What the frames depend on, hashed: scene hash and options.
    pub key: String,
    /// Hash of the scene's sources, hex.
    pub scene_hash: String,
    /// The options that shape the pixels, as text (for people reading the file).
    pub options: String,
    /// Finished frames by number.
    pub frames: BTreeMap<i64, FrameRecord>,
}

impl Manifest {
    /// An empty manifest for `key`.
    pub fn new(scene_hash: u64, options: String) -> Manifest {
        let key = format!(
            "{:016x}",
            fnv64(format!("{scene_hash:016x}\n{options}").as_bytes())
        );
        Manifest {
            key,
            scene_hash: format!("{scene_hash:016x}"),
            options,
            frames: BTreeMap::new(),
        }
    }

    /// Records `frame` as written to `path`.
    pub fn record(&mut self, frame: i64, path: &Path) -> std::io::Result<()> {
        let bytes = rts::files::read_regular(path, u64::MAX).map_err(std::io::Error::other)?;
        self.frames.insert(
            frame,
            FrameRecord {
                file: path
                    .file_name()
                    .map_or_else(String::new, |n| n.to_string_lossy().into_owned()),
                bytes: bytes.len() as u64,
                hash: format!("{:016x}", fnv64(&bytes)),
            },
        );
        Ok(())
    }

    /// Writes the manifest atomically (a temporary file renamed over it).
    pub fn save(&self, path: &Path) -> std::io::Result<()> {
        use std::io::Write;
        let text = serde_json::to_string_pretty(self).map_err(std::io::Error::other)?;
        let mut f = rts::files::create(path, rts::files::Policy::FileOnly)?;
        f.write_all(text.as_bytes())?;
        f.write_all(b"\n")?;
        f.commit()
    }
}

/// The manifest this run writes, for frames named by `pattern` (a path with `#`s).
pub fn path_for(pattern: &Path, shard: Option<(u32, u32)>) -> PathBuf {
    let name = pattern
        .file_name()
        .map_or_else(|| "frames".into(), |n| n.to_string_lossy().into_owned());
    let file = match shard {
        Some((i, n)) => format!("{name}.shard-{i}-of-{n}.manifest.json"),
        None => format!("{name}.manifest.json"),
    };
    pattern.with_file_name(file)
}

/// Every manifest for `pattern` in its folder (all shards), unreadable ones left out.
pub fn load_all(pattern: &Path) -> Vec<Manifest> {
    let name = pattern
        .file_name()
        .map_or_else(String::new, |n| n.to_string_lossy().into_owned());
    let dir = match pattern.parent() {
        Some(d) if !d.as_os_str().is_empty() => d.to_path_buf(),
        _ => PathBuf::from("."),
    };
    let Ok(rd) = std::fs::read_dir(&dir) else {
        return Vec::new();
    };
    let mut out = Vec::new();
    for e in rd.flatten() {
        let f = e.file_name().to_string_lossy().into_owned();
        if f.starts_with(&name) && f.ends_with(".manifest.json") {
            // A manifest is small: a FIFO or a huge file of that name is passed over.
            if let Ok(bytes) = rts::files::read_regular(&e.path(), MAX_MANIFEST) {
                if let Ok(m) = serde_json::from_slice::<Manifest>(&bytes) {
                    out.push(m);
                }
            }
        }
    }
    out
}

/// Whether `frame`, at `path`, is complete for `key` according to `manifests`.
pub fn complete(manifests: &[Manifest], key: &str, frame: i64, path: &Path) -> bool {
    let records: Vec<&FrameRecord> = manifests
        .iter()
        .filter(|m| m.key == key)
        .filter_map(|m| m.frames.get(&frame))
        .collect();
    if records.is_empty() {
        return false;
    }
    let Ok(bytes) = rts::files::read_regular(path, u64::MAX) else {
        return false;
    };
    let hash = format!("{:016x}", fnv64(&bytes));
    records
        .iter()
        .any(|r| r.bytes == bytes.len() as u64 && r.hash == hash)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fnv_is_stable() {
        assert_eq!(fnv64(b""), 0xcbf2_9ce4_8422_2325);
        assert_eq!(fnv64(b"a"), 0xaf63_dc4c_8601_ec8c);
    }

    #[test]
    fn manifest_names() {
        let p = Path::new("out/shot_####.png");
        assert_eq!(
            path_for(p, None),
            Path::new("out/shot_####.png.manifest.json")
        );
        assert_eq!(
            path_for(p, Some((2, 3))),
            Path::new("out/shot_####.png.shard-2-of-3.manifest.json")
        );
    }
}
