//! `camera`, `light_source`, `global_settings` and `background`.

use super::cursor::{Cursor, Tok};
use super::objects::TRANSFORMS;
use super::value::{CameraSpec, Value};
use super::{Evaluator, Fail, R};
use crate::diag::{codes, Diagnostic};
use crate::scene::{Camera, CameraKind, Light, LightKind, Transform};
use crate::span::Span;
use glam::DVec3;

const CAMERA_ITEMS: &[&str] = &[
    "perspective",
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
const LATER_CAMERA: &[&str] = &[
    "orthographic",
    "fisheye",
    "ultra_wide_angle",
    "panoramic",
    "spherical",
    "cylinder",
    "focal_point",
    "aperture",
    "blur_samples",
    "normal",
];
const LIGHT_ITEMS: &[&str] = &[
    "parallel",
    "point_at",
    "shadowless",
    "translate",
    "rotate",
    "scale",
    "matrix",
    "transform",
];
const LATER_LIGHT: &[&str] = &[
    "spotlight",
    "radius",
    "falloff",
    "tightness",
    "area_light",
    "jitter",
    "adaptive",
    "circular",
    "orient",
    "fade_distance",
    "fade_power",
    "looks_like",
    "cylinder",
    "media_interaction",
    "media_attenuation",
    "photons",
];
const GLOBAL_ITEMS: &[&str] = &[
    "ambient_light",
    "assumed_gamma",
    "max_trace_level",
    "adc_bailout",
    "noise_generator",
];

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
                Tok::Kw("perspective", _) => Ok(()),
                Tok::Kw(
                    kw @ ("location" | "look_at" | "up" | "right" | "direction" | "sky"),
                    span,
                ) => {
                    c.once(kw, span)?;
                    let v = self.take_vec3(c, &format!("a vector after `{kw}`"))?;
                    match kw {
                        "location" => cam.location = v,
                        "look_at" => cam.look_at = Some(v),
                        "up" => cam.up = v,
                        "right" => cam.right = v,
                        "direction" => cam.direction = v,
                        _ => cam.sky = v,
                    }
                    Ok(())
                }
                Tok::Kw("angle", span) => {
                    c.once("angle", span)?;
                    let (v, s) = c.value("the field of view in degrees")?;
                    let a = self.to_float(&v, s)?;
                    if a <= 0.0 || a >= 180.0 {
                        Err(Diagnostic::error(codes::OUT_OF_RANGE, s, format!("a perspective camera's angle must be between 0 and 180 degrees, found {a}"))
                            .with_help("typical values are 30 to 90")
                            .into())
                    } else {
                        cam.angle = Some(a);
                        Ok(())
                    }
                }
                Tok::Kw(kw, span) if TRANSFORMS.contains(&kw) => {
                    self.transform_kw(kw, span, c).map(|t| {
                        cam.transform = Some(cam.transform.unwrap_or(Transform::IDENTITY).then(&t));
                    })
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
                .with_help("this release has the perspective camera")
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
    pub(crate) fn resolve_camera(&self, spec: &CameraSpec, span: Span) -> R<Camera> {
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
        if let Some(angle) = spec.angle {
            dir = dir.normalize() * (0.5 * right.length() / (angle.to_radians() / 2.0).tan());
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
            let r = spec.sky.cross(d);
            if r.length_squared() < 1e-20 {
                return Err(bad(
                    "the camera looks straight along `sky`, so its roll is undefined",
                    "give a `sky` vector that is not parallel to the view direction, e.g. `sky z`",
                ));
            }
            let r = r.normalize();
            let u = d.cross(r);
            let sign = if handed < 0.0 { -1.0 } else { 1.0 };
            right = r * right.length() * sign;
            up = u * up.length();
            dir = d * dir.length();
        }
        let mut cam = Camera {
            kind: CameraKind::Perspective,
            location: spec.location,
            direction: dir,
            right,
            up,
            span,
        };
        if let Some(t) = spec.transform {
            cam.location = t.point(cam.location);
            cam.direction = t.vector(cam.direction);
            cam.right = t.vector(cam.right);
            cam.up = t.vector(cam.up);
        }
        Ok(cam)
    }

    /// `light_source { LOCATION, COLOUR [parallel point_at P] [shadowless] }`.
    pub(crate) fn light(&mut self, c: &mut Cursor) -> R<Light> {
        let location = self.take_vec3(c, "the light's location")?;
        c.comma();
        let colour = if c.value_next() {
            self.take_colour(c, "the light's colour")?.rgb
        } else {
            return Err(Diagnostic::error(
                codes::MISSING_VALUE,
                c.span,
                "a light source needs a colour",
            )
            .with_help("write `light_source { <x, y, z> color rgb <1, 1, 1> }`")
            .into());
        };
        let mut light = Light {
            location,
            colour,
            kind: LightKind::Point,
            shadowless: false,
            span: c.span,
        };
        let mut point_at = DVec3::ZERO;
        let mut parallel = false;
        while let Some(tok) = c.next() {
            let r: R<()> = match tok {
                Tok::Kw("parallel", span) => c.once("parallel", span).map(|_| parallel = true),
                Tok::Kw("point_at", span) => {
                    c.once("point_at", span)?;
                    self.take_vec3(c, "the point the light aims at")
                        .map(|p| point_at = p)
                }
                Tok::Kw("shadowless", _) => {
                    light.shadowless = true;
                    Ok(())
                }
                Tok::Kw(kw, span) if TRANSFORMS.contains(&kw) => {
                    self.transform_kw(kw, span, c).map(|t| {
                        light.location = t.point(light.location);
                        point_at = t.point(point_at);
                    })
                }
                Tok::Block(_, Value::Transform(t), _) => {
                    light.location = t.point(light.location);
                    point_at = t.point(point_at);
                    Ok(())
                }
                Tok::Kw(kw, span) | Tok::Block(kw, _, span) if LATER_LIGHT.contains(&kw) => {
                    Err(Diagnostic::error(
                        codes::UNSUPPORTED,
                        span,
                        format!("`{kw}` is not implemented in rts yet"),
                    )
                    .with_help("this release has point and parallel lights")
                    .into())
                }
                other => Err(self.unexpected(c, &other, LIGHT_ITEMS)),
            };
            if let Err(f) = r {
                self.report(f);
            }
        }
        if parallel {
            if (light.location - point_at).length_squared() == 0.0 {
                return Err(Diagnostic::error(
                    codes::BAD_CAMERA,
                    c.span,
                    "a parallel light's location equals its point_at",
                )
                .with_help("the light shines from location towards point_at: make them differ")
                .into());
            }
            light.kind = LightKind::Parallel { point_at };
        }
        Ok(light)
    }

    /// `global_settings { ambient_light assumed_gamma max_trace_level adc_bailout }`.
    pub(crate) fn global_settings(&mut self, c: &mut Cursor) {
        while let Some(tok) = c.next() {
            let r: R<()> = match tok {
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
                Tok::Block(kw @ ("radiosity" | "photons"), _, span)
                | Tok::Kw(kw @ ("radiosity" | "photons"), span) => Err(Diagnostic::error(
                    codes::UNSUPPORTED,
                    span,
                    format!("`{kw}` is not implemented in rts yet"),
                )
                .into()),
                Tok::Kw("noise_generator", span) => self.noise_generator(c, span),
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
