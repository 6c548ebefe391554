//! Participating media along rays, as POV-Ray 3.7 defines it.
//!
//! A ray carries the list of objects it is inside ([`MediaPath`]): camera rays
//! start with the objects around the camera, a ray passing through a surface into
//! an object adds it, one leaving removes it. Over each stretch of a ray, the
//! media of the interiors it is in, then the atmospheric media, then fog act on
//! the colour arriving from the far end — only while every object the ray is in
//! is `hollow` (as in POV-Ray: a solid object keeps media and fog out).
//!
//! Along a stretch the media's coefficients (each times its density, several media
//! adding up) are sampled at points: `emission` and light scattered from the light
//! sources towards the viewer add colour, `absorption + extinction · scattering`
//! dims it. The stretch is cut into intervals (more where spotlight beams and
//! cylinder lights cross it, per `ratio`); method 1 samples intervals at random
//! places, method 2 evenly with jitter (both adding samples up to the most while
//! the variance is above the `confidence`/`variance` bound), method 3 adaptively,
//! halving where neighbouring samples differ by more than `aa_threshold`.
//! Random numbers come from the camera sample's [`Sampler`](super::sampler::Sampler).

use super::lights;
use super::shade::TraceCtx;
use crate::build::{Ray, RayKind, World};
use crate::scene::{Interior, LightKind, Media, ScatteringKind};
use glam::DVec3;
use std::sync::Arc;

/// How far a ray that hits nothing is taken to run through atmospheric media
/// (POV-Ray's largest distance).
pub const MISS_DISTANCE: f64 = 1e7;

/// Most surfaces a shadow ray is followed through for media attenuation.
const MAX_CROSSINGS: usize = 64;

/// What identifies an object a ray is inside: its interior (shared by the parts
/// of a CSG or union) or, for the default interior, the primitive.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Key {
    Interior(usize),
    Primitive(u32),
}

/// One object a ray is inside.
#[derive(Clone, Debug)]
struct Container {
    key: Key,
    interior: Option<Arc<Interior>>,
    hollow: bool,
}

/// The objects a ray is inside, innermost last.
#[derive(Clone, Debug, Default)]
pub struct MediaPath {
    containers: Vec<Container>,
}

impl MediaPath {
    /// The objects around the camera of `world` (none when the world has no media
    /// or fog, which are all this is for).
    pub fn at_camera(world: &World) -> MediaPath {
        let mut path = MediaPath::default();
        for &i in &world.camera_inside {
            let prim = &world.primitives[i as usize];
            path.enter(i, prim.interior.as_ref(), prim.flags.hollow);
        }
        path
    }

    /// Whether every object the ray is in is hollow (true outside all objects).
    pub fn hollow(&self) -> bool {
        self.containers.iter().all(|c| c.hollow)
    }

    /// The ray passes into primitive `prim` with interior `interior`.
    pub fn enter(&mut self, prim: u32, interior: Option<&Arc<Interior>>, hollow: bool) {
        self.containers.push(Container {
            key: key(prim, interior),
            interior: interior.cloned(),
            hollow,
        });
    }

    /// The ray leaves primitive `prim` with interior `interior` (nothing happens
    /// when it was not inside).
    pub fn leave(&mut self, prim: u32, interior: Option<&Arc<Interior>>) {
        let k = key(prim, interior);
        if let Some(i) = self.containers.iter().rposition(|c| c.key == k) {
            self.containers.remove(i);
        }
    }

    /// The media of the interiors the ray is in (when it is hollow).
    fn media(&self) -> Vec<&Media> {
        if !self.hollow() {
            return Vec::new();
        }
        self.containers
            .iter()
            .filter_map(|c| c.interior.as_deref())
            .flat_map(|i| i.media.iter())
            .collect()
    }
}

fn key(prim: u32, interior: Option<&Arc<Interior>>) -> Key {
    match interior {
        Some(i) => Key::Interior(Arc::as_ptr(i) as usize),
        None => Key::Primitive(prim),
    }
}

