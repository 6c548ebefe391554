//! `path_tracing { … }` inside `global_settings` (an rts addition): the path
//! tracer's settings, see docs/pathtracing.md.

use crate::diag::{codes, Diagnostic};
use crate::eval::core::cursor::{Cursor, Tok};
use crate::eval::core::{Evaluator, R};
use crate::scene::{PathTracing, PixelFilter};
use crate::span::Span;

/// The parameters of `path_tracing`.
pub(crate) const PATH_ITEMS: &[&str] = &["samples", "max_depth", "firefly_clamp", "pixel_filter"];

/// A whole number in `lo..=hi` or an out-of-range error naming `kw`.
fn whole(kw: &str, n: f64, lo: f64, hi: f64, span: Span) -> R<u32> {
    if !(lo..=hi).contains(&n) || n.fract() != 0.0 {
        return Err(Diagnostic::error(
            codes::OUT_OF_RANGE,
            span,
            format!("{kw} must be a whole number from {lo} to {hi}, found {n}"),
        )
        .into());
    }
    Ok(n as u32)
}

impl Evaluator<'_> {
    /// `path_tracing { samples N max_depth N firefly_clamp X pixel_filter "box" }`:
    /// sets the scene's path tracing settings (and so selects the path tracer).
    pub(crate) fn path_tracing(&mut self, c: &mut Cursor) -> R<()> {
        let mut p = PathTracing::default();
        while let Some(tok) = c.next() {
            let r: R<()> = match tok {
                Tok::Kw("samples", span) => c.once("samples", span).and_then(|()| {
                    let (v, s) = c.value("the samples per pixel")?;
                    p.samples = whole("samples", self.to_float(&v, s)?, 1.0, 65536.0, s)?;
                    Ok(())
                }),
                Tok::Kw("max_depth", span) => c.once("max_depth", span).and_then(|()| {
                    let (v, s) = c.value("the longest path (segments)")?;
                    p.max_depth = whole("max_depth", self.to_float(&v, s)?, 1.0, 1024.0, s)?;
                    Ok(())
                }),
                Tok::Kw("firefly_clamp", span) => c.once("firefly_clamp", span).and_then(|()| {
                    let (v, s) = c.value("the largest value of one sample")?;
                    let x = self.to_float(&v, s)?;
                    if !(x >= 0.0 && x.is_finite()) {
                        return Err(Diagnostic::error(
                            codes::OUT_OF_RANGE,
                            s,
                            format!("firefly_clamp must be 0 (off) or positive, found {x}"),
                        )
                        .into());
                    }
                    p.firefly_clamp = x;
                    Ok(())
                }),
                Tok::Kw("pixel_filter", span) => c.once("pixel_filter", span).and_then(|()| {
                    let (v, s) = c.value("the filter name (\"box\" or \"gaussian\")")?;
                    let name = self.to_str(&v, s)?;
                    p.filter = match &*name {
                        "box" => PixelFilter::Box,
                        "gaussian" => PixelFilter::Gaussian,
                        other => {
                            return Err(Diagnostic::error(
                                codes::OUT_OF_RANGE,
                                s,
                                format!("unknown pixel filter \"{other}\""),
                            )
                            .with_help("write \"box\" or \"gaussian\"")
                            .into())
                        }
                    };
                    Ok(())
                }),
                other => Err(self.unexpected(c, &other, PATH_ITEMS)),
            };
            if let Err(f) = r {
                self.report(f);
            }
        }
        self.scene.global.path_tracing = Some(p);
        Ok(())
    }
}
