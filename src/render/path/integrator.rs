//! The light transport: unidirectional path tracing with next-event estimation
//! (every light source, plus one emitter chosen by power), multiple importance
//! sampling (power heuristic) between emitter sampling and BSDF sampling, and
//! Russian roulette.

use super::bsdf::{Bsdf, Material};
use super::emitters::Emitters;
use super::environment::Environment;
use super::lights;
use crate::build::{Bvh, Hit, PrimShape, Ray, RayKind, World};
use crate::render::{sky, RayStats, Sampler};
use glam::DVec3;

/// Bounces after which Russian roulette may end a path.
const ROULETTE_AFTER: u32 = 5;

/// A world prepared for path tracing.
pub struct PathScene<'a> {
    /// The world.
    pub world: &'a World,
    /// Its emitting surfaces.
    pub emitters: Emitters,
    /// Longest path in segments (1: only what the camera sees directly).
    pub max_depth: u32,
    /// Whether any surface may let shadow rays through.
    pub clear: bool,
    /// The environment as a sampled light (`None`: black or uniform).
    pub env: Option<Environment>,
    /// Per primitive: its scattering when that is the same all over it (see
    /// [`Material`]), so hits need not evaluate the texture.
    pub materials: Vec<Option<Material>>,
    /// Per primitive: the unit normal of a triangle kept in world space (as
    /// [`World::surface`] computes it), so its hits skip that query.
    pub flat_normals: Vec<Option<DVec3>>,
    /// The world's bounded primitives as a [`Bvh::flat`] list, which this
    /// renderer's scattered rays walk faster than the world's tree when the
    /// world is small enough for one (else `None`: the tree).
    pub flat: Option<Bvh>,
}

impl<'a> PathScene<'a> {
    /// Prepares `world`.
    pub fn new(world: &'a World, max_depth: u32) -> PathScene<'a> {
        let emitters = Emitters::new(world);
        let materials = world
            .primitives
            .iter()
            .map(|p| {
                let own_textures = match &p.shape {
                    PrimShape::Csg(_) => true,
                    PrimShape::Mesh(m) => !m.data.textures.is_empty(),
                    _ => false,
                };
                if own_textures || emitters.is_looks_like(&p.texture) {
                    return None;
                }
                Material::constant(&p.texture, p.interior.as_deref())
            })
            .collect();
        let flat_normals = world
            .primitives
            .iter()
            .map(|p| match (&p.shape, &p.transform) {
                (PrimShape::Triangle { e1, e2, .. }, None) => Some(e1.cross(*e2).normalize()),
                _ => None,
            })
            .collect();
        PathScene {
            flat: world.flat_bvh(),
            world,
            emitters,
            materials,
            flat_normals,
            max_depth: max_depth.max(1),
            clear: world.transparent,
            env: Environment::new(world),
        }
    }
}

impl PathScene<'_> {
    /// The nearest hit in `(t_min, t_max)` among primitives `kind` can see
    /// ([`World::intersect`], through [`PathScene::flat`] when there is one).
    #[inline]
    pub fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64, kind: RayKind) -> Option<Hit> {
        let bvh = self.flat.as_ref().unwrap_or(&self.world.bvh);
        self.world.intersect_among(bvh, ray, t_min, t_max, kind)
    }

    /// Whether a shadow-casting primitive lies on `ray` within `(t_min, t_max)`
    /// ([`World::occluded`], through [`PathScene::flat`] when there is one).
    #[inline]
    pub fn occluded(&self, ray: &Ray, t_min: f64, t_max: f64) -> bool {
        let bvh = self.flat.as_ref().unwrap_or(&self.world.bvh);
        self.world.occluded_among(bvh, ray, t_min, t_max)
    }
}

/// One camera sample's result.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct PathSample {
    /// Light arriving along the camera ray.
    pub radiance: DVec3,
    /// Albedo of the first surface seen (the background where nothing is hit).
    pub albedo: DVec3,
    /// Shading normal of the first surface seen (zero where nothing is hit).
    pub normal: DVec3,
}

/// Power heuristic weight of a strategy with density `a` against one with `b`.
fn power(a: f64, b: f64) -> f64 {
    let (a2, b2) = (a * a, b * b);
    if a2 + b2 > 0.0 {
        a2 / (a2 + b2)
    } else {
        0.0
    }
}

