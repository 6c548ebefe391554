//! Scattering functions for the path tracer, and how a POV-Ray texture maps onto
//! them (see docs/pathtracing.md for the table):
//!
//! - a Lambertian lobe (albedo = `diffuse` × pigment),
//! - a conductor lobe from `reflection` (tinted by the pigment with `metallic`),
//!   smooth or GGX-rough by `roughness`,
//! - a faint GGX "highlight" lobe carrying the energy of `phong` / `specular`,
//! - a transmission lobe from pigment `filter`/`transmit`: a smooth or rough
//!   dielectric with Fresnel when the interior's `ior` differs from 1, a straight
//!   pass-through otherwise.
//!
//! Directions are unit vectors pointing away from the surface; `wo` towards the
//! viewer, `wi` towards the light.

use super::super::shade::{fresnel, reflection_amount};
use crate::build::SurfaceHit;
use crate::pattern;
use crate::render::sampler::turn;
use crate::scene::{Finish, Interior, Texture};
use glam::DVec3;
use std::f64::consts::{FRAC_1_PI, PI};

/// POV-Ray's default `roughness` (which only sizes highlights there): the path
/// tracer reads it as "smooth".
const DEFAULT_ROUGHNESS: f64 = 0.05;
/// GGX roughness below which a lobe is treated as a perfect mirror.
const SMOOTH_ALPHA: f64 = 1e-3;

/// One surface's scattering, built from the texture at a hit.
#[derive(Clone, Copy, Debug)]
pub struct Bsdf {
    /// Shading normal on the viewer's side.
    pub n: DVec3,
    /// Lambertian albedo.
    pub diffuse: DVec3,
    /// Conductor (mirror) reflectance.
    pub spec: DVec3,
    /// GGX alpha of the conductor lobe (0: a perfect mirror).
    pub spec_alpha: f64,
    /// Reflectance of the highlight lobe.
    pub gloss: DVec3,
    /// GGX alpha of the highlight lobe.
    pub gloss_alpha: f64,
    /// Colour of light passing through (0: opaque).
    pub trans: DVec3,
    /// Relative index of refraction, beyond / viewer's side (1: straight through).
    pub eta: f64,
    /// GGX alpha of the dielectric (0: smooth).
    pub trans_alpha: f64,
    /// Radiance the surface emits (both sides).
    pub emission: DVec3,
    /// The pigment colour times opacity, for the albedo AOV.
    pub albedo: DVec3,
}

/// A sampled direction and what it carries.
#[derive(Clone, Copy, Debug)]
pub struct BsdfSample {
    /// The new direction.
    pub wi: DVec3,
    /// `f · cos / pdf`: what the path's throughput is multiplied by.
    pub weight: DVec3,
    /// Solid-angle density of the whole mixture (for MIS); 0 for delta lobes.
    pub pdf: f64,
    /// From a lobe that cannot be evaluated (mirror, smooth or rough dielectric,
    /// pass-through): emitters hit next count without MIS.
    pub delta: bool,
    /// Straight through the surface (an `ior 1` transparent surface): not a
    /// scattering event.
    pub pass: bool,
}

/// The scattering of a texture that is the same at every point: a solid pigment,
/// no `normal { }`, and a reflection that does not vary with the viewing angle.
/// [`Material::at`] then gives exactly what [`Bsdf::at`] would, without
/// evaluating the texture at each hit.
#[derive(Clone, Copy, Debug)]
pub struct Material {
    /// Everything but the normal and the relative index of refraction.
    template: Bsdf,
    /// The interior's index of refraction.
    ior: f64,
}

