//! `texture { }` blocks, plain, layered or patterned, `tiles { }` and
//! `texture_map { }`.

use super::pattern_blocks::pattern_token;
use super::patterns::{map_entry_value, PatternSpec, MODIFIERS, PATTERNS};
use super::pigment::uv_mapped;
use crate::diag::{codes, Diagnostic};
use crate::eval::core::cursor::{Cursor, Tok};
use crate::eval::core::transforms::TRANSFORMS;
use crate::eval::core::value::Value;
use crate::eval::core::{Evaluator, Fail, R};
use crate::scene::{
    PatternKind, PatternedTexture, Texture, TextureEntries, TextureMapEntries, Transform,
};
use crate::span::Span;
use std::sync::Arc;

pub(crate) const TEXTURE_ITEMS: &[&str] = &[
    "pigment",
    "normal",
    "finish",
    "texture_map",
    "translate",
    "rotate",
    "scale",
    "matrix",
    "transform",
    "uv_mapping",
];

/// What a `texture { }` accepts: its own items, and the patterns and modifiers of
/// a patterned texture.
pub(crate) fn texture_items() -> Vec<&'static str> {
    [TEXTURE_ITEMS, PATTERNS, MODIFIERS, &["warp"]].concat()
}

/// A texture's pattern being read: its keyword, modifiers, textures and the
/// transforms written in its block (applied to the whole texture at the end).
struct TexturePatternSpec {
    keyword: &'static str,
    span: Span,
    spec: PatternSpec,
    map: Option<TextureMapEntries>,
    list: Vec<Arc<Texture>>,
    transform: Transform,
    /// Something in the block failed and was reported.
    failed: bool,
}

/// How many textures list pattern `kw` chooses between.
pub(super) fn list_len(kw: &str) -> usize {
    match kw {
        "hexagon" => 3,
        "square" => 4,
        "triangular" => 6,
        _ => 2,
    }
}

/// A pigment, normal or finish written in a patterned texture.
fn own_item_of_patterned(what: &str, span: Span) -> Fail {
    Diagnostic::error(
        codes::UNEXPECTED_ITEM,
        span,
        format!("a patterned texture has no {what} of its own"),
    )
    .with_label("inside a texture whose pattern chooses whole textures")
    .with_help("put it inside each texture the pattern chooses, or in the texture_map entries")
    .into()
}

/// A `texture { }` after a list pattern's textures are all given.
fn extra_texture(p: &TexturePatternSpec, span: Span) -> Fail {
    let n = list_len(p.keyword);
    let count = if n == 3 { "three" } else { "two" };
    if p.list.len() < n {
        return Diagnostic::error(
            codes::UNEXPECTED_ITEM,
            span,
            format!("the textures of `{}` come right after it", p.keyword),
        )
        .with_secondary(p.span, "this pattern")
        .with_help(format!(
            "move the {count} `texture {{ … }}` blocks just after `{}`, before modifiers and transforms",
            p.keyword
        ))
        .into();
    }
    Diagnostic::error(
        codes::UNEXPECTED_ITEM,
        span,
        format!(
            "`{}` chooses between {count} textures; this is one more",
            p.keyword
        ),
    )
    .with_secondary(p.span, "this pattern")
    .with_help(format!(
        "remove this texture (`{}` takes {count})",
        p.keyword
    ))
    .into()
}

/// `warp { }` written before any pattern in a `what` block.
pub(super) fn warp_without_pattern(span: Span, what: &str) -> Fail {
    Diagnostic::error(
        codes::WARP_WITHOUT_PATTERN,
        span,
        format!("a warp needs a pattern before it in this {what}"),
    )
    .with_label("nothing to warp yet")
    .with_help("write the pattern first, e.g. `bozo warp { turbulence 0.5 }`")
    .into()
}

