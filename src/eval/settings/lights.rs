//! `light_source { … }`: point, spot, cylinder, parallel and area lights.

use crate::diag::{codes, Diagnostic};
use crate::eval::core::cursor::{Cursor, Tok};
use crate::eval::core::transforms::TRANSFORMS;
use crate::eval::core::value::Value;
use crate::eval::core::{Evaluator, Fail, R};
use crate::scene::{AreaLight, Beam, Light, LightKind, Transform};
use crate::span::Span;
use std::sync::Arc;

pub(crate) const LIGHT_ITEMS: &[&str] = &[
    "spotlight",
    "cylinder",
    "parallel",
    "point_at",
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
    "projected_through",
    "shadowless",
    "photons",
    "media_interaction",
    "media_attenuation",
    "translate",
    "rotate",
    "scale",
    "matrix",
    "transform",
];

/// A light's object block (`looks_like`, `projected_through`) written twice.
fn given_twice(kw: &str, span: Span) -> Fail {
    Diagnostic::error(
        codes::DUPLICATE_PARAMETER,
        span,
        format!("`{kw}` is given twice in this `light_source`"),
    )
    .with_help(format!("put both shapes in a `union` inside one `{kw}`"))
    .into()
}

/// A light's number parameter that must not be negative.
fn out_of_range(span: Span, msg: String, help: &str) -> Fail {
    Diagnostic::error(codes::OUT_OF_RANGE, span, msg)
        .with_help(help.to_string())
        .into()
}

