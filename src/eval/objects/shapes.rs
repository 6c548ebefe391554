//! The shapes beyond the first release: `cylinder`, `cone`, `torus`, `disc`,
//! `smooth_triangle`, `polygon`, `polyhedron`, `prism`, and the list blocks that
//! hold their data (`vertex_vectors { … }` and friends).

use crate::build::shapes::solid;
use crate::diag::{codes, Diagnostic};
use crate::eval::core::cursor::{Cursor, Tok};
use crate::eval::core::value::{Array, Value};
use crate::eval::core::{Evaluator, Fail, R};
use crate::scene::{Object, Shape};
use crate::span::Span;
use glam::DVec3;
use std::rc::Rc;

/// One evaluated element of a list block, with where it was written.
pub(crate) type Listed = (Value, Span);

impl Evaluator<'_> {
    /// A list block (`vertex_vectors`, `face_indices`, `texture_list`, `clipped_by`, …):
    /// its values and blocks in order, commas dropped, as a one-dimensional array.
    pub(crate) fn list_block(&mut self, c: &mut Cursor) -> R<Value> {
        if crate::eval::core::list::PACKED_LISTS.contains(&c.block) {
            return self.packed_list(c);
        }
        let mut elems = Vec::new();
        while let Some(t) = c.next() {
            match t {
                Tok::Comma(_) => {}
                Tok::Val(v, _) | Tok::Block(_, v, _) => elems.push(Some(v)),
                // `bounded_by { clipped_by }`: bound by the clipping objects
                // (rts bounds every object itself, so nothing to keep).
                Tok::Kw("clipped_by", _) if c.block == "bounded_by" => {}
                other => {
                    let valid: &[&str] = match c.block {
                        "clipped_by" | "bounded_by" => &["an object"],
                        "texture_list" => &["texture"],
                        _ => &["a count, then values separated by commas"],
                    };
                    self.report(self.unexpected(c, &other, valid));
                }
            }
        }
        Ok(Value::Array(Rc::new(Array {
            dims: vec![elems.len()],
            elems,
        })))
    }

    /// A list block whose numbers and vectors stay packed (`vertex_vectors`,
    /// `face_indices`, …; see `list.rs`), commas dropped.
    fn packed_list(&mut self, c: &mut Cursor) -> R<Value> {
        let mut list = crate::eval::core::list::List::default();
        while let Some(t) = c.next() {
            match t {
                Tok::Comma(_) => {}
                Tok::Data(run) => list.push_packed(run),
                Tok::Val(v, _) | Tok::Block(_, v, _) => list.push(v),
                other => {
                    self.report(self.unexpected(
                        c,
                        &other,
                        &["a count, then values separated by commas"],
                    ));
                }
            }
        }
        Ok(Value::List(Rc::new(list)))
    }

    /// Takes the list block `kw` if it is next: its elements (with the block's span,
    /// as list elements keep no spans of their own) and the block's span.
    pub(crate) fn take_list(&mut self, c: &mut Cursor, kw: &str) -> Option<(Vec<Listed>, Span)> {
        match c.peek() {
            Some(Tok::Block(k, Value::Array(_) | Value::List(_), _)) if *k == kw => {}
            _ => return None,
        }
        match c.next() {
            Some(Tok::Block(_, Value::Array(a), span)) => Some((
                a.elems
                    .iter()
                    .map(|e| (e.clone().unwrap_or(Value::Poison), span))
                    .collect(),
                span,
            )),
            Some(Tok::Block(_, Value::List(l), span)) => Some((l.listed(span), span)),
            _ => None,
        }
    }

    /// Splits POV-Ray's leading count off a list and checks it: `vertex_vectors {
    /// 3, A, B, C }` → `[A, B, C]`. Entries are the non-float elements (floats after
    /// a face are its texture indices). With `optional`, a list without a count is
    /// accepted (for `polyhedron`).
    pub(crate) fn counted<'a>(
        &mut self,
        kw: &str,
        list: &'a [Listed],
        span: Span,
        optional: bool,
    ) -> R<&'a [Listed]> {
        let Some((Value::Float(n), _)) = list.first() else {
            if optional || list.is_empty() {
                return Ok(list);
            }
            return Err(Diagnostic::error(
                codes::MISSING_VALUE,
                span,
                format!("`{kw}` must start with how many entries follow"),
            )
            .with_help(format!("write `{kw} {{ COUNT, … }}`"))
            .into());
        };
        let rest = &list[1..];
        let given = rest
            .iter()
            .filter(|(v, _)| !matches!(v, Value::Float(_)))
            .count();
        if *n < 0.0 || n.fract() != 0.0 || *n as usize != given {
            return Err(Diagnostic::error(
                codes::INVALID_SIZE,
                span,
                format!("`{kw}` says {n} entries but lists {given}"),
            )
            .with_label("count does not match")
            .with_help(format!("make the count {given}, or list {n} entries"))
            .into());
        }
        Ok(rest)
    }

    /// [`Self::counted`] for a packed list: checks its leading count against
    /// its entries (the elements after it that are not numbers); the entries are
    /// then `list.iter().skip(1)`.
    pub(crate) fn counted_list(
        &mut self,
        kw: &str,
        list: &crate::eval::core::list::List,
        span: Span,
    ) -> R<()> {
        let mut it = list.iter();
        let Some(n) = it.next().and_then(|e| e.float()) else {
            if list.len() == 0 {
                return Ok(());
            }
            return Err(Diagnostic::error(
                codes::MISSING_VALUE,
                span,
                format!("`{kw}` must start with how many entries follow"),
            )
            .with_help(format!("write `{kw} {{ COUNT, … }}`"))
            .into());
        };
        let given = it.filter(|e| e.float().is_none()).count();
        if n < 0.0 || n.fract() != 0.0 || n as usize != given {
            return Err(Diagnostic::error(
                codes::INVALID_SIZE,
                span,
                format!("`{kw}` says {n} entries but lists {given}"),
            )
            .with_label("count does not match")
            .with_help(format!("make the count {given}, or list {n} entries"))
            .into());
        }
        Ok(())
    }

    /// The shapes of this file; `None` when `c.block` is not one of them.
    pub(crate) fn new_shape(&mut self, c: &mut Cursor) -> R<Option<Object>> {
        let span = c.span;
        let shape = match c.block {
            "cylinder" => {
                let base = self.take_vec3(c, "the cylinder's base point")?;
                c.comma();
                let cap = self.take_vec3(c, "the cylinder's cap point")?;
                c.comma();
                let (v, s) = c.value("the cylinder's radius")?;
                let radius = self.to_float(&v, s)?;
                if radius <= 0.0 {
                    return Err(self.bad_size(s, "cylinder radius", radius));
                }
                self.check_ends(base, cap, s)?;
                Shape::Cylinder {
                    base,
                    cap,
                    radius,
                    open: false,
                }
            }
            "cone" => {
                let base = self.take_vec3(c, "the cone's base point")?;
                c.comma();
                let (v, s0) = c.value("the cone's base radius")?;
                let base_radius = self.to_float(&v, s0)?;
                c.comma();
                let cap = self.take_vec3(c, "the cone's cap point")?;
                c.comma();
                let (v, s1) = c.value("the cone's cap radius")?;
                let cap_radius = self.to_float(&v, s1)?;
                for (r, s) in [(base_radius, s0), (cap_radius, s1)] {
                    if r < 0.0 {
                        return Err(Diagnostic::error(
                            codes::INVALID_SIZE,
                            s,
                            format!("a cone radius cannot be negative, found {r}"),
                        )
                        .with_help("give a radius of 0 (a point) or more")
                        .into());
                    }
                }
                if base_radius == 0.0 && cap_radius == 0.0 {
                    return Err(self.bad_size(s1, "cone radius at one end", 0.0));
                }
                self.check_ends(base, cap, s1)?;
                Shape::Cone {
                    base,
                    base_radius,
                    cap,
                    cap_radius,
                    open: false,
                }
            }
            "quadric" => {
                let mut k = [0.0; 10];
                let what = [
                    "<A, B, C>: the x², y², z² coefficients",
                    "<D, E, F>: the xy, xz, yz coefficients",
                    "<G, H, I>: the x, y, z coefficients",
                ];
                for (n, w) in what.iter().enumerate() {
                    let v = self.take_vec3(c, w)?;
                    k[3 * n..3 * n + 3].copy_from_slice(&v.to_array());
                    c.comma();
                }
                k[9] = self.take_float(c, "J: the constant term")?;
                Shape::Quadric { coefficients: k }
            }
            "poly" | "cubic" | "quartic" => self.poly(c)?,
            "torus" => {
                let (v, s0) = c.value("the torus's major radius")?;
                let major = self.to_float(&v, s0)?;
                c.comma();
                let (v, s1) = c.value("the torus's minor radius")?;
                let minor = self.to_float(&v, s1)?;
                if major <= 0.0 {
                    return Err(self.bad_size(s0, "major radius", major));
                }
                if minor <= 0.0 {
                    return Err(self.bad_size(s1, "minor radius", minor));
                }
                Shape::Torus { major, minor }
            }
            "disc" => {
                let center = self.take_vec3(c, "the disc's centre")?;
                c.comma();
                let (v, s) = c.value("the disc's normal")?;
                let normal = self.to_vec3(&v, s)?;
                if normal.length_squared() == 0.0 {
                    return Err(Diagnostic::error(
                        codes::INVALID_SIZE,
                        s,
                        "the disc's normal is <0, 0, 0>",
                    )
                    .with_help("give the direction the disc faces, e.g. `y`")
                    .into());
                }
                c.comma();
                let (v, s) = c.value("the disc's radius")?;
                let radius = self.to_float(&v, s)?;
                if radius <= 0.0 {
                    return Err(self.bad_size(s, "disc radius", radius));
                }
                let mut hole = 0.0;
                if matches!(c.peek(), Some(Tok::Comma(_))) {
                    c.comma();
                    let (v, s) = c.value("the disc's hole radius")?;
                    hole = self.to_float(&v, s)?;
                    if hole < 0.0 || hole >= radius {
                        return Err(Diagnostic::error(
                            codes::INVALID_SIZE,
                            s,
                            format!(
                                "the hole radius {hole} must be between 0 and the radius {radius}"
                            ),
                        )
                        .with_help("make the hole smaller than the disc")
                        .into());
                    }
                }
                Shape::Disc {
                    center,
                    normal: normal.normalize(),
                    radius,
                    hole,
                }
            }
            "smooth_triangle" => {
                let mut v = [DVec3::ZERO; 6];
                const WHAT: [&str; 6] = [
                    "the first corner",
                    "the first corner's normal",
                    "the second corner",
                    "the second corner's normal",
                    "the third corner",
                    "the third corner's normal",
                ];
                for (k, slot) in v.iter_mut().enumerate() {
                    if k > 0 {
                        c.comma();
                    }
                    *slot = self.take_vec3(c, WHAT[k])?;
                }
                Shape::SmoothTriangle {
                    vertices: [v[0], v[2], v[4]],
                    normals: [v[1], v[3], v[5]],
                    uv: self.triangle_uv(c)?,
                }
            }
            "polygon" => {
                let (v, s) = c.value("the number of points")?;
                let n = self.to_float(&v, s)?;
                if n < 3.0 || n.fract() != 0.0 {
                    return Err(Diagnostic::error(
                        codes::INVALID_SIZE,
                        s,
                        format!("a polygon needs a whole number of at least 3 points, found {n}"),
                    )
                    .into());
                }
                // Not preallocated from the count: a huge count must end in a
                // diagnostic (no point after the last one), not an allocation failure.
                let mut points = Vec::new();
                for _ in 0..n as usize {
                    c.comma();
                    points.push(self.take_vec3(c, "a polygon point")?);
                }
                Shape::Polygon { points }
            }
            "polyhedron" => self.polyhedron(c)?,
            "prism" => self.prism(c)?,
            "lathe" => self.lathe(c)?,
            "sor" => self.sor(c)?,
            "text" => self.text(c)?,
            "superellipsoid" => self.superellipsoid(c)?,
            "isosurface" => self.isosurface_shape(c)?,
            _ => return Ok(None),
        };
        Ok(Some(Object::new(shape, span)))
    }

    fn check_ends(&self, a: DVec3, b: DVec3, s: Span) -> R<()> {
        if a == b {
            return Err(Diagnostic::error(
                codes::INVALID_SIZE,
                s,
                "the two end points are the same: the shape has no length",
            )
            .with_help("give different base and cap points")
            .into());
        }
        Ok(())
    }

    /// `polyhedron { vertex_vectors { [N,] V… } face_indices { [N,] <I, J, K…>… } }`.
    /// `poly { ORDER, <…> }`, `cubic { <20 numbers> }`, `quartic { <35 numbers> }`.
    fn poly(&mut self, c: &mut Cursor) -> R<Shape> {
        use crate::build::shapes::poly::{term_count, MAX_ORDER};
        let order = match c.block {
            "cubic" => 3,
            "quartic" => 4,
            _ => {
                let (v, s) = c.value("the order, 2 to 4")?;
                let n = self.to_float(&v, s)?;
                c.comma();
                if n.fract() != 0.0 || !(2.0..=7.0).contains(&n) {
                    return Err(Diagnostic::error(
                        codes::OUT_OF_RANGE,
                        s,
                        format!("a poly's order is a whole number from 2 to 7, found {n}"),
                    )
                    .with_help("write the order first: `poly { 4, <…> }`")
                    .into());
                }
                if n as u32 > MAX_ORDER {
                    return Err(Diagnostic::error(
                        codes::UNSUPPORTED,
                        s,
                        format!(
                            "poly of order {n} is not implemented in rts yet (orders 2 to 4 are)"
                        ),
                    )
                    .with_label("not implemented yet")
                    .with_help("see docs/language.md for what this release supports")
                    .into());
                }
                n as u32
            }
        };
        let want = term_count(order);
        let (v, s) = c.value("the coefficients `<…>`")?;
        let coefficients: Vec<f64> = match &v {
            Value::Array(a) if a.dims.len() == 1 => a
                .elems
                .iter()
                .map(|e| match e {
                    Some(Value::Float(f)) => Some(*f),
                    _ => None,
                })
                .collect::<Option<_>>()
                .ok_or_else(|| self.mismatch("numbers", &v, s))?,
            Value::Vector(x) => x.c[..usize::from(x.len)].to_vec(),
            other => return Err(self.mismatch(&format!("{want} coefficients `<…>`"), other, s)),
        };
        if coefficients.len() != want {
            return Err(Diagnostic::error(
                codes::INVALID_SIZE,
                s,
                format!(
                    "a polynomial of order {order} has {want} coefficients, this list has {}",
                    coefficients.len()
                ),
            )
            .with_label("wrong count")
            .with_help("list every term's coefficient, zeros included, in POV-Ray's order (see docs/language.md)")
            .into());
        }
        Ok(Shape::Poly {
            order,
            coefficients,
        })
    }

    /// `prism { [SPLINE] [SWEEP] [sturm] H1, H2, N, <u, v>… }` (`open` and `sturm`
    /// after the points are object modifiers).
    fn prism(&mut self, c: &mut Cursor) -> R<Shape> {
        use crate::build::shapes::prism::{outline, Spline, Tail};
        let mut spline = Spline::Linear;
        let mut conic = false;
        // The spline and sweep keywords seen so far, with where they were written.
        type Seen = Option<(&'static str, Span)>;
        let (mut spline_kw, mut sweep_kw): (Seen, Seen) = (None, None);
        while let Some(Tok::Kw(kw, span)) = c.peek() {
            let (kw, span) = (*kw, *span);
            c.next();
            let (seen, what) = if let Some(s) = Spline::from_keyword(kw) {
                spline = s;
                (&mut spline_kw, "spline type")
            } else if kw == "linear_sweep" || kw == "conic_sweep" {
                conic = kw == "conic_sweep";
                (&mut sweep_kw, "sweep type")
            } else if kw == "sturm" {
                continue;
            } else {
                return Err(self.unknown_keyword(c, kw, span, PRISM_ITEMS));
            };
            if let Some((first, first_span)) = *seen {
                return Err(Diagnostic::error(
                    codes::DUPLICATE_PARAMETER,
                    span,
                    format!("a prism has one {what}, and `{first}` is already given"),
                )
                .with_label(format!("second {what}"))
                .with_secondary(first_span, "first")
                .with_help(format!("keep one of `{first}` and `{kw}`"))
                .into());
            }
            *seen = Some((kw, span));
        }
        let h1 = self.take_float(c, "the prism's first height")?;
        c.comma();
        let h2 = self.take_float(c, "the prism's second height")?;
        c.comma();
        let (v, count_span) = c.value("the number of points")?;
        let n = self.to_float(&v, count_span)?;
        let kw = spline.keyword();
        let min = spline.min_points();
        if n.fract() != 0.0 || n < min as f64 {
            return Err(Diagnostic::error(
                codes::INVALID_SIZE,
                count_span,
                format!("a `{kw}` prism needs a whole number of at least {min} points, found {n}"),
            )
            .with_label("too few points")
            .with_help(spline.closing_rule())
            .into());
        }
        if spline == Spline::Bezier && !(n as usize).is_multiple_of(4) {
            return Err(Diagnostic::error(
                codes::INVALID_SIZE,
                count_span,
                format!("a `bezier_spline` prism has 4 points per segment, and {n} is not a multiple of 4"),
            )
            .with_label("not a multiple of 4")
            .with_help(spline.closing_rule())
            .into());
        }
        let listed = self.points_2d(
            c,
            n,
            count_span,
            "prism",
            "write `<x, z>`: the outline lies in the x-z plane and y is swept",
        )?;
        let last = listed.last().map_or(count_span, |p| p.1);
        let points: Vec<glam::DVec2> = listed.iter().map(|p| p.0).collect();
        let (curves, tail) = outline(spline, &points);
        let head = c.span.head();
        match tail {
            Tail::Closed => {}
            Tail::ClosedForYou => self.warn(
                Diagnostic::warning(
                    codes::INVALID_SIZE,
                    last,
                    "this prism's last outline does not close: it is closed with a line back to its first point",
                )
                .with_help("repeat the outline's first point at its end (POV-Ray closes it the same way)"),
            ),
            Tail::Ignored(i) | Tail::Unclosed(i) if !curves.is_empty() || i > 0 => {
                let d = if matches!(tail, Tail::Unclosed(_)) {
                    Diagnostic::error
                } else {
                    Diagnostic::warning
                };
                let msg = if i + 1 == points.len() {
                    format!("point {} of this `{kw}` prism closes no sub-shape", i + 1)
                } else {
                    format!(
                        "points {} to {} of this `{kw}` prism close no sub-shape",
                        i + 1,
                        points.len()
                    )
                };
                let diag = d(codes::INVALID_SIZE, last, msg)
                    .with_label("the outline is still open here");
                if matches!(tail, Tail::Unclosed(_)) {
                    return Err(diag.with_help(spline.closing_rule()).into());
                }
                self.warn(diag.with_help(format!(
                    "rts ignores them, as POV-Ray does; {}",
                    spline.closing_rule()
                )));
            }
            Tail::Ignored(_) | Tail::Unclosed(_) => {}
        }
        if curves.is_empty() {
            return Err(Diagnostic::error(
                codes::INVALID_SIZE,
                head,
                format!("this `{kw}` prism has no closed sub-shape"),
            )
            .with_help(spline.closing_rule())
            .into());
        }
        if h1 == h2 {
            self.warn(
                Diagnostic::warning(
                    codes::INVALID_SIZE,
                    head,
                    format!("this prism is flat: both heights are {h1}"),
                )
                .with_help("give two different heights"),
            );
        }
        Ok(Shape::Prism {
            curves: curves.into(),
            heights: [h1, h2],
            conic,
            open: false,
        })
    }

    fn polyhedron(&mut self, c: &mut Cursor) -> R<Shape> {
        let head = c.span.head();
        let missing = |what: &str, ex: &str| -> Fail {
            Diagnostic::error(
                codes::MISSING_VALUE,
                head,
                format!("`polyhedron` needs `{what}`"),
            )
            .with_help(format!("write e.g. `polyhedron {{ {ex} }}`"))
            .into()
        };
        let (vl, vspan) = self.take_list(c, "vertex_vectors").ok_or_else(|| {
            missing(
                "vertex_vectors { … }",
                "vertex_vectors { <0,0,0>, <1,0,0>, <0,1,0>, <0,0,1> } face_indices { … }",
            )
        })?;
        let (fl, fspan) = self.take_list(c, "face_indices").ok_or_else(|| {
            missing(
                "face_indices { … } after vertex_vectors",
                "vertex_vectors { … } face_indices { <0,1,2>, <0,1,3>, <0,2,3>, <1,2,3> }",
            )
        })?;
        let vl = self.counted("vertex_vectors", &vl, vspan, true)?;
        let mut verts = Vec::with_capacity(vl.len());
        for (v, s) in vl {
            verts.push(self.to_vec3(v, *s)?);
        }
        let fl = self.counted("face_indices", &fl, fspan, true)?;
        let mut faces = Vec::with_capacity(fl.len());
        for (v, s) in fl {
            let Value::Vector(x) = v else {
                return Err(self.mismatch("a face: a vector of 3 to 5 vertex indices", v, *s));
            };
            let mut f = Vec::new();
            for &i in x.as_slice() {
                if i < 0.0 || i.fract() != 0.0 || i as usize >= verts.len() {
                    return Err(Diagnostic::error(
                        codes::INDEX_OUT_OF_RANGE,
                        *s,
                        format!(
                            "face index {i} does not name one of the {} vertices",
                            verts.len()
                        ),
                    )
                    .with_help("vertex indices count from 0")
                    .into());
                }
                f.push(i as usize);
            }
            if f.len() < 3 {
                return Err(self.mismatch("a face of at least 3 vertex indices", v, *s));
            }
            faces.push(f);
        }
        if faces.len() < 4 {
            return Err(Diagnostic::error(
                codes::INVALID_SIZE,
                fspan,
                format!("a polyhedron needs at least 4 faces, found {}", faces.len()),
            )
            .into());
        }
        if let Some(edge) = open_edge(&faces) {
            return Err(Diagnostic::error(
                codes::INVALID_SIZE,
                fspan,
                format!(
                    "the faces do not close: the edge from vertex {} to {} belongs to one face only",
                    edge.0, edge.1
                ),
            )
            .with_help("list every face of the solid (each edge is shared by two faces)")
            .into());
        }
        let planes = solid::planes(&verts, &faces).map_err(|m| {
            Fail::from(
                Diagnostic::error(codes::INVALID_SIZE, fspan, m)
                    .with_help("a polyhedron must be convex, with flat faces"),
            )
        })?;
        Ok(Shape::Polyhedron { planes })
    }
}

/// The keywords a `prism` takes before its heights.
pub(crate) const PRISM_ITEMS: &[&str] = &[
    "linear_spline",
    "quadratic_spline",
    "cubic_spline",
    "bezier_spline",
    "linear_sweep",
    "conic_sweep",
    "sturm",
];

/// An edge used by only one face, if any (faces of a closed solid share edges).
fn open_edge(faces: &[Vec<usize>]) -> Option<(usize, usize)> {
    let mut count: std::collections::BTreeMap<(usize, usize), u32> = Default::default();
    for f in faces {
        for k in 0..f.len() {
            let (a, b) = (f[k], f[(k + 1) % f.len()]);
            *count.entry((a.min(b), a.max(b))).or_default() += 1;
        }
    }
    count.into_iter().find(|&(_, n)| n < 2).map(|(e, _)| e)
}
