//! `sky_sphere { … }`, `fog { … }`, `rainbow { … }` and `looks_like { … }`.

use crate::diag::{codes, Diagnostic};
use crate::eval::core::cursor::{Cursor, Tok};
use crate::eval::core::transforms::TRANSFORMS;
use crate::eval::core::value::Value;
use crate::eval::core::{Evaluator, R};
use crate::scene::{Fog, FogKind, FogTurbulence, Object, Rainbow, SkySphere, Transform};
use glam::DVec3;

pub(crate) const SKY_ITEMS: &[&str] = &[
    "pigment",
    "translate",
    "rotate",
    "scale",
    "matrix",
    "transform",
];
pub(crate) const FOG_ITEMS: &[&str] = &[
    "fog_type",
    "distance",
    "color",
    "fog_offset",
    "fog_alt",
    "up",
    "turbulence",
    "turb_depth",
    "octaves",
    "omega",
    "lambda",
];

pub(crate) const RAINBOW_ITEMS: &[&str] = &[
    "direction",
    "angle",
    "width",
    "distance",
    "jitter",
    "color_map",
    "up",
    "arc_angle",
    "falloff_angle",
];

impl Evaluator<'_> {
    /// `sky_sphere { [SKY_SPHERE_IDENTIFIER] pigment { … } … transforms }`: a sky
    /// sphere (placed in the scene at top level, or declared).
    pub(crate) fn sky_sphere(&mut self, c: &mut Cursor) -> R<SkySphere> {
        let mut sky = SkySphere {
            pigments: Vec::new(),
            transform: None,
        };
        if let Some(Tok::Val(Value::SkySphere(_), _)) = c.peek() {
            if let Some(Tok::Val(Value::SkySphere(s), _)) = c.next() {
                sky = (*s).clone();
            }
        }
        while let Some(tok) = c.next() {
            let r: R<()> = match tok {
                Tok::Block(_, Value::Pigment(p), _) => {
                    sky.pigments.push((*p).clone());
                    Ok(())
                }
                Tok::Kw(kw, span) if TRANSFORMS.contains(&kw) => {
                    self.transform_kw(kw, span, c).map(|t| {
                        sky.transform = Some(sky.transform.unwrap_or(Transform::IDENTITY).then(&t));
                    })
                }
                Tok::Block(_, Value::Transform(t), _) => {
                    sky.transform = Some(sky.transform.unwrap_or(Transform::IDENTITY).then(&t));
                    Ok(())
                }
                other => Err(self.unexpected(c, &other, SKY_ITEMS)),
            };
            if let Err(f) = r {
                self.report(f);
            }
        }
        if sky.pigments.is_empty() {
            return Err(Diagnostic::error(
                codes::MISSING_VALUE,
                c.span,
                "a sky_sphere needs at least one pigment",
            )
            .with_help("write `sky_sphere { pigment { gradient y color_map { … } } }`")
            .into());
        }
        Ok(sky)
    }

    /// `fog { [fog_type 1|2] distance D COLOUR [fog_offset O fog_alt A up V]
    /// [turbulence T turb_depth D octaves N omega W lambda L] }`, optionally starting
    /// from a declared fog: a fog (added to the scene at top level, or declared).
    pub(crate) fn fog(&mut self, c: &mut Cursor) -> R<Fog> {
        let mut ty = 1.0;
        let mut distance = None;
        let mut colour = None;
        let (mut offset, mut alt, mut up) = (0.0, 1.0, DVec3::Y);
        let mut turb = FogTurbulence {
            amount: DVec3::ZERO,
            depth: 0.5,
            octaves: 6,
            omega: 0.5,
            lambda: 2.0,
        };
        if let Some(Tok::Val(Value::Fog(_), _)) = c.peek() {
            if let Some(Tok::Val(Value::Fog(f), _)) = c.next() {
                distance = Some(f.distance);
                colour = Some(f.colour);
                if let FogKind::Ground {
                    offset: o,
                    alt: a,
                    up: u,
                } = f.kind
                {
                    (ty, offset, alt, up) = (2.0, o, a, u);
                }
                if let Some(t) = f.turbulence {
                    turb = t;
                }
            }
        }
        while let Some(tok) = c.next() {
            let r: R<()> = match tok {
                Tok::Val(Value::Colour(_), _) => {
                    self.take_colour_from(tok).map(|col| colour = Some(col))
                }
                Tok::Kw("fog_type", span) => {
                    c.once("fog_type", span)?;
                    let (v, s) = c.value("the fog type (1 constant, 2 ground)")?;
                    let t = self.to_float(&v, s)?;
                    if t != 1.0 && t != 2.0 {
                        Err(Diagnostic::error(
                            codes::OUT_OF_RANGE,
                            s,
                            format!("`fog_type` is 1 (constant) or 2 (ground fog), found {t}"),
                        )
                        .into())
                    } else {
                        ty = t;
                        Ok(())
                    }
                }
                Tok::Kw(kw @ ("distance" | "fog_alt"), span) => {
                    c.once(kw, span)?;
                    let (v, s) = c.value(&format!("a positive number after `{kw}`"))?;
                    let d = self.to_float(&v, s)?;
                    if d <= 0.0 {
                        Err(Diagnostic::error(
                            codes::OUT_OF_RANGE,
                            s,
                            format!("`{kw}` must be positive, found {d}"),
                        )
                        .with_help("the fog's distance is where it hides about two thirds of what is behind it")
                        .into())
                    } else {
                        if kw == "distance" {
                            distance = Some(d);
                        } else {
                            alt = d;
                        }
                        Ok(())
                    }
                }
                Tok::Kw("fog_offset", span) => {
                    c.once("fog_offset", span)?;
                    self.take_float(c, "the height of the fog's top")
                        .map(|v| offset = v)
                }
                Tok::Kw("up", span) => {
                    c.once("up", span)?;
                    let (v, s) = c.value("the fog's up direction")?;
                    let u = self.to_vec3(&v, s)?;
                    if u.length_squared() == 0.0 {
                        Err(Diagnostic::error(
                            codes::OUT_OF_RANGE,
                            s,
                            "the fog's `up` must not be zero",
                        )
                        .with_help("use `up y`")
                        .into())
                    } else {
                        up = u.normalize();
                        Ok(())
                    }
                }
                Tok::Kw("turbulence", span) => {
                    c.once("turbulence", span)?;
                    self.take_vec3(c, "the turbulence amount (a number or a vector)")
                        .map(|v| turb.amount = v)
                }
                Tok::Kw("turb_depth", span) => {
                    c.once("turb_depth", span)?;
                    let (v, s) = c.value("where along the ray turbulence is taken (0 to 1)")?;
                    let d = self.to_float(&v, s)?;
                    if (0.0..=1.0).contains(&d) {
                        turb.depth = d;
                        Ok(())
                    } else {
                        Err(Diagnostic::error(
                            codes::OUT_OF_RANGE,
                            s,
                            format!("`turb_depth` is between 0 and 1, found {d}"),
                        )
                        .with_help("0 takes the turbulence at the camera, 1 at the surface hit; the default is 0.5")
                        .into())
                    }
                }
                Tok::Kw("octaves", span) => {
                    c.once("octaves", span)?;
                    // As in patterns: POV-Ray keeps 1 to 10 octaves.
                    self.take_float(c, "the number of octaves")
                        .map(|n| turb.octaves = n.clamp(1.0, 10.0) as u32)
                }
                Tok::Kw(kw @ ("omega" | "lambda"), span) => {
                    c.once(kw, span)?;
                    self.take_float(c, kw).map(|v| {
                        if kw == "omega" {
                            turb.omega = v;
                        } else {
                            turb.lambda = v;
                        }
                    })
                }
                other => Err(self.unexpected(c, &other, FOG_ITEMS)),
            };
            if let Err(f) = r {
                self.report(f);
            }
        }
        let Some(distance) = distance else {
            return Err(Diagnostic::error(
                codes::MISSING_VALUE,
                c.span,
                "a fog needs a `distance`",
            )
            .with_help("write `fog { distance 10 color rgb 0.7 }`")
            .into());
        };
        let kind = if ty == 2.0 {
            FogKind::Ground { offset, alt, up }
        } else {
            FogKind::Constant
        };
        Ok(Fog {
            kind,
            distance,
            colour: colour.unwrap_or(crate::scene::Colour::BLACK),
            turbulence: (turb.amount != DVec3::ZERO).then_some(turb),
        })
    }

    /// `rainbow { [RAINBOW_IDENTIFIER] direction <D> angle A width W [distance D]
    /// [jitter J] [up <U>] [arc_angle ARC] [falloff_angle FALL] colour_map { … } }`:
    /// a rainbow (added to the scene at top level, or declared). Defaults and
    /// checks are POV-Ray 3.7's: angle and width 0 (no rainbow), distance 1e7, up
    /// y, arc and falloff 360°; a zero direction, an up along the direction and a
    /// falloff wider than the arc are errors.
    pub(crate) fn rainbow(&mut self, c: &mut Cursor) -> R<Rainbow> {
        let mut rb = Rainbow {
            direction: DVec3::ZERO,
            angle: 0.0,
            width: 0.0,
            distance: 1e7,
            jitter: 0.0,
            colour_map: std::sync::Arc::new(Vec::new()),
            up: DVec3::Y,
            arc_angle: 360.0,
            falloff_angle: 360.0,
        };
        if let Some(Tok::Val(Value::Rainbow(_), _)) = c.peek() {
            if let Some(Tok::Val(Value::Rainbow(r), _)) = c.next() {
                rb = (*r).clone();
            }
        }
        let mut spans = (None, None, None);
        while let Some(tok) = c.next() {
            let r: R<()> = match tok {
                Tok::Kw(kw @ ("direction" | "up"), span) => {
                    c.once(kw, span)?;
                    let (v, s) = c.value(&format!("a vector after `{kw}`"))?;
                    self.to_vec3(&v, s).map(|d| {
                        if kw == "direction" {
                            rb.direction = d;
                            spans.0 = Some(s);
                        } else {
                            rb.up = d;
                            spans.1 = Some(s);
                        }
                    })
                }
                Tok::Kw(kw @ ("angle" | "width" | "jitter"), span) => {
                    c.once(kw, span)?;
                    self.take_float(c, &format!("a number after `{kw}`"))
                        .map(|v| match kw {
                            "angle" => rb.angle = v,
                            "width" => rb.width = v,
                            _ => rb.jitter = v,
                        })
                }
                Tok::Kw(kw @ ("arc_angle" | "falloff_angle"), span) => {
                    c.once(kw, span)?;
                    let (v, s) = c.value(&format!("an angle in degrees after `{kw}`"))?;
                    let a = self.to_float(&v, s)?;
                    if !(0.0..=360.0).contains(&a) {
                        Err(Diagnostic::error(
                            codes::OUT_OF_RANGE,
                            s,
                            format!("`{kw}` is between 0 and 360 degrees, found {a}"),
                        )
                        .with_help("360 (the default) is the whole circle")
                        .into())
                    } else {
                        if kw == "arc_angle" {
                            rb.arc_angle = a;
                        } else {
                            rb.falloff_angle = a;
                        }
                        spans.2 = Some(s);
                        Ok(())
                    }
                }
                Tok::Kw("distance", span) => {
                    c.once("distance", span)?;
                    let (v, s) = c.value("a positive number after `distance`")?;
                    let d = self.to_float(&v, s)?;
                    if d <= 0.0 {
                        Err(Diagnostic::error(
                            codes::OUT_OF_RANGE,
                            s,
                            format!("`distance` must be positive, found {d}"),
                        )
                        .with_help("as a fog's: leave it out (1e7) to keep the rainbow off objects")
                        .into())
                    } else {
                        rb.distance = d;
                        Ok(())
                    }
                }
                Tok::Block(_, Value::ColourMap(m), _) => {
                    rb.colour_map = m;
                    Ok(())
                }
                other => Err(self.unexpected(c, &other, RAINBOW_ITEMS)),
            };
            if let Err(f) = r {
                self.report(f);
            }
        }
        let span = c.span;
        let fail = |at: Option<crate::span::Span>, msg: &str, help: &str| {
            Err(
                Diagnostic::error(codes::OUT_OF_RANGE, at.unwrap_or(span), msg.to_string())
                    .with_help(help.to_string())
                    .into(),
            )
        };
        if rb.direction.length_squared() == 0.0 {
            return fail(
                spans.0,
                "a rainbow needs a non-zero `direction`",
                "give the direction the sunlight travels in, e.g. `direction <-0.2, -0.2, 1>` (the rainbow rings it)",
            );
        }
        rb.direction = rb.direction.normalize();
        if rb.up.length_squared() == 0.0 || rb.up.cross(rb.direction).length_squared() < 1e-20 {
            return fail(
                spans.1,
                "the rainbow's `up` lies along its `direction`",
                "`up` marks the middle of the arc: give a vector across the direction, e.g. `up y`",
            );
        }
        // Made perpendicular to the direction here, once, as the scene type says.
        rb.up = rb.direction.cross(rb.up.cross(rb.direction)).normalize();
        if rb.falloff_angle > rb.arc_angle {
            return fail(
                spans.2,
                &format!(
                    "the rainbow's `falloff_angle` ({}) is wider than its `arc_angle` ({})",
                    rb.falloff_angle, rb.arc_angle
                ),
                "the falloff angle is the part of the arc at full strength: make it no wider than the arc",
            );
        }
        if rb.colour_map.is_empty() {
            return Err(Diagnostic::error(
                codes::MISSING_VALUE,
                span,
                "a rainbow needs a `color_map`",
            )
            .with_help("e.g. `color_map { [0 rgbf <1, 0, 1, 1>] [0.5 rgbf <0, 1, 0, 0.8>] [1 rgbf <1, 0, 0, 1>] }` (index 0 at the inner edge)")
            .into());
        }
        Ok(rb)
    }

    /// `looks_like { OBJECT }` or `projected_through { OBJECT }` (`kw`): the object.
    pub(crate) fn looks_like(&mut self, c: &mut Cursor, kw: &str) -> R<Object> {
        let obj = match c.next() {
            Some(Tok::Block(_, Value::Object(o), _) | Tok::Val(Value::Object(o), _)) => {
                (*o).clone()
            }
            Some(Tok::Block(_, Value::Poison, _) | Tok::Val(Value::Poison, _)) => {
                return Err(crate::eval::core::Fail::silent())
            }
            Some(other) => return Err(self.unexpected(c, &other, &["an object"])),
            None => {
                return Err(Diagnostic::error(
                    codes::MISSING_VALUE,
                    c.span,
                    format!("`{kw}` needs an object"),
                )
                .with_help(format!(
                    "write `{kw} {{ sphere {{ 0, 0.2 pigment {{ rgb 1 }} }} }}`"
                ))
                .into())
            }
        };
        if let Some(t) = c.next() {
            return Err(self.unexpected(c, &t, &["one object"]));
        }
        Ok(obj)
    }

    /// A colour value already taken from the cursor.
    fn take_colour_from(&mut self, tok: Tok) -> R<crate::scene::Colour> {
        match tok {
            Tok::Val(v, s) => self.to_colour(&v, s),
            _ => Err(crate::eval::core::Fail::silent()),
        }
    }
}
