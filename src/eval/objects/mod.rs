//! Readers of objects: the shapes, CSG and the modifiers every object takes
//! (`object`), the shapes beyond the first release (`shapes`, `shapes_more`),
//! meshes written in the scene (`mesh`) or read from files (`import`, kept
//! between frames by `mesh_cache`), Bézier patches tessellated into meshes
//! (`bicubic`), revolved shapes (`revolve`), blobs, text and isosurfaces.

pub mod bicubic;
pub(crate) mod blob;
pub(crate) mod import;
pub(crate) mod isosurface;
pub(crate) mod mesh;
pub(crate) mod mesh_cache;
pub(crate) mod modifiers;
pub(crate) mod object;
pub(crate) mod revolve;
pub(crate) mod shapes;
pub(crate) mod shapes_more;
pub(crate) mod text;