/// Lays texture `top` over the texture an object already has (`texture { A }
/// texture { B }`: B over A, as POV-Ray links them). A patterned texture cannot be
/// layered, over or under (POV-Ray 3.7 refuses both); `span` is `top`'s block.
pub(crate) fn layer_texture(
    below: Option<&Arc<Texture>>,
    top: Arc<Texture>,
    span: Span,
) -> R<Arc<Texture>> {
    let Some(below) = below else { return Ok(top) };
    if top.patterned.is_some() || below.patterned.is_some() {
        let msg = if top.patterned.is_some() {
            "a patterned texture cannot be layered over another texture"
        } else {
            "a texture cannot be layered over a patterned texture"
        };
        return Err(Diagnostic::error(codes::PATTERNED_LAYER, span, msg)
            .with_label("layered over the texture before it")
            .with_help(
                "give the object one texture, or put the layers inside the textures the pattern chooses (a declared layered texture can be a texture_map entry)",
            )
            .into());
    }
    let mut t = (*top).clone();
    fn set_bottom(t: &mut Texture, below: &Arc<Texture>) {
        match &mut t.under {
            Some(u) => {
                let mut inner = (**u).clone();
                set_bottom(&mut inner, below);
                *u = Arc::new(inner);
            }
            None => t.under = Some(below.clone()),
        }
    }
    set_bottom(&mut t, below);
    Ok(Arc::new(t))
}

/// Refuses a `pigment`, `normal` or `finish` (`what`) given to an object whose
/// texture is patterned: POV-Ray 3.7 would layer it over the patterned texture,
/// which it does not allow.
pub(crate) fn check_not_patterned(texture: Option<&Arc<Texture>>, what: &str, span: Span) -> R<()> {
    if texture.is_some_and(|t| t.patterned.is_some()) {
        return Err(Diagnostic::error(
            codes::PATTERNED_LAYER,
            span,
            format!("a `{what}` cannot be added to an object whose texture is patterned"),
        )
        .with_label("the object's texture is chosen by a pattern")
        .with_help(format!(
            "put the `{what}` inside each texture the pattern chooses"
        ))
        .into());
    }
    Ok(())
}

