//! `text`: the glyphs of a TrueType (or CFF OpenType) font laid out along x, each
//! glyph an extruded outline.
//!
//! A glyph outline is closed contours of lines and quadratic Béziers (cubics in
//! CFF fonts). Each glyph becomes one [`super::prism::Prism`]: its contours are
//! prism [`Curve`]s in the prism's x-z plane as `<x, −y>` (so a rotation about x
//! stands them up, see [`glyph_placement`]), extruded along the prism's y. The
//! world BVH then sees one primitive per glyph.
//!
//! Layout, measured against POV-Ray 3.7 (`trace` and `min_extent` on
//! `timrom.ttf`, `crystal.ttf`, `povlogo.ttf`): font units are divided by the
//! em size (`unitsPerEm`), so the em square is 1 unit; the baseline is y = 0;
//! the whole string is moved left by the left edge (`xMin`) of its first glyph,
//! so it starts at x = 0; each character advances the pen by its advance width,
//! its `kern` table kerning with the next glyph, and the offset vector's x and y.
//! A character the font does not map is drawn as the font's glyph 0 (`.notdef`).
//!
//! TrueType fills outlines by the non-zero winding rule and the prism by the
//! even-odd rule: they agree unless contours of one glyph overlap (rare in
//! fonts; overlapping parts then show as holes).

use super::prism::Curve;
use glam::{DMat4, DVec2, DVec4};
use rustc_hash::FxHashMap;
use std::sync::Arc;
use ttf_parser::{Face, GlyphId, OutlineBuilder};

/// A parsed font file, with the outlines of the glyphs used so far.
pub struct Font {
    data: Vec<u8>,
    units_per_em: f64,
    outlines: FxHashMap<u16, Arc<[Curve]>>,
}

/// One glyph of a laid-out string.
#[derive(Clone, Debug, PartialEq)]
pub struct PlacedGlyph {
    /// The outline as prism curves (`<x, −y>`, em units, glyph origin at 0).
    pub curves: Arc<[Curve]>,
    /// Where the glyph's origin goes in the text's x-y plane.
    pub origin: DVec2,
}

/// The result of [`Font::layout`].
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Layout {
    /// The glyphs with an outline (spaces have none), left to right.
    pub glyphs: Vec<PlacedGlyph>,
    /// Characters the font does not map, drawn as its glyph 0 (`.notdef`).
    pub missing: Vec<char>,
}

impl Font {
    /// Reads a font file's bytes (the first font of a collection); the error says
    /// what is wrong.
    pub fn parse(data: Vec<u8>) -> Result<Font, String> {
        let face = Face::parse(&data, 0).map_err(|e| match e {
            ttf_parser::FaceParsingError::UnknownMagic => {
                "the file does not start like a TrueType or OpenType font".to_string()
            }
            ttf_parser::FaceParsingError::MalformedFont => {
                "the font file is damaged or cut short".to_string()
            }
            e => e.to_string(),
        })?;
        if face.tables().cmap.is_none() {
            return Err("the font has no character map (`cmap` table)".into());
        }
        let units_per_em = f64::from(face.units_per_em());
        if units_per_em <= 0.0 {
            return Err("the font's em size (`unitsPerEm`) is 0".into());
        }
        Ok(Font {
            data,
            units_per_em,
            outlines: FxHashMap::default(),
        })
    }

    fn face(&self) -> Face<'_> {
        // `parse` checked that it parses.
        Face::parse(&self.data, 0).expect("font parsed before")
    }

    /// The glyphs of `text` with `offset` added after each character (see the
    /// module documentation).
    pub fn layout(&mut self, text: &str, offset: DVec2) -> Layout {
        let mut out = Layout::default();
        let scale = 1.0 / self.units_per_em;
        let mut placed: Vec<(GlyphId, DVec2)> = Vec::new();
        {
            let face = self.face();
            let mut pen = DVec2::ZERO;
            let mut shift = 0.0;
            let mut prev: Option<GlyphId> = None;
            for (i, ch) in text.chars().enumerate() {
                let gid = glyph_of(&face, ch).unwrap_or_else(|| {
                    if !out.missing.contains(&ch) {
                        out.missing.push(ch);
                    }
                    GlyphId(0)
                });
                if i == 0 {
                    shift = face
                        .glyph_bounding_box(gid)
                        .map_or(0.0, |r| f64::from(r.x_min) * scale);
                }
                if let Some(p) = prev {
                    pen.x += kerning(&face, p, gid) * scale;
                }
                placed.push((gid, pen - DVec2::new(shift, 0.0)));
                let advance = face.glyph_hor_advance(gid).map_or(0.0, f64::from);
                pen += DVec2::new(advance * scale, 0.0) + offset;
                prev = Some(gid);
            }
        }
        for (gid, origin) in placed {
            let curves = self.outline(gid);
            if !curves.is_empty() {
                out.glyphs.push(PlacedGlyph { curves, origin });
            }
        }
        out
    }

    /// The outline of glyph `gid` as prism curves, read once.
    fn outline(&mut self, gid: GlyphId) -> Arc<[Curve]> {
        if let Some(c) = self.outlines.get(&gid.0) {
            return c.clone();
        }
        let mut b = CurveBuilder::new(1.0 / self.units_per_em);
        let curves: Arc<[Curve]> = if self.face().outline_glyph(gid, &mut b).is_some() {
            b.finish().into()
        } else {
            Arc::from(Vec::new())
        };
        self.outlines.insert(gid.0, curves.clone());
        curves
    }
}

