//! Objects: shapes with placement, material and flags.

use super::{Interior, Texture, Transform};
use crate::span::Span;
use glam::DVec3;
use std::sync::Arc;

/// Per-object flags (`no_shadow`, `no_image`, …) kept together.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ObjectFlags {
    /// `no_shadow`: the object casts no shadow.
    pub no_shadow: bool,
    /// `no_image`: invisible to camera rays.
    pub no_image: bool,
    /// `no_reflection`: invisible in reflections.
    pub no_reflection: bool,
    /// `inverse`: inside and outside swapped.
    pub inverse: bool,
    /// `hollow`: accepted (it matters for media only, which rts does not have).
    pub hollow: bool,
    /// `double_illuminate`: lit from both sides.
    pub double_illuminate: bool,
    /// `no_radiosity`: invisible to radiosity's gathering rays.
    pub no_radiosity: bool,
    /// `radiosity { importance F }` in ten-thousandths (1 to 10 000); `None`:
    /// inherited from an enclosing CSG object, else 1.
    pub importance: Option<u16>,
    /// The `light_group`s the object is in, one bit per group (see
    /// [`super::Light::group`]); 0: in none, lit by the scene's lights.
    pub light_groups: u64,
    /// `global_lights` of the innermost `light_group` the object is in
    /// (`None` outside groups).
    pub global_lights: Option<bool>,
    /// `photons { … }`: target, reflection, refraction, collect, pass-through.
    pub photons: super::ObjectPhotons,
}

/// One object: a shape, its placement and its material.
#[derive(Clone, Debug)]
pub struct Object {
    /// The geometry, in object space.
    pub shape: Shape,
    /// `world_from_object`, the product of the object's `translate rotate scale matrix`
    /// in the order written; `None` for the identity.
    pub transform: Option<Arc<Transform>>,
    /// The object's texture; `None` inherits from an enclosing CSG object or the
    /// `#default` texture that was in force.
    pub texture: Option<Arc<Texture>>,
    /// `interior { … }`; `None` inherits from an enclosing CSG object, else
    /// POV-Ray's default interior.
    pub interior: Option<Arc<Interior>>,
    /// Flags such as `no_shadow`.
    pub flags: ObjectFlags,
    /// `clipped_by { … }`: only the parts of the shape inside all of these remain
    /// (the clipping objects' own surfaces are not added).
    pub clipped_by: Option<Arc<Vec<Object>>>,
    /// Light sources written among a CSG object's members (`union { light_source
    /// { … } sphere { … } }`), in the object's space: they move with it, as in
    /// POV-Ray. The evaluator takes them out into the scene's lights when the
    /// object is placed, so the renderer never sees them here.
    pub lights: Vec<super::Light>,
    /// How many levels of `union`, CSG and `clipped_by` lie below this object
    /// (0 for a plain shape): walks over the object tree are as deep as this,
    /// and evaluation keeps it under a limit.
    pub nesting: u32,
    /// Where the object was written.
    pub span: Span,
}

impl Object {
    /// A shape with no transform, no texture (inherited or default) and no flags.
    pub fn new(shape: Shape, span: Span) -> Object {
        Object {
            shape,
            transform: None,
            texture: None,
            interior: None,
            flags: ObjectFlags::default(),
            clipped_by: None,
            lights: Vec::new(),
            nesting: 0,
            span,
        }
    }
}

/// The members of a `union` or CSG object: a persistent vector, so copying an
/// object (`object { Fence }`) shares its members instead of copying them, and
/// `union { object { Fence } box { … } }` grows the union in constant time.
pub type Members = imbl::Vector<Object>;

