//! Built-in constants and functions.

use super::value::{Value, Vector};
use super::{Evaluator, Fail, R};
use crate::diag::{codes, Diagnostic};
use crate::span::Span;
use crate::syntax::builtins::BUILTIN_NAMES;
use glam::DMat3;
use std::rc::Rc;

fn v3(x: f64, y: f64, z: f64) -> Value {
    Value::Vector(Vector::from_slice(&[x, y, z]))
}

impl Evaluator<'_> {
    /// The value of built-in constant `index`.
    pub(crate) fn builtin_constant(&self, index: usize) -> Value {
        let o = self.options;
        let name = BUILTIN_NAMES[index];
        if matches!(
            name,
            "clock"
                | "clock_delta"
                | "clock_on"
                | "frame_number"
                | "initial_frame"
                | "final_frame"
                | "initial_clock"
                | "final_clock"
        ) {
            // A per-frame value (see `reuse.rs`).
            self.moving();
        }
        Value::Float(match name {
            "pi" => std::f64::consts::PI,
            "tau" => std::f64::consts::TAU,
            "x" => return v3(1.0, 0.0, 0.0),
            "y" => return v3(0.0, 1.0, 0.0),
            "z" => return v3(0.0, 0.0, 1.0),
            "t" => return Value::Vector(Vector::from_slice(&[0.0, 0.0, 0.0, 1.0])),
            "u" => return Value::Vector(Vector::from_slice(&[1.0, 0.0])),
            "v" => return Value::Vector(Vector::from_slice(&[0.0, 1.0])),
            "true" | "on" | "yes" => 1.0,
            "false" | "off" | "no" => 0.0,
            "clock" => o.clock,
            "clock_delta" => o.clock_delta,
            "clock_on" => f64::from(u8::from(o.clock_on)),
            "frame_number" => o.frame_number,
            "initial_frame" => o.initial_frame,
            "final_frame" => o.final_frame,
            "initial_clock" => o.initial_clock,
            "final_clock" => o.final_clock,
            "image_width" => o.image_width,
            "image_height" => o.image_height,
            // `version`: the last `#version`, 3.7 when none was set.
            _ => self.language_version.unwrap_or(3.7),
        })
    }

    /// Calls built-in function `index` with evaluated arguments.
    pub(crate) fn call_builtin(
        &mut self,
        index: usize,
        call: Span,
        args: &[(Value, Span)],
    ) -> R<Value> {
        let name = BUILTIN_NAMES[index];
        let arity = |lo: usize, hi: usize| -> R<()> {
            if args.len() < lo || args.len() > hi {
                let want = if lo == hi {
                    format!("{lo}")
                } else if hi == usize::MAX {
                    format!("at least {lo}")
                } else {
                    format!("{lo} to {hi}")
                };
                return Err(Diagnostic::error(
                    codes::ARITY,
                    call,
                    format!(
                        "`{name}` takes {want} argument{}, found {}",
                        if want == "1" { "" } else { "s" },
                        args.len()
                    ),
                )
                .with_help(format!("call it as {}", signature(name)))
                .into());
            }
            Ok(())
        };
        let f = |i: usize| -> R<f64> { self.to_float(&args[i].0, args[i].1) };
        let domain = |i: usize, what: &str| -> Fail {
            Diagnostic::error(codes::DOMAIN_ERROR, args[i].1, format!("`{name}` {what}"))
                .with_label(format!("this is {}", describe(&args[i].0)))
                .into()
        };
        let float1 = |g: fn(f64) -> f64| -> R<Value> {
            arity(1, 1)?;
            Ok(Value::Float(g(f(0)?)))
        };
        match name {
            "abs" => {
                arity(1, 1)?;
                match &args[0].0 {
                    Value::Vector(v) => {
                        let mut r = *v;
                        r.c.iter_mut().for_each(|c| *c = c.abs());
                        Ok(Value::Vector(r))
                    }
                    _ => Ok(Value::Float(f(0)?.abs())),
                }
            }
            "acos" | "asin" => {
                arity(1, 1)?;
                let a = f(0)?;
                if !(-1.0..=1.0).contains(&a) {
                    return Err(domain(0, "needs a value from -1 to 1"));
                }
                Ok(Value::Float(if name == "acos" {
                    a.acos()
                } else {
                    a.asin()
                }))
            }
            "atan" => float1(f64::atan),
            "atan2" => {
                arity(2, 2)?;
                Ok(Value::Float(f(0)?.atan2(f(1)?)))
            }
            "ceil" => float1(f64::ceil),
            "cos" => float1(f64::cos),
            "cosh" => float1(f64::cosh),
            "sinh" => float1(f64::sinh),
            "tanh" => float1(f64::tanh),
            "asinh" => float1(f64::asinh),
            "acosh" => {
                arity(1, 1)?;
                let a = f(0)?;
                if a < 1.0 {
                    return Err(domain(0, "needs a value of at least 1"));
                }
                Ok(Value::Float(a.acosh()))
            }
            "atanh" => {
                arity(1, 1)?;
                let a = f(0)?;
                if a <= -1.0 || a >= 1.0 {
                    return Err(domain(0, "needs a value strictly between -1 and 1"));
                }
                Ok(Value::Float(a.atanh()))
            }
            "degrees" => float1(f64::to_degrees),
            "radians" => float1(f64::to_radians),
            "exp" => float1(f64::exp),
            "floor" => float1(f64::floor),
            "int" => float1(f64::trunc),
            "sin" => float1(f64::sin),
            "tan" => float1(f64::tan),
            "ln" | "log" => {
                arity(1, 1)?;
                let a = f(0)?;
                if a <= 0.0 {
                    return Err(domain(0, "is only defined for positive values"));
                }
                Ok(Value::Float(if name == "ln" { a.ln() } else { a.log10() }))
            }
            "sqrt" => {
                arity(1, 1)?;
                let a = f(0)?;
                if a < 0.0 {
                    return Err(domain(0, "of a negative number is not a real number"));
                }
                Ok(Value::Float(a.sqrt()))
            }
            "div" | "mod" => {
                arity(2, 2)?;
                let (a, b) = (f(0)?, f(1)?);
                if b == 0.0 {
                    return Err(Diagnostic::error(
                        codes::DIVISION_BY_ZERO,
                        args[1].1,
                        format!("`{name}` by zero"),
                    )
                    .with_label("this is 0")
                    .into());
                }
                Ok(Value::Float(if name == "div" {
                    (a / b).trunc()
                } else {
                    a % b
                }))
            }
            "pow" => {
                arity(2, 2)?;
                let (a, b) = (f(0)?, f(1)?);
                if a == 0.0 && b < 0.0 {
                    return Err(Diagnostic::error(
                        codes::DIVISION_BY_ZERO,
                        call,
                        "`pow(0, negative)` divides by zero",
                    )
                    .into());
                }
                if a < 0.0 && b.fract() != 0.0 {
                    return Err(domain(
                        0,
                        "of a negative number to a fractional power is not real",
                    ));
                }
                Ok(Value::Float(a.powf(b)))
            }
            "max" | "min" => {
                arity(1, usize::MAX)?;
                let mut acc = f(0)?;
                for i in 1..args.len() {
                    let b = f(i)?;
                    acc = if name == "max" {
                        acc.max(b)
                    } else {
                        acc.min(b)
                    };
                }
                Ok(Value::Float(acc))
            }
            "select" => {
                arity(3, 4)?;
                let s = f(0)?;
                let pick = if args.len() == 3 {
                    if s < 0.0 {
                        1
                    } else {
                        2
                    }
                } else if s < 0.0 {
                    1
                } else if s == 0.0 {
                    2
                } else {
                    3
                };
                Ok(args[pick].0.clone())
            }
            "vturbulence" => {
                arity(4, 4)?;
                let (lambda, omega, octaves) = (f(0)?, f(1)?, f(2)?);
                let p = self.to_vec3(&args[3].0, args[3].1)?;
                let octaves = octaves.clamp(1.0, 10.0) as u32;
                Ok(Value::Vector(Vector::v3(
                    crate::pattern::noise::turbulence_vec(p, octaves, omega, lambda),
                )))
            }
            "vlength" => {
                arity(1, 1)?;
                Ok(Value::Float(self.to_vec3(&args[0].0, args[0].1)?.length()))
            }
            "vnormalize" => {
                arity(1, 1)?;
                let a = self.to_vec3(&args[0].0, args[0].1)?;
                if a.length_squared() == 0.0 {
                    return Err(domain(0, "of a zero-length vector has no direction"));
                }
                Ok(Value::Vector(Vector::v3(a.normalize())))
            }
            "vdot" => {
                arity(2, 2)?;
                let a = self.to_vec3(&args[0].0, args[0].1)?;
                let b = self.to_vec3(&args[1].0, args[1].1)?;
                Ok(Value::Float(a.dot(b)))
            }
            "vcross" => {
                arity(2, 2)?;
                let a = self.to_vec3(&args[0].0, args[0].1)?;
                let b = self.to_vec3(&args[1].0, args[1].1)?;
                Ok(Value::Vector(Vector::v3(a.cross(b))))
            }
            "vrotate" => {
                arity(2, 2)?;
                let a = self.to_vec3(&args[0].0, args[0].1)?;
                let r = self.to_vec3(&args[1].0, args[1].1)?;
                let t = crate::scene::Transform::rotate(r);
                Ok(Value::Vector(Vector::v3(t.vector(a))))
            }
            "vaxis_rotate" => {
                arity(3, 3)?;
                let a = self.to_vec3(&args[0].0, args[0].1)?;
                let axis = self.to_vec3(&args[1].0, args[1].1)?;
                let deg = f(2)?;
                if axis.length_squared() == 0.0 {
                    return Err(domain(1, "needs a non-zero axis"));
                }
                let m = DMat3::from_axis_angle(axis.normalize(), deg.to_radians());
                Ok(Value::Vector(Vector::v3(m * a)))
            }
            "vtransform" | "vinv_transform" => {
                // POV-Ray's transforms.inc macros, built in: rts has no
                // functions for them to be written with.
                arity(2, 2)?;
                let p = self.to_vec3(&args[0].0, args[0].1)?;
                let Value::Transform(t) = &args[1].0 else {
                    return Err(self.mismatch("a transform", &args[1].0, args[1].1));
                };
                let m = if name == "vtransform" {
                    t.matrix
                } else {
                    t.inverse
                };
                Ok(Value::Vector(Vector::v3(m.transform_point3(p))))
            }
            "min_extent" | "max_extent" => {
                arity(1, 1)?;
                let Value::Object(o) = &args[0].0 else {
                    return Err(self.mismatch("an object", &args[0].0, args[0].1));
                };
                let (min, max) = self.object_extent(&o.clone());
                Ok(Value::Vector(Vector::v3(if name == "min_extent" {
                    min
                } else {
                    max
                })))
            }
            "inside" => {
                arity(2, 2)?;
                let Value::Object(o) = &args[0].0 else {
                    return Err(self.mismatch("an object", &args[0].0, args[0].1));
                };
                let p = self.to_vec3(&args[1].0, args[1].1)?;
                Ok(Value::Float(f64::from(u8::from(
                    self.object_inside(&o.clone(), p),
                ))))
            }
            "seed" => {
                arity(1, 1)?;
                let s = f(0)?;
                let state = splitmix(s.to_bits() ^ 0x9E37_79B9_7F4A_7C15);
                self.rand_streams.push(state);
                Ok(Value::Float((self.rand_streams.len() - 1) as f64))
            }
            "rand" => {
                arity(1, 1)?;
                let id = f(0)?;
                let slot = usize::try_from(id as i64)
                    .ok()
                    .filter(|i| *i < self.rand_streams.len() && id.fract() == 0.0);
                let Some(i) = slot else {
                    return Err(Diagnostic::error(
                        codes::TYPE_MISMATCH,
                        args[0].1,
                        "`rand` needs a stream made by `seed`",
                    )
                    .with_help("write `#declare S = seed(42);` and then `rand(S)`")
                    .into());
                };
                self.rand_streams[i] = splitmix(self.rand_streams[i]);
                Ok(Value::Float(
                    (self.rand_streams[i] >> 11) as f64 / (1u64 << 53) as f64,
                ))
            }
            "str" => {
                arity(3, 3)?;
                let (v, l, p) = (f(0)?, f(1)?, f(2)?);
                Ok(Value::Str(Rc::from(format_str(v, l, p))))
            }
            "vstr" => {
                arity(5, 5)?;
                let n = f(0)?.clamp(2.0, 5.0) as usize;
                let comps: Vec<f64> = match &args[1].0 {
                    Value::Vector(v) => v.as_slice().to_vec(),
                    Value::Float(x) => vec![*x; 5],
                    Value::Colour(c) => super::value::colour_to_array(c).to_vec(),
                    other => return Err(self.mismatch("a vector", other, args[1].1)),
                };
                let sep = self.to_str(&args[2].0, args[2].1)?;
                let (l, p) = (f(3)?, f(4)?);
                let parts: Vec<String> =
                    comps.iter().take(n).map(|c| format_str(*c, l, p)).collect();
                Ok(Value::Str(Rc::from(parts.join(&sep))))
            }
            "concat" => {
                arity(1, usize::MAX)?;
                let len = args
                    .iter()
                    .map(|(v, _)| match v {
                        Value::Str(s) => s.len(),
                        _ => 0,
                    })
                    .sum();
                self.check_string_length(len, call)?;
                let mut s = String::with_capacity(len);
                for (v, sp) in args {
                    s.push_str(&self.to_str(v, *sp)?);
                }
                Ok(Value::Str(Rc::from(s)))
            }
            "strcmp" => {
                arity(2, 2)?;
                let a = self.to_str(&args[0].0, args[0].1)?;
                let b = self.to_str(&args[1].0, args[1].1)?;
                Ok(Value::Float(strcmp(a.as_bytes(), b.as_bytes()) as f64))
            }
            "strlen" => {
                arity(1, 1)?;
                Ok(Value::Float(
                    self.to_str(&args[0].0, args[0].1)?.chars().count() as f64,
                ))
            }
            "strupr" | "strlwr" => {
                arity(1, 1)?;
                let s = self.to_str(&args[0].0, args[0].1)?;
                Ok(Value::Str(Rc::from(if name == "strupr" {
                    s.to_uppercase()
                } else {
                    s.to_lowercase()
                })))
            }
            "substr" => {
                arity(3, 3)?;
                let s = self.to_str(&args[0].0, args[0].1)?;
                let (p, l) = (f(1)?, f(2)?);
                let n = s.chars().count() as f64;
                if p < 1.0 || l < 0.0 || p + l - 1.0 > n {
                    return Err(Diagnostic::error(
                        codes::INDEX_OUT_OF_RANGE,
                        call,
                        format!("`substr` from {p} for {l} characters is outside a string of {n} characters"),
                    )
                    .with_help("positions start at 1; the start plus the length minus 1 must not pass the end")
                    .into());
                }
                Ok(Value::Str(Rc::from(
                    s.chars()
                        .skip(p as usize - 1)
                        .take(l as usize)
                        .collect::<String>(),
                )))
            }
            "chr" => {
                arity(1, 1)?;
                let c = f(0)?;
                match char::from_u32(c as u32).filter(|_| c >= 0.0 && c.fract() == 0.0) {
                    Some(ch) => Ok(Value::Str(Rc::from(ch.to_string()))),
                    None => Err(domain(0, "needs a Unicode code point")),
                }
            }
            "asc" => {
                arity(1, 1)?;
                let s = self.to_str(&args[0].0, args[0].1)?;
                Ok(Value::Float(
                    s.chars().next().map_or(0.0, |c| f64::from(u32::from(c))),
                ))
            }
            "val" => {
                arity(1, 1)?;
                let s = self.to_str(&args[0].0, args[0].1)?;
                let t = s.trim();
                let end = t
                    .char_indices()
                    .take_while(|(i, c)| {
                        c.is_ascii_digit()
                            || matches!(c, '.' | 'e' | 'E')
                            || (*i == 0 && matches!(c, '-' | '+'))
                    })
                    .count();
                Ok(Value::Float(t[..end].parse::<f64>().unwrap_or(0.0)))
            }
            "dimensions" => {
                arity(1, 1)?;
                match &args[0].0 {
                    Value::Array(a) => Ok(Value::Float(a.dims.len() as f64)),
                    other => Err(self.mismatch("an array", other, args[0].1)),
                }
            }
            "dimension_size" => {
                arity(2, 2)?;
                let d = f(1)?;
                match &args[0].0 {
                    Value::Array(a) => {
                        let i = d as usize;
                        if d < 1.0 || i > a.dims.len() {
                            return Err(Diagnostic::error(
                                codes::INDEX_OUT_OF_RANGE,
                                args[1].1,
                                format!("the array has {} dimension(s), not {d}", a.dims.len()),
                            )
                            .into());
                        }
                        Ok(Value::Float(a.dims[i - 1] as f64))
                    }
                    other => Err(self.mismatch("an array", other, args[0].1)),
                }
            }
            "bitwise_and" | "bitwise_or" | "bitwise_xor" => {
                arity(2, usize::MAX)?;
                let mut acc = f(0)? as i64;
                for i in 1..args.len() {
                    let b = f(i)? as i64;
                    acc = match name {
                        "bitwise_and" => acc & b,
                        "bitwise_or" => acc | b,
                        _ => acc ^ b,
                    };
                }
                Ok(Value::Float(acc as f64))
            }
            // `defined` is handled before arguments are evaluated.
            _ => Err(Diagnostic::error(
                codes::TYPE_MISMATCH,
                call,
                format!("`{name}` is not a function"),
            )
            .into()),
        }
    }
}

