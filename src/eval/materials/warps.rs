//! `warp { … }` blocks in patterns, and the parameters of the fractal patterns.

use super::patterns::PatternSpec;
use crate::diag::{codes, Diagnostic};
use crate::eval::core::cursor::{Cursor, Tok};
use crate::eval::core::{Evaluator, R};
use crate::scene::{MappingWarp, Transform, Warp, WarpStep};
use glam::DVec3;
use std::sync::Arc;

/// What a `warp { }` accepts.
const WARP_KINDS: &[&str] = &[
    "turbulence",
    "repeat",
    "black_hole",
    "cylindrical",
    "spherical",
    "toroidal",
    "planar",
];

/// The modifiers each warp kind takes.
fn warp_items(kind: &str) -> &'static [&'static str] {
    match kind {
        "turbulence" => &["octaves", "omega", "lambda"],
        "repeat" => &["offset", "flip"],
        "black_hole" => &["strength", "falloff", "inverse", "repeat", "turbulence"],
        "toroidal" => &["orientation", "dist_exp", "major_radius"],
        "planar" => &[],
        _ => &["orientation", "dist_exp"],
    }
}

impl Evaluator<'_> {
    /// `warp { KIND … }`.
    pub(crate) fn warp_block(&mut self, c: &mut Cursor) -> R<Warp> {
        let (kind, kspan) = match c.next() {
            Some(Tok::Kw(kw, span)) if WARP_KINDS.contains(&kw) => (kw, span),
            Some(other) => return Err(self.unexpected(c, &other, WARP_KINDS)),
            None => {
                return Err(Diagnostic::error(
                    codes::MISSING_VALUE,
                    c.span,
                    "a warp needs its kind",
                )
                .with_help("write e.g. `warp { turbulence 0.5 }` or `warp { repeat x }`")
                .into())
            }
        };
        let mut w = match kind {
            "turbulence" => Warp::Turbulence {
                amount: {
                    let (v, s) = c.value("the turbulence amount")?;
                    self.to_vec3(&v, s)?
                },
                octaves: 6,
                omega: 0.5,
                lambda: 2.0,
            },
            "repeat" => {
                let (v, s) = c.value("the repeat direction, e.g. x*2")?;
                let d = self.to_vec3(&v, s)?;
                let nonzero: Vec<usize> = (0..3).filter(|&i| d[i] != 0.0).collect();
                if nonzero.len() != 1 {
                    return Err(Diagnostic::error(
                        codes::OUT_OF_RANGE,
                        s,
                        format!(
                            "`repeat` needs a direction along one axis, found <{}, {}, {}>",
                            d.x, d.y, d.z
                        ),
                    )
                    .with_help("write `repeat x*WIDTH`, `repeat y*WIDTH` or `repeat z*WIDTH`")
                    .into());
                }
                Warp::Repeat {
                    axis: nonzero[0],
                    width: d[nonzero[0]],
                    offset: DVec3::ZERO,
                    flip: DVec3::ZERO,
                }
            }
            "black_hole" => {
                let centre = self.take_vec3(c, "the black hole's centre")?;
                c.comma();
                let (v, s) = c.value("the black hole's radius")?;
                let radius = self.to_float(&v, s)?;
                if radius <= 0.0 {
                    return Err(Diagnostic::error(
                        codes::OUT_OF_RANGE,
                        s,
                        format!("a black hole's radius must be positive, found {radius}"),
                    )
                    .into());
                }
                Warp::BlackHole {
                    centre,
                    radius,
                    strength: 1.0,
                    falloff: 2.0,
                    inverse: false,
                    repeat: DVec3::ZERO,
                    turbulence: DVec3::ZERO,
                }
            }
            other => {
                let kind = match other {
                    "cylindrical" => MappingWarp::Cylindrical,
                    "spherical" => MappingWarp::Spherical,
                    "toroidal" => MappingWarp::Toroidal,
                    _ => MappingWarp::Planar,
                };
                Warp::Mapping {
                    kind,
                    orientation: DVec3::Z,
                    dist_exp: 0.0,
                    major_radius: 1.0,
                }
            }
        };
        if let Warp::Mapping {
            kind: MappingWarp::Planar,
            orientation,
            ..
        } = &mut w
        {
            // `planar [<NORMAL>, DISTANCE]`.
            if c.value_next() {
                *orientation = self.take_vec3(c, "the plane's normal")?;
                c.comma();
                self.take_float(c, "the plane's distance")?;
            }
        }
        let _ = kspan;
        while let Some(tok) = c.next() {
            let kw = match tok {
                Tok::Kw(kw, _) if warp_items(kind).contains(&kw) => kw,
                Tok::Comma(_) => continue,
                other => return Err(self.unexpected(c, &other, warp_items(kind))),
            };
            match (&mut w, kw) {
                (Warp::Turbulence { octaves, .. }, "octaves") => {
                    *octaves = self
                        .take_float(c, "the number of octaves")?
                        .clamp(1.0, 10.0) as u32
                }
                (Warp::Turbulence { omega, .. }, "omega") => {
                    *omega = self.take_float(c, "omega")?
                }
                (Warp::Turbulence { lambda, .. }, "lambda") => {
                    *lambda = self.take_float(c, "lambda")?
                }
                (Warp::Repeat { offset, .. }, "offset") => {
                    *offset = self.take_vec3(c, "the offset per repeat")?
                }
                (Warp::Repeat { flip, .. }, "flip") => {
                    *flip = self.take_vec3(c, "the axes to flip")?
                }
                (Warp::BlackHole { strength, .. }, "strength") => {
                    *strength = self.take_float(c, "the strength")?
                }
                (Warp::BlackHole { falloff, .. }, "falloff") => {
                    *falloff = self.take_float(c, "the falloff")?
                }
                (Warp::BlackHole { inverse, .. }, "inverse") => *inverse = true,
                (Warp::BlackHole { repeat, .. }, "repeat") => {
                    *repeat = self.take_vec3(c, "the repeat spacing")?
                }
                (Warp::BlackHole { turbulence, .. }, "turbulence") => {
                    *turbulence = self.take_vec3(c, "the turbulence of the centres")?
                }
                (Warp::Mapping { orientation, .. }, "orientation") => {
                    *orientation = self.take_vec3(c, "the orientation")?
                }
                (Warp::Mapping { dist_exp, .. }, "dist_exp") => {
                    *dist_exp = self.take_float(c, "the distance exponent")?
                }
                (Warp::Mapping { major_radius, .. }, "major_radius") => {
                    *major_radius = self.take_float(c, "the major radius")?
                }
                _ => {}
            }
        }
        Ok(w)
    }
}

