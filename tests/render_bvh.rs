//! The BVH finds exactly what testing every primitive finds, and secondary rays
//! never re-hit the surface they leave.

mod render_support;

use glam::DVec3;
use proptest::prelude::*;
use proptest::test_runner::{Config, RngSeed};
use render_support::*;
use rts::build::{build, Ray, RayKind, World};
use rts::scene::{Camera, CsgOp, MeshData, Object, Shape, Transform};

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

/// The analytic shapes that are convex (a ray leaving them outwards never
/// comes back).
fn convex_object() -> impl Strategy<Value = Object> {
    prop_oneof![
        (v3(10.0), 0.05..2.0f64).prop_map(|(c, r)| sphere(c, r)),
        (v3(10.0), v3(1.5)).prop_map(|(c, e)| cuboid(c - e.abs(), c + e.abs())),
        (v3(10.0), v3(2.0), v3(2.0)).prop_map(|(a, b, c)| triangle(a, a + b, a + c)),
        (unit(), -10.0..10.0f64).prop_map(|(n, d)| plane(n, d)),
        (v3(10.0), v3(2.0), 0.05..1.5f64, any::<bool>()).prop_map(|(a, d, r, open)| {
            object(Shape::Cylinder {
                base: a,
                cap: a + d + DVec3::X * 0.1,
                radius: r,
                open,
            })
        }),
        (v3(10.0), unit(), 0.1..2.0f64, 0.0..1.0f64).prop_map(|(c, n, r, h)| {
            object(Shape::Disc {
                center: c,
                normal: n,
                radius: r,
                hole: h * r * 0.9,
            })
        }),
        (v3(10.0), 0.1..2.0f64).prop_map(|(c, r)| polyhedron_cube(c, r)),
    ]
}

/// Every kind of shape, CSG and meshes included.
fn any_object() -> impl Strategy<Value = Object> {
    prop_oneof![
        4 => convex_object(),
        1 => (v3(10.0), 0.05..1.5f64, v3(10.0), 0.0..1.5f64, any::<bool>()).prop_map(
            |(a, r0, b, r1, open)| object(Shape::Cone {
                base: a,
                base_radius: r0,
                cap: b + DVec3::Y * 0.1,
                cap_radius: r1,
                open,
            })
        ),
        1 => (0.5..3.0f64, 0.05..1.0f64, v3(8.0)).prop_map(|(major, minor, at)| {
            with_transform(object(Shape::Torus { major, minor }), Transform::translate(at))
        }),
        1 => (v3(10.0), v3(2.0), v3(2.0), v3(1.0), v3(1.0), v3(1.0)).prop_map(
            |(a, b, c, n0, n1, n2)| object(Shape::SmoothTriangle {
                vertices: [a, a + b, a + c],
                normals: [n0, n1, n2],
                uv: None,
            })
        ),
        1 => (0usize..3, prop::collection::vec(convex_object(), 2..4)).prop_map(|(k, children)| {
            let op = [CsgOp::Merge, CsgOp::Intersection, CsgOp::Difference][k];
            object(Shape::Csg { op, children: children.into() })
        }),
        1 => (convex_object(), convex_object()).prop_map(|(mut o, clip)| {
            o.clipped_by = Some(std::sync::Arc::new(vec![clip]));
            o
        }),
        1 => Just(object(Shape::Mesh(shared_mesh()))),
    ]
}

/// One mesh shared by every instance in a test (as a declared mesh is).
fn shared_mesh() -> std::sync::Arc<MeshData> {
    static MESH: std::sync::OnceLock<std::sync::Arc<MeshData>> = std::sync::OnceLock::new();
    MESH.get_or_init(|| {
        // A bumpy grid of 20×20 quads.
        let n = 21u32;
        let mut m = MeshData::default();
        for j in 0..n {
            for i in 0..n {
                let (x, z) = (i as f32 * 0.3 - 3.0, j as f32 * 0.3 - 3.0);
                m.positions
                    .push([x, ((x * 3.0).sin() * (z * 2.0).cos()) * 0.5, z]);
            }
        }
        for j in 0..n - 1 {
            for i in 0..n - 1 {
                let k = j * n + i;
                m.triangles.push([k, k + 1, k + n]);
                m.triangles.push([k + 1, k + n + 1, k + n]);
            }
        }
        std::sync::Arc::new(m)
    })
    .clone()
}

fn polyhedron_cube(c: DVec3, r: f64) -> Object {
    let planes = DVec3::AXES
        .iter()
        .flat_map(|&a| [(a, a.dot(c) + r), (-a, -a.dot(c) + r)])
        .collect();
    object(Shape::Polyhedron { planes })
}

