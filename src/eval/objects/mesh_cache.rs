//! Meshes kept from one evaluation of a scene to the next (animation frames), so a
//! mesh that does not change is the same `Arc` in every frame and the renderer can
//! keep its BVH ([`crate::build::BuildCache`]).

use crate::scene::MeshData;
use rustc_hash::{FxHashMap, FxHasher};
use std::hash::{Hash, Hasher};
use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::time::SystemTime;

/// A mesh read from a file, valid while the file's size and time are the same.
struct FileMesh {
    len: u64,
    modified: Option<SystemTime>,
    data: Arc<MeshData>,
}

/// Meshes by file and by content.
#[derive(Default)]
pub(crate) struct MeshCache {
    files: FxHashMap<PathBuf, FileMesh>,
    /// By content hash: the mesh and the evaluation that last used it.
    by_content: FxHashMap<u64, Vec<(Arc<MeshData>, u64)>>,
    generation: u64,
}

fn stat(path: &Path) -> Option<(u64, Option<SystemTime>)> {
    let m = std::fs::metadata(path).ok()?;
    Some((m.len(), m.modified().ok()))
}

fn content_hash(m: &MeshData) -> u64 {
    let mut h = FxHasher::default();
    let bits3 = |v: &[[f32; 3]], h: &mut FxHasher| {
        v.len().hash(h);
        for p in v {
            p.map(f32::to_bits).hash(h);
        }
    };
    bits3(&m.positions, &mut h);
    bits3(&m.normals, &mut h);
    m.uvs.len().hash(&mut h);
    for p in &m.uvs {
        p.map(f32::to_bits).hash(&mut h);
    }
    m.triangles.hash(&mut h);
    m.normal_indices.hash(&mut h);
    m.uv_indices.hash(&mut h);
    m.texture_indices.hash(&mut h);
    m.inside_vector
        .map(|v| v.to_array().map(f64::to_bits))
        .hash(&mut h);
    h.finish()
}

fn same(a: &MeshData, b: &MeshData) -> bool {
    a.positions == b.positions
        && a.normals == b.normals
        && a.uvs == b.uvs
        && a.triangles == b.triangles
        && a.normal_indices == b.normal_indices
        && a.uv_indices == b.uv_indices
        && a.texture_indices == b.texture_indices
        && a.inside_vector == b.inside_vector
}

impl MeshCache {
    /// Starts an evaluation.
    pub(crate) fn begin(&mut self) {
        self.generation += 1;
    }

    /// Ends an evaluation: meshes it did not use are forgotten (an animated mesh
    /// does not pile up one copy per frame).
    pub(crate) fn end(&mut self) {
        let g = self.generation;
        self.by_content.retain(|_, v| {
            v.retain(|(_, used)| *used == g);
            !v.is_empty()
        });
    }

    /// The mesh read earlier from `path`, if the file has not changed since.
    pub(crate) fn file(&self, path: &Path) -> Option<Arc<MeshData>> {
        let f = self.files.get(path)?;
        let (len, modified) = stat(path)?;
        (f.len == len && f.modified == modified).then(|| f.data.clone())
    }

    /// Remembers the mesh read from `path` and gives it back shared.
    pub(crate) fn store_file(&mut self, path: &Path, m: MeshData) -> Arc<MeshData> {
        let data = Arc::new(m);
        if let Some((len, modified)) = stat(path) {
            self.files.insert(
                path.to_path_buf(),
                FileMesh {
                    len,
                    modified,
                    data: data.clone(),
                },
            );
        }
        data
    }

    /// The shared mesh equal to `data`: the one an earlier evaluation made, or a new
    /// one. Meshes with per-triangle textures are not shared across evaluations.
    pub(crate) fn intern(&mut self, data: MeshData) -> Arc<MeshData> {
        if !data.textures.is_empty() {
            return Arc::new(data);
        }
        let g = self.generation;
        let list = self.by_content.entry(content_hash(&data)).or_default();
        for (m, used) in list.iter_mut() {
            if same(m, &data) {
                *used = g;
                return m.clone();
            }
        }
        let m = Arc::new(data);
        list.push((m.clone(), g));
        m
    }
}