/// The shapes of this release, in object space.
#[derive(Clone, Debug)]
pub enum Shape {
    /// `sphere { CENTER, RADIUS }`.
    Sphere {
        /// Centre.
        center: DVec3,
        /// Radius (> 0).
        radius: f64,
    },
    /// `plane { NORMAL, DISTANCE }`: the points p with `p·n = distance`, inside below.
    Plane {
        /// Unit normal.
        normal: DVec3,
        /// Offset along the normal.
        distance: f64,
    },
    /// `box { CORNER1, CORNER2 }` with the corners sorted so `min <= max`.
    Box {
        /// Lowest corner.
        min: DVec3,
        /// Highest corner.
        max: DVec3,
    },
    /// `triangle { A, B, C }`.
    Triangle {
        /// Vertices.
        vertices: [DVec3; 3],
        /// `uv_vectors UV1, UV2, UV3`: the corners' uv coordinates (used inside a
        /// mesh, for `uv_mapping` and `mesh_camera` distribution 3).
        uv: Option<[glam::DVec2; 3]>,
    },
    /// `union { OBJECT… }`: the children keep their own transforms, which are applied
    /// before the union's.
    Union {
        /// The member objects.
        children: Members,
    },
    /// `cylinder { BASE, CAP, RADIUS [open] }`.
    Cylinder {
        /// Centre of the base end.
        base: DVec3,
        /// Centre of the cap end.
        cap: DVec3,
        /// Radius (> 0).
        radius: f64,
        /// `open`: no end caps, and not a solid (inside is always false).
        open: bool,
    },
    /// `cone { BASE, BASE_RADIUS, CAP, CAP_RADIUS [open] }`.
    Cone {
        /// Centre of the base end.
        base: DVec3,
        /// Radius at the base (>= 0).
        base_radius: f64,
        /// Centre of the cap end.
        cap: DVec3,
        /// Radius at the cap (>= 0).
        cap_radius: f64,
        /// `open`: no end caps, and not a solid.
        open: bool,
    },
    /// `torus { MAJOR, MINOR }`: in the x-z plane around the y axis.
    Torus {
        /// Radius of the ring's centre line.
        major: f64,
        /// Radius of the tube.
        minor: f64,
    },
    /// `quadric { <A, B, C>, <D, E, F>, <G, H, I>, J }`: the surface
    /// `A x² + B y² + C z² + D xy + E xz + F yz + G x + H y + I z + J = 0`, inside
    /// where the left side is negative; unbounded.
    Quadric {
        /// The coefficients `A … J`.
        coefficients: [f64; 10],
    },
    /// `poly { ORDER, <A, B, …> }`, `cubic { <20 numbers> }`, `quartic { <35 numbers> }`:
    /// the surface where a polynomial in x, y, z is zero, inside where it is
    /// negative; coefficients in POV-Ray's order (terms by falling power of x, then
    /// y, then z); unbounded. `sturm` is accepted after the coefficients.
    Poly {
        /// 2 to 4.
        order: u32,
        /// `(order+1)(order+2)(order+3)/6` coefficients.
        coefficients: Vec<f64>,
    },
    /// `disc { CENTER, NORMAL, RADIUS [, HOLE_RADIUS] }` (not a solid).
    Disc {
        /// Centre.
        center: DVec3,
        /// Unit normal.
        normal: DVec3,
        /// Outer radius.
        radius: f64,
        /// Inner radius (0 for none).
        hole: f64,
    },
    /// `smooth_triangle { A, NA, B, NB, C, NC }` (not a solid).
    SmoothTriangle {
        /// Vertices.
        vertices: [DVec3; 3],
        /// Vertex normals (unnormalised as written).
        normals: [DVec3; 3],
        /// `uv_vectors UV1, UV2, UV3`, as for [`Shape::Triangle`].
        uv: Option<[glam::DVec2; 3]>,
    },
    /// `polygon { N, P1, …, PN }`: closed sub-polygons filled by the even-odd rule,
    /// in one plane (not a solid).
    Polygon {
        /// The points as written (each sub-polygon repeats its first point).
        points: Vec<DVec3>,
    },
    /// `polyhedron { vertex_vectors { … } face_indices { … } }`: the convex solid
    /// bounded by the face planes (rts's own; see docs/language.md).
    Polyhedron {
        /// Face planes `(outward unit normal, d)`: inside is `n·p < d` for all.
        planes: Vec<(DVec3, f64)>,
    },
    /// `prism { [SPLINE] [SWEEP] H1, H2, N, <u, v>… [open] }`: closed curves in the
    /// x-z plane (`<u, v>` → x, z) swept along y between the heights, straight up
    /// or (`conic_sweep`) scaled by y from a point at the origin.
    Prism {
        /// The outline's segments, each `c0 + c1 s + c2 s² + c3 s³` for
        /// `s ∈ [0, 1]` as `<x, z>` (see [`crate::build::shapes::prism::outline`]).
        curves: Arc<[[glam::DVec2; 4]]>,
        /// The two heights as written (either order).
        heights: [f64; 2],
        /// `conic_sweep`.
        conic: bool,
        /// `open`: no caps (inside tests still see a solid, as in POV-Ray).
        open: bool,
    },
    /// `lathe { [SPLINE] N, <x, y>… }`: a spline in the x-y plane revolved around
    /// the y axis.
    Lathe {
        /// The spline's segments, each `c0 + c1 s + c2 s² + c3 s³` for `s ∈ [0, 1]`
        /// as `<x, y>` (see [`crate::build::shapes::lathe::segments`]).
        curves: Arc<[[glam::DVec2; 4]]>,
    },
    /// `sor { N, <r, h>… [open] }`: a surface of revolution around y whose
    /// squared radius is a cubic spline over the height.
    Sor {
        /// The points `<r, h>` as written (checked: at least 4, heights rising).
        points: Arc<[glam::DVec2]>,
        /// `open`: no end caps (inside tests still see a solid, as in POV-Ray).
        open: bool,
    },
    /// `mesh { … }` or `mesh2 { … }`: triangles shared by every copy.
    Mesh(Arc<MeshData>),
    /// `text { ttf "FONT" "STRING" THICKNESS, OFFSET }`: glyph outlines in the x-y
    /// plane, baseline on y = 0 from x = 0, extruded from z = 0 to z = THICKNESS;
    /// a solid (the union of its glyphs).
    Text(Arc<TextData>),
    /// `blob { … }`: the surface where the components' summed field equals the
    /// threshold (see [`super::BlobData`]).
    Blob(Arc<super::BlobData>),
    /// `superellipsoid { <E, N> }`: `(|x|^(2/E) + |y|^(2/E))^(E/N) + |z|^(2/N) = 1`,
    /// inside the box from −1 to 1, inside where the left side is below 1.
    Superellipsoid {
        /// The east-west exponent (> 0).
        e: f64,
        /// The north-south exponent (> 0).
        n: f64,
    },
    /// `isosurface { function { … } contained_by { … } … }`.
    Isosurface(Arc<super::Isosurface>),
    /// `julia_fractal { <c> … }`: a slice of a 4D Julia set.
    Julia(Arc<super::Julia>),
    /// `sphere_sweep { SPLINE N, <p>, r … }`.
    SphereSweep(Arc<super::SweepData>),
    /// `merge`, `intersection` or `difference` (a `union` is [`Shape::Union`]).
    Csg {
        /// Which operation.
        op: CsgOp,
        /// The operands, in order.
        children: Members,
    },
}