fn placed(obj: impl Strategy<Value = Object>) -> impl Strategy<Value = Object> {
    (obj, transform()).prop_map(|(mut o, t)| {
        o.transform = t.map(std::sync::Arc::new);
        o
    })
}

fn shape_object() -> impl Strategy<Value = Object> {
    placed(any_object())
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
            // The surface facts are finite wherever something is hit.
            if let Some(h) = fast {
                let s = w.surface(&ray, &h);
                prop_assert!(s.geo_normal.is_finite() && s.normal.is_finite());
                prop_assert!((s.geo_normal.length() - 1.0).abs() < 1e-6);
            }
        }
    }

    /// The path tracer's flat list of boxes (`Bvh::flat`, both its small and
    /// its large key arrays) finds the same nearest hits and blockers as testing
    /// every primitive, rays starting inside the scene included.
    #[test]
    fn flat_list_hit_equals_brute_force(
        objects in prop::collection::vec(shape_object(), 1..80),
        rays in prop::collection::vec((v3(15.0), unit()), 32),
    ) {
        let w = world(objects);
        let Some(flat) = w.flat_bvh() else {
            prop_assert!(w.primitives.iter().all(|p| p.bounds.is_none()));
            return Ok(());
        };
        for (o, d) in rays {
            let ray = Ray::new(o, d);
            let fast = w.intersect_among(&flat, &ray, 0.0, f64::INFINITY, RayKind::Camera);
            let slow = w.intersect_brute_force(&ray, 0.0, f64::INFINITY, RayKind::Camera);
            prop_assert_eq!(fast.map(|h| h.t), slow.map(|h| h.t));
            let occluded = w.occluded_among(&flat, &ray, 0.0, 20.0);
            prop_assert_eq!(occluded, slow.is_some_and(|h| h.t < 20.0));
        }
    }

    /// Every shape, convex or not (torus, cone, smooth triangle, CSG, mesh): a
    /// secondary ray never finds its own starting point again (no hit within a
    /// tiny distance of where it leaves).
    #[test]
    fn secondary_rays_leave_every_shape_cleanly(
        obj in shape_object(),
        scale in prop_oneof![Just(1.0), Just(1e-3), Just(1e3)],
        rays in prop::collection::vec((v3(15.0), unit(), unit()), 48),
    ) {
        let obj = with_transform(union_of(obj), Transform::scale(DVec3::splat(scale)));
        let w = world(vec![obj]);
        for (o, d, out) in rays {
            let ray = Ray::new(o * scale, d);
            let Some(hit) = w.intersect(&ray, 0.0, f64::INFINITY, RayKind::Camera) else {
                continue;
            };
            let p = ray.at(hit.t);
            let n = w.surface(&ray, &hit).geo_normal;
            let dir = (out - n * n.dot(out) * 0.999).normalize();
            let (sec, eps) = Ray::secondary(p, n, dir);
            if let Some(again) = w.intersect(&sec, eps, f64::INFINITY, RayKind::Reflected) {
                prop_assert!(again.t > 1e-6 * scale, "self-hit at t = {} from {:?}", again.t, p);
            }
        }
    }

    #[test]
    fn secondary_rays_do_not_self_intersect(
        obj in placed(convex_object()),
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
        let closed = !matches!(
            prim.shape,
            rts::build::PrimShape::Plane { .. }
                | rts::build::PrimShape::Triangle { .. }
                | rts::build::PrimShape::Disc { .. }
        ) && !matches!(prim.shape, rts::build::PrimShape::Frustum(f) if f.open);
        for (o, d, out) in rays {
            let ray = Ray::new(o * scale + offset, d);
            let Some(hit) = w.intersect(&ray, 0.0, f64::INFINITY, RayKind::Camera) else {
                continue;
            };
            let p = ray.at(hit.t);
            let n = w.surface(&ray, &hit).geo_normal;
            // Any direction leaving the surface on either side, including grazing.
            let dir = (out - n * n.dot(out) * 0.999_999).normalize();
            let (sec, eps) = Ray::secondary(p, n, dir);
            // Primitives are convex: a ray leaving the surface cannot re-enter on the
            // side it leaves towards, except through the interior (boxes and spheres
            // when it leaves inwards), so check only outward rays for closed shapes.
            if closed && dir.dot(n) < 0.0 {
                continue;
            }
            let again = w.intersect(&sec, eps, f64::INFINITY, RayKind::Reflected);
            prop_assert!(again.is_none(), "re-hit at t = {:?} from {:?} dir {:?}", again.map(|h| h.t), p, dir);
        }
    }
}

