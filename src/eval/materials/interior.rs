//! `interior { }` blocks: refraction, fading, caustics, dispersion and media.

use crate::diag::{codes, Diagnostic};
use crate::eval::core::cursor::{Cursor, Tok};
use crate::eval::core::value::Value;
use crate::eval::core::{Evaluator, Fail, R};
use crate::scene::Interior;

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

impl Evaluator<'_> {
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
}
