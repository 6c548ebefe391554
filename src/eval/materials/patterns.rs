//! Pattern keywords inside `pigment` and `normal`: the pattern, its modifiers,
//! `color_map`, `pigment_map` and list entries.

use crate::diag::{codes, Diagnostic};
use crate::eval::core::cursor::{Cursor, Tok};
use crate::eval::core::value::Value;
use crate::eval::core::{Evaluator, Fail, R};
use crate::scene::{Colour, PatternKind, PatternMap, PatternMods, Pigment, Wave};
use glam::DVec3;
use std::sync::Arc;

/// Pattern keywords this release evaluates.
pub(crate) const PATTERNS: &[&str] = &[
    "checker",
    "object",
    "hexagon",
    "square",
    "triangular",
    "brick",
    "gradient",
    "radial",
    "onion",
    "leopard",
    "spotted",
    "bozo",
    "marble",
    "wood",
    "granite",
    "agate",
    "wrinkles",
    "ripples",
    "waves",
    "bumps",
    "dents",
    "crackle",
    "function",
    // Geometric, quilted, spiral and fractal patterns.
    "planar",
    "spherical",
    "cylindrical",
    "boxed",
    "quilted",
    "spiral1",
    "spiral2",
    "mandel",
    "julia",
    "magnet",
    "pigment_pattern",
    "image_pattern",
    "slope",
    "average",
    "density_file",
    "cells",
];

/// Pattern modifiers.
pub(crate) const MODIFIERS: &[&str] = &[
    "turbulence",
    "octaves",
    "omega",
    "lambda",
    "frequency",
    "phase",
    "ramp_wave",
    "triangle_wave",
    "sine_wave",
    "scallop_wave",
    "cubic_wave",
    "poly_wave",
    "brick_size",
    "mortar",
    "agate_turb",
    "form",
    "metric",
    "offset",
    "solid",
    "control0",
    "control1",
    "exponent",
    "exterior",
    "interior",
    "noise_generator",
];

/// A pattern being read: kind, modifiers and map.
#[derive(Default)]
pub(crate) struct PatternSpec {
    pub(crate) kind: Option<PatternKind>,
    pub(crate) mods: PatternMods,
    pub(crate) wave: Option<Wave>,
    pub(crate) map: Option<PatternMap>,
    pub(crate) list: Vec<Pigment>,
}

impl PatternSpec {
    /// The modifiers with the pattern's own default wave.
    pub(crate) fn final_mods(&self) -> PatternMods {
        let mut m = self.mods.clone();
        let kind = self.kind.clone().unwrap_or(PatternKind::Bozo);
        m.wave = self.wave.unwrap_or(match kind {
            PatternKind::Marble
            | PatternKind::Wood
            | PatternKind::Spiral1(_)
            | PatternKind::Spiral2(_) => Wave::Triangle,
            _ => Wave::Ramp,
        });
        m
    }
}

fn solid(c: Colour) -> Pigment {
    Pigment {
        pattern: crate::scene::Pattern::Solid(c),
        transform: None,
    }
}

/// The colour map a pattern uses when none is given (measured on POV-Ray 3.7).
pub(crate) fn default_map(kind: &PatternKind) -> PatternMap {
    let c = Colour::rgb;
    let e: Vec<(f64, Colour)> = match kind {
        PatternKind::Marble => vec![
            (0.0, c(0.9, 0.8, 0.8)),
            (0.9, c(0.9, 0.08, 0.08)),
            (0.9, c(0.0, 0.0, 0.0)),
        ],
        PatternKind::Wood => vec![(0.6, c(0.666, 0.312, 0.2)), (0.6, c(0.4, 0.133, 0.066))],
        PatternKind::Radial => vec![
            (0.0, c(0.0, 1.0, 1.0)),
            (1.0 / 3.0, c(1.0, 1.0, 0.0)),
            (2.0 / 3.0, c(1.0, 0.0, 1.0)),
            (1.0, c(0.0, 1.0, 1.0)),
        ],
        PatternKind::Bozo => vec![
            (0.4, c(1.0, 1.0, 1.0)),
            (0.4, c(0.0, 1.0, 0.0)),
            (0.6, c(0.0, 1.0, 0.0)),
            (0.6, c(0.0, 0.0, 1.0)),
            (0.8, c(0.0, 0.0, 1.0)),
            (0.8, c(1.0, 0.0, 0.0)),
        ],
        PatternKind::Agate => vec![
            (0.0, c(1.0, 1.0, 1.0)),
            (0.5, c(0.95, 0.75, 0.5)),
            (1.0, c(0.6, 0.3, 0.01)),
        ],
        _ => vec![(0.0, c(0.0, 0.0, 0.0)), (1.0, c(1.0, 1.0, 1.0))],
    };
    PatternMap::Colours(Arc::new(e))
}