impl Material {
    /// The constant scattering of `tex` with interior `interior`, or `None` when it
    /// varies over the surface or with the viewing angle.
    pub fn constant(tex: &Texture, interior: Option<&Interior>) -> Option<Material> {
        let r = &tex.finish.reflection;
        if tex.patterned.is_some() {
            return None;
        }
        let crate::scene::Pattern::Solid(c) = tex.pigment.pattern else {
            return None;
        };
        if tex.normal.is_some() || r.fresnel || r.min != r.max {
            return None;
        }
        let ior = interior.map_or(1.0, |i| i.ior);
        Some(Material {
            template: Bsdf::from_colour(tex, c, ior, DVec3::Z, DVec3::Z, true),
            ior,
        })
    }

    /// The scattering at a hit with unit shading normal `normal` and geometric
    /// normal `geo_normal`, seen from unit direction `wo`: equal to [`Bsdf::at`].
    #[inline]
    pub fn at(&self, normal: DVec3, geo_normal: DVec3, wo: DVec3) -> Bsdf {
        let mut b = self.template;
        b.n = facing(normal, wo);
        let eta = if wo.dot(geo_normal) > 0.0 {
            self.ior
        } else {
            1.0 / self.ior
        };
        b.eta = straight_or(self.ior, eta);
        b
    }
}

/// `n` turned to the side of `wo`.
#[inline]
fn facing(n: DVec3, wo: DVec3) -> DVec3 {
    if n.dot(wo) < 0.0 {
        -n
    } else {
        n
    }
}

/// The relative index stored in a [`Bsdf`]: exactly 1 for an interior of ior 1
/// (light passes straight through), else `eta`.
#[inline]
fn straight_or(ior: f64, eta: f64) -> f64 {
    if (ior - 1.0).abs() < 1e-9 {
        1.0
    } else {
        eta
    }
}

/// GGX alpha for a Blinn exponent `n` (Beckmann-equivalent width).
fn blinn_alpha(n: f64) -> f64 {
    (2.0 / (n.max(0.0) + 2.0)).sqrt().clamp(SMOOTH_ALPHA, 1.0)
}

/// The path tracer's reading of `roughness` for reflection and refraction: POV-Ray's
/// default (0.05) and anything below 0.001 are smooth; other values are GGX alpha.
pub fn ggx_alpha(roughness: f64) -> f64 {
    if roughness == DEFAULT_ROUGHNESS || roughness < SMOOTH_ALPHA {
        0.0
    } else {
        roughness.min(1.0)
    }
}

/// The highlight lobe of `phong`/`specular`: (reflectance, alpha). Its reflectance
/// is the hemispherical energy of POV-Ray's highlight term, `2 ks / (n + 1)` for a
/// Phong exponent n (a Blinn exponent b acts like a Phong exponent b / 4).
pub fn highlight(f: &Finish) -> (f64, f64) {
    let phong = if f.phong > 0.0 {
        2.0 * f.phong / (f.phong_size.max(0.0) + 1.0)
    } else {
        0.0
    };
    let blinn_n = 1.0 / f.roughness.max(1e-6);
    let spec = if f.specular > 0.0 {
        8.0 * f.specular / (blinn_n + 4.0)
    } else {
        0.0
    };
    let alpha = if phong >= spec {
        blinn_alpha(4.0 * f.phong_size)
    } else {
        blinn_alpha(blinn_n)
    };
    ((phong + spec).min(1.0), alpha)
}

impl Bsdf {
    /// The scattering at hit `s`, seen from unit direction `wo` (towards the
    /// viewer). Uses the top texture layer.
    pub fn at(s: &SurfaceHit, wo: DVec3) -> Bsdf {
        Bsdf::of_texture(s, s.texture, wo)
    }

    /// As [`Bsdf::at`] with plain texture `tex` in place of the hit's own (the
    /// texture a patterned texture chose there).
    pub fn of_texture(s: &SurfaceHit, tex: &Texture, wo: DVec3) -> Bsdf {
        let n = match &tex.normal {
            Some(nrm) => pattern::perturb(nrm, facing(s.normal, wo), s.p, s.texture_from_world),
            None => facing(s.normal, wo),
        };
        let tp = s
            .texture_from_world
            .map_or(s.p, |m| m.transform_point3(s.p));
        let c = pattern::evaluate_uv(&tex.pigment, tp, s.uv);
        let ior = s.interior.map_or(1.0, |i| i.ior);
        Bsdf::from_colour(tex, c, ior, n, wo, wo.dot(s.geo_normal) > 0.0)
    }