/// `colour` arriving along `ray` from distance `depth` (in units of `|ray.dir|`;
/// [`super::atmosphere::MISS_DISTANCE`] when nothing was hit), after the media of
/// the objects the ray is in and the atmospheric media.
pub fn along(world: &World, ray: &Ray, depth: f64, colour: DVec3, ctx: &mut TraceCtx) -> DVec3 {
    if !ctx.media.hollow() {
        return colour;
    }
    let len = ray.dir.length();
    if len == 0.0 || !len.is_finite() {
        return colour;
    }
    let dir = ray.dir / len;
    let dist = (depth * len).min(MISS_DISTANCE);
    let mut out = colour;
    let path = ctx.media.clone();
    let inner = path.media();
    if !inner.is_empty() {
        let (t, e) = integrate(world, &inner, ray.origin, dir, dist, false, ctx);
        out = out * t + e;
    }
    if !world.atmosphere.media.is_empty() {
        let outer: Vec<&Media> = world.atmosphere.media.iter().collect();
        let (t, e) = integrate(world, &outer, ray.origin, dir, dist, false, ctx);
        out = out * t + e;
    }
    out
}

/// How much of a light's colour passes the media between `p` and the light, `dist`
/// away along unit `dir`: the media of each object the shadow ray crosses
/// (entering and leaving objects as it meets their surfaces), and with
/// `atmospheric` (the light's `media_attenuation on`) the atmospheric media and
/// fog over the whole way.
pub fn shadow_attenuation(
    world: &World,
    p: DVec3,
    dir: DVec3,
    dist: f64,
    atmospheric: bool,
    ctx: &mut TraceCtx,
) -> DVec3 {
    let dist = dist.min(MISS_DISTANCE);
    let mut through = DVec3::ONE;
    let mut path = ctx.media.clone();
    if world.object_media || atmospheric && !path.containers.is_empty() {
        let ray = Ray::new(p, dir);
        let mut t0 = 0.0;
        for _ in 0..MAX_CROSSINGS {
            let eps = crate::build::surface_offset(ray.at(f64::max(t0, 1e-9)));
            let hit = world.intersect(&ray, t0 + eps, dist, RayKind::Shadow);
            let t1 = hit.map_or(dist, |h| h.t);
            let inner = path.media();
            if !inner.is_empty() && t1 > t0 {
                let here = ray.at(t0);
                through *= integrate(world, &inner, here, dir, t1 - t0, true, ctx).0;
            }
            let Some(h) = hit else { break };
            let s = world.surface(&ray, &h);
            if dir.dot(s.geo_normal) < 0.0 {
                path.enter(s.prim, s.interior, s.flags.hollow);
            } else {
                path.leave(s.prim, s.interior);
            }
            t0 = t1;
            if through.max_element() <= 0.0 {
                return DVec3::ZERO;
            }
        }
    }
    // As in POV-Ray, the atmosphere counts when the shadow ray ends in hollow
    // space (one leaving a solid glass sphere towards the light is dimmed).
    if atmospheric && path.hollow() {
        if !world.atmosphere.media.is_empty() {
            let outer: Vec<&Media> = world.atmosphere.media.iter().collect();
            through *= integrate(world, &outer, p, dir, dist, true, ctx).0;
        }
        // Fog dims the light too (measured in POV-Ray 3.7: a light 800 units
        // away through fog of distance 80 keeps about exp(-10) of its colour).
        for fog in &world.atmosphere.fogs {
            through *= super::atmosphere::fog_pass(fog, p, dir, dist);
        }
    }
    through
}

/// A light's stretch of a ray: where the light can shine into the media.
#[derive(Clone, Copy, Debug)]
struct LitLight {
    index: usize,
    s0: f64,
    s1: f64,
}

/// A piece of the ray between `s0` and `s1`, lit by some light or not.
#[derive(Clone, Copy, Debug)]
struct Interval {
    lit: bool,
    s0: f64,
    s1: f64,
}

/// The running sums of one interval's samples.
#[derive(Clone, Copy, Debug, Default)]
struct Sums {
    /// Sum of the samples' light (emission and scattering, times the interval's
    /// length).
    te: DVec3,
    /// Sum of squares of `te`'s terms (methods 1 and 2).
    te2: DVec3,
    /// Sum of the samples' optical depths over the interval.
    od: DVec3,
    samples: u32,
}

