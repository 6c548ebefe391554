//! `mesh { triangle { … } smooth_triangle { … } … }` and `mesh2 { vertex_vectors
//! … face_indices … }`: triangles stored once ([`MeshData`], f32 positions, u32
//! indices) and shared by every object made from the declared mesh.

use super::shapes::Listed;
use crate::diag::{codes, Diagnostic};
use crate::eval::core::cursor::{Cursor, Tok};
use crate::eval::core::list::{Elem, List};
use crate::eval::core::value::Value;
use crate::eval::core::{Evaluator, R};
use crate::scene::{MeshData, Object, Shape, Texture};
use crate::span::Span;
use glam::{DVec2, DVec3};
use rustc_hash::FxHashMap;
use std::rc::Rc;
use std::sync::Arc;

fn f32x3(v: DVec3) -> [f32; 3] {
    [v.x as f32, v.y as f32, v.z as f32]
}

/// Collects `mesh` triangles, sharing equal vertices, normals and textures.
#[derive(Default)]
struct MeshBuilder {
    data: MeshData,
    positions: FxHashMap<[u32; 3], u32>,
    normals: FxHashMap<[u32; 3], u32>,
    uvs: FxHashMap<[u32; 3], u32>,
    textures: FxHashMap<*const Texture, u32>,
}

impl MeshBuilder {
    fn index(map: &mut FxHashMap<[u32; 3], u32>, list: &mut Vec<[f32; 3]>, v: DVec3) -> u32 {
        let p = f32x3(v);
        *map.entry(p.map(f32::to_bits)).or_insert_with(|| {
            list.push(p);
            list.len() as u32 - 1
        })
    }

    fn push(
        &mut self,
        v: [DVec3; 3],
        n: Option<[DVec3; 3]>,
        tex: Option<&Arc<Texture>>,
        uv: Option<[DVec2; 3]>,
    ) {
        let d = &mut self.data;
        let tri = v.map(|p| MeshBuilder::index(&mut self.positions, &mut d.positions, p));
        d.triangles.push(tri);
        if let Some(uv) = uv {
            // Triangles before the first with uv_vectors get <0, 0> corners.
            if d.uvs.is_empty() {
                d.uvs.push([0.0; 2]);
            }
            d.uv_indices.resize(d.triangles.len() - 1, [0; 3]);
            let k = uv.map(|p| {
                let key = [p.x as f32, p.y as f32];
                let bits = [key[0].to_bits(), key[1].to_bits(), 0];
                *self.uvs.entry(bits).or_insert_with(|| {
                    d.uvs.push(key);
                    d.uvs.len() as u32 - 1
                })
            });
            d.uv_indices.push(k);
        } else if !d.uv_indices.is_empty() {
            d.uv_indices.push([0; 3]);
        }
        if let Some(n) = n {
            if d.normal_indices.len() + 1 < d.triangles.len() {
                d.normal_indices
                    .resize(d.triangles.len() - 1, [u32::MAX; 3]);
            }
            let ni = n.map(|m| {
                MeshBuilder::index(&mut self.normals, &mut d.normals, m.normalize_or_zero())
            });
            d.normal_indices.push(ni);
        } else if !d.normal_indices.is_empty() {
            d.normal_indices.push([u32::MAX; 3]);
        }
        if let Some(t) = tex {
            let k = *self.textures.entry(Arc::as_ptr(t)).or_insert_with(|| {
                d.textures.push(t.clone());
                d.textures.len() as u32 - 1
            });
            d.texture_indices
                .resize(d.triangles.len() - 1, [u32::MAX; 3]);
            d.texture_indices.push([k; 3]);
        } else if !d.texture_indices.is_empty() {
            d.texture_indices.push([u32::MAX; 3]);
        }
    }
}

