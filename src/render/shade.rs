//! POV-Ray 3.7's classic shading model: ambient, diffuse, Phong and Blinn
//! highlights, hard shadows and mirror reflection.

use super::atmosphere;
use super::lights;
use super::media::{self, MediaPath};
use super::sampler::Sampler;
use super::stats::RayStats;
use crate::build::{Ray, RayKind, SurfaceHit, World};
use crate::pattern;
use crate::scene::{Finish, Interior, Reflection, Texture};
use glam::DVec3;

/// What one camera sample carries down its tree of rays: its sample values and
/// its ray counters.
pub struct TraceCtx<'a> {
    /// Sample values for this (pixel, sample, frame, seed).
    pub sampler: &'a mut Sampler,
    /// Rays traced so far.
    pub stats: &'a mut RayStats,
    /// The objects the ray being traced is inside (for media and fog).
    pub media: MediaPath,
    /// Surfaces passed straight through (no change of `ior`) on the way to
    /// the ray being traced; see [`MAX_PASSES`].
    pub passes: u32,
    /// Radiosity's cache and phase, when the scene has `radiosity { }`.
    pub radiosity: Option<&'a super::radiosity::State<'a>>,
    /// Which radiosity bounce this ray serves, and what the pretrace gathered.
    pub rad: super::radiosity::Local,
    /// The photons shot before the render, when the scene has `photons { }`.
    pub photons: Option<&'a super::photons::PhotonMap>,
    /// The interiors the ray being traced is in (for indices of refraction).
    pub iors: super::ior::IorStack,
}

/// How many surfaces a ray may pass straight through (transmitted without a
/// change of `ior`) before those crossings count towards `max_trace_level`.
/// POV-Ray 3.7 does not count them at all (measured: 200 clear planes in a row
/// under `max_trace_level 3` all let the background through, while 100
/// surfaces with an `ior` of 1.01 end black); the bound keeps the recursion
/// finite and shallow on scenes with thousands of such surfaces.
pub const MAX_PASSES: u32 = 256;

/// POV-Ray's "metallic" weight at angle of incidence `cos_incidence` (cosine against
/// the facing normal): about 0 at normal incidence, 1 at grazing.
///
/// Measured against POV-Ray 3.7 (16-bit linear output, several angles and colours)
/// it is the Fresnel-like fit
///
/// `F(θ) = 0.014567225 / (x - 1.12)² - 0.011612903`, `x = θ / (π/2)`.
///
/// A metallic amount `m` then tints per channel by
///
/// `tint = 1 + m (1 - F) (C - 1)`
///
/// where C is the pigment colour: highlights (`phong`, `specular`) multiply the
/// light colour by it, with θ the angle between the normal and the light; metallic
/// reflection multiplies the reflection amount by it, with θ the angle between the
/// normal and the viewing ray.
pub fn metallic_weight(cos_incidence: f64) -> f64 {
    let x = cos_incidence.clamp(-1.0, 1.0).abs().acos() / std::f64::consts::FRAC_PI_2;
    (0.014567225 / ((x - 1.12) * (x - 1.12)) - 0.011612903).clamp(0.0, 1.0)
}

/// The metallic tint `1 + m (1 - F) (C - 1)` (see [`metallic_weight`]).
pub fn metallic_tint(metallic: f64, colour: DVec3, cos_incidence: f64) -> DVec3 {
    if metallic == 0.0 {
        return DVec3::ONE;
    }
    let f = metallic_weight(cos_incidence);
    DVec3::ONE + metallic * (1.0 - f) * (colour - DVec3::ONE)
}

/// Fresnel reflectance of unpolarised light arriving at `cos_i` (cosine against
/// the normal, on the incident side) on a boundary with relative index of refraction
/// `eta` (= n_transmitted / n_incident); 1 under total internal reflection.
pub fn fresnel(cos_i: f64, eta: f64) -> f64 {
    let cos_i = cos_i.clamp(0.0, 1.0);
    let sin_t2 = (1.0 - cos_i * cos_i) / (eta * eta);
    if sin_t2 >= 1.0 {
        return 1.0;
    }
    let cos_t = (1.0 - sin_t2).sqrt();
    let rs = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
    let rp = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
    0.5 * (rs * rs + rp * rp)
}

/// The refracted direction of unit direction `d` through a surface with unit
/// normal `n` facing against `d`, for `eta` = n_incident / n_transmitted; `None`
/// under total internal reflection.
pub fn refract(d: DVec3, n: DVec3, eta: f64) -> Option<DVec3> {
    let cos_i = -d.dot(n);
    let k = 1.0 - eta * eta * (1.0 - cos_i * cos_i);
    if k < 0.0 {
        return None;
    }
    Some((eta * d + (eta * cos_i - k.sqrt()) * n).normalize())
}