/// What the media `medias` do to light travelling the `dist` from `origin` along
/// unit `dir`: (transmittance, light added). A shadow ray (`shadow`) only needs
/// the transmittance.
fn integrate(
    world: &World,
    medias: &[&Media],
    origin: DVec3,
    dir: DVec3,
    dist: f64,
    shadow: bool,
    ctx: &mut TraceCtx,
) -> (DVec3, DVec3) {
    if medias.is_empty() || dist.is_nan() || dist <= 0.0 {
        return (DVec3::ONE, DVec3::ZERO);
    }
    // The media with the most intervals leads the sampling (the first of equals).
    let mut lead = medias[0];
    for m in medias {
        if m.intervals > lead.intervals {
            lead = m;
        }
    }
    let aa_threshold = medias
        .iter()
        .map(|m| m.aa_threshold)
        .fold(f64::INFINITY, f64::min);
    let use_extinction = medias.iter().any(|m| m.extinction() != DVec3::ZERO);
    let use_scattering = medias
        .iter()
        .any(|m| m.scattering.is_some_and(|s| s.colour != DVec3::ZERO));
    let constant_shadow = shadow
        && medias.iter().all(|m| {
            m.density
                .iter()
                .all(|d| matches!(d.pattern, crate::scene::Pattern::Solid(_)))
        });
    if shadow && !use_extinction {
        return (DVec3::ONE, DVec3::ZERO);
    }
    if !shadow
        && !use_scattering
        && !use_extinction
        && medias.iter().all(|m| m.emission == DVec3::ZERO)
    {
        return (DVec3::ONE, DVec3::ZERO);
    }
    let lights = if shadow || !use_scattering {
        Vec::new()
    } else {
        lit_lights(world, origin, dir, dist)
    };
    let lit = lit_intervals(&lights, dist);
    let mut intervals = sample_intervals(&lit, lead, dist);
    if let Some(first) = intervals.first() {
        if first.s0 > 0.0 {
            intervals.insert(
                0,
                Interval {
                    lit: false,
                    s0: 0.0,
                    s1: first.s0,
                },
            );
        }
    }
    if let Some(last) = intervals.last().copied() {
        if last.s1 < dist {
            intervals.push(Interval {
                lit: false,
                s0: last.s1,
                s1: dist,
            });
        }
    }
    let sampler = Sampling {
        world,
        medias,
        lights: &lights,
        origin,
        dir,
        shadow,
        use_scattering,
    };
    let mut sums = vec![Sums::default(); intervals.len()];
    if lead.method == 3 && !constant_shadow {
        sampler.adaptive(&intervals, &mut sums, lead, aa_threshold, ctx);
    } else {
        sampler.regular(&intervals, &mut sums, lead, constant_shadow, ctx);
    }
    // Each interval's light is dimmed by everything before it.
    let mut od = DVec3::ZERO;
    let mut te = DVec3::ZERO;
    for s in &sums {
        let n = 1.0 / f64::from(s.samples.max(1));
        te += s.te * n * exp(-od);
        od += s.od * n;
    }
    (exp(-od), te)
}

fn exp(v: DVec3) -> DVec3 {
    DVec3::new((v.x).exp(), (v.y).exp(), (v.z).exp())
}

/// The lights that shine into media, with the stretch of the ray (within
/// `0..dist`) each can light: all of it for point and parallel lights, the part
/// inside the cone of a spotlight or the cylinder of a cylinder light.
fn lit_lights(world: &World, origin: DVec3, dir: DVec3, dist: f64) -> Vec<LitLight> {
    let mut out = Vec::new();
    for (index, l) in world.lights.iter().enumerate() {
        if !l.media_interaction {
            continue;
        }
        let axis = (l.point_at - l.location).normalize_or_zero();
        let span = match l.kind {
            LightKind::Point => Some((0.0, dist)),
            LightKind::Spot(b) => {
                let cos = b.falloff.clamp(0.0, 180.0).to_radians().cos();
                let inside = |t: f64| {
                    let v = origin + dir * t - l.location;
                    v.dot(axis) >= cos * v.length()
                };
                let v = origin - l.location;
                let (k1, k2, k3, k4) = (dir.dot(axis), v.dot(axis), v.dot(dir), v.dot(v));
                let c2 = cos * cos;
                let roots = quadratic(k1 * k1 - c2, 2.0 * (k1 * k2 - c2 * k3), k2 * k2 - c2 * k4);
                let plane = (k1 != 0.0).then(|| -k2 / k1);
                stretch(&roots, plane, dist, inside)
            }
            LightKind::Cylinder(b) => {
                let r2 = b.falloff * b.falloff;
                let inside = |t: f64| {
                    let v = origin + dir * t - l.location;
                    let along = v.dot(axis);
                    along >= 0.0 && v.length_squared() - along * along <= r2
                };
                let v = origin - l.location;
                let (k1, k2, k3, k4) = (dir.dot(axis), v.dot(axis), v.dot(dir), v.dot(v));
                let roots = quadratic(1.0 - k1 * k1, 2.0 * (k3 - k1 * k2), k4 - k2 * k2 - r2);
                let plane = (k1 != 0.0).then(|| -k2 / k1);
                stretch(&roots, plane, dist, inside)
            }
        };
        if let Some((s0, s1)) = span {
            if s1 > s0 {
                out.push(LitLight { index, s0, s1 });
            }
        }
    }
    out
}

