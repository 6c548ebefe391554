use super::*;

fn pts(p: &[(f64, f64)]) -> Vec<DVec2> {
    p.iter().map(|&(x, y)| DVec2::new(x, y)).collect()
}

/// The radius POV-Ray 3.7's `trace()` finds from `<5, y, 0>` towards −x.
fn radius_at(l: &Lathe, y: f64) -> f64 {
    let ray = Ray::new(DVec3::new(5.0, y, 0.0), DVec3::NEG_X);
    5.0 - l.nearest(&ray, 0.0, f64::INFINITY).unwrap().0
}

/// A spline, its points and `(height, radius)` pairs POV-Ray's `trace()` found.
type Case<'a> = (Spline, &'a [DVec2], &'a [(f64, f64)]);

#[test]
fn every_spline_matches_povray_trace() {
    let p = pts(&[(0.0, -1.0), (1.0, 0.0), (2.0, 1.0), (1.0, 2.0), (0.0, 3.0)]);
    let cases: [Case; 4] = [
        (Spline::Linear, &p[1..4], &[(0.5, 1.5), (1.5, 1.5)]),
        (
            Spline::Quadratic,
            &p[..4],
            &[(0.25, 1.25), (1.25, 1.9375), (1.5, 1.75), (1.75, 1.4375)],
        ),
        (
            Spline::Cubic,
            &p,
            &[
                (0.25, 1.296875),
                (0.5, 1.625),
                (1.25, 1.890625),
                (1.75, 1.296875),
            ],
        ),
        (
            Spline::Bezier,
            &[],
            &[(0.25, 1.873013), (0.5, 2.251939), (1.0, 2.5)],
        ),
    ];
    let bez = pts(&[(1.0, 0.0), (3.0, 0.3), (3.0, 1.7), (1.0, 2.0)]);
    for (spline, p, expect) in cases {
        let p = if spline == Spline::Bezier {
            &bez[..]
        } else {
            p
        };
        let l = Lathe::new(&segments(spline, p));
        for &(y, r) in expect {
            let got = radius_at(&l, y);
            assert!((got - r).abs() < 1e-6, "{spline:?} at {y}: {got} vs {r}");
        }
    }
}

#[test]
fn inside_follows_povray() {
    // inside() values from POV-Ray 3.7 for an open and a closed outline.
    let open = Lathe::new(&segments(
        Spline::Linear,
        &pts(&[(1.0, 0.0), (2.0, 1.0), (2.0, 2.0)]),
    ));
    let closed = Lathe::new(&segments(
        Spline::Linear,
        &pts(&[(1.0, 0.0), (2.0, 1.0), (2.0, 2.0), (1.0, 0.0)]),
    ));
    for (l, p, want) in [
        (&open, (1.4, 0.5), true),
        (&open, (1.1, 0.5), true),
        (&open, (0.5, 0.5), false),
        (&open, (1.6, 0.5), false),
        (&open, (1.9, 1.5), true),
        (&open, (1.2, 1.5), true),
        (&open, (0.5, 1.5), false),
        (&open, (2.5, 1.5), false),
        (&closed, (1.4, 0.5), true),
        (&closed, (1.1, 0.5), false),
        (&closed, (1.9, 1.5), true),
        (&closed, (1.2, 1.5), false),
    ] {
        assert_eq!(l.inside(DVec3::new(0.0, p.1, p.0)), want, "{p:?}");
    }
}

#[test]
fn rays_of_every_slope_agree_with_inside() {
    let l = Lathe::new(&segments(
        Spline::Cubic,
        &pts(&[
            (0.0, -1.0),
            (0.5, 0.0),
            (1.5, 0.5),
            (0.7, 1.2),
            (1.0, 2.0),
            (0.0, 2.5),
            (0.0, 3.0),
        ]),
    ));
    for dy in [0.0, 1e-12, 1e-7, 1e-3, 0.3, 1.0, 5.0, -2.0] {
        let o = DVec3::new(-4.0, 0.9, 0.2);
        let ray = Ray::new(o, DVec3::new(1.0, dy, 0.03));
        let mut ts = Vec::new();
        l.hits(&ray, 0.0, f64::INFINITY, &mut |t, _| ts.push(t));
        ts.sort_by(f64::total_cmp);
        let mut inside = false;
        for w in ts.windows(2) {
            inside = !inside;
            let mid = ray.origin + ray.dir * (0.5 * (w[0] + w[1]));
            assert_eq!(l.inside(mid), inside, "dy {dy}: {ts:?}");
        }
        if dy.abs() < 1.0 {
            assert!(!ts.is_empty(), "dy {dy}");
        }
    }
}

#[test]
fn normals_point_out_of_the_solid() {
    let l = Lathe::new(&segments(
        Spline::Linear,
        &pts(&[(1.0, 0.0), (2.0, 1.0), (2.0, 2.0), (1.0, 0.0)]),
    ));
    let ray = Ray::new(DVec3::new(5.0, 1.5, 0.0), DVec3::NEG_X);
    let (t, sub) = l.nearest(&ray, 0.0, f64::INFINITY).unwrap();
    let n = l.normal(ray.origin + ray.dir * t, sub);
    assert!(n.x > 0.0 && n.y.abs() < 1e-9, "{n}");
    let b = l.bounds();
    assert!((b.max.x - 2.0).abs() < 1e-6 && (b.min.y).abs() < 1e-6 && (b.max.y - 2.0).abs() < 1e-6);
}

#[test]
fn the_smallest_radius_is_the_curves_not_the_points() {
    // POV-Ray 3.7's inside(): the parabola dips to x = 0.875 between points at x = 1,
    // and a point at 0.9 inside that dip is inside; control points do not count.
    let q = Lathe::new(&segments(
        Spline::Quadratic,
        &pts(&[(2.0, -1.0), (1.0, 0.0), (1.0, 1.0), (2.0, 2.0)]),
    ));
    assert!(q.inside(DVec3::new(0.9, 0.2, 0.0)));
    assert!(!q.inside(DVec3::new(0.95, 0.2, 0.0)));
    assert!(!q.inside(DVec3::new(0.88, 0.5, 0.0)));
    let q2 = Lathe::new(&segments(
        Spline::Quadratic,
        &pts(&[(0.5, -1.0), (1.0, 0.0), (1.5, 1.0), (1.5, 2.0)]),
    ));
    for r in [0.3, 0.5, 0.7, 0.9] {
        assert!(!q2.inside(DVec3::new(r, 0.3, 0.0)), "{r}");
    }
}