/// Reflection amount at a surface viewed at `cos_view` (cosine between the facing
/// normal and the reversed ray): `min + (max - min) (1 - cos)^falloff`; with
/// `fresnel`, `min + (max - min) F` where F is the Fresnel reflectance for relative
/// index `eta` (n beyond the surface / n on the viewer's side).
pub fn reflection_amount(r: &Reflection, cos_view: f64, eta: f64) -> DVec3 {
    if r.fresnel {
        return r.min + (r.max - r.min) * fresnel(cos_view, eta);
    }
    if r.min == r.max {
        return r.min;
    }
    r.min + (r.max - r.min) * (1.0 - cos_view).max(0.0).powf(r.falloff)
}

/// The reflected colour `seen` under a reflection `exponent`: each channel
/// raised to `1 / exponent` (measured on POV-Ray 3.7: a mirror of reflection
/// 0.5, exponent 0.5 shows a background of 0.5 as 0.125, of 1 as 0.5).
fn reflection_exponent(seen: DVec3, exponent: Option<f64>) -> DVec3 {
    match exponent {
        Some(e) if e != 1.0 => seen.max(DVec3::ZERO).powf(1.0 / e),
        _ => seen,
    }
}

/// Colour seen along `ray`; `level` counts the ray's generation (1 for camera rays)
/// and `weight` is how much this ray contributes to the pixel.
pub fn trace(
    world: &World,
    ray: &Ray,
    t_min: f64,
    kind: RayKind,
    level: u32,
    weight: f64,
    ctx: &mut TraceCtx,
) -> DVec3 {
    let hit = world.intersect(ray, t_min, f64::INFINITY, kind);
    trace_found(world, ray, hit, level, weight, ctx)
}

/// [`trace`] once the nearest hit along `ray` (if any) is known.
pub fn trace_found(
    world: &World,
    ray: &Ray,
    hit: Option<crate::build::Hit>,
    level: u32,
    weight: f64,
    ctx: &mut TraceCtx,
) -> DVec3 {
    let (colour, depth) = match hit {
        None => (atmosphere::sky(world, ray.dir), atmosphere::MISS_DISTANCE),
        Some(hit) => {
            let surface = world.surface(ray, &hit);
            (shade(world, &surface, ray, level, weight, ctx), hit.t)
        }
    };
    if !world.tracks_interiors {
        return atmosphere::apply_atmosphere(&world.atmosphere, ray, depth, colour);
    }
    // Media and fog act only where every object the ray is in is hollow.
    let skip_media = ctx.radiosity.is_some_and(|r| r.skips_media(&ctx.rad));
    let colour = if world.has_media && !skip_media {
        media::along(world, ray, depth, colour, ctx)
    } else {
        colour
    };
    if ctx.media.hollow() {
        atmosphere::apply_atmosphere(&world.atmosphere, ray, depth, colour)
    } else {
        colour
    }
}

/// The layers of `tex`, top first.
fn layers(tex: &Texture) -> impl Iterator<Item = &Texture> {
    std::iter::successors(Some(tex), |t| t.under.as_deref())
}

/// Colour of the surface `s` seen along `ray`.
fn shade(
    world: &World,
    s: &SurfaceHit,
    ray: &Ray,
    level: u32,
    weight: f64,
    ctx: &mut TraceCtx,
) -> DVec3 {
    pattern::slope::set_surface_normal_facing(s.normal, ray.dir);
    // `interior_texture`: seen from inside the surface (the ray leaving
    // through it), as POV-Ray shades it.
    if let Some(inside) = &s.texture.interior_texture {
        if ray.dir.dot(s.geo_normal) > 0.0 {
            return shade_texture(world, s, inside, ray, level, weight, ctx);
        }
    }
    if let Some((blob, local)) = s.blob {
        // A blob's component textures: each shaded with its share of the
        // field at the point, and the colours averaged (as POV-Ray does).
        let mut out = DVec3::ZERO;
        for (tex, w) in blob.texture_weights(local) {
            let mut part = SurfaceHit { blob: None, ..*s };
            if let Some((t, m)) = tex {
                part.texture = t;
                part.texture_from_world = Some(m);
            }
            out += w * shade_texture(world, &part, part.texture, ray, level, weight * w, ctx);
        }
        return out;
    }
    shade_texture(world, s, s.texture, ray, level, weight, ctx)
}

