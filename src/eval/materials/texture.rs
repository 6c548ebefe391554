//! `texture`, `pigment`, `finish` and `reflection` blocks.

use super::patterns::map_entry_value;
use super::patterns::PatternSpec;
use super::patterns::{default_map, MODIFIERS, PATTERNS};
use crate::diag::{codes, Diagnostic};
use crate::eval::core::cursor::{Cursor, Tok};
use crate::eval::core::images::ImageFail;
use crate::eval::core::value::Value;
use crate::eval::core::{Evaluator, Fail, R};
use crate::eval::objects::object::TRANSFORMS;
use crate::scene::{
    compose, Colour, Finish, ImageMap, IndexClear, Interior, Mapped, Normal, NormalBlend, Pattern,
    PatternKind, PatternMap, PatternedTexture, Pigment, Reflection, Texture, TextureEntries,
    TextureMapEntries, Transfer, Transform,
};
use crate::span::Span;
use glam::DVec3;
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
pub(crate) const INTERIOR_ITEMS: &[&str] = &[
    "ior",
    "fade_distance",
    "fade_power",
    "fade_color",
    "fade_colour",
    "caustics",
    "dispersion",
    "dispersion_samples",
    "media",
];
pub(crate) const IMAGE_MAP_ITEMS: &[&str] = &[
    "png",
    "jpeg",
    "exr",
    "gamma",
    "map_type",
    "interpolate",
    "once",
    "filter",
    "transmit",
    "uv_mapping",
];
const LATER_FINISH: &[&str] = &["fresnel"];

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
fn list_len(kw: &str) -> usize {
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
fn warp_without_pattern(span: Span, what: &str) -> Fail {
    Diagnostic::error(
        codes::WARP_WITHOUT_PATTERN,
        span,
        format!("a warp needs a pattern before it in this {what}"),
    )
    .with_label("nothing to warp yet")
    .with_help("write the pattern first, e.g. `bozo warp { turbulence 0.5 }`")
    .into()
}

fn compose_pattern(p: &mut Pigment, t: &Transform) {
    compose(&mut p.transform, t);
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
            let tok = self.function_pattern_token(tok);
            let tok = self.block_pattern_token(tok, c);
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
                    self.texture_pattern(kw, span, c, &mut pat, plain_items)
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
        let r = self.pattern_kw(kw, c, &mut spec, false);
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

    /// `pigment { COLOUR | PATTERN [entries] [color_map/pigment_map] modifiers |
    /// image_map { … } | Name … transforms }`.
    pub(crate) fn pigment(&mut self, c: &mut Cursor) -> R<Pigment> {
        let mut pig = if self.density_block {
            // A media's density is 1 where nothing else is said.
            Pigment {
                pattern: Pattern::Solid(Colour::rgb(1.0, 1.0, 1.0)),
                transform: None,
            }
        } else {
            self.default_texture.pigment.clone()
        };
        let mut pattern_given = false;
        let mut spec = self.new_spec();
        let mut modified = false;
        let mut uv_mapping = false;
        while let Some(tok) = c.next() {
            let tok = self.function_pattern_token(tok);
            let tok = self.block_pattern_token(tok, c);
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
                        self.pattern_kw(kw, c, &mut spec, true)
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
            let tok = self.function_pattern_token(tok);
            let tok = self.block_pattern_token(tok, c);
            let r: R<()> = match tok {
                Tok::Kw(kw, _) if PATTERNS.contains(&kw) => {
                    let r = self.pattern_kw(kw, c, &mut spec, false);
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

    /// `interior { [Name] ior fade_distance fade_power fade_color caustics dispersion }`.
    pub(crate) fn interior(&mut self, c: &mut Cursor) -> R<Interior> {
        let mut i = match c.peek() {
            Some(Tok::Val(Value::Interior(_), _)) => match c.next() {
                Some(Tok::Val(Value::Interior(x), _)) => (*x).clone(),
                _ => unreachable!(),
            },
            Some(Tok::Val(Value::Poison, _)) => return Err(Fail::silent()),
            _ => Interior::default(),
        };
        while let Some(tok) = c.next() {
            let r: R<()> = match tok {
                Tok::Kw("ior", span) => c.once("ior", span).and_then(|_| {
                    let (v, s) = c.value("the index of refraction")?;
                    let x = self.to_float(&v, s)?;
                    if x <= 0.0 {
                        return Err(Diagnostic::error(
                            codes::OUT_OF_RANGE,
                            s,
                            format!("ior must be positive, found {x}"),
                        )
                        .with_help("1.0 is air, 1.33 water, 1.5 glass")
                        .into());
                    }
                    i.ior = x;
                    Ok(())
                }),
                Tok::Kw("fade_distance", _) => self
                    .take_float(c, "the fade distance")
                    .map(|x| i.fade_distance = x.max(0.0)),
                Tok::Kw("fade_power", _) => self
                    .take_float(c, "the fade power")
                    .map(|x| i.fade_power = x.max(0.0)),
                Tok::Kw("fade_color" | "fade_colour", _) => self
                    .take_colour(c, "the fade colour")
                    .map(|x| i.fade_colour = x.rgb),
                Tok::Block("media", Value::Media(m), _) => {
                    // Several media in one interior add up.
                    i.media.push((*m).clone());
                    Ok(())
                }
                Tok::Kw("caustics", _) => self
                    .take_float(c, "the caustics power")
                    .map(|x| i.caustics = x.max(0.0)),
                Tok::Kw("dispersion" | "dispersion_samples", _) => {
                    // Accepted as in POV-Ray; they need spectral rays.
                    self.take_float(c, "a number").map(|_| ())
                }
                other => Err(self.unexpected(c, &other, INTERIOR_ITEMS)),
            };
            if let Err(f) = r {
                self.report(f);
            }
        }
        Ok(i)
    }

    /// `image_map { png "file" map_type N interpolate N once filter/transmit … }`.
    pub(crate) fn image_map(&mut self, c: &mut Cursor) -> R<Pigment> {
        let mut file: Option<(String, crate::span::Span)> = None;
        let (mut map_type, mut interpolate, mut once, mut uv_mapping) = (0u8, false, false, false);
        let mut filter_all: Option<f64> = None;
        let mut transmit_all: Option<f64> = None;
        // `filter INDEX, AMOUNT` / `transmit INDEX, AMOUNT`: (is filter, palette
        // index, amount, where).
        let mut by_index: Vec<(bool, u8, f64, crate::span::Span)> = Vec::new();
        let mut file_gamma: Option<f64> = None;
        while let Some(tok) = c.next() {
            let r: R<()> = match tok {
                Tok::Kw("gamma", _) => self
                    .take_above_zero(
                        c,
                        "the image file's gamma",
                        "an image's gamma",
                        "2.2 is the usual gamma of 8-bit pictures; 1 reads the values as they are",
                    )
                    .map(|g| file_gamma = Some(g)),
                Tok::Kw("png" | "jpeg" | "exr", _) => {
                    c.value("the image's file name").and_then(|(v, s)| match v {
                        Value::Str(name) => {
                            file = Some((name.to_string(), s));
                            Ok(())
                        }
                        other => Err(Diagnostic::error(
                            codes::TYPE_MISMATCH,
                            s,
                            format!("expected a file name, found {}", other.kind()),
                        )
                        .into()),
                    })
                }
                Tok::Val(Value::Str(name), s) if file.is_none() => {
                    file = Some((name.to_string(), s));
                    Ok(())
                }
                Tok::Kw("map_type", _) => self
                    .take_float(c, "the map type (0, 1 or 2)")
                    .map(|x| map_type = x as u8),
                Tok::Kw("interpolate", _) => self
                    .take_float(c, "the interpolation (2 bilinear)")
                    .map(|x| interpolate = x >= 2.0),
                Tok::Kw("once", _) => {
                    once = true;
                    Ok(())
                }
                Tok::Kw("uv_mapping", _) => {
                    uv_mapping = true;
                    Ok(())
                }
                Tok::Kw(kw @ ("filter" | "transmit"), _) => {
                    if let Some(Tok::Kw("all", _)) = c.peek() {
                        c.next();
                        self.take_float(c, "the amount").map(|x| {
                            if kw == "filter" {
                                filter_all = Some(x)
                            } else {
                                transmit_all = Some(x)
                            }
                        })
                    } else {
                        // POV-Ray's `filter PALETTE, AMOUNT`: one colour of a
                        // palette image.
                        let (v, s) = c.value(&format!(
                            "a palette index after `{kw}` (or `{kw} all AMOUNT`)"
                        ))?;
                        let i = self.to_float(&v, s)?;
                        if !(0.0..=255.0).contains(&i) || i.fract() != 0.0 {
                            Err(Diagnostic::error(
                                codes::OUT_OF_RANGE,
                                s,
                                format!("a palette index is a whole number from 0 to 255, found {i}"),
                            )
                            .with_help(format!("`{kw} 5, 1` makes palette colour 5 clear; `{kw} all 0.5` the whole image"))
                            .into())
                        } else {
                            c.comma();
                            self.take_float(c, &format!("the amount after `{kw} {i},`"))
                                .map(|x| by_index.push((kw == "filter", i as u8, x, s)))
                        }
                    }
                }
                other => Err(self.unexpected(c, &other, IMAGE_MAP_ITEMS)),
            };
            if let Err(f) = r {
                self.report(f);
            }
        }
        let Some((name, span)) = file else {
            return Err(Diagnostic::error(
                codes::MISSING_VALUE,
                c.span,
                "`image_map` needs a file: `image_map { png \"name.png\" }`",
            )
            .into());
        };
        let path = self.data_file(&name, span, "image")?;
        let picture = self.picture(&path, &name, span).map_err(|e| match e {
            ImageFail::Fail(f) => f,
            ImageFail::Read(e) => Fail::from(
                Diagnostic::error(
                    codes::FILE_NOT_FOUND,
                    span,
                    format!("cannot read image `{name}`: {e}"),
                )
                .with_help("image_map reads PNG, JPEG and OpenEXR files"),
            ),
        })?;
        // How stored values become linear ones, as POV-Ray 3.7 does (measured): a
        // `gamma G` after the file name decodes by that power; else scenes of
        // `#version 3.7` read 8- and 16-bit PNG and JPEG pictures as sRGB, and
        // older scenes (or floating-point pictures) use the values as stored.
        let srgb = file_gamma.is_none()
            && !picture.is_float()
            && self.language_version.is_some_and(|v| v >= 3.7);
        let transfer = match file_gamma {
            Some(g) => Transfer::Power(g),
            None if srgb => Transfer::Srgb,
            None => Transfer::AsStored,
        };
        let tones = self.images.tones(picture.depth(), transfer);
        let mut im = ImageMap {
            map_type,
            interpolate,
            once,
            uv_mapping,
            ..ImageMap::new(picture, tones)
        };
        im.filter_all = filter_all;
        im.transmit_all = transmit_all;
        if !by_index.is_empty() {
            if im.picture.palette().is_some() {
                let mut table = [IndexClear::default(); 256];
                for &(is_filter, at, amount, _) in &by_index {
                    let entry = &mut table[usize::from(at)];
                    if is_filter {
                        entry.filter = Some(amount);
                    } else {
                        entry.transmit = Some(amount);
                    }
                }
                im.by_index = Some(Arc::new(table));
            } else {
                self.warn(
                    Diagnostic::warning(
                        codes::IGNORED,
                        by_index[0].3,
                        format!("`{name}` has no palette: filter and transmit by palette index do nothing"),
                    )
                    .with_help("use `filter all AMOUNT` / `transmit all AMOUNT`, or an alpha channel"),
                );
            }
        }
        im.see_through = im.find_see_through();
        Ok(Pigment {
            pattern: Pattern::Image(Arc::new(im)),
            transform: None,
        })
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
