//! Pigment evaluation.

use crate::scene::{Colour, Pattern, Pigment};
use glam::DVec3;

/// Added to each coordinate before flooring in `checker`. POV-Ray 3.7 shows the
/// same bias: a point 3e-10 below an integer plane still takes the lower cube, one
/// 1e-10 below flips to the upper one (measured with rays hitting exact boundaries).
pub const CHECKER_OFFSET: f64 = 1e-10;

/// Which of the two `checker` pigments covers pattern-space point `p`: 0 when
/// `floor(x) + floor(y) + floor(z)` is even (after [`CHECKER_OFFSET`]), else 1.
///
/// Measured against POV-Ray 3.7: the unit cube [0,1)³ takes the first pigment,
/// a point exactly on an integer plane belongs to the cube above it.
pub fn checker_index(p: DVec3) -> usize {
    let f = (p + DVec3::splat(CHECKER_OFFSET)).floor();
    let sum = f.x + f.y + f.z;
    usize::from(sum.rem_euclid(2.0) != 0.0)
}

/// The colour of `pigment` at point `p`, given in the space the pigment's own
/// transform is relative to (the texture's space).
pub fn evaluate(pigment: &Pigment, p: DVec3) -> Colour {
    let p = match &pigment.transform {
        Some(t) => t.inverse.transform_point3(p),
        None => p,
    };
    match &pigment.pattern {
        Pattern::Solid(c) => *c,
        Pattern::Checker(pair) => evaluate(&pair[checker_index(p)], p),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::Transform;
    use std::sync::Arc;

    fn solid(r: f64, g: f64, b: f64) -> Pigment {
        Pigment {
            pattern: Pattern::Solid(Colour::rgb(r, g, b)),
            transform: None,
        }
    }

    #[test]
    fn checker_parity_and_boundaries() {
        assert_eq!(checker_index(DVec3::splat(0.5)), 0);
        assert_eq!(checker_index(DVec3::new(1.5, 0.5, 0.5)), 1);
        assert_eq!(checker_index(DVec3::new(-0.5, 0.5, 0.5)), 1);
        assert_eq!(checker_index(DVec3::new(-0.5, -0.5, 0.5)), 0);
        // Exactly on a plane: the cube above.
        assert_eq!(checker_index(DVec3::new(1.0, 0.5, 0.5)), 1);
        assert_eq!(checker_index(DVec3::new(-1.0, 2.0, 0.5)), 1);
        assert_eq!(checker_index(DVec3::new(0.0, 2.0, 0.5)), 0);
        // Within the offset below a plane: still the cube above.
        assert_eq!(checker_index(DVec3::new(1.0 - 1e-11, 0.5, 0.5)), 1);
        assert_eq!(checker_index(DVec3::new(1.0 - 1e-9, 0.5, 0.5)), 0);
    }

    #[test]
    fn checker_uses_pigment_transform() {
        let pig = Pigment {
            pattern: Pattern::Checker(Box::new([solid(1.0, 0.0, 0.0), solid(0.0, 1.0, 0.0)])),
            transform: Some(Arc::new(Transform::scale(DVec3::splat(2.0)))),
        };
        assert_eq!(evaluate(&pig, DVec3::new(1.5, 0.5, 0.5)).rgb, DVec3::X);
        assert_eq!(evaluate(&pig, DVec3::new(2.5, 0.5, 0.5)).rgb, DVec3::Y);
    }
}