impl Evaluator<'_> {
    /// A pattern being read, with the `noise_generator` in force.
    pub(crate) fn new_spec(&self) -> PatternSpec {
        let mut spec = PatternSpec::default();
        spec.mods.noise_generator = self.scene.global.noise_generator;
        spec.mods.number_of_waves = self.scene.global.number_of_waves;
        spec
    }

    /// `noise_generator N` in `global_settings` (1, 2 or 3).
    pub(crate) fn noise_generator(&mut self, c: &mut Cursor, _kw: crate::span::Span) -> R<()> {
        let (v, s) = c.value("the noise generator (1, 2 or 3)")?;
        let n = self.to_float(&v, s)?;
        if !(1.0..=3.0).contains(&n) || n.fract() != 0.0 {
            return Err(Diagnostic::error(
                codes::OUT_OF_RANGE,
                s,
                format!("noise_generator must be 1, 2 or 3, found {n}"),
            )
            .with_help("2 is POV-Ray's default")
            .into());
        }
        self.scene.global.noise_generator = n as u8;
        Ok(())
    }

    /// Reads the parameters that follow pattern keyword `kw` (already taken,
    /// with the pattern it `carried` if it was written as a block, see
    /// [`pattern_token`](super::pattern_blocks::pattern_token)); list patterns
    /// read their entries when `entries` (pigments; not normals).
    pub(crate) fn pattern_kw(
        &mut self,
        kw: &str,
        carried: Option<PatternKind>,
        c: &mut Cursor,
        spec: &mut PatternSpec,
        entries: bool,
    ) -> R<()> {
        let kind = match kw {
            "checker" => PatternKind::Checker,
            "hexagon" => PatternKind::Hexagon,
            "square" => PatternKind::Square,
            "triangular" => PatternKind::Triangular,
            "brick" => PatternKind::Brick {
                size: DVec3::new(8.0, 3.0, 4.5),
                mortar: 0.5,
            },
            "gradient" => {
                let v = self.take_vec3(c, "the gradient's direction")?;
                let len = v.length();
                PatternKind::Gradient(if len > 0.0 { v / len } else { DVec3::X })
            }
            "radial" => PatternKind::Radial,
            "onion" => PatternKind::Onion,
            "leopard" => PatternKind::Leopard,
            "spotted" | "bozo" => PatternKind::Bozo,
            "marble" => PatternKind::Marble,
            "wood" => PatternKind::Wood,
            "granite" => PatternKind::Granite,
            "crackle" => PatternKind::Crackle {
                form: DVec3::new(-1.0, 1.0, 0.0),
                metric: 2.0,
                solid: false,
                offset: 0.0,
            },
            "agate" => PatternKind::Agate,
            "wrinkles" => PatternKind::Wrinkles,
            "ripples" => PatternKind::Ripples,
            "waves" => PatternKind::Waves,
            "bumps" => PatternKind::Bumps,
            "function" => carried.ok_or_else(|| {
                Diagnostic::error(
                    codes::MISSING_VALUE,
                    c.last,
                    "the `function` pattern needs its expression in braces",
                )
                .with_help("write `function { x*x + y*y }` or `function { F(x, y, z) }`")
            })?,
            "planar" | "spherical" | "cylindrical" | "boxed" | "quilted" | "spiral1"
            | "spiral2" | "mandel" | "julia" | "magnet" => self.shape_pattern(kw, c)?,
            "pigment_pattern" | "image_pattern" | "slope" | "object" => {
                self.block_pattern(kw, carried, c)?
            }
            "average" => PatternKind::Average,
            "density_file" => self.density_file(c)?,
            "cells" => PatternKind::Cells,
            _ => PatternKind::Dents,
        };
        spec.kind = Some(kind.clone());
        if kind.is_list() && entries {
            self.list_entries(c, spec)?;
        }
        Ok(())
    }

    /// The colours or pigments after `checker`, `hexagon`, `square`,
    /// `triangular` or `brick`.
    fn list_entries(&mut self, c: &mut Cursor, spec: &mut PatternSpec) -> R<()> {
        let max = match spec.kind {
            Some(PatternKind::Hexagon) => 3,
            Some(PatternKind::Square) => 4,
            Some(PatternKind::Triangular) => 6,
            _ => 2,
        };
        spec.list.clear();
        while spec.list.len() < max {
            match c.peek() {
                Some(Tok::Val(Value::Colour(_) | Value::Vector(_) | Value::Float(_), _)) => {
                    let col = self.take_colour(c, "a colour")?;
                    spec.list.push(solid(col));
                }
                Some(Tok::Block(_, Value::Pigment(_), _) | Tok::Val(Value::Pigment(_), _)) => {
                    if let Some(
                        Tok::Block(_, Value::Pigment(p), _) | Tok::Val(Value::Pigment(p), _),
                    ) = c.next()
                    {
                        spec.list.push((*p).clone());
                    }
                }
                Some(Tok::Val(Value::Poison, _)) => {
                    c.next();
                    return Err(Fail::silent());
                }
                _ => break,
            }
            c.comma();
        }
        Ok(())
    }

    /// The default entries of a list pattern (POV-Ray's colours).
    pub(crate) fn complete_list(kind: &PatternKind, list: &mut Vec<Pigment>) {
        let defaults: &[Colour] = match kind {
            PatternKind::Hexagon => &[
                Colour::rgb(0.0, 0.0, 1.0),
                Colour::rgb(0.0, 1.0, 0.0),
                Colour::rgb(1.0, 0.0, 0.0),
            ],
            PatternKind::Brick { .. } => {
                &[Colour::rgb(0.5, 0.5, 0.5), Colour::rgb(0.6, 0.15, 0.15)]
            }
            // Measured on POV-Ray 3.7 (its manual names other colours).
            PatternKind::Square => &[
                Colour::rgb(1.0, 0.0, 0.0),
                Colour::rgb(0.0, 1.0, 0.0),
                Colour::rgb(0.0, 0.0, 1.0),
                Colour::rgb(1.0, 1.0, 0.0),
            ],
            PatternKind::Triangular => &[
                Colour::rgb(1.0, 0.0, 0.0),
                Colour::rgb(0.0, 1.0, 0.0),
                Colour::rgb(0.0, 0.0, 1.0),
                Colour::rgb(1.0, 1.0, 0.0),
                Colour::rgb(0.0, 1.0, 1.0),
                Colour::rgb(1.0, 0.0, 1.0),
            ],
            _ => &[Colour::rgb(0.0, 0.0, 1.0), Colour::rgb(0.0, 1.0, 0.0)],
        };
        while list.len() < defaults.len() {
            list.push(solid(defaults[list.len()]));
        }
    }

    /// Reads a pattern modifier `kw` (already taken); `false` when `kw` is not one.
    pub(crate) fn pattern_modifier(
        &mut self,
        kw: &'static str,
        c: &mut Cursor,
        spec: &mut PatternSpec,
    ) -> R<bool> {
        let m = &mut spec.mods;
        match kw {
            "turbulence" => {
                let (v, s) = c.value("the turbulence amount")?;
                m.turbulence = self.to_vec3(&v, s)?;
            }
            "octaves" => {
                let n = self.take_float(c, "the number of octaves")?;
                spec.mods.octaves = n.clamp(1.0, 10.0) as u32;
            }
            "omega" => spec.mods.omega = self.take_float(c, "omega")?,
            "agate_turb" => spec.mods.agate_turb = self.take_float(c, "agate_turb")?,
            "lambda" => spec.mods.lambda = self.take_float(c, "lambda")?,
            "frequency" => spec.mods.frequency = self.take_float(c, "the frequency")?,
            "phase" => spec.mods.phase = self.take_float(c, "the phase")?,
            "ramp_wave" => spec.wave = Some(Wave::Ramp),
            "triangle_wave" => spec.wave = Some(Wave::Triangle),
            "sine_wave" => spec.wave = Some(Wave::Sine),
            "scallop_wave" => spec.wave = Some(Wave::Scallop),
            "cubic_wave" => spec.wave = Some(Wave::Cubic),
            "poly_wave" => {
                let e = self.take_optional_float(c, 1.0)?;
                spec.wave = Some(Wave::Poly(e));
            }
            "form" | "metric" | "solid" | "offset" => {
                let Some(PatternKind::Crackle {
                    form,
                    metric,
                    solid,
                    offset,
                }) = &mut spec.kind
                else {
                    let span = c.last;
                    // Its value is taken too, so it is not reported again.
                    if kw != "solid" {
                        c.value("a value")?;
                    }
                    return Err(Diagnostic::error(
                        codes::UNKNOWN_PARAMETER,
                        span,
                        format!("`{kw}` applies to the `crackle` pattern only"),
                    )
                    .with_help("write `crackle` before it")
                    .into());
                };
                match kw {
                    "solid" => *solid = true,
                    "form" => *form = self.take_vec3(c, "the form <F1, F2, F3>")?,
                    "metric" => {
                        let (v, s) = c.value("the metric exponent")?;
                        let m = self.to_float(&v, s)?;
                        if m <= 0.0 {
                            return Err(Diagnostic::error(
                                codes::OUT_OF_RANGE,
                                s,
                                format!("`metric` must be positive, found {m}"),
                            )
                            .with_help("2 is the usual distance, 1 the Manhattan distance")
                            .into());
                        }
                        *metric = m;
                    }
                    _ => *offset = self.take_float(c, "the offset")?,
                }
            }
            "control0" | "control1" | "exponent" | "exterior" | "interior" | "noise_generator" => {
                self.shape_modifier(kw, c, spec)?
            }
            "brick_size" | "mortar" => {
                let (v, s) = c.value(&format!("a value after `{kw}`"))?;
                match &mut spec.kind {
                    Some(PatternKind::Brick { size, mortar }) => {
                        if kw == "mortar" {
                            *mortar = self.to_float(&v, s)?;
                        } else {
                            *size = self.to_vec3(&v, s)?;
                        }
                    }
                    _ => {
                        return Err(Diagnostic::error(
                            codes::UNKNOWN_PARAMETER,
                            s,
                            format!("`{kw}` applies to the `brick` pattern only"),
                        )
                        .with_help("write `brick` before it")
                        .into())
                    }
                }
            }
            _ => return Ok(false),
        }
        Ok(true)
    }

    /// `color_map { [v COLOUR] … }` (also `[v1, v2 COLOUR1 COLOUR2]`, and a
    /// declared map as the first item).
    pub(crate) fn colour_map(&mut self, c: &mut Cursor) -> R<Vec<(f64, Colour)>> {
        let mut entries: Vec<(f64, Colour)> = Vec::new();
        if let Some(Tok::Val(Value::ColourMap(_), _)) = c.peek() {
            if let Some(Tok::Val(Value::ColourMap(m), _)) = c.next() {
                entries = (*m).clone();
            }
        }
        while let Some(tok) = c.next() {
            match tok {
                Tok::Bracket(items, span) => {
                    let mut vals = Vec::new();
                    let mut cols = Vec::new();
                    for t in items {
                        match t {
                            Tok::Val(Value::Float(x), _) if cols.is_empty() => vals.push(x),
                            Tok::Val(
                                v @ (Value::Colour(_) | Value::Vector(_) | Value::Float(_)),
                                s,
                            ) => cols.push(self.to_colour(&v, s)?),
                            Tok::Comma(_) => {}
                            Tok::Val(Value::Poison, _) => return Err(Fail::silent()),
                            other => {
                                return Err(Diagnostic::error(
                                    codes::UNEXPECTED_ITEM,
                                    other.span(),
                                    format!(
                                        "{} does not belong in a colour map entry",
                                        other.describe()
                                    ),
                                )
                                .with_help(
                                    "write entries as `[VALUE COLOUR]`, e.g. `[0.5 rgb <1, 0, 0>]`",
                                )
                                .into())
                            }
                        }
                    }
                    if vals.is_empty() || cols.is_empty() || vals.len() != cols.len() {
                        return Err(Diagnostic::error(
                            codes::MISSING_VALUE,
                            span,
                            "a colour map entry needs a value and a colour",
                        )
                        .with_help("write entries as `[VALUE COLOUR]`, e.g. `[0.5 rgb <1, 0, 0>]`")
                        .into());
                    }
                    entries.extend(vals.into_iter().zip(cols));
                }
                Tok::Comma(_) => {}
                other => return Err(self.unexpected(c, &other, &["[VALUE COLOUR]"])),
            }
        }
        if entries.len() > 256 {
            return Err(Diagnostic::error(
                codes::OUT_OF_RANGE,
                c.span,
                "a colour map holds at most 256 entries",
            )
            .into());
        }
        entries.sort_by(|a, b| a.0.total_cmp(&b.0));
        Ok(entries)
    }
}