    /// The scattering of `tex` whose pigment gave `c` at the hit, with interior
    /// `ior`, shading normal `n` (on the viewer's side), viewer direction `wo`, and
    /// whether the viewer is on the geometric normal's side (`entering`).
    fn from_colour(
        tex: &Texture,
        c: crate::scene::Colour,
        ior: f64,
        n: DVec3,
        wo: DVec3,
        entering: bool,
    ) -> Bsdf {
        let f = &tex.finish;
        let colour = c.rgb.max(DVec3::ZERO);
        let tr = (c.filter + c.transmit).clamp(0.0, 1.0);
        let opacity = 1.0 - tr;
        let eta = if entering { ior } else { 1.0 / ior };
        let cos_v = n.dot(wo).max(0.0);
        let r = reflection_amount(&f.reflection, cos_v, eta).clamp(DVec3::ZERO, DVec3::ONE);
        let m = f.reflection.metallic.clamp(0.0, 1.0);
        let spec = r * (DVec3::ONE + m * (colour.min(DVec3::ONE) - DVec3::ONE));
        let (g, gloss_alpha) = highlight(f);
        let gm = f.metallic.clamp(0.0, 1.0);
        let gloss = g * (DVec3::ONE + gm * (colour.min(DVec3::ONE) - DVec3::ONE));
        let keep = (1.0 - spec.max_element() - gloss.max_element()).max(0.0);
        let diffuse = (f.diffuse.max(0.0) * colour * keep).min(DVec3::ONE);
        let trans = if tr > 0.0 {
            (c.filter * colour + DVec3::splat(c.transmit)).clamp(DVec3::ZERO, DVec3::ONE)
        } else {
            DVec3::ZERO
        };
        let alpha = ggx_alpha(f.roughness);
        Bsdf {
            n,
            diffuse: diffuse * opacity,
            spec: spec * opacity,
            spec_alpha: alpha,
            gloss: gloss * opacity,
            gloss_alpha,
            trans,
            eta: straight_or(ior, eta),
            trans_alpha: alpha,
            emission: f.emission * colour * opacity,
            albedo: colour * opacity + trans,
        }
    }

    /// Lobe selection weights: diffuse, conductor, highlight, transmission.
    fn lobe_weights(&self) -> [f64; 4] {
        [
            self.diffuse.max_element(),
            self.spec.max_element(),
            self.gloss.max_element(),
            self.trans.max_element(),
        ]
    }

    /// Whether any lobe can be evaluated for a given pair of directions (so light
    /// sampling helps).
    pub fn has_smooth_lobes(&self) -> bool {
        self.diffuse.max_element() > 0.0
            || (self.spec_alpha > 0.0 && self.spec.max_element() > 0.0)
            || self.gloss.max_element() > 0.0
    }

    /// Whether nothing scatters (black, opaque surface).
    pub fn is_black(&self) -> bool {
        self.lobe_weights().iter().all(|w| *w <= 0.0)
    }