/// Colour of the surface `s` with texture `tex` seen along `ray`.
///
/// A patterned texture shades the texture its pattern chooses; between two
/// entries of a `texture_map` it shades both, each with its share of the ray's
/// weight, and averages the colours by the blend (as POV-Ray does).
///
/// POV-Ray's rule for transparency: each layer's ambient, emission and diffuse
/// light is scaled by its opacity `1 - filter · max(r, g, b) - transmit`
/// (measured: rgbf <0.2, 0.6, 0.3, 0.5> shows 0.7 of its colour); what passes through is
/// scaled by `filter · colour + transmit` and continues into the layer below, and
/// past the last layer into the object (refracted by the interior's `ior`).
fn shade_texture(
    world: &World,
    s: &SurfaceHit,
    tex: &Texture,
    ray: &Ray,
    level: u32,
    weight: f64,
    ctx: &mut TraceCtx,
) -> DVec3 {
    let (p, geo_n) = (s.p, s.geo_normal);
    let tp = s.texture_from_world.map_or(p, |m| m.transform_point3(p));
    if let Some(pt) = &tex.patterned {
        return match pattern::texture_map::choose(pt, tp) {
            pattern::texture_map::Choice::One(t) => {
                shade_texture(world, s, t, ray, level, weight, ctx)
            }
            pattern::texture_map::Choice::Blend(a, b, t) => {
                let ca = shade_texture(world, s, a, ray, level, weight * (1.0 - t), ctx);
                let cb = shade_texture(world, s, b, ray, level, weight * t, ctx);
                ca * (1.0 - t) + cb * t
            }
            pattern::texture_map::Choice::Average(entries) => {
                let total: f64 = entries.iter().map(|(w, _)| *w).sum();
                if total == 0.0 {
                    return DVec3::ZERO;
                }
                let mut out = DVec3::ZERO;
                for (w, t) in entries {
                    let share = w / total;
                    out += share * shade_texture(world, s, t, ray, level, weight * share, ctx);
                }
                out
            }
        };
    }
    let d = ray.dir.normalize();
    let facing = |n: DVec3| if n.dot(d) > 0.0 { -n } else { n };
    let ior = s.interior.map_or(1.0, |i| i.ior);
    // Entering when the ray meets the outside of the surface (or, for a
    // triangle, mesh, polygon or disc, when it is not in the object yet).
    let entering = ctx.iors.entering(world, s, d);
    // The indices on the near and far side (nested interiors: see `ior`).
    let (n_near, n_far) = ctx.iors.sides(super::ior::key(s), ior, entering);
    let eta_view = n_far / n_near;

    let mut out = DVec3::ZERO;
    // The part of `out` that is the surfaces' reflection (see the end).
    let mut reflected = DVec3::ZERO;
    let mut through = DVec3::ONE;
    let mut conserve = DVec3::ONE;
    let mut last_n = facing(s.normal);
    // Radiosity's gathered light, looked up once for all layers.
    let mut gathered: Option<DVec3> = None;
    // The photons' light, likewise.
    let mut caustic: Option<DVec3> = None;
    for tex in layers(tex) {
        let c = pattern::evaluate_uv(&tex.pigment, tp, s.uv);
        let n = match &tex.normal {
            Some(nrm) => pattern::perturb(nrm, facing(s.normal), p, s.texture_from_world),
            None => facing(s.normal),
        };
        last_n = n;
        let f = &tex.finish;
        let colour = c.rgb;
        // In a 3.7 scene the surface's own light is scaled by 1 - filter -
        // transmit; in an older one (or one without `#version`) filter counts
        // in proportion to the colour's largest component (a dark filtering
        // colour hides less of the surface's own light): both measured on
        // POV-Ray 3.7. Not clamped: POV-Ray lets `filter + transmit`
        // above 1 make the opacity negative, so the surface's own light is
        // subtracted from the amplified light behind it (advanced/bwstripe.pov's
        // threshold lens; measured: rgb 0.5 transmit 2 over 0.6 gives 2·0.6 − 0.5).
        let filter_share = if world.global.pre_3_7 {
            colour.max_element()
        } else {
            1.0
        };
        let opacity = 1.0 - c.filter * filter_share - c.transmit;
        let ambient = match ctx.radiosity {
            // Radiosity replaces `ambient` with the gathered light times
            // `diffuse` (a 3.7 scene's `ambient` then counts for nothing; an
            // older scene's still adds; both measured on POV-Ray 3.7).
            Some(rs) => {
                let legacy = if world.global.pre_3_7 {
                    f.ambient * world.global.ambient_light
                } else {
                    DVec3::ZERO
                };
                if f.diffuse > 0.0 && colour != DVec3::ZERO && opacity != 0.0 {
                    let e = match gathered {
                        Some(e) => e,
                        None => {
                            let rn = if rs.settings.normal {
                                n
                            } else {
                                facing(s.normal)
                            };
                            let at = super::radiosity::Spot {
                                p,
                                geo_n: facing(geo_n),
                                n: rn,
                            };
                            let e = super::radiosity::irradiance(world, rs, at, level, ctx);
                            gathered = Some(e);
                            e
                        }
                    };
                    legacy + f.diffuse * e
                } else {
                    legacy
                }
            }
            None => f.ambient * world.global.ambient_light,
        };
        let mut layer = (ambient + f.emission) * colour * opacity;
        for light in 0..world.lights.len() {
            // A light_group's lights light only its objects (see `Light::reaches`).
            if !world.lights[light].reaches(&s.flags) {
                continue;
            }
            if let Some(inc) = lights::incident(world, light, p, geo_n, n, ctx) {
                layer += direct(
                    f,
                    colour,
                    opacity,
                    super::irid::tint(f, inc.colour, n, inc.dir, d, tp),
                    n,
                    inc.dir,
                    d,
                    n.dot(inc.dir),
                );
            } else if f.diffuse_back > 0.0 && !s.flags.double_illuminate {
                // `diffuse D, BACK`: a light behind the surface shows through
                // it by BACK (diffuse only, no highlights), the shadow ray
                // leaving from the back.
                if let Some(inc) = lights::incident(world, light, p, -geo_n, -n, ctx) {
                    let back = Finish {
                        diffuse: f.diffuse_back,
                        phong: 0.0,
                        specular: 0.0,
                        ..*f
                    };
                    layer += direct(
                        &back,
                        colour,
                        opacity,
                        inc.colour,
                        -n,
                        inc.dir,
                        d,
                        -n.dot(inc.dir),
                    );
                }
            } else if s.flags.double_illuminate {
                // `double_illuminate`: a light behind the surface (as seen from
                // the viewer) lights it too, as if the normal were turned to it;
                // the shadow ray then leaves from the back.
                if let Some(inc) = lights::incident(world, light, p, -geo_n, -n, ctx) {
                    layer += direct(
                        f,
                        colour,
                        opacity,
                        super::irid::tint(f, inc.colour, -n, inc.dir, d, tp),
                        -n,
                        inc.dir,
                        d,
                        -n.dot(inc.dir),
                    );
                }
            }
        }
        // Caustics: the light of the photons stored near the point, taken as
        // `diffuse` takes a light's (measured on POV-Ray 3.7: no further
        // cosine; the photons' density already holds it).
        if let Some(map) = ctx.photons.filter(|_| !s.flags.photons.no_collect) {
            if f.diffuse != 0.0 && colour != DVec3::ZERO && opacity != 0.0 {
                let e = *caustic.get_or_insert_with(|| map.irradiance(p, facing(geo_n)));
                layer += f.diffuse * e * colour * opacity;
            }
        }
        let r = &f.reflection;
        if r.min != DVec3::ZERO || r.max != DVec3::ZERO {
            let cos_v = -n.dot(d);
            let mut amount = reflection_amount(r, cos_v, eta_view);
            amount *= metallic_tint(r.metallic, colour, cos_v);
            if f.conserve_energy {
                conserve *= (DVec3::ONE - amount).max(DVec3::ZERO);
            }
            let next_weight = weight * amount.max_element() * through.max_element();
            if level < world.global.max_trace_level
                && next_weight >= world.global.adc_bailout
                && next_weight > 0.0
            {
                let dir = viewer_side(d - 2.0 * d.dot(n) * n, facing(geo_n));
                let (refl, eps) = Ray::secondary(p, geo_n, dir);
                ctx.stats.reflected += 1;
                let seen = trace(
                    world,
                    &refl,
                    eps,
                    RayKind::Reflected,
                    level + 1,
                    next_weight,
                    ctx,
                );
                let part = amount * reflection_exponent(seen, r.exponent);
                layer += part;
                reflected += through * part;
            }
        }
        if f.crand > 0.0 {
            // `crand`: each sample loses a random amount in [0, crand) of every
            // channel, clipped at black (measured on POV-Ray 3.7: a grey of
            // 0.397 with crand 0.5 loses 0 to 0.5, uniformly). Random numbers come
            // from the sampler so pictures are the same for any thread count.
            let u = f.crand * ctx.sampler.next_f64();
            layer = (layer - DVec3::splat(u)).max(DVec3::ZERO);
        }
        out += through * layer;
        through *= c.filter * colour + DVec3::splat(c.transmit);
        if through.max_element() <= 0.0 {
            return out;
        }
    }
    through *= conserve;
    let next_weight = weight * through.max_element();
    // Passing straight through a surface costs no trace level (see
    // `MAX_PASSES`); bending through it does.
    let passes = n_near == n_far && ctx.passes < MAX_PASSES;
    if (level >= world.global.max_trace_level && !passes)
        || next_weight < world.global.adc_bailout
        || next_weight <= 0.0
    {
        return out;
    }
    let (dir, kind) = bend(d, last_n, n_near / n_far);
    let dir = if kind == RayKind::Reflected {
        viewer_side(dir, facing(geo_n))
    } else {
        dir
    };
    // Total internal reflection returns all the light it reflects, whatever
    // the surface's filter and transmit (measured on POV-Ray 3.7: a clear box
    // with transmit 0.9 shows the light it reflects inside unscaled).
    // It also takes the place of the surface's own reflection (measured on
    // POV-Ray 3.7: seen from inside water of ior 1.3 past the critical angle,
    // `reflection 0`, 0.3 and 0.6 all show the reflected floor at full
    // brightness, and the surface's ambient light still adds).
    let (through, next_weight, out) = if kind == RayKind::Reflected {
        (DVec3::ONE, weight, (out - reflected).max(DVec3::ZERO))
    } else {
        (through, next_weight, out)
    };
    let next = Onward {
        dir,
        kind,
        entering,
        passes,
    };
    out + through * transmitted(world, s, next, level, next_weight, ctx)
}

