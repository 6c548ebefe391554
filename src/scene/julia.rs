//! `julia_fractal { … }`: a 3D slice of a 4D Julia set `z ← f(z) + c`, as
//! written.

use glam::DVec4;

/// The algebra the iteration uses.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Algebra {
    /// `quaternion` (the default).
    Quaternion,
    /// `hypercomplex`.
    Hypercomplex,
}

/// The function iterated (plus the Julia parameter).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum JuliaFn {
    /// `sqr` (the default).
    Sqr,
    /// `cube`.
    Cube,
    /// `exp`.
    Exp,
    /// `reciprocal`.
    Reciprocal,
    /// `sin`.
    Sin,
    /// `asin`.
    Asin,
    /// `sinh`.
    Sinh,
    /// `asinh`.
    Asinh,
    /// `cos`.
    Cos,
    /// `acos`.
    Acos,
    /// `cosh`.
    Cosh,
    /// `acosh`.
    Acosh,
    /// `tan`.
    Tan,
    /// `atan`.
    Atan,
    /// `tanh`.
    Tanh,
    /// `atanh`.
    Atanh,
    /// `ln`.
    Ln,
    /// `pwr(X, Y)`: `z` to the complex power `X + Yi`.
    Pwr(f64, f64),
}

impl JuliaFn {
    /// The function named `name` (not `pwr`, which takes arguments).
    pub fn from_name(name: &str) -> Option<JuliaFn> {
        Some(match name {
            "sqr" => JuliaFn::Sqr,
            "cube" => JuliaFn::Cube,
            "exp" => JuliaFn::Exp,
            "reciprocal" => JuliaFn::Reciprocal,
            "sin" => JuliaFn::Sin,
            "asin" => JuliaFn::Asin,
            "sinh" => JuliaFn::Sinh,
            "asinh" => JuliaFn::Asinh,
            "cos" => JuliaFn::Cos,
            "acos" => JuliaFn::Acos,
            "cosh" => JuliaFn::Cosh,
            "acosh" => JuliaFn::Acosh,
            "tan" => JuliaFn::Tan,
            "atan" => JuliaFn::Atan,
            "tanh" => JuliaFn::Tanh,
            "atanh" => JuliaFn::Atanh,
            "ln" => JuliaFn::Ln,
            _ => return None,
        })
    }

    /// The names `from_name` knows, and `pwr`.
    pub const NAMES: &'static [&'static str] = &[
        "sqr",
        "cube",
        "exp",
        "reciprocal",
        "sin",
        "asin",
        "sinh",
        "asinh",
        "cos",
        "acos",
        "cosh",
        "acosh",
        "tan",
        "atan",
        "tanh",
        "atanh",
        "ln",
        "pwr",
    ];
}

/// `julia_fractal { <c> … }`: a slice of a 4D Julia set, in its own space
/// (intersected by `crate::build::shapes::julia`).
#[derive(Clone, Debug, PartialEq)]
pub struct Julia {
    /// The Julia parameter `c`.
    pub c: DVec4,
    /// The algebra.
    pub algebra: Algebra,
    /// The function.
    pub function: JuliaFn,
    /// `max_iteration` (≥ 1, default 20).
    pub max_iteration: u32,
    /// `precision` (> 0, default 20).
    pub precision: f64,
    /// The slice's unit 4D normal (`w` not 0).
    pub slice_normal: DVec4,
    /// The slice's distance from the origin along its normal.
    pub slice_distance: f64,
}
