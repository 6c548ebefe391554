//! Pattern functions: each maps a point in pattern space to a value in [0, 1]
//! (or, for list patterns, to an entry index). Definitions follow the POV-Ray 3.7
//! manual; the geometric ones were checked pixel by pixel against POV-Ray renders.

use super::noise::{dnoise, noise, noise_grad, signed_noise, turbulence_vec};
use crate::scene::{PatternKind, PatternMods, Wave};
use glam::DVec3;
use std::f64::consts::{PI, TAU};

/// Bias added before flooring in cell patterns so points on cell boundaries fall
/// in the cell above, as POV-Ray shows (see `CHECKER_OFFSET`).
const EPS: f64 = 1e-10;

/// The entry index a list pattern selects at `p`.
pub fn list_index(kind: &PatternKind, p: DVec3) -> usize {
    match kind {
        PatternKind::Checker => super::checker_index(p),
        PatternKind::Hexagon => hexagon_index(p),
        PatternKind::Square => square_index(p),
        PatternKind::Triangular => triangular_index(p),
        PatternKind::Brick { size, mortar } => usize::from(!is_mortar(p, *size, *mortar)),
        PatternKind::MaterialMap(im) => super::image_map::index_at(im, p),
        PatternKind::Object(t) => usize::from(t.inside(p)),
        _ => 0,
    }
}

/// `hexagon`: hexagons of side 1 tiling the x-z plane with two vertices on the x
/// axis, centred on the origin, coloured so no two neighbours share an entry.
/// Measured on POV-Ray 3.7: the hexagon at the origin takes the first entry, the
/// one above it in +z the second, the one below the third.
pub fn hexagon_index(p: DVec3) -> usize {
    let s3 = 3f64.sqrt();
    // Axial coordinates: centre (q, r) is at x = 1.5 q, z = √3 (r + q / 2).
    let q = 2.0 / 3.0 * p.x + EPS;
    let r = -p.x / 3.0 + s3 / 3.0 * p.z + EPS;
    let s = -q - r;
    let (mut rq, mut rr, rs) = (q.round(), r.round(), s.round());
    let (dq, dr, ds) = ((rq - q).abs(), (rr - r).abs(), (rs - s).abs());
    if dq > dr && dq > ds {
        rq = -rr - rs;
    } else if dr > ds {
        rr = -rq - rs;
    }
    (rr + 2.0 * rq).rem_euclid(3.0) as usize % 3
}

/// `square`: unit squares tiling the x-z plane in blocks of four, the entries
/// going round each block: the square of x and z in [0, 1) takes the first, the
/// one beyond it in +z the second, the one diagonally across the third, the one
/// in +x the fourth (measured on POV-Ray 3.7 at 3000 points, all agreeing).
pub fn square_index(p: DVec3) -> usize {
    let a = (p.x + EPS).floor().rem_euclid(2.0) as usize;
    let b = (p.z + EPS).floor().rem_euclid(2.0) as usize;
    [[0, 1], [3, 2]][a][b]
}

/// `triangular`: equilateral triangles of side 1 tiling the x-z plane, with
/// edges along x at every multiple of √3/2 in z and a vertex at the origin; the
/// six entries meet round every vertex. Within the band of rows `k` (z from
/// k√3/2), `u` is x less half a unit in odd bands; the triangle with its base
/// on the band's lower edge from u = i to i + 1 takes entry 1, 5 or 3 (i - k mod
/// 2, mod 3 = 0, 1, 2) and the one with its apex there at u = c takes entry 2,
/// 4 or 6 (c - k mod 2, mod 3). Measured on POV-Ray 3.7 at 3000 points, all
/// agreeing.
pub fn triangular_index(p: DVec3) -> usize {
    const H: f64 = 0.866_025_403_784_438_6; // √3 / 2
    let band = (p.z / H + EPS).floor();
    let v = p.z / H - band;
    let odd = band.rem_euclid(2.0) as i64;
    let u = p.x - 0.5 * odd as f64 + EPS;
    let i = u.floor();
    if (u - (i + 0.5)).abs() <= (1.0 - v) / 2.0 {
        [0, 4, 2][(i as i64 - odd).rem_euclid(3) as usize]
    } else {
        [1, 3, 5][(u.round() as i64 - odd).rem_euclid(3) as usize]
    }
}