/// The glyphs of a `text` object.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct TextData {
    /// Each glyph's outline as prism curves (`<x, −y>` in em units, the glyph's
    /// origin at 0; see [`crate::build::shapes::text`]) and where its origin goes
    /// in the x-y plane.
    pub glyphs: Vec<(Arc<[[glam::DVec2; 4]]>, glam::DVec2)>,
    /// The extrusion depth along z (negative: towards −z).
    pub thickness: f64,
}

/// A CSG operation other than `union`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CsgOp {
    /// `merge`: a union without inner surfaces.
    Merge,
    /// `intersection`: the points inside every operand.
    Intersection,
    /// `difference`: the first operand minus all the others.
    Difference,
}

/// The triangles of a `mesh` / `mesh2`, stored compactly (f32 positions, u32
/// indices) and shared through an [`Arc`] by every object that uses them.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct MeshData {
    /// Vertex positions.
    pub positions: Vec<[f32; 3]>,
    /// Vertex normals (may be empty).
    pub normals: Vec<[f32; 3]>,
    /// uv coordinates (may be empty).
    pub uvs: Vec<[f32; 2]>,
    /// Per triangle: position indices.
    pub triangles: Vec<[u32; 3]>,
    /// Per triangle: normal indices, or empty when no triangle is smooth. A
    /// triangle whose entry is `[u32::MAX; 3]` is flat.
    pub normal_indices: Vec<[u32; 3]>,
    /// Per triangle: uv indices, or empty.
    pub uv_indices: Vec<[u32; 3]>,
    /// Textures the triangles refer to.
    pub textures: Vec<Arc<Texture>>,
    /// Per triangle: up to three texture indices (one per vertex, as in `mesh2`'s
    /// `face_indices`; rts uses the first), or empty; `u32::MAX` is "the object's".
    pub texture_indices: Vec<[u32; 3]>,
    /// `inside_vector`: makes the mesh a solid (inside by ray parity).
    pub inside_vector: Option<DVec3>,
    /// The triangles were written as `mesh` / `mesh2` text. rts's flat face
    /// normal is `(b − a) × (c − a)`; POV-Ray's `trace` reports such a face's
    /// as `(c − a) × (b − a)` (measured), so `trace` turns it round. Height
    /// fields and tessellated patches are wound so their normals already
    /// point as POV-Ray's do.
    pub text_winding: bool,
}

impl MeshData {
    /// The three corners of triangle `i`.
    #[inline]
    pub fn corners(&self, i: usize) -> [DVec3; 3] {
        self.triangles[i].map(|k| {
            let p = self.positions[k as usize];
            DVec3::new(p[0] as f64, p[1] as f64, p[2] as f64)
        })
    }
}
