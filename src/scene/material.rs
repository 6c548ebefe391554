//! Colours, pigments, finishes and textures.

use super::Transform;
use glam::DVec3;
use std::sync::Arc;

/// A POV-Ray colour: red, green, blue, filter and transmit.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct Colour {
    /// Red, green and blue.
    pub rgb: DVec3,
    /// `filter`: light passing through, tinted by the colour.
    pub filter: f64,
    /// `transmit`: light passing through untinted.
    pub transmit: f64,
}

impl Colour {
    /// Opaque black.
    pub const BLACK: Colour = Colour {
        rgb: DVec3::ZERO,
        filter: 0.0,
        transmit: 0.0,
    };

    /// An opaque colour.
    pub fn rgb(r: f64, g: f64, b: f64) -> Colour {
        Colour {
            rgb: DVec3::new(r, g, b),
            filter: 0.0,
            transmit: 0.0,
        }
    }
}

/// `texture { pigment { … } normal { … } finish { … } }`.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct Texture {
    /// The colour pattern.
    pub pigment: Pigment,
    /// How the surface responds to light.
    pub finish: Finish,
    /// `normal { … }`: the bump pattern, if any.
    pub normal: Option<Normal>,
    /// Texture layers written before this one (`texture { A } texture { B }`: B's
    /// `under` holds A): they show through where this layer's pigment has filter or
    /// transmit.
    pub under: Option<std::sync::Arc<Texture>>,
    /// A patterned texture (`texture { checker texture { A } texture { B } }`,
    /// `texture { gradient y texture_map { … } }`): the pattern chooses whole
    /// textures, and this texture's own pigment, normal and finish are unused.
    /// Patterned textures are never layered (`under` is `None`), as in POV-Ray.
    pub patterned: Option<Arc<PatternedTexture>>,
    /// `interior_texture { … }` of the object: the texture seen where a ray
    /// meets the surface from inside (`None`: this texture on both sides).
    pub interior_texture: Option<Arc<Texture>>,
}

/// A pattern that chooses between whole textures.
#[derive(Clone, Debug, PartialEq)]
pub struct PatternedTexture {
    /// The pattern function.
    pub kind: PatternKind,
    /// Its modifiers (turbulence, wave form, frequency, phase).
    pub mods: PatternMods,
    /// Transforms of the pattern (the textures inside carry their own copies).
    pub transform: Option<Arc<Transform>>,
    /// The textures the pattern chooses from.
    pub entries: TextureEntries,
}

/// The entries of a `texture_map { [v TEXTURE] … }`, in the order written.
pub type TextureMapEntries = Arc<Vec<(f64, Arc<Texture>)>>;

/// What a patterned texture's pattern chooses from.
#[derive(Clone, Debug, PartialEq)]
pub enum TextureEntries {
    /// `texture_map { [v TEXTURE] … }`, in the order written (POV-Ray does not
    /// sort texture maps; see `pattern::texture_map::map_lookup`).
    Map(TextureMapEntries),
    /// The textures of a list pattern (`checker`: 2, `hexagon`: 3, `brick`: 2).
    List(Vec<Arc<Texture>>),
}

impl PatternedTexture {
    /// The textures the pattern chooses from.
    pub fn textures(&self) -> Vec<&Arc<Texture>> {
        match &self.entries {
            TextureEntries::Map(m) => m.iter().map(|(_, t)| t).collect(),
            TextureEntries::List(l) => l.iter().collect(),
        }
    }
}

impl Texture {
    /// Whether any pigment of this texture or the layers under it looks its colour
    /// up by the surface's uv coordinates (`image_map { … uv_mapping }`), so the
    /// renderer need not compute uv for other surfaces.
    pub fn uses_uv(&self) -> bool {
        self.any_plain(&mut |t| t.pigment.uses_uv())
    }

    /// Whether `f` holds for any plain texture this one is made of: its layers, or
    /// (for a patterned texture) the layers of every texture its pattern may choose.
    pub fn any_plain(&self, f: &mut impl FnMut(&Texture) -> bool) -> bool {
        match &self.patterned {
            Some(pt) => pt.textures().into_iter().any(|t| t.any_plain(f)),
            None => f(self) || self.under.as_ref().is_some_and(|t| t.any_plain(f)),
        }
    }

