//! `text { ttf "FONT" "STRING" THICKNESS, OFFSET }` (and `internal N` for
//! POV-Ray's built-in fonts, read from POV-Ray's installed font files): font
//! lookup, a font cache, and the layout into glyph prisms
//! ([`crate::build::shapes::text`]).

use crate::build::shapes::text::Font;
use crate::diag::{codes, Diagnostic};
use crate::eval::core::cursor::{Cursor, Tok};
use crate::eval::core::value::Value;
use crate::eval::core::{Evaluator, R};
use crate::scene::{Shape, TextData};
use crate::span::Span;
use glam::DVec2;
use std::path::{Path, PathBuf};
use std::sync::Arc;

/// Where POV-Ray installs its fonts: searched for font files after the scene's
/// own folders, so POV-Ray scenes find `timrom.ttf` and friends.
pub(crate) const POVRAY_FONT_DIRS: &[&str] = &[
    "/usr/share/povray-3.7/include",
    "/usr/local/share/povray-3.7/include",
];

/// POV-Ray's `internal N` fonts by number (measured: the same glyphs as these
/// files; numbers past the list are font 0).
const INTERNAL_FONTS: &[&str] = &["povlogo.ttf", "timrom.ttf", "cyrvetic.ttf", "crystal.ttf"];

/// The keywords a `text` takes before its string.
pub(crate) const TEXT_ITEMS: &[&str] = &["ttf", "internal"];

/// Fonts read during one evaluation, by file; `Err` keeps the reason a file is
/// not a font (reported at each use).
pub(crate) type FontCache = rustc_hash::FxHashMap<PathBuf, Result<Font, String>>;