/// Reflected direction `dir` kept on the viewer's side of the surface (`g`: the
/// geometric normal turned to the viewer): a perturbed normal can lean so far
/// that the mirror direction points into the surface; it is then mirrored back
/// across the surface's plane. Measured on POV-Ray 3.7: seen from under water at
/// 75 to 80 degrees off the vertical through `bumps 0.5`, 95% of the rays come
/// back totally reflected (rts let 31% through before this rule, where the
/// microfacet's mirror direction pointed up through the surface).
fn viewer_side(dir: DVec3, g: DVec3) -> DVec3 {
    let k = dir.dot(g);
    if k < 0.0 {
        dir - 2.0 * k * g
    } else {
        dir
    }
}

/// Where a ray through a surface goes on: along unit direction `d` unbent when
/// the ratio `eta` of the indices (near side over far side) is 1, else
/// refracted (a camera-kind ray) or, under total internal reflection,
/// reflected (`n`: the shading normal facing the viewer).
pub(super) fn bend(d: DVec3, n: DVec3, eta: f64) -> (DVec3, RayKind) {
    if eta == 1.0 {
        return (d, RayKind::Camera);
    }
    match refract(d, n, eta) {
        Some(t) => (t, RayKind::Camera),
        None => (d - 2.0 * d.dot(n) * n, RayKind::Reflected),
    }
}