/// Real roots of `a t² + b t + c = 0`.
fn quadratic(a: f64, b: f64, c: f64) -> Vec<f64> {
    if a.abs() < 1e-12 {
        if b.abs() < 1e-12 {
            return Vec::new();
        }
        return vec![-c / b];
    }
    let d = b * b - 4.0 * a * c;
    if d < 0.0 {
        return Vec::new();
    }
    let q = d.sqrt();
    vec![(-b - q) / (2.0 * a), (-b + q) / (2.0 * a)]
}

/// The smallest stretch of `0..dist` holding every part where `inside` holds,
/// given the places (`roots`, `plane`) where it may change.
fn stretch(
    roots: &[f64],
    plane: Option<f64>,
    dist: f64,
    inside: impl Fn(f64) -> bool,
) -> Option<(f64, f64)> {
    let mut cuts: Vec<f64> = vec![0.0, dist];
    cuts.extend(
        roots
            .iter()
            .chain(plane.iter())
            .copied()
            .filter(|t| t.is_finite() && *t > 0.0 && *t < dist),
    );
    cuts.sort_by(f64::total_cmp);
    let mut span: Option<(f64, f64)> = None;
    for w in cuts.windows(2) {
        if w[1] <= w[0] {
            continue;
        }
        if inside(0.5 * (w[0] + w[1])) {
            span = Some(match span {
                None => (w[0], w[1]),
                Some((a, _)) => (a, w[1]),
            });
        }
    }
    span
}

/// The lit and unlit pieces of `0..dist`: the lights' stretches merged where they
/// overlap (POV-Ray pairs their sorted starts and ends), with unlit gaps.
fn lit_intervals(lights: &[LitLight], dist: f64) -> Vec<Interval> {
    if lights.is_empty() {
        return vec![Interval {
            lit: false,
            s0: 0.0,
            s1: dist,
        }];
    }
    let mut s0: Vec<f64> = lights.iter().map(|l| l.s0).collect();
    let mut s1: Vec<f64> = lights.iter().map(|l| l.s1).collect();
    s0.sort_by(f64::total_cmp);
    s1.sort_by(f64::total_cmp);
    let mut out = Vec::new();
    if s0[0] > 0.0 {
        out.push(Interval {
            lit: false,
            s0: 0.0,
            s1: s0[0],
        });
    }
    out.push(Interval {
        lit: true,
        s0: s0[0],
        s1: s1[0],
    });
    for i in 1..lights.len() {
        let end = out.last().map_or(0.0, |l: &Interval| l.s1);
        if s0[i] > end {
            out.push(Interval {
                lit: false,
                s0: end,
                s1: s0[i],
            });
            out.push(Interval {
                lit: true,
                s0: s0[i],
                s1: s1[i],
            });
        } else if let Some(last) = out.last_mut() {
            last.s1 = last.s1.max(s1[i]);
        }
    }
    let end = out.last().map_or(0.0, |l| l.s1);
    if end < dist {
        out.push(Interval {
            lit: false,
            s0: end,
            s1: dist,
        });
    }
    out
}

/// The intervals sampled: `intervals` of the lead media (at least one per lit or
/// unlit piece), shared out by `ratio` between lit and unlit pieces; a constant
/// unlit media needs one.
fn sample_intervals(lit: &[Interval], lead: &Media, _dist: f64) -> Vec<Interval> {
    let count = (lead.intervals as usize).max(lit.len());
    let mut out = Vec::new();
    if lit.len() == 1 {
        let l = lit[0];
        if !l.lit && lead.density.is_empty() {
            out.push(l);
        } else {
            let delta = (l.s1 - l.s0) / count as f64;
            for i in 0..count {
                out.push(Interval {
                    lit: l.lit,
                    s0: l.s0 + delta * i as f64,
                    s1: l.s0 + delta * (i + 1) as f64,
                });
            }
        }
        return out;
    }
    let weight = |l: &Interval| if l.lit { lead.ratio } else { 1.0 - lead.ratio };
    let sum: f64 = lit.iter().map(weight).sum();
    let mut remaining = count;
    for (i, l) in lit.iter().enumerate() {
        let share = if sum > 0.0 { weight(l) / sum } else { 0.0 };
        let mut n = (share * count as f64) as usize + 1;
        let room = (remaining + i + 1).saturating_sub(lit.len()).max(1);
        n = n.min(room);
        let delta = (l.s1 - l.s0) / n as f64;
        for j in 0..n {
            out.push(Interval {
                lit: l.lit,
                s0: l.s0 + delta * j as f64,
                s1: l.s0 + delta * (j + 1) as f64,
            });
        }
        remaining = remaining.saturating_sub(n);
    }
    out
}

