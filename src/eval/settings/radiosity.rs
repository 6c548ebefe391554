//! `radiosity { … }`: in `global_settings`, POV-Ray 3.7's radiosity settings;
//! in an object, its `importance`.

use crate::diag::{codes, Diagnostic};
use crate::eval::core::cursor::{Cursor, Tok};
use crate::eval::core::{Evaluator, R};
use crate::scene::{Radiosity, RadiosityBlock};
use crate::span::Span;

/// The items of a `radiosity` block.
pub(crate) const RADIOSITY_ITEMS: &[&str] = &[
    "adc_bailout",
    "always_sample",
    "brightness",
    "count",
    "error_bound",
    "gray_threshold",
    "importance",
    "low_error_factor",
    "max_sample",
    "maximum_reuse",
    "media",
    "minimum_reuse",
    "nearest_count",
    "normal",
    "pretrace_end",
    "pretrace_start",
    "recursion_limit",
    "subsurface",
];

/// `x` unless it lies outside `lo..=hi` (or is not whole when `whole`).
fn within(kw: &str, x: f64, (lo, hi): (f64, f64), whole: bool, span: Span) -> R<f64> {
    if !(lo..=hi).contains(&x) || (whole && x.fract() != 0.0) {
        let kind = if whole { "a whole number" } else { "a number" };
        return Err(Diagnostic::error(
            codes::OUT_OF_RANGE,
            span,
            format!("radiosity `{kw}` must be {kind} from {lo} to {hi}, found {x}"),
        )
        .into());
    }
    Ok(x)
}