/// How a ray goes on through a surface (see [`transmitted`]).
struct Onward {
    /// Its direction, from [`bend`].
    dir: DVec3,
    /// Camera for a ray passing through, Reflected under total internal
    /// reflection.
    kind: RayKind,
    /// Whether the ray entered the object at the surface.
    entering: bool,
    /// Whether it passes straight through without costing a trace level
    /// (see [`MAX_PASSES`]).
    passes: bool,
}

/// Light arriving through the surface at `s` along the ray going on as `onward`
/// (refracted, or reflected back by total internal reflection), faded by the
/// interior over the distance it travels inside.
fn transmitted(
    world: &World,
    s: &SurfaceHit,
    onward: Onward,
    level: u32,
    weight: f64,
    ctx: &mut TraceCtx,
) -> DVec3 {
    let Onward {
        dir,
        kind,
        entering,
        passes,
    } = onward;
    let (next, eps) = Ray::secondary(s.p, s.geo_normal, dir);
    ctx.stats.transmitted += 1;
    // A ray passing through the surface enters or leaves the object.
    let iors = ctx.iors;
    if kind == RayKind::Camera {
        let key = super::ior::key(s);
        if entering {
            ctx.iors.enter(key, s.interior.map_or(1.0, |i| i.ior));
        } else {
            ctx.iors.leave(key);
        }
    }
    let outer = (world.tracks_interiors && kind == RayKind::Camera).then(|| {
        let outer = ctx.media.clone();
        if entering {
            ctx.media.enter(s.prim, s.interior, s.flags.hollow);
        } else {
            ctx.media.leave(s.prim, s.interior);
        }
        outer
    });
    let colour = if passes {
        ctx.passes += 1;
        let c = trace(world, &next, eps, kind, level, weight, ctx);
        ctx.passes -= 1;
        c
    } else {
        trace(world, &next, eps, kind, level + 1, weight, ctx)
    };
    if let Some(outer) = outer {
        ctx.media = outer;
    }
    ctx.iors = iors;
    // Fading applies to light that crossed the inside: rays leaving it now.
    let inside = (kind == RayKind::Camera) == entering;
    match s.interior {
        // Only when the ray leaves through the object's own surface: a ray that
        // meets another object inside (a floor through a glass block's bottom)
        // is not faded, as POV-Ray 3.7 shows (measured: a floor halfway up a
        // fading box is seen at full brightness, one just below it faded).
        Some(i) if inside && i.fade_distance > 0.0 && i.fade_power > 0.0 => {
            match world.intersect(&next, eps, f64::INFINITY, kind) {
                Some(h) if h.prim == s.prim => {
                    let att = interior_fade(h.t, i.fade_distance, i.fade_power);
                    colour * (DVec3::splat(att) + (1.0 - att) * i.fade_colour)
                }
                Some(_) => colour,
                None => colour * i.fade_colour,
            }
        }
        _ => colour,
    }
}