/// Whether `p` is in the mortar of `brick`: bricks of `size` whose mortar joint
/// of width `mortar` lies at the top end of each cell; every other course is
/// shifted by half a brick in x and z (measured on POV-Ray 3.7 renders).
pub fn is_mortar(p: DVec3, size: DVec3, mortar: f64) -> bool {
    let row = (p.y / size.y + EPS).floor();
    let y = p.y - row * size.y;
    let odd = row.rem_euclid(2.0) != 0.0;
    let x = p.x + if odd { size.x / 2.0 } else { 0.0 };
    let z = p.z + if odd { size.z / 2.0 } else { 0.0 };
    let lx = (x + EPS).rem_euclid(size.x);
    let lz = (z + EPS).rem_euclid(size.z);
    y >= size.y - mortar || lx >= size.x - mortar || lz >= size.z - mortar
}

/// How far agate's turbulence shifts its bands along z, in periods per unit of
/// [`agate_turbulence`]. With it, a plane cut through `agate` has POV-Ray 3.7's
/// spread of feature sizes: the share of picture energy per octave of spatial
/// frequency (1/16 to 8 cycles per unit) agrees with POV-Ray's renders of a
/// z = 0 and an x = 0 cut to within 0.04 in every band, where the |noise|
/// turbulence used before put 0.28 of it at 2-4 cycles per unit against
/// POV-Ray's 0.09 (busy, creased bands; POV-Ray's are smooth and wavy).
const AGATE_SWIRL: f64 = 1.1;

/// The smooth fractal sum agate bends its bands by: seven octaves of signed
/// noise, each half the amplitude and twice the frequency of the one before (no
/// absolute value, so no creases).
fn agate_turbulence(p: DVec3) -> f64 {
    let (mut sum, mut amp, mut freq) = (0.0, 1.0, 1.0);
    for _ in 0..7 {
        sum += amp * signed_noise(p * freq);
        amp *= 0.5;
        freq *= 2.0;
    }
    sum
}

/// The raw value of a non-list pattern at `p` (before the frequency, phase and
/// wave that map it; `ripples` and `waves` space their waves by frequency and
/// phase here too), with turbulence already applied to `p` for the patterns
/// that take it that way.
fn raw(kind: &PatternKind, p: DVec3, m: &PatternMods) -> f64 {
    let g = m.noise_generator;
    match kind {
        PatternKind::Gradient(v) => p.dot(*v),
        PatternKind::Cells => cell_value(p.floor()),
        PatternKind::Radial => {
            let a = (-p.z).atan2(p.x);
            (a / TAU).rem_euclid(1.0)
        }
        PatternKind::Onion => p.length(),
        PatternKind::Leopard => {
            let s = (p.x.sin() + p.y.sin() + p.z.sin()) / 3.0;
            s * s
        }
        PatternKind::Bozo | PatternKind::Bumps => noise(p, g),
        PatternKind::Dents => {
            let n = noise(p, g);
            n * n * n
        }
        PatternKind::Marble => p.x,
        PatternKind::Wood => (p.x * p.x + p.y * p.y).sqrt(),
        PatternKind::Crackle {
            form,
            metric,
            solid,
            offset,
        } => crackle(p, *form, *metric, *solid, *offset, g),
        PatternKind::Granite => {
            let mut sum = 0.0;
            let mut freq = 1.0;
            for _ in 0..6 {
                sum += (noise(p * 4.0 * freq, g) - 0.5).abs() / freq;
                freq *= 2.0;
            }
            sum * 2.2
        }
        PatternKind::Agate => {
            let t = agate_turbulence(p);
            let v = 0.5 + 0.5 * (TAU * (p.z + AGATE_SWIRL * m.agate_turb * t)).sin();
            v.powf(0.77)
        }
        PatternKind::Wrinkles => {
            // A smooth 1/f sum of ten octaves (no creases, so its slope is smooth
            // too, as POV-Ray's wrinkled normals are).
            let mut sum = 0.0;
            let mut freq = 1.0;
            for _ in 0..10 {
                sum += (noise(p * freq, g) - 0.5) / freq;
                freq *= 2.0;
            }
            (0.5 + WRINKLES_SPREAD * sum).clamp(0.0, 1.0)
        }
        PatternKind::Ripples | PatternKind::Waves => {
            let sources = wave_sources(kind, m);
            let n = sources.len() as f64;
            let sum: f64 = sources
                .map(|(c, l)| l * (TAU * ((p - c).length() * m.frequency / l + m.phase)).sin())
                .sum();
            let spread = if matches!(kind, PatternKind::Waves) {
                WAVES_SPREAD
            } else {
                RIPPLES_SPREAD
            };
            (0.5 + spread * sum / n).clamp(0.0, 1.0)
        }
        PatternKind::Function(f) => f.eval3(p),
        PatternKind::Planar
        | PatternKind::Spherical
        | PatternKind::Cylindrical
        | PatternKind::Boxed
        | PatternKind::Quilted { .. }
        | PatternKind::Spiral1(_)
        | PatternKind::Spiral2(_)
        | PatternKind::Fractal(_) => super::shapes::raw(kind, p),
        PatternKind::Checker
        | PatternKind::Hexagon
        | PatternKind::Square
        | PatternKind::Triangular
        | PatternKind::Brick { .. } => 0.0,
        PatternKind::PigmentPattern(pig) => grey(super::evaluate(pig, p)),
        PatternKind::ImagePattern(im) => super::image_map::value_at(im, p),
        PatternKind::DensityFile(g) => g.value(p),
        PatternKind::Slope(s) => super::slope::value(s, p),
        PatternKind::Average | PatternKind::MaterialMap(_) | PatternKind::Object(_) => 0.0,
    }
}

