//! Geometry read from files: `mesh { obj_file "x.obj" }`, `mesh { ply_file
//! "x.ply" }` and `height_field { png "x.png" [smooth] [water_level W] }`.
//! Files are found like include files (the scene's folder, then `-I` folders)
//! and must lie inside the read sandbox.

use crate::diag::{codes, Diagnostic};
use crate::eval::core::cursor::Cursor;
use crate::eval::core::{Evaluator, R};
use crate::scene::{MeshData, Object, Shape};
use crate::span::Span;
use std::sync::Arc;

impl Evaluator<'_> {
    /// The file name string after `obj_file`, `ply_file` or `png`.
    fn file_name(&mut self, c: &mut Cursor, what: &str) -> R<(String, Span)> {
        let (v, s) = c.value(what)?;
        match v {
            crate::eval::core::value::Value::Str(t) => Ok((t.to_string(), s)),
            other => Err(self.mismatch("a file name in quotes", &other, s)),
        }
    }

    /// `obj_file "NAME"` inside a mesh: the triangles of a Wavefront OBJ file (all
    /// its objects; polygons are triangulated; normals and uvs kept; materials
    /// ignored).
    pub(crate) fn obj_mesh(&mut self, c: &mut Cursor) -> R<Arc<MeshData>> {
        let (name, span) = self.file_name(c, "the OBJ file's name")?;
        let path = self.data_file(&name, span, "OBJ file")?;
        if let Some(m) = self.mesh_cache.file(&path) {
            return Ok(m);
        }
        let bad = |e: String| -> crate::eval::core::Fail {
            Diagnostic::error(
                codes::FILE_NOT_FOUND,
                span,
                format!("cannot read `{name}` as OBJ: {e}"),
            )
            .with_help("give a Wavefront .obj file with `v` and `f` lines")
            .into()
        };
        let file = crate::files::open_regular(&path).map_err(|e| bad(e.to_string()))?;
        let opts = tobj::LoadOptions {
            triangulate: true,
            single_index: false,
            ignore_points: true,
            ignore_lines: true,
        };
        let (models, _) = tobj::load_obj_buf(&mut std::io::BufReader::new(file), &opts, |_| {
            Err(tobj::LoadError::OpenFileFailed)
        })
        .map_err(|e| bad(e.to_string()))?;
        let mut m = MeshData::default();
        for model in &models {
            let mm = &model.mesh;
            let (pbase, nbase, tbase) = (
                m.positions.len() as u32,
                m.normals.len() as u32,
                m.uvs.len() as u32,
            );
            m.positions
                .extend(mm.positions.chunks_exact(3).map(|p| [p[0], p[1], p[2]]));
            m.normals
                .extend(mm.normals.chunks_exact(3).map(|p| [p[0], p[1], p[2]]));
            m.uvs
                .extend(mm.texcoords.chunks_exact(2).map(|p| [p[0], p[1]]));
            let tri = |ix: &[u32], base: u32| -> Vec<[u32; 3]> {
                ix.chunks_exact(3)
                    .map(|t| [t[0] + base, t[1] + base, t[2] + base])
                    .collect()
            };
            let faces = tri(&mm.indices, pbase);
            let nfaces = faces.len();
            m.triangles.extend(faces);
            if mm.normal_indices.len() == mm.indices.len() && !mm.normals.is_empty() {
                m.normal_indices
                    .resize(m.triangles.len() - nfaces, [u32::MAX; 3]);
                m.normal_indices.extend(tri(&mm.normal_indices, nbase));
            }
            if mm.texcoord_indices.len() == mm.indices.len() && !mm.texcoords.is_empty() {
                m.uv_indices.resize(m.triangles.len() - nfaces, [0; 3]);
                m.uv_indices.extend(tri(&mm.texcoord_indices, tbase));
            }
        }
        if !m.normal_indices.is_empty() {
            m.normal_indices.resize(m.triangles.len(), [u32::MAX; 3]);
        }
        normalize(&mut m.normals);
        if !m.uv_indices.is_empty() && m.uv_indices.len() != m.triangles.len() {
            m.uv_indices.clear();
        }
        check_indices(&m).map_err(bad)?;
        if m.triangles.is_empty() {
            return Err(bad("the file has no faces".into()));
        }
        Ok(self.mesh_cache.store_file(&path, m))
    }

    /// `ply_file "NAME"` inside a mesh: the `vertex` (x, y, z [, nx, ny, nz]) and
    /// `face` (vertex_indices or vertex_index lists, fanned into triangles)
    /// elements of a PLY file, ASCII or binary.
    pub(crate) fn ply_mesh(&mut self, c: &mut Cursor) -> R<Arc<MeshData>> {
        use ply_rs_bw::parser::Parser;
        use ply_rs_bw::ply::DefaultElement;
        let (name, span) = self.file_name(c, "the PLY file's name")?;
        let path = self.data_file(&name, span, "PLY file")?;
        if let Some(m) = self.mesh_cache.file(&path) {
            return Ok(m);
        }
        let bad = |e: String| -> crate::eval::core::Fail {
            Diagnostic::error(
                codes::FILE_NOT_FOUND,
                span,
                format!("cannot read `{name}` as PLY: {e}"),
            )
            .with_help("give a .ply file with `vertex` and `face` elements")
            .into()
        };
        let file = crate::files::open_regular(&path).map_err(|e| bad(e.to_string()))?;
        let ply = Parser::<DefaultElement>::new()
            .read_ply(&mut std::io::BufReader::new(file))
            .map_err(|e| bad(e.to_string()))?;
        let mut m = MeshData::default();
        let verts = ply
            .payload
            .get("vertex")
            .ok_or_else(|| bad("no `vertex` element".into()))?;
        let mut has_normals = true;
        for v in verts {
            let get = |k: &str| v.get(k).and_then(|p| p.to_f32_lossy());
            let (Some(x), Some(y), Some(z)) = (get("x"), get("y"), get("z")) else {
                return Err(bad("a vertex lacks x, y or z".into()));
            };
            m.positions.push([x, y, z]);
            match (get("nx"), get("ny"), get("nz")) {
                (Some(a), Some(b), Some(cc)) => m.normals.push([a, b, cc]),
                _ => has_normals = false,
            }
        }
        let faces = ply
            .payload
            .get("face")
            .ok_or_else(|| bad("no `face` element".into()))?;
        for f in faces {
            let list = f
                .get("vertex_indices")
                .or_else(|| f.get("vertex_index"))
                .and_then(|p| p.to_u32_list())
                .ok_or_else(|| bad("a face lacks vertex_indices".into()))?;
            for k in 1..list.len().saturating_sub(1) {
                m.triangles.push([list[0], list[k], list[k + 1]]);
            }
        }
        if has_normals && m.normals.len() == m.positions.len() {
            normalize(&mut m.normals);
            m.normal_indices = m.triangles.clone();
        } else {
            m.normals.clear();
        }
        check_indices(&m).map_err(bad)?;
        if m.triangles.is_empty() {
            return Err(bad("the file has no faces".into()));
        }
        Ok(self.mesh_cache.store_file(&path, m))
    }

    /// `height_field { png "NAME" [smooth] [water_level W] … }`: the image's grey
    /// levels as heights over the unit square (x and z in [0, 1], y in [0, 1)),
    /// two triangles per cell, as POV-Ray does; solid below the surface.
    pub(crate) fn height_field(&mut self, c: &mut Cursor) -> R<Object> {
        let span = c.span;
        let (grid, w, h) = if let Some(crate::eval::core::cursor::Tok::Val(
            crate::eval::core::value::Value::Float(_),
            _,
        )) = c.peek()
        {
            self.height_field_function(c)?
        } else {
            self.height_field_image(c)?
        };
        self.height_field_mesh(c, span, &grid, w, h)
    }

    /// The heights of `png "NAME"` or `"NAME"`: grey levels, rows top first.
    fn height_field_image(&mut self, c: &mut Cursor) -> R<(Vec<f32>, usize, usize)> {
        let span = c.span;
        match c.peek() {
            Some(crate::eval::core::cursor::Tok::Kw("png", _)) => {
                c.next();
            }
            // POV-Ray 3.7 also takes the file alone and reads its type from
            // its extension.
            Some(crate::eval::core::cursor::Tok::Val(
                crate::eval::core::value::Value::Str(_),
                _,
            )) => {}
            _ => {
                let other = c.next();
                let s = other.as_ref().map_or(span, |t| t.span());
                return Err(Diagnostic::error(
                    codes::MISSING_VALUE,
                    s,
                    "`height_field` needs the image type and file: `png \"name.png\"`",
                )
                .with_help("rts reads PNG height fields: `height_field { png \"hf.png\" }`")
                .into());
            }
        }
        let (name, fspan) = self.file_name(c, "the PNG file's name")?;
        let path = self.data_file(&name, fspan, "height map")?;
        let picture = self.picture(&path, &name, fspan).map_err(|e| match e {
            crate::eval::core::images::ImageFail::Fail(f) => f,
            crate::eval::core::images::ImageFail::Read(e) => crate::eval::core::Fail::from(
                Diagnostic::error(
                    codes::FILE_NOT_FOUND,
                    fspan,
                    format!("cannot read `{name}` as PNG: {e}"),
                )
                .with_help("give a PNG image"),
            ),
        })?;
        // The grey levels as the image decoder converts colours (a temporary
        // 16-bit copy; the mesh made from it is larger still).
        let img = crate::eval::core::images::to_dynamic(&picture);
        drop(picture);
        let grey = img.to_luma16();
        let (w, h) = (grey.width() as usize, grey.height() as usize);
        if w < 2 || h < 2 {
            return Err(Diagnostic::error(
                codes::INVALID_SIZE,
                fspan,
                format!("a height field needs an image of at least 2×2 pixels, found {w}×{h}"),
            )
            .into());
        }
        let mut grid = Vec::with_capacity(w * h);
        for j in 0..h {
            for i in 0..w {
                grid.push(grey.get_pixel(i as u32, j as u32)[0] as f32 / 65536.0);
            }
        }
        Ok((grid, w, h))
    }

    /// The triangles of a height field of `w × h` heights (rows top first) and
    /// its `smooth` and `water_level` items.
    fn height_field_mesh(
        &mut self,
        c: &mut Cursor,
        span: crate::span::Span,
        grid: &[f32],
        w: usize,
        h: usize,
    ) -> R<Object> {
        let mut smooth = false;
        let mut water = 0.0f64;
        loop {
            match c.peek() {
                Some(crate::eval::core::cursor::Tok::Kw("smooth", _)) => {
                    c.next();
                    smooth = true;
                }
                Some(crate::eval::core::cursor::Tok::Kw("water_level", _)) => {
                    c.next();
                    water = self.take_float(c, "the water level (0 to 1)")?;
                }
                _ => break,
            }
        }
        // POV-Ray: column i → x = i / (w - 1); row j (top first) → z = 1 - j / (h - 1).
        let height = |i: usize, j: usize| grid[j * w + i];
        let mut m = MeshData::default();
        for j in 0..h {
            for i in 0..w {
                m.positions.push([
                    i as f32 / (w - 1) as f32,
                    height(i, j),
                    1.0 - j as f32 / (h - 1) as f32,
                ]);
            }
        }
        let at = |i: usize, j: usize| (j * w + i) as u32;
        for j in 0..h - 1 {
            for i in 0..w - 1 {
                let q = [at(i, j), at(i + 1, j), at(i, j + 1), at(i + 1, j + 1)];
                if q.iter()
                    .all(|&k| (m.positions[k as usize][1] as f64) < water)
                {
                    continue;
                }
                // Split along the diagonal from (x, z + dz) to (x + dx, z), as
                // POV-Ray does (checked against its pictures); wound so the
                // faces' normals point up, as POV-Ray's `trace` and `slope`
                // see them.
                m.triangles.push([q[0], q[3], q[2]]);
                m.triangles.push([q[0], q[1], q[3]]);
            }
        }
        if smooth {
            // Normals from central differences of the height grid.
            let (dx, dz) = (1.0 / (w - 1) as f32, 1.0 / (h - 1) as f32);
            for j in 0..h {
                for i in 0..w {
                    let hx = height((i + 1).min(w - 1), j) - height(i.saturating_sub(1), j);
                    let hz = height(i, j.saturating_sub(1)) - height(i, (j + 1).min(h - 1));
                    let sx = ((i + 1).min(w - 1) - i.saturating_sub(1)) as f32 * dx;
                    let sz = ((j + 1).min(h - 1) - j.saturating_sub(1)) as f32 * dz;
                    m.normals.push([-hx / sx, 1.0, -hz / sz]);
                }
            }
            normalize(&mut m.normals);
            m.normal_indices = m.triangles.clone();
        }
        m.inside_vector = Some(glam::DVec3::Y);
        Ok(Object::new(Shape::Mesh(Arc::new(m)), span))
    }
}

fn normalize(normals: &mut [[f32; 3]]) {
    for n in normals {
        let v = glam::Vec3::from(*n).normalize_or_zero();
        *n = [v.x, v.y, v.z];
    }
}

fn check_indices(m: &MeshData) -> Result<(), String> {
    let n = m.positions.len() as u32;
    if let Some(t) = m.triangles.iter().find(|t| t.iter().any(|&i| i >= n)) {
        return Err(format!(
            "a face refers to vertex {} of {n}",
            t.iter().max().unwrap_or(&0)
        ));
    }
    let nn = m.normals.len() as u32;
    if m.normal_indices
        .iter()
        .any(|t| t[0] != u32::MAX && t.iter().any(|&i| i >= nn))
    {
        return Err("a face refers to a missing normal".into());
    }
    let nu = m.uvs.len() as u32;
    if m.uv_indices.iter().any(|t| t.iter().any(|&i| i >= nu)) {
        return Err("a face refers to a missing uv".into());
    }
    Ok(())
}
