//! `subsurface { … }` (in `finish`, `interior` and `global_settings`) and
//! `mm_per_unit`: POV-Ray 3.7's subsurface light transport. rts reads and checks
//! them so that scenes using them render, warns once per block that they are
//! ignored, and renders the surfaces without the light carried under them.

use crate::diag::{codes, Diagnostic};
use crate::eval::core::cursor::{Cursor, Tok};
use crate::eval::core::{Evaluator, R};
use crate::span::Span;

/// What a `subsurface` block holds: `translucency COLOUR` (in a finish or
/// interior), `samples N, M` and `radiosity BOOL` (in global_settings).
pub(crate) const SUBSURFACE_ITEMS: &[&str] = &["translucency", "samples", "radiosity"];

/// The warning for an ignored subsurface setting.
pub(crate) fn ignored(span: Span, what: &str) -> Diagnostic {
    Diagnostic::warning(
        codes::IGNORED,
        span,
        format!("{what} is read but ignored: rts does not carry light under surfaces"),
    )
    .with_label("no subsurface scattering")
    .with_help("the surface renders as without it; remove it to silence this warning")
}

impl Evaluator<'_> {
    /// `subsurface { [translucency COLOUR] [samples N, M] [radiosity BOOL] }`:
    /// checked and ignored (with a warning).
    pub(crate) fn subsurface(&mut self, c: &mut Cursor) -> R<()> {
        while let Some(tok) = c.next() {
            let r: R<()> = match tok {
                Tok::Kw("translucency", span) => {
                    c.once("translucency", span)?;
                    self.take_colour(c, "the translucency colour (how far light goes under the surface, per colour)")
                        .map(|_| ())
                }
                Tok::Kw("samples", span) => {
                    c.once("samples", span)?;
                    let n =
                        self.take_float(c, "the number of subsurface samples for diffuse light")?;
                    c.comma();
                    let m = self
                        .take_float(c, "the number of subsurface samples for single scattering")?;
                    if n < 1.0 || m < 1.0 {
                        Err(Diagnostic::error(
                            codes::OUT_OF_RANGE,
                            span,
                            format!(
                                "subsurface `samples` are counts of at least 1, found {n}, {m}"
                            ),
                        )
                        .with_help("POV-Ray's defaults are `samples 50, 50`")
                        .into())
                    } else {
                        Ok(())
                    }
                }
                Tok::Kw("radiosity", span) => {
                    c.once("radiosity", span)?;
                    self.take_float(c, "on or off after `radiosity`")
                        .map(|_| ())
                }
                other => Err(self.unexpected(c, &other, SUBSURFACE_ITEMS)),
            };
            if let Err(f) = r {
                self.report(f);
            }
        }
        self.warn(ignored(c.span, "`subsurface`"));
        Ok(())
    }
}
