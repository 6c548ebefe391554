//! Built-ins that need an object's geometry while the scene is read: `trace`
//! (where a ray first meets an object), `inside` (whether a point is in it) and
//! `min_extent` / `max_extent` (its bounding box). Both build the object's hierarchy, kept for the calls that
//! follow: scenes call `trace` thousands of times on one terrain to place things
//! on it.

use super::value::{Value, Vector};
use super::{Evaluator, R};
use crate::build::{PrimShape, Ray, RayKind, World};
use crate::diag::{codes, Diagnostic};
use crate::scene::Object;
use crate::span::Span;
use crate::syntax::ast::{Arg, ExprKind};
use glam::DVec3;
use std::sync::Arc;

/// Built objects kept (most recent last): enough for a scene that traces
/// against a few objects in turn.
const KEPT: usize = 8;

/// Hits nearer than this along the (unit) direction are skipped, so a ray
/// started on a surface leaves it; POV-Ray 3.7 skips a sphere's surface 10⁻⁵
/// ahead of the start as well.
const T_MIN: f64 = 1e-4;

/// Half the width of the box `min_extent` / `max_extent` give for an unbounded
/// object (a plane), as POV-Ray does.
const HUGE: f64 = 1e10;

/// Objects built for `trace` and `min_extent` (see the module documentation).
#[derive(Default)]
pub(crate) struct BuiltObjects {
    kept: Vec<(Arc<Object>, Arc<World>)>,
    /// What the last build made that the next can reuse (mesh hierarchies,
    /// glyph prisms): a union grown in a loop and traced at every step is
    /// built again each time, its meshes and letters not.
    cache: crate::build::BuildCache,
}