    /// Appends `t` to the transforms of every pattern of the texture (pigment and
    /// normal), as `translate`/`rotate`/`scale` written after them do.
    pub fn transform_patterns(&mut self, t: &Transform) {
        if let Some(it) = &mut self.interior_texture {
            let mut inner = (**it).clone();
            inner.transform_patterns(t);
            *it = Arc::new(inner);
        }
        if let Some(pt) = &mut self.patterned {
            // The transform applies to the whole texture: the pattern and every
            // texture it chooses (POV-Ray's manual; measured: a `scale` written
            // before or after the `texture_map` scales the entries' patterns too).
            let pt = Arc::make_mut(pt);
            compose(&mut pt.transform, t);
            let moved = |x: &Arc<Texture>| {
                let mut inner = (**x).clone();
                inner.transform_patterns(t);
                Arc::new(inner)
            };
            pt.entries = match &pt.entries {
                TextureEntries::Map(m) => {
                    TextureEntries::Map(Arc::new(m.iter().map(|(v, x)| (*v, moved(x))).collect()))
                }
                TextureEntries::List(l) => TextureEntries::List(l.iter().map(moved).collect()),
            };
            return;
        }
        compose(&mut self.pigment.transform, t);
        if let Some(n) = &mut self.normal {
            compose(&mut n.transform, t);
        }
        if let Some(u) = &mut self.under {
            let mut inner = (**u).clone();
            inner.transform_patterns(t);
            *u = std::sync::Arc::new(inner);
        }
    }
}

/// `transform := transform ∘ t` (t applied after).
pub fn compose(transform: &mut Option<Arc<Transform>>, t: &Transform) {
    let cur = transform.as_deref().copied().unwrap_or(Transform::IDENTITY);
    *transform = Some(Arc::new(cur.then(t)));
}

/// `pigment { PATTERN … [transforms] }`.
#[derive(Clone, Debug, PartialEq)]
pub struct Pigment {
    /// The pattern that gives the colour at a point.
    pub pattern: Pattern,
    /// `pattern_from_object`… stored as `object_from_pattern`: the transforms written
    /// inside the pigment (and those applied to the texture/object after it).
    pub transform: Option<Arc<Transform>>,
}

impl Pigment {
    /// Whether this pigment (or one nested in it) uses `uv_mapping`.
    pub fn uses_uv(&self) -> bool {
        match &self.pattern {
            Pattern::Solid(_) => false,
            Pattern::Checker(pair) => pair.iter().any(Pigment::uses_uv),
            Pattern::Image(im) => im.uv_mapping,
            Pattern::Uv(_) => true,
            Pattern::Mapped(m) => match &m.map {
                PatternMap::Colours(_) => false,
                PatternMap::Pigments(entries) => entries.iter().any(|(_, p)| p.uses_uv()),
                PatternMap::List(list) => list.iter().any(Pigment::uses_uv),
            },
        }
    }
}

impl Default for Pigment {
    /// POV-Ray's default pigment is black.
    fn default() -> Self {
        Pigment {
            pattern: Pattern::Solid(Colour::BLACK),
            transform: None,
        }
    }
}

/// The colour patterns of this release.
#[derive(Clone, Debug, PartialEq)]
pub enum Pattern {
    /// One colour everywhere.
    Solid(Colour),
    /// `checker A, B`: unit cubes alternating between two pigments.
    Checker(Box<[Pigment; 2]>),
    /// Any other pattern with its colour map, pigment map or list of pigments.
    Mapped(Box<Mapped>),
    /// `image_map { … }`.
    Image(Arc<ImageMap>),
    /// `pigment { uv_mapping … }`: the pigment looked up at `<u, v, 0>`, the
    /// surface's uv coordinates, through the transforms written in its own block
    /// (those applied from outside it, by a texture or object, do not move it, as
    /// in POV-Ray). Where a shape has no uv coordinates the point is used.
    Uv(Arc<Pigment>),
}

/// A pattern function with its modifiers and what its values map to.
#[derive(Clone, Debug, PartialEq)]
pub struct Mapped {
    /// The pattern function.
    pub kind: PatternKind,
    /// Turbulence, wave form, frequency and phase.
    pub mods: PatternMods,
    /// What the values (or, for list patterns, the cell index) select.
    pub map: PatternMap,
}