/// What every sample of one ray's stretch shares.
struct Sampling<'a> {
    world: &'a World,
    medias: &'a [&'a Media],
    lights: &'a [LitLight],
    origin: DVec3,
    dir: DVec3,
    shadow: bool,
    use_scattering: bool,
}

impl Sampling<'_> {
    /// Light (emission and scattering, times the interval's length) and optical
    /// depth (over the interval's length) at fraction `f` of interval `iv`.
    fn sample(&self, iv: &Interval, f: f64, ctx: &mut TraceCtx) -> (DVec3, DVec3, f64) {
        let ds = iv.s1 - iv.s0;
        let d0 = f * ds;
        let t = iv.s0 + d0;
        let p = self.origin + self.dir * t;
        let mut extinction = DVec3::ZERO;
        let mut emission = DVec3::ZERO;
        let mut scattering = DVec3::ZERO;
        for m in self.medias {
            let d = density(m, p);
            if d == DVec3::ZERO {
                continue;
            }
            extinction += d * m.extinction();
            if !self.shadow {
                emission += d * m.emission;
                if let Some(s) = m.scattering {
                    scattering += d * s.colour;
                }
            }
        }
        if !self.shadow && self.use_scattering && iv.lit && scattering != DVec3::ZERO {
            for l in self.lights {
                if t < l.s0 || t > l.s1 {
                    continue;
                }
                if let Some((to_light, colour)) = light_at(self.world, l.index, p, ctx) {
                    let k = phase(self.medias, to_light.dot(self.dir));
                    emission += k * scattering * colour;
                }
            }
        }
        (emission * ds, extinction * ds, d0)
    }

    /// Methods 1 and 2: `samples` per interval (one for constant media on a
    /// shadow ray), then more up to the most while the variance is too high.
    fn regular(
        &self,
        intervals: &[Interval],
        sums: &mut [Sums],
        lead: &Media,
        constant_shadow: bool,
        ctx: &mut TraceCtx,
    ) {
        let n = if constant_shadow { 1 } else { lead.min_samples };
        for (iv, s) in intervals.iter().zip(sums.iter_mut()) {
            for j in 0..n {
                let f = if lead.method == 2 {
                    (f64::from(j) + 0.5) / f64::from(n)
                        + ctx.sampler.next_f64() * lead.jitter / f64::from(n)
                } else {
                    ctx.sampler.next_f64()
                };
                self.add(iv, s, f, ctx);
            }
        }
        if self.shadow || lead.max_samples <= n {
            return;
        }
        let thresholds = thresholds(lead);
        for (iv, s) in intervals.iter().zip(sums.iter_mut()) {
            while s.samples < lead.max_samples {
                let k = 1.0 / f64::from(s.samples.max(1));
                let va = (s.te2 * k - (s.te * k) * (s.te * k)) * k;
                let limit = thresholds[(s.samples as usize)
                    .saturating_sub(1)
                    .min(thresholds.len() - 1)];
                if va.abs().max_element() < limit {
                    break;
                }
                let f = ctx.sampler.next_f64();
                self.add(iv, s, f, ctx);
            }
        }
    }

    /// One sample of methods 1 and 2, added to the interval's sums (light dimmed
    /// by the sample's own extinction over its distance into the interval).
    fn add(&self, iv: &Interval, s: &mut Sums, f: f64, ctx: &mut TraceCtx) {
        let (c, od, d0) = self.sample(iv, f, ctx);
        let ds = iv.s1 - iv.s0;
        let ext = if ds > 0.0 { od / ds } else { DVec3::ZERO };
        let c = c * exp(-ext * d0);
        s.te += c;
        s.te2 += c * c;
        s.od += od;
        s.samples += 1;
    }

    /// Method 3: each interval cut into `(samples + 1) / 2` pieces, sampled at
    /// their ends and refined towards the middle (`aa_level`, `aa_threshold`).
    fn adaptive(
        &self,
        intervals: &[Interval],
        sums: &mut [Sums],
        lead: &Media,
        aa_threshold: f64,
        ctx: &mut TraceCtx,
    ) {
        let pieces = lead.min_samples.div_ceil(2).max(1);
        let dd = 1.0 / f64::from(pieces);
        let jitter = lead.jitter;
        for (iv, s) in intervals.iter().zip(sums.iter_mut()) {
            let j0 = dd * jitter * (ctx.sampler.next_f64() - 0.5);
            let (mut c0, mut od0, _) = self.sample(iv, j0, ctx);
            let mut d0 = 0.0;
            for _ in 0..pieces {
                let d1 = d0 + dd;
                let j1 = d1 + dd * jitter * (ctx.sampler.next_f64() - 0.5);
                let (c1, od1, _) = self.sample(iv, j1, ctx);
                let (res, od_res) = self.refine(
                    iv,
                    (d0, d1),
                    (c0, c1),
                    (od0, od1),
                    lead.aa_level.saturating_sub(1),
                    jitter,
                    aa_threshold,
                    ctx,
                );
                s.te += res * exp(-(s.od + od_res * 0.5) * dd);
                s.od += od_res;
                (c0, od0, d0) = (c1, od1, d1);
            }
            s.samples = pieces;
        }
    }

    /// The mean light and optical depth between fractions `d.0` and `d.1` (whose
    /// samples are `c` and `od`), sampling the middle and halving again where
    /// the light changes by more than `threshold`, `depth` more times at most.
    #[allow(clippy::too_many_arguments)]
    fn refine(
        &self,
        iv: &Interval,
        d: (f64, f64),
        c: (DVec3, DVec3),
        od: (DVec3, DVec3),
        depth: u32,
        jitter: f64,
        threshold: f64,
        ctx: &mut TraceCtx,
    ) -> (DVec3, DVec3) {
        let mid = 0.5 * (d.0 + d.1);
        let at = mid + jitter * (d.1 - d.0) * (ctx.sampler.next_f64() - 0.5);
        let (c2, od2, _) = self.sample(iv, at, ctx);
        if depth == 0 {
            return ((c.0 + c2 + c.1) / 3.0, (od.0 + od2 + od.1) / 3.0);
        }
        // As POV-Ray 3.7 weighs them: each half gives half of the result; an
        // unrefined half weighs its outer end twice its middle.
        let (mut res, mut od_res) = if distance(c.0, c2) > threshold {
            let (r, o) = self.refine(
                iv,
                (d.0, mid),
                (c.0, c2),
                (od.0, od2),
                depth - 1,
                jitter,
                threshold,
                ctx,
            );
            (r / 2.0, o / 2.0)
        } else {
            (c.0 / 3.0 + c2 / 6.0, od.0 / 3.0 + od2 / 6.0)
        };
        if distance(c2, c.1) > threshold {
            let (r, o) = self.refine(
                iv,
                (mid, d.1),
                (c2, c.1),
                (od2, od.1),
                depth - 1,
                jitter,
                threshold,
                ctx,
            );
            res += r / 2.0;
            od_res += o / 2.0;
        } else {
            res += c2 / 6.0 + c.1 / 3.0;
            od_res += od2 / 6.0 + od.1 / 3.0;
        }
        (res, od_res)
    }
}

