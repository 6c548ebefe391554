//! `photons { … }`: in `global_settings`, how photons are shot and gathered;
//! in an object, whether it is a target and what it does to photons; in a
//! light, which photons it shoots. One reader for all three; each place then
//! takes the items it allows ([`Evaluator::photons_for`]).

use crate::diag::{codes, Diagnostic};
use crate::eval::core::cursor::{Cursor, Tok};
use crate::eval::core::{Evaluator, R};
use crate::scene::{PhotonDensity, PhotonsBlock};
use crate::span::Span;

/// The items of a global `photons` block.
pub(crate) const GLOBAL_ITEMS: &[&str] = &[
    "adc_bailout",
    "autostop",
    "count",
    "expand_thresholds",
    "gather",
    "jitter",
    "load_file",
    "max_trace_level",
    "media",
    "radius",
    "save_file",
    "spacing",
];
/// The items of an object's `photons` block.
pub(crate) const OBJECT_ITEMS: &[&str] = &[
    "collect",
    "pass_through",
    "reflection",
    "refraction",
    "split_union",
    "target",
];
/// The items of a light's `photons` block.
pub(crate) const LIGHT_ITEMS: &[&str] = &["area_light", "reflection", "refraction"];

/// Where a `photons` block stands.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum PhotonsIn {
    Global,
    Object,
    Light,
}

impl PhotonsIn {
    fn items(self) -> &'static [&'static str] {
        match self {
            PhotonsIn::Global => GLOBAL_ITEMS,
            PhotonsIn::Object => OBJECT_ITEMS,
            PhotonsIn::Light => LIGHT_ITEMS,
        }
    }

    fn name(self) -> &'static str {
        match self {
            PhotonsIn::Global => "the global",
            PhotonsIn::Object => "an object's",
            PhotonsIn::Light => "a light's",
        }
    }
}

/// Every item any `photons` block takes.
fn all_items() -> Vec<&'static str> {
    let mut all: Vec<&str> = GLOBAL_ITEMS
        .iter()
        .chain(OBJECT_ITEMS)
        .chain(LIGHT_ITEMS)
        .copied()
        .collect();
    all.sort_unstable();
    all.dedup();
    all
}

