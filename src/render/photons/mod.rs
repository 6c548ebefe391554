//! Photon mapping (POV-Ray 3.7's caustics): before the render, every light
//! shoots photons at every `photons { target }` object; photons those objects
//! reflect or refract are stored where they land, and the shading of a
//! surface adds the light of the photons near the point (see [`PhotonMap`]).
//!
//! Photon light, as measured on POV-Ray 3.7 (mirror and lens scenes, see
//! docs/language.md): a photon carries the light's colour times the solid
//! angle it was shot into, and where it lands that is multiplied by the
//! square of the distance it travelled, so a mirror sends on the light's full
//! colour at any distance (POV-Ray's lights do not fade with distance) and
//! only focusing or spreading by curved surfaces changes it; a flat mirror at
//! 45° lights the floor with the light's colour times the cosine, as a light
//! would. Parallel and cylinder lights shoot parallel photons, each carrying
//! the colour times the area it stands for.
//!
//! Deterministic: photon `i` of (light, target) pair `k` takes its jitter from
//! a hash of (seed, k, i), and photons are stored in the order of (k, i),
//! whatever the threads.

mod map;

pub use map::{Photon, PhotonMap};

use super::ior::{self, IorStack};
use super::lights::{cylinder_attenuation, fade, spot_attenuation};
use super::sampler::mix;
use super::shade::{bend, interior_fade, metallic_tint, reflection_amount, surface_filter};
use crate::build::{Ray, RayKind, World};
use crate::pattern;
use crate::scene::{Interior, Light, LightKind, PhotonDensity};
use glam::DVec3;
use rayon::prelude::*;

/// Most photons one render shoots: denser settings are thinned to this (each
/// photon then carries more light, so the picture keeps its brightness).
pub const MAX_SHOT: u64 = 20_000_000;

/// Most segments one shot photon is followed along (its reflections and
/// refractions together): glass that reflects and passes almost all light
/// both (no `conserve_energy`) would otherwise split without end.
const MAX_SEGMENTS: u64 = 1024;

/// Photons shot at one target from one light.
#[derive(Clone, Copy, Debug)]
struct Beam {
    /// Index of the light in the world.
    light: usize,
    /// Index of the target primitive.
    target: u32,
    /// Centre and radius of the target's bounding sphere.
    centre: DVec3,
    radius: f64,
    /// The target's spacing multiplier.
    multiplier: f64,
}

/// What shooting found.
#[derive(Clone, Debug, Default)]
pub struct Shot {
    /// The stored photons.
    pub map: PhotonMap,
    /// Photons shot from the lights.
    pub shot: u64,
    /// The spacing used (the one given, or the one `count` asked for).
    pub spacing: f64,
}

/// How one beam is shot: from a point (over a cone or the whole sphere) or
/// parallel (over a disc).
#[derive(Clone, Copy, Debug)]
enum Pattern {
    /// From `origin`, `n` directions within `cos_max` of `axis`, each of
    /// solid angle `omega`.
    Cone {
        origin: DVec3,
        axis: DVec3,
        cos_max: f64,
        n: u64,
        omega: f64,
        step: f64,
    },
    /// Along `dir`, `n` photons over the disc of `radius` round `centre`
    /// (moved back to the light's plane), each standing for `area`.
    Parallel {
        dir: DVec3,
        centre: DVec3,
        radius: f64,
        plane: DVec3,
        n: u64,
        area: f64,
        step: f64,
    },
}

/// The golden angle, turning each photon of a spiral from the one before.
const GOLDEN: f64 = 2.399_963_229_728_653;