/// How far apart two colours are: the sum of the channels' differences.
fn distance(a: DVec3, b: DVec3) -> f64 {
    (a - b).abs().element_sum()
}

/// The density of media `m` at world point `p`: the product of its densities'
/// colours (1 without any).
pub fn density(m: &Media, p: DVec3) -> DVec3 {
    let mut d = DVec3::ONE;
    for pig in &m.density {
        d *= crate::pattern::evaluate(pig, p).rgb;
        if d == DVec3::ZERO {
            break;
        }
    }
    d
}

/// The phase functions of `medias` averaged, for light arriving from a light in
/// unit direction `cos` = (direction to the light) · (ray direction), scaled as
/// POV-Ray 3.7 scales them (isotropic = 1).
pub fn phase(medias: &[&Media], cos: f64) -> f64 {
    if medias.is_empty() {
        return 0.0;
    }
    let mut k = 0.0;
    for m in medias {
        let kind = m.scattering.map_or(ScatteringKind::Isotropic, |s| s.kind);
        k += match kind {
            ScatteringKind::Isotropic => 1.0,
            ScatteringKind::Rayleigh => 0.799372013 * (1.0 + cos * cos),
            ScatteringKind::MieHazy => 0.576655375 * (1.0 + 9.0 * (0.5 * (1.0 + cos)).powi(8)),
            ScatteringKind::MieMurky => 0.495714547 * (1.0 + 50.0 * (0.5 * (1.0 + cos)).powi(32)),
            ScatteringKind::HenyeyGreenstein => {
                let g = m.scattering.map_or(0.0, |s| s.eccentricity);
                (1.0 - g * g) / (1.0 + g * g - 2.0 * g * cos).max(1e-12).powf(1.5)
            }
        };
    }
    k / medias.len() as f64
}

