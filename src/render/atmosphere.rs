//! What a ray meets besides objects: the sky sphere behind everything, and
//! rainbows and fog along the way, as POV-Ray 3.7 defines them.

use crate::build::{Ray, World};
use crate::pattern;
use crate::pattern::noise;
use crate::scene::{Atmosphere, Fog, FogKind, FogTurbulence, Rainbow};
use glam::DVec3;

/// Distance a ray that hits nothing is taken to travel through fog.
pub const MISS_DISTANCE: f64 = 1e30;

/// The colour of a ray that hits nothing: the background, under the sky sphere's
/// pigments (evaluated at the unit direction, in the sky sphere's own space; each
/// layer lets through what lies below in proportion to its filter and transmit).
pub fn sky(world: &World, dir: DVec3) -> DVec3 {
    let mut out = world.background;
    if let Some(sky) = &world.atmosphere.sky_sphere {
        let mut d = dir.normalize();
        if let Some(t) = &sky.transform {
            d = t.inverse.transform_vector3(d).normalize();
        }
        for pig in &sky.pigments {
            let c = pattern::evaluate(pig, d);
            out = c.rgb * (1.0 - c.filter - c.transmit) + out * (c.transmit + c.filter * c.rgb);
        }
    }
    out
}

/// `colour` seen along `ray` at distance `depth` (in units of `|ray.dir|`), through
/// the rainbows and then every fog of `atmosphere` (measured in POV-Ray 3.7: the
/// rainbows lie behind the fogs whatever their order in the file). Several fogs
/// do not lie over one another: what is behind is dimmed by all of them and
/// their colours add up (so two fogs can be brighter than either).
pub fn apply_atmosphere(atmosphere: &Atmosphere, ray: &Ray, depth: f64, colour: DVec3) -> DVec3 {
    if atmosphere.fogs.is_empty() && atmosphere.rainbows.is_empty() {
        return colour;
    }
    let len = ray.dir.length();
    let (dir, dist) = (ray.dir / len, depth * len);
    let colour = through_rainbows(&atmosphere.rainbows, dir, dist, colour);
    let mut through = colour;
    let mut added = DVec3::ZERO;
    for fog in &atmosphere.fogs {
        let k = transmittance(fog, ray.origin, dir, dist);
        let (pass, own) = blend(fog, k);
        through *= pass;
        added += own;
    }
    through + added
}

/// `colour`, `dist` away along unit `dir`, seen through `rainbows`. Measured in
/// POV-Ray 3.7 (16-bit linear renders):
///
/// - a rainbow's index is `(θ - angle + width / 2) / width`, θ the angle between
///   `dir` and its direction, moved by up to ± `jitter` (uniformly, per ray);
///   the rainbow shows where that lies in [0, 1], and its colour map is read
///   there;
/// - with an arc, the angle φ round the direction from `up` (made perpendicular
///   to the direction) must be within `arc_angle / 2`; beyond `falloff_angle / 2`
///   the colour's transmit t becomes `1 - s (1 - t)`, s falling from 1 to 0 by a
///   smoothstep (`1 - 3u² + 2u³`, u the way across the soft part);
/// - each rainbow mixes with what is behind as a fog, but with its filter
///   weakened: `w = max(exp(-dist / distance), transmit)`, `f' = filter (1 - w)`;
///   the colour behind is multiplied by `w (1 - f' + f' rgb)` and `(1 - w) rgb`
///   added;
/// - several rainbows over one ray: the average of what each alone would give.
fn through_rainbows(rainbows: &[Rainbow], dir: DVec3, dist: f64, colour: DVec3) -> DVec3 {
    let mut sum = DVec3::ZERO;
    let mut hits = 0u32;
    for rb in rainbows {
        if let Some(c) = rainbow_colour(rb, dir) {
            let k = (-dist / rb.distance).exp();
            let w = k.max(c.transmit);
            let f = c.filter * (1.0 - w);
            sum += colour * (w * (DVec3::splat(1.0 - f) + f * c.rgb)) + (1.0 - w) * c.rgb;
            hits += 1;
        }
    }
    if hits == 0 {
        colour
    } else {
        sum / f64::from(hits)
    }
}