/// Shoots the photons of `world` (whose `global.photons` is set) and stores them.
pub fn shoot(world: &World, seed: u64) -> Shot {
    let Some(settings) = world.global.photons else {
        return Shot::default();
    };
    let beams = beams(world);
    let amount = |b: &Beam| -> f64 {
        let light = &world.lights[b.light];
        let m2 = b.multiplier * b.multiplier;
        if shoots_parallel(light) {
            std::f64::consts::PI * b.radius * b.radius / m2
        } else {
            let d = (b.centre - light.location).length();
            let (_, omega) = cone(d, b.radius);
            omega * d * d / m2
        }
    };
    // Photons of a beam: amount / spacing²; `count` sets the spacing.
    let total: f64 = beams.iter().map(amount).sum();
    let mut spacing = match settings.density {
        PhotonDensity::Spacing(s) => s,
        PhotonDensity::Count(0) => return Shot::default(),
        PhotonDensity::Count(n) => (total / n as f64).sqrt(),
    };
    if total / (spacing * spacing) > MAX_SHOT as f64 {
        spacing = (total / MAX_SHOT as f64).sqrt();
    }
    if !(spacing > 0.0 && spacing.is_finite()) {
        return Shot::default();
    }
    let max_level = settings
        .max_trace_level
        .unwrap_or(world.global.max_trace_level);
    let bailout = settings.adc_bailout.unwrap_or(world.global.adc_bailout);
    let mut photons = Vec::new();
    let mut shot = 0u64;
    for (k, b) in beams.iter().enumerate() {
        let light = &world.lights[b.light];
        let s = spacing * b.multiplier;
        let pattern = if shoots_parallel(light) {
            let dir = (light.point_at - light.location).normalize();
            let n = (std::f64::consts::PI * b.radius * b.radius / (s * s)).ceil() as u64;
            Pattern::Parallel {
                dir,
                centre: b.centre,
                radius: b.radius,
                plane: light.location,
                n,
                area: std::f64::consts::PI * b.radius * b.radius / n as f64,
                step: s,
            }
        } else {
            let d = (b.centre - light.location).length();
            let (cos_max, omega) = cone(d, b.radius);
            let step = s / d.max(1e-9);
            let n = (omega / (step * step)).ceil().max(1.0) as u64;
            Pattern::Cone {
                origin: light.location,
                axis: if d > 0.0 {
                    (b.centre - light.location) / d
                } else {
                    DVec3::Y
                },
                cos_max,
                n,
                omega: omega / n as f64,
                step,
            }
        };
        let n = match pattern {
            Pattern::Cone { n, .. } | Pattern::Parallel { n, .. } => n,
        };
        shot += n;
        let tracer = Tracer {
            world,
            light,
            target: b.target,
            max_level,
            bailout,
            key: mix(seed ^ mix(k as u64 + 1)),
        };
        // Chunks in order, so the photons are stored in the order they were
        // shot whatever the threads.
        const CHUNK: u64 = 4096;
        let chunks: Vec<u64> = (0..n.div_ceil(CHUNK)).collect();
        let found: Vec<Vec<Photon>> = chunks
            .par_iter()
            .map(|&c| {
                let mut out = Vec::new();
                for i in c * CHUNK..((c + 1) * CHUNK).min(n) {
                    tracer.photon(&pattern, i, settings.jitter, &mut out);
                }
                out
            })
            .collect();
        for f in found {
            photons.extend(f);
        }
    }
    let radius = settings.radius.unwrap_or_else(|| {
        // At the spacing photons reach their targets, `gather.1` photons
        // cover a disc of this radius.
        let m = beams
            .iter()
            .map(|b| b.multiplier)
            .fold(f64::INFINITY, f64::min);
        (f64::from(settings.gather_max) / std::f64::consts::PI).sqrt() * spacing * m.min(1e9)
    }) * settings.radius_multiplier;
    Shot {
        map: PhotonMap::new(photons, radius, (settings.gather_min, settings.gather_max)),
        shot,
        spacing,
    }
}

/// Whether `light` shoots parallel photons (parallel and cylinder lights).
fn shoots_parallel(light: &Light) -> bool {
    light.parallel || matches!(light.kind, LightKind::Cylinder(_))
}

/// The cone from a point at distance `d` from the centre of a sphere of
/// `radius` that holds the sphere: its cosine limit and solid angle (the
/// whole sphere of directions from inside).
fn cone(d: f64, radius: f64) -> (f64, f64) {
    if d <= radius {
        return (-1.0, 4.0 * std::f64::consts::PI);
    }
    let sin = radius / d;
    let cos = (1.0 - sin * sin).max(0.0).sqrt();
    (cos, 2.0 * std::f64::consts::PI * (1.0 - cos))
}

/// Every (light, target) pair that shoots: lights that let their photons
/// reflect or refract, bounded targets (a plane has no bounding sphere to
/// aim at).
fn beams(world: &World) -> Vec<Beam> {
    let mut out = Vec::new();
    for (li, light) in world.lights.iter().enumerate() {
        if !(light.photons.reflection || light.photons.refraction) {
            continue;
        }
        for (pi, prim) in world.primitives.iter().enumerate() {
            let ph = prim.flags.photons;
            let (Some(m), Some(bounds)) = (ph.target, prim.bounds) else {
                continue;
            };
            if !(ph.reflection || ph.refraction) || !light.reaches(&prim.flags) {
                continue;
            }
            out.push(Beam {
                light: li,
                target: pi as u32,
                centre: bounds.centroid(),
                radius: (bounds.max - bounds.min).length() / 2.0,
                multiplier: f64::from(m),
            });
        }
    }
    out
}