/// The pattern functions (`gradient`, `bozo`, …). List patterns (`hexagon`,
/// `brick`) select an entry by index; the others give a value in [0, 1].
#[derive(Clone, Debug, PartialEq)]
pub enum PatternKind {
    /// `checker` (as a list pattern inside a normal or with pigment entries).
    Checker,
    /// `hexagon`: three-colour hexagonal tiling of the x-z plane.
    Hexagon,
    /// `square`: four-colour tiling of the x-z plane by unit squares.
    Square,
    /// `triangular`: six-colour tiling of the x-z plane by equilateral triangles
    /// of side 1.
    Triangular,
    /// `brick`: bricks of `size` separated by `mortar`.
    Brick {
        /// `brick_size` (default <8, 3, 4.5>).
        size: glam::DVec3,
        /// `mortar` width (default 0.5).
        mortar: f64,
    },
    /// `gradient <V>`: position along V.
    Gradient(glam::DVec3),
    /// `radial`: angle around the y axis.
    Radial,
    /// `onion`: distance from the origin.
    Onion,
    /// `leopard`: regular spots.
    Leopard,
    /// `bozo` and `spotted`: smooth noise.
    Bozo,
    /// `marble`: x plus turbulence, triangle wave.
    Marble,
    /// `wood`: distance from the z axis, triangle wave.
    Wood,
    /// `granite`: 1/f fractal noise.
    Granite,
    /// `crackle`: cells around random points, one per unit cube; the value
    /// weighs the distances to the nearest three by `form`.
    Crackle {
        /// `form <F1, F2, F3>` (default `<-1, 1, 0>`: second nearest minus nearest).
        form: glam::DVec3,
        /// `metric P`: the Minkowski distance exponent (default 2, Euclidean).
        metric: f64,
        /// `solid`: each cell one value (of the noise at its point).
        solid: bool,
        /// `offset O` (default 0): the point lies O off the cell points along a
        /// fourth dimension, so every distance d becomes `(dᵐ + Oᵐ)^(1/m)`.
        offset: f64,
    },
    /// `agate`: turbulent sine bands.
    Agate,
    /// `wrinkles`: sum of noise octaves.
    Wrinkles,
    /// `ripples`: concentric waves from ten centres.
    Ripples,
    /// `waves`: like ripples, with varying frequency.
    Waves,
    /// `bumps`: noise (as a normal, bumps).
    Bumps,
    /// `dents`: as a normal, cubed noise dents.
    Dents,
    /// `function { … }`: a user function of x, y, z (wrapped into [0, 1] like
    /// `gradient`, as POV-Ray does).
    Function(Arc<super::Function>),
    // --- Geometric, quilted, spiral and fractal patterns (one group) ---
    /// `planar`: 1 on the x-z plane, down to 0 at distance 1.
    Planar,
    /// `spherical`: 1 at the origin, down to 0 at distance 1.
    Spherical,
    /// `cylindrical`: 1 on the y axis, down to 0 at distance 1.
    Cylindrical,
    /// `boxed`: 1 at the origin, down to 0 on the cube of side 2.
    Boxed,
    /// `quilted`: cushions in each unit cube, shaped by `control0` and `control1`.
    Quilted {
        /// `control0` (default 1).
        control0: f64,
        /// `control1` (default 1).
        control1: f64,
    },
    /// `spiral1 N`: N arms winding around the z axis like a screw thread.
    Spiral1(f64),
    /// `spiral2 N`: two spirals of N arms twisting in opposite directions.
    Spiral2(f64),
    /// `mandel`, `julia`, `magnet`: escape-time fractals in the x-y plane.
    Fractal(super::Fractal),
    /// `pigment_pattern { PIGMENT }`: the pigment's grey value
    /// (0.297 red + 0.589 green + 0.114 blue, as POV-Ray weighs them).
    PigmentPattern(Arc<Pigment>),
    /// `image_pattern { … }` (and a `bump_map`'s heights): a value read from an
    /// image.
    ImagePattern(Arc<ImagePattern>),
    /// `density_file df3 "FILE" [interpolate N]`: a value read from a 3-D grid
    /// filling the unit cube (see [`super::DensityGrid`]).
    DensityFile(Arc<super::DensityGrid>),
    /// `object { OBJECT A, B }`: entry B inside the object, A outside.
    Object(InsideTest),
    /// `average`: the entries of a pigment, normal or texture map averaged by
    /// their weights (the map values).
    Average,
    /// `cells`: one random value in [0, 1) for each unit cube (rts's own hash of
    /// the cube, so the values differ from POV-Ray's; the cells are the same).
    Cells,
    /// `slope { DIRECTION [, LO, HI] [altitude DIRECTION [, LO, HI]] }`: how
    /// far the surface normal faces a direction (and how high the point is).
    Slope(Box<SlopeSpec>),
    /// `material_map { png "file" texture { … } … }`: the image's palette index
    /// (or, for images without a palette, its grey value × 255) chooses a texture.
    MaterialMap(Arc<ImagePattern>),
}

