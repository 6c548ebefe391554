//! `keyframes { … }` (ours): a float, vector or colour keyed in time, standing for
//! its value at the current `clock` wherever a value may stand.
//!
//! ```text
//! keyframes {
//!   catmull_rom            // linear_spline (default) | catmull_rom | natural_spline
//!                          // | bezier_spline | step_spline
//!   seconds                // key times in seconds (or `frames`; default: clock units)
//!   ping_pong              // beyond the last key: hold (default) | loop | ping_pong
//!   key 0,   <0, 1, 0>  ease_in_out        // easing of the piece that starts here
//!   key 1.5, <2, 1, 0>  tangent <1, 0, 0>  // bezier_spline: the velocity at the key
//!   key 3,   <0, 1, 0>
//! }
//! ```

use crate::diag::{codes, Diagnostic};
use crate::eval::core::cursor::{Cursor, Tok};
use crate::eval::core::value::{colour_from_array, colour_to_array, Value, Vector};
use crate::eval::core::{Evaluator, R};
use crate::scene::spline::{hermite, Spline, SplineKind};
use crate::span::Span;

/// How time runs within one piece between two keys.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Easing {
    /// Uniformly: `e(u) = u`.
    Linear,
    /// `ease_in`: slow start, `e(u) = u³`.
    In,
    /// `ease_out`: slow end, `e(u) = 1 − (1 − u)³`.
    Out,
    /// `ease_in_out`: `4u³` below one half, `1 − (2 − 2u)³ / 2` above.
    InOut,
    /// `ease_bezier X1, Y1, X2, Y2`: CSS's `cubic-bezier()`, the curve from (0,0)
    /// to (1,1) with control points (X1,Y1) and (X2,Y2), read as `y` at `x = u`.
    Bezier(f64, f64, f64, f64),
}

/// The eased parameter `e(u)` for `u` in `[0, 1]`.
pub fn ease(e: Easing, u: f64) -> f64 {
    let u = u.clamp(0.0, 1.0);
    match e {
        Easing::Linear => u,
        Easing::In => u * u * u,
        Easing::Out => {
            let v = 1.0 - u;
            1.0 - v * v * v
        }
        Easing::InOut => {
            if u < 0.5 {
                4.0 * u * u * u
            } else {
                let v = 2.0 - 2.0 * u;
                1.0 - v * v * v / 2.0
            }
        }
        Easing::Bezier(x1, y1, x2, y2) => {
            let b = |s: f64, p1: f64, p2: f64| {
                let r = 1.0 - s;
                3.0 * r * r * s * p1 + 3.0 * r * s * s * p2 + s * s * s
            };
            // x(s) is monotonic for X1, X2 in [0, 1]: bisection, a fixed number of
            // steps so the result is the same everywhere.
            let (mut lo, mut hi) = (0.0f64, 1.0f64);
            for _ in 0..60 {
                let mid = 0.5 * (lo + hi);
                if b(mid, x1, x2) < u {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            b(0.5 * (lo + hi), y1, y2)
        }
    }
}

/// How the keys are joined.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Interp {
    /// `linear_spline`.
    Linear,
    /// `catmull_rom`: cubic through the keys, slopes from the neighbours.
    CatmullRom,
    /// `natural_spline`: the natural cubic spline through the keys.
    Natural,
    /// `bezier_spline`: cubic Bézier pieces whose handles are the keys'
    /// `tangent`s (Catmull-Rom's slopes where none is given).
    Bezier,
    /// `step_spline`: each key's value holds until the next key.
    Step,
}

/// What happens before the first and after the last key.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Extrapolate {
    /// `hold`: the end values stay.
    Hold,
    /// `loop`: the keys repeat.
    Loop,
    /// `ping_pong`: the keys play forward, then backward, and so on.
    PingPong,
}

/// One key: its time in clock units and its value.
#[derive(Clone, Debug)]
pub struct Key {
    /// Time, in clock units.
    pub t: f64,
    /// Value components.
    pub v: [f64; 5],
    /// Easing of the piece that starts at this key.
    pub ease: Easing,
    /// `tangent`: velocity (value per clock unit) for `bezier_spline`.
    pub tangent: Option<[f64; 5]>,
}

