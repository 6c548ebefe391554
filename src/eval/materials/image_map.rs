//! `image_map { }`: a picture read from a file as a pigment.

use crate::diag::{codes, Diagnostic};
use crate::eval::core::cursor::{Cursor, Tok};
use crate::eval::core::images::ImageFail;
use crate::eval::core::value::Value;
use crate::eval::core::{Evaluator, Fail, R};
use crate::scene::{ImageMap, IndexClear, Pattern, Pigment, Transfer};
use std::sync::Arc;

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

impl Evaluator<'_> {
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
}