/// The colour `rb` gives a ray along unit `dir` (its transmit raised in the soft
/// ends of an arc), or `None` where the ray misses the rainbow.
fn rainbow_colour(rb: &Rainbow, dir: DVec3) -> Option<crate::scene::Colour> {
    if rb.width <= 0.0 {
        return None;
    }
    let theta = dir.dot(rb.direction).clamp(-1.0, 1.0).acos().to_degrees();
    let mut index = (theta - rb.angle + rb.width / 2.0) / rb.width;
    if rb.jitter != 0.0 {
        // A value in [0, 1) that depends only on the ray, so pictures do not
        // depend on threads or the order of pixels.
        let key =
            dir.x.to_bits() ^ dir.y.to_bits().rotate_left(21) ^ dir.z.to_bits().rotate_left(42);
        let u = (super::sampler::mix(key) >> 11) as f64 * (1.0 / (1u64 << 53) as f64);
        index += rb.jitter * (2.0 * u - 1.0);
    }
    // The jittered index decides: the band's edges are ragged too.
    if !(0.0..=1.0).contains(&index) {
        return None;
    }
    let mut c = pattern::colour_at(&rb.colour_map, index);
    if rb.falloff_angle < 360.0 {
        // `up` and `direction` are perpendicular unit vectors (see `Rainbow`).
        let right = rb.up.cross(rb.direction);
        let phi = dir.dot(right).abs().atan2(dir.dot(rb.up)).to_degrees();
        let (half_arc, half_full) = (rb.arc_angle / 2.0, rb.falloff_angle / 2.0);
        if phi > half_arc {
            return None;
        }
        if phi > half_full {
            let u = (phi - half_full) / (half_arc - half_full);
            let s = 1.0 - u * u * (3.0 - 2.0 * u);
            c.transmit = 1.0 - s * (1.0 - c.transmit);
        }
    }
    Some(c)
}

/// What passes through `fog` along the `dist` from `origin` along unit `dir`
/// (for light on its way to a point: the fog's own colour is not added).
pub fn fog_pass(fog: &Fog, origin: DVec3, dir: DVec3, dist: f64) -> DVec3 {
    blend(fog, transmittance(fog, origin, dir, dist)).0
}

/// How much of what lies `dist` away along unit `dir` from `origin` shows through
/// `fog`: `exp(-D / distance)`, D the distance weighted by the fog's density.
pub fn transmittance(fog: &Fog, origin: DVec3, dir: DVec3, dist: f64) -> f64 {
    let depth = match fog.kind {
        FogKind::Constant => dist,
        FogKind::Ground { offset, alt, up } => {
            let h0 = origin.dot(up);
            let dh = dir.dot(up);
            if dh.abs() < 1e-12 {
                dist * ground_density(h0, offset, alt)
            } else {
                let h1 = h0 + dist * dh;
                (ground_integral(h1, offset, alt) - ground_integral(h0, offset, alt)) / dh
            }
        }
    };
    if !depth.is_finite() {
        return 0.0;
    }
    let scale = fog
        .turbulence
        .map_or(1.0, |t| thickness(&t, origin + dir * (dist * t.depth)));
    (-depth * scale / fog.distance).exp()
}

/// How a fog's `turbulence` scales the attenuation along a ray whose turbulence
/// point (`turb_depth` of the way along it) is `p`. As the POV-Ray manual says,
/// the fog's density does not change; only its distance-based attenuation is
/// modified by a turbulence value at that point. rts's rule: the value is the
/// scalar turbulence `T = Σ omegaⁱ |noise(q lambdaⁱ)|` at `q = p × amount` (per
/// axis: a larger amount varies faster, a zero component not at all), and the
/// attenuation is scaled by `1 - GAIN × turb_depth × T`, never below 0.
///
/// `GAIN` is fitted to POV-Ray 3.7 (its noise is its own, so only the statistics
/// can agree): a black wall 10 units away in white fog of distance 10, 160×120,
/// 16-bit linear, turbulence 0.8. Attenuation relative to the plain fog, mean and
/// standard deviation over the picture, POV-Ray then rts: default 0.863 / 0.054
/// and 0.860 / 0.062; `turb_depth 1` 0.73 and 0.72; `octaves 1` 0.946 / 0.041 and
/// 0.927 / 0.053; `turb_depth 0` 1.033 and 1. POV-Ray's mean does not depend on
/// the amount once it is above about 0.2, nor does rts's.
fn thickness(t: &FogTurbulence, p: DVec3) -> f64 {
    const GAIN: f64 = 1.3;
    let q = p * t.amount;
    if !q.is_finite() {
        return 1.0;
    }
    let turb = noise::turbulence(q, t.octaves, t.omega, t.lambda);
    (1.0 - GAIN * t.depth * turb).max(0.0)
}