/// Keyed values, ready to be evaluated at any time.
#[derive(Clone, Debug)]
pub struct Keyframes {
    /// The keys, by increasing time.
    pub keys: Vec<Key>,
    /// How they are joined.
    pub interp: Interp,
    /// Beyond the ends.
    pub extrapolate: Extrapolate,
    /// `rotate`: the values are rotations (`rotate <x, y, z>` in degrees), joined
    /// along the shortest arc (quaternion slerp).
    pub rotation: bool,
    /// The keys' times are the clock negated: keys given in seconds or frames
    /// on a timeline whose clock runs backwards (`clock_range 5, 1`) come in
    /// decreasing clock order, so they are kept in time order on `-clock`.
    pub reversed: bool,
    natural: Option<Spline>,
}

impl Keyframes {
    /// Keyframes from keys sorted by strictly increasing time.
    pub fn new(keys: Vec<Key>, interp: Interp, extrapolate: Extrapolate) -> Keyframes {
        let natural = (interp == Interp::Natural).then(|| {
            Spline::new(
                SplineKind::Natural,
                keys.iter().map(|k| (k.t, k.v)).collect(),
                5,
            )
        });
        Keyframes {
            keys,
            interp,
            extrapolate,
            rotation: false,
            reversed: false,
            natural,
        }
    }

    /// Catmull-Rom velocity at key `j` (value per clock unit): the chord through
    /// the neighbours, one-sided at the ends.
    fn slope(&self, j: usize, k: usize) -> f64 {
        let ks = &self.keys;
        let (a, b) = (j.saturating_sub(1), (j + 1).min(ks.len() - 1));
        if a == b {
            return 0.0;
        }
        (ks[b].v[k] - ks[a].v[k]) / (ks[b].t - ks[a].t)
    }

    /// The value at clock time `t`.
    pub fn eval(&self, t: f64) -> [f64; 5] {
        let t = if self.reversed { -t } else { t };
        let ks = &self.keys;
        let n = ks.len();
        if n == 1 {
            return ks[0].v;
        }
        let (t0, tn) = (ks[0].t, ks[n - 1].t);
        let len = tn - t0;
        let t = match self.extrapolate {
            // Held; so are all keys at one clock (a timeline whose clock does
            // not move: no length to repeat). `max`/`min`, not `clamp`:
            // nothing here may panic.
            _ if self.extrapolate == Extrapolate::Hold || len.is_nan() || len <= 0.0 => {
                t.max(t0).min(tn)
            }
            Extrapolate::Loop if t < t0 || t > tn => t0 + (t - t0).rem_euclid(len),
            Extrapolate::PingPong if t < t0 || t > tn => {
                let x = (t - t0).rem_euclid(2.0 * len);
                t0 + if x > len { 2.0 * len - x } else { x }
            }
            _ => t,
        };
        if t >= tn {
            return ks[n - 1].v;
        }
        let i = ks
            .partition_point(|k| k.t <= t)
            .saturating_sub(1)
            .min(n - 2);
        let (a, b) = (&ks[i], &ks[i + 1]);
        let h = b.t - a.t;
        let u = ease(a.ease, (t - a.t) / h);
        let mut out = [0.0; 5];
        if self.rotation && self.interp != Interp::Step && u > 0.0 {
            let (q0, mut q1) = (pov_rotation(a.v), pov_rotation(b.v));
            if q0.dot(q1) < 0.0 {
                q1 = -q1;
            }
            let q = q0.slerp(q1, u);
            let (z, y, x) = q.to_euler(glam::EulerRot::ZYX);
            return [x.to_degrees(), y.to_degrees(), z.to_degrees(), 0.0, 0.0];
        }
        match self.interp {
            Interp::Step => return a.v,
            Interp::Linear => {
                for (k, o) in out.iter_mut().enumerate() {
                    *o = a.v[k] + (b.v[k] - a.v[k]) * u;
                }
            }
            Interp::CatmullRom => {
                for (k, o) in out.iter_mut().enumerate() {
                    let (m0, m1) = (self.slope(i, k) * h, self.slope(i + 1, k) * h);
                    *o = hermite(a.v[k], b.v[k], m0, m1, u);
                }
            }
            Interp::Bezier => {
                for (k, o) in out.iter_mut().enumerate() {
                    let v0 = a.tangent.map_or_else(|| self.slope(i, k), |tg| tg[k]);
                    let v1 = b.tangent.map_or_else(|| self.slope(i + 1, k), |tg| tg[k]);
                    let p1 = a.v[k] + v0 * h / 3.0;
                    let p2 = b.v[k] - v1 * h / 3.0;
                    let r = 1.0 - u;
                    *o = r * r * r * a.v[k]
                        + 3.0 * r * r * u * p1
                        + 3.0 * r * u * u * p2
                        + u * u * u * b.v[k];
                }
            }
            Interp::Natural => {
                if let Some(s) = &self.natural {
                    return s.eval(a.t + u * h);
                }
            }
        }
        out
    }
}