/// Adds `warp` to the pattern being read, with the pattern transform written
/// before it (`None`: none yet).
pub(crate) fn push_warp(spec: &mut PatternSpec, warp: &Warp, before: Option<&Transform>) {
    let mut steps: Vec<WarpStep> = spec.mods.warps.as_deref().unwrap_or(&[]).to_vec();
    steps.push(WarpStep {
        warp: warp.clone(),
        before: before
            .filter(|t| t.matrix != glam::DMat4::IDENTITY)
            .map(|t| (t.matrix, t.inverse)),
    });
    spec.mods.warps = Some(Arc::from(steps));
}

impl Evaluator<'_> {
    /// The parameters after `planar`, `spherical`, `cylindrical`, `boxed`,
    /// `quilted`, `spiral1 N`, `spiral2 N`, `mandel ITER`, `julia <C>, ITER`
    /// and `magnet 1|2 mandel ITER | julia <C>, ITER`.
    pub(crate) fn shape_pattern(
        &mut self,
        kw: &str,
        c: &mut Cursor,
    ) -> R<crate::scene::PatternKind> {
        use crate::scene::{Fractal, FractalKind, PatternKind as K};
        let fractal = |kind, iterations: f64| {
            K::Fractal(Fractal {
                kind,
                iterations: iterations.clamp(1.0, 1e9) as u32,
                exponent: 2,
                exterior: (1, 1.0),
                interior: (0, 1.0),
            })
        };
        Ok(match kw {
            "planar" => K::Planar,
            "spherical" => K::Spherical,
            "cylindrical" => K::Cylindrical,
            "boxed" => K::Boxed,
            "quilted" => K::Quilted {
                control0: 1.0,
                control1: 1.0,
            },
            "spiral1" => K::Spiral1(self.take_float(c, "the number of arms")?),
            "spiral2" => K::Spiral2(self.take_float(c, "the number of arms")?),
            "mandel" => fractal(
                FractalKind::Mandel,
                self.take_float(c, "the number of iterations")?,
            ),
            "julia" => {
                let k = self.take_vec3(c, "the julia parameter <re, im>")?;
                c.comma();
                let n = self.take_float(c, "the number of iterations")?;
                fractal(FractalKind::Julia(k.truncate()), n)
            }
            _ => {
                let (v, s) = c.value("the magnet type (1 or 2)")?;
                let t = self.to_float(&v, s)?;
                let julia = match c.next() {
                    Some(Tok::Kw("mandel", _)) => None,
                    Some(Tok::Kw("julia", _)) => {
                        let k = self.take_vec3(c, "the julia parameter <re, im>")?;
                        c.comma();
                        Some(k.truncate())
                    }
                    Some(other) => return Err(self.unexpected(c, &other, &["mandel", "julia"])),
                    None => {
                        return Err(Diagnostic::error(
                            codes::MISSING_VALUE,
                            c.span,
                            "`magnet` needs `mandel` or `julia` after its type",
                        )
                        .with_help("write e.g. `magnet 1 mandel 30`")
                        .into())
                    }
                };
                let n = self.take_float(c, "the number of iterations")?;
                // Checked after the rest is read, so nothing else is reported.
                if t != 1.0 && t != 2.0 {
                    return Err(Diagnostic::error(
                        codes::OUT_OF_RANGE,
                        s,
                        format!("the magnet type must be 1 or 2, found {t}"),
                    )
                    .with_help("write `magnet 1 mandel ITERATIONS` or `magnet 2 …`")
                    .into());
                }
                let kind = match (t == 1.0, julia) {
                    (true, None) => FractalKind::Magnet1Mandel,
                    (true, Some(k)) => FractalKind::Magnet1Julia(k),
                    (false, None) => FractalKind::Magnet2Mandel,
                    (false, Some(k)) => FractalKind::Magnet2Julia(k),
                };
                fractal(kind, n)
            }
        })
    }

    /// `control0`, `control1` (quilted), `exponent`, `exterior`, `interior`
    /// (fractals) and `noise_generator` in a pattern.
    pub(crate) fn shape_modifier(
        &mut self,
        kw: &str,
        c: &mut Cursor,
        spec: &mut PatternSpec,
    ) -> R<()> {
        use crate::scene::PatternKind as K;
        let span = c.last;
        if kw == "noise_generator" {
            let (v, s) = c.value("the noise generator (1, 2 or 3)")?;
            let n = self.to_float(&v, s)?;
            if !(1.0..=3.0).contains(&n) || n.fract() != 0.0 {
                return Err(Diagnostic::error(
                    codes::OUT_OF_RANGE,
                    s,
                    format!("noise_generator must be 1, 2 or 3, found {n}"),
                )
                .with_help("2 is POV-Ray's default")
                .into());
            }
            spec.mods.noise_generator = n as u8;
            return Ok(());
        }
        let owner = match kw {
            "control0" | "control1" => "quilted",
            _ => "mandel`, `julia` or `magnet",
        };
        // The value is read first, so a misplaced modifier is reported once.
        let first = if kw == "exterior" || kw == "interior" {
            let (v, s) = c.value(&format!("the {kw} type (0 to 6)"))?;
            let t = self.to_float(&v, s)?;
            c.comma();
            Some((t, s))
        } else {
            None
        };
        let (v, s) = c.value(&format!("a value after `{kw}`"))?;
        let x = self.to_float(&v, s)?;
        let first = match first {
            Some((t, ts)) if !(0.0..=6.0).contains(&t) || t.fract() != 0.0 => {
                return Err(Diagnostic::error(
                    codes::OUT_OF_RANGE,
                    ts,
                    format!("the {kw} type must be a whole number from 0 to 6, found {t}"),
                )
                .with_help(format!("write `{kw} TYPE, FACTOR` with TYPE 0 to 6"))
                .into());
            }
            Some((t, _)) => t,
            None => 0.0,
        };
        match (&mut spec.kind, kw) {
            (Some(K::Quilted { control0, .. }), "control0") => *control0 = x,
            (Some(K::Quilted { control1, .. }), "control1") => *control1 = x,
            (Some(K::Fractal(f)), "exponent") => {
                if !(2.0..=33.0).contains(&x) || x.fract() != 0.0 {
                    return Err(Diagnostic::error(
                        codes::OUT_OF_RANGE,
                        s,
                        format!(
                            "a fractal's exponent must be a whole number from 2 to 33, found {x}"
                        ),
                    )
                    .into());
                }
                f.exponent = x as u32;
            }
            (Some(K::Fractal(f)), "exterior") => f.exterior = (first as u8, x),
            (Some(K::Fractal(f)), "interior") => f.interior = (first as u8, x),
            _ => {
                return Err(Diagnostic::error(
                    codes::UNKNOWN_PARAMETER,
                    span,
                    format!("`{kw}` applies to the `{owner}` pattern only"),
                )
                .with_help(format!(
                    "write `{}` before it",
                    owner.split('`').next().unwrap_or(owner)
                ))
                .into())
            }
        }
        Ok(())
    }
}

impl Evaluator<'_> {
    /// `irid { AMOUNT [thickness T] [turbulence U] }` in a finish.
    pub(crate) fn irid_block(&mut self, c: &mut Cursor) -> R<crate::scene::Irid> {
        let mut irid = crate::scene::Irid {
            amount: self.take_float(c, "the iridescence amount")?,
            ..Default::default()
        };
        while let Some(tok) = c.next() {
            match tok {
                Tok::Kw("thickness", _) => {
                    irid.thickness = self.take_float(c, "the film thickness")?
                }
                Tok::Kw("turbulence", _) => {
                    irid.turbulence = self.take_float(c, "the thickness turbulence")?
                }
                Tok::Comma(_) => {}
                other => return Err(self.unexpected(c, &other, &["thickness", "turbulence"])),
            }
        }
        Ok(irid)
    }
}
