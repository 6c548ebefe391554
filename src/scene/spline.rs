//! POV-Ray's `spline { [linear_spline | quadratic_spline | cubic_spline |
//! natural_spline] T, VALUE … }`, a first-class value called as `S(t)`.
//!
//! The meaning, checked against POV-Ray 3.7 with `#debug` (tests below hold its
//! numbers):
//! - points are sorted by `t`; a repeated `t` keeps the first point;
//! - floats become 2-vectors `<f, f>` and the result is a vector as long as the
//!   longest point (POV-Ray: `S(t)` of a float spline is a vector, read `S(t).x`);
//! - `linear_spline` (the default) joins the points with straight lines;
//! - `quadratic_spline`: between points `i` and `i+1` the parabola through points
//!   `i-1, i, i+1` (through `0, 1, 2` on the first piece);
//! - `cubic_spline`: runs from the second point to the next-to-last (the end points
//!   only shape it); a cubic Hermite piece whose slope at each point is the mean of
//!   the slopes of the two chords that meet there;
//! - `natural_spline`: the natural cubic spline through every point (no curvature at
//!   the ends);
//! - outside its range every spline holds its end value.

/// How a spline passes through its points.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SplineKind {
    /// `linear_spline`.
    Linear,
    /// `quadratic_spline`.
    Quadratic,
    /// `cubic_spline`.
    Cubic,
    /// `natural_spline`.
    Natural,
}

impl SplineKind {
    /// The kind named by a keyword.
    pub fn from_keyword(kw: &str) -> Option<SplineKind> {
        Some(match kw {
            "linear_spline" => SplineKind::Linear,
            "quadratic_spline" => SplineKind::Quadratic,
            "cubic_spline" => SplineKind::Cubic,
            "natural_spline" => SplineKind::Natural,
            _ => return None,
        })
    }
}

/// A POV-Ray spline: sorted points with values of up to five components.
#[derive(Clone, Debug, PartialEq)]
pub struct Spline {
    /// The interpolation.
    pub kind: SplineKind,
    /// `(t, value)` sorted by `t`, no `t` twice.
    pub points: Vec<(f64, [f64; 5])>,
    /// Components of the result (2 to 5).
    pub dim: u8,
    /// Second derivatives at the points (natural splines only).
    second: Vec<[f64; 5]>,
}

impl Spline {
    /// A spline through `points` (any order; for a repeated `t` the first is kept).
    pub fn new(kind: SplineKind, mut points: Vec<(f64, [f64; 5])>, dim: u8) -> Spline {
        points.sort_by(|a, b| a.0.total_cmp(&b.0));
        points.dedup_by(|later, first| later.0 == first.0);
        let second = if kind == SplineKind::Natural {
            natural_second_derivatives(&points)
        } else {
            Vec::new()
        };
        Spline {
            kind,
            points,
            dim,
            second,
        }
    }