/// How an `image_pattern`, `bump_map` or `material_map` reads its image.
#[derive(Clone, Debug, PartialEq)]
pub struct ImagePattern {
    /// The image, with its projection (`map_type`, `once`, `interpolate`),
    /// read as stored (the palette index of each pixel comes from its picture,
    /// for palette images).
    pub image: Arc<ImageMap>,
    /// What the value is made of.
    pub source: ImageUse,
}

/// What value an image gives a pattern.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ImageUse {
    /// The pixel's grey value (`use_color`; for images without a palette, the
    /// default).
    Colour,
    /// The pixel's palette index / 255 (`use_index`, the default for palette
    /// images).
    Index,
    /// The pixel's opacity (`use_alpha`).
    Alpha,
}

/// The parameters of the `slope` pattern.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SlopeSpec {
    /// The direction the normal is compared with (its length weighs it against
    /// the altitude).
    pub direction: DVec3,
    /// The slope values mapped to 0 and 1 (default 0 and 1).
    pub slope_range: (f64, f64),
    /// `altitude DIRECTION` (none: slope only).
    pub altitude: Option<DVec3>,
    /// The altitudes mapped to 0 and 1 (default 0 and 1).
    pub altitude_range: (f64, f64),
}

impl PatternKind {
    /// Whether the pattern selects entries by index (`checker`, `hexagon`,
    /// `square`, `triangular`, `brick`).
    pub fn is_list(&self) -> bool {
        matches!(
            self,
            PatternKind::Checker
                | PatternKind::Hexagon
                | PatternKind::Square
                | PatternKind::Triangular
                | PatternKind::Brick { .. }
                | PatternKind::MaterialMap(_)
                | PatternKind::Object(_)
        )
    }
}

/// POV-Ray's wave forms, applied to the pattern value after frequency and phase.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Wave {
    /// `ramp_wave`: the value modulo 1 (the default of most patterns).
    Ramp,
    /// `triangle_wave`: up from 0 to 1 and back down each unit.
    Triangle,
    /// `sine_wave`: `(1 + sin(2πv)) / 2`.
    Sine,
    /// `scallop_wave`: `|sin(πv)|`.
    Scallop,
    /// `cubic_wave`: `3v² - 2v³` of the ramp.
    Cubic,
    /// `poly_wave E`: the ramp to the power E.
    Poly(f64),
}

/// Pattern modifiers: `turbulence`, `octaves`, `omega`, `lambda`, wave form,
/// `frequency`, `phase`, warps.
#[derive(Clone, Debug, PartialEq)]
pub struct PatternMods {
    /// `turbulence <V>` (zero: none).
    pub turbulence: glam::DVec3,
    /// `octaves` (default 6).
    pub octaves: u32,
    /// `omega` (default 0.5).
    pub omega: f64,
    /// `lambda` (default 2).
    pub lambda: f64,
    /// The wave form.
    pub wave: Wave,
    /// `frequency` (default 1).
    pub frequency: f64,
    /// `phase` (default 0).
    pub phase: f64,
    /// `noise_generator` in force (1, 2 or 3; default 2).
    pub noise_generator: u8,
    /// `agate_turb`: how turbulent `agate` is (default 1).
    pub agate_turb: f64,
    /// `number_of_waves` in force: how many wave centres `waves` and `ripples`
    /// sum (1 to 10; default 10).
    pub number_of_waves: u8,
    /// `warp { … }` steps in the order written (applied last to first).
    pub warps: Option<Arc<[super::WarpStep]>>,
}