impl Evaluator<'_> {
    /// Reads `photons { … }` with the items of every place it may stand.
    pub(crate) fn photons_block(&mut self, c: &mut Cursor) -> R<PhotonsBlock> {
        let mut b = PhotonsBlock::default();
        let mut density_given: Option<(&str, Span)> = None;
        while let Some(tok) = c.next() {
            let res: R<()> = match tok {
                Tok::Kw(kw @ ("spacing" | "count"), span) => {
                    if let Some((prev, at)) = density_given {
                        // Its value is read (and checked) so it is not
                        // reported again as out of place.
                        let mut scratch = PhotonsBlock::default();
                        let _ = self.photon_density(c, kw, &mut scratch);
                        Err(Diagnostic::error(
                            codes::DUPLICATE_PARAMETER,
                            span,
                            format!("photons already has `{prev}`"),
                        )
                        .with_secondary(at, "given here")
                        .with_help("give either `spacing` or `count`, not both")
                        .into())
                    } else {
                        density_given = Some((kw, span));
                        b.items.push((kw, span));
                        self.photon_density(c, kw, &mut b)
                    }
                }
                Tok::Kw("gather", span) => c.once("gather", span).and_then(|()| {
                    b.items.push(("gather", span));
                    let lo = self.photon_whole(c, "the fewest photons an estimate gathers", 1.0)?;
                    c.comma();
                    let hi = self.photon_whole(c, "the most photons an estimate gathers", 1.0)?;
                    if hi < lo {
                        return Err(Diagnostic::error(
                            codes::OUT_OF_RANGE,
                            span,
                            format!("photons `gather {lo}, {hi}`: the most is below the fewest"),
                        )
                        .with_help("write the smaller number first: gather 20, 100")
                        .into());
                    }
                    b.global.gather_min = lo.min(100_000.0) as u32;
                    b.global.gather_max = hi.min(100_000.0) as u32;
                    Ok(())
                }),
                Tok::Kw("jitter", span) => c.once("jitter", span).and_then(|()| {
                    b.items.push(("jitter", span));
                    let (v, s) = c.value("how far photons move within their cells (0 to 1)")?;
                    let x = self.to_float(&v, s)?;
                    if !(0.0..=1.0).contains(&x) {
                        return Err(Diagnostic::error(
                            codes::OUT_OF_RANGE,
                            s,
                            format!("photons `jitter` is from 0 to 1, found {x}"),
                        )
                        .into());
                    }
                    b.global.jitter = x;
                    Ok(())
                }),
                Tok::Kw("max_trace_level", span) => c.once("max_trace_level", span).and_then(|()| {
                    b.items.push(("max_trace_level", span));
                    let n = self.photon_whole(c, "the reflections and refractions a photon makes", 0.0)?;
                    b.global.max_trace_level = Some(n.min(256.0) as u32);
                    Ok(())
                }),
                Tok::Kw("adc_bailout", span) => c.once("adc_bailout", span).and_then(|()| {
                    b.items.push(("adc_bailout", span));
                    let (v, s) = c.value("the smallest share of light a photon carries on")?;
                    let x = self.to_float(&v, s)?;
                    if x < 0.0 {
                        return Err(Diagnostic::error(
                            codes::OUT_OF_RANGE,
                            s,
                            format!("photons `adc_bailout` must not be negative, found {x}"),
                        )
                        .into());
                    }
                    b.global.adc_bailout = Some(x);
                    Ok(())
                }),
                Tok::Kw("radius", span) => c.once("radius", span).and_then(|()| {
                    b.items.push(("radius", span));
                    self.photon_radius(c, &mut b)
                }),
                Tok::Kw(kw @ ("autostop" | "media"), span) => c.once(kw, span).and_then(|()| {
                    b.items.push((kw, span));
                    let (v, s) = c.value("a number")?;
                    let x = self.to_float(&v, s)?;
                    if kw == "autostop" && !(0.0..=1.0).contains(&x) {
                        return Err(Diagnostic::error(
                            codes::OUT_OF_RANGE,
                            s,
                            format!("photons `autostop` is from 0 to 1, found {x}"),
                        )
                        .into());
                    }
                    if kw == "media" {
                        if matches!(c.peek(), Some(Tok::Comma(_))) {
                            c.comma();
                            let (v, s) = c.value("the media photon spacing factor")?;
                            self.to_float(&v, s)?;
                        }
                        if x > 0.0 {
                            self.warn(
                                Diagnostic::warning(
                                    codes::IGNORED,
                                    span,
                                    "photons `media` is read but ignored: rts stores photons on surfaces only",
                                )
                                .with_label("no media photons")
                                .with_help("media are lit by the lights directly; remove it to silence this warning"),
                            );
                        }
                    }
                    Ok(())
                }),
                Tok::Kw("expand_thresholds", span) => {
                    c.once("expand_thresholds", span).and_then(|()| {
                        b.items.push(("expand_thresholds", span));
                        let (v, s) = c.value("the largest increase of an expanded estimate")?;
                        self.to_float(&v, s)?;
                        c.comma();
                        let (v, s) = c.value("the photons an expanded search always keeps")?;
                        self.to_float(&v, s)?;
                        Ok(())
                    })
                }
                Tok::Kw(kw @ ("save_file" | "load_file"), span) => c.once(kw, span).and_then(|()| {
                    b.items.push((kw, span));
                    let (v, s) = c.value("a file name")?;
                    if !matches!(v, crate::eval::core::value::Value::Str(_)) {
                        return Err(self.mismatch("a file name in quotes", &v, s));
                    }
                    self.warn(
                        Diagnostic::warning(
                            codes::IGNORED,
                            span,
                            format!("photons `{kw}` is read but ignored: rts shoots the photons for every render"),
                        )
                        .with_label("no photon map file")
                        .with_help("the picture is the same without it; remove it to silence this warning"),
                    );
                    Ok(())
                }),
                Tok::Kw("target", span) => c.once("target", span).and_then(|()| {
                    b.items.push(("target", span));
                    let m = if c.value_next() {
                        self.take_above_zero(
                            c,
                            "the spacing multiplier",
                            "photons `target` spacing multiplier",
                            "1 shoots at the global spacing; 0.5 twice as densely",
                        )?
                    } else {
                        1.0
                    };
                    b.object.target = Some(m as f32);
                    Ok(())
                }),
                Tok::Kw(kw @ ("refraction" | "reflection" | "collect" | "split_union"), span) => {
                    c.once(kw, span).and_then(|()| {
                        b.items.push((kw, span));
                        let on = self.take_switch(c)?;
                        match kw {
                            "refraction" => {
                                b.object.refraction = on;
                                b.light_refraction = Some(on);
                            }
                            "reflection" => {
                                b.object.reflection = on;
                                b.light_reflection = Some(on);
                            }
                            "collect" => b.object.no_collect = !on,
                            _ => {}
                        }
                        Ok(())
                    })
                }
                Tok::Kw("pass_through", span) => c.once("pass_through", span).and_then(|()| {
                    b.items.push(("pass_through", span));
                    let on = self.take_switch(c)?;
                    b.object.pass_through = on;
                    b.pass_through_off = !on;
                    Ok(())
                }),
                Tok::Kw("area_light", span) => c.once("area_light", span).map(|()| {
                    b.items.push(("area_light", span));
                    b.area_light = true;
                }),
                Tok::Block("reflection", _, span) => Err(Diagnostic::error(
                    codes::UNEXPECTED_ITEM,
                    span,
                    "photons take `reflection on` or `reflection off`, not a reflection block",
                )
                .into()),
                other => Err(self.unexpected(c, &other, &all_items())),
            };
            if let Err(f) = res {
                self.report(f);
            }
        }
        Ok(b)
    }

    /// `spacing S` or `count N`.
    fn photon_density(&mut self, c: &mut Cursor, kw: &str, b: &mut PhotonsBlock) -> R<()> {
        let (v, s) = c.value(if kw == "spacing" {
            "the distance between photons"
        } else {
            "the number of photons to shoot"
        })?;
        let x = self.to_float(&v, s)?;
        b.global.density = if kw == "spacing" {
            if !(x > 0.0 && x.is_finite()) {
                return Err(Diagnostic::error(
                    codes::OUT_OF_RANGE,
                    s,
                    format!("photons `spacing` must be above 0, found {x}"),
                )
                .with_help("a typical spacing is 1/100 to 1/1000 of the scene's size")
                .into());
            }
            PhotonDensity::Spacing(x)
        } else {
            if !(x >= 1.0 && x.is_finite()) {
                return Err(Diagnostic::error(
                    codes::OUT_OF_RANGE,
                    s,
                    format!("photons `count` must be at least 1, found {x}"),
                )
                .with_help("a typical count is 10000 to 1000000")
                .into());
            }
            PhotonDensity::Count(x.round() as u64)
        };
        Ok(())
    }

    /// `radius [R] [, M [, RM [, MM]]]`: every part optional.
    fn photon_radius(&mut self, c: &mut Cursor, b: &mut PhotonsBlock) -> R<()> {
        let mut parts: Vec<Option<f64>> = Vec::new();
        loop {
            let x = if c.value_next() {
                let (v, s) = c.value("a gather radius or multiplier")?;
                let x = self.to_float(&v, s)?;
                if x < 0.0 {
                    return Err(Diagnostic::error(
                        codes::OUT_OF_RANGE,
                        s,
                        format!("photons `radius` values must not be negative, found {x}"),
                    )
                    .into());
                }
                Some(x)
            } else {
                None
            };
            parts.push(x);
            if parts.len() == 4 || !matches!(c.peek(), Some(Tok::Comma(_))) {
                break;
            }
            c.comma();
        }
        b.global.radius = parts[0].filter(|&r| r > 0.0);
        if let Some(Some(m)) = parts.get(1) {
            if *m > 0.0 {
                b.global.radius_multiplier = *m;
            }
        }
        Ok(())
    }

    /// A whole number of at least `min`.
    fn photon_whole(&mut self, c: &mut Cursor, what: &str, min: f64) -> R<f64> {
        let (v, s) = c.value(what)?;
        let x = self.to_float(&v, s)?;
        if x < min || x.fract() != 0.0 || !x.is_finite() {
            return Err(Diagnostic::error(
                codes::OUT_OF_RANGE,
                s,
                format!("{what}: expected a whole number from {min}, found {x}"),
            )
            .into());
        }
        Ok(x)
    }

    /// Checks that block `b` (at `span`) has only the items of `place`,
    /// reporting each other one.
    pub(crate) fn photons_for(&mut self, b: &PhotonsBlock, place: PhotonsIn, span: Span) {
        for &(kw, at) in &b.items {
            if place.items().contains(&kw) {
                continue;
            }
            let belongs = [PhotonsIn::Global, PhotonsIn::Object, PhotonsIn::Light]
                .into_iter()
                .filter(|p| p.items().contains(&kw))
                .map(|p| match p {
                    PhotonsIn::Global => "global_settings { photons { … } }",
                    PhotonsIn::Object => "an object's photons { … }",
                    PhotonsIn::Light => "a light_source's photons { … }",
                })
                .collect::<Vec<_>>()
                .join(" or ");
            self.report(
                Diagnostic::error(
                    codes::UNEXPECTED_ITEM,
                    at,
                    format!("`{kw}` does not belong in {} photons block", place.name()),
                )
                .with_secondary(span, "in this photons block")
                .with_help(format!("`{kw}` goes in {belongs}"))
                .into(),
            );
        }
    }
}
