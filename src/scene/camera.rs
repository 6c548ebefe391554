//! The camera, resolved to the vectors POV-Ray's cameras use.

use crate::span::Span;
use glam::DVec3;

/// Camera projections. Screen coordinates (sx, sy) run over [-0.5, 0.5]² (sy up).
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub enum CameraKind {
    /// `perspective` (the default): direction `direction + sx right + sy up`.
    #[default]
    Perspective,
    /// `orthographic`: parallel rays along `direction` from
    /// `location + sx right + sy up`.
    Orthographic,
    /// `fisheye`: the angle from `direction` grows linearly with the distance from
    /// the image centre, reaching `angle / 2` at the edge of the inscribed circle;
    /// nothing is seen outside it.
    Fisheye {
        /// Full field of view in degrees (default 180).
        angle: f64,
    },
    /// `ultra_wide_angle`: with longitude `2 sx · angle/2` and latitude
    /// `2 sy · angle/2 · |up|/|right|`, the direction
    /// `sin(lon) right + sin(lat) up + cos(lon) cos(lat) direction` (unit vectors).
    UltraWideAngle {
        /// Horizontal field of view in degrees (default 90).
        angle: f64,
    },
    /// `panoramic`: with `a = π sx` and `b = π sy`, the direction
    /// `sin(a) right + tan(b) up + cos(a) direction` (the vectors as they are, not
    /// normalised; measured against POV-Ray 3.7, which ignores `angle` for it).
    Panoramic,
    /// `cylinder 1` to `4` (measured against POV-Ray 3.7). The angle around the
    /// cylinder's axis is `θ = s · angle`, `s` the screen coordinate across the axis;
    /// along the axis the screen coordinate `a` moves the ray by `a` times the
    /// (unnormalised) axis vector. Types 1 and 3 have a vertical axis (`up`; θ
    /// from `sx`, towards `right`), types 2 and 4 a horizontal one (`right`; θ from
    /// `sy`, towards `up`). Types 1 and 2 start every ray at `location` and tilt
    /// the direction `cos θ D + sin θ A + a·axis` (unit `D`, `A`); types 3 and 4
    /// move the start along the axis instead and keep the direction flat.
    Cylinder {
        /// The type, 1 to 4.
        kind: u8,
        /// The angle around the axis the image spans, in degrees (default 90).
        angle: f64,
    },
    /// `spherical`: longitude and latitude mapped linearly onto the image.
    Spherical {
        /// Horizontal field of view in degrees (default 360).
        h_angle: f64,
        /// Vertical field of view in degrees (default half the horizontal).
        v_angle: f64,
    },
}

/// A camera after `look_at`, `angle` and `sky` have been applied, as POV-Ray does:
/// for a perspective camera the primary ray through screen point (sx, sy) in
/// [-0.5, 0.5]² (sy up) has direction `direction + sx * right + sy * up`.
#[derive(Clone, Debug, PartialEq)]
pub struct Camera {
    /// The projection.
    pub kind: CameraKind,
    /// Eye position.
    pub location: DVec3,
    /// Vector from the eye to the centre of the image plane.
    pub direction: DVec3,
    /// Full image-plane vector from left edge to right edge.
    pub right: DVec3,
    /// Full image-plane vector from bottom edge to top edge.
    pub up: DVec3,
    /// `aperture`: size of the lens for depth of field (0 = pinhole); the lens radius
    /// is aperture / 4, which blurs as much as POV-Ray 3.7.
    pub aperture: f64,
    /// Distance from `location` (along `direction`) of the plane in focus, from
    /// `focal_point`.
    pub focal_distance: f64,
    /// `blur_samples [MIN,] MAX`: the most lens rays a depth-of-field camera
    /// averages for one image sample.
    pub blur_samples: u32,
    /// The fewest lens rays per image sample (`MIN` of `blur_samples MIN, MAX`).
    pub blur_min_samples: u32,
    /// `confidence` (default 0.9) and `variance` (default 1/128) of the rule that
    /// stops taking lens rays once the mean is close enough (see
    /// `render::focal_blur`).
    pub confidence: f64,
    /// See `confidence`.
    pub variance: f64,
    /// `mesh_camera { … }`: rays from the faces of meshes instead of the
    /// projection (see [`MeshCamera`]).
    pub mesh: Option<std::sync::Arc<MeshCamera>>,
    /// `normal { … }`: perturbs every camera ray's direction (see
    /// `pattern::perturb_camera_ray`).
    pub normal: Option<std::sync::Arc<super::Normal>>,
    /// Where the camera was written (default span for the default camera).
    pub span: Span,
}