impl Evaluator<'_> {
    /// The contents of a `text` block up to its object modifiers.
    pub(crate) fn text(&mut self, c: &mut Cursor) -> R<Shape> {
        let head = c.span.head();
        let (path, name, name_span) = match c.next() {
            Some(Tok::Kw("ttf", _)) => {
                let (v, s) = c.value("the font file's name, e.g. \"timrom.ttf\"")?;
                let Value::Str(name) = &v else {
                    return Err(self.mismatch("a font file name in quotes", &v, s));
                };
                (self.font_file(name, s, None)?, name.to_string(), s)
            }
            Some(Tok::Kw("internal", kspan)) => {
                let (v, s) = c.value("the number of a built-in font, 0 to 3")?;
                let n = self.to_float(&v, s)?;
                let k = if n >= 0.0 && n.fract() == 0.0 && (n as usize) < INTERNAL_FONTS.len() {
                    n as usize
                } else {
                    0
                };
                let name = INTERNAL_FONTS[k];
                let span = kspan.join(s);
                (self.font_file(name, span, Some(n))?, name.to_string(), span)
            }
            other => {
                let (found, span) = match &other {
                    Some(t) => (t.describe(), t.span()),
                    None => ("nothing".to_string(), head),
                };
                return Err(Diagnostic::error(
                    codes::MISSING_VALUE,
                    span,
                    format!("a text starts with its font, found {found}"),
                )
                .with_label("expected `ttf \"FONT.ttf\"`")
                .with_help("write e.g. `text { ttf \"timrom.ttf\" \"Hello\" 0.2, 0 }`")
                .into());
            }
        };
        c.comma();
        let (v, s) = c.value("the text to show, a string")?;
        let string = match &v {
            Value::Str(t) => t.clone(),
            Value::Float(_) => {
                return Err(Diagnostic::error(
                    codes::TYPE_MISMATCH,
                    s,
                    "the text to show must be a string, found a float",
                )
                .with_label("a number")
                .with_help("turn a number into text with str(X, 0, 2), e.g. `str(clock, 0, 2)`")
                .into())
            }
            other => return Err(self.mismatch("the text to show, a string", other, s)),
        };
        let string_span = s;
        c.comma();
        let thickness = self.take_float(c, "the text's thickness (its depth along z)")?;
        c.comma();
        let (v, s) = c.value("the offset added after each character, e.g. 0 or <0.1, 0>")?;
        let offset = self.to_vec3(&v, s)?;
        // A float offset is the same in x, y and z: only a written z is worth a word.
        if matches!(&v, Value::Vector(x) if x.len >= 3) && offset.z != 0.0 {
            self.warn(
                Diagnostic::warning(
                    codes::IGNORED,
                    s,
                    "the offset's z is ignored: characters move along x and y only",
                )
                .with_help("POV-Ray ignores it too; give `<x, y>`"),
            );
        }
        let font = self.fonts.entry(path.clone()).or_insert_with(|| {
            crate::files::read_regular(&path, u64::MAX)
                .map_err(|e| e.to_string())
                .and_then(Font::parse)
        });
        let font = match font {
            Ok(f) => f,
            Err(e) => {
                return Err(Diagnostic::error(
                    codes::FILE_NOT_FOUND,
                    name_span,
                    format!("cannot read `{name}` as a font: {e}"),
                )
                .with_label("not a usable font")
                .with_help("give a TrueType (.ttf) or OpenType (.otf) font file")
                .into())
            }
        };
        let layout = font.layout(&string, DVec2::new(offset.x, offset.y));
        if !layout.missing.is_empty() {
            let list: Vec<String> = layout
                .missing
                .iter()
                .map(|ch| format!("{ch:?} (U+{:04X})", u32::from(*ch)))
                .collect();
            self.warn(
                Diagnostic::warning(
                    codes::IGNORED,
                    string_span,
                    format!(
                        "`{name}` has no glyph for {}: drawn as the font's missing-glyph shape",
                        list.join(", ")
                    ),
                )
                .with_help("POV-Ray does the same; use a font that has these characters"),
            );
        }
        if string.is_empty() {
            self.warn(
                Diagnostic::warning(codes::INVALID_SIZE, string_span, "this text is empty")
                    .with_help("give the characters to show, e.g. \"Hello\""),
            );
        }
        Ok(Shape::Text(Arc::new(TextData {
            glyphs: layout
                .glyphs
                .into_iter()
                .map(|g| (g.curves, g.origin))
                .collect(),
            thickness,
        })))
    }

    /// The path of font file `name` (written at `span`): the scene's folders
    /// first (like every file), `name.ttf` when `name` has no extension, then
    /// POV-Ray's installed font folders. `internal` is the built-in font number
    /// when the name came from `internal N`.
    fn font_file(&self, name: &str, span: Span, internal: Option<f64>) -> R<PathBuf> {
        let mut tried = Vec::new();
        let mut names = vec![name.to_string()];
        if Path::new(name).extension().is_none() {
            names.push(format!("{name}.ttf"));
        }
        for n in &names {
            if let Some((canon, _)) = self.search(n, span, &mut tried)? {
                self.data_files.borrow_mut().push(canon.clone());
                return Ok(canon);
            }
        }
        if Path::new(name).is_relative() {
            for dir in POVRAY_FONT_DIRS {
                for n in &names {
                    let path = Path::new(dir).join(n);
                    tried.push(path.display().to_string());
                    if path.is_file() {
                        let canon = path.canonicalize().unwrap_or(path);
                        self.data_files.borrow_mut().push(canon.clone());
                        return Ok(canon);
                    }
                }
            }
        }
        let what = match internal {
            Some(n) => format!("POV-Ray's built-in font {n} (`{name}`) not found"),
            None => format!("font file `{name}` not found"),
        };
        let mut d = Diagnostic::error(codes::FILE_NOT_FOUND, span, what)
            .with_label("no such font file")
            .with_note(format!("tried: {}", tried.join(", ")))
            .with_note(
                "fonts are searched in the scene's folders and -I folders, then in POV-Ray's \
                 font folders (/usr/share/povray-3.7/include, /usr/local/share/povray-3.7/include)",
            );
        d = if internal.is_some() {
            d.with_help(
                "rts has no fonts built in: it reads POV-Ray's font files; install POV-Ray's \
                 fonts, or name a font file with `ttf \"FILE.ttf\"`",
            )
        } else {
            d.with_help("check the file name, or add the font's folder with -I DIR")
        };
        Err(d.into())
    }
}