impl Default for PatternMods {
    fn default() -> Self {
        PatternMods {
            turbulence: glam::DVec3::ZERO,
            octaves: 6,
            omega: 0.5,
            lambda: 2.0,
            wave: Wave::Ramp,
            frequency: 1.0,
            phase: 0.0,
            noise_generator: 2,
            agate_turb: 1.0,
            number_of_waves: 10,
            warps: None,
        }
    }
}

/// What a pattern's values select.
#[derive(Clone, Debug, PartialEq)]
pub enum PatternMap {
    /// `color_map { [v colour] … }`, sorted by value.
    Colours(Arc<Vec<(f64, Colour)>>),
    /// `pigment_map { [v pigment] … }`, sorted by value.
    Pigments(Arc<Vec<(f64, Pigment)>>),
    /// The pigments of a list pattern (`hexagon A, B, C`).
    List(Vec<Pigment>),
}

/// `image_map { png "file" map_type interpolate once filter/transmit }`.
#[derive(Clone, Debug, PartialEq)]
pub struct ImageMap {
    /// The decoded file, shared by every map that reads it.
    pub picture: Arc<super::Picture>,
    /// How its stored values become colours (`gamma`, sRGB or as stored),
    /// for the picture's depth.
    pub tones: Arc<super::Tones>,
    /// `filter all F`: every pixel's filter (`None`: 0).
    pub filter_all: Option<f64>,
    /// `transmit all T`: every pixel's transmit (`None`: 1 − the pixel's
    /// opacity).
    pub transmit_all: Option<f64>,
    /// `filter INDEX, F` / `transmit INDEX, T` of a palette image: the filter
    /// and transmit of the pixels of each palette entry, where given.
    pub by_index: Option<Arc<[IndexClear; 256]>>,
    /// `map_type`: 0 planar, 1 spherical, 2 cylindrical.
    pub map_type: u8,
    /// `interpolate 2` (bilinear) when true; nearest pixel otherwise.
    pub interpolate: bool,
    /// `once`: no tiling (outside the unit square is transparent).
    pub once: bool,
    /// `uv_mapping`: look up by the surface's uv instead of the point.
    pub uv_mapping: bool,
    /// Whether light may pass: a pixel has filter or transmit, or the map is
    /// `once` (clear outside the unit square). See [`ImageMap::find_see_through`].
    pub see_through: bool,
    /// `turbulence` and `warp { }` of the pigment, applied to the point before
    /// the lookup (`None`: none).
    pub mods: Option<PatternMods>,
}

/// The filter and transmit `filter INDEX, F` / `transmit INDEX, T` give the
/// pixels of one palette entry (`None`: as the rest of the image).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct IndexClear {
    /// Filter.
    pub filter: Option<f64>,
    /// Transmit.
    pub transmit: Option<f64>,
}

impl ImageMap {
    /// A map of `picture` seen through `tones`, tiled, nearest pixel, planar,
    /// opaque where the picture is.
    pub fn new(picture: Arc<super::Picture>, tones: Arc<super::Tones>) -> ImageMap {
        let mut im = ImageMap {
            picture,
            tones,
            filter_all: None,
            transmit_all: None,
            by_index: None,
            map_type: 0,
            interpolate: false,
            once: false,
            uv_mapping: false,
            see_through: false,
            mods: None,
        };
        im.see_through = im.find_see_through();
        im
    }

    /// Width in pixels.
    pub fn width(&self) -> u32 {
        self.picture.width()
    }

    /// Height in pixels.
    pub fn height(&self) -> u32 {
        self.picture.height()
    }