impl Evaluator<'_> {
    /// `light_source { LOCATION, COLOUR [spotlight | cylinder] [parallel] [point_at P]
    /// [radius R falloff F tightness T] [area_light A1, A2, N1, N2 [jitter]
    /// [adaptive A] [circular] [orient]] [fade_distance D fade_power P]
    /// [looks_like { OBJECT }] [shadowless] transforms }`.
    pub(crate) fn light(&mut self, c: &mut Cursor) -> R<Light> {
        // `light_source { LIGHT_IDENTIFIER transforms }`: as `object { … }`.
        if matches!(c.peek(), Some(Tok::Val(Value::Light(_), _))) {
            return self.light_object(c);
        }
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
            span: c.span,
            ..Light::default()
        };
        // Beam parameters as written: (radius, falloff, tightness) and their spans.
        let mut beam: [Option<(f64, Span)>; 3] = [None; 3];
        let mut kind: Option<(&str, Span)> = None;
        let mut transform = Transform::IDENTITY;
        let mut area_opts: Vec<(&str, Span)> = Vec::new();
        let mut adaptive = None;
        while let Some(tok) = c.next() {
            let r: R<()> = match tok {
                Tok::Kw(kw @ ("spotlight" | "cylinder"), span) => {
                    if let Some((prev, _)) = kind {
                        Err(Diagnostic::error(
                            codes::DUPLICATE_PARAMETER,
                            span,
                            format!("this light is already a `{prev}`"),
                        )
                        .with_help("a light is either a spotlight or a cylinder light")
                        .into())
                    } else {
                        kind = Some((kw, span));
                        Ok(())
                    }
                }
                Tok::Kw("parallel", span) => {
                    c.once("parallel", span).map(|_| light.parallel = true)
                }
                Tok::Kw("point_at", span) => {
                    c.once("point_at", span)?;
                    self.take_vec3(c, "the point the light aims at")
                        .map(|p| light.point_at = p)
                }
                Tok::Kw(kw @ ("radius" | "falloff" | "tightness"), span) => {
                    c.once(kw, span)?;
                    let (v, s) = c.value(&format!("a number after `{kw}`"))?;
                    let x = self.to_float(&v, s)?;
                    let i = ["radius", "falloff", "tightness"]
                        .iter()
                        .position(|k| *k == kw)
                        .unwrap_or(0);
                    if x < 0.0 && kw != "tightness" {
                        // POV-Ray uses the cosine of the angle, the same for
                        // both signs (measured: `falloff -30` lights exactly as
                        // `falloff 30`).
                        self.warn(
                            Diagnostic::warning(
                                codes::OUT_OF_RANGE,
                                s,
                                format!(
                                    "`{kw} {x}` is taken as `{kw} {}`, as POV-Ray takes it",
                                    -x
                                ),
                            )
                            .with_help("write the angle without its sign"),
                        );
                        beam[i] = Some((-x, s));
                        Ok(())
                    } else if x < 0.0 {
                        Err(out_of_range(
                            s,
                            format!("`{kw}` must not be negative, found {x}"),
                            "tightness 0 gives an even beam; larger values narrow it",
                        ))
                    } else {
                        beam[i] = Some((x, s));
                        Ok(())
                    }
                }
                Tok::Kw("area_light", span) => {
                    c.once("area_light", span)?;
                    self.area_light(c, span).map(|a| light.area = Some(a))
                }
                Tok::Kw(kw @ ("jitter" | "circular" | "orient"), span) => {
                    c.once(kw, span)?;
                    area_opts.push((kw, span));
                    Ok(())
                }
                Tok::Kw("adaptive", span) => {
                    c.once("adaptive", span)?;
                    area_opts.push(("adaptive", span));
                    let (v, s) = c.value("the adaptive level (0 to 4 is usual)")?;
                    let x = self.to_float(&v, s)?;
                    if !(0.0..=30.0).contains(&x) {
                        Err(out_of_range(
                            s,
                            format!("`adaptive` must be from 0 to 30, found {x}"),
                            "use a small level such as 1 or 2",
                        ))
                    } else {
                        adaptive = Some(x as u32);
                        Ok(())
                    }
                }
                Tok::Kw(kw @ ("fade_distance" | "fade_power"), span) => {
                    c.once(kw, span)?;
                    let (v, s) = c.value(&format!("a number after `{kw}`"))?;
                    let x = self.to_float(&v, s)?;
                    if x < 0.0 {
                        Err(out_of_range(
                            s,
                            format!("`{kw}` must not be negative, found {x}"),
                            "fade_power 2 with fade_distance at the distance of full brightness is physical",
                        ))
                    } else {
                        if kw == "fade_distance" {
                            light.fade_distance = x;
                        } else {
                            light.fade_power = x;
                        }
                        Ok(())
                    }
                }
                Tok::Block("looks_like", Value::Object(o), span) => {
                    if light.looks_like.is_some() {
                        Err(given_twice("looks_like", span))
                    } else {
                        let mut obj = (*o).clone();
                        let t = Transform::translate(location);
                        crate::eval::objects::object::apply_transform(&mut obj, &t);
                        light.looks_like = Some(Arc::new(obj));
                        Ok(())
                    }
                }
                Tok::Block("projected_through", Value::Object(o), span) => {
                    if light.projected_through.is_some() {
                        Err(given_twice("projected_through", span))
                    } else {
                        light.projected_through = Some(o);
                        Ok(())
                    }
                }
                Tok::Kw("shadowless", _) => {
                    light.shadowless = true;
                    Ok(())
                }
                Tok::Kw(kw @ ("media_interaction" | "media_attenuation"), span) => {
                    c.once(kw, span)?;
                    // `media_interaction [BOOL]`, `media_attenuation [BOOL]`: a
                    // keyword alone means on.
                    let on = if c.value_next() {
                        self.take_float(c, "on or off").map(|x| x > 0.0)?
                    } else {
                        true
                    };
                    if kw == "media_interaction" {
                        light.media_interaction = on;
                    } else {
                        light.media_attenuation = on;
                    }
                    Ok(())
                }
                Tok::Kw(kw, span) if TRANSFORMS.contains(&kw) => self
                    .transform_kw(kw, span, c)
                    .map(|t| move_light(&mut light, &mut transform, &t)),
                Tok::Block(_, Value::Transform(t), _) => {
                    move_light(&mut light, &mut transform, &t);
                    Ok(())
                }
                Tok::Block("photons", Value::Photons(b), span) => {
                    self.photons_for(&b, super::photons::PhotonsIn::Light, span);
                    light.photons = crate::scene::LightPhotons {
                        refraction: b.light_refraction.unwrap_or(true),
                        reflection: b.light_reflection.unwrap_or(true),
                        area_light: b.area_light,
                    };
                    Ok(())
                }
                other => Err(self.unexpected(c, &other, LIGHT_ITEMS)),
            };
            if let Err(f) = r {
                self.report(f);
            }
        }
        if let Some(a) = &mut light.area {
            for (kw, _) in &area_opts {
                match *kw {
                    "jitter" => a.jitter = true,
                    "circular" => a.circular = true,
                    "orient" => a.orient = true,
                    _ => a.adaptive = adaptive,
                }
            }
        } else if let Some((kw, span)) = area_opts.first() {
            self.report(
                Diagnostic::warning(
                    codes::IGNORED,
                    *span,
                    format!("`{kw}` only changes area lights; this light has no `area_light`"),
                )
                .with_help("add `area_light <1, 0, 0>, <0, 0, 1>, 5, 5` or remove it")
                .into(),
            );
        }
        match kind {
            Some(("spotlight", _)) => {
                let b = beam_from(&beam, Beam::SPOT);
                // Half-angles past 90° widen the cone beyond a hemisphere; POV-Ray
                // 3.7 takes them (its sample lights/laser.pov has falloff 100, and
                // 250) and so does the falloff rule in cos θ, which lights no more
                // than the half space in front of the spotlight whatever the angle.
                if b.radius >= 180.0 || b.falloff >= 180.0 {
                    let s = beam[0].or(beam[1]).map_or(c.span, |x| x.1);
                    self.report(
                        Diagnostic::warning(
                            codes::IGNORED,
                            s,
                            "a spotlight's radius and falloff are half-angles below 180 degrees",
                        )
                        .with_help(
                            "past 90 degrees a spotlight already lights the whole half space in front of it; 30 and 45 are the defaults",
                        )
                        .into(),
                    );
                }
                light.kind = LightKind::Spot(b);
            }
            Some(_) => light.kind = LightKind::Cylinder(beam_from(&beam, Beam::CYLINDER)),
            None => {
                if let Some((_, s)) = beam.iter().flatten().next() {
                    self.report(
                        Diagnostic::warning(
                            codes::IGNORED,
                            *s,
                            "radius, falloff and tightness only change spotlights and cylinder lights",
                        )
                        .with_help("add `spotlight` (or `cylinder`) to the light, or remove them")
                        .into(),
                    );
                }
            }
        }
        let aims = light.parallel || light.kind != LightKind::Point;
        if aims && (light.location - light.point_at).length_squared() == 0.0 {
            return Err(Diagnostic::error(
                codes::BAD_CAMERA,
                c.span,
                "the light's location equals its point_at",
            )
            .with_help(
                "parallel lights, spotlights and cylinder lights shine from location towards point_at: make them differ",
            )
            .into());
        }
        if let Some(obj) = &mut light.looks_like {
            let o = Arc::make_mut(obj);
            crate::eval::objects::object::apply_transform(o, &transform);
            o.flags.no_shadow = true;
        }
        if let Some(obj) = &mut light.projected_through {
            crate::eval::objects::object::apply_transform(Arc::make_mut(obj), &transform);
        }
        Ok(light)
    }

    /// `object { LIGHT_IDENTIFIER transforms }` (or `light_source { … }`): a
    /// declared light placed again, moved by the transforms (POV-Ray lights are
    /// objects). `c` starts at the light.
    pub(crate) fn light_object(&mut self, c: &mut Cursor) -> R<Light> {
        let Some(Tok::Val(Value::Light(l), _)) = c.next() else {
            unreachable!("called when the object block starts with a light");
        };
        let mut light = (*l).clone();
        let mut transform = Transform::IDENTITY;
        while let Some(tok) = c.next() {
            let r: R<()> = match tok {
                Tok::Kw(kw, span) if TRANSFORMS.contains(&kw) => self
                    .transform_kw(kw, span, c)
                    .map(|t| move_light(&mut light, &mut transform, &t)),
                Tok::Block(_, Value::Transform(t), _) => {
                    move_light(&mut light, &mut transform, &t);
                    Ok(())
                }
                other => Err(self.unexpected(c, &other, TRANSFORMS)),
            };
            if let Err(f) = r {
                self.report(f);
            }
        }
        for obj in [&mut light.looks_like, &mut light.projected_through]
            .into_iter()
            .flatten()
        {
            crate::eval::objects::object::apply_transform(Arc::make_mut(obj), &transform);
        }
        Ok(light)
    }

    /// `area_light AXIS1, AXIS2, N1, N2` after the keyword.
    fn area_light(&mut self, c: &mut Cursor, span: Span) -> R<AreaLight> {
        let axis1 = self.take_vec3(c, "the first axis of the area light")?;
        c.comma();
        let axis2 = self.take_vec3(c, "the second axis of the area light")?;
        c.comma();
        let (n1, s1) = c.value("the number of lights along the first axis")?;
        c.comma();
        let (n2, s2) = c.value("the number of lights along the second axis")?;
        let mut size = [1u32; 2];
        for (i, (v, s)) in [(n1, s1), (n2, s2)].into_iter().enumerate() {
            let n = self.to_float(&v, s)?;
            if !(1.0..=1024.0).contains(&n) {
                return Err(out_of_range(
                    s,
                    format!("an area light needs 1 to 1024 lights along each axis, found {n}"),
                    "5 × 5 (or 2^n + 1 with adaptive) is usual",
                ));
            }
            size[i] = n as u32;
        }
        if axis1.length_squared() == 0.0 || axis2.length_squared() == 0.0 {
            return Err(out_of_range(
                span,
                "an area light's axes must not be zero".into(),
                "give each axis the light's extent, e.g. `area_light <2, 0, 0>, <0, 0, 2>, 5, 5`",
            ));
        }
        Ok(AreaLight {
            axis1,
            axis2,
            size1: size[0],
            size2: size[1],
            jitter: false,
            adaptive: None,
            circular: false,
            orient: false,
        })
    }
}