/// The light `index` brings to media point `p`: unit direction towards it and
/// its colour after beam, fading, shadows and (with `media_attenuation`) media.
fn light_at(world: &World, index: usize, p: DVec3, ctx: &mut TraceCtx) -> Option<(DVec3, DVec3)> {
    let light = world.lights.get(index)?;
    let towards = if light.parallel || matches!(light.kind, LightKind::Cylinder(_)) {
        (light.location - light.point_at).normalize_or_zero()
    } else {
        (light.location - p).normalize_or_zero()
    };
    if towards == DVec3::ZERO {
        return None;
    }
    lights::incident(world, index, p, towards, towards, ctx).map(|i| (i.dir, i.colour))
}

/// Per sample count, the variance below which methods 1 and 2 stop adding
/// samples: `variance / χ²⁻¹(max - 1) · χ²⁻¹(n)` at the `confidence`.
fn thresholds(m: &Media) -> Vec<f64> {
    let max = m.max_samples.max(1) as usize;
    if max <= 1 {
        return vec![0.0];
    }
    let t = chi2_inverse_upper((max - 1) as f64, m.confidence);
    let t = if t > 0.0 {
        m.variance / t
    } else {
        m.variance * 1e-10
    };
    (0..max)
        .map(|i| t * chi2_inverse_upper((i + 1) as f64, m.confidence))
        .collect()
}

