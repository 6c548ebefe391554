//! `warp { … }` in patterns, and the parameters of the fractal patterns
//! (`mandel`, `julia`, `magnet`): plain descriptions, evaluated by
//! `pattern::warps` and `pattern::fractals`.

use glam::{DMat4, DVec2, DVec3};

/// One `warp { … }` of a pattern, with the pattern transform written before it.
#[derive(Clone, Debug, PartialEq)]
pub struct WarpStep {
    /// The warp.
    pub warp: Warp,
    /// The pattern's accumulated transform (pattern space to its parent) when the
    /// warp was written: the warp acts in the space of the transforms after it.
    pub before: Option<(DMat4, DMat4)>,
}

/// The warps POV-Ray 3.7 documents.
#[derive(Clone, Debug, PartialEq)]
pub enum Warp {
    /// `turbulence <T> [octaves] [omega] [lambda]`: displacement by vector noise.
    Turbulence {
        /// Amount per axis.
        amount: DVec3,
        /// `octaves` (default 6).
        octaves: u32,
        /// `omega` (default 0.5).
        omega: f64,
        /// `lambda` (default 2).
        lambda: f64,
    },
    /// `repeat <D> [offset <O>] [flip <F>]`: the slab [0, |D|) along D's axis
    /// repeats; each copy is shifted by `offset` and, every other one, flipped.
    Repeat {
        /// The axis (0, 1, 2).
        axis: usize,
        /// The repeat width along it.
        width: f64,
        /// `offset` per repeat.
        offset: DVec3,
        /// `flip`: axes mirrored in odd repeats (non-zero components).
        flip: DVec3,
    },
    /// `black_hole <C>, R [strength S] [falloff F] [inverse] [repeat <V>] [turbulence <T>]`.
    BlackHole {
        /// Centre.
        centre: DVec3,
        /// Radius of influence.
        radius: f64,
        /// `strength` (default 1).
        strength: f64,
        /// `falloff` (default 2).
        falloff: f64,
        /// `inverse`: push instead of pull.
        inverse: bool,
        /// `repeat <V>`: copies every V (zero components do not repeat).
        repeat: DVec3,
        /// `turbulence <T>`: random shift of each copy's centre (with `repeat`).
        turbulence: DVec3,
    },
    /// A mapping warp: `planar`, `cylindrical`, `spherical` or `toroidal`.
    Mapping {
        /// Which mapping.
        kind: MappingWarp,
        /// `orientation <V>` (default `<0, 0, 1>`).
        orientation: DVec3,
        /// `dist_exp E` (default 0).
        dist_exp: f64,
        /// `major_radius R` (toroidal; default 1).
        major_radius: f64,
    },
}

/// The mapping warps.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MappingWarp {
    /// `planar`: the x-y plane is kept; z becomes the distance exponent term.
    Planar,
    /// `cylindrical`: x = angle around the axis, y = height, z = distance.
    Cylindrical,
    /// `spherical`: x = longitude, y = latitude, z = distance.
    Spherical,
    /// `toroidal`: as cylindrical around a ring of `major_radius`.
    Toroidal,
}

/// Which fractal a fractal pattern iterates.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum FractalKind {
    /// `mandel`: z ← zⁿ + c from z = 0, c the point.
    Mandel,
    /// `julia <c>`: z ← zⁿ + c from z = the point.
    Julia(DVec2),
    /// `magnet 1 mandel`.
    Magnet1Mandel,
    /// `magnet 1 julia <c>`.
    Magnet1Julia(DVec2),
    /// `magnet 2 mandel`.
    Magnet2Mandel,
    /// `magnet 2 julia <c>`.
    Magnet2Julia(DVec2),
}

/// `mandel`, `julia` and `magnet` with their options.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Fractal {
    /// The iteration.
    pub kind: FractalKind,
    /// The maximum number of iterations.
    pub iterations: u32,
    /// `exponent` (2 to 33; default 2; mandel and julia only).
    pub exponent: u32,
    /// `exterior TYPE, FACTOR` (default 1, 1).
    pub exterior: (u8, f64),
    /// `interior TYPE, FACTOR` (default 0, 1).
    pub interior: (u8, f64),
}
