//! `texture`, `pigment`, `finish` and `reflection` blocks.

use super::cursor::{Cursor, Tok};
use super::objects::TRANSFORMS;
use super::value::Value;
use super::{Evaluator, Fail, R};
use crate::diag::{codes, Diagnostic};
use crate::scene::{Colour, Finish, Pattern, Pigment, Reflection, Texture, Transform};
use glam::DVec3;
use std::sync::Arc;

const TEXTURE_ITEMS: &[&str] = &[
    "pigment",
    "finish",
    "translate",
    "rotate",
    "scale",
    "matrix",
    "transform",
];
const PIGMENT_ITEMS: &[&str] = &[
    "color",
    "rgb",
    "checker",
    "translate",
    "rotate",
    "scale",
    "matrix",
    "transform",
];
const FINISH_ITEMS: &[&str] = &[
    "ambient",
    "diffuse",
    "brilliance",
    "phong",
    "phong_size",
    "specular",
    "roughness",
    "metallic",
    "reflection",
];
const REFLECTION_ITEMS: &[&str] = &["fresnel", "falloff", "metallic"];
/// Pattern keywords of POV-Ray that a later release implements.
const LATER_PATTERNS: &[&str] = &[
    "hexagon",
    "brick",
    "gradient",
    "radial",
    "onion",
    "leopard",
    "spotted",
    "bozo",
    "marble",
    "wood",
    "granite",
    "agate",
    "wrinkles",
    "ripples",
    "waves",
    "bumps",
    "dents",
    "image_map",
    "color_map",
    "colour_map",
    "turbulence",
    "octaves",
    "omega",
    "lambda",
    "frequency",
    "phase",
    "uv_mapping",
    "warp",
];
const LATER_FINISH: &[&str] = &[
    "conserve_energy",
    "emission",
    "irid",
    "crand",
    "reflection_exponent",
    "fresnel",
];

fn compose_pattern(p: &mut Pigment, t: &Transform) {
    let cur = p
        .transform
        .as_deref()
        .copied()
        .unwrap_or(Transform::IDENTITY);
    p.transform = Some(Arc::new(cur.then(t)));
}

