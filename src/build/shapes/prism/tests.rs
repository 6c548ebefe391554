//! Analytic checks of the prism: against a box, a cylinder, a pyramid; inside
//! tests; degenerate rays; bounds.

use super::*;
use rand_core::{RngCore, SeedableRng};

fn rng(seed: u64) -> impl FnMut() -> f64 {
    let mut r = rand_pcg::Pcg64Mcg::seed_from_u64(seed);
    move || (r.next_u64() >> 11) as f64 / (1u64 << 53) as f64
}

fn v(x: f64, z: f64) -> DVec2 {
    DVec2::new(x, z)
}

/// The square `[-1, 1]²` as POV-Ray's closed linear outline.
fn square(r: f64) -> Vec<DVec2> {
    vec![v(-r, -r), v(r, -r), v(r, r), v(-r, r), v(-r, -r)]
}

fn prism(spline: Spline, points: &[DVec2], h0: f64, h1: f64, conic: bool) -> Prism {
    let (curves, tail) = outline(spline, points);
    assert_eq!(tail, Tail::Closed, "{points:?}");
    Prism::new(&curves, h0, h1, conic, false)
}

/// A random ray from outside a 6-unit cube towards a point near the origin.
fn random_ray(u: &mut impl FnMut() -> f64) -> Ray {
    let dir = loop {
        let d = DVec3::new(u() - 0.5, u() - 0.5, u() - 0.5);
        if d.length_squared() > 1e-4 {
            break d.normalize();
        }
    };
    let target = DVec3::new(u() - 0.5, u() - 0.5, u() - 0.5) * 3.0;
    Ray::new(target - dir * 8.0, dir)
}

fn box_hits(min: DVec3, max: DVec3, ray: &Ray) -> Option<(f64, f64)> {
    let inv = ray.dir.recip();
    let t0 = (min - ray.origin) * inv;
    let t1 = (max - ray.origin) * inv;
    let near = t0.min(t1).max_element();
    let far = t0.max(t1).min_element();
    (near <= far).then_some((near, far))
}

#[test]
fn a_square_linear_prism_is_a_box() {
    let p = prism(Spline::Linear, &square(1.0), -0.5, 1.5, false);
    let (min, max) = (DVec3::new(-1.0, -0.5, -1.0), DVec3::new(1.0, 1.5, 1.0));
    let mut u = rng(1);
    let mut hit = 0;
    for _ in 0..5000 {
        let ray = random_ray(&mut u);
        let want = box_hits(min, max, &ray);
        let got = p.nearest(&ray, 0.0, f64::INFINITY);
        match (want, got) {
            (Some((near, _)), Some((t, sub))) => {
                hit += 1;
                assert!((t - near).abs() < 1e-9, "{ray:?}: {t} vs {near}");
                let pt = ray.at(t);
                let n = p.normal(pt, sub).normalize();
                // The box face the point is on.
                let d = [
                    (pt.x + 1.0).abs(),
                    (pt.x - 1.0).abs(),
                    (pt.y + 0.5).abs(),
                    (pt.y - 1.5).abs(),
                    (pt.z + 1.0).abs(),
                    (pt.z - 1.0).abs(),
                ];
                let face = (0..6).min_by(|&a, &b| d[a].total_cmp(&d[b])).unwrap();
                let want_n = [
                    DVec3::NEG_X,
                    DVec3::X,
                    DVec3::NEG_Y,
                    DVec3::Y,
                    DVec3::NEG_Z,
                    DVec3::Z,
                ][face];
                assert!((n - want_n).length() < 1e-9, "{pt}: {n} vs {want_n}");
                // Both crossings.
                let mut ts = Vec::new();
                p.hits(&ray, 0.0, f64::INFINITY, &mut |t, _| ts.push(t));
                ts.sort_by(f64::total_cmp);
                let far = want.unwrap().1;
                assert!((ts[ts.len() - 1] - far).abs() < 1e-9, "{ts:?} vs {far}");
            }
            (None, None) => {}
            // Rays grazing an edge may go either way.
            (w, g) => {
                let near = w.map_or_else(|| g.unwrap().0, |w| w.0);
                let pt = ray.at(near);
                let on_edge = [pt.x.abs() - 1.0, pt.z.abs() - 1.0]
                    .iter()
                    .filter(|e| e.abs() < 1e-6)
                    .count()
                    + usize::from((pt.y + 0.5).abs() < 1e-6 || (pt.y - 1.5).abs() < 1e-6);
                assert!(on_edge >= 2, "{ray:?}: box {w:?}, prism {g:?}");
            }
        }
        // Inside agrees with the box at random points.
        let q = DVec3::new(u() - 0.5, u() - 0.5, u() - 0.5) * 4.0;
        let inside_box = q.cmpgt(min).all() && q.cmplt(max).all();
        assert_eq!(p.inside(q), inside_box, "{q}");
    }
    assert!(hit > 1000, "{hit}");
}