/// A short description of a value for labels: "-1", "a vector", …
pub(crate) fn describe(v: &Value) -> String {
    match v {
        Value::Float(f) => format!("{f}"),
        other => other.kind().to_string(),
    }
}

/// How to call a built-in, for arity help.
pub fn signature(name: &str) -> String {
    match name {
        "atan2" => "atan2(A, B)".into(),
        "div" | "mod" | "pow" => format!("{name}(A, B)"),
        "max" | "min" => format!("{name}(A, B, …)"),
        "select" => "select(S, NEG, POS) or select(S, NEG, ZERO, POS)".into(),
        "vdot" | "vcross" => format!("{name}(V1, V2)"),
        "vrotate" => "vrotate(V, <ROTX, ROTY, ROTZ>)".into(),
        "vaxis_rotate" => "vaxis_rotate(V, AXIS, DEGREES)".into(),
        "vtransform" | "vinv_transform" => format!("{name}(V, TRANSFORM)"),
        "str" => "str(VALUE, LENGTH, PRECISION)".into(),
        "vstr" => "vstr(N, V, SEPARATOR, LENGTH, PRECISION)".into(),
        "concat" => "concat(S1, S2, …)".into(),
        "substr" => "substr(S, START, LENGTH)".into(),
        "dimension_size" => "dimension_size(ARRAY, DIMENSION)".into(),
        "defined" => "defined(NAME)".into(),
        "trace" => "trace(OBJECT, START, DIRECTION [, NORMAL])".into(),
        "inside" => "inside(OBJECT, POINT)".into(),
        "strcmp" => "strcmp(S1, S2)".into(),
        "vturbulence" => "vturbulence(LAMBDA, OMEGA, OCTAVES, <P>)".into(),
        "bitwise_and" | "bitwise_or" | "bitwise_xor" => format!("{name}(A, B, …)"),
        _ => format!("{name}(A)"),
    }
}

