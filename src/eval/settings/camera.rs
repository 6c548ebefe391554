//! `camera`, `light_source`, `global_settings` and `background`.

use crate::diag::{codes, Diagnostic};
use crate::eval::core::cursor::{Cursor, Tok};
use crate::eval::core::transforms::TRANSFORMS;
use crate::eval::core::value::{CameraSpec, Value};
use crate::eval::core::{Evaluator, Fail, R};
use crate::scene::{Camera, CameraKind, Transform};
use crate::span::Span;
use glam::DVec3;

pub(crate) const CAMERA_ITEMS: &[&str] = &[
    "perspective",
    "orthographic",
    "fisheye",
    "ultra_wide_angle",
    "panoramic",
    "spherical",
    "cylinder",
    "mesh_camera",
    "normal",
    "aperture",
    "focal_point",
    "blur_samples",
    "confidence",
    "variance",
    "location",
    "look_at",
    "up",
    "right",
    "direction",
    "sky",
    "angle",
    "translate",
    "rotate",
    "scale",
    "matrix",
    "transform",
];
const LATER_CAMERA: &[&str] = &["omnimax"];
/// The projection keywords.
const PROJECTIONS: &[&str] = &[
    "perspective",
    "orthographic",
    "fisheye",
    "ultra_wide_angle",
    "panoramic",
    "spherical",
];
pub(crate) const GLOBAL_ITEMS: &[&str] = &[
    "ambient_light",
    "assumed_gamma",
    "max_trace_level",
    "adc_bailout",
    "noise_generator",
    "number_of_waves",
    "hf_gray_16",
    "path_tracing",
    "mm_per_unit",
    "radiosity",
];

/// An out-of-range camera value.
fn return_range(span: Span, msg: String) -> R<()> {
    Err(Diagnostic::error(codes::OUT_OF_RANGE, span, msg)
        .with_help("typical angles are 30 to 90 (perspective) and 180 (fisheye)")
        .into())
}

