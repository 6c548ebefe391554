//! Ray intersection, normals and inside tests of each kind of shape, in the
//! shape's own space. One file per family; [`super::PrimShape`] dispatches.

pub mod blob;
pub mod flat;
pub mod isosurface;
pub mod julia;
pub mod lathe;
pub mod poly;
pub mod prism;
pub mod quadric;
pub mod revolve;
pub mod solid;
pub mod sor;
pub mod superellipsoid;
pub mod surface;
pub mod sweep;
pub mod text;
pub mod torus;

/// The smallest distance `hits` reports (it calls its argument once per crossing).
pub fn nearest(hits: impl FnOnce(&mut dyn FnMut(f64))) -> Option<f64> {
    let mut best: Option<f64> = None;
    hits(&mut |t| {
        if best.is_none_or(|b| t < b) {
            best = Some(t)
        }
    });
    best
}