    /// The value at `t` (all five components; those past `dim` are 0).
    pub fn eval(&self, t: f64) -> [f64; 5] {
        let p = &self.points;
        let n = p.len();
        if n == 0 {
            return [0.0; 5];
        }
        if n == 1 {
            return p[0].1;
        }
        let mut out = [0.0; 5];
        match self.kind {
            SplineKind::Cubic if n >= 4 => {
                let (lo, hi) = (p[1].0, p[n - 2].0);
                if t <= lo {
                    return p[1].1;
                }
                if t >= hi {
                    return p[n - 2].1;
                }
                let i = segment(p, t).clamp(1, n - 3);
                let (t0, t1) = (p[i].0, p[i + 1].0);
                let h = t1 - t0;
                let u = (t - t0) / h;
                for (k, o) in out.iter_mut().enumerate() {
                    let slope = |j: usize| {
                        let a = (p[j].1[k] - p[j - 1].1[k]) / (p[j].0 - p[j - 1].0);
                        let b = (p[j + 1].1[k] - p[j].1[k]) / (p[j + 1].0 - p[j].0);
                        0.5 * (a + b)
                    };
                    *o = hermite(p[i].1[k], p[i + 1].1[k], slope(i) * h, slope(i + 1) * h, u);
                }
                out
            }
            SplineKind::Cubic => {
                // Fewer than four points: POV-Ray holds the second point's value.
                p[1.min(n - 1)].1
            }
            _ if t <= p[0].0 => p[0].1,
            _ if t >= p[n - 1].0 => p[n - 1].1,
            SplineKind::Linear => {
                let i = segment(p, t);
                let u = (t - p[i].0) / (p[i + 1].0 - p[i].0);
                for (k, o) in out.iter_mut().enumerate() {
                    *o = p[i].1[k] + (p[i + 1].1[k] - p[i].1[k]) * u;
                }
                out
            }
            SplineKind::Quadratic => {
                let i = segment(p, t);
                if n == 2 {
                    let u = (t - p[0].0) / (p[1].0 - p[0].0);
                    for (k, o) in out.iter_mut().enumerate() {
                        *o = p[0].1[k] + (p[1].1[k] - p[0].1[k]) * u;
                    }
                    return out;
                }
                let a = i.saturating_sub(1).min(n - 3);
                let (ta, tb, tc) = (p[a].0, p[a + 1].0, p[a + 2].0);
                let la = (t - tb) * (t - tc) / ((ta - tb) * (ta - tc));
                let lb = (t - ta) * (t - tc) / ((tb - ta) * (tb - tc));
                let lc = (t - ta) * (t - tb) / ((tc - ta) * (tc - tb));
                for (k, o) in out.iter_mut().enumerate() {
                    *o = la * p[a].1[k] + lb * p[a + 1].1[k] + lc * p[a + 2].1[k];
                }
                out
            }
            SplineKind::Natural => {
                let i = segment(p, t);
                let (t0, t1) = (p[i].0, p[i + 1].0);
                let h = t1 - t0;
                let a = (t1 - t) / h;
                let b = (t - t0) / h;
                for (k, o) in out.iter_mut().enumerate() {
                    *o = a * p[i].1[k]
                        + b * p[i + 1].1[k]
                        + ((a * a * a - a) * self.second[i][k]
                            + (b * b * b - b) * self.second[i + 1][k])
                            * h
                            * h
                            / 6.0;
                }
                out
            }
        }
    }
}

/// Index `i` of the piece `[t_i, t_{i+1}]` holding `t` (points sorted, `t` inside).
fn segment(p: &[(f64, [f64; 5])], t: f64) -> usize {
    let i = p.partition_point(|q| q.0 <= t);
    i.saturating_sub(1).min(p.len() - 2)
}

/// Cubic Hermite on `u ∈ [0, 1]` with end values and end tangents (in `u` units).
pub fn hermite(p0: f64, p1: f64, m0: f64, m1: f64, u: f64) -> f64 {
    let u2 = u * u;
    let u3 = u2 * u;
    (2.0 * u3 - 3.0 * u2 + 1.0) * p0
        + (u3 - 2.0 * u2 + u) * m0
        + (-2.0 * u3 + 3.0 * u2) * p1
        + (u3 - u2) * m1
}

/// Second derivatives of the natural cubic spline through `p` (zero at the ends),
/// by the tridiagonal (Thomas) solve.
#[allow(clippy::needless_range_loop)] // one solve per component, over three arrays
pub fn natural_second_derivatives(p: &[(f64, [f64; 5])]) -> Vec<[f64; 5]> {
    let n = p.len();
    let mut m = vec![[0.0; 5]; n];
    if n < 3 {
        return m;
    }
    for k in 0..5 {
        let mut c = vec![0.0; n];
        let mut d = vec![0.0; n];
        for i in 1..n - 1 {
            let h0 = p[i].0 - p[i - 1].0;
            let h1 = p[i + 1].0 - p[i].0;
            let a = h0 / 6.0;
            let b = (h0 + h1) / 3.0;
            let cc = h1 / 6.0;
            let r = (p[i + 1].1[k] - p[i].1[k]) / h1 - (p[i].1[k] - p[i - 1].1[k]) / h0;
            let denom = b - a * c[i - 1];
            c[i] = cc / denom;
            d[i] = (r - a * d[i - 1]) / denom;
        }
        for i in (1..n - 1).rev() {
            m[i][k] = d[i] - c[i] * m[i + 1][k];
        }
    }
    m
}