/// Splits a map entry `[V ITEM]` into its value and the tokens of its item (a comma
/// after the value is dropped). As `average` maps allow, the value may be left
/// out: it is then 1. An empty entry gives 1 and no tokens, for the caller to
/// report with the map's own words.
pub(crate) fn map_entry_value(items: Vec<Tok>) -> R<(f64, Vec<Tok>)> {
    let mut it = items.into_iter().peekable();
    let v = match it.peek() {
        Some(Tok::Val(Value::Float(x), _)) => {
            let x = *x;
            it.next();
            x
        }
        Some(Tok::Val(Value::Poison, _)) => return Err(Fail::silent()),
        _ => 1.0,
    };
    if matches!(it.peek(), Some(Tok::Comma(_))) {
        it.next();
    }
    Ok((v, it.collect()))
}

impl Evaluator<'_> {
    /// `pigment_map { [v PIGMENT] … }`.
    pub(crate) fn pigment_map(&mut self, c: &mut Cursor) -> R<Vec<(f64, Pigment)>> {
        let mut entries: Vec<(f64, Pigment)> = Vec::new();
        if let Some(Tok::Val(Value::PigmentMap(_), _)) = c.peek() {
            if let Some(Tok::Val(Value::PigmentMap(m), _)) = c.next() {
                entries = (*m).clone();
            }
        }
        while let Some(tok) = c.next() {
            match tok {
                Tok::Bracket(items, span) => {
                    // `[V pigment { … }]`, `[V NAME]`, `[V COLOUR]` or, as POV-Ray
                    // also allows, `[V PIGMENT-BODY]` (`[0.5 checker rgb 1, rgb 0]`).
                    let (v, rest) = map_entry_value(items)?;
                    let pig = match rest.as_slice() {
                        [Tok::Block(_, Value::Pigment(p), _)] => (**p).clone(),
                        [] => {
                            return Err(Diagnostic::error(
                                codes::MISSING_VALUE,
                                span,
                                "a pigment map entry needs a value and a pigment",
                            )
                            .with_help("write entries as `[VALUE pigment { … }]`")
                            .into())
                        }
                        _ => {
                            let mut inner = Cursor::new(rest, "pigment_map", span);
                            self.pigment(&mut inner)?
                        }
                    };
                    entries.push((v, pig));
                }
                Tok::Comma(_) => {}
                other => return Err(self.unexpected(c, &other, &["[VALUE pigment { … }]"])),
            }
        }
        entries.sort_by(|a, b| a.0.total_cmp(&b.0));
        Ok(entries)
    }
}