/// The grey value of a colour as POV-Ray weighs it (its manual's
/// `pigment_pattern`: 0.297 red + 0.589 green + 0.114 blue).
pub fn grey(c: crate::scene::Colour) -> f64 {
    0.297 * c.rgb.x + 0.589 * c.rgb.y + 0.114 * c.rgb.z
}

/// Spread of the `waves` sum around 0.5 per unit of wavelength: each centre's
/// waves rise in proportion to their spacing, 0.2 a unit (measured on
/// POV-Ray 3.7 with `number_of_waves` 1 to 10, each centre's waves told apart
/// by the difference of successive counts: every centre's swing about 0.5
/// times its wave frequency is 0.2000).
const WAVES_SPREAD: f64 = 0.2;

/// The spacing of each `waves` centre's waves (times 1/`frequency`), in the
/// order of [`CENTRES`] (measured on POV-Ray 3.7 as for [`WAVES_SPREAD`]: sine
/// fits over two planes, residual below 2e-4 of the grey range).
const WAVE_LENGTHS: [f64; 10] = [
    1.08800, 1.04162, 2.30856, 1.40984, 1.45098, 1.00863, 1.27718, 2.49584, 4.35404, 5.93426,
];

/// Spread of the `ripples` sum around 0.5: the mean of the centres' sines
/// swings by half the grey range (measured as for [`WAVES_SPREAD`]: a single
/// centre's ripples reach exactly 0 and 1).
const RIPPLES_SPREAD: f64 = 0.5;

/// Spread of the wrinkles sum around 0.5 (fitted to the contrast of POV-Ray's
/// grey-mapped wrinkles).
const WRINKLES_SPREAD: f64 = 1.0;

/// The ten wave centres of `ripples` and `waves`, points on the unit sphere, in
/// the order `number_of_waves` takes them (measured on POV-Ray 3.7: each
/// centre's rings fitted over two planes of a grey-mapped render, to 1e-5).
const CENTRES: [DVec3; 10] = [
    DVec3::new(-0.60438, 0.49205, -0.62659),
    DVec3::new(-0.55257, -0.24608, -0.79631),
    DVec3::new(-0.44455, 0.62333, 0.64330),
    DVec3::new(0.49659, 0.66895, 0.55309),
    DVec3::new(-0.06437, -0.80595, -0.58847),
    DVec3::new(0.24619, -0.91456, -0.32090),
    DVec3::new(-0.66609, -0.59188, -0.45388),
    DVec3::new(-0.52049, -0.38603, -0.76163),
    DVec3::new(0.13795, -0.70464, -0.69602),
    DVec3::new(0.56490, 0.72204, -0.39944),
];

/// The first `number_of_waves` of [`CENTRES`] with the spacing of their waves
/// (the measured [`WAVE_LENGTHS`] for `waves`, 1 for `ripples`).
fn wave_sources(
    kind: &PatternKind,
    m: &PatternMods,
) -> impl ExactSizeIterator<Item = (DVec3, f64)> {
    let waves = matches!(kind, PatternKind::Waves);
    let n = usize::from(m.number_of_waves.clamp(1, 10));
    CENTRES[..n]
        .iter()
        .zip(WAVE_LENGTHS)
        .map(move |(c, l)| (*c, if waves { l } else { 1.0 }))
}