    /// `f(wo, wi) · |cos θi|` of the evaluable lobes, and the mixture's
    /// solid-angle density of sampling `wi`.
    pub fn eval(&self, wo: DVec3, wi: DVec3) -> (DVec3, f64) {
        let w = self.lobe_weights();
        let total: f64 = w.iter().sum();
        if total <= 0.0 {
            return (DVec3::ZERO, 0.0);
        }
        let n = self.n;
        let cos_i = n.dot(wi);
        let cos_o = n.dot(wo);
        if cos_i <= 0.0 || cos_o <= 0.0 {
            return (DVec3::ZERO, 0.0);
        }
        if w[1] <= 0.0 && w[2] <= 0.0 && w[3] <= 0.0 {
            // Lambert alone: the general sum below with its one term (w[0] is
            // the total), the same numbers.
            return (self.diffuse * FRAC_1_PI * cos_i, cos_i * FRAC_1_PI);
        }
        let mut f = DVec3::ZERO;
        let mut pdf = 0.0;
        if w[0] > 0.0 {
            f += self.diffuse * FRAC_1_PI * cos_i;
            pdf += w[0] / total * cos_i * FRAC_1_PI;
        }
        if !((w[1] > 0.0 && self.spec_alpha > 0.0) || (w[2] > 0.0 && self.gloss_alpha > 0.0)) {
            return (f, pdf);
        }
        let frame = Frame::new(n);
        let (lo, li) = (frame.local(wo), frame.local(wi));
        for (k, colour, alpha) in [
            (1, self.spec, self.spec_alpha),
            (2, self.gloss, self.gloss_alpha),
        ] {
            if w[k] > 0.0 && alpha > 0.0 {
                let (v, p) = ggx_reflect_eval(lo, li, alpha);
                f += colour * v;
                pdf += w[k] / total * p;
            }
        }
        (f, pdf)
    }

    /// Samples a direction with the three values `u` (lobe choice, then a point on
    /// the square); `None` when the path ends.
    pub fn sample(&self, wo: DVec3, u: f64, u2: (f64, f64)) -> Option<BsdfSample> {
        let w = self.lobe_weights();
        let total: f64 = w.iter().sum();
        if total <= 0.0 {
            return None;
        }
        let mut x = u * total;
        let mut lobe = 3;
        for (k, wk) in w.iter().enumerate() {
            if x < *wk {
                lobe = k;
                break;
            }
            x -= wk;
        }
        while w[lobe] <= 0.0 {
            lobe -= 1; // rounding pushed past the last non-empty lobe
        }
        let p_lobe = w[lobe] / total;
        let n = self.n;
        let frame = Frame::new(n);
        let lo = frame.local(wo);
        let evaluable = |wi: DVec3| -> Option<BsdfSample> {
            let (f, pdf) = self.eval(wo, wi);
            if pdf <= 0.0 {
                return None;
            }
            Some(BsdfSample {
                wi,
                weight: f / pdf,
                pdf,
                delta: false,
                pass: false,
            })
        };
        match lobe {
            0 if p_lobe == 1.0 => {
                // Lambert alone (most surfaces): `eval` reduced to its one lobe,
                // the same numbers.
                let wi = frame.world(cosine_hemisphere(u2));
                let (cos_i, cos_o) = (n.dot(wi), n.dot(wo));
                if cos_i <= 0.0 || cos_o <= 0.0 {
                    return None;
                }
                let pdf = cos_i * FRAC_1_PI;
                Some(BsdfSample {
                    wi,
                    weight: self.diffuse * FRAC_1_PI * cos_i / pdf,
                    pdf,
                    delta: false,
                    pass: false,
                })
            }
            0 => {
                let li = cosine_hemisphere(u2);
                evaluable(frame.world(li))
            }
            1 | 2 => {
                let (colour, alpha) = if lobe == 1 {
                    (self.spec, self.spec_alpha)
                } else {
                    (self.gloss, self.gloss_alpha)
                };
                if alpha <= 0.0 {
                    let wi = reflect(wo, n);
                    return Some(BsdfSample {
                        wi,
                        weight: colour / p_lobe,
                        pdf: 0.0,
                        delta: true,
                        pass: false,
                    });
                }
                if lo.z <= 0.0 {
                    return None;
                }
                let h = sample_vndf(lo, alpha, u2);
                let li = reflect(lo, h);
                if li.z <= 0.0 {
                    return None;
                }
                evaluable(frame.world(li))
            }
            _ => {
                if self.eta == 1.0 {
                    return Some(BsdfSample {
                        wi: -wo,
                        weight: self.trans / p_lobe,
                        pdf: 0.0,
                        delta: true,
                        pass: true,
                    });
                }
                // Dielectric: a smooth interface, or one microfacet of a rough one
                // (visible-normal sampling; the weight is then G1(wi)).
                let (h, rough) = if self.trans_alpha > 0.0 && lo.z > 0.0 {
                    (
                        frame.world(sample_vndf(lo, self.trans_alpha, u2)),
                        Some(self.trans_alpha),
                    )
                } else {
                    (n, None)
                };
                let cos_o = wo.dot(h);
                if cos_o <= 0.0 {
                    return None;
                }
                let f = fresnel(cos_o, self.eta);
                // Reuse the lobe choice's leftover as the reflect/refract choice.
                let v = (x / w[lobe]).clamp(0.0, 1.0);
                let (wi, tint, reflected) = if v < f {
                    (reflect(wo, h), DVec3::ONE, true)
                } else {
                    match refract(-wo, h, 1.0 / self.eta) {
                        Some(t) => (t, self.trans, false),
                        None => (reflect(wo, h), DVec3::ONE, true),
                    }
                };
                // Rough: reflections must leave above the macro surface,
                // refractions below it.
                if rough.is_some() && (wi.dot(n) > 0.0) != reflected {
                    return None;
                }
                let g = rough.map_or(1.0, |a| {
                    let li = frame.local(wi);
                    g1(DVec3::new(li.x, li.y, li.z.abs()), a)
                });
                Some(BsdfSample {
                    wi,
                    weight: tint * g / p_lobe,
                    pdf: 0.0,
                    delta: true,
                    pass: false,
                })
            }
        }
    }
}