/// The glyph of `ch`: a Unicode character map first, then a Windows symbol map
/// (at `0xF000 + code` or `code`), then the Macintosh Roman map for codes below
/// 256, as fonts of POV-Ray's era need.
fn glyph_of(face: &Face, ch: char) -> Option<GlyphId> {
    let nonzero = |g: Option<GlyphId>| g.filter(|g| g.0 != 0);
    if let Some(g) = nonzero(face.glyph_index(ch)) {
        return Some(g);
    }
    let code = u32::from(ch);
    let cmap = face.tables().cmap?;
    for t in cmap.subtables {
        use ttf_parser::PlatformId;
        let g = match (t.platform_id, t.encoding_id) {
            (PlatformId::Windows, 0) => {
                nonzero(t.glyph_index(0xF000 | code)).or_else(|| nonzero(t.glyph_index(code)))
            }
            (PlatformId::Macintosh, 0) if code < 128 => nonzero(t.glyph_index(code)),
            _ => None,
        };
        if g.is_some() {
            return g;
        }
    }
    None
}

/// The horizontal kerning between two glyphs, in font units, from the font's
/// `kern` table (POV-Ray applies it; OpenType `GPOS` kerning is not used).
fn kerning(face: &Face, left: GlyphId, right: GlyphId) -> f64 {
    let Some(kern) = face.tables().kern else {
        return 0.0;
    };
    kern.subtables
        .into_iter()
        .filter(|s| s.horizontal && !s.variable && !s.has_cross_stream)
        .filter_map(|s| s.glyphs_kerning(left, right))
        .map(f64::from)
        .sum()
}

/// Collects a glyph outline as prism curves `<x, −y>` scaled by `scale`.
pub struct CurveBuilder {
    scale: f64,
    curves: Vec<Curve>,
    start: DVec2,
    at: DVec2,
    open: bool,
}

impl CurveBuilder {
    /// A builder that multiplies font units by `scale`.
    pub fn new(scale: f64) -> CurveBuilder {
        CurveBuilder {
            scale,
            curves: Vec::new(),
            start: DVec2::ZERO,
            at: DVec2::ZERO,
            open: false,
        }
    }

    fn point(&self, x: f32, y: f32) -> DVec2 {
        DVec2::new(f64::from(x), -f64::from(y)) * self.scale
    }

    fn line(&mut self, to: DVec2) {
        if to != self.at {
            self.curves
                .push([self.at, to - self.at, DVec2::ZERO, DVec2::ZERO]);
        }
        self.at = to;
    }

    /// The curves, every contour closed.
    pub fn finish(mut self) -> Vec<Curve> {
        self.close();
        self.curves
            .into_iter()
            .filter(|c| c.iter().all(|p| p.is_finite()))
            .collect()
    }
}

impl OutlineBuilder for CurveBuilder {
    fn move_to(&mut self, x: f32, y: f32) {
        self.close();
        self.start = self.point(x, y);
        self.at = self.start;
        self.open = true;
    }

    fn line_to(&mut self, x: f32, y: f32) {
        let p = self.point(x, y);
        self.line(p);
    }

    fn quad_to(&mut self, x1: f32, y1: f32, x: f32, y: f32) {
        let (a, b, c) = (self.at, self.point(x1, y1), self.point(x, y));
        if a == c && a == b {
            return;
        }
        self.curves
            .push([a, 2.0 * (b - a), a - 2.0 * b + c, DVec2::ZERO]);
        self.at = c;
    }

    fn curve_to(&mut self, x1: f32, y1: f32, x2: f32, y2: f32, x: f32, y: f32) {
        let (a, b, c, d) = (
            self.at,
            self.point(x1, y1),
            self.point(x2, y2),
            self.point(x, y),
        );
        if a == b && b == c && c == d {
            return;
        }
        self.curves.push([
            a,
            3.0 * (b - a),
            3.0 * (a - 2.0 * b + c),
            -a + 3.0 * b - 3.0 * c + d,
        ]);
        self.at = d;
    }

    fn close(&mut self) {
        if self.open {
            let s = self.start;
            self.line(s);
            self.open = false;
        }
    }
}

/// `text_from_glyph`: stands a glyph prism up and puts it at `origin`. The
/// prism's `(x, h, z)` (outline `<x, z> = <x, −y>`, extrusion `h`) goes to the
/// text's `(x + origin.x, −z + origin.y, h)`: a rotation about x, then a move.
pub fn glyph_placement(origin: DVec2) -> DMat4 {
    DMat4::from_cols(
        DVec4::new(1.0, 0.0, 0.0, 0.0),
        DVec4::new(0.0, 0.0, 1.0, 0.0),
        DVec4::new(0.0, -1.0, 0.0, 0.0),
        DVec4::new(origin.x, origin.y, 0.0, 1.0),
    )
}

#[cfg(test)]
mod tests;