    /// The colour of pixel `i` (row-major from the top-left): the stored value
    /// through the tones, filter and transmit as the map says.
    #[inline]
    pub fn pixel(&self, i: usize) -> Colour {
        let (rgb, alpha) = self.tones.colour(self.picture.texel(i));
        let mut filter = self.filter_all.unwrap_or(0.0);
        let mut transmit = self.transmit_all.unwrap_or_else(|| 1.0 - f64::from(alpha));
        if let (Some(table), Some(k)) = (&self.by_index, self.picture.index(i)) {
            let c = table[usize::from(k)];
            filter = c.filter.unwrap_or(filter);
            transmit = c.transmit.unwrap_or(transmit);
        }
        Colour {
            rgb: DVec3::from_array(rgb),
            filter,
            transmit,
        }
    }

    /// Whether any pixel lets light through (filter + transmit above 0) or the
    /// map is `once`: what [`ImageMap::see_through`] should be. Found from the
    /// picture's lowest opacity and the palette entries it uses, without
    /// reading every pixel.
    pub fn find_see_through(&self) -> bool {
        let clear = |c: IndexClear, alpha: f32| {
            let f = c.filter.or(self.filter_all).unwrap_or(0.0);
            let t = c
                .transmit
                .or(self.transmit_all)
                .unwrap_or(1.0 - f64::from(alpha));
            f + t > 0.0
        };
        if self.once {
            return true;
        }
        match (self.picture.palette(), &self.by_index) {
            (Some(palette), Some(table)) => (0..=255u8).any(|k| {
                self.picture.uses_index(k)
                    && clear(
                        table[usize::from(k)],
                        (f32::from(palette[usize::from(k)][3]) / 255.0).clamp(0.0, 1.0),
                    )
            }),
            _ => clear(IndexClear::default(), self.picture.min_alpha()),
        }
    }
}

/// `normal { PATTERN [bump_size] modifiers transforms }`.
#[derive(Clone, Debug, PartialEq)]
pub struct Normal {
    /// The bump pattern.
    pub kind: PatternKind,
    /// Its modifiers.
    pub mods: PatternMods,
    /// `bump_size` (the depth of the bumps).
    pub bump_size: f64,
    /// Transforms of the normal pattern.
    pub transform: Option<Arc<Transform>>,
    /// `accuracy`: the step of the slope's differences in pattern units (`None`:
    /// rts's own small step).
    pub accuracy: Option<f64>,
    /// What the pattern's value selects or shapes, if not bumps of its own
    /// slope: a `normal_map`, `slope_map`, the normals of a list pattern or an
    /// `average`.
    pub blend: Option<Arc<NormalBlend>>,
}

/// What a normal's pattern blends or shapes.
#[derive(Clone, Debug, PartialEq)]
pub enum NormalBlend {
    /// `normal_map { [v NORMAL] … }`, in the order written (`average`: the
    /// values are weights).
    Map(Vec<(f64, Normal)>),
    /// The normals of a list pattern (`checker normal { A } normal { B }`).
    List(Vec<Normal>),
    /// `slope_map { [v, <height, slope>] … }`: the pattern's value gives a
    /// height profile whose slope tilts the normal.
    Slopes(Vec<(f64, glam::DVec2)>),
    /// `bump_map { … }`: the image's values are heights.
    BumpMap,
}

/// `reflection { MIN, MAX fresnel falloff metallic }` or `reflection COLOUR`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Reflection {
    /// Reflection at normal incidence (and the only value when `max` equals it).
    pub min: DVec3,
    /// Reflection at grazing incidence.
    pub max: DVec3,
    /// `fresnel`: use the Fresnel equations with the interior's ior between min and max.
    pub fresnel: bool,
    /// `falloff`: exponent of the blend from min to max.
    pub falloff: f64,
    /// `metallic`: tint the reflection by the surface colour.
    pub metallic: f64,
    /// `exponent` (or the finish's `reflection_exponent`): the reflected
    /// colour is raised to `1 / exponent` per channel before it is scaled by
    /// the reflection amount (measured on POV-Ray 3.7); `None`: not given (1).
    pub exponent: Option<f64>,
}

impl Default for Reflection {
    fn default() -> Self {
        Reflection {
            min: DVec3::ZERO,
            max: DVec3::ZERO,
            fresnel: false,
            falloff: 1.0,
            metallic: 0.0,
            exponent: None,
        }
    }
}

