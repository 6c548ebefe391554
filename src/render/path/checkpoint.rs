//! Checkpoints of a progressive render: the per-pixel sums and the sample count,
//! with what they depend on, in a small binary file (little-endian):
//!
//! ```text
//! "RTSPATH1"  magic
//! u32 × 6     image width, height, crop x0, y0, x1, y1
//! u64         seed
//! u32         frame
//! u32         max_depth
//! f64         clamp
//! u8          filter (0 box, 1 gaussian)
//! u64         scene fingerprint (a hash of the scene text the caller supplies)
//! u32         samples per pixel so far
//! f64 × 9 × N radiance, albedo and normal sums per pixel (row-major)
//! ```
//!
//! Sums are stored exactly, so continuing from a checkpoint gives the same bytes
//! as an uninterrupted render of the same total.

use super::{Accum, PathOptions};
use crate::render::{Crop, RenderOptions, Settings};
use crate::scene::PixelFilter;
use glam::DVec3;
use std::io::Write;
use std::path::Path;

const MAGIC: &[u8; 8] = b"RTSPATH1";

/// What a checkpoint must agree with to be continued.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Key {
    /// Image size.
    pub opts: RenderOptions,
    /// Region rendered.
    pub crop: Crop,
    /// Seed.
    pub seed: u64,
    /// Frame.
    pub frame: u32,
    /// Path options.
    pub path: PathOptions,
    /// Fingerprint of the scene.
    pub scene: u64,
}

impl Key {
    /// The key of a render.
    pub fn new(
        opts: &RenderOptions,
        settings: &Settings,
        crop: Crop,
        path: &PathOptions,
        scene: u64,
    ) -> Key {
        Key {
            opts: *opts,
            crop,
            seed: settings.seed,
            frame: settings.frame,
            path: *path,
            scene,
        }
    }

    fn header(&self) -> Vec<u8> {
        let mut b = Vec::with_capacity(80);
        b.extend_from_slice(MAGIC);
        for v in [
            self.opts.width,
            self.opts.height,
            self.crop.x0,
            self.crop.y0,
            self.crop.x1,
            self.crop.y1,
        ] {
            b.extend_from_slice(&v.to_le_bytes());
        }
        b.extend_from_slice(&self.seed.to_le_bytes());
        b.extend_from_slice(&self.frame.to_le_bytes());
        b.extend_from_slice(&self.path.max_depth.to_le_bytes());
        b.extend_from_slice(&self.path.clamp.to_le_bytes());
        b.push(match self.path.filter {
            PixelFilter::Box => 0,
            PixelFilter::Gaussian => 1,
        });
        b.extend_from_slice(&self.scene.to_le_bytes());
        b
    }
}

/// A 64-bit FNV-1a hash of `bytes`, for scene fingerprints.
pub fn fingerprint(bytes: &[u8]) -> u64 {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for b in bytes {
        h ^= u64::from(*b);
        h = h.wrapping_mul(0x0100_0000_01b3);
    }
    h
}

/// Writes `accum` with `key` to `path` (atomically: a temporary file renamed; a
/// FIFO or device there is refused).
pub fn save(path: &Path, key: &Key, accum: &Accum) -> std::io::Result<()> {
    let mut b = key.header();
    b.extend_from_slice(&accum.samples.to_le_bytes());
    for v in [&accum.sum, &accum.albedo, &accum.normal] {
        for p in v.iter() {
            for c in p.to_array() {
                b.extend_from_slice(&c.to_le_bytes());
            }
        }
    }
    let mut f = crate::files::create(path, crate::files::Policy::FileOnly)?;
    f.write_all(&b)?;
    f.commit()
}

/// Reads a checkpoint written for `key`; an error says why it cannot be used.
pub fn load(path: &Path, key: &Key) -> Result<Accum, String> {
    let head = key.header();
    let c = key.crop;
    let pixels = u64::from(c.x1.saturating_sub(c.x0)) * u64::from(c.y1.saturating_sub(c.y0));
    // Nothing longer than a checkpoint of this size is read (nor a FIFO waited on).
    let size = head.len() as u64 + 4 + pixels * 9 * 8;
    let b = crate::files::read_regular(path, size)
        .map_err(|e| format!("cannot read checkpoint `{}`: {e}", path.display()))?;
    if b.len() < head.len() + 4 || &b[..8] != MAGIC {
        return Err(format!(
            "`{}` is not an rts path tracing checkpoint",
            path.display()
        ));
    }
    if b[..head.len()] != head[..] {
        return Err(format!(
            "checkpoint `{}` was made for another scene, size, crop, seed, frame or path settings; \
             render again without --resume or with the same options",
            path.display()
        ));
    }
    let mut at = head.len();
    let samples = u32::from_le_bytes(b[at..at + 4].try_into().expect("4 bytes"));
    at += 4;
    let mut accum = Accum::new(key.crop);
    let n = accum.sum.len();
    if b.len() != at + n * 9 * 8 {
        return Err(format!("checkpoint `{}` is truncated", path.display()));
    }
    let mut f = || {
        let v = f64::from_le_bytes(b[at..at + 8].try_into().expect("8 bytes"));
        at += 8;
        v
    };
    for k in 0..3 {
        for i in 0..n {
            let p = DVec3::new(f(), f(), f());
            match k {
                0 => accum.sum[i] = p,
                1 => accum.albedo[i] = p,
                _ => accum.normal[i] = p,
            }
        }
    }
    accum.samples = samples;
    Ok(accum)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn round_trip_and_key_check() {
        let opts = RenderOptions {
            width: 4,
            height: 3,
        };
        let crop = Crop {
            x0: 0,
            y0: 0,
            x1: 4,
            y1: 3,
        };
        let key = Key::new(
            &opts,
            &Settings::default(),
            crop,
            &PathOptions::default(),
            42,
        );
        let mut a = Accum::new(crop);
        a.samples = 7;
        a.sum[5] = DVec3::new(0.1, 1e300, -3.0);
        a.normal[11] = DVec3::X;
        let dir = std::env::temp_dir().join(format!("rts_ckpt_{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let p = dir.join("a.ckpt");
        save(&p, &key, &a).unwrap();
        assert_eq!(load(&p, &key).unwrap(), a);
        let other = Key { scene: 43, ..key };
        assert!(load(&p, &other).unwrap_err().contains("another scene"));
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
