//! Affine transforms kept with their inverse.

use glam::{DMat4, DVec3};

/// An affine transform `world_from_object` and its inverse.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Transform {
    /// Object space to world space.
    pub matrix: DMat4,
    /// World space to object space.
    pub inverse: DMat4,
}

impl Default for Transform {
    fn default() -> Self {
        Transform::IDENTITY
    }
}

impl Transform {
    /// The identity.
    pub const IDENTITY: Transform = Transform {
        matrix: DMat4::IDENTITY,
        inverse: DMat4::IDENTITY,
    };

    /// From a matrix; `None` when it cannot be inverted.
    pub fn from_matrix(matrix: DMat4) -> Option<Transform> {
        let det = matrix.determinant();
        if !det.is_finite() || det.abs() < 1e-300 {
            return None;
        }
        Some(Transform {
            matrix,
            inverse: matrix.inverse(),
        })
    }

    /// `translate V`.
    pub fn translate(v: DVec3) -> Transform {
        Transform {
            matrix: DMat4::from_translation(v),
            inverse: DMat4::from_translation(-v),
        }
    }

    /// `scale V` (components must be non-zero).
    pub fn scale(v: DVec3) -> Transform {
        Transform {
            matrix: DMat4::from_scale(v),
            inverse: DMat4::from_scale(v.recip()),
        }
    }

    /// `rotate <X, Y, Z>` in degrees: about x, then y, then z, in POV-Ray's
    /// left-handed sense.
    pub fn rotate(degrees: DVec3) -> Transform {
        let r = degrees * (std::f64::consts::PI / 180.0);
        // POV-Ray's rotation matrices are the right-handed ones applied to row
        // vectors; for column vectors that is the usual rotation by the same angle.
        let m =
            DMat4::from_rotation_z(r.z) * DMat4::from_rotation_y(r.y) * DMat4::from_rotation_x(r.x);
        Transform {
            matrix: m,
            inverse: m.transpose(),
        }
    }

    /// `then` applied after `self`: the result maps p to `then(self(p))`.
    pub fn then(&self, then: &Transform) -> Transform {
        Transform {
            matrix: then.matrix * self.matrix,
            inverse: self.inverse * then.inverse,
        }
    }

    /// Transforms a point.
    pub fn point(&self, p: DVec3) -> DVec3 {
        self.matrix.transform_point3(p)
    }

    /// Transforms a direction.
    pub fn vector(&self, v: DVec3) -> DVec3 {
        self.matrix.transform_vector3(v)
    }

    /// Transforms a surface normal (by the inverse transpose); not normalised.
    pub fn normal(&self, n: DVec3) -> DVec3 {
        self.inverse.transpose().transform_vector3(n)
    }
}
