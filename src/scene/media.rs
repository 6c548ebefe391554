//! Participating media: `media { … }` in an interior (bounded by the object) or at
//! top level (filling all space), as POV-Ray 3.7 defines it.

use super::{Pigment, Transform};
use glam::DVec3;

/// One `media { … }` block.
///
/// Along a ray, a medium absorbs (`absorption`), glows (`emission`) and scatters
/// light of the light sources towards the viewer (`scattering`); all three are per
/// unit of distance and multiplied by the density at the point. What lies behind
/// is dimmed by `exp(-∫ (absorption + extinction · scattering) · density ds)`.
#[derive(Clone, Debug, PartialEq)]
pub struct Media {
    /// `method` 1 (random samples), 2 (stratified, jittered) or 3 (adaptive, the
    /// default).
    pub method: u8,
    /// `intervals` (default 1): how many pieces the lit part of a ray is cut into.
    pub intervals: u32,
    /// `samples Min[, Max]` (default 10, 10, as measured on POV-Ray 3.7).
    pub min_samples: u32,
    /// The most samples per interval (methods 1 and 2 add samples up to it while
    /// the variance is too high).
    pub max_samples: u32,
    /// `confidence` (default 0.9), for the variance test of methods 1 and 2.
    pub confidence: f64,
    /// `variance` (default 1/128), for the variance test of methods 1 and 2.
    pub variance: f64,
    /// `ratio` (default 0.9): the share of intervals given to lit parts of a ray.
    pub ratio: f64,
    /// `jitter` (default 0): how much sample positions are moved at random.
    pub jitter: f64,
    /// `aa_threshold` (default 0.1): method 3 subdivides where neighbouring
    /// samples differ by more.
    pub aa_threshold: f64,
    /// `aa_level` (default 3): how often method 3 may subdivide.
    pub aa_level: u32,
    /// `absorption COLOUR` (default black).
    pub absorption: DVec3,
    /// `emission COLOUR` (default black).
    pub emission: DVec3,
    /// `scattering { … }`.
    pub scattering: Option<Scattering>,
    /// `density { … }` blocks (their colours multiply); none means density 1.
    pub density: Vec<Pigment>,
}

impl Default for Media {
    /// POV-Ray 3.7's defaults.
    fn default() -> Self {
        Media {
            method: 3,
            intervals: 1,
            min_samples: 10,
            max_samples: 10,
            confidence: 0.9,
            variance: 1.0 / 128.0,
            ratio: 0.9,
            jitter: 0.0,
            aa_threshold: 0.1,
            aa_level: 3,
            absorption: DVec3::ZERO,
            emission: DVec3::ZERO,
            scattering: None,
            density: Vec::new(),
        }
    }
}

impl Media {
    /// Extinction per unit density: `absorption + extinction · scattering`.
    pub fn extinction(&self) -> DVec3 {
        self.absorption
            + self
                .scattering
                .map_or(DVec3::ZERO, |s| s.extinction * s.colour)
    }

    /// Moves the media's densities by `t` (written after them, or applied to the
    /// object that holds them).
    pub fn transform(&mut self, t: &Transform) {
        for d in &mut self.density {
            super::compose(&mut d.transform, t);
        }
    }
}

/// `scattering { TYPE, COLOUR [eccentricity E] [extinction X] }`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Scattering {
    /// The phase function.
    pub kind: ScatteringKind,
    /// How much light is scattered per unit distance.
    pub colour: DVec3,
    /// `eccentricity` (Henyey-Greenstein only; default 0).
    pub eccentricity: f64,
    /// `extinction` (default 1): how much scattering dims what lies behind.
    pub extinction: f64,
}

/// The scattering types: how scattered light depends on the angle between the
/// light and the viewing direction.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ScatteringKind {
    /// 1: the same in every direction.
    Isotropic,
    /// 2: Mie scattering by small particles (haze), mostly forwards.
    MieHazy,
    /// 3: Mie scattering by large particles (murky water), strongly forwards.
    MieMurky,
    /// 4: Rayleigh scattering by very small particles.
    Rayleigh,
    /// 5: Henyey-Greenstein, shaped by `eccentricity`.
    HenyeyGreenstein,
}

impl ScatteringKind {
    /// The type numbered `n` in POV-Ray (1 to 5).
    pub fn from_number(n: i64) -> Option<Self> {
        Some(match n {
            1 => ScatteringKind::Isotropic,
            2 => ScatteringKind::MieHazy,
            3 => ScatteringKind::MieMurky,
            4 => ScatteringKind::Rayleigh,
            5 => ScatteringKind::HenyeyGreenstein,
            _ => return None,
        })
    }
}