/// The share of light left after `dist` units inside an interior with
/// `fade_distance` and `fade_power`, as POV-Ray 3.7 computes it (measured):
/// `1 / (1 + (dist / fade_distance)^fade_power)`, and for a power of 1000 or
/// more the physical `exp(-dist / fade_distance)`.
pub(super) fn interior_fade(dist: f64, fade_distance: f64, fade_power: f64) -> f64 {
    if fade_power >= 1000.0 {
        (-dist / fade_distance).exp()
    } else {
        1.0 / (1.0 + (dist / fade_distance).powf(fade_power))
    }
}

/// How much of a light's colour reaches along the shadow ray `ray` between
/// `t_min` and `t_max`: 1 when nothing is in the way, 0 behind an opaque surface,
/// and the product of `filter · colour + transmit` of each transparent surface
/// crossed otherwise (POV-Ray's filtered shadows; shadow rays do not bend).
/// `hint` is a primitive to test first, updated to the blocker found (see
/// [`World::occluded_hinted`]).
///
/// `photon_light`: the light shoots photons that refract (the scene has
/// `photons { }` and the light does not say `refraction off`); objects that
/// refract photons then block it fully, since the light through them arrives
/// as photons (measured on POV-Ray 3.7: a glass sphere that is a photon
/// target casts a dark shadow round its caustic, and none without photons).
pub fn shadow_filter(
    world: &World,
    ray: &Ray,
    t_min: f64,
    t_max: f64,
    hint: &mut u32,
    photon_light: bool,
) -> DVec3 {
    if !world.transparent {
        return if world.occluded_hinted(ray, t_min, t_max, hint) {
            DVec3::ZERO
        } else {
            DVec3::ONE
        };
    }
    // Dark behind anything opaque; else the product of the see-through
    // surfaces' filters (dark past 64 of them, as a bound on the walk), and of
    // the fading of the interiors crossed.
    let mut through = DVec3::ONE;
    let mut crossings = 0;
    let mut fading: Vec<Crossing> = Vec::new();
    let blocked = world.shadow_crossings(ray, t_min, t_max, hint, |hit| {
        crossings += 1;
        if crossings >= 64
            || (photon_light && world.primitives[hit.prim as usize].flags.photons.refraction)
        {
            return false;
        }
        let s = world.surface(ray, &hit);
        through *= surface_filter(&s);
        if let Some(c) = s.interior.map(|i| i.caustics).filter(|&c| c > 0.0) {
            through *= caustic_gain(&s, ray.dir, c);
        }
        if let Some(i) = s
            .interior
            .filter(|i| i.fade_distance > 0.0 && i.fade_power > 0.0)
        {
            fading.push(Crossing {
                prim: hit.prim,
                t: hit.t,
                entering: s.geo_normal.dot(ray.dir) < 0.0,
                interior: i,
            });
        }
        through.max_element() > 0.0
    });
    if blocked {
        return DVec3::ZERO;
    }
    if !fading.is_empty() {
        through *= shadow_fade(&mut fading, t_min, t_max);
    }
    through
}

/// POV-Ray's simulated caustics (`interior { caustics C }`): light crossing
/// surface `s` along `dir` is brightened by `1 + |cos θ|^(45 C)`, θ the angle
/// between `dir` and the surface normal as the texture's `normal` perturbs it.
/// Measured on POV-Ray 3.7 through a clear disc under a parallel light: the
/// gain is 2 at normal incidence for any C, `cos(10°)^45` over 1 at 10° for
/// C = 1 (1.502), the same for any pigment, once per surface crossed (a
/// sphere's shadow centre is 4 times as bright), and bumps on the disc make
/// the brightening vary with them.
fn caustic_gain(s: &SurfaceHit, dir: DVec3, power: f64) -> f64 {
    let d = dir.normalize();
    let toward = if s.normal.dot(d) > 0.0 {
        -s.normal
    } else {
        s.normal
    };
    let n = if s.texture.patterned.is_none() && s.blob.is_none() {
        layers(s.texture)
            .find_map(|t| t.normal.as_ref())
            .map_or(toward, |nrm| {
                pattern::perturb(nrm, toward, s.p, s.texture_from_world)
            })
    } else {
        toward
    };
    1.0 + n.dot(d).abs().powf(45.0 * power)
}

