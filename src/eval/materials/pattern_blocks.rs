//! Pattern-combining blocks: `pigment_pattern { … }`, `image_pattern { … }`,
//! `slope { … }` (patterns written as blocks), `normal_map`, `slope_map`,
//! `bump_map` and `material_map`.

use super::patterns::map_entry_value;
use crate::diag::{codes, Diagnostic};
use crate::eval::core::cursor::{Cursor, Tok};
use crate::eval::core::images::ImageFail;
use crate::eval::core::value::Value;
use crate::eval::core::{Evaluator, Fail, R};
use crate::scene::{
    ImageMap, ImagePattern, ImageUse, InsideTest, Normal, NormalBlend, PatternKind, PatternMods,
    PatternedTexture, SlopeSpec, Texture, TextureEntries, Transfer,
};
use crate::span::Span;
use glam::{DVec2, DVec3};
use std::sync::Arc;

/// What `image_pattern`, `bump_map` and `material_map` accept.
pub(crate) const IMAGE_PATTERN_ITEMS: &[&str] = &[
    "png",
    "jpeg",
    "exr",
    "map_type",
    "interpolate",
    "once",
    "use_alpha",
    "use_color",
    "use_colour",
    "use_index",
];

/// What `slope { }` accepts after its direction.
pub(crate) const SLOPE_ITEMS: &[&str] = &["altitude"];

/// An image block being read: the file, the projection and what it reads.
struct ImageSpec {
    file: Option<(String, Span)>,
    map_type: u8,
    interpolate: bool,
    once: bool,
    source: Option<ImageUse>,
}

/// A pattern written as a block among a pigment's, normal's or texture's
/// items (`function { }`, `pigment_pattern { }`, `image_pattern { }`, `slope
/// { }`, the object pattern) becomes its keyword, carrying its pattern to
/// [`Evaluator::pattern_kw`]; the object pattern's entries go back into `c`.
/// Other tokens carry nothing.
pub(crate) fn pattern_token(tok: Tok, c: &mut Cursor) -> (Tok, Option<PatternKind>) {
    match tok {
        Tok::Block("function", Value::Function(f), span) => {
            (Tok::Kw("function", span), Some(PatternKind::Function(f)))
        }
        Tok::Block("object", Value::ObjectPattern(op), span) => {
            c.inject(op.1 .0.clone());
            (Tok::Kw("object", span), Some(op.0.clone()))
        }
        Tok::Block(
            kw @ ("pigment_pattern" | "image_pattern" | "slope"),
            Value::Pattern(p),
            span,
        ) => (Tok::Kw(kw, span), Some((*p).clone())),
        t => (t, None),
    }
}

