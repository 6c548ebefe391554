//! Light sources.

use super::Object;
use crate::span::Span;
use glam::DVec3;
use std::sync::Arc;

/// `light_source { LOCATION, COLOUR … }`.
#[derive(Clone, Debug)]
pub struct Light {
    /// Position in world space.
    pub location: DVec3,
    /// Colour, used as intensity (may exceed 1).
    pub colour: DVec3,
    /// What kind of light this is.
    pub kind: LightKind,
    /// `parallel`: light arrives everywhere from the direction `location - point_at`;
    /// only objects in front of the plane through `location` cast shadows.
    pub parallel: bool,
    /// `point_at` (default origin): where spotlights, cylinder and parallel lights aim.
    pub point_at: DVec3,
    /// `shadowless`: this light casts no shadows.
    pub shadowless: bool,
    /// `fade_distance` (0 = no fading).
    pub fade_distance: f64,
    /// `fade_power` (0 = no fading).
    pub fade_power: f64,
    /// `media_interaction` (default on): whether scattering media is lit by it.
    pub media_interaction: bool,
    /// `media_attenuation` (default off): whether media on the way dims its light.
    pub media_attenuation: bool,
    /// `area_light …`: soft shadows from a grid of lights.
    pub area: Option<AreaLight>,
    /// `looks_like { OBJECT }`: the object, already placed at the light; the evaluator
    /// adds it to the scene with `no_shadow`.
    pub looks_like: Option<Arc<Object>>,
    /// `projected_through { OBJECT }`: only light whose way to a point crosses this
    /// object shines there, and only what lies beyond the object shadows it. The
    /// object is a mask, not part of the scene; it moves with the light's own
    /// transforms.
    pub projected_through: Option<Arc<Object>>,
    /// Where the light was written.
    pub span: Span,
    /// The `light_group` (bit index of [`super::ObjectFlags::light_groups`])
    /// whose objects alone this light lights; `None`: a scene light.
    pub group: Option<u8>,
    /// `photons { … }`: what this light's photons may do.
    pub photons: super::LightPhotons,
}

impl Default for Light {
    /// A white point light at the origin.
    fn default() -> Self {
        Light {
            location: DVec3::ZERO,
            colour: DVec3::ONE,
            kind: LightKind::Point,
            parallel: false,
            point_at: DVec3::ZERO,
            shadowless: false,
            fade_distance: 0.0,
            fade_power: 0.0,
            media_interaction: true,
            media_attenuation: false,
            area: None,
            looks_like: None,
            projected_through: None,
            span: Span::default(),
            group: None,
            photons: super::LightPhotons::default(),
        }
    }
}

impl Light {
    /// Whether this light lights an object with `flags`: a group's light only
    /// the group's objects; a scene light every object outside groups, and a
    /// group's objects when the group says `global_lights on`.
    pub fn reaches(&self, flags: &super::ObjectFlags) -> bool {
        match self.group {
            Some(g) => flags.light_groups & (1u64 << g) != 0,
            None => flags.light_groups == 0 || flags.global_lights == Some(true),
        }
    }
}

/// The kinds of light source (the cone or cylinder that limits them).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum LightKind {
    /// An omnidirectional point light (or a `parallel` light).
    Point,
    /// `spotlight`: a cone from `location` towards `point_at`.
    Spot(Beam),
    /// `cylinder`: a cylinder along `location → point_at`; radii in scene units.
    Cylinder(Beam),
}

/// The shape of a spotlight's cone or a cylinder light's beam.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Beam {
    /// `radius`: full intensity inside (degrees for spotlights, units for cylinders).
    pub radius: f64,
    /// `falloff`: no light outside (same units as `radius`).
    pub falloff: f64,
    /// `tightness`: extra exponent softening the beam.
    pub tightness: f64,
}

impl Beam {
    /// POV-Ray 3.7's spotlight defaults: `radius 30 falloff 45 tightness 0`.
    pub const SPOT: Beam = Beam {
        radius: 30.0,
        falloff: 45.0,
        tightness: 0.0,
    };
    /// POV-Ray 3.7's cylinder light defaults: `radius 0.75 falloff 1 tightness 0`.
    pub const CYLINDER: Beam = Beam {
        radius: 0.75,
        falloff: 1.0,
        tightness: 0.0,
    };
}

/// `area_light AXIS1, AXIS2, N1, N2 [jitter] [adaptive A] [circular] [orient]`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AreaLight {
    /// First axis: the full extent of the grid along it.
    pub axis1: DVec3,
    /// Second axis.
    pub axis2: DVec3,
    /// Lights along `axis1` (≥ 1).
    pub size1: u32,
    /// Lights along `axis2` (≥ 1).
    pub size2: u32,
    /// `jitter`: each light moves randomly within its cell, per sample.
    pub jitter: bool,
    /// `adaptive A`: test grid corners first, subdividing where they differ; forced
    /// subdivision for the first A levels. `None` tests every light.
    pub adaptive: Option<u32>,
    /// `circular`: the grid is mapped onto a disc (an ellipse for unequal axes).
    pub circular: bool,
    /// `orient`: the axes turn to face each lit point.
    pub orient: bool,
}