/// CSG results: a hit of a difference is on the first operand outside the
/// others, or on another operand inside the first; inside tests agree.
#[test]
fn csg_hits_and_inside_follow_pov_rules() {
    let a = sphere(DVec3::ZERO, 1.0);
    let b = sphere(DVec3::X, 1.0);
    let diff = object(Shape::Csg {
        op: CsgOp::Difference,
        children: vec![a.clone(), b.clone()].into(),
    });
    let inter = object(Shape::Csg {
        op: CsgOp::Intersection,
        children: vec![a.clone(), b.clone()].into(),
    });
    let merge = object(Shape::Csg {
        op: CsgOp::Merge,
        children: vec![a, b].into(),
    });
    let along_x = Ray::new(DVec3::new(-5.0, 0.0, 0.0), DVec3::X);
    let hits = |o: &Object| {
        let w = world(vec![o.clone()]);
        let mut ts = Vec::new();
        let mut t0 = 0.0;
        while let Some(h) = w.intersect(&along_x, t0, f64::INFINITY, RayKind::Camera) {
            let s = w.surface(&along_x, &h);
            ts.push((h.t, s.geo_normal.x.signum()));
            t0 = h.t + 1e-9;
        }
        (w, ts)
    };
    // Difference: enters A at x=-1 (normal -x), leaves at x=0 through B's surface
    // with B's normal flipped (+x... out of the solid is towards B: +x).
    let (w, ts) = hits(&diff);
    assert_eq!(ts, vec![(4.0, -1.0), (5.0, 1.0)]);
    assert!(w.inside(DVec3::new(-0.5, 0.0, 0.0)));
    assert!(!w.inside(DVec3::new(0.5, 0.0, 0.0)));
    let (w, ts) = hits(&inter);
    assert_eq!(ts, vec![(5.0, -1.0), (6.0, 1.0)]);
    assert!(w.inside(DVec3::new(0.5, 0.0, 0.0)));
    assert!(!w.inside(DVec3::new(-0.5, 0.0, 0.0)));
    let (w, ts) = hits(&merge);
    assert_eq!(ts, vec![(4.0, -1.0), (7.0, 1.0)]);
    assert!(w.inside(DVec3::new(1.5, 0.0, 0.0)));
}

/// A mesh placed many times is held once; each instance is one primitive.
#[test]
fn mesh_instances_share_triangles() {
    let m = shared_mesh();
    let objs: Vec<Object> = (0..10)
        .map(|i| {
            with_transform(
                object(Shape::Mesh(m.clone())),
                Transform::translate(DVec3::X * 10.0 * i as f64),
            )
        })
        .collect();
    let w = world(objs);
    assert_eq!(w.primitives.len(), 10);
    let first = match &w.primitives[0].shape {
        rts::build::PrimShape::Mesh(a) => a.clone(),
        _ => panic!("not a mesh"),
    };
    for p in w.primitives.iter() {
        match &p.shape {
            rts::build::PrimShape::Mesh(a) => assert!(std::sync::Arc::ptr_eq(a, &first)),
            _ => panic!("not a mesh"),
        }
    }
    assert!(std::sync::Arc::ptr_eq(&first.data, &m));
}

fn union_of(obj: Object) -> Object {
    let mut u = object(rts::scene::Shape::Union {
        children: vec![obj].into(),
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
    // Node bounds are f32, rounded outwards.
    let (lo, hi) = (DVec3::new(-0.4, -0.4, -0.4), DVec3::new(19.4, 19.4, 0.4));
    assert!(w.bounds.min.cmple(lo).all() && (w.bounds.min - lo).length() < 1e-5);
    assert!(w.bounds.max.cmpge(hi).all() && (w.bounds.max - hi).length() < 1e-5);
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

/// A mesh object reused by a later frame, then evaluated again (placed anew)
/// with the same triangles, still has the hierarchy built in the first frame.
#[test]
fn a_mesh_keeps_its_hierarchy_through_reused_and_new_placements() {
    let m = shared_mesh();
    let accel = |w: &World| match &w.primitives[0].shape {
        rts::build::PrimShape::Mesh(a) => a.clone(),
        _ => panic!("not a mesh"),
    };
    let mut s = scene(Camera::default(), vec![object(Shape::Mesh(m.clone()))]);
    let mut cache = rts::build::BuildCache::default();
    s.placed = vec![rts::scene::next_placement()];
    let first = accel(&rts::build::build_cached(&s, &mut cache));
    // Reused: the same placement.
    let second = accel(&rts::build::build_cached(&s, &mut cache));
    // Placed again (its item evaluated again), the same mesh data.
    s.placed = vec![rts::scene::next_placement()];
    let third = accel(&rts::build::build_cached(&s, &mut cache));
    assert!(std::sync::Arc::ptr_eq(&first, &second));
    assert!(std::sync::Arc::ptr_eq(&first, &third));
}