impl Evaluator<'_> {
    /// The pattern of the block `kw` just met, `carried` by its keyword (see
    /// [`pattern_token`]).
    pub(crate) fn block_pattern(
        &mut self,
        kw: &str,
        carried: Option<PatternKind>,
        c: &mut Cursor,
    ) -> R<PatternKind> {
        match carried {
            Some(p) => Ok(p),
            // POV-Ray's older `slope DIRECTION [, LO, HI]` without braces
            // (still read by 3.7: advanced/balcony's terrain.inc).
            None if kw == "slope" && c.value_next() => match self.slope_spec(c, false)? {
                Value::Pattern(p) => Ok((*p).clone()),
                _ => unreachable!("slope_spec makes a pattern"),
            },
            None => Err(Diagnostic::error(
                codes::MISSING_VALUE,
                c.last,
                format!("`{kw}` needs its contents in braces"),
            )
            .with_help(match kw {
                "pigment_pattern" => "write `pigment_pattern { PIGMENT }`, e.g. `pigment_pattern { checker rgb 0, rgb 1 }`",
                "image_pattern" => "write `image_pattern { png \"file.png\" }`",
                _ => "write `slope { y }` or `slope { y, 0, 1 altitude y, 0, 10 }`",
            })
            .into()),
        }
    }

    /// `pigment_pattern { PIGMENT }`: the pigment's grey value as a pattern.
    pub(crate) fn pigment_pattern(&mut self, c: &mut Cursor) -> R<Value> {
        let pig = self.pigment(c)?;
        Ok(Value::Pattern(Arc::new(PatternKind::PigmentPattern(
            Arc::new(pig),
        ))))
    }

    /// `slope { DIRECTION [, LO, HI] [altitude DIRECTION [, LO, HI]] }`.
    pub(crate) fn slope_block(&mut self, c: &mut Cursor) -> R<Value> {
        self.slope_spec(c, true)
    }

    /// A slope's items; `whole_block`: the cursor holds the block's items
    /// alone (else only the direction and range are read, the braceless form).
    fn slope_spec(&mut self, c: &mut Cursor, whole_block: bool) -> R<Value> {
        let direction = self.take_vec3(c, "the slope's direction, e.g. `y`")?;
        let mut s = SlopeSpec {
            direction,
            slope_range: (0.0, 1.0),
            altitude: None,
            altitude_range: (0.0, 1.0),
        };
        s.slope_range = self.optional_range(c, "slope")?.unwrap_or((0.0, 1.0));
        while let Some(tok) = if whole_block { c.next() } else { None } {
            match tok {
                Tok::Kw("altitude", span) => {
                    c.once("altitude", span)?;
                    s.altitude = Some(self.take_vec3(c, "the altitude's direction, e.g. `y`")?);
                    s.altitude_range = self.optional_range(c, "altitude")?.unwrap_or((0.0, 1.0));
                }
                Tok::Comma(_) => {}
                other => return Err(self.unexpected(c, &other, SLOPE_ITEMS)),
            }
        }
        if s.direction == DVec3::ZERO {
            return Err(Diagnostic::error(
                codes::OUT_OF_RANGE,
                c.span,
                "the slope's direction is the zero vector",
            )
            .with_help("give the direction the surface faces for value 1, e.g. `slope { y }`")
            .into());
        }
        Ok(Value::Pattern(Arc::new(PatternKind::Slope(Box::new(s)))))
    }

    /// `, LO, HI` after a slope or altitude direction, if written.
    fn optional_range(&mut self, c: &mut Cursor, what: &str) -> R<Option<(f64, f64)>> {
        c.comma();
        if !c.value_next() {
            return Ok(None);
        }
        let (v, lo_span) = c.value(&format!("the low {what} value"))?;
        let lo = self.to_float(&v, lo_span)?;
        c.comma();
        let hi = self.take_float(c, &format!("the high {what} value (after the low one)"))?;
        if hi == lo {
            return Err(Diagnostic::error(
                codes::OUT_OF_RANGE,
                lo_span,
                format!("the low and high {what} values are both {lo}"),
            )
            .with_help("give two different values: they are mapped to 0 and 1")
            .into());
        }
        Ok(Some((lo, hi)))
    }

    /// `image_pattern { png "file" [map_type N] [interpolate N] [once]
    /// [use_alpha | use_color | use_index] }`.
    pub(crate) fn image_pattern(&mut self, c: &mut Cursor) -> R<Value> {
        let mut spec = self.image_spec();
        while let Some(tok) = c.next() {
            let r = self.image_item(&mut spec, c, tok, IMAGE_PATTERN_ITEMS);
            if let Err(f) = r {
                self.report(f);
            }
        }
        let ip = self.load_image_pattern(spec, c, "image_pattern", ImageUse::Colour)?;
        Ok(Value::Pattern(Arc::new(PatternKind::ImagePattern(
            Arc::new(ip),
        ))))
    }

    /// `bump_map { png "file" [bump_size N] [map_type N] [interpolate N] [once]
    /// [use_color | use_index] }`: a normal whose heights are the image's.
    pub(crate) fn bump_map(&mut self, c: &mut Cursor) -> R<Normal> {
        let mut spec = self.image_spec();
        let mut bump_size = 1.0;
        let items = [
            &IMAGE_PATTERN_ITEMS[..6],
            &["use_color", "use_colour", "use_index", "bump_size"],
        ]
        .concat();
        while let Some(tok) = c.next() {
            let r = match tok {
                Tok::Kw("bump_size", _) => {
                    self.take_float(c, "the bump size").map(|x| bump_size = x)
                }
                tok => self.image_item(&mut spec, c, tok, &items),
            };
            if let Err(f) = r {
                self.report(f);
            }
        }
        let ip = self.load_image_pattern(spec, c, "bump_map", ImageUse::Colour)?;
        Ok(Normal {
            kind: PatternKind::ImagePattern(Arc::new(ip)),
            mods: PatternMods::default(),
            bump_size,
            transform: None,
            accuracy: None,
            blend: Some(Arc::new(NormalBlend::BumpMap)),
        })
    }

    /// `material_map { png "file" [map_type N] [interpolate N] [once] texture
    /// { … } … }`: the image's palette index chooses the texture.
    pub(crate) fn material_map(&mut self, c: &mut Cursor) -> R<Texture> {
        let mut spec = self.image_spec();
        let mut textures: Vec<Arc<Texture>> = Vec::new();
        let items = [&IMAGE_PATTERN_ITEMS[..6], &["texture"]].concat();
        while let Some(tok) = c.next() {
            let r = match tok {
                Tok::Block("texture", Value::Texture(t), _) | Tok::Val(Value::Texture(t), _) => {
                    textures.push(t);
                    Ok(())
                }
                tok => self.image_item(&mut spec, c, tok, &items),
            };
            if let Err(f) = r {
                self.report(f);
            }
        }
        if textures.is_empty() {
            return Err(Diagnostic::error(
                codes::MISSING_VALUE,
                c.span,
                "`material_map` needs the textures its image chooses",
            )
            .with_help("add `texture { … }` blocks after the file: the first for index 0, the next for index 1, …")
            .into());
        }
        let ip = self.load_image_pattern(spec, c, "material_map", ImageUse::Index)?;
        Ok(Texture {
            patterned: Some(Arc::new(PatternedTexture {
                kind: PatternKind::MaterialMap(Arc::new(ip)),
                mods: PatternMods::default(),
                transform: None,
                entries: TextureEntries::List(textures),
            })),
            ..Texture::default()
        })
    }

    fn image_spec(&self) -> ImageSpec {
        ImageSpec {
            file: None,
            map_type: 0,
            interpolate: false,
            once: false,
            source: None,
        }
    }

    /// One item of an image block.
    fn image_item(
        &mut self,
        spec: &mut ImageSpec,
        c: &mut Cursor,
        tok: Tok,
        items: &[&str],
    ) -> R<()> {
        match tok {
            Tok::Kw("png" | "jpeg" | "exr", _) => {
                let (v, s) = c.value("the image's file name")?;
                match v {
                    Value::Str(name) => {
                        spec.file = Some((name.to_string(), s));
                        Ok(())
                    }
                    other => Err(Diagnostic::error(
                        codes::TYPE_MISMATCH,
                        s,
                        format!("expected a file name, found {}", other.kind()),
                    )
                    .into()),
                }
            }
            Tok::Val(Value::Str(name), s) if spec.file.is_none() => {
                spec.file = Some((name.to_string(), s));
                Ok(())
            }
            Tok::Kw("map_type", _) => self
                .take_float(c, "the map type (0, 1 or 2)")
                .map(|x| spec.map_type = x as u8),
            Tok::Kw("interpolate", _) => self
                .take_float(c, "the interpolation (2 bilinear)")
                .map(|x| spec.interpolate = x >= 2.0),
            Tok::Kw("once", _) => {
                spec.once = true;
                Ok(())
            }
            Tok::Kw(kw @ ("use_alpha" | "use_color" | "use_colour" | "use_index"), span) => {
                if !items.contains(&kw) {
                    return Err(self.unknown_keyword(c, kw, span, items));
                }
                spec.source = Some(match kw {
                    "use_alpha" => ImageUse::Alpha,
                    "use_index" => ImageUse::Index,
                    _ => ImageUse::Colour,
                });
                Ok(())
            }
            other => Err(self.unexpected(c, &other, items)),
        }
    }

    /// Reads the image of `spec` (`block` names the block for messages; `index`
    /// is what a palette image gives when no `use_…` is written).
    fn load_image_pattern(
        &mut self,
        spec: ImageSpec,
        c: &Cursor,
        block: &str,
        palette_default: ImageUse,
    ) -> R<ImagePattern> {
        let Some((name, span)) = spec.file else {
            return Err(Diagnostic::error(
                codes::MISSING_VALUE,
                c.span,
                format!("`{block}` needs an image file: `{block} {{ png \"name.png\" … }}`"),
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
                .with_help(format!("{block} reads PNG, JPEG and OpenEXR files")),
            ),
        })?;
        let source = spec.source.unwrap_or(if picture.palette().is_some() {
            palette_default
        } else {
            ImageUse::Colour
        });
        // Patterns read the values as stored.
        let tones = self.images.tones(picture.depth(), Transfer::AsStored);
        Ok(ImagePattern {
            image: Arc::new(ImageMap {
                map_type: spec.map_type,
                interpolate: spec.interpolate,
                once: spec.once,
                see_through: false,
                ..ImageMap::new(picture, tones)
            }),
            source,
        })
    }

    /// `normal_map { [v NORMAL] … }` (also a declared map as the first item).
    pub(crate) fn normal_map(&mut self, c: &mut Cursor) -> R<Vec<(f64, Normal)>> {
        let mut entries: Vec<(f64, Normal)> = Vec::new();
        if let Some(Tok::Val(Value::NormalMap(_), _)) = c.peek() {
            if let Some(Tok::Val(Value::NormalMap(m), _)) = c.next() {
                entries = (*m).clone();
            }
        }
        let help = "write entries as `[VALUE normal { … }]` or `[VALUE bumps 0.5 scale 0.2]`";
        while let Some(tok) = c.next() {
            match tok {
                Tok::Bracket(items, span) => {
                    let (v, rest) = map_entry_value(items)?;
                    let n = match rest.as_slice() {
                        [Tok::Block("normal", Value::Normal(n), _)] => (**n).clone(),
                        [] => {
                            return Err(Diagnostic::error(
                                codes::MISSING_VALUE,
                                span,
                                "a normal map entry needs a value and a normal",
                            )
                            .with_help(help)
                            .into())
                        }
                        _ => {
                            let mut inner = Cursor::new(rest, "normal_map", span);
                            self.normal(&mut inner)?
                        }
                    };
                    entries.push((v, n));
                }
                Tok::Comma(_) => {}
                Tok::Val(Value::Poison, _) | Tok::Block(_, Value::Poison, _) => {
                    return Err(Fail::silent())
                }
                other => return Err(self.unexpected(c, &other, &["[VALUE normal { … }]"])),
            }
        }
        if entries.is_empty() {
            return Err(Diagnostic::error(
                codes::MISSING_VALUE,
                c.span,
                "a normal map needs at least one entry",
            )
            .with_help(help)
            .into());
        }
        Ok(entries)
    }

    /// `slope_map { [v, <height, slope>] … }` (also a declared map first).
    pub(crate) fn slope_map(&mut self, c: &mut Cursor) -> R<Vec<(f64, DVec2)>> {
        let mut entries: Vec<(f64, DVec2)> = Vec::new();
        if let Some(Tok::Val(Value::SlopeMap(_), _)) = c.peek() {
            if let Some(Tok::Val(Value::SlopeMap(m), _)) = c.next() {
                entries = (*m).clone();
            }
        }
        let help = "write entries as `[VALUE, <HEIGHT, SLOPE>]`, e.g. `[0.5, <1, 0>]`";
        while let Some(tok) = c.next() {
            match tok {
                Tok::Bracket(items, span) => {
                    let vals: Vec<(Value, Span)> = items
                        .into_iter()
                        .filter_map(|t| match t {
                            Tok::Val(v, s) => Some((v, s)),
                            _ => None,
                        })
                        .collect();
                    if vals.iter().any(|(v, _)| matches!(v, Value::Poison)) {
                        return Err(Fail::silent());
                    }
                    let [(Value::Float(v), _), (hs, hs_span)] = vals.as_slice() else {
                        return Err(Diagnostic::error(
                            codes::SLOPE_MAP_ENTRY,
                            span,
                            "a slope map entry is a value and a 2-vector <height, slope>",
                        )
                        .with_help(help)
                        .into());
                    };
                    let pair = match hs {
                        Value::Vector(vec) if vec.len == 2 => DVec2::new(vec.c[0], vec.c[1]),
                        Value::Float(h) => DVec2::new(*h, 0.0),
                        other => {
                            return Err(Diagnostic::error(
                                codes::SLOPE_MAP_ENTRY,
                                *hs_span,
                                format!(
                                    "a slope map entry's second part is <height, slope>, found {}",
                                    other.kind()
                                ),
                            )
                            .with_help(help)
                            .into())
                        }
                    };
                    entries.push((*v, pair));
                }
                Tok::Comma(_) => {}
                Tok::Val(Value::Poison, _) => return Err(Fail::silent()),
                other => return Err(self.unexpected(c, &other, &["[VALUE, <HEIGHT, SLOPE>]"])),
            }
        }
        if entries.is_empty() {
            return Err(Diagnostic::error(
                codes::MISSING_VALUE,
                c.span,
                "a slope map needs at least one entry",
            )
            .with_help(help)
            .into());
        }
        Ok(entries)
    }
}

