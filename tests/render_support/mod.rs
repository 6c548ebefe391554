//! Scene-building helpers shared by the `render_*` tests.
#![allow(dead_code)]

use glam::DVec3;
use rts::scene::{
    Camera, Colour, Finish, Light, Object, Pattern, Pigment, Scene, Shape, Texture, Transform,
};
use rts::span::Span;
use std::sync::Arc;

/// An opaque solid pigment.
pub fn solid(rgb: DVec3) -> Pigment {
    Pigment {
        pattern: Pattern::Solid(Colour {
            rgb,
            filter: 0.0,
            transmit: 0.0,
        }),
        transform: None,
    }
}

/// A texture with a solid colour and a finish.
pub fn texture(rgb: DVec3, finish: Finish) -> Option<Arc<Texture>> {
    Some(Arc::new(Texture {
        pigment: solid(rgb),
        finish,
        ..Texture::default()
    }))
}

/// A finish with only ambient and diffuse set.
pub fn matte(ambient: f64, diffuse: f64) -> Finish {
    Finish {
        ambient: DVec3::splat(ambient),
        diffuse,
        ..Finish::default()
    }
}

/// An object with no transform, no texture and default flags.
pub fn object(shape: Shape) -> Object {
    Object::new(shape, Span::default())
}

/// A sphere object.
pub fn sphere(center: DVec3, radius: f64) -> Object {
    object(Shape::Sphere { center, radius })
}

/// A plane object.
pub fn plane(normal: DVec3, distance: f64) -> Object {
    object(Shape::Plane { normal, distance })
}

/// A box object.
pub fn cuboid(min: DVec3, max: DVec3) -> Object {
    object(Shape::Box { min, max })
}

/// A triangle object.
pub fn triangle(a: DVec3, b: DVec3, c: DVec3) -> Object {
    object(Shape::Triangle {
        vertices: [a, b, c],
        uv: None,
    })
}

/// `obj` with a texture.
pub fn with_texture(mut obj: Object, tex: Option<Arc<Texture>>) -> Object {
    obj.texture = tex;
    obj
}

/// `obj` with a transform.
pub fn with_transform(mut obj: Object, t: Transform) -> Object {
    obj.transform = Some(Arc::new(t));
    obj
}

/// A white point light.
pub fn point_light(location: DVec3) -> Light {
    Light {
        location,
        colour: DVec3::ONE,
        ..Light::default()
    }
}

/// A camera at `location` looking along +z with a square `size`×`size` view at
/// distance 1.
pub fn square_camera(location: DVec3, size: f64) -> Camera {
    Camera {
        location,
        direction: DVec3::Z,
        right: DVec3::X * size,
        up: DVec3::Y * size,
        ..Camera::default()
    }
}

/// A scene with the given camera and objects, no lights, black background,
/// `assumed_gamma 1`.
pub fn scene(camera: Camera, objects: Vec<Object>) -> Scene {
    let mut s = Scene {
        camera,
        objects,
        ..Scene::default()
    };
    s.global.assumed_gamma = Some(1.0);
    s
}

/// Renders `scene` (rts source) with the `rts` binary at `w`×`h`, linear 16-bit
/// output, and returns its pixels (row-major, channels in 0..1). Files go to
/// `CARGO_TARGET_TMPDIR/<group>/<name>.{rts,png}`.
pub fn render_source(group: &str, name: &str, scene: &str, w: u32, h: u32) -> Vec<[f64; 3]> {
    let dir = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(group);
    std::fs::create_dir_all(&dir).expect("temp dir");
    let src = dir.join(format!("{name}.rts"));
    let out = dir.join(format!("{name}.png"));
    std::fs::write(&src, scene).expect("write scene");
    let status = std::process::Command::new(env!("CARGO_BIN_EXE_rts"))
        .arg("render")
        .arg(&src)
        .arg("-o")
        .arg(&out)
        .args(["-W", &w.to_string(), "-H", &h.to_string(), "-q"])
        .args(["--gamma", "1.0", "--bit-depth", "16"])
        .status()
        .expect("run rts");
    assert!(status.success(), "render {name}");
    let img = image::open(&out).expect("read png").to_rgb16();
    img.pixels()
        .map(|p| [0, 1, 2].map(|i| f64::from(p[i]) / 65535.0))
        .collect()
}