/// `finish { ambient diffuse brilliance phong phong_size specular roughness metallic reflection }`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Finish {
    /// `ambient`: light the surface has without any source (default 0.1).
    pub ambient: DVec3,
    /// `diffuse`: Lambertian response (default 0.6).
    pub diffuse: f64,
    /// `diffuse D, BACK`: response to lights behind the surface (thin
    /// translucent things: paper, leaves; default 0).
    pub diffuse_back: f64,
    /// `brilliance`: exponent on the diffuse cosine (default 1).
    pub brilliance: f64,
    /// `phong`: Phong highlight strength (default 0).
    pub phong: f64,
    /// `phong_size`: Phong exponent (default 40).
    pub phong_size: f64,
    /// `specular`: Blinn highlight strength (default 0).
    pub specular: f64,
    /// `roughness`: Blinn highlight size (default 0.05; exponent is 1/roughness).
    pub roughness: f64,
    /// `metallic`: how much highlights take the surface colour (0 to 1).
    pub metallic: f64,
    /// Mirror reflection.
    pub reflection: Reflection,
    /// `emission`: light the surface gives off regardless of `ambient_light`.
    pub emission: DVec3,
    /// `conserve_energy`: transmitted light is reduced by what is reflected.
    pub conserve_energy: bool,
    /// `crand`: random darkening of each sample (0 = none).
    pub crand: f64,
    /// `irid { … }`: thin-film interference (amount 0 = none).
    pub irid: Irid,
}

/// `irid { AMOUNT thickness T turbulence U }`: thin-film interference colours.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct Irid {
    /// How much of the diffuse colour the interference replaces (0 = none).
    pub amount: f64,
    /// `thickness` of the film (default 0).
    pub thickness: f64,
    /// `turbulence`: how much the thickness varies (default 0).
    pub turbulence: f64,
}

impl Default for Finish {
    fn default() -> Self {
        Finish {
            ambient: DVec3::splat(0.1),
            diffuse: 0.6,
            diffuse_back: 0.0,
            brilliance: 1.0,
            phong: 0.0,
            phong_size: 40.0,
            specular: 0.0,
            roughness: 0.05,
            metallic: 0.0,
            reflection: Reflection::default(),
            emission: DVec3::ZERO,
            conserve_energy: false,
            crand: 0.0,
            irid: Irid::default(),
        }
    }
}

/// `interior { ior fade_distance fade_power }`: what is inside a surface, for rays
/// that pass through it (filter/transmit).
#[derive(Clone, Debug, PartialEq)]
pub struct Interior {
    /// `ior`: index of refraction (1 = no bending).
    pub ior: f64,
    /// `fade_distance`: distance at which light inside has faded to half (0 = no
    /// fading).
    pub fade_distance: f64,
    /// `fade_power`: exponent of the fading (0 = no fading).
    pub fade_power: f64,
    /// `fade_color`: the colour light fades towards (default black).
    pub fade_colour: DVec3,
    /// `media { … }` blocks inside the object (their effects add up).
    pub media: Vec<super::Media>,
    /// `caustics C`: POV-Ray's simulated caustics. Light a shadow ray carries
    /// through the surface is multiplied by `1 + |cos θ|^(45 C)`, θ between
    /// the ray and the (perturbed) surface normal (0 = off).
    pub caustics: f64,
}

impl Default for Interior {
    /// POV-Ray's default interior: ior 1, no fading.
    fn default() -> Self {
        Interior {
            ior: 1.0,
            fade_distance: 0.0,
            fade_power: 0.0,
            fade_colour: DVec3::ZERO,
            media: Vec::new(),
            caustics: 0.0,
        }
    }
}

/// The inside test of an `object` pattern's object, made by the evaluator from
/// the built object (so the scene description does not depend on the build).
#[derive(Clone)]
pub struct InsideTest(pub Arc<dyn Fn(DVec3) -> bool + Send + Sync>);

impl InsideTest {
    /// Whether `p` (pattern space) is inside the object.
    pub fn inside(&self, p: DVec3) -> bool {
        (self.0)(p)
    }
}

impl PartialEq for InsideTest {
    fn eq(&self, other: &Self) -> bool {
        Arc::ptr_eq(&self.0, &other.0)
    }
}

impl std::fmt::Debug for InsideTest {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("InsideTest")
    }
}