/// POV-Ray's `rotate <x, y, z>` (degrees; about x, then y, then z) as a quaternion.
fn pov_rotation(v: [f64; 5]) -> glam::DQuat {
    glam::DQuat::from_euler(
        glam::EulerRot::ZYX,
        v[2].to_radians(),
        v[1].to_radians(),
        v[0].to_radians(),
    )
}

/// The kind of value keyed: what every key must be.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum KeyKind {
    Float,
    Vector(u8),
    Colour,
}

impl KeyKind {
    fn name(self) -> String {
        match self {
            KeyKind::Float => "a float".into(),
            KeyKind::Vector(n) => format!("a {n}-vector"),
            KeyKind::Colour => "a colour".into(),
        }
    }
}

/// Keywords valid in `keyframes { }`.
pub(crate) const KEYFRAME_ITEMS: &[&str] = &[
    "key",
    "rotate",
    "linear_spline",
    "catmull_rom",
    "natural_spline",
    "bezier_spline",
    "step_spline",
    "seconds",
    "frames",
    "hold",
    "loop",
    "ping_pong",
];

/// Keywords valid after a key's value.
pub(crate) const KEY_ITEMS: &[&str] = &[
    "ease_in",
    "ease_out",
    "ease_in_out",
    "ease_bezier",
    "tangent",
];