/// C's `strcmp`, as POV-Ray returns it: the difference of the first bytes that
/// differ (a missing byte counts as 0), 0 for equal strings.
fn strcmp(a: &[u8], b: &[u8]) -> i32 {
    let n = a.len().max(b.len());
    (0..n)
        .map(|i| i32::from(*a.get(i).unwrap_or(&0)) - i32::from(*b.get(i).unwrap_or(&0)))
        .find(|d| *d != 0)
        .unwrap_or(0)
}

/// POV-Ray's `str(V, L, P)`: at least |L| characters (zero-padded when L < 0), P
/// decimals (P < 0: six, as POV-Ray 3.7 prints).
fn format_str(v: f64, l: f64, p: f64) -> String {
    let width = l.abs().min(64.0) as usize;
    // A negative precision means POV-Ray's default of six decimals.
    let decimals = if p < 0.0 { 6 } else { p.min(20.0) as usize };
    let body = format!("{v:.decimals$}");
    if l < 0.0 {
        let neg = body.starts_with('-');
        let digits = body.trim_start_matches('-');
        let pad = width.saturating_sub(body.len());
        format!(
            "{}{}{}",
            if neg { "-" } else { "" },
            "0".repeat(pad),
            digits
        )
    } else {
        format!("{body:>width$}")
    }
}

/// A well-mixed 64-bit step (SplitMix64).
fn splitmix(mut z: u64) -> u64 {
    z = z.wrapping_add(0x9E37_79B9_7F4A_7C15);
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}