impl Evaluator<'_> {
    /// `radiosity { count N [, M] error_bound F … }` or, in an object,
    /// `radiosity { importance F }`.
    pub(crate) fn radiosity_block(&mut self, c: &mut Cursor) -> R<RadiosityBlock> {
        let mut r = Radiosity::default();
        let mut importance = None;
        let mut global_item = None;
        let (mut min_given, mut max_given) = (false, false);
        while let Some(tok) = c.next() {
            if let Tok::Kw(kw, span) = &tok {
                if *kw != "importance" && global_item.is_none() {
                    global_item = Some(*span);
                }
            }
            let res: R<()> = match tok {
                Tok::Kw("importance", span) => c.once("importance", span).and_then(|()| {
                    let (v, s) = c.value("the share of gathering rays to compute (0 to 1)")?;
                    let x = self.to_float(&v, s)?;
                    if !(x > 0.0 && x <= 1.0) {
                        return Err(Diagnostic::error(
                            codes::OUT_OF_RANGE,
                            s,
                            format!(
                                "radiosity `importance` must be above 0 and at most 1, found {x}"
                            ),
                        )
                        .into());
                    }
                    importance = Some((x, span));
                    Ok(())
                }),
                Tok::Kw("count", span) => c.once("count", span).and_then(|()| {
                    let (v, s) = c.value("the rays gathered per value")?;
                    let n = within("count", self.to_float(&v, s)?, (1.0, 1e5), true, s)?;
                    r.count = n as u32;
                    r.count_pool = r.count;
                    if matches!(c.peek(), Some(Tok::Comma(_))) {
                        c.comma();
                        let (v, s) = c.value("the number of directions to draw from")?;
                        let m = within("count", self.to_float(&v, s)?, (n, 1e6), true, s)?;
                        r.count_pool = m as u32;
                    }
                    Ok(())
                }),
                Tok::Kw("nearest_count", span) => c.once("nearest_count", span).and_then(|()| {
                    let (v, s) = c.value("the fewest values blended")?;
                    r.nearest_count =
                        within("nearest_count", self.to_float(&v, s)?, (1.0, 20.0), true, s)?
                            as u32;
                    if matches!(c.peek(), Some(Tok::Comma(_))) {
                        // The adaptive pretrace's target: accepted; every pass
                        // of rts's pretrace covers the whole image.
                        c.comma();
                        let (v, s) = c.value("the adaptive pretrace's target count")?;
                        within("nearest_count", self.to_float(&v, s)?, (1.0, 20.0), true, s)?;
                    }
                    Ok(())
                }),
                Tok::Kw("recursion_limit", span) => {
                    c.once("recursion_limit", span).and_then(|()| {
                        let (v, s) = c.value("the bounces of diffuse light")?;
                        r.recursion_limit = within(
                            "recursion_limit",
                            self.to_float(&v, s)?,
                            (1.0, 20.0),
                            true,
                            s,
                        )? as u32;
                        Ok(())
                    })
                }
                Tok::Kw(
                    kw @ ("adc_bailout" | "brightness" | "error_bound" | "gray_threshold"
                    | "low_error_factor" | "max_sample" | "maximum_reuse" | "minimum_reuse"
                    | "pretrace_start" | "pretrace_end"),
                    span,
                ) => c.once(kw, span).and_then(|()| {
                    let (v, s) = c.value("a number")?;
                    let x = self.to_float(&v, s)?;
                    let (lo, hi) = match kw {
                        "gray_threshold" | "low_error_factor" | "maximum_reuse"
                        | "minimum_reuse" | "pretrace_start" | "pretrace_end" => (0.0, 1.0),
                        "max_sample" => (f64::NEG_INFINITY, f64::INFINITY),
                        _ => (0.0, f64::INFINITY),
                    };
                    let x = within(kw, x, (lo, hi), false, s)?;
                    match kw {
                        "adc_bailout" => r.adc_bailout = x,
                        "brightness" => r.brightness = x,
                        "error_bound" => r.error_bound = x.max(1e-4),
                        "gray_threshold" => r.gray_threshold = x,
                        "low_error_factor" => r.low_error_factor = x.max(1e-3),
                        "max_sample" => r.max_sample = x,
                        "maximum_reuse" => {
                            r.maximum_reuse = x;
                            max_given = true;
                        }
                        "minimum_reuse" => {
                            r.minimum_reuse = x;
                            min_given = true;
                        }
                        "pretrace_start" => r.pretrace_start = x,
                        _ => r.pretrace_end = x,
                    }
                    Ok(())
                }),
                Tok::Kw(kw @ ("always_sample" | "media" | "normal" | "subsurface"), span) => {
                    c.once(kw, span).and_then(|()| {
                        let on = self.take_switch(c)?;
                        match kw {
                            "always_sample" => r.always_sample = on,
                            "media" => r.media = on,
                            "normal" => r.normal = on,
                            _ if on => self.warn(crate::eval::materials::subsurface::ignored(
                                span,
                                "radiosity `subsurface`",
                            )),
                            _ => {}
                        }
                        Ok(())
                    })
                }
                Tok::Block("normal", _, span) => Err(Diagnostic::error(
                    codes::UNEXPECTED_ITEM,
                    span,
                    "radiosity takes `normal on` or `normal off`, not a normal block",
                )
                .into()),
                other => Err(self.unexpected(c, &other, RADIOSITY_ITEMS)),
            };
            if let Err(f) = res {
                self.report(f);
            }
        }
        self.reuse_bounds(&mut r, min_given, max_given, c.span)?;
        if r.pretrace_end > r.pretrace_start {
            r.pretrace_end = r.pretrace_start;
        }
        Ok(RadiosityBlock {
            settings: r,
            importance,
            global_item,
        })
    }

    /// POV-Ray's rules for `minimum_reuse` against `maximum_reuse`.
    fn reuse_bounds(
        &mut self,
        r: &mut Radiosity,
        min_given: bool,
        max_given: bool,
        span: Span,
    ) -> R<()> {
        if r.minimum_reuse >= r.maximum_reuse {
            return Err(Diagnostic::error(
                codes::OUT_OF_RANGE,
                span,
                format!(
                    "radiosity `minimum_reuse` ({}) must be below `maximum_reuse` ({})",
                    r.minimum_reuse, r.maximum_reuse
                ),
            )
            .into());
        }
        if r.minimum_reuse > r.maximum_reuse / 2.0 {
            let adjusted = match (min_given, max_given) {
                (true, false) => {
                    r.maximum_reuse = 2.0 * r.minimum_reuse;
                    format!("`maximum_reuse` raised to {}", r.maximum_reuse)
                }
                (false, true) => {
                    r.minimum_reuse = r.maximum_reuse / 2.0;
                    format!("`minimum_reuse` lowered to {}", r.minimum_reuse)
                }
                _ => "both kept as given".to_string(),
            };
            self.warn(
                Diagnostic::warning(
                    codes::OUT_OF_RANGE,
                    span,
                    format!(
                        "radiosity `minimum_reuse` is more than half `maximum_reuse`: {adjusted}"
                    ),
                )
                .with_help("as POV-Ray 3.7 does; keep minimum_reuse at most half of maximum_reuse"),
            );
        }
        Ok(())
    }
}
