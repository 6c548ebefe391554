//! `bicubic_patch`, `julia_fractal` and `sphere_sweep` against shapes whose
//! answers are known: a Julia set with c = 0 is the unit ball, a linear sweep
//! of equal spheres is a capsule (two spheres and a cylinder), a flat patch is
//! a square. Seeded property tests check hits and inside tests against those
//! brute-force answers and that secondary rays leave the new shapes cleanly;
//! render checks compare whole pictures.

mod render_support;

use glam::{DVec2, DVec3, DVec4};
use proptest::prelude::*;
use proptest::test_runner::{Config, RngSeed};
use render_support::*;
use rts::build::shapes::julia::{Algebra, Julia, JuliaFn};
use rts::build::shapes::sweep::SweepSpline;
use rts::build::{build, Ray, RayKind, World};
use rts::eval::bicubic;
use rts::scene::{Camera, Object, Shape, SweepData, Transform};
use std::sync::Arc;

fn config(cases: u32) -> Config {
    Config {
        cases,
        rng_seed: RngSeed::Fixed(0x5eed_5a9e),
        failure_persistence: None,
        ..Config::default()
    }
}

fn v3(range: f64) -> impl Strategy<Value = DVec3> {
    (-range..range, -range..range, -range..range).prop_map(|(x, y, z)| DVec3::new(x, y, z))
}

fn unit() -> impl Strategy<Value = DVec3> {
    v3(1.0)
        .prop_filter("non-zero", |v| v.length() > 1e-3)
        .prop_map(|v| v.normalize())
}

fn unit_ball_julia() -> Object {
    object(Shape::Julia(Arc::new(Julia {
        c: DVec4::ZERO,
        algebra: Algebra::Quaternion,
        function: JuliaFn::Sqr,
        max_iteration: 20,
        precision: 20.0,
        slice_normal: DVec4::W,
        slice_distance: 0.0,
    })))
}

fn capsule_sweep(a: DVec3, b: DVec3, r: f64) -> Object {
    object(Shape::SphereSweep(Arc::new(SweepData {
        spline: SweepSpline::Linear,
        points: vec![(a, r), (b, r)],
        tolerance: 1e-6,
    })))
}

fn capsule_csg(a: DVec3, b: DVec3, r: f64) -> Vec<Object> {
    vec![
        sphere(a, r),
        sphere(b, r),
        object(Shape::Cylinder {
            base: a,
            cap: b,
            radius: r,
            open: false,
        }),
    ]
}

/// A flat patch: the square from `o` spanned by `u` and `v`.
fn flat_patch(o: DVec3, u: DVec3, v: DVec3, steps: u32) -> Object {
    let pts: [DVec3; 16] =
        std::array::from_fn(|k| o + u * ((k / 4) as f64 / 3.0) + v * ((k % 4) as f64 / 3.0));
    let uv = [DVec2::ZERO, DVec2::X, DVec2::ONE, DVec2::Y];
    object(Shape::Mesh(Arc::new(bicubic::tessellate(
        &pts, steps, steps, uv,
    ))))
}

fn world(objects: Vec<Object>) -> World {
    build(&scene(Camera::default(), objects))
}

fn first_hit(w: &World, ray: &Ray) -> Option<f64> {
    w.intersect(ray, 0.0, f64::INFINITY, RayKind::Camera)
        .map(|h| h.t)
}

