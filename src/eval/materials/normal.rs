//! `normal { }` blocks: a bump pattern with its size, maps and modifiers.

use super::pattern_blocks::pattern_token;
use super::patterns::{MODIFIERS, PATTERNS};
use super::texture::{list_len, warp_without_pattern};
use crate::diag::{codes, Diagnostic};
use crate::eval::core::cursor::{Cursor, Tok};
use crate::eval::core::transforms::TRANSFORMS;
use crate::eval::core::value::Value;
use crate::eval::core::{Evaluator, Fail, R};
use crate::scene::{compose, Normal, NormalBlend, PatternKind};
use std::sync::Arc;

/// What a `normal { }` accepts.
pub(crate) fn normal_items() -> Vec<&'static str> {
    [
        PATTERNS,
        &["bump_size", "accuracy", "warp"],
        MODIFIERS,
        TRANSFORMS,
    ]
    .concat()
}

impl Evaluator<'_> {
    /// `normal { PATTERN [AMOUNT] [bump_size AMOUNT] modifiers transforms | Name }`.
    pub(crate) fn normal(&mut self, c: &mut Cursor) -> R<Normal> {
        let n = match c.peek() {
            Some(Tok::Val(Value::Normal(_), _)) => match c.next() {
                Some(Tok::Val(Value::Normal(x), _)) => Some((*x).clone()),
                _ => unreachable!(),
            },
            Some(Tok::Val(Value::Poison, _)) => return Err(Fail::silent()),
            _ => None,
        };
        let mut spec = self.new_spec();
        let mut bump = n.as_ref().map_or(0.5, |x| x.bump_size);
        let mut transform = n.as_ref().and_then(|x| x.transform.clone());
        let mut accuracy = n.as_ref().and_then(|x| x.accuracy);
        let mut blend = n.as_ref().and_then(|x| x.blend.clone());
        let mut list: Vec<Normal> = Vec::new();
        if let Some(x) = &n {
            spec.kind = Some(x.kind.clone());
            spec.mods = x.mods.clone();
            spec.wave = Some(x.mods.wave);
        }
        while let Some(tok) = c.next() {
            let (tok, carried) = pattern_token(tok, c);
            let r: R<()> = match tok {
                Tok::Kw(kw, _) if PATTERNS.contains(&kw) => {
                    let r = self.pattern_kw(kw, carried, c, &mut spec, false);
                    // A new pattern replaces a declared normal's map or image.
                    blend = None;
                    if r.is_ok() && spec.kind.as_ref().is_some_and(PatternKind::is_list) {
                        self.list_normals(c, kw, &mut list);
                    }
                    // `gradient x, 0.5`: POV-Ray takes a comma before the amount.
                    if r.is_ok() && matches!(c.peek(), Some(Tok::Comma(_))) {
                        c.comma();
                    }
                    if r.is_ok() && c.value_next() {
                        self.take_float(c, "the bump size").map(|x| bump = x)
                    } else {
                        r
                    }
                }
                Tok::Kw("bump_size", _) => self.take_float(c, "the bump size").map(|x| bump = x),
                Tok::Kw("accuracy", _) => {
                    let (v, s) = c.value("the slope step")?;
                    let a = self.to_float(&v, s)?;
                    if a <= 0.0 {
                        Err(Diagnostic::error(
                            codes::OUT_OF_RANGE,
                            s,
                            format!("a normal's `accuracy` must be positive, found {a}"),
                        )
                        .with_help("POV-Ray's default is 0.02")
                        .into())
                    } else {
                        accuracy = Some(a);
                        Ok(())
                    }
                }
                Tok::Kw(kw, _) if MODIFIERS.contains(&kw) => {
                    self.pattern_modifier(kw, c, &mut spec).map(|_| ())
                }
                Tok::Kw(kw, span) if TRANSFORMS.contains(&kw) => self
                    .transform_kw(kw, span, c)
                    .map(|t| compose(&mut transform, &t)),
                Tok::Block(_, Value::Transform(t), _) => {
                    compose(&mut transform, &t);
                    Ok(())
                }
                Tok::Block(_, Value::NormalMap(m), _) | Tok::Val(Value::NormalMap(m), _) => {
                    blend = Some(Arc::new(NormalBlend::Map((*m).clone())));
                    Ok(())
                }
                Tok::Block(_, Value::SlopeMap(m), _) | Tok::Val(Value::SlopeMap(m), _) => {
                    blend = Some(Arc::new(NormalBlend::Slopes((*m).clone())));
                    Ok(())
                }
                Tok::Block("bump_map", Value::Normal(b), _) => {
                    spec.kind = Some(b.kind.clone());
                    bump = b.bump_size;
                    blend = b.blend.clone();
                    Ok(())
                }
                Tok::Block(_, Value::ColourMap(_) | Value::PigmentMap(_), _) => Ok(()),
                Tok::Block("warp", Value::Warp(w), span) => {
                    if spec.kind.is_none() {
                        Err(warp_without_pattern(span, "normal"))
                    } else {
                        super::warps::push_warp(&mut spec, &w, transform.as_deref());
                        Ok(())
                    }
                }
                Tok::Val(Value::Poison, _) | Tok::Block(_, Value::Poison, _) => Err(Fail::silent()),
                other => Err(self.unexpected(c, &other, &normal_items())),
            };
            if let Err(f) = r {
                self.report(f);
            }
        }
        let kind = spec.kind.clone().unwrap_or(PatternKind::Bumps);
        let mods = spec.final_mods();
        if !list.is_empty() && blend.is_none() {
            blend = Some(Arc::new(NormalBlend::List(list)));
        }
        if kind == PatternKind::Average && blend.is_none() {
            return Err(Diagnostic::error(
                codes::MISSING_VALUE,
                c.span,
                "an `average` normal needs a `normal_map` of the normals it averages",
            )
            .with_help("add `normal_map { [1 bumps 0.5] [1 dents 0.5] }` (the values are weights)")
            .into());
        }
        Ok(Normal {
            kind,
            mods,
            bump_size: if spec.kind.is_none() { 0.0 } else { bump },
            transform,
            accuracy,
            blend,
        })
    }

    /// The `normal { … }` blocks after a list pattern in a normal (`checker
    /// normal { A } normal { B }`); those not written stay flat.
    fn list_normals(&mut self, c: &mut Cursor, kw: &str, list: &mut Vec<Normal>) {
        let max = list_len(kw);
        list.clear();
        while list.len() < max {
            match c.peek() {
                Some(Tok::Block("normal", Value::Normal(_), _) | Tok::Val(Value::Normal(_), _)) => {
                    if let Some(
                        Tok::Block(_, Value::Normal(x), _) | Tok::Val(Value::Normal(x), _),
                    ) = c.next()
                    {
                        list.push((*x).clone());
                    }
                    c.comma();
                }
                _ => break,
            }
        }
        if !list.is_empty() {
            let flat = Normal {
                kind: PatternKind::Bumps,
                mods: Default::default(),
                bump_size: 0.0,
                transform: None,
                accuracy: None,
                blend: None,
            };
            while list.len() < max {
                list.push(flat.clone());
            }
        }
    }
}
