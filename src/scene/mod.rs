//! The scene description: plain data produced by [`crate::eval`] and consumed by
//! [`crate::build`]. Every entity keeps the [`Span`] it came from so later stages can
//! report problems at the source, but nothing here refers to syntax.
//!
//! The types are closed enums so new shapes, patterns and lights are added as variants
//! without reshaping what exists.

mod animation;
mod atmosphere;
mod blob;
mod camera;
mod density;
pub mod function;
mod isosurface;
mod julia;
mod light;
mod material;
mod media;
mod object;
mod path;
mod photons;
mod picture;
mod radiosity;
pub mod spline;
mod sweep;
mod transform;
mod warp;

pub use animation::{Timeline, DEFAULT_FPS};
pub use atmosphere::{Atmosphere, Fog, FogKind, FogTurbulence, Rainbow, SkySphere};
pub use blob::{BlobComponent, BlobData, BlobKind};
pub use camera::{Camera, CameraFace, CameraKind, CameraMesh, MeshCamera, UvGrid};
pub use density::{DensityGrid, DF3_MAX_VOXELS};
pub use function::Function;
pub use isosurface::{Container, Isosurface, SlopeMeter};
pub use julia::{Algebra, Julia, JuliaFn};
pub use light::{AreaLight, Beam, Light, LightKind};
pub use material::{
    compose, Colour, Finish, ImageMap, InsideTest, Interior, Irid, Mapped, Normal, Pattern,
    PatternKind, PatternMap, PatternMods, PatternedTexture, Pigment, Reflection, Texture,
    TextureEntries, TextureMapEntries, Wave,
};
pub use material::{ImagePattern, ImageUse, IndexClear, NormalBlend, SlopeSpec};
pub use media::{Media, Scattering, ScatteringKind};
pub use object::{CsgOp, Members, MeshData, Object, ObjectFlags, Shape, TextData};
pub use path::{PathTracing, PixelFilter};
pub use photons::{LightPhotons, ObjectPhotons, PhotonDensity, Photons, PhotonsBlock};
pub use picture::{srgb_to_linear, Depth, Palette, Picture, Samples, Texel, Tones, Transfer};
pub use radiosity::{Radiosity, RadiosityBlock};
pub use spline::{Spline, SplineKind};
pub use sweep::{SweepData, SweepSpline};
pub use transform::Transform;
pub use warp::{Fractal, FractalKind, MappingWarp, Warp, WarpStep};

use glam::DVec3;

/// A whole evaluated scene: what one frame of a `.rts` file describes.
#[derive(Clone, Debug)]
pub struct Scene {
    /// The camera (POV-Ray's default camera when the file has none).
    pub camera: Camera,
    /// Light sources, in file order.
    pub lights: Vec<Light>,
    /// Top-level objects, in file order.
    pub objects: Vec<Object>,
    /// For each of `objects`, a number no other placement of an object shares
    /// (see [`next_placement`]). An object an animation's later frame reuses
    /// from an earlier one (its item was not evaluated again) keeps its number,
    /// so the build can reuse what it made of it. Shorter than `objects` (for a
    /// scene made in code) means nothing is known: everything is built.
    pub placed: Vec<u64>,
    /// Colour of rays that hit nothing (`background { … }`; black by default).
    pub background: Colour,
    /// `global_settings { … }`.
    pub global: GlobalSettings,
    /// `sky_sphere` and `fog`.
    pub atmosphere: Atmosphere,
    /// `animation { … }`: the timeline the scene declares, if any.
    pub animation: Option<Timeline>,
}

/// A number for one placement of an object in a scene, unique in the process.
pub fn next_placement() -> u64 {
    use std::sync::atomic::{AtomicU64, Ordering};
    static NEXT: AtomicU64 = AtomicU64::new(1);
    NEXT.fetch_add(1, Ordering::Relaxed)
}

impl Default for Scene {
    fn default() -> Self {
        Scene {
            camera: Camera::default(),
            lights: Vec::new(),
            objects: Vec::new(),
            placed: Vec::new(),
            background: Colour::BLACK,
            global: GlobalSettings::default(),
            atmosphere: Atmosphere::default(),
            animation: None,
        }
    }
}

/// `global_settings { ambient_light assumed_gamma max_trace_level adc_bailout }`.
#[derive(Clone, Debug, PartialEq)]
pub struct GlobalSettings {
    /// `ambient_light`: multiplies every finish's `ambient` (default white).
    pub ambient_light: DVec3,
    /// `assumed_gamma`: the gamma of the working colour space; `None` when the scene
    /// does not say (POV-Ray 3.7 then behaves as `assumed_gamma 1.0` with a warning).
    pub assumed_gamma: Option<f64>,
    /// No `assumed_gamma` in a scene without `#version 3.7`: POV-Ray 3.7 then turns
    /// gamma handling off, and the classic renderer writes the working values to
    /// the file as they are (unless `--gamma` is given).
    pub gamma_off: bool,
    /// A scene of a version before 3.7, or of none (POV-Ray 3.7 measured both
    /// ways): a filtering surface's own light is scaled by
    /// `1 - filter·max(r, g, b) - transmit` instead of 3.7's
    /// `1 - filter - transmit`, and under radiosity a finish's `ambient` still
    /// adds `ambient · ambient_light` (in 3.7 scenes it counts for nothing).
    pub pre_3_7: bool,
    /// `max_trace_level`: deepest recursion of reflected rays (default 5).
    pub max_trace_level: u32,
    /// `adc_bailout`: rays whose contribution falls below this are not traced further
    /// (default 1/255).
    pub adc_bailout: f64,
    /// `noise_generator`: 1, 2 or 3 (default 2); patterns declared after it use it.
    pub noise_generator: u8,
    /// `number_of_waves`: wave centres of `waves` and `ripples` (1 to 10, default
    /// 10); patterns declared after it use it.
    pub number_of_waves: u8,
    /// `path_tracing { … }` (rts): render with the path tracer, with these settings.
    pub path_tracing: Option<PathTracing>,
    /// `radiosity { … }`: gather indirect diffuse light (the classic renderer).
    pub radiosity: Option<Radiosity>,
    /// `photons { … }`: shoot photons at targets for caustics (the classic
    /// renderer).
    pub photons: Option<Photons>,
}

impl Default for GlobalSettings {
    fn default() -> Self {
        GlobalSettings {
            ambient_light: DVec3::ONE,
            assumed_gamma: None,
            gamma_off: false,
            pre_3_7: false,
            max_trace_level: 5,
            adc_bailout: 1.0 / 255.0,
            noise_generator: 2,
            number_of_waves: 10,
            path_tracing: None,
            radiosity: None,
            photons: None,
        }
    }
}
