//! Photon mapping: `global_settings { photons { … } }`, an object's
//! `photons { target … }` and a light's `photons { … }` (POV-Ray 3.7's
//! caustics; see docs/language.md, "Photons").

use crate::span::Span;

/// How densely photons are shot.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum PhotonDensity {
    /// `spacing S`: about `S` units between photons where they reach a target
    /// (times the target's multiplier).
    Spacing(f64),
    /// `count N`: about `N` photons over all lights and targets.
    Count(u64),
}

/// The global photon settings, POV-Ray 3.7's defaults unless the scene says.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Photons {
    /// `spacing` or `count`.
    pub density: PhotonDensity,
    /// `gather MIN, MAX`: photons an estimate wants at least (the search
    /// radius grows until it has them) and uses at most (default 20, 100).
    pub gather_min: u32,
    /// See [`Photons::gather_min`].
    pub gather_max: u32,
    /// `jitter`: how far each photon's direction moves at random within its
    /// cell of the shooting pattern (0 to 1, default 0.4).
    pub jitter: f64,
    /// `max_trace_level`: reflections and refractions a photon may make
    /// (`None`: the scene's `max_trace_level`).
    pub max_trace_level: Option<u32>,
    /// `adc_bailout`: a photon whose share of the light falls below this stops
    /// (`None`: the scene's `adc_bailout`).
    pub adc_bailout: Option<f64>,
    /// `radius R`: the gather radius (`None` or 0: from the spacing).
    pub radius: Option<f64>,
    /// `radius , M`: multiplies the gather radius (default 1).
    pub radius_multiplier: f64,
}

impl Default for Photons {
    fn default() -> Self {
        Photons {
            density: PhotonDensity::Count(20_000),
            gather_min: 20,
            gather_max: 100,
            jitter: 0.4,
            max_trace_level: None,
            adc_bailout: None,
            radius: None,
            radius_multiplier: 1.0,
        }
    }
}

/// An object's `photons { … }`. The default (no block) collects photons and
/// neither reflects nor refracts them.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ObjectPhotons {
    /// `target [MULTIPLIER]`: lights shoot photons at this object, spaced
    /// `spacing × MULTIPLIER` apart (`None`: not a target).
    pub target: Option<f32>,
    /// `refraction on`: photons pass through it, bent by its `ior` and
    /// coloured by its `filter`/`transmit`.
    pub refraction: bool,
    /// `reflection on`: photons bounce off it as its `reflection` says.
    pub reflection: bool,
    /// `collect off`: photons are neither stored on nor gathered from it.
    pub no_collect: bool,
    /// `pass_through` (and `no_shadow`): photons on their way to a target go
    /// through it unaffected.
    pub pass_through: bool,
}

/// The multiplier is finite and above 0 (checked where it is read), so `==`
/// is an equivalence.
impl Eq for ObjectPhotons {}

impl ObjectPhotons {
    /// The settings of an object inside a CSG object whose own are `outer`:
    /// the object's own `target` multiplier wins, every switch adds.
    pub fn inherit(outer: ObjectPhotons, own: ObjectPhotons) -> ObjectPhotons {
        ObjectPhotons {
            target: own.target.or(outer.target),
            refraction: own.refraction || outer.refraction,
            reflection: own.reflection || outer.reflection,
            no_collect: own.no_collect || outer.no_collect,
            pass_through: own.pass_through || outer.pass_through,
        }
    }
}

/// A light's `photons { … }`. Measured on POV-Ray 3.7: a light without the
/// block (or with an empty one) shoots photons for both reflection and
/// refraction.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LightPhotons {
    /// `refraction off` stops this light's photons from refracting; objects
    /// that refract its photons then cast full shadows from it (the light
    /// through them arrives as photons).
    pub refraction: bool,
    /// `reflection off` stops its photons from reflecting.
    pub reflection: bool,
    /// `area_light`: accepted; photons always leave from the light's centre.
    pub area_light: bool,
}

impl Default for LightPhotons {
    fn default() -> Self {
        LightPhotons {
            refraction: true,
            reflection: true,
            area_light: false,
        }
    }
}

/// A `photons { … }` block as read, before the place it stands in (global
/// settings, an object or a light) takes the items it allows.
#[derive(Clone, Debug, Default)]
pub struct PhotonsBlock {
    /// Global settings (defaults where the block does not say).
    pub global: Photons,
    /// Object settings.
    pub object: ObjectPhotons,
    /// Light settings: `None` where the block does not say.
    pub light_refraction: Option<bool>,
    /// See [`PhotonsBlock::light_refraction`].
    pub light_reflection: Option<bool>,
    /// `area_light` was given.
    pub area_light: bool,
    /// `pass_through off` was given (it undoes `no_shadow`'s pass-through).
    pub pass_through_off: bool,
    /// Every item written, by keyword, where (for the context's checks).
    pub items: Vec<(&'static str, Span)>,
}
