//! Ray intersection, normals and inside tests of each kind of shape, in the
//! shape's own space. One file per family; [`super::PrimShape`] dispatches.

pub mod flat;
pub mod poly;
pub mod quadric;
pub mod solid;
pub mod surface;
pub mod torus;