/// The point after the `warp { }` steps and turbulence (`p + turbulence · turb(p)`).
pub fn warp(p: DVec3, m: &PatternMods) -> DVec3 {
    let p = match &m.warps {
        Some(w) => super::warps::apply(w, p),
        None => p,
    };
    if m.turbulence == DVec3::ZERO {
        return p;
    }
    p + m.turbulence * turbulence_vec(p, m.octaves, m.omega, m.lambda)
}

/// Applies a wave form to `v` (already scaled by frequency and shifted by phase).
pub fn wave(w: Wave, v: f64) -> f64 {
    let r = v - v.floor();
    match w {
        Wave::Ramp => r,
        Wave::Triangle => {
            if r < 0.5 {
                2.0 * r
            } else {
                2.0 - 2.0 * r
            }
        }
        Wave::Sine => 0.5 + 0.5 * (TAU * v).sin(),
        Wave::Scallop => (PI * v).sin().abs(),
        Wave::Cubic => r * r * (3.0 - 2.0 * r),
        Wave::Poly(e) => r.powf(e),
    }
}

/// `crackle` at `p`: one random point in each unit cube (uniform in it; measured
/// in POV-Ray 3.7, the mean distances to the nearest and second nearest point,
/// 0.52 and 0.72, are those of one point per unit volume). The value is
/// The 27 cubes around a point's own, by how many axes they step along:
/// its own cube, the 6 sharing a face, the 12 sharing an edge, the 8 corners.
const CRACKLE_CUBES: [[i8; 3]; 27] = {
    let mut out = [[0i8; 3]; 27];
    let mut n = 0;
    let mut steps = 0;
    while steps <= 3 {
        let mut k = 0;
        while k < 27 {
            let c = [(k % 3) as i8 - 1, (k / 3 % 3) as i8 - 1, (k / 9) as i8 - 1];
            if (c[0] != 0) as i32 + (c[1] != 0) as i32 + (c[2] != 0) as i32 == steps {
                out[n] = c;
                n += 1;
            }
            k += 1;
        }
        steps += 1;
    }
    out
};

/// `form · (d1, d2, d3)` over the distances to the nearest three points in the
/// `metric` (searched in the 27 cubes around `p`), or with `solid` the noise at
/// the nearest point, one value per cell (POV-Ray's cells spread alike: mean 0.51,
/// standard deviation 0.13).
fn crackle(p: DVec3, form: DVec3, metric: f64, solid: bool, offset: f64, generator: u8) -> f64 {
    let mut near = if metric == 2.0 || metric == 1.0 {
        nearest_three(p, |r| {
            if metric == 2.0 {
                r.length()
            } else {
                r.x + r.y + r.z
            }
        })
    } else {
        nearest_three_powered(p, metric)
    };
    if solid {
        return noise(near[0].1, generator);
    }
    if offset != 0.0 {
        // Measured on POV-Ray 3.7 (16-bit renders, offset 0 against ±0.3 for
        // metrics 1, 2 and 3): d' = (dᵐ + offsetᵐ)^(1/m), the power of a
        // negative offset keeping its sign where the metric is odd, and 0 where
        // the sum is not positive. (A negative offset under a fractional metric
        // has no real power; rts takes its size.)
        let mut om = offset.powf(metric);
        if om.is_nan() {
            om = offset.abs().powf(metric);
        }
        for n in &mut near {
            let s = n.0.powf(metric) + om;
            n.0 = if s > 0.0 { s.powf(1.0 / metric) } else { 0.0 };
        }
    }
    form.x * near[0].0 + form.y * near[1].0 + form.z * near[2].0
}

/// The nearest three of the points of the 27 cubes around `p` (each cube's
/// [`cell_point`]), by `distance` of the offset's absolute components, nearest
/// first, with their distances.
fn nearest_three(p: DVec3, distance: impl Fn(DVec3) -> f64) -> [(f64, DVec3); 3] {
    let base = p.floor();
    let mut near = [(f64::INFINITY, DVec3::ZERO); 3];
    for dz in -1..=1 {
        for dy in -1..=1 {
            for dx in -1..=1 {
                let cell = base + DVec3::new(f64::from(dx), f64::from(dy), f64::from(dz));
                let point = cell + cell_point(cell);
                keep_nearest(&mut near, distance((p - point).abs()), point);
            }
        }
    }
    near
}