/// Traces the photons of one beam.
struct Tracer<'a> {
    world: &'a World,
    light: &'a Light,
    target: u32,
    max_level: u32,
    bailout: f64,
    /// Hash key of the beam (with the seed).
    key: u64,
}

/// A photon on its way.
struct InFlight<'a> {
    ray: Ray,
    t_min: f64,
    power: DVec3,
    /// Share of the light's colour it still carries (for `adc_bailout`).
    weight: f64,
    /// Distance travelled so far.
    travelled: f64,
    /// Reflections and refractions so far.
    level: u32,
    /// The interior it travels in since its last refraction into an object.
    inside: Option<(u32, &'a Interior)>,
    /// The interiors it is in (for indices of refraction).
    iors: IorStack,
}

impl<'a> Tracer<'a> {
    /// Two numbers in [0, 1) for photon `i`, the `j`-th pair.
    fn random(&self, i: u64, j: u64) -> (f64, f64) {
        let h = mix(self.key ^ mix(i.wrapping_mul(4).wrapping_add(j)));
        let unit = |x: u64| (x >> 11) as f64 * (1.0 / (1u64 << 53) as f64);
        (unit(h), unit(mix(h)))
    }

    /// Shoots photon `i` of `pattern`, adding what it stores to `out`.
    fn photon(&self, pattern: &Pattern, i: u64, jitter: f64, out: &mut Vec<Photon>) {
        let (ja, jb) = self.random(i, 0);
        let (ja, jb) = (jitter * (ja - 0.5), jitter * (jb - 0.5));
        let light = self.light;
        let (origin, dir, power) = match *pattern {
            Pattern::Cone {
                origin,
                axis,
                cos_max,
                n,
                omega,
                step,
            } => {
                // A spiral of equal-area steps from the axis outwards.
                let z = 1.0 - (i as f64 + 0.5) / n as f64 * (1.0 - cos_max);
                let phi = i as f64 * GOLDEN;
                let r = (1.0 - z * z).max(0.0).sqrt();
                let (u, v) = axis.any_orthonormal_pair();
                let d = (u * (r * phi.cos()) + v * (r * phi.sin()) + axis * z).normalize();
                let (du, dv) = d.any_orthonormal_pair();
                let d = (d + (du * ja + dv * jb) * step).normalize();
                (origin, d, light.colour * omega)
            }
            Pattern::Parallel {
                dir,
                centre,
                radius,
                plane,
                n,
                area,
                step,
            } => {
                let r = radius * ((i as f64 + 0.5) / n as f64).sqrt();
                let phi = i as f64 * GOLDEN;
                let (u, v) = dir.any_orthonormal_pair();
                let at = centre + u * (r * phi.cos() + ja * step) + v * (r * phi.sin() + jb * step);
                // Back to the plane through the light, facing along `dir`.
                let origin = at + dir * (plane - at).dot(dir);
                (origin, dir, light.colour * area)
            }
        };
        // Spot and cylinder beams as the light shines them.
        let power = power
            * match light.kind {
                LightKind::Point => 1.0,
                LightKind::Spot(beam) => {
                    let axis = (light.point_at - light.location).normalize();
                    spot_attenuation(&beam, dir.dot(axis))
                }
                LightKind::Cylinder(beam) => {
                    let axis = (light.point_at - light.location).normalize();
                    cylinder_attenuation(&beam, axis, origin - light.location)
                }
            };
        if power.max_element() <= 0.0 || !dir.is_finite() {
            return;
        }
        let mut stack = vec![InFlight {
            ray: Ray::new(origin, dir),
            t_min: 0.0,
            power,
            weight: 1.0,
            travelled: 0.0,
            level: 0,
            inside: None,
            iors: IorStack::default(),
        }];
        let mut splits = 0u64;
        while let Some(ph) = stack.pop() {
            splits += 1;
            if splits > MAX_SEGMENTS {
                // A pathological tree (surfaces that reflect and pass nearly
                // all light both): the rest of it is dropped.
                break;
            }
            self.follow(ph, i, splits, out, &mut stack);
        }
    }