/// Light arriving along `ray` (a camera ray), its random numbers from `sampler`.
pub fn radiance(
    sc: &PathScene,
    ray: Ray,
    sampler: &mut Sampler,
    stats: &mut RayStats,
) -> PathSample {
    let world = sc.world;
    let mut out = PathSample::default();
    let mut ray = Ray::new(ray.origin, ray.dir.normalize());
    let mut t_min = 0.0;
    let mut kind = RayKind::Camera;
    let mut beta = DVec3::ONE;
    // Segments so far, counting the one being traced.
    let mut depth = 1;
    // The last scattering: whether it was a delta lobe, its pdf, its position.
    let mut prev_delta = true;
    let mut prev_pdf = 0.0;
    let mut prev_p = ray.origin;
    let mut first = true;
    loop {
        let Some(hit) = sc.intersect(&ray, t_min, f64::INFINITY, kind) else {
            let env = sky(world, ray.dir);
            let w = match &sc.env {
                Some(e) if !prev_delta => power(prev_pdf, e.pdf(ray.dir)),
                _ => 1.0,
            };
            out.radiance += beta * w * env;
            if first {
                out.albedo = env;
            }
            break;
        };
        let wo = -ray.dir;
        let material = &sc.materials[hit.prim as usize];
        let (p, geo_normal);
        let bsdf = match (material, sc.flat_normals[hit.prim as usize]) {
            // A plain triangle: the point and normal without the general
            // surface query (the same numbers).
            (Some(m), Some(n)) => {
                p = ray.at(hit.t);
                geo_normal = n;
                m.at(n, n, wo)
            }
            _ => {
                let s = world.surface(&ray, &hit);
                if material.is_none() && sc.emitters.is_looks_like(s.texture) {
                    // The visible stand-in of a light source: seen directly or in a
                    // mirror it shows as in the classic renderer; the light itself
                    // does the lighting, so it neither reflects nor emits for other
                    // paths.
                    if prev_delta {
                        let tp = s
                            .texture_from_world
                            .map_or(s.p, |m| m.transform_point3(s.p));
                        crate::pattern::slope::set_surface_normal_facing(s.normal, ray.dir);
                        let tex = crate::pattern::plain_at(s.texture, tp, 0.5);
                        let c = crate::pattern::evaluate_uv(&tex.pigment, tp, s.uv);
                        let glow = (tex.finish.ambient * world.global.ambient_light
                            + tex.finish.emission)
                            * c.rgb
                            * (1.0 - c.filter - c.transmit).max(0.0);
                        out.radiance += beta * glow;
                        if first {
                            out.albedo = c.rgb;
                            out.normal = s.normal;
                        }
                    }
                    break;
                }
                p = s.p;
                geo_normal = s.geo_normal;
                match material {
                    Some(m) => m.at(s.normal, s.geo_normal, wo),
                    // A patterned texture: one of the textures its pattern shows
                    // here, picked by their blend weights (one more sample value).
                    None if s.texture.patterned.is_some() => {
                        let tp = s
                            .texture_from_world
                            .map_or(s.p, |m| m.transform_point3(s.p));
                        crate::pattern::slope::set_surface_normal_facing(s.normal, ray.dir);
                        let tex = crate::pattern::plain_at(s.texture, tp, sampler.next_f64());
                        Bsdf::of_texture(&s, tex, wo)
                    }
                    None => Bsdf::at(&s, wo),
                }
            }
        };
        if first {
            out.albedo = bsdf.albedo;
            out.normal = bsdf.n;
        }
        // Emission found by BSDF sampling (or seen directly).
        if bsdf.emission.max_element() > 0.0 {
            let w = if prev_delta {
                1.0
            } else {
                let pa = sc.emitters.pdf_area(world, hit.prim, hit.sub, p, prev_p);
                if pa > 0.0 {
                    let d2 = (p - prev_p).length_squared();
                    let cos = geo_normal.dot(wo).abs().max(1e-12);
                    power(prev_pdf, pa * d2 / cos)
                } else {
                    1.0
                }
            };
            out.radiance += beta * w * bsdf.emission;
        }
        if depth >= sc.max_depth || bsdf.is_black() {
            break;
        }
        // Next-event estimation.
        if bsdf.has_smooth_lobes() {
            let flags = &world.primitives[hit.prim as usize].flags;
            for (index, light) in world.lights.iter().enumerate() {
                let u = sampler.next_2d();
                if !light.reaches(flags) {
                    continue;
                }
                let Some(mut ls) = lights::sample(light, p, u) else {
                    continue;
                };
                // `projected_through`: masked as in the classic renderer.
                match crate::render::lights::beyond_mask(world, index, p, ls.wi, ls.dist) {
                    Some(None) => continue,
                    Some(Some(rest)) if !light.shadowless => ls.dist = rest,
                    _ => {}
                }
                let (f, _) = bsdf.eval(wo, ls.wi);
                if f.max_element() <= 0.0 {
                    continue;
                }
                let vis = if light.shadowless {
                    DVec3::ONE
                } else {
                    lights::transmittance(sc, p, geo_normal, ls.wi, ls.dist, &mut stats.shadow)
                };
                out.radiance += beta * f * ls.li * vis;
            }
            if let Some(env) = &sc.env {
                let (wi, pdf_e) = env.sample(sampler.next_2d());
                let (f, pdf_b) = bsdf.eval(wo, wi);
                if f.max_element() > 0.0 && pdf_e > 0.0 {
                    let vis = lights::transmittance(
                        sc,
                        p,
                        geo_normal,
                        wi,
                        f64::INFINITY,
                        &mut stats.shadow,
                    );
                    if vis.max_element() > 0.0 {
                        out.radiance +=
                            beta * f * sky(world, wi) * vis * power(pdf_e, pdf_b) / pdf_e;
                    }
                }
            }
            if !sc.emitters.is_empty() {
                let pick = sampler.next_f64();
                let u = sampler.next_2d();
                if let Some(ep) = sc.emitters.sample(world, p, pick, u) {
                    let to = ep.p - p;
                    let d2 = to.length_squared();
                    let dist = d2.sqrt();
                    let wi = to / dist;
                    let cos_l = ep.n.dot(wi).abs();
                    if cos_l > 1e-12 && ep.radiance.max_element() > 0.0 && dist.is_finite() {
                        let (f, pdf_b) = bsdf.eval(wo, wi);
                        if f.max_element() > 0.0 {
                            let pdf_l = ep.pdf_area * d2 / cos_l;
                            // Stop short of the emitter so it does not hide itself.
                            let reach = dist * (1.0 - 1e-7) - crate::build::surface_offset(ep.p);
                            let vis = lights::transmittance(
                                sc,
                                p,
                                geo_normal,
                                wi,
                                reach,
                                &mut stats.shadow,
                            );
                            if vis.max_element() > 0.0 {
                                out.radiance +=
                                    beta * f * ep.radiance * vis * power(pdf_l, pdf_b) / pdf_l;
                            }
                        }
                    }
                }
            } else {
                // Keep the dimensions of later bounces in place.
                sampler.next_f64();
                sampler.next_2d();
            }
        }
        // Continue the path.
        let u = sampler.next_f64();
        let u2 = sampler.next_2d();
        let Some(bs) = bsdf.sample(wo, u, u2) else {
            break;
        };
        beta *= bs.weight;
        if !beta.is_finite() || beta.max_element() <= 0.0 {
            break;
        }
        if !bs.pass {
            first = false;
            prev_delta = bs.delta;
            prev_pdf = bs.pdf;
            prev_p = p;
            kind = RayKind::Reflected;
        }
        if depth >= ROULETTE_AFTER {
            let q = beta.max_element().min(0.95);
            if sampler.next_f64() >= q {
                break;
            }
            beta /= q;
        }
        let (next, eps) = Ray::secondary(p, geo_normal, bs.wi);
        // Through the surface (refraction, translucency, pass-through) or back
        // from it.
        if bs.wi.dot(geo_normal) * wo.dot(geo_normal) < 0.0 {
            stats.transmitted += 1;
        } else {
            stats.reflected += 1;
        }
        ray = next;
        t_min = eps;
        depth += 1;
    }
    out
}