/// Mirror of `v` about unit `n` (both pointing away from the surface).
pub fn reflect(v: DVec3, n: DVec3) -> DVec3 {
    2.0 * v.dot(n) * n - v
}

/// Refraction of unit direction `d` (travelling towards the surface) through unit
/// normal `n` facing against it, `eta` = n_incident / n_transmitted.
fn refract(d: DVec3, n: DVec3, eta: f64) -> Option<DVec3> {
    super::super::shade::refract(d, n, eta)
}

/// An orthonormal frame around a unit normal.
#[derive(Clone, Copy, Debug)]
pub struct Frame {
    t: DVec3,
    b: DVec3,
    n: DVec3,
}

impl Frame {
    /// A frame with `n` as local z.
    pub fn new(n: DVec3) -> Frame {
        let (t, b) = n.any_orthonormal_pair();
        Frame { t, b, n }
    }

    /// World → local.
    pub fn local(&self, v: DVec3) -> DVec3 {
        DVec3::new(v.dot(self.t), v.dot(self.b), v.dot(self.n))
    }

    /// Local → world.
    pub fn world(&self, v: DVec3) -> DVec3 {
        v.x * self.t + v.y * self.b + v.z * self.n
    }
}

/// A cosine-weighted direction about +z from a point on the unit square.
pub fn cosine_hemisphere((u1, u2): (f64, f64)) -> DVec3 {
    let r = u1.sqrt();
    let (c, s) = turn(u2);
    DVec3::new(r * c, r * s, (1.0 - u1).max(0.0).sqrt())
}

/// GGX normal distribution at local half vector `h`.
pub fn ggx_d(h: DVec3, alpha: f64) -> f64 {
    if h.z <= 0.0 {
        return 0.0;
    }
    let a2 = alpha * alpha;
    let c2 = h.z * h.z;
    let d = c2 * (a2 - 1.0) + 1.0;
    a2 / (PI * d * d)
}