proptest! {
    #![proptest_config(config(32))]

    /// A Julia set with c = 0 is the unit ball: same hits, same inside.
    #[test]
    fn julia_of_zero_is_the_unit_ball(
        rays in prop::collection::vec((v3(4.0), unit()), 24),
        t in v3(3.0),
        s in 0.3..2.0f64,
    ) {
        let tr = Transform::scale(DVec3::splat(s)).then(&Transform::translate(t));
        let j = world(vec![with_transform(unit_ball_julia(), tr)]);
        let b = world(vec![with_transform(sphere(DVec3::ZERO, 1.0), tr)]);
        for (o, d) in rays {
            let ray = Ray::new(o, d);
            let (hj, hb) = (first_hit(&j, &ray), first_hit(&b, &ray));
            prop_assert_eq!(hj.is_some(), hb.is_some(), "{:?} vs {:?}", hj, hb);
            if let (Some(a), Some(b)) = (hj, hb) {
                prop_assert!((a - b).abs() < 1e-3 * s.max(1.0), "{} vs {}", a, b);
            }
            prop_assert_eq!(j.primitives[0].inside(o), b.primitives[0].inside(o));
        }
    }

    /// A linear sweep of two equal spheres is the capsule.
    #[test]
    fn linear_sweep_is_the_capsule(
        a in v3(3.0),
        d in v3(3.0),
        r in 0.1..1.5f64,
        rays in prop::collection::vec((v3(8.0), unit()), 24),
    ) {
        let b = a + d + DVec3::X * 0.1;
        let sw = world(vec![capsule_sweep(a, b, r)]);
        let cs = world(capsule_csg(a, b, r));
        for (o, dir) in rays {
            let inside_csg = cs.primitives.iter().any(|p| p.inside(o));
            prop_assert_eq!(sw.primitives[0].inside(o), inside_csg);
            if inside_csg {
                // From inside, the separate parts show their inner surfaces.
                continue;
            }
            let ray = Ray::new(o, dir);
            let (h1, h2) = (first_hit(&sw, &ray), first_hit(&cs, &ray));
            prop_assert_eq!(h1.is_some(), h2.is_some(), "{:?} vs {:?}", h1, h2);
            if let (Some(x), Some(y)) = (h1, h2) {
                prop_assert!((x - y).abs() < 1e-4, "{} vs {}", x, y);
            }
        }
    }

    /// A flat patch is hit where its square is.
    #[test]
    fn flat_patch_is_its_square(
        o in v3(3.0),
        u in v3(2.0),
        v in v3(2.0),
        steps in 0u32..4,
        rays in prop::collection::vec((v3(6.0), unit()), 24),
    ) {
        prop_assume!(u.cross(v).length() > 0.1);
        let p = world(vec![flat_patch(o, u, v, steps)]);
        let sq = world(vec![
            triangle(o, o + u, o + u + v),
            triangle(o, o + u + v, o + v),
        ]);
        for (org, d) in rays {
            let ray = Ray::new(org, d);
            let (h1, h2) = (first_hit(&p, &ray), first_hit(&sq, &ray));
            // Rays through the shared diagonal may slip between two triangles
            // in one split and not the other: compare where both agree on hitting.
            if let (Some(x), Some(y)) = (h1, h2) {
                prop_assert!((x - y).abs() < 1e-6 * (1.0 + x), "{} vs {}", x, y);
            }
            prop_assert!(!p.primitives[0].inside(org), "a patch has no inside");
        }
    }

    /// Secondary rays leaving the new shapes outwards do not hit them again
    /// right away.
    #[test]
    fn secondary_rays_leave_cleanly(
        which in 0usize..3,
        rays in prop::collection::vec((v3(6.0), unit(), unit()), 32),
    ) {
        let obj = match which {
            0 => unit_ball_julia(),
            1 => capsule_sweep(DVec3::new(-1.0, 0.0, 0.0), DVec3::new(1.0, 0.5, 0.0), 0.7),
            _ => {
                let mut pts: [DVec3; 16] = std::array::from_fn(|k| {
                    DVec3::new((k % 4) as f64 - 1.5, 0.0, (k / 4) as f64 - 1.5)
                });
                pts[5].y = 2.0;
                pts[10].y = -1.0;
                object(Shape::Mesh(Arc::new(bicubic::tessellate(
                    &pts,
                    3,
                    3,
                    [DVec2::ZERO, DVec2::X, DVec2::ONE, DVec2::Y],
                ))))
            }
        };
        let w = world(vec![obj]);
        for (o, d, out) in rays {
            let ray = Ray::new(o, d);
            let Some(hit) = w.intersect(&ray, 0.0, f64::INFINITY, RayKind::Camera) else {
                continue;
            };
            let p = ray.at(hit.t);
            let n = w.surface(&ray, &hit).geo_normal;
            prop_assert!(n.is_finite());
            let n = if n.dot(d) > 0.0 { -n } else { n };
            // Leave on the side the ray came from.
            let dir = (out - n * n.dot(out)).normalize_or_zero() * 0.5 + n;
            let (sec, eps) = Ray::secondary(p, n, dir.normalize());
            if let Some(again) = w.intersect(&sec, eps, f64::INFINITY, RayKind::Reflected) {
                prop_assert!(again.t > 1e-4, "self-hit at t = {} from {:?}", again.t, p);
            }
        }
    }
}