    /// Follows one photon to its next surface: stores it there if it has
    /// been reflected or refracted and the surface collects; pushes what it
    /// reflects and refracts onto `stack`.
    fn follow(
        &self,
        mut ph: InFlight<'a>,
        i: u64,
        split: u64,
        out: &mut Vec<Photon>,
        stack: &mut Vec<InFlight<'a>>,
    ) {
        let world = self.world;
        let light = self.light;
        // No_image objects are invisible to photons too (measured on POV-Ray
        // 3.7: a no_image mirror reflects none).
        let Some(hit) = world.intersect(&ph.ray, ph.t_min, f64::INFINITY, RayKind::Camera) else {
            return;
        };
        let prim = &world.primitives[hit.prim as usize];
        let flags = prim.flags.photons;
        let d = ph.ray.dir;
        let p = ph.ray.at(hit.t);
        let first = ph.level == 0;
        if first && hit.prim != self.target {
            if flags.pass_through {
                // On its way to the target: through, unaffected.
                stack.push(InFlight {
                    t_min: hit.t + crate::build::surface_offset(p),
                    ..ph
                });
            }
            // Another target is shot at on its own (its beam covers this
            // direction); anything else stops the photon before it is a
            // caustic one.
            return;
        }
        // Measured along the ray from where it was shot or last scattered.
        ph.travelled += hit.t;
        if let Some((at, interior)) = ph.inside {
            if at == hit.prim && interior.fade_distance > 0.0 && interior.fade_power > 0.0 {
                let a = interior_fade(hit.t, interior.fade_distance, interior.fade_power);
                ph.power *= DVec3::splat(a) + (1.0 - a) * interior.fade_colour;
            }
        }
        if !first && !flags.no_collect {
            let scale = if shoots_parallel(light) {
                1.0
            } else {
                ph.travelled * ph.travelled
            };
            let e = ph.power * scale * fade(light.fade_distance, light.fade_power, ph.travelled);
            if e.max_element() > 0.0 && e.is_finite() {
                out.push(Photon {
                    p: p.as_vec3(),
                    dir: d.as_vec3(),
                    power: e.as_vec3(),
                });
            }
        }
        let reflects = flags.reflection && light.photons.reflection;
        let refracts = flags.refraction && light.photons.refraction;
        if ph.level >= self.max_level || !(reflects || refracts) {
            return;
        }
        let s = world.surface(&ph.ray, &hit);
        let tp = s
            .texture_from_world
            .map_or(s.p, |m| m.transform_point3(s.p));
        pattern::slope::set_surface_normal_facing(s.normal, ph.ray.dir);
        let (u, _) = self.random(i, 1 + split);
        let tex = pattern::plain_at(s.texture, tp, u);
        let facing = |n: DVec3| if n.dot(d) > 0.0 { -n } else { n };
        let n = match &tex.normal {
            Some(nrm) => pattern::perturb(nrm, facing(s.normal), s.p, s.texture_from_world),
            None => facing(s.normal),
        };
        let ior = s.interior.map_or(1.0, |i| i.ior);
        let entering = ph.iors.entering(world, &s, d);
        let key = ior::key(&s);
        let (n_near, n_far) = ph.iors.sides(key, ior, entering);
        let eta_view = n_far / n_near;
        let mut onward = |dir: DVec3, share: DVec3, inside, iors| {
            let weight = ph.weight * share.max_element();
            if weight < self.bailout || weight <= 0.0 {
                return;
            }
            let (ray, eps) = Ray::secondary(s.p, s.geo_normal, dir);
            stack.push(InFlight {
                ray,
                t_min: eps,
                power: ph.power * share,
                weight,
                travelled: ph.travelled,
                level: ph.level + 1,
                inside,
                iors,
            });
        };
        // What reflection takes from the light passing through, with
        // `conserve_energy` (as for camera rays).
        let mut kept = DVec3::ONE;
        let r = &tex.finish.reflection;
        if r.min != DVec3::ZERO || r.max != DVec3::ZERO {
            let colour = pattern::evaluate_uv(&tex.pigment, tp, s.uv).rgb;
            let cos_v = -n.dot(d);
            let amount =
                reflection_amount(r, cos_v, eta_view) * metallic_tint(r.metallic, colour, cos_v);
            if tex.finish.conserve_energy {
                kept = (DVec3::ONE - amount).max(DVec3::ZERO);
            }
            if reflects {
                onward(d - 2.0 * d.dot(n) * n, amount, ph.inside, ph.iors);
            }
        }
        if refracts {
            let through = surface_filter(&s) * kept;
            if through.max_element() > 0.0 {
                let (dir, kind) = bend(d, n, n_near / n_far);
                if kind == RayKind::Reflected {
                    // Total internal reflection: all of it, still inside.
                    onward(dir, DVec3::ONE, ph.inside, ph.iors);
                } else {
                    let mut iors = ph.iors;
                    let inside = if entering {
                        iors.enter(key, ior);
                        s.interior.map(|i| (hit.prim, &**i))
                    } else {
                        iors.leave(key);
                        None
                    };
                    onward(dir, through, inside, iors);
                }
            }
        }
    }
}
