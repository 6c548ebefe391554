//! Light sources.

use crate::span::Span;
use glam::DVec3;

/// `light_source { LOCATION, COLOUR [parallel point_at P] }`.
#[derive(Clone, Debug, PartialEq)]
pub struct Light {
    /// Position in world space.
    pub location: DVec3,
    /// Colour, used as intensity (may exceed 1).
    pub colour: DVec3,
    /// What kind of light this is.
    pub kind: LightKind,
    /// `shadowless`: this light casts no shadows.
    pub shadowless: bool,
    /// Where the light was written.
    pub span: Span,
}

/// The kinds of light source.
#[derive(Clone, Debug, PartialEq)]
pub enum LightKind {
    /// An omnidirectional point light.
    Point,
    /// `parallel`: light arrives everywhere from the direction `location - point_at`;
    /// only objects in front of the plane through `location` cast shadows.
    Parallel {
        /// The point the light shines at (`point_at`, default origin).
        point_at: DVec3,
    },
}