/// The unit circle as four cubic Bézier arcs (error below 3e-4).
fn bezier_circle() -> Vec<DVec2> {
    let k = 0.552_284_749_831;
    let mut pts = Vec::new();
    for q in 0..4 {
        let rot = |x: f64, z: f64| {
            let a = q as f64 * std::f64::consts::FRAC_PI_2;
            v(x * a.cos() - z * a.sin(), x * a.sin() + z * a.cos())
        };
        pts.extend([rot(1.0, 0.0), rot(1.0, k), rot(k, 1.0), rot(0.0, 1.0)]);
    }
    pts
}

/// Points on the unit circle for POV-Ray's quadratic and cubic splines: one
/// leading control point, the closing repeat, and for cubic one trailing one.
fn spline_circle(n: usize, spline: Spline) -> Vec<DVec2> {
    let at = |i: isize| {
        let a = std::f64::consts::TAU * i as f64 / n as f64;
        v(a.cos(), a.sin())
    };
    let last = if spline == Spline::Cubic { n + 1 } else { n };
    (-1..=last as isize).map(at).collect()
}

/// Checks hits of horizontal and slanted rays against the unit cylinder
/// `x² + z² = 1`, `0 < y < 1`, within `tol`.
fn like_a_cylinder(p: &Prism, tol: f64, seed: u64) {
    let mut u = rng(seed);
    for _ in 0..2000 {
        let a = u() * std::f64::consts::TAU;
        let o = DVec3::new(3.0 * a.cos(), 0.2 + 0.6 * u(), 3.0 * a.sin());
        let target = DVec3::new(u() - 0.5, 0.5, u() - 0.5) * 1.2;
        let ray = Ray::new(o, (target - o).normalize());
        // |o₂ + t d₂|² = 1.
        let (o2, d2) = (DVec2::new(o.x, o.z), DVec2::new(ray.dir.x, ray.dir.z));
        let (a2, b2, c2) = (d2.dot(d2), o2.dot(d2), o2.dot(o2) - 1.0);
        let want = (-b2 - (b2 * b2 - a2 * c2).sqrt()) / a2;
        let (t, sub) = p.nearest(&ray, 0.0, f64::INFINITY).expect("hit");
        assert!((t - want).abs() < tol, "{t} vs {want}");
        let pt = ray.at(t);
        let n = p.normal(pt, sub).normalize();
        let radial = DVec3::new(pt.x, 0.0, pt.z).normalize();
        assert!((n - radial).length() < 20.0 * tol, "{n} vs {radial}");
        assert!(p.inside(DVec3::new(0.5 * pt.x, 0.5, 0.5 * pt.z)));
        assert!(!p.inside(DVec3::new(1.1 * pt.x, 0.5, 1.1 * pt.z)));
    }
}

#[test]
fn curved_prisms_are_cylinders() {
    like_a_cylinder(
        &prism(Spline::Bezier, &bezier_circle(), 0.0, 1.0, false),
        1e-3,
        2,
    );
    like_a_cylinder(
        &prism(
            Spline::Cubic,
            &spline_circle(64, Spline::Cubic),
            0.0,
            1.0,
            false,
        ),
        1e-3,
        3,
    );
    like_a_cylinder(
        &prism(
            Spline::Quadratic,
            &spline_circle(64, Spline::Quadratic),
            0.0,
            1.0,
            false,
        ),
        2e-3,
        4,
    );
}