impl Evaluator<'_> {
    /// `texture { [Name] pigment { … } finish { … } transforms }`, or a patterned
    /// texture: `texture { [Name] PATTERN texture { … } texture { … } modifiers
    /// transforms }` (list patterns) or `texture { PATTERN texture_map { … }
    /// modifiers transforms }`.
    pub(crate) fn texture(&mut self, c: &mut Cursor) -> R<Texture> {
        let (mut tex, declared) = match c.peek() {
            // `tiles { … }` (POV-Ray's older checker of textures) stands for the
            // patterned texture it makes, like a declared one.
            Some(Tok::Val(Value::Texture(_), _) | Tok::Block("tiles", Value::Texture(_), _)) => {
                match c.next() {
                    Some(
                        Tok::Val(Value::Texture(t), _) | Tok::Block("tiles", Value::Texture(t), _),
                    ) => ((*t).clone(), true),
                    _ => unreachable!(),
                }
            }
            Some(Tok::Val(Value::Poison, _)) => return Err(Fail::silent()),
            _ => ((*self.default_texture).clone(), false),
        };
        // A declared patterned texture takes transforms only.
        let mut declared_patterned = tex.patterned.is_some();
        // Whether the texture has items of its own: a declared texture it starts
        // from, or a pigment, normal or finish written in this block.
        let mut plain_items = declared;
        // The pattern written in this block, with its textures and transforms.
        let mut pat: Option<TexturePatternSpec> = None;
        let mut uv_mapping: Option<Span> = None;
        while let Some(tok) = c.next() {
            let (tok, carried) = pattern_token(tok, c);
            // `pigment { … }`, `finish { … }`, `normal { … }` modify the texture's own.
            let tok = match tok {
                Tok::Deferred(b) => {
                    let base = if pat.is_some() || declared_patterned {
                        None
                    } else {
                        match b.block.keyword.name {
                            "pigment" => Some(Value::Pigment(Arc::new(tex.pigment.clone()))),
                            "finish" => Some(Value::Finish(Arc::new(tex.finish))),
                            _ => tex.normal.clone().map(|n| Value::Normal(Arc::new(n))),
                        }
                    };
                    self.undefer(&b, base)
                }
                t => t,
            };
            let r: R<()> = match tok {
                // POV-Ray also takes a declared pigment, finish or normal written
                // bare inside a texture: `texture { Jade }`.
                Tok::Block(
                    kw,
                    v @ (Value::Pigment(_) | Value::Finish(_) | Value::Normal(_)),
                    span,
                ) if pat.is_some() || declared_patterned => {
                    let _ = v;
                    Err(own_item_of_patterned(kw, span))
                }
                Tok::Val(v @ (Value::Pigment(_) | Value::Finish(_) | Value::Normal(_)), span)
                    if pat.is_some() || declared_patterned =>
                {
                    Err(own_item_of_patterned(v.kind(), span))
                }
                Tok::Block(_, Value::Pigment(p), _) | Tok::Val(Value::Pigment(p), _) => {
                    plain_items = true;
                    tex.pigment = (*p).clone();
                    Ok(())
                }
                Tok::Block(_, Value::Finish(f), _) | Tok::Val(Value::Finish(f), _) => {
                    plain_items = true;
                    tex.finish = *f;
                    Ok(())
                }
                Tok::Block(_, Value::Normal(n), _) | Tok::Val(Value::Normal(n), _) => {
                    plain_items = true;
                    tex.normal = Some((*n).clone());
                    Ok(())
                }
                Tok::Kw(kw, span) if PATTERNS.contains(&kw) => {
                    self.texture_pattern(kw, span, carried, c, &mut pat, plain_items)
                }
                Tok::Kw(kw, span) if MODIFIERS.contains(&kw) && pat.is_some() => {
                    let spec = &mut pat.as_mut().expect("checked").spec;
                    let _ = span;
                    self.pattern_modifier(kw, c, spec).map(|_| ())
                }
                Tok::Block("material_map", Value::Texture(t), span) => {
                    if pat.is_some() || plain_items {
                        Err(Diagnostic::error(
                            codes::UNEXPECTED_ITEM,
                            span,
                            "a `material_map` is the whole texture",
                        )
                        .with_help("write it alone in its `texture { material_map { … } }`, with transforms only")
                        .into())
                    } else {
                        tex = (*t).clone();
                        plain_items = true;
                        declared_patterned = true;
                        Ok(())
                    }
                }
                Tok::Block("texture_map", Value::TextureMap(m), span) => {
                    self.set_texture_map(m, span, &mut pat, declared_patterned)
                }
                Tok::Block("texture", Value::Texture(_), span) if pat.is_some() => {
                    Err(extra_texture(pat.as_ref().expect("checked"), span))
                }
                Tok::Kw(kw, span) if TRANSFORMS.contains(&kw) => {
                    self.transform_kw(kw, span, c).map(|t| match &mut pat {
                        Some(p) => p.transform = p.transform.then(&t),
                        None => tex.transform_patterns(&t),
                    })
                }
                Tok::Block(_, Value::Transform(t), _) => {
                    match &mut pat {
                        Some(p) => p.transform = p.transform.then(&t),
                        None => tex.transform_patterns(&t),
                    }
                    Ok(())
                }
                Tok::Block(_, Value::Poison, _) | Tok::Val(Value::Poison, _) => {
                    // Reported already (a texture_map with a bad entry, …): the
                    // pattern's own checks would only repeat it.
                    if let Some(p) = &mut pat {
                        p.failed = true;
                    }
                    Err(Fail::silent())
                }
                Tok::Block("warp", Value::Warp(w), span) => match &mut pat {
                    Some(p) => {
                        super::warps::push_warp(&mut p.spec, &w, Some(&p.transform));
                        Ok(())
                    }
                    None => Err(warp_without_pattern(span, "texture")),
                },
                Tok::Kw("uv_mapping", span) => {
                    uv_mapping = Some(span);
                    Ok(())
                }
                other => Err(self.unexpected(c, &other, &texture_items())),
            };
            if let Err(f) = r {
                self.report(f);
            }
        }
        if let Some(span) = uv_mapping {
            if pat.is_some() || declared_patterned {
                self.report(
                    Diagnostic::error(
                        codes::UNSUPPORTED,
                        span,
                        "`uv_mapping` on a patterned texture is not implemented",
                    )
                    .with_help("write `uv_mapping` in the pigments of the textures it chooses")
                    .into(),
                );
            } else {
                // The texture's pigment, with the transforms written in this
                // block, is looked up at the surface's uv coordinates.
                tex.pigment = uv_mapped(std::mem::take(&mut tex.pigment));
            }
        }
        match pat {
            Some(p) => self.finish_patterned(p),
            None => Ok(tex),
        }
    }

    /// `tiles { TEXTURE… tile2 TEXTURE… }`: POV-Ray's older spelling of a checker
    /// of two textures (several textures in a row on one side are layers).
    pub(crate) fn tiles(&mut self, c: &mut Cursor) -> R<Texture> {
        let mut sides: [Option<Arc<Texture>>; 2] = [None, None];
        let mut side = 0;
        let mut tile2: Option<Span> = None;
        while let Some(tok) = c.next() {
            let r: R<()> = match tok {
                Tok::Block("texture", Value::Texture(t), span) => {
                    layer_texture(sides[side].as_ref(), t, span).map(|l| sides[side] = Some(l))
                }
                Tok::Kw("tile2", span) if tile2.is_none() => {
                    tile2 = Some(span);
                    side = 1;
                    Ok(())
                }
                Tok::Block(_, Value::Poison, _) => Err(Fail::silent()),
                other => Err(self.unexpected(c, &other, &["texture", "tile2"])),
            };
            if let Err(f) = r {
                self.report(f);
            }
        }
        let missing = |what: &str, help: &str| -> Fail {
            Diagnostic::error(
                codes::MISSING_VALUE,
                c.span,
                format!("`tiles` needs {what}"),
            )
            .with_help(help.to_string())
            .into()
        };
        let [Some(a), Some(b)] = sides else {
            return Err(if tile2.is_none() {
                missing(
                    "`tile2` between its two textures",
                    "write `tiles { texture { … } tile2 texture { … } }`",
                )
            } else {
                missing(
                    "a texture on each side of `tile2`",
                    "write `tiles { texture { … } tile2 texture { … } }`",
                )
            });
        };
        let span = c.span;
        // Measured against POV-Ray 3.7: `tiles`' first texture lies where
        // `checker`'s second does.
        let toks = vec![
            Tok::Kw("checker", span),
            Tok::Block("texture", Value::Texture(b), span),
            Tok::Block("texture", Value::Texture(a), span),
        ];
        let mut inner = Cursor::new(toks, "texture", span);
        self.texture(&mut inner)
    }

    /// Reads pattern keyword `kw` (already taken) in a texture, and for list
    /// patterns the textures after it.
    fn texture_pattern(
        &mut self,
        kw: &'static str,
        span: Span,
        carried: Option<PatternKind>,
        c: &mut Cursor,
        pat: &mut Option<TexturePatternSpec>,
        has_own_items: bool,
    ) -> R<()> {
        let conflict: Option<Fail> = if pat.is_some() {
            Some(
                Diagnostic::error(
                    codes::DUPLICATE_PARAMETER,
                    span,
                    "a texture has only one pattern",
                )
                .with_help("remove one of the patterns")
                .into(),
            )
        } else if has_own_items {
            Some(Diagnostic::error(
                codes::UNEXPECTED_ITEM,
                span,
                format!("`{kw}` would make this a patterned texture, but it already has its own pigment, normal or finish"),
            )
            .with_label("pattern of whole textures")
            .with_help(format!(
                "write a separate `texture {{ {kw} … }}`, and give each texture the pattern chooses its own pigment, normal and finish"
            ))
            .into())
        } else {
            None
        };
        // The pattern and its textures are read even after a conflict, so they are
        // not reported again as out of place.
        let mut spec = self.new_spec();
        let r = self.pattern_kw(kw, carried, c, &mut spec, false);
        let mut p = TexturePatternSpec {
            keyword: kw,
            span,
            spec,
            map: None,
            list: Vec::new(),
            transform: Transform::IDENTITY,
            failed: conflict.is_some() || r.is_err(),
        };
        if p.spec.kind.as_ref().is_some_and(|k| k.is_list()) {
            let max = list_len(kw);
            let mut told = false;
            loop {
                match c.peek() {
                    Some(Tok::Block("texture", Value::Texture(_), _)) if p.list.len() < max => {
                        if let Some(Tok::Block(_, Value::Texture(t), _)) = c.next() {
                            p.list.push(t);
                        }
                    }
                    Some(Tok::Val(Value::Texture(_), s)) => {
                        let s = *s;
                        c.next();
                        p.failed = true;
                        if !std::mem::replace(&mut told, true) {
                            self.report(
                                Diagnostic::error(
                                    codes::UNEXPECTED_ITEM,
                                    s,
                                    format!(
                                        "the textures of `{kw}` are written as `texture {{ … }}` blocks"
                                    ),
                                )
                                .with_help("wrap each name in a block: `texture { Name }`")
                                .into(),
                            );
                        }
                    }
                    Some(Tok::Comma(_)) => {
                        c.next();
                    }
                    _ => break,
                }
            }
        }
        *pat = Some(p);
        match conflict {
            Some(f) => Err(f),
            None => r,
        }
    }

    /// `texture_map { … }` in a texture.
    fn set_texture_map(
        &mut self,
        m: TextureMapEntries,
        span: Span,
        pat: &mut Option<TexturePatternSpec>,
        declared_patterned: bool,
    ) -> R<()> {
        let Some(p) = pat else {
            let help = if declared_patterned {
                "a declared patterned texture keeps its own map; write a new `texture { PATTERN texture_map { … } }`"
            } else {
                "write the pattern first, e.g. `texture { gradient y texture_map { … } }`"
            };
            return Err(Diagnostic::error(
                codes::MISSING_VALUE,
                span,
                "`texture_map` needs a pattern before it",
            )
            .with_label("no pattern to map")
            .with_help(help)
            .into());
        };
        if p.spec.kind.as_ref().is_some_and(|k| k.is_list()) {
            let (count, blocks) = if list_len(p.keyword) == 3 {
                ("three", "texture { … } texture { … } texture { … }")
            } else {
                ("two", "texture { … } texture { … }")
            };
            return Err(Diagnostic::error(
                codes::UNEXPECTED_ITEM,
                span,
                format!(
                    "`{}` chooses between {count} textures and takes no `texture_map`",
                    p.keyword
                ),
            )
            .with_secondary(p.span, "this pattern")
            .with_help(format!(
                "write its {count} textures right after it: `{} {blocks}`",
                p.keyword
            ))
            .into());
        }
        if p.map.is_some() {
            return Err(Diagnostic::error(
                codes::DUPLICATE_PARAMETER,
                span,
                "`texture_map` is given twice in this `texture`",
            )
            .with_label("second time")
            .with_help("remove one of the `texture_map`s")
            .into());
        }
        p.map = Some(m);
        Ok(())
    }

    /// The patterned texture `p` describes, once its block is read.
    fn finish_patterned(&mut self, mut p: TexturePatternSpec) -> R<Texture> {
        let Some(kind) = p.spec.kind.clone().filter(|_| !p.failed) else {
            return Err(Fail::silent());
        };
        let entries = if kind.is_list() {
            // Textures not written are the default texture (measured: POV-Ray
            // 3.7 fills them from `#default`).
            while p.list.len() < list_len(p.keyword) {
                p.list.push(self.default_texture.clone());
            }
            TextureEntries::List(std::mem::take(&mut p.list))
        } else {
            match p.map.take() {
                Some(m) => TextureEntries::Map(m),
                None => {
                    return Err(Diagnostic::error(
                        codes::MISSING_VALUE,
                        p.span,
                        format!("a texture with the `{}` pattern needs a `texture_map {{ … }}`", p.keyword),
                    )
                    .with_label("pattern without textures")
                    .with_help(format!(
                        "add `texture_map {{ [0 Texture_A] [1 Texture_B] }}`, or use `pigment {{ {} … }}` for a pattern of colours",
                        p.keyword
                    ))
                    .into())
                }
            }
        };
        let mut tex = Texture {
            patterned: Some(Arc::new(PatternedTexture {
                kind,
                mods: p.spec.final_mods(),
                transform: None,
                entries,
            })),
            ..Texture::default()
        };
        if p.transform != Transform::IDENTITY {
            tex.transform_patterns(&p.transform);
        }
        Ok(tex)
    }

    /// `texture_map { [v TEXTURE-BODY] … }` (also a declared map as the first item).
    pub(crate) fn texture_map(&mut self, c: &mut Cursor) -> R<Vec<(f64, Arc<Texture>)>> {
        let mut entries: Vec<(f64, Arc<Texture>)> = Vec::new();
        if let Some(Tok::Val(Value::TextureMap(_), _)) = c.peek() {
            if let Some(Tok::Val(Value::TextureMap(m), _)) = c.next() {
                entries = (*m).clone();
            }
        }
        let help =
            "write entries as `[VALUE pigment { … } finish { … }]` or `[VALUE Texture_Name]`";
        let mut spans: Vec<Span> = Vec::new();
        while let Some(tok) = c.next() {
            match tok {
                Tok::Bracket(items, span) => {
                    let (v, rest) = map_entry_value(items)?;
                    let tex = match rest.as_slice() {
                        // rts also takes `[V texture { … }]` (POV-Ray 3.7 does not), as
                        // it takes `[V pigment { … }]` in a pigment_map.
                        [Tok::Block("texture", Value::Texture(t), _)] => t.clone(),
                        [] => {
                            return Err(Diagnostic::error(
                                codes::MISSING_VALUE,
                                span,
                                "a texture map entry needs a value and a texture",
                            )
                            .with_help(help)
                            .into())
                        }
                        _ => {
                            let mut inner = Cursor::new(rest, "texture_map", span);
                            Arc::new(self.texture(&mut inner)?)
                        }
                    };
                    entries.push((v, tex));
                    spans.push(span);
                }
                Tok::Comma(_) => {}
                Tok::Val(Value::Poison, _) | Tok::Block(_, Value::Poison, _) => {
                    return Err(Fail::silent())
                }
                other => {
                    return Err(self.unexpected(c, &other, &["[VALUE pigment { … } finish { … }]"]))
                }
            }
        }
        if entries.is_empty() {
            return Err(Diagnostic::error(
                codes::MISSING_VALUE,
                c.span,
                "a texture map needs at least one entry",
            )
            .with_help(help)
            .into());
        }
        if entries.len() > 256 {
            return Err(Diagnostic::error(
                codes::OUT_OF_RANGE,
                c.span,
                "a texture map holds at most 256 entries",
            )
            .into());
        }
        // POV-Ray takes the entries in the order written; values that go down are
        // almost always a slip, so say so (the picture follows POV-Ray's lookup).
        if let Some(i) = (1..entries.len()).find(|&i| entries[i].0 < entries[i - 1].0) {
            let (a, b) = (entries[i - 1].0, entries[i].0);
            let mut d = Diagnostic::warning(
                codes::MAP_OUT_OF_ORDER,
                spans.get(i).copied().unwrap_or(c.span),
                format!("texture map values go down here, from {a} to {b}"),
            )
            .with_help("write the entries in increasing order of value, as POV-Ray expects");
            if let Some(s) = spans.get(i - 1) {
                d = d.with_secondary(*s, "previous entry");
            }
            self.warn(d);
        }
        Ok(entries)
    }
}
