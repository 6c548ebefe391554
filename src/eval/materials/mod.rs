//! Readers of materials: `texture`, `pigment`, `finish`, `normal` and
//! `interior` (`texture`), `material` (`material_block`), POV-Ray's rule that a
//! pigment, finish or normal in a texture or object modifies the one in force
//! (`modify`), the patterns and their maps (`patterns`), pattern blocks and
//! image maps (`pattern_blocks`), warps, and `subsurface`.

pub(crate) mod material_block;
pub(crate) mod modify;
pub(crate) mod pattern_blocks;
pub(crate) mod patterns;
pub(crate) mod subsurface;
pub(crate) mod texture;
pub(crate) mod warps;