#[test]
fn a_conic_sweep_of_a_square_is_a_pyramid() {
    // Apex at the origin, full size (±1) at y = 1: |x| < y, |z| < y.
    let p = prism(Spline::Linear, &square(1.0), 0.25, 1.0, true);
    let inside = |q: DVec3| q.y > 0.25 && q.y < 1.0 && q.x.abs() < q.y && q.z.abs() < q.y;
    let mut u = rng(5);
    let mut hits = 0;
    for _ in 0..4000 {
        let q = DVec3::new(u() - 0.5, u(), u() - 0.5) * DVec3::new(3.0, 1.4, 3.0);
        assert_eq!(p.inside(q), inside(q), "{q}");
        let ray = random_ray(&mut u);
        let Some((t, sub)) = p.nearest(&ray, 0.0, f64::INFINITY) else {
            continue;
        };
        hits += 1;
        let pt = ray.at(t);
        // On the surface: entering the solid there (the origin is outside).
        let e = 1e-6;
        assert!(!inside(ray.at(t - e)), "{pt}");
        let on = (pt.x.abs() - pt.y).abs() < 1e-9
            || (pt.z.abs() - pt.y).abs() < 1e-9
            || (pt.y - 1.0).abs() < 1e-9
            || (pt.y - 0.25).abs() < 1e-9;
        assert!(on, "{pt}");
        let n = p.normal(pt, sub).normalize();
        if sub >= FIRST_SIDE {
            // The face x = y (or −x = y, ±z = y): normal ∝ (±1, −1, 0) or (0, −1, ±1).
            let want = if (pt.x.abs() - pt.y).abs() < 1e-9 {
                DVec3::new(pt.x.signum(), -1.0, 0.0)
            } else {
                DVec3::new(0.0, -1.0, pt.z.signum())
            }
            .normalize();
            assert!((n - want).length() < 1e-9, "{pt}: {n} vs {want}");
        }
        assert!(n.dot(ray.dir) < 0.0, "entering: {pt} {n}");
    }
    assert!(hits > 200, "{hits}");
}

#[test]
fn holes_by_the_even_odd_rule() {
    let mut pts = square(2.0);
    pts.extend(square(1.0));
    let p = prism(Spline::Linear, &pts, 0.0, 1.0, false);
    assert!(p.inside(DVec3::new(1.5, 0.5, 0.0)));
    assert!(!p.inside(DVec3::new(0.0, 0.5, 0.0)));
    assert!(!p.inside(DVec3::new(3.0, 0.5, 0.0)));
    assert!(!p.inside(DVec3::new(1.5, 1.5, 0.0)));
    // Down the axis through the hole: nothing; through the ring: the top cap.
    assert!(p
        .nearest(&Ray::new(DVec3::new(0.0, 5.0, 0.0), DVec3::NEG_Y), 0.0, 1e9)
        .is_none());
    let (t, sub) = p
        .nearest(&Ray::new(DVec3::new(1.5, 5.0, 0.3), DVec3::NEG_Y), 0.0, 1e9)
        .expect("cap");
    assert_eq!((t, sub), (4.0, TOP));
    // Across: outer wall, hole wall, hole wall, outer wall; the hole's walls face
    // into the hole.
    let ray = Ray::new(DVec3::new(-5.0, 0.5, 0.1), DVec3::X);
    let mut h = Vec::new();
    p.hits(&ray, 0.0, 1e9, &mut |t, s| h.push((t, s)));
    h.sort_by(|a, b| a.0.total_cmp(&b.0));
    let ts: Vec<f64> = h.iter().map(|x| x.0).collect();
    assert_eq!(ts, vec![3.0, 4.0, 6.0, 7.0]);
    let nx: Vec<f64> = h
        .iter()
        .map(|&(t, s)| p.normal(ray.at(t), s).normalize().x)
        .collect();
    assert_eq!(nx, vec![-1.0, 1.0, -1.0, 1.0]);
    // `open`: no caps, the same walls, the same inside.
    let (curves, _) = outline(Spline::Linear, &pts);
    let open = Prism::new(&curves, 0.0, 1.0, false, true);
    assert!(open
        .nearest(&Ray::new(DVec3::new(1.5, 5.0, 0.3), DVec3::NEG_Y), 0.0, 1e9)
        .is_none());
    assert!(open.inside(DVec3::new(1.5, 0.5, 0.0)));
}