impl Evaluator<'_> {
    /// `keyframes { … }`: the keyed value at the current clock.
    pub(crate) fn keyframes_block(&mut self, c: &mut Cursor) -> R<Value> {
        let (k, kind) = self.keyframes(c)?;
        self.moving();
        let v = k.eval(self.options.clock);
        Ok(match kind {
            KeyKind::Float => Value::Float(v[0]),
            KeyKind::Vector(n) => Value::Vector(Vector::from_slice(&v[..n as usize])),
            KeyKind::Colour => Value::Colour(colour_from_array(v)),
        })
    }

    pub(crate) fn keyframes(&mut self, c: &mut Cursor) -> R<(Keyframes, KeyKind)> {
        let mut interp = Interp::Linear;
        let mut rotation: Option<Span> = None;
        let mut extrapolate = Extrapolate::Hold;
        let mut units: Option<(&'static str, Span)> = None;
        // Keys as written: time (in the block's units), its span, value, kind.
        let mut raw: Vec<(f64, Span, Key, KeyKind, Span)> = Vec::new();
        while let Some(tok) = c.next() {
            let r: R<()> = match tok {
                Tok::Kw(kw, span)
                    if matches!(
                        kw,
                        "linear_spline"
                            | "catmull_rom"
                            | "natural_spline"
                            | "bezier_spline"
                            | "step_spline"
                    ) =>
                {
                    c.once("interpolation", span).map(|_| {
                        interp = match kw {
                            "catmull_rom" => Interp::CatmullRom,
                            "natural_spline" => Interp::Natural,
                            "bezier_spline" => Interp::Bezier,
                            "step_spline" => Interp::Step,
                            _ => Interp::Linear,
                        }
                    })
                }
                Tok::Kw(kw @ ("seconds" | "frames"), span) => {
                    if !raw.is_empty() {
                        Err(Diagnostic::error(
                            codes::UNEXPECTED_ITEM,
                            span,
                            format!("`{kw}` must come before the first key"),
                        )
                        .with_help("the unit applies to every key: move it to the start")
                        .into())
                    } else {
                        c.once("units", span).map(|_| units = Some((kw, span)))
                    }
                }
                Tok::Kw(kw @ ("hold" | "loop" | "ping_pong"), span) => {
                    c.once("extrapolation", span).map(|_| {
                        extrapolate = match kw {
                            "loop" => Extrapolate::Loop,
                            "ping_pong" => Extrapolate::PingPong,
                            _ => Extrapolate::Hold,
                        }
                    })
                }
                Tok::Kw("key", span) => self.key(c, span).map(|k| raw.push(k)),
                Tok::Kw("rotate", span) => c.once("rotate", span).map(|_| rotation = Some(span)),
                other => Err(self.unexpected(c, &other, KEYFRAME_ITEMS)),
            };
            if let Err(f) = r {
                self.report(f);
            }
        }
        if raw.is_empty() {
            return Err(Diagnostic::error(
                codes::MISSING_VALUE,
                c.span,
                "these keyframes have no keys",
            )
            .with_help("add keys: `keyframes { key 0, 1  key 1, 2 }`")
            .into());
        }
        let kind = raw[0].3;
        for (_, _, _, k, vs) in &raw[1..] {
            if *k != kind {
                return Err(Diagnostic::error(
                    codes::KEY_MIXED_TYPES,
                    *vs,
                    format!(
                        "this key is {}, but the first key is {}",
                        k.name(),
                        kind.name()
                    ),
                )
                .with_label(format!("{} here", k.name()))
                .with_secondary(raw[0].4, "first key's value")
                .with_help("every key of one `keyframes` must hold the same kind of value")
                .into());
            }
        }
        for w in raw.windows(2) {
            if w[1].0 <= w[0].0 {
                return Err(Diagnostic::error(
                    codes::KEYS_OUT_OF_ORDER,
                    w[1].1,
                    format!("key times must increase: {} comes after {}", w[1].0, w[0].0),
                )
                .with_label("this key's time")
                .with_secondary(w[0].1, "previous key")
                .with_help("list the keys in time order, each at a different time")
                .into());
            }
        }
        let tl = self.timeline();
        let (lo, hi) = (
            tl.initial_clock.min(tl.final_clock),
            tl.initial_clock.max(tl.final_clock),
        );
        let has_timeline = self.has_timeline();
        // Keys in seconds or frames on a clock that runs backwards land in
        // decreasing clock order: they are kept on the negated clock.
        let reversed = match units {
            Some(("seconds", _)) => tl.clock_of_seconds(1.0) < tl.clock_of_seconds(0.0),
            Some(("frames", _)) => tl.clock_delta() < 0.0,
            _ => false,
        };
        let mut keys = Vec::with_capacity(raw.len());
        for (t, ts, mut key, _, _) in raw {
            key.t = match units {
                Some(("seconds", _)) => tl.clock_of_seconds(t),
                Some(("frames", _)) => tl.clock_of_frame(t),
                _ => t,
            };
            if let Some(tg) = key.tangent.as_mut() {
                // A tangent per second or per frame becomes one per clock unit.
                let scale = match units {
                    Some(("seconds", _)) => tl.clock_of_seconds(1.0) - tl.clock_of_seconds(0.0),
                    Some(("frames", _)) => tl.clock_delta(),
                    _ => 1.0,
                };
                if scale != 0.0 {
                    tg.iter_mut().for_each(|x| *x /= scale);
                }
            }
            let eps = 1e-9 * (1.0 + hi.abs());
            if has_timeline && (key.t < lo - eps || key.t > hi + eps) {
                self.warn(
                    Diagnostic::warning(
                        codes::KEY_OUTSIDE_TIMELINE,
                        ts,
                        format!(
                            "this key (clock {}) is outside the timeline (clock {lo} to {hi})",
                            key.t
                        ),
                    )
                    .with_label("never reached by a frame")
                    .with_help(
                        "move the key inside the timeline, or widen `animation { clock_range … }`",
                    ),
                );
            }
            if reversed {
                key.t = -key.t;
                if let Some(tg) = key.tangent.as_mut() {
                    tg.iter_mut().for_each(|x| *x = -*x);
                }
            }
            keys.push(key);
        }
        let mut k = Keyframes::new(keys, interp, extrapolate);
        k.reversed = reversed;
        if let Some(rs) = rotation {
            if kind != KeyKind::Vector(3) {
                return Err(Diagnostic::error(
                    codes::KEY_MIXED_TYPES,
                    rs,
                    format!(
                        "rotation keys are 3-vectors of degrees, these keys are {}",
                        kind.name()
                    ),
                )
                .with_help("write keys like `key 0, <0, 90, 0>`")
                .into());
            }
            k.rotation = true;
        }
        Ok((k, kind))
    }

    /// `key T, VALUE [ease_…] [tangent V]`.
    fn key(&mut self, c: &mut Cursor, _span: Span) -> R<(f64, Span, Key, KeyKind, Span)> {
        let (tv, ts) = c.value("the key's time")?;
        let t = self.to_float(&tv, ts)?;
        c.comma();
        let (v, vs) = c.value("the key's value (a float, vector or colour)")?;
        let (vals, kind) = self.key_value(&v, vs)?;
        let mut key = Key {
            t,
            v: vals,
            ease: Easing::Linear,
            tangent: None,
        };
        let mut eased = false;
        loop {
            let (kw, span) = match c.peek() {
                Some(Tok::Kw(kw, span)) if KEY_ITEMS.contains(kw) => (*kw, *span),
                _ => break,
            };
            c.next();
            if kw == "tangent" {
                let (tv, tspan) = c.value("the tangent (the value's change per time unit)")?;
                let (tg, tk) = self.key_value(&tv, tspan)?;
                if tk != kind {
                    return Err(Diagnostic::error(
                        codes::KEY_MIXED_TYPES,
                        tspan,
                        format!(
                            "the tangent is {}, but the key's value is {}",
                            tk.name(),
                            kind.name()
                        ),
                    )
                    .into());
                }
                key.tangent = Some(tg);
                continue;
            }
            if eased {
                return Err(Diagnostic::error(
                    codes::DUPLICATE_PARAMETER,
                    span,
                    "this key already has an easing",
                )
                .with_help("give one of ease_in, ease_out, ease_in_out, ease_bezier per key")
                .into());
            }
            eased = true;
            key.ease = match kw {
                "ease_in" => Easing::In,
                "ease_out" => Easing::Out,
                "ease_in_out" => Easing::InOut,
                _ => {
                    let mut p = [0.0; 4];
                    for (i, x) in p.iter_mut().enumerate() {
                        if i > 0 {
                            c.comma();
                        }
                        let (v, s) = c.value("four numbers X1, Y1, X2, Y2")?;
                        *x = self.to_float(&v, s)?;
                        if (i == 0 || i == 2) && !(0.0..=1.0).contains(x) {
                            return Err(Diagnostic::error(
                                codes::OUT_OF_RANGE,
                                s,
                                format!("X1 and X2 of ease_bezier must be 0 to 1, found {x}"),
                            )
                            .with_help("as in CSS cubic-bezier(): ease_bezier 0.42, 0, 0.58, 1")
                            .into());
                        }
                    }
                    Easing::Bezier(p[0], p[1], p[2], p[3])
                }
            };
        }
        Ok((t, ts, key, kind, vs))
    }

    fn key_value(&mut self, v: &Value, span: Span) -> R<([f64; 5], KeyKind)> {
        Ok(match v {
            Value::Float(f) => ([*f, 0.0, 0.0, 0.0, 0.0], KeyKind::Float),
            Value::Vector(vec) => (vec.c, KeyKind::Vector(vec.len)),
            Value::Colour(col) => (colour_to_array(col), KeyKind::Colour),
            Value::Poison => return Err(crate::eval::core::Fail::silent()),
            other => return Err(self.mismatch("a float, a vector or a colour", other, span)),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn keys(interp: Interp, extrapolate: Extrapolate) -> Keyframes {
        let k = |t: f64, v: f64| Key {
            t,
            v: [v, 0.0, 0.0, 0.0, 0.0],
            ease: Easing::Linear,
            tangent: None,
        };
        Keyframes::new(
            vec![k(0.0, 1.0), k(0.5, 3.0), k(2.0, -1.0)],
            interp,
            extrapolate,
        )
    }

    #[test]
    fn easing_formulas() {
        for i in 0..=20 {
            let u = f64::from(i) / 20.0;
            assert_eq!(ease(Easing::Linear, u), u);
            assert!((ease(Easing::In, u) - u.powi(3)).abs() < 1e-15);
            assert!((ease(Easing::Out, u) - (1.0 - (1.0 - u).powi(3))).abs() < 1e-15);
            let io = if u < 0.5 {
                4.0 * u.powi(3)
            } else {
                1.0 - (-2.0 * u + 2.0).powi(3) / 2.0
            };
            assert!((ease(Easing::InOut, u) - io).abs() < 1e-15);
            // cubic-bezier(0,0,1,1) is the identity; (.42,0,.58,1) is symmetric.
            assert!((ease(Easing::Bezier(0.0, 0.0, 1.0, 1.0), u) - u).abs() < 1e-9);
            let s = ease(Easing::Bezier(0.42, 0.0, 0.58, 1.0), u);
            let s2 = ease(Easing::Bezier(0.42, 0.0, 0.58, 1.0), 1.0 - u);
            assert!((s + s2 - 1.0).abs() < 1e-9);
        }
        // cubic-bezier(.25,.1,.25,1) (CSS `ease`) at x = 0.5 is about 0.8024.
        assert!((ease(Easing::Bezier(0.25, 0.1, 0.25, 1.0), 0.5) - 0.8024).abs() < 1e-3);
        for e in [Easing::In, Easing::Out, Easing::InOut] {
            assert_eq!(ease(e, 0.0), 0.0);
            assert_eq!(ease(e, 1.0), 1.0);
        }
    }

    #[test]
    fn keys_are_hit_exactly() {
        for interp in [
            Interp::Linear,
            Interp::CatmullRom,
            Interp::Natural,
            Interp::Bezier,
            Interp::Step,
        ] {
            let k = keys(interp, Extrapolate::Hold);
            assert_eq!(k.eval(0.0)[0], 1.0, "{interp:?}");
            assert_eq!(k.eval(0.5)[0], 3.0, "{interp:?}");
            assert_eq!(k.eval(2.0)[0], -1.0, "{interp:?}");
        }
    }

    #[test]
    fn beyond_the_ends() {
        let h = keys(Interp::Linear, Extrapolate::Hold);
        assert_eq!(h.eval(-1.0)[0], 1.0);
        assert_eq!(h.eval(9.0)[0], -1.0);
        let l = keys(Interp::Linear, Extrapolate::Loop);
        assert!((l.eval(2.25)[0] - l.eval(0.25)[0]).abs() < 1e-12);
        let p = keys(Interp::Linear, Extrapolate::PingPong);
        assert!((p.eval(2.5)[0] - p.eval(1.5)[0]).abs() < 1e-12);
        assert!((p.eval(4.25)[0] - p.eval(0.25)[0]).abs() < 1e-12);
    }

    #[test]
    fn rotations_take_the_shortest_arc() {
        let k = |t: f64, y: f64| Key {
            t,
            v: [0.0, y, 0.0, 0.0, 0.0],
            ease: Easing::Linear,
            tangent: None,
        };
        let mut r = Keyframes::new(
            vec![k(0.0, 0.0), k(1.0, 270.0)],
            Interp::Linear,
            Extrapolate::Hold,
        );
        r.rotation = true;
        // 0 to 270 about y is 90 degrees the other way: halfway is -45.
        let mid = r.eval(0.5);
        assert!((mid[1] + 45.0).abs() < 1e-9, "{mid:?}");
        assert!(mid[0].abs() < 1e-9 && mid[2].abs() < 1e-9);
        let end = r.eval(1.0);
        assert!((end[1] - 270.0).abs() < 1e-9);
    }

    #[test]
    fn step_and_linear_between() {
        assert_eq!(keys(Interp::Step, Extrapolate::Hold).eval(0.49)[0], 1.0);
        assert_eq!(keys(Interp::Linear, Extrapolate::Hold).eval(0.25)[0], 2.0);
        // Bezier with no tangents is Catmull-Rom.
        let b = keys(Interp::Bezier, Extrapolate::Hold).eval(1.1)[0];
        let c = keys(Interp::CatmullRom, Extrapolate::Hold).eval(1.1)[0];
        assert!((b - c).abs() < 1e-12);
    }
}