/// Renders `scene` at 48×36 with linear 16-bit output; pixels in 0..1.
fn render(name: &str, scene: &str) -> Vec<[f64; 3]> {
    render_support::render_source("render_shapes_more", name, scene, 48, 36)
}

/// The mean absolute difference and how many pixels differ by more than `tol`.
fn diff(a: &[[f64; 3]], b: &[[f64; 3]], tol: f64) -> (f64, usize) {
    let mut sum = 0.0;
    let mut off = 0;
    for (p, q) in a.iter().zip(b) {
        let d: Vec<f64> = (0..3).map(|i| (p[i] - q[i]).abs()).collect();
        sum += d.iter().sum::<f64>() / 3.0;
        if d.iter().any(|x| *x > tol) {
            off += 1;
        }
    }
    (sum / a.len() as f64, off)
}

const SETUP: &str = "global_settings { assumed_gamma 1.0 }\n\
    camera { location <0, 1, -4> look_at 0 angle 50 }\n\
    light_source { <3, 5, -4> rgb 1 }\n\
    plane { y, -1.2 pigment { rgb 0.6 } }\n";

#[test]
fn julia_of_zero_renders_as_the_sphere_in_csg() {
    let scene = |obj: &str| {
        format!(
            "{SETUP}difference {{ {obj} box {{ <-0.5, -0.5, -2>, <0.5, 0.5, 0> }} \
             pigment {{ rgb <1, 0.6, 0.3> }} finish {{ phong 0.4 }} rotate <10, 30, 0> }}"
        )
    };
    let j = render(
        "julia_csg",
        &scene("julia_fractal { <0, 0, 0, 0> quaternion sqr max_iteration 20 }"),
    );
    let s = render("sphere_csg", &scene("sphere { 0, 1 }"));
    let (mean, off) = diff(&j, &s, 0.02);
    assert!(
        mean < 0.003 && off <= 12,
        "mean {mean}, {off} pixels differ"
    );
}

#[test]
fn sweep_renders_as_its_capsule() {
    let tex = "pigment { rgb <0.3, 0.7, 1> } finish { phong 0.5 } rotate <0, 20, 10>";
    let sw = render(
        "sweep",
        &format!(
            "{SETUP}sphere_sweep {{ linear_spline 2, <-1, 0, 0>, 0.5, <1, 0.2, 0>, 0.5 {tex} }}"
        ),
    );
    let cs = render(
        "capsule",
        &format!(
            "{SETUP}merge {{ sphere {{ <-1, 0, 0>, 0.5 }} sphere {{ <1, 0.2, 0>, 0.5 }} \
             cylinder {{ <-1, 0, 0>, <1, 0.2, 0>, 0.5 }} {tex} }}"
        ),
    );
    let (mean, off) = diff(&sw, &cs, 0.02);
    assert!(
        mean < 0.003 && off <= 12,
        "mean {mean}, {off} pixels differ"
    );
}

#[test]
fn flat_patch_renders_as_its_square() {
    let tex = "pigment { rgb <1, 0.9, 0.2> } rotate <-60, 20, 0>";
    let patch = render(
        "patch",
        &format!(
            "{SETUP}bicubic_patch {{ type 1 u_steps 2 v_steps 2 \
             <-1,0,-1>, <-1/3,0,-1>, <1/3,0,-1>, <1,0,-1>, \
             <-1,0,-1/3>, <-1/3,0,-1/3>, <1/3,0,-1/3>, <1,0,-1/3>, \
             <-1,0,1/3>, <-1/3,0,1/3>, <1/3,0,1/3>, <1,0,1/3>, \
             <-1,0,1>, <-1/3,0,1>, <1/3,0,1>, <1,0,1> {tex} }}"
        ),
    );
    let square = render(
        "square",
        &format!("{SETUP}polygon {{ 5, <-1,0,-1>, <1,0,-1>, <1,0,1>, <-1,0,1>, <-1,0,-1> {tex} }}"),
    );
    let (mean, off) = diff(&patch, &square, 0.02);
    assert!(
        mean < 0.003 && off <= 12,
        "mean {mean}, {off} pixels differ"
    );
}