#[test]
fn vertical_and_grazing_rays_neither_panic_nor_give_nan() {
    let star: Vec<DVec2> = (0..=10)
        .map(|i| {
            let a = std::f64::consts::TAU * i as f64 / 10.0;
            let r = if i % 2 == 0 { 1.0 } else { 0.4 };
            v(r * a.cos(), r * a.sin())
        })
        .collect();
    let shapes = [
        prism(Spline::Linear, &star, 0.0, 1.0, false),
        prism(Spline::Linear, &star, 0.0, 1.0, true),
        prism(Spline::Bezier, &bezier_circle(), -1.0, 1.0, true),
        prism(
            Spline::Cubic,
            &spline_circle(8, Spline::Cubic),
            0.0,
            2.0,
            false,
        ),
    ];
    let mut u = rng(6);
    for p in &shapes {
        // Straight down at every vertex, and from far along each edge.
        for c in &p.curves {
            let a = at(c, 0.0);
            let b = at(c, 1.0);
            let down = Ray::new(DVec3::new(a.x, 5.0, a.y), DVec3::NEG_Y);
            let along = Ray::new(
                DVec3::new(a.x, 0.5, a.y) - DVec3::new(b.x - a.x, 0.0, b.y - a.y) * 3.0,
                DVec3::new(b.x - a.x, 0.0, b.y - a.y),
            );
            let through = Ray::new(
                DVec3::new(a.x, 0.5, a.y) + DVec3::new(0.3, 0.0, -4.0),
                DVec3::new(-0.3, 0.0, 4.0),
            );
            for ray in [down, along, through] {
                p.hits(&ray, 0.0, f64::INFINITY, &mut |t, sub| {
                    assert!(t.is_finite());
                    let n = p.normal(ray.at(t), sub);
                    assert!(n.is_finite() && n.length_squared() > 0.0, "{n}");
                });
            }
        }
        // Rays parallel to y see only caps, at the right distances.
        for _ in 0..200 {
            let (x, z) = (u() * 2.4 - 1.2, u() * 2.4 - 1.2);
            let ray = Ray::new(DVec3::new(x, 10.0, z), DVec3::NEG_Y);
            let mut subs = Vec::new();
            p.hits(&ray, 0.0, f64::INFINITY, &mut |t, sub| subs.push((t, sub)));
            for (t, sub) in subs {
                if p.conic {
                    continue;
                }
                assert!(sub == TOP || sub == BOTTOM, "{sub}");
                assert_eq!(t, 10.0 - p.h[sub as usize]);
            }
        }
        // From the apex of a conic sweep (the origin): no NaN.
        let ray = Ray::new(DVec3::ZERO, DVec3::new(0.1, 1.0, 0.2));
        p.hits(&ray, 0.0, f64::INFINITY, &mut |t, _| assert!(t.is_finite()));
    }
}

#[test]
fn no_hit_outside_the_bounds() {
    let mut pts = spline_circle(7, Spline::Cubic);
    for p in pts.iter_mut() {
        *p *= DVec2::new(2.0, 0.7);
    }
    let wobbly: Vec<DVec2> = vec![
        v(0.0, 0.0),
        v(3.0, -2.0),
        v(1.0, 4.0),
        v(1.0, 1.0),
        v(1.0, 1.0),
        v(-3.0, 2.0),
        v(-2.0, -5.0),
        v(0.0, 0.0),
    ];
    let shapes = [
        prism(Spline::Cubic, &pts, -1.0, 2.0, false),
        prism(Spline::Cubic, &pts, -0.5, 2.0, true),
        prism(Spline::Bezier, &wobbly, 0.3, 1.2, false),
        prism(Spline::Bezier, &wobbly, 0.3, 1.2, true),
        prism(
            Spline::Quadratic,
            &spline_circle(5, Spline::Quadratic),
            0.0,
            1.0,
            false,
        ),
    ];
    let mut u = rng(8);
    for p in &shapes {
        let b = p.bounds();
        let mut n = 0;
        for _ in 0..3000 {
            let ray = random_ray(&mut u);
            p.hits(&ray, 0.0, f64::INFINITY, &mut |t, _| {
                n += 1;
                let q = ray.at(t);
                assert!(
                    q.cmpge(b.min - 1e-9).all() && q.cmple(b.max + 1e-9).all(),
                    "{q} outside {b:?}"
                );
            });
        }
        assert!(n > 100, "{n}");
    }
}