impl Evaluator<'_> {
    /// `df3 "FILE" [interpolate N]` after `density_file`.
    fn density_file(&mut self, c: &mut Cursor) -> R<PatternKind> {
        match c.next() {
            Some(Tok::Kw("df3", _)) => {}
            Some(Tok::Kw(kw, span)) => {
                return Err(Diagnostic::error(
                    codes::UNSUPPORTED,
                    span,
                    format!("`density_file` reads the df3 format only, found `{kw}`"),
                )
                .with_help("convert the data to DF3: density_file df3 \"name.df3\"")
                .into())
            }
            Some(other) => return Err(self.unexpected(c, &other, &["df3"])),
            None => {
                return Err(Diagnostic::error(
                    codes::MISSING_VALUE,
                    c.span,
                    "`density_file` needs its format and file: `density_file df3 \"name.df3\"`",
                )
                .into())
            }
        }
        let (v, span) = c.value("the DF3 file's name, a string")?;
        let Value::Str(name) = v else {
            return Err(Diagnostic::error(
                codes::TYPE_MISMATCH,
                span,
                format!("the DF3 file's name must be a string, found {}", v.kind()),
            )
            .with_help("write the name in quotes: density_file df3 \"name.df3\"")
            .into());
        };
        let mut interpolate = 0;
        if let Some(Tok::Kw("interpolate", _)) = c.peek() {
            c.next();
            let (v, s) = c.value("the interpolation: 0 none, 1 trilinear, 2 tricubic")?;
            let n = self.to_float(&v, s)?;
            if ![0.0, 1.0, 2.0].contains(&n) {
                return Err(Diagnostic::error(
                    codes::OUT_OF_RANGE,
                    s,
                    format!("a density file's interpolate is 0, 1 or 2, found {n}"),
                )
                .with_help("0: nearest voxel, 1: trilinear, 2: tricubic")
                .into());
            }
            interpolate = n as u8;
        }
        let path = self.data_file(&name, span, "density file")?;
        let bytes = crate::files::read_regular(&path, u64::MAX).map_err(|e| {
            Fail::from(Diagnostic::error(
                codes::FILE_IO,
                span,
                format!("cannot read density file `{name}`: {e}"),
            ))
        })?;
        let grid = crate::scene::DensityGrid::parse(&bytes, interpolate).map_err(|e| {
            Fail::from(
                Diagnostic::error(
                    codes::FILE_IO,
                    span,
                    format!("`{name}` is not a DF3 file: {e}"),
                )
                .with_help(
                    "DF3: three big-endian 16-bit sizes, then 1, 2 or 4 bytes per voxel, x fastest",
                ),
            )
        })?;
        Ok(PatternKind::DensityFile(Arc::new(grid)))
    }
}
