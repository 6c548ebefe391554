//! What a texture description is worth at a point: patterns and the noise
//! under them, warps, pigments with their colour and pigment maps, image maps,
//! normal perturbation, the textures a patterned texture chooses, and compiled
//! functions (which are patterns, and call pigments and patterns in turn).
//!
//! Runtime code that the evaluator (`trace`, function calls, `f_noise3d`),
//! the build (isosurfaces) and the renderer all run, on [`crate::scene`] data
//! only: it knows nothing of syntax, rays or the world, and imports no stage
//! but `scene`. It stands apart from `render` so that `eval` and `build` need
//! not import the renderer.

mod fractals;
pub mod function;
mod image_map;
pub mod internal;
pub mod noise;
mod normal_blend;
pub mod patterns;
mod pigment;
mod shapes;
pub mod slope;
pub mod texture_map;
pub mod warps;

pub use pigment::{
    checker_index, colour_at, evaluate, evaluate_uv, perturb, perturb_camera_ray, CHECKER_OFFSET,
};
pub use texture_map::{for_each_plain, plain_at};