/// A shadow ray's crossing of a surface whose interior fades light.
struct Crossing<'a> {
    prim: u32,
    t: f64,
    entering: bool,
    interior: &'a Interior,
}

/// What the fading interiors let through along a shadow ray, from its
/// `crossings` of their surfaces (in any order): each stretch inside an object
/// fades the light as a camera ray's is faded, `a + (1 - a) fade_color` (as
/// POV-Ray 3.7 does, measured: a slab crossed over √2 units with exponential
/// fade over 1 unit leaves exp(-√2) of the light).
fn shadow_fade(crossings: &mut [Crossing], t_min: f64, t_max: f64) -> DVec3 {
    crossings.sort_by(|a, b| a.prim.cmp(&b.prim).then(a.t.total_cmp(&b.t)));
    let mut out = DVec3::ONE;
    for group in crossings.chunk_by(|a, b| a.prim == b.prim) {
        let i = group[0].interior;
        // A ray whose first crossing leaves the object started inside it.
        let mut since = (!group[0].entering).then_some(t_min);
        let mut stretches = Vec::new();
        for c in group {
            match (c.entering, since) {
                (true, _) => since = Some(c.t),
                (false, Some(t0)) => {
                    stretches.push(c.t - t0);
                    since = None;
                }
                (false, None) => {}
            }
        }
        if let Some(t0) = since.filter(|_| t_max.is_finite()) {
            stretches.push(t_max - t0);
        }
        for d in stretches {
            let a = interior_fade(d, i.fade_distance, i.fade_power);
            out *= DVec3::splat(a) + (1.0 - a) * i.fade_colour;
        }
    }
    out
}

/// What passes through the surface `s`: the product of
/// `filter · colour + transmit` over its texture's layers (a pattern's or a
/// blob's textures averaged by their weights there).
pub(super) fn surface_filter(s: &SurfaceHit) -> DVec3 {
    let tp = s
        .texture_from_world
        .map_or(s.p, |m| m.transform_point3(s.p));
    if let Some((blob, local)) = s.blob {
        // A blob's component textures: their filters averaged by the
        // components' shares of the field, as their colours are.
        let mut sum = DVec3::ZERO;
        for (own, w) in blob.texture_weights(local) {
            let (tex, m) = match own {
                Some((t, m)) => (t, Some(m)),
                None => (s.texture, s.texture_from_world),
            };
            let tp = m.map_or(s.p, |m| m.transform_point3(s.p));
            pattern::for_each_plain(tex, tp, w, &mut |t, w| {
                sum += w * layers_filter(t, tp, s.uv);
            });
        }
        sum
    } else if s.texture.patterned.is_some() {
        // The filters of the textures the pattern shows here, averaged by
        // their blend weights.
        let mut sum = DVec3::ZERO;
        pattern::for_each_plain(s.texture, tp, 1.0, &mut |t, w| {
            sum += w * layers_filter(t, tp, s.uv);
        });
        sum
    } else {
        layers_filter(s.texture, tp, s.uv)
    }
}

/// The product of `filter · colour + transmit` over the layers of plain texture
/// `tex` at `tp`: what passes through it.
fn layers_filter(tex: &Texture, tp: DVec3, uv: Option<glam::DVec2>) -> DVec3 {
    layers(tex).fold(DVec3::ONE, |through, t| {
        let c = pattern::evaluate_uv(&t.pigment, tp, uv);
        through * (c.filter * c.rgb + DVec3::splat(c.transmit))
    })
}

/// `x` to the power `e`: exact shortcuts for the common exponents of finishes
/// (`brilliance 1`, whole `phong_size`s), which otherwise cost a libm `pow` per
/// light per hit (a quarter of a simple scene's time in `perf`).
#[inline]
fn pow(x: f64, e: f64) -> f64 {
    if e == 1.0 {
        x
    } else if e == e.trunc() && (2.0..=256.0).contains(&e) {
        x.powi(e as i32)
    } else {
        x.powf(e)
    }
}

