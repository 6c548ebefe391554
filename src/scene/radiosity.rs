//! `global_settings { radiosity { … } }`: POV-Ray 3.7's indirect diffuse
//! lighting (see docs/language.md, "Radiosity").

/// The radiosity settings, POV-Ray 3.7's defaults unless the scene says.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Radiosity {
    /// `adc_bailout`: gathering rays whose contribution falls below this stop.
    pub adc_bailout: f64,
    /// `always_sample`: the final pass gathers new values where the pretrace
    /// left too few (rts computes them without keeping them, see docs).
    pub always_sample: bool,
    /// `brightness`: multiplies the gathered light.
    pub brightness: f64,
    /// `count N`: rays a new value is gathered from.
    pub count: u32,
    /// `count N, M`: the pool of directions they are drawn from (`count` when
    /// not given).
    pub count_pool: u32,
    /// `error_bound`: how far a value is reused (larger: further, smoother).
    pub error_bound: f64,
    /// `gray_threshold`: 0 keeps the gathered colour, 1 makes it grey.
    pub gray_threshold: f64,
    /// `low_error_factor`: the pretrace uses `error_bound` times this.
    pub low_error_factor: f64,
    /// `max_sample`: the brightest a gathered value may be (≤ 0: no limit).
    pub max_sample: f64,
    /// `maximum_reuse`: largest reuse radius, as a fraction of the distance
    /// from the camera.
    pub maximum_reuse: f64,
    /// `minimum_reuse`: smallest reuse radius, likewise.
    pub minimum_reuse: f64,
    /// `nearest_count N`: the pretrace gathers a new value where fewer than
    /// this many can be blended.
    pub nearest_count: u32,
    /// `media`: gathering rays see media.
    pub media: bool,
    /// `normal`: gathering uses the perturbed (`normal { }`) normal.
    pub normal: bool,
    /// `pretrace_start`: block size of the first pretrace pass, as a fraction
    /// of the image's larger side.
    pub pretrace_start: f64,
    /// `pretrace_end`: block size of the last pretrace pass.
    pub pretrace_end: f64,
    /// `recursion_limit`: bounces of diffuse light gathered (1 to 20).
    pub recursion_limit: u32,
}

impl Default for Radiosity {
    fn default() -> Self {
        Radiosity {
            adc_bailout: 0.01,
            always_sample: false,
            brightness: 1.0,
            count: 35,
            count_pool: 35,
            error_bound: 1.8,
            gray_threshold: 0.0,
            low_error_factor: 0.5,
            max_sample: -1.0,
            maximum_reuse: 0.2,
            minimum_reuse: 0.015,
            nearest_count: 5,
            media: false,
            normal: false,
            pretrace_start: 0.08,
            pretrace_end: 0.04,
            recursion_limit: 2,
        }
    }
}

/// What a `radiosity { … }` block said: global settings (in `global_settings`)
/// or an object's `importance`.
#[derive(Clone, Debug, PartialEq)]
pub struct RadiosityBlock {
    /// The settings, defaults where the block is silent.
    pub settings: Radiosity,
    /// `importance F` (an object's block).
    pub importance: Option<(f64, crate::span::Span)>,
    /// Span of the first global-settings item, if any.
    pub global_item: Option<crate::span::Span>,
}
