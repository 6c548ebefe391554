//! The BVH finds exactly what testing every primitive finds, and secondary rays
//! never re-hit the surface they leave.

mod render_support;

use glam::DVec3;
use proptest::prelude::*;
use proptest::test_runner::{Config, RngSeed};
use render_support::*;
use rts::build::{build, Ray, RayKind, World};
use rts::scene::{Camera, Object, Transform};

fn config(cases: u32) -> Config {
    Config {
        cases,
        rng_seed: RngSeed::Fixed(0x5eed_0fb4),
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

/// A random transform: scale, rotate, translate.
fn transform() -> impl Strategy<Value = Option<Transform>> {
    prop_oneof![
        Just(None),
        (v3(1.0), v3(180.0), v3(5.0)).prop_map(|(s, r, t)| {
            let s = s.abs() + DVec3::splat(0.2);
            Some(
                Transform::scale(s)
                    .then(&Transform::rotate(r))
                    .then(&Transform::translate(t)),
            )
        }),
    ]
}

fn shape_object() -> impl Strategy<Value = Object> {
    let obj = prop_oneof![
        (v3(10.0), 0.05..2.0f64).prop_map(|(c, r)| sphere(c, r)),
        (v3(10.0), v3(1.5)).prop_map(|(c, e)| cuboid(c - e.abs(), c + e.abs())),
        (v3(10.0), v3(2.0), v3(2.0)).prop_map(|(a, b, c)| triangle(a, a + b, a + c)),
        (unit(), -10.0..10.0f64).prop_map(|(n, d)| plane(n, d)),
    ];
    (obj, transform()).prop_map(|(mut o, t)| {
        o.transform = t.map(std::sync::Arc::new);
        o
    })
}

fn world(objects: Vec<Object>) -> World {
    build(&scene(Camera::default(), objects))
}

proptest! {
    #![proptest_config(config(64))]

    #[test]
    fn bvh_hit_equals_brute_force(
        objects in prop::collection::vec(shape_object(), 1..80),
        rays in prop::collection::vec((v3(15.0), unit()), 32),
    ) {
        let w = world(objects);
        for (o, d) in rays {
            let ray = Ray::new(o, d);
            let fast = w.intersect(&ray, 0.0, f64::INFINITY, RayKind::Camera);
            let slow = w.intersect_brute_force(&ray, 0.0, f64::INFINITY, RayKind::Camera);
            prop_assert_eq!(fast.map(|h| h.t), slow.map(|h| h.t));
            let occluded = w.occluded(&ray, 0.0, 20.0);
            prop_assert_eq!(occluded, slow.is_some_and(|h| h.t < 20.0));
        }
    }

    #[test]
    fn secondary_rays_do_not_self_intersect(
        obj in shape_object(),
        scale in prop_oneof![Just(1.0), Just(1e-3), Just(1e3)],
        offset in prop_oneof![Just(DVec3::ZERO), Just(DVec3::new(1e4, -3e3, 5e3))],
        rays in prop::collection::vec((v3(15.0), unit(), unit()), 64),
    ) {
        // Scale and move the whole object to stress the relative epsilon.
        let obj = with_transform(
            union_of(obj),
            Transform::scale(DVec3::splat(scale)).then(&Transform::translate(offset)),
        );
        let w = world(vec![obj]);
        let prim = &w.primitives[0];
        for (o, d, out) in rays {
            let ray = Ray::new(o * scale + offset, d);
            let Some(hit) = w.intersect(&ray, 0.0, f64::INFINITY, RayKind::Camera) else {
                continue;
            };
            let p = ray.at(hit.t);
            let n = prim.normal(p);
            // Any direction leaving the surface on either side, including grazing.
            let dir = (out - n * n.dot(out) * 0.999_999).normalize();
            let (sec, eps) = Ray::secondary(p, n, dir);
            // Primitives are convex: a ray leaving the surface cannot re-enter on the
            // side it leaves towards, except through the interior (boxes and spheres
            // when it leaves inwards), so check only outward rays for closed shapes.
            let closed = !matches!(prim.shape, rts::build::PrimShape::Plane { .. } | rts::build::PrimShape::Triangle { .. });
            if closed && dir.dot(n) < 0.0 {
                continue;
            }
            let again = w.intersect(&sec, eps, f64::INFINITY, RayKind::Reflected);
            prop_assert!(again.is_none(), "re-hit at t = {:?} from {:?} dir {:?}", again.map(|h| h.t), p, dir);
        }
    }
}

fn union_of(obj: Object) -> Object {
    let mut u = object(rts::scene::Shape::Union {
        children: vec![obj],
    });
    u.transform = None;
    u
}

#[test]
fn many_spheres_use_a_real_tree() {
    let mut objs = Vec::new();
    for i in 0..20 {
        for j in 0..20 {
            objs.push(sphere(DVec3::new(i as f64, j as f64, 0.0), 0.4));
        }
    }
    let w = world(objs);
    assert!(w.bvh.node_count() > 100);
    assert_eq!(w.bounds.min, DVec3::new(-0.4, -0.4, -0.4));
    assert_eq!(w.bounds.max, DVec3::new(19.4, 19.4, 0.4));
    let hit = w.intersect(
        &Ray::new(DVec3::new(7.0, 3.0, -5.0), DVec3::Z),
        0.0,
        f64::INFINITY,
        RayKind::Camera,
    );
    assert!((hit.unwrap().t - 4.6).abs() < 1e-12);
}

#[test]
#[ignore = "timing; run with --ignored --nocapture"]
fn timing_many_spheres() {
    use rts::render::{render, RenderOptions};
    let mut objs = Vec::new();
    for i in 0..100 {
        for j in 0..100 {
            let c = DVec3::new(
                i as f64 * 0.3 - 15.0,
                (i * j % 7) as f64 * 0.1,
                j as f64 * 0.3,
            );
            objs.push(with_texture(
                sphere(c, 0.14),
                texture(DVec3::ONE, matte(0.1, 0.6)),
            ));
        }
    }
    let mut sc = scene(
        Camera {
            location: DVec3::new(0.0, 5.0, -10.0),
            direction: DVec3::new(0.0, -0.3, 1.0),
            right: DVec3::X * 4.0 / 3.0,
            ..Camera::default()
        },
        objs,
    );
    sc.lights.push(point_light(DVec3::new(5.0, 20.0, -5.0)));
    let t = std::time::Instant::now();
    let w = build(&sc);
    let tb = t.elapsed();
    let film = render(
        &w,
        &RenderOptions {
            width: 640,
            height: 480,
        },
    );
    println!(
        "build {tb:?}, render {:?}, nodes {}",
        t.elapsed() - tb,
        w.bvh.node_count()
    );
    assert_eq!(film.pixels.len(), 640 * 480);
}