impl Evaluator<'_> {
    /// `texture { [Name] pigment { … } finish { … } transforms }`.
    pub(crate) fn texture(&mut self, c: &mut Cursor) -> R<Texture> {
        let mut tex = match c.peek() {
            Some(Tok::Val(Value::Texture(_), _)) => match c.next() {
                Some(Tok::Val(Value::Texture(t), _)) => (*t).clone(),
                _ => unreachable!(),
            },
            Some(Tok::Val(Value::Poison, _)) => return Err(Fail::silent()),
            _ => (*self.default_texture).clone(),
        };
        while let Some(tok) = c.next() {
            let r: R<()> = match tok {
                Tok::Block(_, Value::Pigment(p), _) => {
                    tex.pigment = (*p).clone();
                    Ok(())
                }
                Tok::Block(_, Value::Finish(f), _) => {
                    tex.finish = *f;
                    Ok(())
                }
                Tok::Kw(kw, span) if TRANSFORMS.contains(&kw) => self
                    .transform_kw(kw, span, c)
                    .map(|t| compose_pattern(&mut tex.pigment, &t)),
                Tok::Block(_, Value::Transform(t), _) => {
                    compose_pattern(&mut tex.pigment, &t);
                    Ok(())
                }
                other => Err(self.unexpected(c, &other, TEXTURE_ITEMS)),
            };
            if let Err(f) = r {
                self.report(f);
            }
        }
        Ok(tex)
    }

    /// `pigment { COLOUR | checker A, B | Name … transforms }`.
    pub(crate) fn pigment(&mut self, c: &mut Cursor) -> R<Pigment> {
        let mut pig = self.default_texture.pigment.clone();
        let mut pattern_given = false;
        while let Some(tok) = c.next() {
            let r: R<()> = match tok {
                Tok::Val(Value::Pigment(p), _) if !pattern_given => {
                    pig = (*p).clone();
                    pattern_given = true;
                    Ok(())
                }
                Tok::Val(v @ (Value::Colour(_) | Value::Vector(_) | Value::Float(_)), span)
                    if !pattern_given =>
                {
                    pattern_given = true;
                    self.to_colour(&v, span).map(|col| {
                        pig = Pigment {
                            pattern: Pattern::Solid(col),
                            transform: None,
                        }
                    })
                }
                Tok::Kw("checker", span) => {
                    if pattern_given {
                        Err(self.second_pattern(span))
                    } else {
                        pattern_given = true;
                        self.checker(c).map(|p| {
                            pig = Pigment {
                                pattern: p,
                                transform: None,
                            }
                        })
                    }
                }
                Tok::Kw(kw, span) if TRANSFORMS.contains(&kw) => self
                    .transform_kw(kw, span, c)
                    .map(|t| compose_pattern(&mut pig, &t)),
                Tok::Block(_, Value::Transform(t), _) => {
                    compose_pattern(&mut pig, &t);
                    Ok(())
                }
                Tok::Kw("quick_color" | "quick_colour", _) => {
                    self.take_colour(c, "a colour").map(|_| ())
                }
                Tok::Kw(kw, span) | Tok::Block(kw, _, span) if LATER_PATTERNS.contains(&kw) => {
                    Err(Diagnostic::error(
                        codes::UNSUPPORTED,
                        span,
                        format!("`{kw}` in pigments is not implemented in rts yet"),
                    )
                    .with_help("this release supports solid colours and `checker`")
                    .into())
                }
                Tok::Val(Value::Poison, _) => Err(Fail::silent()),
                Tok::Val(v, span) if pattern_given => Err(Diagnostic::error(
                    codes::UNEXPECTED_ITEM,
                    span,
                    format!("{} does not belong after the pigment's pattern", v.kind()),
                )
                .with_help("a pigment has one colour or pattern; use `checker A, B` for two")
                .into()),
                other => Err(self.unexpected(c, &other, PIGMENT_ITEMS)),
            };
            if let Err(f) = r {
                self.report(f);
            }
        }
        Ok(pig)
    }

    fn second_pattern(&self, span: crate::span::Span) -> Fail {
        Diagnostic::error(
            codes::DUPLICATE_PARAMETER,
            span,
            "a pigment has only one pattern",
        )
        .with_help("remove the earlier colour or pattern")
        .into()
    }

    /// The two entries after `checker` (colours or pigments); POV-Ray's defaults are
    /// blue and green.
    fn checker(&mut self, c: &mut Cursor) -> R<Pattern> {
        let mut entries: Vec<Pigment> = Vec::new();
        while entries.len() < 2 {
            let solid = |col: Colour| Pigment {
                pattern: Pattern::Solid(col),
                transform: None,
            };
            match c.peek() {
                Some(Tok::Val(Value::Colour(_) | Value::Vector(_) | Value::Float(_), _)) => {
                    let col = self.take_colour(c, "a colour")?;
                    entries.push(solid(col));
                }
                Some(Tok::Block(_, Value::Pigment(_), _)) => {
                    if let Some(Tok::Block(_, Value::Pigment(p), _)) = c.next() {
                        entries.push((*p).clone());
                    }
                }
                Some(Tok::Val(Value::Pigment(_), _)) => {
                    if let Some(Tok::Val(Value::Pigment(p), _)) = c.next() {
                        entries.push((*p).clone());
                    }
                }
                Some(Tok::Val(Value::Poison, _)) => {
                    c.next();
                    return Err(Fail::silent());
                }
                _ => break,
            }
            c.comma();
        }
        let defaults = [Colour::rgb(0.0, 0.0, 1.0), Colour::rgb(0.0, 1.0, 0.0)];
        while entries.len() < 2 {
            entries.push(Pigment {
                pattern: Pattern::Solid(defaults[entries.len()]),
                transform: None,
            });
        }
        let b = entries.pop().expect("two entries");
        let a = entries.pop().expect("two entries");
        Ok(Pattern::Checker(Box::new([a, b])))
    }

    /// `finish { [Name] ambient … diffuse … phong … reflection … }`.
    pub(crate) fn finish(&mut self, c: &mut Cursor) -> R<Finish> {
        let mut f = match c.peek() {
            Some(Tok::Val(Value::Finish(_), _)) => match c.next() {
                Some(Tok::Val(Value::Finish(x), _)) => *x,
                _ => unreachable!(),
            },
            Some(Tok::Val(Value::Poison, _)) => return Err(Fail::silent()),
            _ => self.default_texture.finish,
        };
        while let Some(tok) = c.next() {
            let r = self.finish_item(&mut f, c, tok);
            if let Err(fail) = r {
                self.report(fail);
            }
        }
        Ok(f)
    }

    fn finish_item(&mut self, f: &mut Finish, c: &mut Cursor, tok: Tok) -> R<()> {
        let nonneg = |ev: &Self, v: f64, span, what: &str| -> R<f64> {
            if v < 0.0 {
                return Err(Diagnostic::error(
                    codes::OUT_OF_RANGE,
                    span,
                    format!("{what} must not be negative, found {v}"),
                )
                .with_help(format!("give {what} 0 or more"))
                .into());
            }
            let _ = ev;
            Ok(v)
        };
        match tok {
            Tok::Kw(
                kw @ ("ambient" | "diffuse" | "brilliance" | "phong" | "phong_size" | "specular"
                | "roughness"),
                span,
            ) => {
                c.once(kw, span)?;
                if kw == "ambient" {
                    let (v, s) = c.value("the ambient amount or colour")?;
                    f.ambient = match v {
                        Value::Float(x) => DVec3::splat(nonneg(self, x, s, "ambient")?),
                        other => self.to_colour(&other, s)?.rgb,
                    };
                    return Ok(());
                }
                let (v, s) = c.value(&format!("a number after `{kw}`"))?;
                let x = nonneg(self, self.to_float(&v, s)?, s, kw)?;
                match kw {
                    "diffuse" => f.diffuse = x,
                    "brilliance" => f.brilliance = x,
                    "phong" => f.phong = x,
                    "phong_size" => f.phong_size = x,
                    "specular" => f.specular = x,
                    _ => {
                        if x == 0.0 {
                            return Err(Diagnostic::error(
                                codes::OUT_OF_RANGE,
                                s,
                                "roughness must be greater than 0",
                            )
                            .with_help("typical values are 0.0005 (sharp) to 0.1 (broad)")
                            .into());
                        }
                        f.roughness = x;
                    }
                }
            }
            Tok::Kw("metallic", span) => {
                c.once("metallic", span)?;
                f.metallic = self.take_optional_float(c, 1.0)?;
            }
            Tok::Kw("reflection", span) => {
                c.once("reflection", span)?;
                let col = self.take_colour(c, "the reflection amount or colour")?;
                f.reflection = Reflection {
                    min: col.rgb,
                    max: col.rgb,
                    ..Reflection::default()
                };
            }
            Tok::Block(_, Value::Reflection(r), span) => {
                c.once("reflection", span)?;
                f.reflection = r;
            }
            Tok::Kw(kw, span) | Tok::Block(kw, _, span) if LATER_FINISH.contains(&kw) => {
                return Err(Diagnostic::error(
                    codes::UNSUPPORTED,
                    span,
                    format!("`{kw}` is not implemented in rts yet"),
                )
                .with_help("see docs/language.md for the finish terms this release supports")
                .into())
            }
            other => return Err(self.unexpected(c, &other, FINISH_ITEMS)),
        }
        Ok(())
    }

    /// `reflection { [MIN,] MAX [fresnel on] [falloff F] [metallic M] }`.
    pub(crate) fn reflection(&mut self, c: &mut Cursor) -> R<Reflection> {
        let mut r = Reflection::default();
        let first = self.take_colour(c, "the reflection amount or colour")?;
        c.comma();
        if c.value_next() {
            let second = self.take_colour(c, "the maximum reflection")?;
            r.min = first.rgb;
            r.max = second.rgb;
        } else {
            r.min = first.rgb;
            r.max = first.rgb;
        }
        while let Some(tok) = c.next() {
            let res: R<()> = match tok {
                Tok::Kw("fresnel", span) => Err(Diagnostic::error(
                    codes::UNSUPPORTED,
                    span,
                    "`fresnel` reflection is not implemented in rts yet",
                )
                .with_help("it needs `interior { ior … }`, which comes with refraction")
                .into()),
                Tok::Kw("falloff", _) => self
                    .take_float(c, "the falloff exponent")
                    .map(|x| r.falloff = x),
                Tok::Kw("metallic", _) => self.take_optional_float(c, 1.0).map(|x| r.metallic = x),
                Tok::Kw("exponent", span) => Err(Diagnostic::error(
                    codes::UNSUPPORTED,
                    span,
                    "`exponent` is not implemented in rts yet",
                )
                .into()),
                other => Err(self.unexpected(c, &other, REFLECTION_ITEMS)),
            };
            if let Err(f) = res {
                self.report(f);
            }
        }
        Ok(r)
    }
}