impl Evaluator<'_> {
    /// `camera { [Name] perspective location … look_at … angle … }`.
    pub(crate) fn camera(&mut self, c: &mut Cursor) -> R<CameraSpec> {
        let mut cam = match c.peek() {
            Some(Tok::Val(Value::Camera(_), _)) => match c.next() {
                Some(Tok::Val(Value::Camera(x), _)) => (*x).clone(),
                _ => unreachable!(),
            },
            _ => CameraSpec::default(),
        };
        while let Some(tok) = c.next() {
            let r: R<()> = match tok {
                Tok::Kw("cylinder", _) => {
                    let (v, s) = c.value("the cylinder camera's type, 1 to 4")?;
                    let t = self.to_float(&v, s)?;
                    if [1.0, 2.0, 3.0, 4.0].contains(&t) {
                        cam.projection = "cylinder";
                        cam.cylinder = t as u8;
                        Ok(())
                    } else {
                        Err(Diagnostic::error(
                            codes::OUT_OF_RANGE,
                            s,
                            format!("a cylinder camera's type is 1, 2, 3 or 4, found {t}"),
                        )
                        .with_help(
                            "1 vertical cylinder, 2 horizontal cylinder (both from one point); \
                             3 and 4 the same with the viewpoint moving along the axis",
                        )
                        .into())
                    }
                }
                Tok::Kw(kw, _) if PROJECTIONS.contains(&kw) => {
                    cam.projection = PROJECTIONS.iter().copied().find(|p| *p == kw).unwrap_or("perspective");
                    Ok(())
                }
                Tok::Kw(
                    kw @ ("location" | "look_at" | "up" | "right" | "direction" | "sky" | "focal_point"),
                    span,
                ) => {
                    c.once(kw, span)?;
                    let v = self.take_vec3(c, &format!("a vector after `{kw}`"))?;
                    match kw {
                        "location" => cam.location = v,
                        "look_at" => cam.look_at = Some(v),
                        "up" => {
                            cam.up = v;
                            cam.sized = true;
                        }
                        "right" => {
                            cam.right = v;
                            cam.sized = true;
                        }
                        "direction" => cam.direction = v,
                        "focal_point" => cam.focal_point = v,
                        _ => cam.sky = v,
                    }
                    Ok(())
                }
                Tok::Kw("angle", span) => {
                    c.once("angle", span)?;
                    let (v, s) = c.value("the field of view in degrees")?;
                    let a = self.to_float(&v, s)?;
                    if cam.projection == "perspective" && a >= 180.0 {
                        Err(Diagnostic::error(
                            codes::OUT_OF_RANGE,
                            s,
                            format!("a perspective camera's angle must be below 180 degrees, found {a}"),
                        )
                        .with_help("typical values are 30 to 90; use `fisheye` or `spherical` for wider views")
                        .into())
                    } else if a <= 0.0 || a > 360.0 {
                        return_range(s, format!("a camera's angle must be above 0 and at most 360 degrees, found {a}"))
                    } else {
                        cam.angle = Some(a);
                        c.comma();
                        if c.value_next() {
                            let (v, s) = c.value("the vertical field of view in degrees")?;
                            let b = self.to_float(&v, s)?;
                            if b <= 0.0 || b > 360.0 {
                                return_range(s, format!("a camera's vertical angle must be above 0 and at most 360 degrees, found {b}"))
                            } else {
                                cam.v_angle = Some(b);
                                Ok(())
                            }
                        } else {
                            Ok(())
                        }
                    }
                }
                Tok::Kw("aperture", span) => {
                    c.once("aperture", span)?;
                    let (v, s) = c.value("the aperture (lens diameter)")?;
                    let a = self.to_float(&v, s)?;
                    if a < 0.0 {
                        return_range(s, format!("`aperture` must not be negative, found {a}"))
                    } else {
                        cam.aperture = a;
                        Ok(())
                    }
                }
                Tok::Kw("blur_samples", span) => {
                    c.once("blur_samples", span)?;
                    let (v, s) = c.value("the number of blur samples per pixel")?;
                    let mut n = self.to_float(&v, s)?;
                    let mut min = 1.0;
                    c.comma();
                    if c.value_next() {
                        // `blur_samples MIN, MAX`.
                        min = n;
                        n = self.take_float(c, "the maximum number of blur samples")?;
                    }
                    if !(1.0..=4096.0).contains(&n) {
                        return_range(s, format!("`blur_samples` must be from 1 to 4096, found {n}"))
                    } else if !(1.0..=n).contains(&min) {
                        return_range(
                            s,
                            format!("the minimum of `blur_samples MIN, MAX` must be from 1 to MAX ({n}), found {min}"),
                        )
                    } else {
                        cam.blur_samples = n as u32;
                        cam.blur_min_samples = min as u32;
                        Ok(())
                    }
                }
                Tok::Kw("confidence", span) => {
                    c.once("confidence", span)?;
                    let (v, s) = c.value("a probability after `confidence`")?;
                    let p = self.to_float(&v, s)?;
                    if !(0.0..1.0).contains(&p) {
                        return_range(s, format!("`confidence` must be from 0 to below 1, found {p}"))
                    } else {
                        cam.confidence = p;
                        Ok(())
                    }
                }
                Tok::Kw("variance", span) => {
                    c.once("variance", span)?;
                    let (v, s) = c.value("a number after `variance`")?;
                    let x = self.to_float(&v, s)?;
                    if x < 0.0 {
                        return_range(s, format!("`variance` must not be negative, found {x}"))
                    } else {
                        cam.variance = x;
                        Ok(())
                    }
                }
                Tok::Kw(kw, span) if TRANSFORMS.contains(&kw) => {
                    self.transform_kw(kw, span, c).map(|t| {
                        cam.transform = Some(cam.transform.unwrap_or(Transform::IDENTITY).then(&t));
                    })
                }
                Tok::Block(_, Value::MeshCamera(m), _) => {
                    cam.mesh = Some(m);
                    Ok(())
                }
                Tok::Block("normal", Value::Normal(n), _) => {
                    cam.normal = Some(n);
                    Ok(())
                }
                Tok::Block(_, Value::Transform(t), _) => {
                    cam.transform = Some(cam.transform.unwrap_or(Transform::IDENTITY).then(&t));
                    Ok(())
                }
                Tok::Kw(kw, span) if LATER_CAMERA.contains(&kw) => Err(Diagnostic::error(
                    codes::UNSUPPORTED,
                    span,
                    format!("`{kw}` cameras and options are not implemented in rts yet"),
                )
                .with_help("rts has perspective, orthographic, fisheye, ultra_wide_angle, panoramic, cylinder and spherical cameras")
                .into()),
                other => Err(self.unexpected(c, &other, CAMERA_ITEMS)),
            };
            if let Err(f) = r {
                self.report(f);
            }
        }
        Ok(cam)
    }

    /// Turns a camera as written into the vectors the renderer uses, as POV-Ray does:
    /// `angle` sets the length of `direction` from `right`; `look_at` turns the camera
    /// about `sky`, keeping the lengths and handedness of `right`, `up` and `direction`.
    pub(crate) fn resolve_camera(&mut self, spec: &CameraSpec, span: Span) -> R<Camera> {
        let bad = |msg: &str, help: &str| -> Fail {
            Diagnostic::error(codes::BAD_CAMERA, span, msg.to_string())
                .with_help(help.to_string())
                .into()
        };
        let (mut dir, mut right, mut up) = (spec.direction, spec.right, spec.up);
        if dir.length_squared() == 0.0
            || right.length_squared() == 0.0
            || up.length_squared() == 0.0
        {
            return Err(bad(
                "the camera's direction, right and up vectors must not be zero",
                "remove the zero vector or give it a length",
            ));
        }
        let handed = up.cross(dir).dot(right);
        let mut ortho_angle = None;
        if let Some(angle) = spec.angle {
            match spec.projection {
                "perspective" if angle >= 180.0 => {
                    return Err(Diagnostic::error(
                        codes::OUT_OF_RANGE,
                        span,
                        format!(
                            "a perspective camera's angle must be below 180 degrees, found {angle}"
                        ),
                    )
                    .with_help(
                        "typical values are 30 to 90; use `fisheye` or `spherical` for wider views",
                    )
                    .into());
                }
                "perspective" => {
                    dir =
                        dir.normalize() * (0.5 * right.length() / (angle.to_radians() / 2.0).tan());
                }
                "orthographic" => ortho_angle = Some(angle),
                _ => {}
            }
        } else if spec.projection == "orthographic" && !spec.sized {
            // Measured in POV-Ray 3.7: without `angle`, `right` or `up`, an
            // orthographic camera shows what the perspective camera
            // of the same vectors shows at the look_at distance.
            ortho_angle = Some(2.0 * (0.5 * right.length() / dir.length()).atan().to_degrees());
        }
        if let Some(target) = spec.look_at {
            let d = target - spec.location;
            if d.length_squared() == 0.0 {
                return Err(bad(
                    "the camera looks at its own location",
                    "move `look_at` away from `location`",
                ));
            }
            let d = d.normalize();
            let mut r = spec.sky.cross(d);
            if r.length_squared() < 1e-20 {
                // POV-Ray warns and keeps the written `right` (measured: the picture
                // is the one `sky z` gives for a camera looking down).
                let along = right - right.dot(d) * d;
                if along.length_squared() < 1e-20 {
                    return Err(bad(
                        "the camera looks straight along `sky` and along `right`, so its roll is undefined",
                        "give a `sky` vector that is not parallel to the view direction, e.g. `sky z`",
                    ));
                }
                self.report(
                    Diagnostic::warning(
                        codes::BAD_CAMERA,
                        span,
                        "the camera looks straight along `sky`; its `right` vector sets the roll",
                    )
                    .with_help("give a `sky` vector that is not parallel to the view direction, e.g. `sky z`")
                    .into(),
                );
                r = along * handed.signum();
            }
            let r = r.normalize();
            let u = d.cross(r);
            // POV-Ray keeps the usual orientation only when `up × direction`
            // points along `right`; when it is zero (`up` along `direction`, as
            // with `up z` and the default `direction z`) the picture is mirrored
            // (measured: POV-Ray's objects/prism3 scenes).
            let sign = if handed > 0.0 { 1.0 } else { -1.0 };
            right = r * right.length() * sign;
            up = u * up.length();
            dir = d * dir.length();
        }
        if let Some(angle) = ortho_angle {
            if angle >= 180.0 {
                return Err(bad(
                    "an orthographic camera's angle must be below 180 degrees",
                    "the angle sizes the view like a perspective camera's at the look_at distance",
                ));
            }
            // The view is as wide as a perspective camera's with this angle at the
            // distance of `look_at` (or of `direction`'s length).
            // POV-Ray's look_at defaults to <0, 0, 1> for this (measured).
            let dist = (spec.look_at.unwrap_or(DVec3::Z) - spec.location).length();
            let width = 2.0 * dist * (angle.to_radians() / 2.0).tan();
            let k = width / right.length();
            right *= k;
            up *= k;
        }
        let h = spec.angle.unwrap_or(180.0);
        let kind = match spec.projection {
            "orthographic" => CameraKind::Orthographic,
            "fisheye" => CameraKind::Fisheye { angle: h },
            "ultra_wide_angle" => CameraKind::UltraWideAngle {
                angle: spec.angle.unwrap_or(90.0),
            },
            "panoramic" => CameraKind::Panoramic,
            "cylinder" => CameraKind::Cylinder {
                kind: spec.cylinder,
                angle: spec.angle.unwrap_or(90.0),
            },
            "spherical" => {
                let h = spec.angle.unwrap_or(360.0);
                CameraKind::Spherical {
                    h_angle: h,
                    v_angle: spec.v_angle.unwrap_or(h / 2.0),
                }
            }
            _ => CameraKind::Perspective,
        };
        let mut cam = Camera {
            kind,
            location: spec.location,
            direction: dir,
            right,
            up,
            aperture: spec.aperture,
            focal_distance: 1.0,
            blur_samples: spec.blur_samples,
            blur_min_samples: spec.blur_min_samples,
            confidence: spec.confidence,
            variance: spec.variance,
            normal: spec.normal.clone(),
            mesh: spec.mesh.as_ref().map(|m| {
                // Only the z of `location` and `direction` matter to a mesh
                // camera: the offset of each ray from its face, and its sense.
                std::sync::Arc::new(crate::scene::MeshCamera {
                    offset: spec.location.z,
                    reversed: spec.direction.z < 0.0,
                    ..(**m).clone()
                })
            }),
            span,
        };
        if spec.transform.is_some() && spec.mesh.is_some() {
            self.warn(
                Diagnostic::warning(
                    codes::IGNORED,
                    span,
                    "transforms of a mesh camera are ignored: its rays come from the meshes"
                        .to_string(),
                )
                .with_help(
                    "move the meshes inside `mesh_camera { … }` instead (mesh { M translate … })",
                ),
            );
        }
        if let Some(t) = spec.transform {
            cam.location = t.point(cam.location);
            cam.direction = t.vector(cam.direction);
            cam.right = t.vector(cam.right);
            cam.up = t.vector(cam.up);
        }
        // The plane in focus passes through `focal_point`, across the view direction.
        let fd = (spec.focal_point - cam.location).dot(cam.direction.normalize());
        cam.focal_distance = if fd > 1e-9 {
            fd
        } else {
            cam.direction.length()
        };
        Ok(cam)
    }

    /// `global_settings { ambient_light assumed_gamma max_trace_level adc_bailout }`.
    pub(crate) fn global_settings(&mut self, c: &mut Cursor) {
        while let Some(tok) = c.next() {
            let r: R<()> = match tok {
                Tok::Kw("mm_per_unit", span) => self
                    .take_float(
                        c,
                        "the millimetres per scene unit (for subsurface scattering)",
                    )
                    .map(|_| self.warn(crate::eval::materials::subsurface::ignored(span, "`mm_per_unit`"))),
                Tok::Kw("ambient_light", _) => self
                    .take_colour(c, "the ambient light colour")
                    .map(|x| self.scene.global.ambient_light = x.rgb),
                Tok::Kw("assumed_gamma", _) => {
                    let r = c.value("the gamma (1.0 for linear)");
                    r.and_then(|(v, s)| {
                        let g = self.to_float(&v, s)?;
                        if g <= 0.0 {
                            return Err(Diagnostic::error(
                                codes::OUT_OF_RANGE,
                                s,
                                "assumed_gamma must be positive",
                            )
                            .with_help("use 1.0 (linear, recommended) or 2.2")
                            .into());
                        }
                        self.scene.global.assumed_gamma = Some(g);
                        Ok(())
                    })
                }
                Tok::Kw("max_trace_level", _) => {
                    c.value("the maximum trace level").and_then(|(v, s)| {
                        let n = self.to_float(&v, s)?;
                        if !(1.0..=256.0).contains(&n) {
                            return Err(Diagnostic::error(
                                codes::OUT_OF_RANGE,
                                s,
                                format!("max_trace_level must be from 1 to 256, found {n}"),
                            )
                            .into());
                        }
                        self.scene.global.max_trace_level = n as u32;
                        Ok(())
                    })
                }
                Tok::Kw("adc_bailout", _) => c.value("the bailout threshold").and_then(|(v, s)| {
                    let n = self.to_float(&v, s)?;
                    if n < 0.0 {
                        return Err(Diagnostic::error(
                            codes::OUT_OF_RANGE,
                            s,
                            "adc_bailout must not be negative",
                        )
                        .into());
                    }
                    self.scene.global.adc_bailout = n;
                    Ok(())
                }),
                Tok::Block("radiosity", Value::Radiosity(b), span) => match b.importance {
                    Some((_, at)) => Err(Diagnostic::error(
                        codes::UNEXPECTED_ITEM,
                        at,
                        "`importance` belongs in an object's `radiosity { }`, not in global_settings",
                    )
                    .with_secondary(span, "in this global radiosity block")
                    .with_help("move it into the object: sphere { … radiosity { importance 0.5 } }")
                    .into()),
                    None => {
                        self.scene.global.radiosity = Some(b.settings);
                        Ok(())
                    }
                },
                Tok::Block("photons", Value::Photons(b), span) => {
                    self.photons_for(&b, super::photons::PhotonsIn::Global, span);
                    let mut settings = b.global;
                    if !b.items.iter().any(|(k, _)| matches!(*k, "spacing" | "count")) {
                        // POV-Ray then shoots a handful of photons: none here.
                        settings.density = crate::scene::PhotonDensity::Count(0);
                        self.warn(
                            Diagnostic::warning(
                                codes::MISSING_VALUE,
                                span,
                                "this photons block has neither `spacing` nor `count`: no photons are shot",
                            )
                            .with_label("no photon density")
                            .with_help("add `spacing 0.01` (the distance between photons) or `count 20000`"),
                        );
                    }
                    self.scene.global.photons = Some(settings);
                    Ok(())
                }
                Tok::Kw("noise_generator", span) => self.noise_generator(c, span),
                Tok::Kw("number_of_waves", _) => {
                    c.value("the number of wave centres").and_then(|(v, s)| {
                        let n = self.to_float(&v, s)?;
                        if n < 1.0 || n.fract() != 0.0 {
                            return Err(Diagnostic::error(
                                codes::OUT_OF_RANGE,
                                s,
                                format!("number_of_waves is a whole number from 1, found {n}"),
                            )
                            .with_help("POV-Ray's default is 10")
                            .into());
                        }
                        if n > 10.0 {
                            self.warn(
                                Diagnostic::warning(
                                    codes::IGNORED,
                                    s,
                                    format!("rts has 10 wave centres; number_of_waves {n} uses 10"),
                                )
                                .with_help("use 10 or fewer"),
                            );
                        }
                        self.scene.global.number_of_waves = n.min(10.0) as u8;
                        Ok(())
                    })
                }
                Tok::Kw("hf_gray_16", span) => {
                    let on_off = if c.value_next() {
                        c.value("on or off").map(|_| ())
                    } else {
                        Ok(())
                    };
                    self.warn(
                        Diagnostic::warning(
                            codes::IGNORED,
                            span,
                            "`hf_gray_16` (grey 16-bit output for height fields) is ignored by rts",
                        )
                        .with_help("write 16-bit output with `--bit-depth 16`; a grey scene gives grey pixels"),
                    );
                    on_off
                }
                other => Err(self.unexpected(c, &other, GLOBAL_ITEMS)),
            };
            if let Err(f) = r {
                self.report(f);
            }
        }
    }

    /// `background { COLOUR }`.
    pub(crate) fn background(&mut self, c: &mut Cursor) -> R<()> {
        let col = self.take_colour(c, "the background colour")?;
        self.scene.background = col;
        if let Some(t) = c.next() {
            return Err(self.unexpected(c, &t, &["a colour"]));
        }
        Ok(())
    }
}
