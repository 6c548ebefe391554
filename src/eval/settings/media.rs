//! `media { … }`, `scattering { … }` and `density { … }`.

use crate::diag::{codes, Diagnostic};
use crate::eval::core::cursor::{Cursor, Tok};
use crate::eval::core::transforms::TRANSFORMS;
use crate::eval::core::value::Value;
use crate::eval::core::{Evaluator, Fail, R};
use crate::scene::{Colour, Media, Pattern, Pigment, Scattering, ScatteringKind};
use crate::span::Span;

/// What a `media { }` accepts.
pub(crate) const MEDIA_ITEMS: &[&str] = &[
    "method",
    "intervals",
    "samples",
    "confidence",
    "variance",
    "ratio",
    "jitter",
    "aa_threshold",
    "aa_level",
    "absorption",
    "emission",
    "scattering",
    "density",
    "translate",
    "rotate",
    "scale",
    "matrix",
    "transform",
];

/// What a `scattering { }` accepts after its type and colour.
pub(crate) const SCATTERING_ITEMS: &[&str] = &["eccentricity", "extinction"];

/// The most samples per interval rts takes (a bound on every loop).
pub(crate) const MAX_SAMPLES: f64 = 10_000.0;
/// The most intervals along one ray.
pub(crate) const MAX_INTERVALS: f64 = 10_000.0;