/// The `x` with `P(χ²(df) > x) = q`.
fn chi2_inverse_upper(df: f64, q: f64) -> f64 {
    let (mut lo, mut hi) = (0.0, df.max(1.0));
    while upper_gamma(df / 2.0, hi / 2.0) > q && hi < 1e6 {
        hi *= 2.0;
    }
    for _ in 0..100 {
        let mid = 0.5 * (lo + hi);
        if upper_gamma(df / 2.0, mid / 2.0) > q {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

/// The regularised upper incomplete gamma function `Q(a, x)`.
fn upper_gamma(a: f64, x: f64) -> f64 {
    if x <= 0.0 {
        return 1.0;
    }
    let ln_front = a * x.ln() - x - ln_gamma(a);
    if x < a + 1.0 {
        // Series for P.
        let (mut sum, mut term, mut n) = (1.0 / a, 1.0 / a, a);
        for _ in 0..500 {
            n += 1.0;
            term *= x / n;
            sum += term;
            if term.abs() < sum.abs() * 1e-15 {
                break;
            }
        }
        1.0 - sum * ln_front.exp()
    } else {
        // Continued fraction for Q (modified Lentz).
        let tiny = 1e-300;
        let mut b = x + 1.0 - a;
        let mut c = 1.0 / tiny;
        let mut d = 1.0 / b;
        let mut h = d;
        for i in 1..500 {
            let an = -(i as f64) * (i as f64 - a);
            b += 2.0;
            d = an * d + b;
            if d.abs() < tiny {
                d = tiny;
            }
            c = b + an / c;
            if c.abs() < tiny {
                c = tiny;
            }
            d = 1.0 / d;
            let delta = d * c;
            h *= delta;
            if (delta - 1.0).abs() < 1e-15 {
                break;
            }
        }
        ln_front.exp() * h
    }
}

/// `ln Γ(x)` for `x > 0` (Lanczos).
fn ln_gamma(x: f64) -> f64 {
    const G: [f64; 9] = [
        0.999_999_999_999_809_9,
        676.520_368_121_885_1,
        -1_259.139_216_722_402_8,
        771.323_428_777_653_1,
        -176.615_029_162_140_6,
        12.507_343_278_686_905,
        -0.138_571_095_265_720_12,
        9.984_369_578_019_572e-6,
        1.505_632_735_149_311_6e-7,
    ];
    if x < 0.5 {
        let pi = std::f64::consts::PI;
        return (pi / (pi * x).sin()).ln() - ln_gamma(1.0 - x);
    }
    let x = x - 1.0;
    let mut a = G[0];
    let t = x + 7.5;
    for (i, g) in G.iter().enumerate().skip(1) {
        a += g / (x + i as f64);
    }
    0.5 * (2.0 * std::f64::consts::PI).ln() + (x + 0.5) * t.ln() - t + a.ln()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn chi_square_quantiles() {
        // Tables: P(χ²(1) > 2.706) = 0.1, P(χ²(10) > 15.987) = 0.1.
        assert!((chi2_inverse_upper(1.0, 0.1) - 2.706).abs() < 2e-3);
        assert!((chi2_inverse_upper(10.0, 0.1) - 15.987).abs() < 2e-3);
        assert!((upper_gamma(1.0, 1.0) - (-1.0f64).exp()).abs() < 1e-12);
    }

    #[test]
    fn phase_functions_are_povray_scaled() {
        let iso = Media::default();
        assert_eq!(phase(&[&iso], 0.3), 1.0);
        let hg = Media {
            scattering: Some(crate::scene::Scattering {
                kind: ScatteringKind::HenyeyGreenstein,
                colour: DVec3::ONE,
                eccentricity: 0.0,
                extinction: 1.0,
            }),
            ..Media::default()
        };
        assert!((phase(&[&hg], -0.7) - 1.0).abs() < 1e-12);
        // Rayleigh is symmetric, the Mie types peak forwards (towards the light),
        // murky more sharply than haze; all are positive.
        let with = |kind| Media {
            scattering: Some(crate::scene::Scattering {
                kind,
                colour: DVec3::ONE,
                eccentricity: 0.0,
                extinction: 1.0,
            }),
            ..Media::default()
        };
        let (r, h, m) = (
            with(ScatteringKind::Rayleigh),
            with(ScatteringKind::MieHazy),
            with(ScatteringKind::MieMurky),
        );
        assert!((phase(&[&r], 0.6) - phase(&[&r], -0.6)).abs() < 1e-12);
        for x in [&h, &m] {
            assert!(phase(&[x], 1.0) > 5.0 * phase(&[x], -1.0));
            assert!(phase(&[x], -1.0) > 0.0);
        }
        assert!(phase(&[&m], 1.0) / phase(&[&m], 0.0) > phase(&[&h], 1.0) / phase(&[&h], 0.0));
        // Two media at a point: their phase functions are averaged.
        let avg = phase(&[&iso, &h], 1.0);
        assert!((avg - 0.5 * (1.0 + phase(&[&h], 1.0))).abs() < 1e-12);
    }

    #[test]
    fn spotlight_stretch_is_the_cone() {
        // A cone of half-angle 45° down -y from (0, 10, 0); a horizontal ray at
        // y = 5 from x = -10 crosses it between x = -5 and 5.
        let inside = |t: f64| {
            let p = DVec3::new(-10.0 + t, 5.0, 0.0) - DVec3::new(0.0, 10.0, 0.0);
            let along = p.dot(-DVec3::Y);
            along > 0.0 && along * along >= 0.5 * p.length_squared()
        };
        let (s0, s1) = stretch(&[5.0, 15.0], None, 20.0, inside).expect("crosses");
        assert!((s0 - 5.0).abs() < 1e-12 && (s1 - 15.0).abs() < 1e-12);
    }

    #[test]
    fn intervals_share_out_by_ratio() {
        let lit = vec![
            Interval {
                lit: false,
                s0: 0.0,
                s1: 4.0,
            },
            Interval {
                lit: true,
                s0: 4.0,
                s1: 6.0,
            },
            Interval {
                lit: false,
                s0: 6.0,
                s1: 10.0,
            },
        ];
        let m = Media::default();
        let iv = sample_intervals(&lit, &m, 10.0);
        assert!(iv.len() >= 3);
        assert_eq!(iv.first().map(|i| i.s0), Some(0.0));
        assert_eq!(iv.last().map(|i| i.s1), Some(10.0));
        for w in iv.windows(2) {
            assert!((w[0].s1 - w[1].s0).abs() < 1e-12);
        }
    }
}
