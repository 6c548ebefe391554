//! `finish { }` and `reflection { }` blocks.

use crate::diag::{codes, Diagnostic};
use crate::eval::core::cursor::{Cursor, Tok};
use crate::eval::core::value::Value;
use crate::eval::core::{Evaluator, Fail, R};
use crate::scene::{Finish, Reflection};
use glam::DVec3;

pub(crate) const FINISH_ITEMS: &[&str] = &[
    "ambient",
    "diffuse",
    "brilliance",
    "phong",
    "phong_size",
    "specular",
    "roughness",
    "metallic",
    "reflection",
    "emission",
    "conserve_energy",
    "crand",
    "irid",
];

pub(crate) const REFLECTION_ITEMS: &[&str] = &["fresnel", "falloff", "metallic", "exponent"];

const LATER_FINISH: &[&str] = &["fresnel"];

impl Evaluator<'_> {
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
                    // Negative ambient darkens, as in POV-Ray (advanced/balcony.pov).
                    let (v, s) = c.value("the ambient amount or colour")?;
                    f.ambient = match v {
                        Value::Float(x) => DVec3::splat(x),
                        other => self.to_colour(&other, s)?.rgb,
                    };
                    return Ok(());
                }
                if kw == "diffuse" {
                    // `diffuse D [, BACK]`: POV-Ray 3.7's light from behind.
                    let (v, s) = c.value("a number after `diffuse`")?;
                    f.diffuse = nonneg(self, self.to_float(&v, s)?, s, "diffuse")?;
                    if matches!(c.peek(), Some(Tok::Comma(_))) {
                        c.comma();
                        let (v, s) = c.value("the diffuse amount for light from behind")?;
                        f.diffuse_back = nonneg(self, self.to_float(&v, s)?, s, "diffuse")?;
                    }
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
            Tok::Kw("emission", span) => {
                c.once("emission", span)?;
                let (v, s) = c.value("the emission amount or colour")?;
                f.emission = match v {
                    Value::Float(x) => DVec3::splat(nonneg(self, x, s, "emission")?),
                    other => self.to_colour(&other, s)?.rgb,
                };
            }
            Tok::Kw("conserve_energy", _) => {
                f.conserve_energy = self.take_optional_float(c, 1.0)? != 0.0;
            }
            Tok::Kw("crand", _) => {
                f.crand = self.take_float(c, "the crand amount")?;
            }
            Tok::Kw("reflection", span) => {
                c.once("reflection", span)?;
                let col = self.take_colour(c, "the reflection amount or colour")?;
                f.reflection = Reflection {
                    min: col.rgb,
                    max: col.rgb,
                    // A `reflection_exponent` written before still holds.
                    exponent: f.reflection.exponent,
                    ..Reflection::default()
                };
            }
            Tok::Block(_, Value::Reflection(r), span) => {
                c.once("reflection", span)?;
                f.reflection = Reflection {
                    exponent: r.exponent.or(f.reflection.exponent),
                    ..r
                };
            }
            Tok::Kw("reflection_exponent", span) => {
                c.once("reflection_exponent", span)?;
                f.reflection.exponent = Some(self.reflection_exponent(c)?);
            }
            Tok::Block(_, Value::Irid(i), span) => {
                c.once("irid", span)?;
                f.irid = i;
            }
            Tok::Block(_, Value::Poison, _) => return Err(Fail::silent()),
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

    /// The reflection exponent after `exponent` or `reflection_exponent`.
    fn reflection_exponent(&mut self, c: &mut Cursor) -> R<f64> {
        self.take_above_zero(
            c,
            "the reflection exponent",
            "the reflection exponent",
            "1 reflects linearly; lower values darken dim reflections",
        )
    }

    /// `reflection { [MIN,] MAX [fresnel on] [falloff F] [metallic M] [exponent E] }`.
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
                Tok::Kw("fresnel", _) => self
                    .take_optional_float(c, 1.0)
                    .map(|x| r.fresnel = x != 0.0),
                Tok::Kw("falloff", _) => self
                    .take_float(c, "the falloff exponent")
                    .map(|x| r.falloff = x),
                Tok::Kw("metallic", _) => self.take_optional_float(c, 1.0).map(|x| r.metallic = x),
                Tok::Kw("exponent", span) => c
                    .once("exponent", span)
                    .and_then(|()| self.reflection_exponent(c))
                    .map(|x| r.exponent = Some(x)),
                other => Err(self.unexpected(c, &other, REFLECTION_ITEMS)),
            };
            if let Err(f) = res {
                self.report(f);
            }
        }
        Ok(r)
    }
}
