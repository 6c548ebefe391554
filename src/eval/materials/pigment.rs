//! `pigment { }` blocks: a colour, a pattern with its map or list, or an
//! image map, with modifiers and transforms.

use super::pattern_blocks::pattern_token;
use super::patterns::{default_map, PatternSpec, MODIFIERS, PATTERNS};
use super::texture::warp_without_pattern;
use crate::diag::{codes, Diagnostic};
use crate::eval::core::cursor::{Cursor, Tok};
use crate::eval::core::transforms::TRANSFORMS;
use crate::eval::core::value::Value;
use crate::eval::core::{Evaluator, Fail, R};
use crate::scene::{compose, Mapped, Pattern, PatternKind, PatternMap, Pigment, Transform};
use std::sync::Arc;

/// What a `pigment { }` accepts (for "did you mean" and help lists).
pub(crate) fn pigment_items() -> Vec<&'static str> {
    let head = [
        "color",
        "rgb",
        "color_map",
        "colour_map",
        "pigment_map",
        "image_map",
        "warp",
    ];
    [&head[..], PATTERNS, MODIFIERS, TRANSFORMS].concat()
}

fn compose_pattern(p: &mut Pigment, t: &Transform) {
    compose(&mut p.transform, t);
}

/// `pig` looked up at the surface's uv coordinates (`uv_mapping`). The transforms
/// it holds so far belong to the uv lookup; any applied later (by a texture or
/// object) leave it where it is, as in POV-Ray. An image lies flat on the uv
/// square whatever its `map_type`.
pub(crate) fn uv_mapped(mut pig: Pigment) -> Pigment {
    if let Pattern::Image(im) = &pig.pattern {
        let mut im = (**im).clone();
        im.map_type = 0;
        pig.pattern = Pattern::Image(Arc::new(im));
    }
    Pigment {
        pattern: Pattern::Uv(Arc::new(pig)),
        transform: None,
    }
}