impl Evaluator<'_> {
    /// `media { [MEDIA_IDENTIFIER] items… }`: one participating medium (placed in
    /// the atmosphere at top level, in an `interior { }`, or declared).
    pub(crate) fn media(&mut self, c: &mut Cursor) -> R<Media> {
        let mut m = match c.peek() {
            Some(Tok::Val(Value::Media(_), _)) => match c.next() {
                Some(Tok::Val(Value::Media(x), _)) => (*x).clone(),
                _ => unreachable!(),
            },
            Some(Tok::Val(Value::Poison, _)) => return Err(Fail::silent()),
            _ => Media::default(),
        };
        while let Some(tok) = c.next() {
            let r: R<()> = match tok {
                Tok::Kw("method", span) => {
                    c.once("method", span)?;
                    let (n, s) = self.media_int(c, "the sampling method (1, 2 or 3)")?;
                    if (1..=3).contains(&n) {
                        m.method = n as u8;
                        Ok(())
                    } else {
                        Err(range(
                            s,
                            format!("`method` is 1, 2 or 3, found {n}"),
                            "3 (adaptive) is the default; 1 samples at random, 2 evenly with jitter",
                        ))
                    }
                }
                Tok::Kw("intervals", span) => {
                    c.once("intervals", span)?;
                    let (n, s) = self.media_int(c, "the number of intervals")?;
                    if n >= 1 && (n as f64) <= MAX_INTERVALS {
                        m.intervals = n as u32;
                        Ok(())
                    } else {
                        Err(range(
                            s,
                            format!("`intervals` is 1 to {MAX_INTERVALS}, found {n}"),
                            "the default is 1; with method 3 more intervals are rarely needed",
                        ))
                    }
                }
                Tok::Kw("samples", span) => {
                    c.once("samples", span)?;
                    let (lo, s) = self.media_int(c, "the least number of samples")?;
                    c.comma();
                    let hi = if c.value_next() {
                        Some(self.media_int(c, "the most samples")?)
                    } else {
                        None
                    };
                    let in_range = |n: i64| n >= 1 && (n as f64) <= MAX_SAMPLES;
                    if !in_range(lo) {
                        return Err(range(
                            s,
                            format!("`samples` must be 1 to {MAX_SAMPLES}, found {lo}"),
                            "write `samples 10` or `samples 10, 50`",
                        ));
                    }
                    let hi_v = match hi {
                        Some((h, hs)) if !in_range(h) || h < lo => {
                            return Err(range(
                                hs,
                                format!(
                                    "the most samples must be {lo} to {MAX_SAMPLES}, found {h}"
                                ),
                                "the second number is the most samples, not less than the first",
                            ));
                        }
                        Some((h, _)) => h,
                        // POV-Ray 3.7: a single value sets both.
                        None => lo,
                    };
                    m.min_samples = lo as u32;
                    m.max_samples = hi_v as u32;
                    Ok(())
                }
                Tok::Kw(kw @ ("confidence" | "ratio"), span) => {
                    c.once(kw, span)?;
                    let (v, s) = c.value(&format!("the {kw} (0 to 1)"))?;
                    let x = self.to_float(&v, s)?;
                    let ok = if kw == "confidence" {
                        x > 0.0 && x < 1.0
                    } else {
                        (0.0..=1.0).contains(&x)
                    };
                    if !ok {
                        return Err(range(
                            s,
                            format!("`{kw}` is between 0 and 1, found {x}"),
                            if kw == "confidence" {
                                "the default is 0.9"
                            } else {
                                "the default is 0.9: nine tenths of the intervals go to lit parts"
                            },
                        ));
                    }
                    if kw == "confidence" {
                        m.confidence = x;
                    } else {
                        m.ratio = x;
                    }
                    Ok(())
                }
                Tok::Kw(kw @ ("variance" | "jitter" | "aa_threshold"), span) => {
                    c.once(kw, span)?;
                    let (v, s) = c.value(&format!("the {kw}"))?;
                    let x = self.to_float(&v, s)?;
                    if x < 0.0 || !x.is_finite() {
                        return Err(range(
                            s,
                            format!("`{kw}` must not be negative, found {x}"),
                            "see docs/language.md, Media, for the defaults",
                        ));
                    }
                    match kw {
                        "variance" => m.variance = x,
                        "jitter" => m.jitter = x,
                        _ => m.aa_threshold = x,
                    }
                    Ok(())
                }
                Tok::Kw("aa_level", span) => {
                    c.once("aa_level", span)?;
                    let (n, s) = self.media_int(c, "the most subdivisions")?;
                    if (1..=16).contains(&n) {
                        m.aa_level = n as u32;
                        Ok(())
                    } else {
                        Err(range(
                            s,
                            format!("`aa_level` is 1 to 16, found {n}"),
                            "the default is 3",
                        ))
                    }
                }
                Tok::Kw(kw @ ("absorption" | "emission"), span) => {
                    c.once(kw, span)?;
                    self.take_colour(c, &format!("the {kw} colour")).map(|col| {
                        if kw == "absorption" {
                            m.absorption = col.rgb;
                        } else {
                            m.emission = col.rgb;
                        }
                    })
                }
                Tok::Block("scattering", Value::Scattering(s), span) => {
                    if m.scattering.is_some() {
                        self.warn(
                            Diagnostic::warning(
                                codes::DUPLICATE_PARAMETER,
                                span,
                                "a second `scattering` replaces the first",
                            )
                            .with_help("a media has one scattering; use two media for two"),
                        );
                    }
                    m.scattering = Some(s);
                    Ok(())
                }
                Tok::Block("density", Value::Pigment(p), _) => {
                    m.density.push((*p).clone());
                    Ok(())
                }
                Tok::Kw(kw, span) if TRANSFORMS.contains(&kw) => {
                    self.transform_kw(kw, span, c).map(|t| m.transform(&t))
                }
                Tok::Block(_, Value::Transform(t), _) => {
                    m.transform(&t);
                    Ok(())
                }
                other => {
                    let f = self.unexpected(c, &other, MEDIA_ITEMS);
                    // The unknown keyword's value is not reported again.
                    c.poisoned = matches!(other, Tok::Kw(..));
                    Err(f)
                }
            };
            if let Err(f) = r {
                self.report(f);
            }
        }
        Ok(m)
    }

    /// `scattering { TYPE, COLOUR [eccentricity E] [extinction X] }`.
    pub(crate) fn scattering(&mut self, c: &mut Cursor) -> R<Scattering> {
        let (n, s) = self.media_int(c, "the scattering type (1 to 5)")?;
        let Some(kind) = ScatteringKind::from_number(n) else {
            return Err(range(
                s,
                format!("the scattering type is 1 to 5, found {n}"),
                "1 isotropic, 2 Mie haze, 3 Mie murky, 4 Rayleigh, 5 Henyey-Greenstein",
            ));
        };
        c.comma();
        let colour = self.take_colour(c, "the scattering colour")?.rgb;
        let mut sc = Scattering {
            kind,
            colour,
            eccentricity: 0.0,
            extinction: 1.0,
        };
        while let Some(tok) = c.next() {
            let r: R<()> = match tok {
                Tok::Kw("eccentricity", span) => {
                    c.once("eccentricity", span)?;
                    let (v, s) = c.value("the eccentricity (-1 to 1)")?;
                    let e = self.to_float(&v, s)?;
                    if e.abs() >= 1.0 {
                        Err(range(
                            s,
                            format!("`eccentricity` lies strictly between -1 and 1, found {e}"),
                            "positive scatters forwards, negative backwards, 0 evenly",
                        ))
                    } else {
                        if kind != ScatteringKind::HenyeyGreenstein {
                            self.warn(
                                Diagnostic::warning(
                                    codes::IGNORED,
                                    span,
                                    "`eccentricity` only shapes scattering type 5",
                                )
                                .with_help("use `scattering { 5, COLOUR eccentricity E }`"),
                            );
                        }
                        sc.eccentricity = e;
                        Ok(())
                    }
                }
                Tok::Kw("extinction", span) => {
                    c.once("extinction", span)?;
                    self.take_float(c, "the extinction")
                        .map(|x| sc.extinction = x)
                }
                other => {
                    let f = self.unexpected(c, &other, SCATTERING_ITEMS);
                    c.poisoned = matches!(other, Tok::Kw(..));
                    Err(f)
                }
            };
            if let Err(f) = r {
                self.report(f);
            }
        }
        Ok(sc)
    }

    /// `density { [DENSITY_IDENTIFIER] [PATTERN] [density_map { … }] modifiers
    /// transforms }`: a pigment whose colour scales a media's coefficients. Without
    /// a pattern it is 1 everywhere; a pattern without a map takes the pattern's
    /// default colour map, as in a pigment (measured: `bozo` is white, green,
    /// blue and red).
    pub(crate) fn density(&mut self, c: &mut Cursor) -> R<Pigment> {
        // A media's density is 1 where nothing else is said.
        let one = Pigment {
            pattern: Pattern::Solid(Colour::rgb(1.0, 1.0, 1.0)),
            transform: None,
        };
        self.pigment_from(one, c)
    }

    /// The next value as a whole number (a float with no fraction).
    fn media_int(&mut self, c: &mut Cursor, what: &str) -> R<(i64, Span)> {
        let (v, s) = c.value(what)?;
        let x = self.to_float(&v, s)?;
        if !x.is_finite() || x.abs() > 1e9 {
            return Err(range(
                s,
                format!("{what} is too large: {x}"),
                "use a small whole number",
            ));
        }
        // POV-Ray truncates these to integers.
        Ok((x.trunc() as i64, s))
    }
}

fn range(span: Span, msg: impl Into<String>, help: &str) -> Fail {
    Diagnostic::error(codes::OUT_OF_RANGE, span, msg)
        .with_label("out of range")
        .with_help(help.to_string())
        .into()
}