/// Puts `(d, point)` among the nearest three if it is nearer than the third;
/// whether it did.
fn keep_nearest(near: &mut [(f64, DVec3); 3], d: f64, point: DVec3) -> bool {
    let kept = d < near[2].0;
    if kept {
        near[2] = (d, point);
        if near[2].0 < near[1].0 {
            near.swap(1, 2);
            if near[1].0 < near[0].0 {
                near.swap(0, 1);
            }
        }
    }
    kept
}

/// [`nearest_three`] in the metric `(|x|ᵐ + |y|ᵐ + |z|ᵐ)^(1/m)`, whose powers
/// cost most of a crackle: the nearest cubes are visited first and a cube
/// whose terms already sum past the third nearest is passed over before its
/// remaining powers and root (with a margin, so rounding never passes over
/// one the full distance would keep). The same points and distances as
/// [`nearest_three`]: which cubes hold the nearest three does not depend on
/// the order.
fn nearest_three_powered(p: DVec3, metric: f64) -> [(f64, DVec3); 3] {
    let base = p.floor();
    let mut near = [(f64::INFINITY, DVec3::ZERO); 3];
    let mut bound = f64::INFINITY;
    for [dx, dy, dz] in CRACKLE_CUBES {
        let cell = base + DVec3::new(f64::from(dx), f64::from(dy), f64::from(dz));
        let point = cell + cell_point(cell);
        let r = (p - point).abs();
        let tx = r.x.powf(metric);
        if tx > bound {
            continue;
        }
        let txy = tx + r.y.powf(metric);
        if txy > bound {
            continue;
        }
        let sum = txy + r.z.powf(metric);
        if sum > bound {
            continue;
        }
        if keep_nearest(&mut near, sum.powf(1.0 / metric), point)
            && near[2].0.is_finite()
            && metric > 0.0
        {
            bound = (near[2].0 * (1.0 + 1e-9)).powf(metric);
        }
    }
    near
}

/// The random point of unit cube `cell` (its lowest corner), as an offset in
/// [0, 1)³: a fixed integer hash of the cube, so every render agrees.
fn cell_point(cell: DVec3) -> DVec3 {
    let mut h = (cell.x as i64 as u64).wrapping_mul(0x9E37_79B9_7F4A_7C15)
        ^ (cell.y as i64 as u64).wrapping_mul(0xC2B2_AE3D_27D4_EB4F)
        ^ (cell.z as i64 as u64).wrapping_mul(0x1656_67B1_9E37_79F9);
    let mut next = || {
        // splitmix64
        h = h.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = h;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^= z >> 31;
        (z >> 11) as f64 / (1u64 << 53) as f64
    };
    DVec3::new(next(), next(), next())
}

/// The value in [0, 1] of a (non-list) pattern at `p`, with all modifiers.
/// `ripples` and `waves` take `frequency` and `phase` twice, as POV-Ray 3.7
/// does (measured: the same pictures to the 8-bit level under a colour map at
/// frequency 2 and phase 0.3): once for the spacing of their waves, once more
/// mapping the value, so the map wraps.
pub fn value(kind: &PatternKind, p: DVec3, m: &PatternMods) -> f64 {
    let q = warp(p, m);
    let v = raw(kind, q, m);
    match kind {
        // Values already in [0, 1]: no wrapping unless frequency/phase ask for it.
        PatternKind::Bozo
        | PatternKind::Bumps
        | PatternKind::Dents
        | PatternKind::Granite
        | PatternKind::Crackle { .. }
        | PatternKind::Agate
        | PatternKind::Wrinkles
        | PatternKind::Leopard
        | PatternKind::Ripples
        | PatternKind::Waves
        | PatternKind::Radial
        | PatternKind::PigmentPattern(_)
        | PatternKind::ImagePattern(_)
        | PatternKind::Slope(_)
            if m.frequency == 1.0 && m.phase == 0.0 && m.wave == Wave::Ramp =>
        {
            v.clamp(0.0, 1.0)
        }
        k if super::shapes::is_shape(k) => super::shapes::wave(m.wave, v * m.frequency + m.phase),
        // A function's value of exactly 1 stays 1 (as POV-Ray 3.7 shows:
        // `average` of `function { … } color_map { … }` entries that reach 1
        // shows the map's top colour), other values wrap as gradient's do.
        // A density file's full voxels (1) show the top of the map too, and
        // tricubic overshoots above 1 wrap (measured).
        PatternKind::Function(_) | PatternKind::DensityFile(_)
            if m.wave == Wave::Ramp && v * m.frequency + m.phase == 1.0 =>
        {
            1.0
        }
        _ => wave(m.wave, v * m.frequency + m.phase),
    }
}