#[test]
fn outlines_follow_povray_counting_rules() {
    // Linear: closes on the first point; an open last outline is closed.
    let (c, t) = outline(Spline::Linear, &square(1.0));
    assert_eq!((c.len(), t), (4, Tail::Closed));
    let (c, t) = outline(Spline::Linear, &square(1.0)[..4]);
    assert_eq!((c.len(), t), (4, Tail::ClosedForYou));
    // Quadratic: control, start … start again.
    let q = [
        v(0.0, -2.0),
        v(-2.0, -2.0),
        v(2.0, -2.0),
        v(0.0, 2.0),
        v(-2.0, -2.0),
    ];
    let (c, t) = outline(Spline::Quadratic, &q);
    assert_eq!((c.len(), t), (3, Tail::Closed));
    assert_eq!(at(&c[0], 0.0), q[1]);
    assert_eq!(at(&c[2], 1.0), q[1]);
    let mut more = q.to_vec();
    more.push(v(4.0, 4.0));
    assert_eq!(outline(Spline::Quadratic, &more).1, Tail::Ignored(5));
    more.extend([v(5.0, 4.0), v(5.0, 5.0)]);
    assert_eq!(outline(Spline::Quadratic, &more).1, Tail::Unclosed(5));
    // Cubic: control, start … start again, control.
    let cu = [
        v(3.0, -5.0),
        v(3.0, 5.0),
        v(-5.0, 0.0),
        v(3.0, -5.0),
        v(3.0, 5.0),
        v(-5.0, 0.0),
    ];
    let (c, t) = outline(Spline::Cubic, &cu);
    assert_eq!((c.len(), t), (3, Tail::Closed));
    assert_eq!(at(&c[0], 0.0), cu[1]);
    assert_eq!(at(&c[2], 1.0), cu[4]);
    assert_eq!(outline(Spline::Cubic, &cu[..5]).1, Tail::Unclosed(0));
    // Bézier: every 4 points; closes when a segment ends on the first point.
    let (c, t) = outline(Spline::Bezier, &bezier_circle());
    assert_eq!((c.len(), t), (4, Tail::Closed));
    assert!((at(&c[1], 0.5).length() - 1.0).abs() < 3e-4);
    let mut open = bezier_circle();
    open.truncate(12);
    let (c, t) = outline(Spline::Bezier, &open);
    assert_eq!((c.len(), t), (0, Tail::Ignored(0)));
}

#[test]
fn crossings_alternate_in_and_out() {
    // Along any ray, the solid is entered and left in turn: between two
    // consecutive crossings the inside test is constant and flips at each one.
    let heart = [
        v(0.0, -1.2),
        v(0.6, -0.6),
        v(1.3, -0.1),
        v(1.2, 0.5),
        v(1.2, 0.5),
        v(1.1, 1.1),
        v(0.3, 1.2),
        v(0.0, 0.6),
        v(0.0, 0.6),
        v(-0.3, 1.2),
        v(-1.1, 1.1),
        v(-1.2, 0.5),
        v(-1.2, 0.5),
        v(-1.3, -0.1),
        v(-0.6, -0.6),
        v(0.0, -1.2),
    ];
    let shapes = [
        prism(Spline::Bezier, &bezier_circle(), 0.3, 1.0, true),
        prism(Spline::Bezier, &heart, 0.3, 1.0, true),
        prism(Spline::Bezier, &heart, -0.5, 1.0, false),
        prism(
            Spline::Cubic,
            &spline_circle(5, Spline::Cubic),
            0.2,
            1.5,
            true,
        ),
        prism(
            Spline::Quadratic,
            &spline_circle(6, Spline::Quadratic),
            0.0,
            1.5,
            false,
        ),
    ];
    let mut u = rng(11);
    let mut bad = Vec::new();
    for (k, p) in shapes.iter().enumerate() {
        for _ in 0..20000 {
            let ray = random_ray(&mut u);
            let mut ts = Vec::new();
            p.hits(&ray, 0.0, f64::INFINITY, &mut |t, _| ts.push(t));
            ts.sort_by(f64::total_cmp);
            ts.dedup_by(|a, b| (*a - *b).abs() < 1e-9);
            let mut inside = p.inside(ray.origin);
            let mut prev = 0.0;
            for &t in ts.iter().chain(&[f64::INFINITY]) {
                let mid = if t.is_finite() {
                    0.5 * (prev + t)
                } else {
                    prev + 100.0
                };
                if (t - prev).abs() > 1e-6 && p.inside(ray.at(mid)) != inside {
                    bad.push((k, ray, ts.clone()));
                    break;
                }
                inside = !inside;
                prev = t;
            }
        }
    }
    assert!(
        bad.len() < 3,
        "{} rays: {:?}",
        bad.len(),
        &bad[..bad.len().min(3)]
    );
}