/// Smith masking for GGX, local direction `v` (above the surface).
pub fn g1(v: DVec3, alpha: f64) -> f64 {
    if v.z <= 0.0 {
        return 0.0;
    }
    let t2 = (v.x * v.x + v.y * v.y) / (v.z * v.z);
    2.0 / (1.0 + (1.0 + alpha * alpha * t2).sqrt())
}

/// GGX reflection of white light between local `lo` and `li` (both above):
/// `(f · cos θi, pdf of visible-normal sampling)`.
fn ggx_reflect_eval(lo: DVec3, li: DVec3, alpha: f64) -> (f64, f64) {
    let h = (lo + li).normalize_or_zero();
    if h == DVec3::ZERO || lo.z <= 0.0 || li.z <= 0.0 {
        return (0.0, 0.0);
    }
    let d = ggx_d(h, alpha);
    let (go, gi) = (g1(lo, alpha), g1(li, alpha));
    let f_cos = d * go * gi / (4.0 * lo.z);
    let pdf = go * d / (4.0 * lo.z);
    (f_cos, pdf)
}

/// A visible GGX normal for local view `v` (Heitz 2018).
pub fn sample_vndf(v: DVec3, alpha: f64, (u1, u2): (f64, f64)) -> DVec3 {
    let vh = DVec3::new(alpha * v.x, alpha * v.y, v.z).normalize();
    let lensq = vh.x * vh.x + vh.y * vh.y;
    let t1 = if lensq > 0.0 {
        DVec3::new(-vh.y, vh.x, 0.0) / lensq.sqrt()
    } else {
        DVec3::X
    };
    let t2 = vh.cross(t1);
    let r = u1.sqrt();
    let (c, s) = turn(u2);
    let p1 = r * c;
    let mut p2 = r * s;
    let s = 0.5 * (1.0 + vh.z);
    p2 = (1.0 - s) * (1.0 - p1 * p1).max(0.0).sqrt() + s * p2;
    let nh = p1 * t1 + p2 * t2 + (1.0 - p1 * p1 - p2 * p2).max(0.0).sqrt() * vh;
    DVec3::new(alpha * nh.x, alpha * nh.y, nh.z.max(1e-9)).normalize()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn lambert(albedo: f64) -> Bsdf {
        Bsdf {
            n: DVec3::Z,
            diffuse: DVec3::splat(albedo),
            spec: DVec3::ZERO,
            spec_alpha: 0.0,
            gloss: DVec3::ZERO,
            gloss_alpha: 0.0,
            trans: DVec3::ZERO,
            eta: 1.0,
            trans_alpha: 0.0,
            emission: DVec3::ZERO,
            albedo: DVec3::splat(albedo),
        }
    }

    /// A simple deterministic 2D point set for integration tests.
    fn grid(n: usize) -> impl Iterator<Item = (f64, f64, f64)> {
        (0..n * n).map(move |i| {
            let (a, b) = ((i % n) as f64, (i / n) as f64);
            let u = ((i as f64) * 0.618_033_988_75).fract();
            (u, (a + 0.5) / n as f64, (b + 0.5) / n as f64)
        })
    }

    #[test]
    fn sampling_weights_agree_with_eval_over_pdf() {
        let wo = DVec3::new(0.3, -0.2, 0.9).normalize();
        for b in [
            lambert(0.8),
            Bsdf {
                spec: DVec3::splat(0.5),
                spec_alpha: 0.3,
                gloss: DVec3::splat(0.1),
                gloss_alpha: 0.2,
                ..lambert(0.3)
            },
        ] {
            for (u, a, c) in grid(20) {
                if let Some(s) = b.sample(wo, u, (a, c)) {
                    let (f, pdf) = b.eval(wo, s.wi);
                    assert!((pdf - s.pdf).abs() < 1e-9 * pdf.max(1.0));
                    assert!((f / pdf - s.weight).length() < 1e-9);
                }
            }
        }
    }

    #[test]
    fn ggx_conductor_albedo_matches_numerical_integration() {
        // Directional albedo of a white GGX conductor (separable Smith masking, as
        // Mitsuba's) at 32° by importance sampling, against ∫ f cos dω computed
        // numerically (single scattering loses energy as roughness grows).
        for (alpha, want) in [(0.05, 0.9967), (0.3, 0.8616), (0.8, 0.4461)] {
            let b = Bsdf {
                spec: DVec3::ONE,
                spec_alpha: alpha,
                ..lambert(0.0)
            };
            let wo = DVec3::new(0.5, 0.0, 0.8).normalize();
            let n = 200;
            let mut sum = 0.0;
            for (u, a, c) in grid(n) {
                if let Some(s) = b.sample(wo, u, (a, c)) {
                    sum += s.weight.x;
                }
            }
            let e = sum / (n * n) as f64;
            assert!((e - want).abs() < 5e-3, "alpha {alpha}: {e} vs {want}");
        }
    }

    #[test]
    fn turn_matches_the_library_sine_and_cosine() {
        for i in 0..=100_000 {
            let u = f64::from(i) / 100_000.0;
            let (c, s) = turn(u);
            // (2πu rounds by up to half an ulp of 2π: 4e-16 near the end.)
            let (ws, wc) = (2.0 * PI * u).sin_cos();
            assert!((c - wc).abs() < 1e-15 && (s - ws).abs() < 1e-15, "{u}");
            assert!((c * c + s * s - 1.0).abs() < 1e-15, "{u}");
        }
        // Sobol values are f32s below 1.
        let below_one = f64::from(1.0f32.next_down());
        assert!((turn(below_one).1 - (2.0 * PI * below_one).sin()).abs() < 1e-15);
    }

    #[test]
    fn vndf_pdf_integrates_to_the_share_of_samples_above_the_horizon() {
        let lo = DVec3::new(0.4, 0.1, 0.7).normalize();
        let alpha = 0.4;
        let n = 400;
        let (mut integral, mut above) = (0.0, 0);
        for (_, a, c) in grid(n) {
            let z = a;
            let r = (1.0 - z * z).sqrt();
            let phi = 2.0 * PI * c;
            let li = DVec3::new(r * phi.cos(), r * phi.sin(), z);
            integral += ggx_reflect_eval(lo, li, alpha).1 * 2.0 * PI;
            if reflect(lo, sample_vndf(lo, alpha, (a, c))).z > 0.0 {
                above += 1;
            }
        }
        let integral = integral / (n * n) as f64;
        let share = f64::from(above) / (n * n) as f64;
        assert!((integral - share).abs() < 5e-3, "{integral} vs {share}");
    }

    #[test]
    fn smooth_glass_splits_by_fresnel() {
        let b = Bsdf {
            trans: DVec3::ONE,
            eta: 1.5,
            ..lambert(0.0)
        };
        let wo = DVec3::Z;
        let (mut refl, mut n) = (0, 0);
        for (u, a, c) in grid(100) {
            let s = b.sample(wo, u, (a, c)).expect("sample");
            assert!(s.delta);
            if s.wi.z > 0.0 {
                refl += 1;
            }
            n += 1;
        }
        let share = f64::from(refl) / f64::from(n);
        assert!((share - 0.04).abs() < 0.01, "{share}");
    }

    #[test]
    fn roughness_mapping() {
        assert_eq!(ggx_alpha(0.05), 0.0);
        assert_eq!(ggx_alpha(0.0001), 0.0);
        assert_eq!(ggx_alpha(0.2), 0.2);
        let f = Finish {
            phong: 1.0,
            phong_size: 40.0,
            ..Finish::default()
        };
        let (w, a) = highlight(&f);
        assert!((w - 2.0 / 41.0).abs() < 1e-12);
        assert!(a > 0.1 && a < 0.2, "{a}");
        assert_eq!(highlight(&Finish::default()).0, 0.0);
    }
}