/// A fog with transmittance `k` passes `pass` times the colour behind it and adds
/// `own`. Measured in POV-Ray 3.7: the fog's `transmit` is the least transmittance,
/// `w = max(k, transmit)`; `pass = w (1 - filter + filter colour)` and
/// `own = (1 - w) colour`.
fn blend(fog: &Fog, k: f64) -> (DVec3, DVec3) {
    let c = fog.colour;
    let w = k.max(c.transmit);
    (
        w * (DVec3::splat(1.0 - c.filter) + c.filter * c.rgb),
        (1.0 - w) * c.rgb,
    )
}

/// Ground fog density at height `h`: 1 up to `offset`, `1 / (1 + ((h - offset) /
/// alt)²)` above (measured against POV-Ray 3.7).
fn ground_density(h: f64, offset: f64, alt: f64) -> f64 {
    if h <= offset {
        1.0
    } else {
        let x = (h - offset) / alt;
        1.0 / (1.0 + x * x)
    }
}

/// A primitive of [`ground_density`] over height.
fn ground_integral(h: f64, offset: f64, alt: f64) -> f64 {
    if h <= offset {
        h
    } else {
        offset + alt * ((h - offset) / alt).atan()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::Colour;

    fn fog(kind: FogKind) -> Fog {
        Fog {
            kind,
            distance: 10.0,
            colour: Colour::rgb(0.5, 0.6, 0.7),
            turbulence: None,
        }
    }

    fn rainbow(direction: DVec3, colour: Colour) -> Rainbow {
        let direction = direction.normalize();
        Rainbow {
            direction,
            angle: 20.0,
            width: 60.0,
            distance: 1e7,
            jitter: 0.0,
            colour_map: std::sync::Arc::new(vec![(0.0, colour), (1.0, colour)]),
            // y made perpendicular to the direction, as evaluation does.
            up: direction.cross(DVec3::Y.cross(direction)).normalize(),
            arc_angle: 360.0,
            falloff_angle: 360.0,
        }
    }

    fn rgbft(r: f64, g: f64, b: f64, filter: f64, transmit: f64) -> Colour {
        Colour {
            rgb: DVec3::new(r, g, b),
            filter,
            transmit,
        }
    }

    fn close(a: DVec3, b: DVec3) -> bool {
        (a - b).abs().max_element() < 2e-4
    }

    // The numbers below are POV-Ray 3.7's, read from 16-bit linear renders of
    // the centre pixel of an 11x11 picture (camera along +z).

    #[test]
    fn a_rainbow_mixes_like_a_fog_with_a_weaker_filter() {
        let mut rb = rainbow(DVec3::Z, rgbft(0.9, 0.5, 0.2, 0.5, 0.3));
        rb.distance = 10.0;
        // A surface 10 away (exp(-1) shows through), black and white behind.
        let on =
            |bg: f64| through_rainbows(std::slice::from_ref(&rb), DVec3::Z, 10.0, DVec3::splat(bg));
        assert!(
            close(on(0.0), DVec3::new(0.5689, 0.3161, 0.1264)),
            "{}",
            on(0.0)
        );
        assert!(
            close(on(1.0), DVec3::new(0.9252, 0.6258, 0.4013)),
            "{}",
            on(1.0)
        );
        // Transmit above exp(-1) wins; over the background (nothing behind it).
        rb.colour_map = std::sync::Arc::new(vec![(0.0, rgbft(0.9, 0.5, 0.2, 0.5, 0.5))]);
        let c = through_rainbows(
            std::slice::from_ref(&rb),
            DVec3::Z,
            MISS_DISTANCE,
            DVec3::ONE,
        );
        assert!(close(c, DVec3::new(0.9375, 0.6875, 0.5)), "{c}");
        // Outside the band nothing changes.
        let side = DVec3::new(1.0, 0.0, 0.1).normalize();
        let c = through_rainbows(std::slice::from_ref(&rb), side, MISS_DISTANCE, DVec3::ONE);
        assert_eq!(c, DVec3::ONE);
    }

    #[test]
    fn an_arc_fades_out_by_a_smoothstep_past_the_falloff_angle() {
        // Direction β from the ray, turned φ round it from up.
        let at = |beta: f64, phi: f64| {
            let (b, p) = (beta.to_radians(), phi.to_radians());
            let d = DVec3::new(b.sin() * p.sin(), -b.sin() * p.cos(), b.cos());
            let mut rb = rainbow(d, rgbft(1.0, 1.0, 1.0, 0.0, 0.0));
            rb.width = 80.0;
            rb.arc_angle = 120.0;
            rb.falloff_angle = 0.0;
            through_rainbows(&[rb], DVec3::Z, MISS_DISTANCE, DVec3::ZERO).x
        };
        for (beta, phi, want) in [
            (20.0, 0.0, 1.0),
            (20.0, 10.0, 0.9170),
            (20.0, 30.0, 0.4609),
            (20.0, 50.0, 0.0516),
            (20.0, 60.0, 0.0),
            (50.0, 10.0, 0.8373),
            (50.0, 30.0, 0.2175),
            (50.0, 50.0, 0.0),
        ] {
            let got = at(beta, phi);
            assert!(
                (got - want).abs() < 2e-4,
                "β {beta} φ {phi}: {got}, POV-Ray {want}"
            );
        }
    }

    #[test]
    fn several_rainbows_average() {
        let green = DVec3::new(0.0, 1.0, 0.0);
        let two = |a: Colour, b: Colour| {
            let rbs = [rainbow(DVec3::Z, a), rainbow(DVec3::Z, b)];
            through_rainbows(&rbs, DVec3::Z, MISS_DISTANCE, green)
        };
        let c = two(
            rgbft(1.0, 0.0, 0.0, 0.0, 0.2),
            rgbft(0.0, 0.0, 1.0, 0.0, 0.6),
        );
        assert!(close(c, DVec3::new(0.4, 0.4, 0.2)), "{c}");
        let c = two(
            rgbft(1.0, 0.0, 0.0, 0.8, 0.2),
            rgbft(0.0, 0.0, 1.0, 0.0, 0.6),
        );
        assert!(close(c, DVec3::new(0.4, 0.336, 0.2)), "{c}");
        // One that misses the ray does not count.
        let mut far = rainbow(DVec3::Z, rgbft(0.0, 0.0, 1.0, 0.0, 0.5));
        far.angle = 80.0;
        let rbs = [rainbow(DVec3::Z, rgbft(1.0, 0.0, 0.0, 0.0, 0.5)), far];
        let c = through_rainbows(&rbs, DVec3::Z, MISS_DISTANCE, green);
        assert!(close(c, DVec3::new(0.5, 0.5, 0.0)), "{c}");
    }

    #[test]
    fn jitter_moves_the_index_and_ragged_edges_with_it() {
        // Index -0.1 with jitter 0.2: about a quarter of the rays reach the band
        // (POV-Ray 0.27 of 37 pixels); the same ray always gets the same value.
        let mut rb = rainbow(DVec3::Z, rgbft(1.0, 0.0, 0.0, 0.0, 0.0));
        rb.angle = 25.0;
        rb.width = 40.0;
        rb.jitter = 0.2;
        let theta = (5.0f64 - 0.1 * 40.0).to_radians();
        let n = 4000;
        let hits = (0..n)
            .filter(|i| {
                let a = *i as f64 * 0.001;
                let d = DVec3::new(theta.sin() * a.cos(), theta.sin() * a.sin(), theta.cos());
                rainbow_colour(&rb, d).is_some()
            })
            .count();
        let share = hits as f64 / n as f64;
        assert!((share - 0.25).abs() < 0.03, "{share}");
        let d = DVec3::new(0.1, 0.2, 1.0).normalize();
        assert_eq!(rainbow_colour(&rb, d), rainbow_colour(&rb, d));
    }

    #[test]
    fn constant_fog_is_exponential_in_distance() {
        let f = fog(FogKind::Constant);
        let k = transmittance(&f, DVec3::ZERO, DVec3::Z, 10.0);
        assert!((k - (-1.0f64).exp()).abs() < 1e-12);
        let (pass, own) = blend(&f, k);
        let c = pass * DVec3::ONE + own;
        let want = DVec3::ONE * k + (1.0 - k) * DVec3::new(0.5, 0.6, 0.7);
        assert!((c - want).length() < 1e-12);
        assert_eq!(transmittance(&f, DVec3::ZERO, DVec3::Z, MISS_DISTANCE), 0.0);
    }

    #[test]
    fn transmitting_fog_lets_the_background_through() {
        let mut f = fog(FogKind::Constant);
        f.colour.transmit = 1.0;
        assert_eq!(blend(&f, 0.0), (DVec3::ONE, DVec3::ZERO));
        // POV-Ray 3.7, fog rgbft <0.9, 0.5, 0.2, 0.5, 0.5> over <0.2, 0.4, 0.8>
        // where k = 0: 0.545, 0.4, 0.341 (8-bit linear).
        let mut f = fog(FogKind::Constant);
        f.colour = Colour {
            rgb: DVec3::new(0.9, 0.5, 0.2),
            filter: 0.5,
            transmit: 0.5,
        };
        let (pass, own) = blend(&f, 0.0);
        let c = DVec3::new(0.2, 0.4, 0.8) * pass + own;
        assert!((c - DVec3::new(0.545, 0.4, 0.341)).abs().max_element() < 0.003);
    }

    #[test]
    fn ground_fog_integrates_its_density() {
        let f = fog(FogKind::Ground {
            offset: 1.0,
            alt: 2.0,
            up: DVec3::Y,
        });
        // Horizontal below the offset: full density.
        let k = transmittance(&f, DVec3::ZERO, DVec3::X, 10.0);
        assert!((k - (-1.0f64).exp()).abs() < 1e-12);
        // Straight up from 0 to 3: 1 (below) + ∫₁³ 1/(1+((h-1)/2)²) dh = 1 + 2 atan 1.
        let k = transmittance(&f, DVec3::ZERO, DVec3::Y, 3.0);
        let want = (-(1.0 + 2.0 * 1f64.atan()) / 10.0).exp();
        assert!((k - want).abs() < 1e-12);
        // Numerical check along a slanted ray.
        let dir = DVec3::new(1.0, 0.3, 0.0).normalize();
        let n = 100_000;
        let mut sum = 0.0;
        for i in 0..n {
            let t = (i as f64 + 0.5) * 20.0 / n as f64;
            sum += ground_density(t * dir.y, 1.0, 2.0) * 20.0 / n as f64;
        }
        let k = transmittance(&f, DVec3::ZERO, dir, 20.0);
        assert!((k - (-sum / 10.0).exp()).abs() < 1e-6);
    }

    #[test]
    fn fog_turbulence_varies_the_attenuation_not_the_density() {
        let turb = FogTurbulence {
            amount: DVec3::splat(0.8),
            depth: 0.5,
            octaves: 6,
            omega: 0.5,
            lambda: 2.0,
        };
        let mut f = fog(FogKind::Constant);
        f.turbulence = Some(turb);
        let plain = fog(FogKind::Constant);
        // Over many rays the attenuation is scaled by about 0.86 on average (the
        // figure fitted to POV-Ray), varies from ray to ray, and is never more
        // than the plain fog's.
        let (mut sum, mut lo, mut hi) = (0.0, f64::MAX, 0.0f64);
        let n = 2000;
        for i in 0..n {
            let a = i as f64 * 0.6180339887;
            let dir = DVec3::new(a.sin() * 0.5, (a * 1.7).cos() * 0.4, 1.0).normalize();
            let k = transmittance(&f, DVec3::ZERO, dir, 10.0);
            let k0 = transmittance(&plain, DVec3::ZERO, dir, 10.0);
            let scale = k.ln() / k0.ln();
            assert!((0.0..=1.0 + 1e-12).contains(&scale), "{scale}");
            sum += scale;
            lo = lo.min(scale);
            hi = hi.max(scale);
        }
        let mean = sum / n as f64;
        assert!((mean - 0.86).abs() < 0.04, "mean {mean}");
        assert!(hi - lo > 0.2, "range {lo}..{hi}");
        // Taken at the camera (turb_depth 0) the fog is the plain one.
        f.turbulence = Some(FogTurbulence { depth: 0.0, ..turb });
        let d = DVec3::new(0.3, 0.1, 1.0).normalize();
        let (k, k0) = (
            transmittance(&f, DVec3::ZERO, d, 10.0),
            transmittance(&plain, DVec3::ZERO, d, 10.0),
        );
        assert!((k - k0).abs() < 1e-15);
        // A ray that misses everything stays fully fogged (no NaN from the
        // far turbulence point).
        f.turbulence = Some(turb);
        assert_eq!(transmittance(&f, DVec3::ZERO, d, MISS_DISTANCE), 0.0);
    }
}