impl Evaluator<'_> {
    /// `object { OBJECT_IDENTIFIER | OBJECT { } [transforms] A, B }` as a
    /// pattern: entry A outside the object, B inside (POV-Ray's object
    /// pattern). The entries stay tokens until the pattern's reader takes them.
    pub(crate) fn object_pattern(&mut self, c: &mut Cursor) -> R<Value> {
        let mut object = match c.next() {
            Some(Tok::Val(Value::Object(o), _) | Tok::Block(_, Value::Object(o), _)) => o,
            Some(Tok::Val(Value::Poison, _) | Tok::Block(_, Value::Poison, _)) => {
                return Err(Fail::silent())
            }
            other => {
                let at = other.as_ref().map_or(c.span, Tok::span);
                return Err(Diagnostic::error(
                    codes::MISSING_VALUE,
                    at,
                    "the object pattern starts with the object to test",
                )
                .with_help("write `object { MyObject color White, color Red }` (outside, inside)")
                .into());
            }
        };
        let mut entries = Vec::new();
        while let Some(tok) = c.next() {
            match tok {
                Tok::Kw(kw, span) if crate::eval::core::transforms::TRANSFORMS.contains(&kw) => {
                    let t = self.transform_kw(kw, span, c)?;
                    let o = Arc::make_mut(&mut object);
                    crate::eval::objects::object::apply_transform(o, &t);
                }
                t => entries.push(t),
            }
        }
        let world = self.built(&object);
        let test = InsideTest(Arc::new(move |p| world.inside(p)));
        Ok(Value::ObjectPattern(std::rc::Rc::new((
            PatternKind::Object(test),
            crate::eval::core::value::ObjectPatternEntries(entries),
        ))))
    }
}
