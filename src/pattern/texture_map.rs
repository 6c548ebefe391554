//! Patterned textures: which of its textures a pattern chooses at a point
//! (`texture { checker texture { A } texture { B } }`, `texture { gradient y
//! texture_map { … } }`).

use super::patterns;
use crate::scene::{PatternKind, PatternedTexture, Texture, TextureEntries};
use glam::DVec3;
use std::sync::Arc;

/// What a patterned texture shows at a point.
#[derive(Clone, Copy, Debug)]
pub enum Choice<'a> {
    /// One texture.
    One(&'a Texture),
    /// Texture `a` weighted `1 - t` and texture `b` weighted `t`: POV-Ray shades
    /// both and averages the two colours.
    Blend(&'a Texture, &'a Texture, f64),
    /// `average`: every entry, weighed by its value (the weights need not sum
    /// to 1); POV-Ray shades each and averages the colours.
    Average(&'a [(f64, Arc<Texture>)]),
}

/// Which entries of a map value `v` falls between, as POV-Ray 3.7 looks it up in
/// entries kept in the order written: `(i, j, t)` blends entry `i` weighted `1 - t`
/// with entry `j` weighted `t`. At or past the last entry's value, the last entry;
/// else at or before the first's, the first; else the first entry `j` whose value
/// is above `v` and the one before it. For increasing values this is the usual
/// clamped linear lookup; for values that go down it matches what POV-Ray shows
/// (measured with colour, pigment and texture maps of two and three entries
/// out of order).
pub fn map_lookup<T>(entries: &[(f64, T)], v: f64) -> (usize, usize, f64) {
    let n = entries.len();
    if n <= 1 {
        return (0, 0, 0.0);
    }
    if v >= entries[n - 1].0 {
        return (n - 1, n - 1, 0.0);
    }
    if v <= entries[0].0 {
        return (0, 0, 0.0);
    }
    for j in 1..n {
        if v < entries[j].0 {
            let (v0, v1) = (entries[j - 1].0, entries[j].0);
            // v0 ≤ v < v1: the entries before j were all at or below v.
            let t = if v1 > v0 { (v - v0) / (v1 - v0) } else { 0.0 };
            return (j - 1, j, t.clamp(0.0, 1.0));
        }
    }
    (n - 1, n - 1, 0.0)
}

/// What patterned texture `pt` shows at point `p` of the texture's space (before
/// the pattern's own transform).
pub fn choose(pt: &PatternedTexture, p: DVec3) -> Choice<'_> {
    let q = match &pt.transform {
        Some(t) => t.inverse.transform_point3(p),
        None => p,
    };
    match &pt.entries {
        TextureEntries::List(list) => {
            let i = patterns::list_index(&pt.kind, patterns::warp(q, &pt.mods));
            Choice::One(&list[i.min(list.len() - 1)])
        }
        TextureEntries::Map(entries) if pt.kind == PatternKind::Average => {
            Choice::Average(entries.as_slice())
        }
        TextureEntries::Map(entries) => {
            let v = patterns::value(&pt.kind, q, &pt.mods);
            match map_lookup(entries, v) {
                (i, j, t) if i == j || t <= 0.0 => Choice::One(&entries[i].1),
                (_, j, t) if t >= 1.0 => Choice::One(&entries[j].1),
                (i, j, t) => Choice::Blend(&entries[i].1, &entries[j].1, t),
            }
        }
    }
}

/// The plain (not patterned) texture `tex` shows at point `p` of its space,
/// choosing between blended textures with `u` in [0, 1): the second with
/// probability equal to its weight. `u` is rescaled at each choice, so nested
/// maps need no further random numbers.
pub fn plain_at(tex: &Texture, p: DVec3, u: f64) -> &Texture {
    let mut tex = tex;
    let mut u = u;
    while let Some(pt) = &tex.patterned {
        tex = match choose(pt, p) {
            Choice::One(t) => t,
            Choice::Blend(a, b, t) => {
                if u < t {
                    u /= t;
                    b
                } else {
                    u = (u - t) / (1.0 - t);
                    a
                }
            }
            Choice::Average(entries) => {
                let total: f64 = entries.iter().map(|(w, _)| w.max(0.0)).sum();
                let mut chosen = &entries[entries.len() - 1].1;
                if total > 0.0 {
                    let mut acc = 0.0;
                    for (w, t) in entries {
                        let share = w.max(0.0) / total;
                        if share > 0.0 && u < acc + share {
                            u = ((u - acc) / share).clamp(0.0, 1.0);
                            chosen = t;
                            break;
                        }
                        acc += share;
                    }
                }
                chosen
            }
        };
    }
    tex
}

/// Calls `f` with each plain texture `tex` shows at `p` and its weight (the
/// weights sum to `weight`).
pub fn for_each_plain(tex: &Texture, p: DVec3, weight: f64, f: &mut impl FnMut(&Texture, f64)) {
    match &tex.patterned {
        None => f(tex, weight),
        Some(pt) => match choose(pt, p) {
            Choice::One(t) => for_each_plain(t, p, weight, f),
            Choice::Blend(a, b, t) => {
                for_each_plain(a, p, weight * (1.0 - t), f);
                for_each_plain(b, p, weight * t, f);
            }
            Choice::Average(entries) => {
                let total: f64 = entries.iter().map(|(w, _)| *w).sum();
                if total != 0.0 {
                    for (w, t) in entries {
                        for_each_plain(t, p, weight * w / total, f);
                    }
                }
            }
        },
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn e(values: &[f64]) -> Vec<(f64, ())> {
        values.iter().map(|&v| (v, ())).collect()
    }

    #[test]
    fn increasing_maps_clamp_and_blend() {
        let m = e(&[0.2, 0.7]);
        assert_eq!(map_lookup(&m, 0.1), (0, 0, 0.0));
        assert_eq!(map_lookup(&m, 0.9), (1, 1, 0.0));
        let (i, j, t) = map_lookup(&m, 0.45);
        assert_eq!((i, j), (0, 1));
        assert!((t - 0.5).abs() < 1e-12);
        // A sharp step: the value itself takes the upper entry.
        let s = e(&[0.0, 0.5, 0.5, 1.0]);
        assert_eq!(map_lookup(&s, 0.5), (2, 3, 0.0));
        assert_eq!(map_lookup(&e(&[0.3]), 0.9), (0, 0, 0.0));
    }

    /// POV-Ray 3.7 on maps out of order (gradient x, values 0.156, 0.406, 0.656,
    /// 0.906): `[0.7 R] [0.2 B]` shows R, B, B, B; `[0.2 R] [0.7 B] [0.5 G]`
    /// shows R, a 59/41 blend of R and B, G, G.
    #[test]
    fn out_of_order_maps_follow_povray() {
        let two = e(&[0.7, 0.2]);
        let got: Vec<_> = [0.156, 0.406, 0.656, 0.906]
            .iter()
            .map(|&v| map_lookup(&two, v).0)
            .collect();
        assert_eq!(got, [0, 1, 1, 1]);
        let three = e(&[0.2, 0.7, 0.5]);
        assert_eq!(map_lookup(&three, 0.156).0, 0);
        let (i, j, t) = map_lookup(&three, 0.406);
        assert_eq!((i, j), (0, 1));
        assert!((t - 0.412).abs() < 1e-9);
        assert_eq!(map_lookup(&three, 0.656), (2, 2, 0.0));
        assert_eq!(map_lookup(&three, 0.906), (2, 2, 0.0));
    }
}