impl Evaluator<'_> {
    /// `pigment { COLOUR | PATTERN [entries] [color_map/pigment_map] modifiers |
    /// image_map { … } | Name … transforms }`.
    pub(crate) fn pigment(&mut self, c: &mut Cursor) -> R<Pigment> {
        let start = self.default_texture.pigment.clone();
        self.pigment_from(start, c)
    }

    /// A pigment block's items read over `start`, the pigment in force where
    /// nothing else is said (the default texture's, or a density's 1).
    pub(crate) fn pigment_from(&mut self, start: Pigment, c: &mut Cursor) -> R<Pigment> {
        let mut pig = start;
        let mut pattern_given = false;
        let mut spec = self.new_spec();
        let mut modified = false;
        let mut uv_mapping = false;
        while let Some(tok) = c.next() {
            let (tok, carried) = pattern_token(tok, c);
            let r: R<()> = match tok {
                Tok::Val(Value::Pigment(p), _) if !pattern_given => {
                    pig = (*p).clone();
                    pattern_given = true;
                    if let Pattern::Mapped(m) = &pig.pattern {
                        spec.kind = Some(m.kind.clone());
                        spec.mods = m.mods.clone();
                        spec.wave = Some(m.mods.wave);
                        match &m.map {
                            PatternMap::List(l) => spec.list = l.clone(),
                            other => spec.map = Some(other.clone()),
                        }
                    }
                    if let Pattern::Image(im) = &pig.pattern {
                        if let Some(m) = &im.mods {
                            spec.mods = m.clone();
                        }
                    }
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
                Tok::Block("image_map", Value::Pigment(p), span) => {
                    if pattern_given {
                        Err(self.second_pattern(span))
                    } else {
                        pattern_given = true;
                        pig = (*p).clone();
                        Ok(())
                    }
                }
                Tok::Kw(kw, span) if PATTERNS.contains(&kw) => {
                    if pattern_given {
                        Err(self.second_pattern(span))
                    } else {
                        pattern_given = true;
                        modified = true;
                        pig.transform = None;
                        self.pattern_kw(kw, carried, c, &mut spec, true)
                    }
                }
                Tok::Kw(kw, _) if MODIFIERS.contains(&kw) => {
                    modified = true;
                    self.pattern_modifier(kw, c, &mut spec).map(|_| ())
                }
                Tok::Block(_, Value::ColourMap(m), _) | Tok::Val(Value::ColourMap(m), _) => {
                    modified = true;
                    spec.map = Some(PatternMap::Colours(m));
                    Ok(())
                }
                Tok::Block(_, Value::PigmentMap(m), _) | Tok::Val(Value::PigmentMap(m), _) => {
                    modified = true;
                    spec.map = Some(PatternMap::Pigments(m));
                    Ok(())
                }
                Tok::Kw(kw, span) if TRANSFORMS.contains(&kw) => self
                    .transform_kw(kw, span, c)
                    .map(|t| compose_pattern(&mut pig, &t)),
                Tok::Block(_, Value::Transform(t), _) => {
                    compose_pattern(&mut pig, &t);
                    Ok(())
                }
                // `pigment { Gold filter 0.9 }`: POV-Ray lets a colour written as a
                // name take `filter`/`transmit` after it, as after `color NAME`.
                Tok::Kw(kw @ ("filter" | "transmit"), _)
                    if pattern_given && matches!(pig.pattern, Pattern::Solid(_)) && !modified =>
                {
                    self.take_float(c, "the amount").map(|x| {
                        if let Pattern::Solid(col) = &mut pig.pattern {
                            if kw == "filter" {
                                col.filter = x;
                            } else {
                                col.transmit = x;
                            }
                        }
                    })
                }
                Tok::Kw("quick_color" | "quick_colour", _) => {
                    self.take_colour(c, "a colour").map(|_| ())
                }
                Tok::Kw("uv_mapping", _) => {
                    uv_mapping = true;
                    Ok(())
                }
                // A block that already reported itself (`warp { }`) says nothing more.
                Tok::Block(_, Value::Poison, _) => Err(Fail::silent()),
                Tok::Block("warp", Value::Warp(w), span) => {
                    if spec.kind.is_none() && !matches!(pig.pattern, Pattern::Image(_)) {
                        Err(warp_without_pattern(span, "pigment"))
                    } else {
                        modified = true;
                        super::warps::push_warp(&mut spec, &w, pig.transform.as_deref());
                        Ok(())
                    }
                }
                Tok::Val(Value::Poison, _) => Err(Fail::silent()),
                Tok::Val(v, span) if pattern_given => Err(Diagnostic::error(
                    codes::UNEXPECTED_ITEM,
                    span,
                    format!("{} does not belong after the pigment's pattern", v.kind()),
                )
                .with_help("a pigment has one colour or pattern; use `checker A, B` for two")
                .into()),
                other => Err(self.unexpected(c, &other, &pigment_items())),
            };
            if let Err(f) = r {
                self.report(f);
            }
        }
        if modified {
            if let (None, Pattern::Image(im)) = (&spec.kind, &pig.pattern) {
                // Turbulence and warps of an image map move the point it looks up.
                let mods = spec.final_mods();
                if mods.warps.is_some() || mods.turbulence != glam::DVec3::ZERO {
                    let mut im = (**im).clone();
                    im.mods = Some(mods);
                    pig.pattern = Pattern::Image(Arc::new(im));
                }
            } else if let Some(kind) = spec.kind.clone() {
                pig.pattern = self.build_pattern(kind, &mut spec);
            } else if let Some(map) = spec.map.take() {
                // A map with no pattern: POV-Ray's default pattern is `bozo`... but a
                // lone map is most often a typo; use gradient-free bozo as POV does.
                pig.pattern = Pattern::Mapped(Box::new(Mapped {
                    kind: PatternKind::Bozo,
                    mods: spec.final_mods(),
                    map,
                }));
            }
        }
        if uv_mapping {
            pig = uv_mapped(pig);
        }
        Ok(pig)
    }

    fn build_pattern(&mut self, kind: PatternKind, spec: &mut PatternSpec) -> Pattern {
        let mods = spec.final_mods();
        if kind == PatternKind::Checker && mods.turbulence == glam::DVec3::ZERO {
            let mut l = std::mem::take(&mut spec.list);
            Self::complete_list(&kind, &mut l);
            let b = l.pop().expect("two entries");
            let a = l.pop().expect("two entries");
            return Pattern::Checker(Box::new([a, b]));
        }
        let map = if kind.is_list() {
            let mut l = std::mem::take(&mut spec.list);
            Self::complete_list(&kind, &mut l);
            PatternMap::List(l)
        } else {
            spec.map.take().unwrap_or_else(|| default_map(&kind))
        };
        Pattern::Mapped(Box::new(Mapped { kind, mods, map }))
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
}
