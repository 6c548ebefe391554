//! `mesh_camera { RAYS DISTRIBUTION MESH… [smooth] }`: POV-Ray 3.7's camera whose
//! rays start on the faces of meshes.

use crate::diag::{codes, Diagnostic};
use crate::eval::core::cursor::{Cursor, Tok};
use crate::eval::core::value::Value;
use crate::eval::core::{Evaluator, R};
use crate::scene::{CameraMesh, MeshCamera, Object, Shape, UvGrid};
use crate::span::Span;

/// The most rays a mesh camera may shoot into one pixel.
const MAX_RAYS_PER_PIXEL: f64 = 1024.0;

impl Evaluator<'_> {
    /// The block's contents: two numbers, then `mesh`/`mesh2` objects and
    /// `smooth`. `offset` and `reversed` come from the camera and are set when
    /// it is resolved.
    pub(crate) fn mesh_camera(&mut self, c: &mut Cursor) -> R<MeshCamera> {
        let (v, rays_span) = c.value("the number of rays per pixel (1 or more)")?;
        let rays = self.to_float(&v, rays_span)?;
        c.comma();
        let (v, dist_span) = c.value("the distribution type: 0, 1, 2 or 3")?;
        let dist = self.to_float(&v, dist_span)?;
        if ![0.0, 1.0, 2.0, 3.0].contains(&dist) {
            return Err(Diagnostic::error(
                codes::OUT_OF_RANGE,
                dist_span,
                format!("a mesh camera's distribution type is 0, 1, 2 or 3, found {dist}"),
            )
            .with_help(
                "0: one mesh per ray, face = pixel; 1: the meshes summed; 2: meshes side by \
                 side (stereo); 3: by uv coordinates (texture baking)",
            )
            .into());
        }
        if rays.fract() != 0.0 || !(1.0..=MAX_RAYS_PER_PIXEL).contains(&rays) {
            return Err(Diagnostic::error(
                codes::OUT_OF_RANGE,
                rays_span,
                format!("a mesh camera's rays per pixel must be a whole number from 1 to 1024, found {rays}"),
            )
            .with_help("write 1 for one ray per pixel")
            .into());
        }
        if rays > 1.0 && dist >= 2.0 {
            return Err(Diagnostic::error(
                codes::OUT_OF_RANGE,
                rays_span,
                format!("distribution {dist} shoots one ray per pixel, found {rays}"),
            )
            .with_help("write 1, or use distribution 0 or 1 for several rays per pixel")
            .into());
        }
        let mut meshes = Vec::new();
        let mut smooth: Option<Span> = None;
        let mut objects = 0;
        while let Some(tok) = c.next() {
            match tok {
                Tok::Block(_, Value::Object(o), span) | Tok::Val(Value::Object(o), span) => {
                    objects += 1;
                    match camera_mesh(&o) {
                        Some(f) => meshes.push(f),
                        None => self.report(
                            Diagnostic::error(
                                codes::TYPE_MISMATCH,
                                span,
                                "a mesh camera takes `mesh` and `mesh2` objects only".to_string(),
                            )
                            .with_help("build the camera's faces as a mesh { triangle { … } … }")
                            .into(),
                        ),
                    }
                }
                Tok::Kw("smooth", span) => smooth = Some(span),
                other => {
                    let f = self.unexpected(c, &other, &["mesh", "mesh2", "smooth"]);
                    self.report(f);
                }
            }
        }
        if objects == 0 {
            return Err(Diagnostic::error(
                codes::MISSING_VALUE,
                c.span,
                "a mesh camera needs at least one `mesh` or `mesh2`".to_string(),
            )
            .with_help("add the mesh whose faces shoot the rays: mesh_camera { 1 0 mesh { … } }")
            .into());
        }
        if meshes.is_empty() {
            // Reported above: only objects that are not meshes.
            return Err(crate::eval::core::Fail::silent());
        }
        if let Some(span) = smooth {
            if dist != 3.0 {
                self.report(
                    Diagnostic::error(
                        codes::UNEXPECTED_ITEM,
                        span,
                        "`smooth` belongs to distribution 3 only".to_string(),
                    )
                    .with_help("remove `smooth`, or use distribution 3 (rays by uv coordinates)")
                    .into(),
                );
            }
        }
        if dist == 3.0 && meshes.iter().all(|m| m.data.uv_indices.is_empty()) {
            self.warn(
                Diagnostic::warning(
                    codes::MISSING_VALUE,
                    c.span,
                    "distribution 3 finds faces by their uv coordinates, and these meshes have none: nothing is seen".to_string(),
                )
                .with_help("give the triangles `uv_vectors` (or a mesh2 `uv_vectors` list)"),
            );
        }
        let uv_grid = if dist == 3.0 {
            UvGrid::new(&meshes)
        } else {
            UvGrid::default()
        };
        Ok(MeshCamera {
            rays_per_pixel: rays as u32,
            distribution: dist as u8,
            meshes,
            smooth: smooth.is_some() && dist == 3.0,
            offset: 0.0,
            reversed: false,
            uv_grid,
        })
    }
}

/// A mesh object as a camera mesh; `None` for other objects.
fn camera_mesh(o: &Object) -> Option<CameraMesh> {
    let Shape::Mesh(m) = &o.shape else {
        return None;
    };
    Some(CameraMesh {
        data: m.clone(),
        transform: o.transform.clone(),
    })
}