/// The vector a `bumps` or `wrinkles` normal leans the surface normal against,
/// in pattern space; `None` for the other patterns, which lean against the slope
/// of their [`value`]. As POV-Ray's renders show, these two perturb by a vector
/// noise rather than by a height's slope: its bumps have the feature size of the
/// noise itself (a slope would halve it), and its wrinkles (ten octaves of the
/// component-wise magnitude of the vector noise) lean consistently to one side,
/// which darkens a surface lit from the other.
pub fn lean_vector(kind: &PatternKind, p: DVec3, m: &PatternMods) -> Option<DVec3> {
    match kind {
        PatternKind::Bumps => Some(dnoise(warp(p, m))),
        PatternKind::Wrinkles => {
            let q = warp(p, m);
            let mut sum = DVec3::ZERO;
            let mut freq = 1.0;
            for _ in 0..10 {
                sum += dnoise(q * freq).abs() / freq;
                freq *= 2.0;
            }
            // Leaning *with* the summed magnitudes (the normal gains them).
            Some(-sum)
        }
        PatternKind::Quilted { .. } => Some(-super::shapes::quilt_vector(kind, warp(p, m))),
        PatternKind::Ripples | PatternKind::Waves => {
            // POV-Ray's own normals for these, not their values' slopes: each
            // centre adds its unit direction from the centre times the sine of
            // its waves' phase (times its wave spacing for waves), averaged
            // over the centres; neither frequency nor scale changes the depth
            // (measured on POV-Ray 3.7: lit planes fitted to 1e-3 of the grey
            // range for one, two and ten centres, frequency 0.5 to 3, phase,
            // scale 0.5 and 2). The surface gains the whole vector (see
            // `leans_whole`), so it leans *with* it.
            let q = warp(p, m);
            let sources = wave_sources(kind, m);
            let n = sources.len() as f64;
            let mut sum = DVec3::ZERO;
            for (c, l) in sources {
                let r = q - c;
                let d = r.length();
                if d > 0.0 {
                    let sin = (TAU * (d * m.frequency / l + m.phase)).sin();
                    sum += r * (l * sin / d);
                }
            }
            Some(-sum / n)
        }
        _ => None,
    }
}

/// The gradient of [`value`] at `p`, computed analytically for the slope-based
/// normal patterns normals mostly use (`bozo`, `dents`, `gradient`) without
/// turbulence; `None` for the others, whose slope is taken by differences. Equal to the differences of [`value`] (a unit test checks).
pub fn value_gradient(kind: &PatternKind, p: DVec3, m: &PatternMods) -> Option<DVec3> {
    if m.turbulence != DVec3::ZERO || m.wave != Wave::Ramp || m.warps.is_some() {
        return None;
    }
    let plain = m.frequency == 1.0 && m.phase == 0.0;
    let g = m.noise_generator;
    match kind {
        PatternKind::Bozo if plain => Some(noise_grad(p, g).1),
        PatternKind::Dents if plain => {
            let (n, d) = noise_grad(p, g);
            Some(3.0 * n * n * d)
        }
        PatternKind::Gradient(dir) => Some(*dir * m.frequency),
        _ => None,
    }
}

/// A value in [0, 1) for the unit cube with corner `c` (integer coordinates):
/// a 64-bit mix of the three indices (the `cells` pattern).
fn cell_value(c: DVec3) -> f64 {
    let mut h: u64 = 0x2545_F491_4F6C_DD1D;
    for k in [c.x, c.y, c.z] {
        h = (h ^ k as i64 as u64).wrapping_mul(0x9E37_79B9_7F4A_7C15);
        h ^= h >> 29;
    }
    h ^= h >> 33;
    h = h.wrapping_mul(0xFF51_AFD7_ED55_8CCD);
    h ^= h >> 33;
    h = h.wrapping_mul(0xC4CE_B9FE_1A85_EC53);
    h ^= h >> 33;
    (h >> 11) as f64 / (1u64 << 53) as f64
}