impl Default for Camera {
    /// POV-Ray's default camera: at the origin looking along +z, `right 1.33*x`.
    fn default() -> Self {
        Camera {
            kind: CameraKind::Perspective,
            location: DVec3::ZERO,
            direction: DVec3::Z,
            right: DVec3::new(1.33, 0.0, 0.0),
            up: DVec3::Y,
            aperture: 0.0,
            focal_distance: 1.0,
            blur_samples: 1,
            blur_min_samples: 1,
            confidence: 0.9,
            variance: 1.0 / 128.0,
            mesh: None,
            normal: None,
            span: Span::default(),
        }
    }
}

/// `mesh_camera { RAYS DISTRIBUTION MESH… [smooth] }` with the camera's
/// `location` and `direction`: POV-Ray 3.7's camera whose rays start on the
/// faces of meshes (see `render::camera` for how pixels pick faces).
#[derive(Clone, Debug, PartialEq)]
pub struct MeshCamera {
    /// Rays shot into each pixel (distributions 0 and 1), averaged.
    pub rays_per_pixel: u32,
    /// How pixels pick faces: 0 (one mesh per ray, face = pixel number), 1 (all
    /// meshes as one, face = ray × pixels + pixel), 2 (meshes side by side,
    /// one per block of columns), 3 (the face whose uv triangle holds the pixel).
    pub distribution: u8,
    /// The meshes, each with its placement (shared with the scene's copies).
    pub meshes: Vec<CameraMesh>,
    /// `smooth` (distribution 3): rays along the interpolated vertex normals.
    pub smooth: bool,
    /// The camera's `location.z`: how far along its direction each ray starts
    /// from its face.
    pub offset: f64,
    /// The camera's `direction.z` is negative: rays go against the faces'
    /// directions.
    pub reversed: bool,
    /// Distribution 3: the faces bucketed by their uv bounds.
    pub uv_grid: UvGrid,
}

/// One mesh of a mesh camera: its data and its placement.
#[derive(Clone, Debug, PartialEq)]
pub struct CameraMesh {
    /// The triangles.
    pub data: std::sync::Arc<super::MeshData>,
    /// `world_from_object`; `None` for the identity.
    pub transform: Option<std::sync::Arc<super::Transform>>,
}

impl CameraMesh {
    /// How many faces the mesh has.
    pub fn len(&self) -> usize {
        self.data.triangles.len()
    }

    /// Whether the mesh has no faces.
    pub fn is_empty(&self) -> bool {
        self.data.triangles.is_empty()
    }

    /// Face `i` in world space (`i` below [`CameraMesh::len`]).
    pub fn face(&self, i: usize) -> CameraFace {
        let m = &*self.data;
        let t = self.transform.as_deref();
        let v3 = |a: [f32; 3]| DVec3::new(f64::from(a[0]), f64::from(a[1]), f64::from(a[2]));
        let normals = m
            .normal_indices
            .get(i)
            .filter(|n| n[0] != u32::MAX)
            .and_then(|n| {
                let get = |k: u32| {
                    m.normals.get(k as usize).map(|&a| {
                        let n = v3(a);
                        t.map_or(n, |t| t.normal(n)).normalize_or_zero()
                    })
                };
                Some([get(n[0])?, get(n[1])?, get(n[2])?])
            });
        CameraFace {
            corners: m.corners(i).map(|p| t.map_or(p, |t| t.point(p))),
            normals,
            uv: self.uv(i),
        }
    }