impl Evaluator<'_> {
    /// The hierarchy of `object`, built once per distinct object value.
    pub(crate) fn built(&mut self, object: &Arc<Object>) -> Arc<World> {
        let kept = &mut self.built_objects.kept;
        if let Some(i) = kept.iter().position(|(o, _)| Arc::ptr_eq(o, object)) {
            let entry = kept.remove(i);
            let world = entry.1.clone();
            kept.push(entry);
            return world;
        }
        let scene = crate::scene::Scene {
            objects: vec![(**object).clone()],
            ..crate::scene::Scene::default()
        };
        let world = Arc::new(crate::build::build_cached(
            &scene,
            &mut self.built_objects.cache,
        ));
        if kept.len() >= KEPT {
            kept.remove(0);
        }
        kept.push((object.clone(), world.clone()));
        world
    }

    /// The corners of `object`'s bounding box, as `min_extent` and `max_extent`
    /// give them: the box our hierarchy bounds it by (as POV-Ray's own bounding
    /// boxes are), ±10¹⁰ when it has an unbounded part, the origin when it is
    /// empty.
    pub(crate) fn object_extent(&mut self, object: &Arc<Object>) -> (DVec3, DVec3) {
        let world = self.built(object);
        if !world.unbounded.is_empty() {
            return (DVec3::splat(-HUGE), DVec3::splat(HUGE));
        }
        let b = world.bvh.bounds();
        if b.min.cmpgt(b.max).any() {
            return (DVec3::ZERO, DVec3::ZERO);
        }
        (
            b.min.max(DVec3::splat(-HUGE)),
            b.max.min(DVec3::splat(HUGE)),
        )
    }

    /// `inside(OBJECT, POINT)`: whether POINT is inside OBJECT by the rules
    /// CSG and refraction use (a surface's inside, `inverse` flipping it).
    pub(crate) fn object_inside(&mut self, object: &Arc<Object>, p: DVec3) -> bool {
        self.built(object).inside(p)
    }

    /// `trace(OBJECT, START, DIRECTION [, NORMAL])`: the point where the ray from
    /// START along DIRECTION first meets OBJECT, or `<0, 0, 0>` when it misses.
    /// NORMAL, a name, receives the object's normal there (outward, as the
    /// object defines it: not turned towards the ray, without `normal { }`
    /// perturbation), or `<0, 0, 0>` on a miss. Every part of the object counts,
    /// `no_image` and `no_shadow` ones too, as in POV-Ray.
    pub(crate) fn trace_call(&mut self, args: &[Arg], span: Span) -> R<Value> {
        if !(3..=4).contains(&args.len()) {
            return Err(Diagnostic::error(
                codes::ARITY,
                span,
                format!("`trace` takes 3 or 4 arguments, found {}", args.len()),
            )
            .with_help("call it as trace(OBJECT, START, DIRECTION) or trace(OBJECT, START, DIRECTION, NORMAL)")
            .into());
        }
        let mut vals = Vec::with_capacity(3);
        for a in &args[..3] {
            vals.push(match a {
                Arg::Expr(e) => (self.expr(e)?, e.span),
                Arg::Block(b) => (self.block_value(b)?, b.span),
                Arg::Empty(s) => {
                    return Err(Diagnostic::error(
                        codes::MISSING_VALUE,
                        *s,
                        "empty argument to `trace`",
                    )
                    .with_label("a value is missing here")
                    .into())
                }
            });
        }
        let normal_name = match args.get(3) {
            None => None,
            Some(Arg::Expr(e)) => match &e.kind {
                ExprKind::Ident(n) if !n.is_builtin() => Some((*n, e.span)),
                _ => {
                    return Err(Diagnostic::error(
                        codes::TYPE_MISMATCH,
                        e.span,
                        "the fourth argument of `trace` is a name to store the normal in",
                    )
                    .with_label("not a name")
                    .with_help("declare a vector first and pass its name: `#declare N = <0, 0, 0>; #declare P = trace(Obj, A, B, N);`")
                    .into())
                }
            },
            Some(a) => {
                return Err(Diagnostic::error(
                    codes::TYPE_MISMATCH,
                    a.span(),
                    "the fourth argument of `trace` is a name to store the normal in",
                )
                .into())
            }
        };
        let Value::Object(object) = &vals[0].0 else {
            return Err(self.mismatch("an object", &vals[0].0, vals[0].1));
        };
        let object = object.clone();
        let start = self.to_vec3(&vals[1].0, vals[1].1)?;
        let dir = self.to_vec3(&vals[2].0, vals[2].1)?;
        if !(dir.length_squared() > 0.0 && dir.is_finite()) {
            return Err(Diagnostic::error(
                codes::DOMAIN_ERROR,
                vals[2].1,
                "`trace` needs a direction of non-zero length",
            )
            .with_label("this is <0, 0, 0>")
            .into());
        }
        let world = self.built(&object);
        let ray = Ray::new(start, dir.normalize());
        let (point, normal) = match nearest(&world, &ray) {
            Some((t, n)) => (ray.at(t), n),
            None => (DVec3::ZERO, DVec3::ZERO),
        };
        if let Some((name, at)) = normal_name {
            self.scope
                .declare(name, Value::Vector(Vector::v3(normal)), at);
        }
        Ok(Value::Vector(Vector::v3(point)))
    }
}

/// The nearest hit of `ray` on anything in `world` (whatever its `no_image`,
/// `no_reflection` or `no_shadow`): distance and unperturbed normal.
fn nearest(world: &World, ray: &Ray) -> Option<(f64, DVec3)> {
    let hit = world.intersect(ray, T_MIN, f64::INFINITY, RayKind::Probe)?;
    let s = world.surface(ray, &hit);
    // A CSG's inverse is in its leaves' normals already; a plain shape's is a flag.
    let n = if s.flags.inverse { -s.normal } else { s.normal };
    // Flat triangles written in the scene: POV-Ray's sense, `(c − a) × (b − a)`
    // (measured: a triangle <-1,0,-1>, <1,0,-1>, <0,0,1> reports +y).
    let flat_written = match &world.primitives[hit.prim as usize].shape {
        PrimShape::Triangle { .. } => true,
        PrimShape::Mesh(m) => {
            m.data.text_winding
                && m.data
                    .normal_indices
                    .get(hit.sub as usize)
                    .is_none_or(|ix| ix[0] == u32::MAX)
        }
        _ => false,
    };
    Some((hit.t, if flat_written { -n } else { n }))
}