#[cfg(test)]
mod tests {
    use super::*;

    fn float_spline(kind: SplineKind) -> Spline {
        let pts = [(0.0, 1.0), (1.0, 3.0), (3.0, 2.0), (4.0, 7.0), (6.0, 0.0)];
        Spline::new(
            kind,
            pts.iter()
                .map(|&(t, v)| (t, [v, v, 0.0, 0.0, 0.0]))
                .collect(),
            2,
        )
    }

    /// `(t, linear, quadratic, cubic, natural)` printed by POV-Ray 3.7 for the
    /// points 0,1 1,3 3,2 4,7 6,0.
    const POVRAY: &[[f64; 5]] = &[
        [-1.0, 1.0, 1.0, 3.0, 1.0],
        [0.25, 1.5, 1.65625, 3.0, 1.71484375],
        [0.5, 2.0, 2.208333333, 3.0, 2.34375],
        [1.25, 2.875, 3.239583333, 3.0390625, 2.888671875],
        [2.0, 2.5, 3.333333333, 2.125, 1.625],
        [2.5, 2.25, 2.875, 1.59375, 1.140625],
        [3.25, 3.25, 2.90625, 3.0625, 3.1484375],
        [3.75, 5.75, 5.40625, 6.21875, 5.9453125],
        [4.5, 5.25, 7.375, 7.0, 7.4375],
        [5.75, 0.875, 2.114583333, 7.0, 1.6953125],
        [7.0, 0.0, 0.0, 7.0, 0.0],
    ];

    #[test]
    fn matches_povray() {
        let kinds = [
            SplineKind::Linear,
            SplineKind::Quadratic,
            SplineKind::Cubic,
            SplineKind::Natural,
        ];
        for row in POVRAY {
            for (k, kind) in kinds.iter().enumerate() {
                let got = float_spline(*kind).eval(row[0])[0];
                assert!(
                    (got - row[k + 1]).abs() < 1e-8,
                    "{kind:?} at {}: {got} vs POV-Ray {}",
                    row[0],
                    row[k + 1]
                );
            }
        }
    }

    #[test]
    fn sorted_first_point_wins() {
        let s = Spline::new(
            SplineKind::Linear,
            vec![
                (0.0, [1.0; 5]),
                (1.0, [2.0; 5]),
                (1.0, [5.0; 5]),
                (2.0, [0.0; 5]),
            ],
            2,
        );
        // POV-Ray: 2, 1.5, 1.
        assert_eq!(s.eval(1.0)[0], 2.0);
        assert_eq!(s.eval(0.5)[0], 1.5);
        assert_eq!(s.eval(1.5)[0], 1.0);
    }

    #[test]
    fn vector_cubic_matches_povray() {
        let s = Spline::new(
            SplineKind::Cubic,
            vec![
                (0.0, [1.0, 2.0, 3.0, 0.0, 0.0]),
                (1.0, [3.0, 0.0, 1.0, 0.0, 0.0]),
                (3.0, [2.0, 2.0, 2.0, 0.0, 0.0]),
                (4.0, [7.0, 1.0, 0.0, 0.0, 0.0]),
                (6.0, [0.0; 5]),
            ],
            3,
        );
        let v = s.eval(2.5);
        for (got, want) in v.iter().zip([1.59375, 1.640625, 1.984375]) {
            assert!((got - want).abs() < 1e-9);
        }
    }
}