    /// The uv coordinates of face `i`'s corners, if it has them.
    pub fn uv(&self, i: usize) -> Option<[glam::DVec2; 3]> {
        let m = &*self.data;
        let k = m.uv_indices.get(i)?;
        let get = |k: u32| {
            m.uvs
                .get(k as usize)
                .map(|a| glam::DVec2::new(f64::from(a[0]), f64::from(a[1])))
        };
        Some([get(k[0])?, get(k[1])?, get(k[2])?])
    }
}

/// One face of a mesh camera, in world space.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CameraFace {
    /// Corners.
    pub corners: [DVec3; 3],
    /// Vertex normals (`smooth_triangle`s and `mesh2` normals), if any.
    pub normals: Option<[DVec3; 3]>,
    /// uv coordinates of the corners, if any.
    pub uv: Option<[glam::DVec2; 3]>,
}

impl CameraFace {
    /// The direction a flat face shoots: `(c - a) × (b - a)`, normalised (the
    /// opposite of the right-hand normal of corners a, b, c, as POV-Ray 3.7
    /// aims them; measured).
    pub fn flat_direction(&self) -> DVec3 {
        let [a, b, c] = self.corners;
        (c - a).cross(b - a).normalize_or_zero()
    }
}

/// Faces of a mesh camera bucketed on a square grid over uv space [0, 1]²
/// (faces reaching outside are clamped into the border cells).
#[derive(Clone, Debug, PartialEq, Default)]
pub struct UvGrid {
    /// Cells per side.
    pub size: usize,
    /// Per cell (row-major, v down the rows): (mesh, face) pairs overlapping it.
    pub cells: Vec<Vec<(u32, u32)>>,
}

impl UvGrid {
    /// The grid over every face of `meshes` that has uv coordinates.
    pub fn new(meshes: &[CameraMesh]) -> UvGrid {
        let count: usize = meshes.iter().map(CameraMesh::len).sum();
        let size = ((count as f64).sqrt().ceil() as usize).clamp(1, 1024);
        let mut cells = vec![Vec::new(); size * size];
        let cell = |t: f64| ((t * size as f64).floor().max(0.0) as usize).min(size - 1);
        for (m, mesh) in meshes.iter().enumerate() {
            for f in 0..mesh.len() {
                let Some(uv) = mesh.uv(f) else { continue };
                let lo = uv[0].min(uv[1]).min(uv[2]);
                let hi = uv[0].max(uv[1]).max(uv[2]);
                if !(lo.is_finite() && hi.is_finite()) {
                    continue;
                }
                for j in cell(lo.y)..=cell(hi.y) {
                    for i in cell(lo.x)..=cell(hi.x) {
                        cells[j * size + i].push((m as u32, f as u32));
                    }
                }
            }
        }
        UvGrid { size, cells }
    }

    /// The first face (in mesh order) whose uv triangle holds `uv`, with the
    /// barycentric weights of its corners there.
    pub fn find(&self, meshes: &[CameraMesh], uv: glam::DVec2) -> Option<(CameraFace, [f64; 3])> {
        if self.size == 0 || !(0.0..=1.0).contains(&uv.x) || !(0.0..=1.0).contains(&uv.y) {
            return None;
        }
        let cell = |t: f64| ((t * self.size as f64).floor() as usize).min(self.size - 1);
        // A cell lists its faces in mesh order (see `new`): the first that
        // holds `uv` is the one.
        for &(m, f) in &self.cells[cell(uv.y) * self.size + cell(uv.x)] {
            let Some([a, b, c]) = meshes[m as usize].uv(f as usize) else {
                continue;
            };
            let d = (b - a).perp_dot(c - a);
            if d == 0.0 {
                continue;
            }
            let wb = (uv - a).perp_dot(c - a) / d;
            let wc = (b - a).perp_dot(uv - a) / d;
            let wa = 1.0 - wb - wc;
            const EDGE: f64 = -1e-12;
            if wa >= EDGE && wb >= EDGE && wc >= EDGE {
                return Some((meshes[m as usize].face(f as usize), [wa, wb, wc]));
            }
        }
        None
    }
}