impl Evaluator<'_> {
    /// `mesh { TRIANGLE… [inside_vector V] }` (modifiers follow, read by the caller).
    /// Also `mesh { MESH_IDENT … }`: a declared mesh used again, with its own
    /// texture and transforms, before the modifiers that follow.
    pub(crate) fn mesh(&mut self, c: &mut Cursor) -> R<Object> {
        if let Some(Tok::Val(Value::Object(o), _)) = c.peek() {
            if matches!(o.shape, Shape::Mesh(_)) {
                let Some(Tok::Val(Value::Object(o), _)) = c.next() else {
                    unreachable!()
                };
                let mut o = Arc::try_unwrap(o).unwrap_or_else(|a| (*a).clone());
                o.span = c.span;
                return Ok(o);
            }
        }
        let mut b = MeshBuilder::default();
        loop {
            match c.peek() {
                Some(Tok::Kw(kw @ ("obj_file" | "ply_file"), _)) => {
                    let kw = *kw;
                    c.next();
                    if !b.data.triangles.is_empty() {
                        return Err(Diagnostic::error(
                            codes::UNEXPECTED_ITEM,
                            c.last,
                            format!("`{kw}` must be the only content of its mesh"),
                        )
                        .with_help("put the file's mesh and the other triangles in separate meshes")
                        .into());
                    }
                    // Read once per file (and kept from frame to frame).
                    let data = if kw == "obj_file" {
                        self.obj_mesh(c)?
                    } else {
                        self.ply_mesh(c)?
                    };
                    if let Some(Tok::Kw("inside_vector", _)) = c.peek() {
                        c.next();
                        let mut d = (*data).clone();
                        d.inside_vector = Some(self.inside_vector(c)?);
                        let d = self.mesh_cache.intern(d);
                        return Ok(Object::new(Shape::Mesh(d), c.span));
                    }
                    return Ok(Object::new(Shape::Mesh(data), c.span));
                }
                Some(Tok::Block("triangle" | "smooth_triangle", _, _)) => {
                    let Some(Tok::Block(_, v, s)) = c.next() else {
                        unreachable!()
                    };
                    let Value::Object(o) = v else {
                        continue; // an erroneous triangle, already reported
                    };
                    let place = |p: DVec3| o.transform.as_deref().map_or(p, |t| t.point(p));
                    match &o.shape {
                        Shape::Triangle { vertices, uv } => {
                            b.push(vertices.map(place), None, o.texture.as_ref(), *uv)
                        }
                        Shape::SmoothTriangle {
                            vertices,
                            normals,
                            uv,
                        } => {
                            let n =
                                normals.map(|n| o.transform.as_deref().map_or(n, |t| t.normal(n)));
                            b.push(vertices.map(place), Some(n), o.texture.as_ref(), *uv)
                        }
                        _ => {
                            return Err(Diagnostic::error(
                                codes::UNEXPECTED_ITEM,
                                s,
                                "a mesh holds triangles and smooth_triangles only",
                            )
                            .into())
                        }
                    }
                }
                Some(Tok::Kw("inside_vector", _)) => {
                    c.next();
                    b.data.inside_vector = Some(self.inside_vector(c)?);
                }
                _ => break,
            }
        }
        if b.data.triangles.is_empty() {
            return Err(Diagnostic::error(
                codes::MISSING_VALUE,
                c.span,
                "this mesh has no triangles",
            )
            .with_help("put triangles in the mesh: `mesh { triangle { A, B, C } … }`")
            .into());
        }
        let mut data = b.data;
        if !data.normal_indices.is_empty() {
            data.normal_indices
                .resize(data.triangles.len(), [u32::MAX; 3]);
        }
        if !data.texture_indices.is_empty() {
            data.texture_indices
                .resize(data.triangles.len(), [u32::MAX; 3]);
        }
        if !data.uv_indices.is_empty() {
            data.uv_indices.resize(data.triangles.len(), [0; 3]);
        }
        Ok(Object::new(
            Shape::Mesh(self.mesh_cache.intern(MeshData {
                text_winding: true,
                ..data
            })),
            c.span,
        ))
    }

    /// `[uv_vectors UV1, UV2, UV3]` after a triangle's corners: the corners' uv
    /// coordinates (2D vectors; a longer vector's first two components).
    pub(crate) fn triangle_uv(&mut self, c: &mut Cursor) -> R<Option<[DVec2; 3]>> {
        let Some(Tok::Kw("uv_vectors", _)) = c.peek() else {
            return Ok(None);
        };
        c.next();
        let mut uv = [DVec2::ZERO; 3];
        for (k, slot) in uv.iter_mut().enumerate() {
            if k > 0 {
                c.comma();
            }
            let p = self.take_vec3(
                c,
                "a corner's uv coordinates (3 in all: `uv_vectors <u, v>, <u, v>, <u, v>`)",
            )?;
            *slot = DVec2::new(p.x, p.y);
        }
        Ok(Some(uv))
    }

    fn inside_vector(&mut self, c: &mut Cursor) -> R<DVec3> {
        let (v, s) = c.value("the inside vector")?;
        let d = self.to_vec3(&v, s)?;
        if d.length_squared() == 0.0 {
            return Err(Diagnostic::error(
                codes::INVALID_SIZE,
                s,
                "the inside vector is <0, 0, 0>",
            )
            .with_help("give any direction, e.g. `inside_vector y`")
            .into());
        }
        Ok(d)
    }

    /// `mesh2 { vertex_vectors … normal_vectors … uv_vectors … texture_list …
    /// face_indices … normal_indices … uv_indices … [inside_vector V] }`. The
    /// lists are read straight from their packed numbers (see `list.rs`).
    pub(crate) fn mesh2(&mut self, c: &mut Cursor) -> R<Object> {
        const LISTS: [&str; 7] = [
            "vertex_vectors",
            "normal_vectors",
            "uv_vectors",
            "texture_list",
            "face_indices",
            "normal_indices",
            "uv_indices",
        ];
        let mut lists: [Option<(Rc<List>, Span)>; 7] = Default::default();
        let mut data = MeshData::default();
        loop {
            let kw = match c.peek() {
                Some(Tok::Block(k, _, _)) if LISTS.contains(k) => *k,
                Some(Tok::Kw("inside_vector", _)) => {
                    c.next();
                    data.inside_vector = Some(self.inside_vector(c)?);
                    continue;
                }
                _ => break,
            };
            let k = LISTS.iter().position(|l| *l == kw).unwrap_or(0);
            let l = match c.next() {
                Some(Tok::Block(_, Value::List(l), span)) => (l, span),
                Some(Tok::Block(_, Value::Array(a), span)) => {
                    let mut l = List::default();
                    for e in &a.elems {
                        l.push(e.clone().unwrap_or(Value::Poison));
                    }
                    (Rc::new(l), span)
                }
                _ => continue, // an erroneous list, already reported
            };
            if lists[k].is_some() {
                return Err(Diagnostic::error(
                    codes::DUPLICATE_PARAMETER,
                    l.1,
                    format!("`{kw}` is given twice in this `mesh2`"),
                )
                .into());
            }
            lists[k] = Some(l);
        }
        let need = |k: usize, lists: &[Option<(Rc<List>, Span)>; 7]| -> R<()> {
            if lists[k].is_none() {
                return Err(Diagnostic::error(
                    codes::MISSING_VALUE,
                    c.span.head(),
                    format!("`mesh2` needs `{} {{ … }}`", LISTS[k]),
                )
                .with_help("a mesh2 needs at least vertex_vectors and face_indices")
                .into());
            }
            Ok(())
        };
        need(0, &lists)?;
        need(4, &lists)?;
        let vec3s = |ev: &mut Self, k: usize| -> R<Vec<[f32; 3]>> {
            let Some((l, s)) = &lists[k] else {
                return Ok(Vec::new());
            };
            ev.counted_list(LISTS[k], l, *s)?;
            let mut out = Vec::with_capacity(l.len().saturating_sub(1));
            for e in l.iter().skip(1) {
                out.push(match e {
                    Elem::Numbers(&[x, y, z]) => [x as f32, y as f32, z as f32],
                    e => f32x3(ev.to_vec3(&e.value(), *s)?),
                });
            }
            Ok(out)
        };
        data.positions = vec3s(self, 0)?;
        // Normals are unit length before interpolation, as in POV-Ray.
        data.normals = vec3s(self, 1)?
            .into_iter()
            .map(|n| {
                let v = glam::Vec3::from(n).normalize_or_zero();
                [v.x, v.y, v.z]
            })
            .collect();
        if let Some((l, s)) = &lists[2] {
            self.counted_list(LISTS[2], l, *s)?;
            for e in l.iter().skip(1) {
                match e {
                    Elem::Numbers(&[u, v]) => data.uvs.push([u as f32, v as f32]),
                    Elem::Value(Value::Vector(x)) if x.len == 2 => {
                        data.uvs.push([x.c[0] as f32, x.c[1] as f32])
                    }
                    e => return Err(self.mismatch("a uv vector <u, v>", &e.value(), *s)),
                }
            }
        }
        if let Some((l, s)) = &lists[3] {
            self.counted_list(LISTS[3], l, *s)?;
            for e in l.iter().skip(1) {
                match e {
                    Elem::Value(Value::Texture(t)) => data.textures.push(t.clone()),
                    e => return Err(self.mismatch("a texture { … }", &e.value(), *s)),
                }
            }
        }
        // face_indices: <a, b, c> [, t | , t0, t1, t2].
        let (l, s) = lists[4].as_ref().expect("checked above");
        self.counted_list(LISTS[4], l, *s)?;
        data.triangles.reserve(l.len());
        let mut entries = l.iter().skip(1).peekable();
        while let Some(e) = entries.next() {
            let tri = self.face(e, *s, data.positions.len(), "vertex_vectors")?;
            data.triangles.push(tri);
            let mut tex = Vec::new();
            while let Some(f) = entries.peek().and_then(Elem::float) {
                if f < 0.0 || f.fract() != 0.0 || f as usize >= data.textures.len() {
                    return Err(out_of_range(*s, f, data.textures.len(), "texture_list"));
                }
                tex.push(f as u32);
                entries.next();
            }
            if !tex.is_empty() {
                data.texture_indices
                    .resize(data.triangles.len() - 1, [u32::MAX; 3]);
                data.texture_indices
                    .push([tex[0], tex[tex.len().min(2) - 1], tex[tex.len() - 1]]);
            }
        }
        if !data.texture_indices.is_empty() {
            data.texture_indices
                .resize(data.triangles.len(), [u32::MAX; 3]);
        }
        // normal_indices / uv_indices default to face_indices, as in POV-Ray.
        for (k, count, target) in [(5, data.normals.len(), 0usize), (6, data.uvs.len(), 1usize)] {
            if count == 0 {
                continue;
            }
            let idx = match &lists[k] {
                Some((l, s)) => {
                    self.counted_list(LISTS[k], l, *s)?;
                    let n = l.len() - 1;
                    if n != data.triangles.len() {
                        return Err(Diagnostic::error(
                            codes::INVALID_SIZE,
                            *s,
                            format!(
                                "`{}` lists {} faces but face_indices lists {}",
                                LISTS[k],
                                n,
                                data.triangles.len()
                            ),
                        )
                        .into());
                    }
                    let name = if target == 0 {
                        "normal_vectors"
                    } else {
                        "uv_vectors"
                    };
                    l.iter()
                        .skip(1)
                        .map(|e| self.face(e, *s, count, name))
                        .collect::<R<Vec<_>>>()?
                }
                None => {
                    if let Some(bad) = data
                        .triangles
                        .iter()
                        .flatten()
                        .find(|&&i| i as usize >= count)
                    {
                        let (_, s) = lists[4].as_ref().expect("checked above");
                        return Err(out_of_range(*s, *bad as f64, count, LISTS[1 + target]));
                    }
                    data.triangles.clone()
                }
            };
            if target == 0 {
                data.normal_indices = idx;
            } else {
                data.uv_indices = idx;
            }
        }
        if data.triangles.is_empty() {
            return Err(
                Diagnostic::error(codes::MISSING_VALUE, c.span, "this mesh2 has no faces").into(),
            );
        }
        Ok(Object::new(
            Shape::Mesh(self.mesh_cache.intern(MeshData {
                text_winding: true,
                ..data
            })),
            c.span,
        ))
    }

    /// A face `<a, b, c>` of indices below `count` into the list `of`.
    fn face(&self, e: Elem, s: Span, count: usize, of: &str) -> R<[u32; 3]> {
        match e {
            Elem::Numbers(v @ &[_, _, _]) => {
                let mut out = [0u32; 3];
                for (o, &i) in out.iter_mut().zip(v) {
                    if i < 0.0 || i.fract() != 0.0 || i as usize >= count {
                        return Err(out_of_range(s, i, count, of));
                    }
                    *o = i as u32;
                }
                Ok(out)
            }
            e => self.indices(&(e.value(), s), count, of),
        }
    }

    fn indices(&self, (v, s): &Listed, count: usize, of: &str) -> R<[u32; 3]> {
        let Value::Vector(x) = v else {
            return Err(self.mismatch("a face <a, b, c> of vertex indices", v, *s));
        };
        if x.len != 3 {
            return Err(self.mismatch("a face <a, b, c> of three indices", v, *s));
        }
        let mut out = [0u32; 3];
        for (o, &i) in out.iter_mut().zip(x.as_slice()) {
            if i < 0.0 || i.fract() != 0.0 || i as usize >= count {
                return Err(out_of_range(*s, i, count, of));
            }
            *o = i as u32;
        }
        Ok(out)
    }
}

fn out_of_range(s: Span, i: f64, count: usize, of: &str) -> crate::eval::core::Fail {
    Diagnostic::error(
        codes::INDEX_OUT_OF_RANGE,
        s,
        format!("index {i} is out of range: `{of}` has {count} entries"),
    )
    .with_help("indices count from 0")
    .into()
}