#[cfg(test)]
mod tests {
    /// `crackle` by [`nearest_three`] (every cube in order, every distance in
    /// full) in any metric: what [`nearest_three_powered`] must give.
    fn crackle_reference(p: DVec3, form: DVec3, metric: f64) -> (f64, DVec3) {
        let near = nearest_three(p, |r| {
            if metric == 2.0 {
                r.length()
            } else if metric == 1.0 {
                r.x + r.y + r.z
            } else {
                (r.x.powf(metric) + r.y.powf(metric) + r.z.powf(metric)).powf(1.0 / metric)
            }
        });
        (
            form.x * near[0].0 + form.y * near[1].0 + form.z * near[2].0,
            near[0].1,
        )
    }

    #[test]
    fn crackle_passing_over_far_cells_changes_no_value() {
        let mut x = 0.271_828_18f64;
        let mut next = || {
            x = (x * 9_301.0 + 49_297.0) % 233_280.0;
            x / 233_280.0
        };
        for metric in [1.0, 2.0, 2.5, 0.7, 3.0, 12.0] {
            for _ in 0..3_000 {
                let p = DVec3::new(
                    next() * 20.0 - 10.0,
                    next() * 20.0 - 10.0,
                    next() * 2e3 - 1e3,
                );
                for form in [
                    DVec3::new(-1.0, 1.0, 0.0),
                    DVec3::new(1.0, 0.0, 0.0),
                    DVec3::new(0.2, 0.3, 0.5),
                ] {
                    let (want, nearest) = crackle_reference(p, form, metric);
                    let got = crackle(p, form, metric, false, 0.0, 2);
                    assert_eq!(got.to_bits(), want.to_bits(), "{p} metric {metric}");
                    let solid = crackle(p, form, metric, true, 0.0, 2);
                    assert_eq!(solid.to_bits(), noise(nearest, 2).to_bits(), "{p} solid");
                }
            }
        }
    }

    use super::*;

    fn mods() -> PatternMods {
        PatternMods::default()
    }

    #[test]
    fn gradient_ramps_each_unit() {
        let g = PatternKind::Gradient(DVec3::X);
        assert!((value(&g, DVec3::new(0.25, 7.0, 1.0), &mods()) - 0.25).abs() < 1e-12);
        assert!((value(&g, DVec3::new(-0.25, 0.0, 0.0), &mods()) - 0.75).abs() < 1e-12);
    }

    #[test]
    fn radial_starts_at_x_and_turns_to_minus_z() {
        let m = mods();
        assert!(value(&PatternKind::Radial, DVec3::X, &m).abs() < 1e-12);
        assert!((value(&PatternKind::Radial, -DVec3::Z, &m) - 0.25).abs() < 1e-12);
        assert!((value(&PatternKind::Radial, -DVec3::X, &m) - 0.5).abs() < 1e-12);
    }

    #[test]
    fn onion_and_wood_and_marble() {
        let m = PatternMods {
            wave: Wave::Triangle,
            ..mods()
        };
        assert!(
            (value(&PatternKind::Onion, DVec3::new(0.0, 1.25, 0.0), &mods()) - 0.25).abs() < 1e-12
        );
        assert!((value(&PatternKind::Wood, DVec3::new(0.3, 0.4, 9.0), &m) - 1.0).abs() < 1e-12);
        assert!((value(&PatternKind::Marble, DVec3::new(0.25, 3.0, 0.0), &m) - 0.5).abs() < 1e-12);
    }

    #[test]
    fn leopard_formula() {
        let p = DVec3::new(1.0, 2.0, 3.0);
        let s = (1f64.sin() + 2f64.sin() + 3f64.sin()) / 3.0;
        assert!((value(&PatternKind::Leopard, p, &mods()) - s * s).abs() < 1e-12);
    }

