//! Path tracing settings written in the scene (`global_settings { path_tracing { … } }`,
//! an rts addition).

/// How a pixel's samples are spread and weighted.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum PixelFilter {
    /// Every sample uniform over the pixel's square, equal weights.
    Box,
    /// A Gaussian (standard deviation 0.5 pixel, cut off at 1.5 pixels) centred on
    /// the pixel, sampled by importance so every sample has weight 1.
    #[default]
    Gaussian,
}

/// `path_tracing { samples N max_depth N firefly_clamp X pixel_filter "box"|"gaussian" }`
/// inside `global_settings`: render with the path tracer unless the command line
/// says `--integrator classic`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PathTracing {
    /// `samples`: samples per pixel (default 64).
    pub samples: u32,
    /// `max_depth`: the longest path in segments, counting the camera ray (1: only
    /// emitters seen directly; default 8).
    pub max_depth: u32,
    /// `firefly_clamp`: largest channel value one sample may add (0: no clamp, the
    /// default).
    pub firefly_clamp: f64,
    /// `pixel_filter`: the reconstruction filter (default Gaussian).
    pub filter: PixelFilter,
}

impl Default for PathTracing {
    fn default() -> Self {
        PathTracing {
            samples: 64,
            max_depth: 8,
            firefly_clamp: 0.0,
            filter: PixelFilter::Gaussian,
        }
    }
}