/// Diffuse and highlight contribution of one unshadowed light: unit normal `n`
/// facing the viewer, unit direction `l` to the light, unit ray direction `d`.
fn direct(
    f: &Finish,
    colour: DVec3,
    opacity: f64,
    light: DVec3,
    n: DVec3,
    l: DVec3,
    d: DVec3,
    cos_l: f64,
) -> DVec3 {
    let mut out = DVec3::ZERO;
    if f.diffuse != 0.0 {
        out += f.diffuse * opacity * pow(cos_l, f.brilliance) * light * colour;
    }
    if f.phong == 0.0 && f.specular == 0.0 {
        return out;
    }
    let highlight = light * metallic_tint(f.metallic, colour, cos_l);
    if f.phong != 0.0 {
        // R·L with R the mirrored view ray equals (mirrored L)·V.
        let r = d - 2.0 * d.dot(n) * n;
        let cos = r.dot(l);
        if cos > 0.0 {
            out += f.phong * pow(cos, f.phong_size) * highlight;
        }
    }
    if f.specular != 0.0 {
        let h = (l - d).normalize();
        let cos = n.dot(h);
        if cos > 0.0 {
            out += f.specular * pow(cos, 1.0 / f.roughness) * highlight;
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// POV-Ray 3.7, phong 1 at the highlight peak, pigment green 0.5, metallic 1:
    /// the green channel (16-bit linear) at several angles of incidence.
    #[test]
    fn metallic_matches_povray_measurements() {
        let measured = [
            (20.0, 32979),
            (40.0, 33433),
            (60.0, 34710),
            (70.0, 36463),
            (80.0, 41324),
            (85.0, 47875),
            (89.0, 60155),
        ];
        for (deg, green) in measured {
            let cos = f64::to_radians(deg).cos();
            let tint = metallic_tint(1.0, DVec3::new(1.0, 0.5, 0.25), cos);
            let ours = (tint.y * 65535.0).round();
            assert!(
                (ours - f64::from(green)).abs() <= 2.0,
                "{deg}°: {ours} vs {green}"
            );
            assert_eq!(tint.x, 1.0);
        }
        // metallic 0.5 at 80°: 53429.
        let half = metallic_tint(0.5, DVec3::splat(0.5), f64::to_radians(80.0).cos());
        assert!(((half.y * 65535.0).round() - 53429.0).abs() <= 2.0);
        assert_eq!(metallic_tint(0.0, DVec3::ZERO, 0.3), DVec3::ONE);
        assert!(metallic_weight(1.0).abs() < 1e-9);
        assert!((metallic_weight(0.0) - 1.0).abs() < 1e-3);
    }

    #[test]
    fn variable_reflection() {
        let r = Reflection {
            min: DVec3::splat(0.2),
            max: DVec3::splat(0.8),
            falloff: 2.0,
            ..Reflection::default()
        };
        // POV-Ray 3.7 at 60° incidence: 0.35 (falloff 2), 0.5 (falloff 1).
        assert!((reflection_amount(&r, 0.5, 1.0).x - 0.35).abs() < 1e-12);
        let r1 = Reflection { falloff: 1.0, ..r };
        assert!((reflection_amount(&r1, 0.5, 1.0).x - 0.5).abs() < 1e-12);
        // Fresnel with ior 1 reflects nothing: only `min` is left.
        assert_eq!(
            reflection_amount(&Reflection { fresnel: true, ..r }, 0.5, 1.0),
            r.min
        );
    }

    #[test]
    fn fresnel_values() {
        // Glass (1.5) at normal incidence: ((1.5 - 1) / (1.5 + 1))² = 0.04.
        assert!((fresnel(1.0, 1.5) - 0.04).abs() < 1e-12);
        // Grazing: everything is reflected.
        assert!((fresnel(0.0, 1.5) - 1.0).abs() < 1e-12);
        // 45° into glass: Rs = 0.0920, Rp = 0.0085 (textbook values).
        let f45 = fresnel(std::f64::consts::FRAC_1_SQRT_2, 1.5);
        assert!((f45 - 0.5 * (0.092_013 + 0.008_466)).abs() < 1e-4, "{f45}");
        // From glass to air beyond the critical angle (41.8°): total reflection.
        assert_eq!(fresnel(f64::to_radians(50.0).cos(), 1.0 / 1.5), 1.0);
        assert!(fresnel(f64::to_radians(30.0).cos(), 1.0 / 1.5) < 1.0);
    }

    #[test]
    fn refraction_follows_snell_and_total_internal_reflection() {
        let d = DVec3::new(
            f64::to_radians(30.0).sin(),
            -f64::to_radians(30.0).cos(),
            0.0,
        );
        let t = refract(d, DVec3::Y, 1.0 / 1.5).expect("refracts");
        let sin_t = t.x;
        assert!((sin_t - 0.5 / 1.5).abs() < 1e-12);
        assert!(t.y < 0.0);
        // Inside glass at 50° (beyond the critical angle): no refracted ray.
        let d = DVec3::new(
            f64::to_radians(50.0).sin(),
            -f64::to_radians(50.0).cos(),
            0.0,
        );
        assert!(refract(d, DVec3::Y, 1.5).is_none());
        assert!(refract(d, DVec3::Y, 1.0 / 1.5).is_some());
    }
}