    #[test]
    fn crackle_weighs_the_nearest_cell_points() {
        let kind = |form, metric, solid| PatternKind::Crackle {
            form,
            metric,
            solid,
            offset: 0.0,
        };
        let d1 = kind(DVec3::X, 2.0, false);
        let d2 = kind(DVec3::Y, 2.0, false);
        let edge = kind(DVec3::new(-1.0, 1.0, 0.0), 2.0, false);
        // At a cell's own point the nearest distance is 0.
        let cell = DVec3::new(3.0, -2.0, 5.0);
        let at = cell + cell_point(cell);
        assert!(raw(&d1, at, &mods()).abs() < 1e-12);
        // Everywhere: 0 <= d1 <= d2, and the default form is their difference.
        for i in 0..500 {
            let p = DVec3::new(
                i as f64 * 0.731,
                (i as f64 * 0.377).sin() * 4.0,
                i as f64 * -0.193,
            );
            let (a, b) = (raw(&d1, p, &mods()), raw(&d2, p, &mods()));
            assert!(0.0 <= a && a <= b, "{a} {b}");
            assert!((raw(&edge, p, &mods()) - (b - a)).abs() < 1e-12);
            // The Manhattan distance is never shorter.
            assert!(raw(&kind(DVec3::X, 1.0, false), p, &mods()) >= a - 1e-12);
        }
        // Offset: every distance moves into a fourth dimension (measured
        // on POV-Ray: (dᵐ + oᵐ)^(1/m), a negative power kept for odd m).
        let off = |metric, offset| PatternKind::Crackle {
            form: DVec3::X,
            metric,
            solid: false,
            offset,
        };
        for i in 0..50 {
            let p = DVec3::new(i as f64 * 0.37, 0.3, i as f64 * -0.21);
            let a = raw(&d1, p, &mods());
            let b = raw(&off(2.0, 0.3), p, &mods());
            assert!((b - (a * a + 0.09).sqrt()).abs() < 1e-12);
            let a3 = raw(&kind(DVec3::X, 3.0, false), p, &mods());
            let b3 = raw(&off(3.0, -0.3), p, &mods());
            let want = (a3.powi(3) - 0.027).max(0.0).cbrt();
            assert!((b3 - want).abs() < 1e-12, "{b3} {want}");
        }
        // Solid: one value across a cell (near its point).
        let s = kind(DVec3::X, 2.0, true);
        let v = raw(&s, at, &mods());
        assert_eq!(raw(&s, at + DVec3::splat(1e-3), &mods()), v);
    }

    #[test]
    fn number_of_waves_sums_that_many_centres() {
        // One centre: ripples are one sine of the distance from it.
        let m = PatternMods {
            number_of_waves: 1,
            ..mods()
        };
        let p = DVec3::new(0.7, -0.2, 1.3);
        let d = (p - CENTRES[0]).length();
        let want = (0.5 + RIPPLES_SPREAD * (TAU * d).sin()).clamp(0.0, 1.0);
        assert!((value(&PatternKind::Ripples, p, &m) - want).abs() < 1e-12);
        // The default (10) differs from one centre.
        assert!((value(&PatternKind::Ripples, p, &mods()) - want).abs() > 1e-6);
    }

    #[test]
    fn waves_forms() {
        assert!((wave(Wave::Triangle, 0.75) - 0.5).abs() < 1e-12);
        assert!((wave(Wave::Sine, 0.25) - 1.0).abs() < 1e-12);
        assert!((wave(Wave::Cubic, 0.5) - 0.5).abs() < 1e-12);
        assert!((wave(Wave::Poly(2.0), 0.5) - 0.25).abs() < 1e-12);
    }

    #[test]
    fn hexagon_neighbours_differ() {
        let s3 = 3f64.sqrt();
        let c = hexagon_index(DVec3::ZERO);
        assert_eq!(c, 0);
        // Above in +z: the second entry; below: the third; two cells along x: the first.
        assert_eq!(hexagon_index(DVec3::new(0.0, 0.0, s3)), 1);
        assert_eq!(hexagon_index(DVec3::new(0.0, 0.0, -s3)), 2);
        assert_eq!(hexagon_index(DVec3::new(3.0, 0.0, 0.0)), 0);
        let n1 = hexagon_index(DVec3::new(1.5, 0.0, s3 / 2.0));
        let n2 = hexagon_index(DVec3::new(1.5, 0.0, -s3 / 2.0));
        assert!(n1 != c && n2 != c && n1 != n2);
    }

    #[test]
    fn brick_mortar() {
        let size = DVec3::new(8.0, 3.0, 4.5);
        assert!(is_mortar(DVec3::new(4.0, 2.9, 2.0), size, 0.5));
        assert!(!is_mortar(DVec3::new(4.0, 1.5, 2.0), size, 0.5));
    }
}
