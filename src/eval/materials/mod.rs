//! Readers of materials, one file per block: `texture` (and `tiles`,
//! `texture_map`), `pigment`, `normal`, `finish` (and `reflection`),
//! `interior`, `image_map`, `material` (`material_block`); POV-Ray's rule that
//! a pigment, finish or normal in a texture or object modifies the one in force
//! (`modify`); the patterns, their modifiers and maps (`patterns`); patterns
//! written as blocks and the maps of normals, slopes and materials
//! (`pattern_blocks`); warps; and `subsurface`.

pub(crate) mod finish;
pub(crate) mod image_map;
pub(crate) mod interior;
pub(crate) mod material_block;
pub(crate) mod modify;
pub(crate) mod normal;
pub(crate) mod pattern_blocks;
pub(crate) mod patterns;
pub(crate) mod pigment;
pub(crate) mod subsurface;
pub(crate) mod texture;
pub(crate) mod warps;