#[test]
fn rays_leaving_the_surface_do_not_hit_it_again_at_once() {
    let shapes = [
        prism(Spline::Bezier, &bezier_circle(), 0.3, 1.0, true),
        prism(Spline::Bezier, &bezier_circle(), 0.3, 1.0, false),
        prism(
            Spline::Cubic,
            &spline_circle(5, Spline::Cubic),
            0.2,
            1.5,
            true,
        ),
        prism(Spline::Linear, &square(1.0), 0.2, 1.5, true),
    ];
    let mut u = rng(12);
    for (k, p) in shapes.iter().enumerate() {
        let mut self_hits = 0;
        let mut n = 0;
        for _ in 0..20000 {
            let ray = random_ray(&mut u);
            let Some((t, sub)) = p.nearest(&ray, 0.0, f64::INFINITY) else {
                continue;
            };
            n += 1;
            let hit = ray.at(t);
            let normal = p.normal(hit, sub).normalize();
            // Straight on (into the solid), and back out.
            for dir in [ray.dir, -ray.dir] {
                let (r2, eps) = Ray::secondary(hit, normal, dir);
                if let Some((t2, _)) = p.nearest(&r2, eps, f64::INFINITY) {
                    if t2 < 1e-6 {
                        self_hits += 1;
                    }
                }
            }
        }
        assert!(self_hits == 0, "shape {k}: {self_hits} of {n}");
    }
}

#[test]
fn rays_from_the_surface_into_the_solid_find_the_way_out() {
    let shapes = [
        prism(Spline::Bezier, &bezier_circle(), 0.3, 1.0, true),
        prism(Spline::Bezier, &bezier_circle(), 0.3, 1.0, false),
        prism(
            Spline::Cubic,
            &spline_circle(5, Spline::Cubic),
            0.2,
            1.5,
            true,
        ),
        prism(Spline::Linear, &square(1.0), 0.2, 1.5, true),
    ];
    let mut u = rng(13);
    for (k, p) in shapes.iter().enumerate() {
        let (mut lost, mut n) = (0, 0);
        for _ in 0..20000 {
            let ray = random_ray(&mut u);
            let Some((t, sub)) = p.nearest(&ray, 0.0, f64::INFINITY) else {
                continue;
            };
            let hit = ray.at(t);
            let normal = p.normal(hit, sub).normalize();
            // A random direction into the solid.
            let d = loop {
                let d = DVec3::new(u() - 0.5, u() - 0.5, u() - 0.5).normalize();
                if d.dot(normal) < -0.05 {
                    break d;
                }
            };
            let (r2, eps) = Ray::secondary(hit, normal, d);
            if !p.inside(r2.at(1e-7)) {
                continue; // a corner or rim: the solid is not on that side
            }
            n += 1;
            match p.nearest(&r2, eps, f64::INFINITY) {
                Some((t2, s2)) => {
                    let out = p.normal(r2.at(t2), s2);
                    if out.dot(d) <= 0.0 {
                        lost += 1;
                    }
                }
                None => lost += 1,
            }
        }
        assert!(lost == 0, "shape {k}: {lost} of {n} rays found no exit");
    }
}