/// Radius, falloff and tightness as written over `default`; POV-Ray widens a
/// falloff narrower than the radius to the radius.
fn beam_from(written: &[Option<(f64, Span)>; 3], default: Beam) -> Beam {
    let mut b = Beam {
        radius: written[0].map_or(default.radius, |x| x.0),
        falloff: written[1].map_or(default.falloff, |x| x.0),
        tightness: written[2].map_or(default.tightness, |x| x.0),
    };
    if b.falloff < b.radius {
        b.falloff = b.radius;
    }
    b
}

/// Moves `light` by `t` and appends `t` to `transform` (what its `looks_like`
/// object is moved by at the end).
fn move_light(light: &mut Light, transform: &mut Transform, t: &Transform) {
    transform_light(light, t);
    *transform = transform.then(t);
}

/// Takes the lights out of a placed object and its CSG members, each moved by the
/// transforms of the objects it was written in (innermost first), then `outer`.
pub(crate) fn take_lights(obj: &mut crate::scene::Object, outer: Option<&Transform>) -> Vec<Light> {
    // Members are shared with the declarations they came from: walk (and so
    // copy) them only when a light is among them.
    if !holds_lights(obj) {
        return Vec::new();
    }
    let t = match (&obj.transform, outer) {
        (Some(own), Some(o)) => Some(own.then(o)),
        (Some(own), None) => Some(**own),
        (None, Some(o)) => Some(*o),
        (None, None) => None,
    };
    let mut out = Vec::new();
    for mut l in std::mem::take(&mut obj.lights) {
        if let Some(t) = &t {
            transform_light(&mut l, t);
            for o in [&mut l.looks_like, &mut l.projected_through]
                .into_iter()
                .flatten()
            {
                let o = Arc::make_mut(o);
                o.transform = Some(Arc::new(match &o.transform {
                    Some(own) => own.then(t),
                    None => *t,
                }));
            }
        }
        out.push(l);
    }
    if let crate::scene::Shape::Union { children } | crate::scene::Shape::Csg { children, .. } =
        &mut obj.shape
    {
        for c in children {
            out.extend(take_lights(c, t.as_ref()));
        }
    }
    out
}

/// Whether `obj` or one of its CSG members holds a light.
fn holds_lights(obj: &crate::scene::Object) -> bool {
    !obj.lights.is_empty()
        || match &obj.shape {
            crate::scene::Shape::Union { children } | crate::scene::Shape::Csg { children, .. } => {
                children.iter().any(holds_lights)
            }
            _ => false,
        }
}

/// Moves a light's location, aim and area axes by `t`.
fn transform_light(light: &mut Light, t: &Transform) {
    light.location = t.point(light.location);
    light.point_at = t.point(light.point_at);
    if let Some(a) = &mut light.area {
        a.axis1 = t.vector(a.axis1);
        a.axis2 = t.vector(a.axis2);
    }
}
