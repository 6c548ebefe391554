//! Analytic render checks of textures: transparency (filter and transmit),
//! filtered shadows, layered textures and a pattern's values across the image.

mod render_support;

/// Renders `scene` at `w`×`h` with linear output and returns its pixels in 0..1.
fn render(name: &str, scene: &str, w: u32, h: u32) -> (u32, Vec<[f64; 3]>) {
    let px = render_support::render_source("render_textures", name, scene, w, h);
    (w, px)
}

fn close(a: [f64; 3], b: [f64; 3], tol: f64) -> bool {
    (0..3).all(|i| (a[i] - b[i]).abs() <= tol)
}

const CAMERA: &str = "global_settings { assumed_gamma 1.0 }\n\
    camera { location <0, 0, -10> direction z*10 right x*4 up y*4 }\n\
    light_source { <0, 0, -100> rgb 1 }\n";

#[test]
fn filter_and_transmit_let_light_through() {
    // A white backdrop seen through a red filtering sheet (left) and a half
    // transmitting blue sheet (right).
    let scene = format!(
        "{CAMERA}plane {{ z, 5 pigment {{ rgb 1 }} finish {{ ambient 1 diffuse 0 }} }}\n\
         box {{ <-2, -2, -1>, <0, 2, -0.9> pigment {{ rgbf <1, 0, 0, 1> }} finish {{ ambient 1 diffuse 0 }} }}\n\
         box {{ <0, -2, -1>, <2, 2, -0.9> pigment {{ rgbt <0, 0, 1, 0.5> }} finish {{ ambient 1 diffuse 0 }} }}\n"
    );
    let (w, px) = render("transparency", &scene, 8, 8);
    let at = |x: u32, y: u32| px[(y * w + x) as usize];
    // Full filter: the colour passes tinted, the surface itself adds nothing.
    assert!(close(at(1, 4), [1.0, 0.0, 0.0], 1e-3), "{:?}", at(1, 4));
    // Transmit 0.5 on both faces of the box: half the surface colour plus half
    // of (half the colour plus half the backdrop).
    assert!(close(at(6, 4), [0.25, 0.25, 1.0], 1e-3), "{:?}", at(6, 4));
}

#[test]
fn transmit_above_one_amplifies_the_light_behind() {
    // POV-Ray does not clamp the opacity 1 − filter − transmit: a sheet of rgb
    // 0.5 with transmit 2 in front of a 0.3 backdrop gives 2·0.3 − 0.5·1 = 0.1
    // (measured with POV-Ray 3.7; advanced/bwstripe.pov's threshold lens).
    // A disc is one surface, so the light crosses it once.
    let scene = format!(
        "{CAMERA}plane {{ z, 5 pigment {{ rgb 0.3 }} finish {{ ambient 1 diffuse 0 }} }}\n\
         disc {{ <0, 0, -1>, z, 5 pigment {{ rgbt <0.5, 0.5, 0.5, 2> }} finish {{ ambient 1 diffuse 0 }} }}\n"
    );
    let (w, px) = render("transmit_above_one", &scene, 4, 4);
    let c = px[(2 * w + 2) as usize];
    assert!(close(c, [0.1, 0.1, 0.1], 2e-3), "{c:?}");
}

#[test]
fn filter_hides_surface_light_by_the_colours_largest_component() {
    // POV-Ray scales a filtering surface's own light by 1 − filter·max(r, g, b)
    // − transmit (measured with POV-Ray 3.7): rgbf <0.2, 0.6, 0.3, 0.5> over
    // black keeps 0.7 of its colour; over white it adds filter · colour.
    for (backdrop, want) in [(0.0, [0.14, 0.42, 0.21]), (1.0, [0.24, 0.72, 0.36])] {
        let scene = format!(
            "{CAMERA}plane {{ z, 5 pigment {{ rgb {backdrop} }} finish {{ ambient 1 diffuse 0 }} }}\n\
             disc {{ <0, 0, -1>, z, 5 pigment {{ rgbf <0.2, 0.6, 0.3, 0.5> }} finish {{ ambient 1 diffuse 0 }} }}\n"
        );
        let (w, px) = render(&format!("filter_max_{backdrop}"), &scene, 4, 4);
        let c = px[(2 * w + 2) as usize];
        assert!(close(c, want, 2e-3), "backdrop {backdrop}: {c:?}");
    }
}

#[test]
fn quick_color_keeps_the_pigment_in_force() {
    // `pigment { quick_color … }` inside a texture only sets the preview colour
    // (advanced/chess2.pov): the declared texture's pigment stays.
    let scene = format!(
        "{CAMERA}#declare T = texture {{ pigment {{ rgb <0, 1, 0> }} finish {{ ambient 1 diffuse 0 }} }}\n\
         plane {{ z, 0 texture {{ T pigment {{ quick_color rgb <1, 0, 0> }} }} }}\n"
    );
    let (w, px) = render("quick_color", &scene, 4, 4);
    let c = px[(2 * w + 2) as usize];
    assert!(close(c, [0.0, 1.0, 0.0], 1e-3), "{c:?}");
}

#[test]
fn shadows_through_filtering_surfaces_are_coloured() {
    // A floor lit straight from above through a green filter sheet.
    let scene = "global_settings { assumed_gamma 1.0 }\n\
        camera { location <0, 10, 0> direction y*-10 right x*2 up z*2 }\n\
        light_source { <0, 100, 0> rgb 1 }\n\
        plane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }\n\
        box { <-50, 5, -50>, <50, 5.1, 50> pigment { rgbf <0.2, 1, 0.2, 1> } finish { ambient 0 diffuse 0 } no_image }\n";
    let (w, px) = render("filtered_shadow", scene, 4, 4);
    let c = px[(2 * w + 2) as usize];
    // Light through the sheet: filter · colour = (0.2, 1, 0.2), crossed twice
    // (two faces of the box): (0.04, 1, 0.04).
    assert!(close(c, [0.04, 1.0, 0.04], 2e-3), "{c:?}");
}

#[test]
fn layered_texture_shows_the_lower_layer_through_clear_parts() {
    let scene = format!(
        "{CAMERA}plane {{ z, 0\n\
           texture {{ pigment {{ rgb <0, 0, 1> }} finish {{ ambient 1 diffuse 0 }} }}\n\
           texture {{ pigment {{ gradient x color_map {{ [0.5 rgbt <1, 0, 0, 0>] [0.5 rgbt <1, 1, 1, 1>] }} }} finish {{ ambient 1 diffuse 0 }} }}\n\
         }}\n"
    );
    let (w, px) = render("layers", &scene, 8, 8);
    // x in [0, 0.5): red top layer; x in [0.5, 1): clear, so the blue layer below.
    let red = px[(4 * w + 4) as usize]; // x ≈ 0.25
    let blue = px[(4 * w + 5) as usize]; // x ≈ 0.75
    assert!(close(red, [1.0, 0.0, 0.0], 1e-3), "{red:?}");
    assert!(close(blue, [0.0, 0.0, 1.0], 1e-3), "{blue:?}");
}

#[test]
fn gradient_values_follow_x() {
    let scene = format!(
        "{CAMERA}plane {{ z, 0 pigment {{ gradient x scale 4 translate -2*x }} finish {{ ambient 1 diffuse 0 }} }}\n"
    );
    let (w, px) = render("gradient", &scene, 16, 2);
    for i in 0..w {
        // Pixel centre x = -2 + (i + 0.5) / 4, value (x + 2) / 4.
        let want = (f64::from(i) + 0.5) / 16.0;
        assert!(
            (px[i as usize][0] - want).abs() < 1e-3,
            "{i}: {:?}",
            px[i as usize]
        );
    }
}

/// Two textures with different finishes: red lit only by `ambient 1`, green by
/// `ambient 0.5` (no diffuse, so the light does not matter).
const TWO_FINISHES: &str =
    "#declare T1 = texture { pigment { rgb <1, 0, 0> } finish { ambient 1 diffuse 0 } }\n\
    #declare T2 = texture { pigment { rgb <0, 1, 0> } finish { ambient 0.5 diffuse 0 } }\n";

#[test]
fn checker_texture_picks_each_squares_texture() {
    // A plane seen straight on, checker squares of side 1 (the image spans
    // [-2, 2]²): the unit square at the origin takes the first texture.
    let scene = format!(
        "{CAMERA}{TWO_FINISHES}plane {{ z, 0 texture {{ checker texture {{ T1 }} texture {{ T2 }} }} }}\n"
    );
    let (w, px) = render("checker_textures", &scene, 8, 8);
    for y in 0..8u32 {
        for x in 0..8u32 {
            let (px_x, px_y) = (
                -2.0 + (f64::from(x) + 0.5) / 2.0,
                2.0 - (f64::from(y) + 0.5) / 2.0,
            );
            let odd = (px_x.floor() + px_y.floor()).rem_euclid(2.0) != 0.0;
            let want = if odd {
                [0.0, 0.5, 0.0]
            } else {
                [1.0, 0.0, 0.0]
            };
            let got = px[(y * w + x) as usize];
            assert!(close(got, want, 1e-3), "({x}, {y}): {got:?}, want {want:?}");
        }
    }
}

#[test]
fn texture_map_blends_shaded_colours_linearly() {
    // gradient x across the image: value (x + 2) / 4, from T1 at 0 to T2 at 1;
    // the 15 pixels' centres take values (i + 0.5) / 15, the middle one 0.5.
    let scene = format!(
        "{CAMERA}{TWO_FINISHES}plane {{ z, 0 texture {{ gradient x texture_map {{ [0 T1] [1 T2] }} scale 4 translate -2*x }} }}\n"
    );
    let (w, px) = render("texture_map_blend", &scene, 15, 1);
    for i in 0..w {
        let v = (f64::from(i) + 0.5) / 15.0;
        let want = [1.0 - v, 0.5 * v, 0.0];
        let got = px[i as usize];
        assert!(close(got, want, 1e-3), "{i}: {got:?}, want {want:?}");
    }
    // The midpoint is the average of the two textures' shaded colours.
    assert!(close(px[7], [0.5, 0.25, 0.0], 1e-3), "{:?}", px[7]);
}

#[test]
fn texture_map_entry_may_be_layered_and_patterned() {
    // Below 0.5 a layered texture (blue under a clear top layer), above it a
    // nested checker of textures; transforms of the outer texture move both.
    let scene = format!(
        "{CAMERA}{TWO_FINISHES}#declare Layered = texture {{ pigment {{ rgb <0, 0, 1> }} finish {{ ambient 1 diffuse 0 }} }}\n\
           texture {{ pigment {{ rgbt 1 }} }}\n\
         #declare Tiles = texture {{ checker texture {{ T1 }} texture {{ T2 }} }}\n\
         plane {{ z, 0 texture {{ gradient x texture_map {{ [0.5 Layered] [0.5 Tiles] }} scale 4 translate -2*x }} }}\n"
    );
    let (w, px) = render("texture_map_nested", &scene, 8, 8);
    let at = |x: u32, y: u32| px[(y * w + x) as usize];
    // Left half: the layered texture's blue.
    assert!(close(at(1, 1), [0.0, 0.0, 1.0], 1e-3), "{:?}", at(1, 1));
    // Right half: the checker, scaled and moved with the map (cells of side 4
    // with a corner at x = -2, y = 0): the upper right quarter lies in the cell
    // of the first texture, the lower right in the cell below it (the second).
    assert!(close(at(6, 1), [1.0, 0.0, 0.0], 1e-3), "{:?}", at(6, 1));
    assert!(close(at(6, 6), [0.0, 0.5, 0.0], 1e-3), "{:?}", at(6, 6));
}

#[test]
fn path_tracer_picks_textures_by_pattern_and_blend_weight() {
    // Emission seen directly. Upper half: a checker of two emitting textures, each
    // square exactly its own. Lower half: a texture_map from one to the other
    // across the image, where each sample picks one entry with the blend weight as
    // probability, so the pixels average to the blend.
    let scene = "global_settings { assumed_gamma 1.0 path_tracing { samples 256 pixel_filter \"box\" } }\n\
        camera { location <0, 0, -10> direction z*10 right x*4 up y*4 }\n\
        #declare E1 = texture { pigment { rgb <1, 0, 0> } finish { emission 1 diffuse 0 } }\n\
        #declare E2 = texture { pigment { rgb <0, 1, 0> } finish { emission 1 diffuse 0 } }\n\
        plane { z, 0 texture { checker texture { E1 } texture { E2 } } clipped_by { plane { -y, 0 } } }\n\
        plane { z, 0 texture { gradient x texture_map { [0 E1] [1 E2] } scale 4 translate -2*x } clipped_by { plane { y, 0 } } }\n";
    let (w, px) = render("path_patterned", scene, 8, 8);
    let at = |x: u32, y: u32| px[(y * w + x) as usize];
    // Pixel (4, 3) covers [0, 0.5] × [0, 0.5]; (6, 3) has x in [1, 1.5]; (4, 1)
    // has y in [1, 1.5].
    assert!(close(at(4, 3), [1.0, 0.0, 0.0], 1e-4), "{:?}", at(4, 3));
    assert!(close(at(6, 3), [0.0, 1.0, 0.0], 1e-4), "{:?}", at(6, 3));
    assert!(close(at(4, 1), [0.0, 1.0, 0.0], 1e-4), "{:?}", at(4, 1));
    for x in 0..w {
        let v = (f64::from(x) + 0.5) / 8.0;
        let got = at(x, 6);
        assert!(
            close(got, [1.0 - v, v, 0.0], 0.08),
            "{x}: {got:?}, want {v}"
        );
        assert!((got[0] + got[1] - 1.0).abs() < 1e-4, "{x}: {got:?}");
    }
}

#[test]
fn pigments_a_macro_writes_into_a_texture_read_its_parameters() {
    // POV-Ray's Basic_Scenes templates: a macro whose body is a bare `pigment`
    // used inside `texture { }`. The block modifies the texture's pigment, so it
    // is read after the texture is complete, when the macro has returned; it
    // must still see the macro's parameters and locals.
    let scene = format!(
        "{CAMERA}#macro Tint(C) #local Half = C / 2; pigment {{ rgb Half }} #end\n\
         #macro Glow(A) finish {{ ambient A diffuse 0 }} #end\n\
         box {{ <-2, -2, 0>, <0, 2, 1> texture {{ Tint(<0, 2, 0>) Glow(1) }} }}\n\
         box {{ <0, -2, 0>, <2, 2, 1> Tint(<0, 0, 1.6>) Glow(0.5) }}\n"
    );
    let (w, px) = render("macro_pigments", &scene, 8, 8);
    let at = |x: u32, y: u32| px[(y * w + x) as usize];
    assert!(close(at(1, 4), [0.0, 1.0, 0.0], 1e-3), "{:?}", at(1, 4));
    assert!(close(at(6, 4), [0.0, 0.0, 0.4], 1e-3), "{:?}", at(6, 4));
}

#[test]
fn pattern_normals_are_as_strong_as_povray_s() {
    // A white plane seen from above, lit at 45°: the spread of its brightness
    // measures how far a normal pattern leans the surface. POV-Ray 3.7's values
    // (200x200, measured once): bozo 0.5 gives 0.0127, granite 0.5 0.149,
    // agate 0.5 0.164, wrinkles 0.5 0.040, dents 0.5 0.024, waves 0.5 0.152,
    // waves 0.5 frequency 2 0.1215 (waves tilt by their own spacing, not by
    // frequency), ripples 0.5 0.0586.
    let cases = [
        ("bozo 0.5", 0.0127),
        ("waves 0.5", 0.152),
        ("waves 0.5 frequency 2", 0.1215),
        ("ripples 0.5", 0.0586),
        ("granite 0.5", 0.149),
        ("agate 0.5", 0.164),
        ("wrinkles 0.5", 0.040),
        ("dents 0.5", 0.024),
    ];
    for (i, (normal, want)) in cases.into_iter().enumerate() {
        let scene = format!(
            "global_settings {{ assumed_gamma 1.0 }}\n\
             camera {{ orthographic location <0, 10, 0> look_at 0 right x*8 up z*8 sky z }}\n\
             light_source {{ <100, 100, 0> color rgb 1 parallel point_at 0 }}\n\
             plane {{ y, 0 pigment {{ rgb 1 }} finish {{ ambient 0 diffuse 1 }} normal {{ {normal} }} }}\n"
        );
        let (_, px) = render(&format!("normal_strength_{i}"), &scene, 100, 100);
        let n = px.len() as f64;
        let mean = px.iter().map(|p| p[0]).sum::<f64>() / n;
        let sd = (px.iter().map(|p| (p[0] - mean).powi(2)).sum::<f64>() / n).sqrt();
        assert!(
            (sd / want - 1.0).abs() < 0.25,
            "{normal}: deviation {sd:.4}, POV-Ray {want}"
        );
    }
}

/// A quad from -1 to 1 in x and y with uv coordinates from 0 to 1, in a mesh.
const UV_QUAD: &str = "#declare Quad = mesh {\n\
    triangle { <-1, -1, 0>, <1, -1, 0>, <1, 1, 0> uv_vectors <0, 0>, <1, 0>, <1, 1> }\n\
    triangle { <-1, -1, 0>, <1, 1, 0>, <-1, 1, 0> uv_vectors <0, 0>, <1, 1>, <0, 1> }\n\
    }\n\
    #declare Ramp = pigment { uv_mapping gradient x color_map { [0 rgb 0] [1 rgb 1] } }\n";

#[test]
fn uv_mapping_moves_with_the_transforms_of_its_own_block_only() {
    // Measured on POV-Ray 3.7: a scale written in the pigment that holds
    // `uv_mapping` repeats the ramp over the quad; one applied to the texture, to
    // a declared pigment where it is used, or to the object does not.
    let f = "finish { ambient 1 diffuse 0 }";
    let rows = [
        format!("mesh {{ Quad pigment {{ uv_mapping gradient x color_map {{ [0 rgb 0] [1 rgb 1] }} scale 0.5 }} {f} }}"),
        format!("mesh {{ Quad texture {{ pigment {{ Ramp }} scale 0.5 {f} }} }}"),
        format!("mesh {{ Quad pigment {{ Ramp scale 0.5 }} {f} }}"),
        format!("mesh {{ Quad pigment {{ Ramp }} {f} scale <1, 1, 1> scale 0.999 }}"),
        format!("mesh {{ Quad texture {{ uv_mapping pigment {{ gradient x color_map {{ [0 rgb 0] [1 rgb 1] }} }} scale 0.5 {f} }} }}"),
    ];
    for (i, obj) in rows.iter().enumerate() {
        let scene = format!(
            "global_settings {{ assumed_gamma 1.0 }}\n\
             camera {{ orthographic location <0, 0, -5> look_at 0 right x*2 up y*2 }}\n\
             {UV_QUAD}{obj}\n"
        );
        let (w, px) = render(&format!("uv_mapping_{i}"), &scene, 16, 2);
        let repeats = if i == 0 || i == 4 { 2.0 } else { 1.0 };
        for x in 0..w {
            let u = (f64::from(x) + 0.5) / f64::from(w);
            let want = (u * repeats).fract();
            let got = px[(w + x) as usize][0];
            assert!(
                (got - want).abs() < 0.01,
                "{obj}: pixel {x} is {got}, want {want}"
            );
        }
    }
}

#[test]
fn a_scene_without_version_or_assumed_gamma_is_written_without_gamma() {
    // POV-Ray 3.7 turns gamma handling off in a scene with neither `#version 3.7`
    // nor `assumed_gamma` (measured: a 0-1 ramp is written as a linear ramp of
    // file values); `#version 3.7` alone assumes 1.0 and writes sRGB.
    let body = "camera { orthographic location <0, 0, -5> look_at 0 right x*2 up y*2 }\n\
        plane { z, 0 pigment { gradient x color_map { [0 rgb 0] [1 rgb 1] } scale 2 translate -x }\n\
        finish { ambient 1 diffuse 0 } }\n";
    for (name, head, linear) in [
        ("gamma_none", "", true),
        ("gamma_v36", "#version 3.6;\n", true),
        ("gamma_v37", "#version 3.7;\n", false),
        ("gamma_inc", "#include \"colors.inc\"\n", false),
    ] {
        let dir = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("render_textures");
        std::fs::create_dir_all(&dir).expect("temp dir");
        let src = dir.join(format!("{name}.rts"));
        let out = dir.join(format!("{name}.png"));
        std::fs::write(&src, format!("{head}{body}")).expect("write scene");
        let status = std::process::Command::new(env!("CARGO_BIN_EXE_rts"))
            .arg("render")
            .arg(&src)
            .arg("-o")
            .arg(&out)
            .args(["-W", "16", "-H", "2", "-q", "--bit-depth", "16"])
            .status()
            .expect("run rts");
        assert!(status.success(), "render {name}");
        let img = image::open(&out).expect("read png").to_rgb16();
        // Pixel 4 of 16: working value 0.28125.
        let v = f64::from(img.get_pixel(4, 1)[0]) / 65535.0;
        let want = if linear { 0.28125 } else { 0.5669 };
        assert!((v - want).abs() < 0.005, "{name}: {v}, want {want}");
    }
}

#[test]
fn interior_fade_follows_povray_s_two_laws() {
    // A clear slab 1 unit thick in front of a white backdrop (seen head on, so
    // the light crosses about 1 unit: the pixel is a little off axis). POV-Ray 3.7 (measured): fade_power 2
    // leaves 1 / (1 + (d/D)²); a power of 1000 or more is exponential,
    // exp(−d/D). glass.inc's I_Glass3 is the exponential kind with D = 1.
    let slab = |i: &str| {
        format!(
            "#include \"glass.inc\"\n{CAMERA}plane {{ z, 5 pigment {{ rgb 1 }} finish {{ ambient 1 diffuse 0 }} }}\n\
             box {{ <-3, -3, -0.5>, <3, 3, 0.5> pigment {{ rgbf 1 }} finish {{ ambient 0 diffuse 0 }} interior {{ {i} }} }}\n"
        )
    };
    for (name, interior, want) in [
        ("fade_sqr", "ior 1.5 fade_distance 2 fade_power 2", 0.8),
        (
            "fade_exp",
            "ior 1.5 fade_distance 0.5 fade_power 1001",
            (-2.0f64).exp(),
        ),
        ("fade_glass3", "I_Glass3", (-1.0f64).exp()),
        ("fade_macro", "I_Glass_Exp(2)", (-0.5f64).exp()),
    ] {
        let (w, px) = render(name, &slab(interior), 4, 4);
        let c = px[(2 * w + 2) as usize];
        assert!(close(c, [want; 3], 1e-3), "{name}: {c:?} want {want}");
    }
}

#[test]
fn shadows_through_fading_interiors_fade_by_the_stretch_inside() {
    // A clear slab 1 unit thick, 2 above a white floor, lit at 45 degrees: the
    // floor below the camera is lit through √2 units of glass, and the camera's
    // own ray misses the slab. POV-Ray 3.7 (measured): cos 45° · exp(−√2) for
    // exponential fade over 1 unit, cos 45° / (1 + (√2/2)²) for power 2 over 2
    // units, and a fade_color lets its own colour through.
    let scene = |i: &str| {
        format!(
            "global_settings {{ assumed_gamma 1.0 }}\n\
             camera {{ orthographic location <0, 10, 0> look_at 0 right x*0.2 up z*0.2 }}\n\
             light_source {{ <0, 100, -100> rgb 1 parallel point_at 0 }}\n\
             plane {{ y, 0 pigment {{ rgb 1 }} finish {{ ambient 0 diffuse 1 }} }}\n\
             box {{ <-3, 2, -6>, <3, 3, -1.5> pigment {{ rgbf 1 }} finish {{ ambient 0 diffuse 0 }} interior {{ {i} }} }}\n"
        )
    };
    let c = std::f64::consts::FRAC_1_SQRT_2;
    let e = (-std::f64::consts::SQRT_2).exp();
    for (name, interior, want) in [
        (
            "shadow_fade_exp",
            "ior 1.5 fade_distance 1 fade_power 1001",
            [c * e; 3],
        ),
        (
            "shadow_fade_sqr",
            "ior 1.5 fade_distance 2 fade_power 2",
            [c / 1.5; 3],
        ),
        (
            "shadow_fade_colour",
            "ior 1.5 fade_distance 1 fade_power 1001 fade_color rgb <0, 0, 1>",
            [c * e, c * e, c],
        ),
    ] {
        let (w, px) = render(name, &scene(interior), 4, 4);
        let got = px[(2 * w + 2) as usize];
        assert!(close(got, want, 2e-4), "{name}: {got:?} want {want:?}");
    }
}

#[test]
fn passing_straight_through_costs_no_trace_level() {
    // 50 thin slabs (100 surfaces) in front of a red backdrop under
    // `max_trace_level 3`, each letting 0.99 through. POV-Ray 3.7 (measured):
    // without a change of `ior` every surface is crossed and 0.99^100 of the red
    // arrives; with `ior 1.01` the rays bend, count levels and end black.
    let scene = |interior: &str| {
        format!(
            "global_settings {{ assumed_gamma 1.0 max_trace_level 3 }}\n\
             camera {{ orthographic location <0, 0, -10> look_at 0 right x*4 up y*3 }}\n\
             background {{ rgb <1, 0, 0> }}\n\
             #for (I, 0, 49)\n\
             box {{ <-100, -100, I*0.02>, <100, 100, I*0.02 + 0.01> pigment {{ rgbt <0, 0, 0, 0.99> }} \
             finish {{ ambient 0 diffuse 0 }} {interior} }}\n\
             #end\n"
        )
    };
    let (w, px) = render("passes_clear", &scene(""), 4, 4);
    let c = px[(2 * w + 2) as usize];
    let want = 0.99f64.powi(100);
    assert!(close(c, [want, 0.0, 0.0], 2e-3), "clear: {c:?} want {want}");
    let (w, px) = render("passes_bent", &scene("interior { ior 1.01 }"), 4, 4);
    let c = px[(2 * w + 2) as usize];
    assert!(close(c, [0.0; 3], 1e-3), "bent: {c:?}");
}

#[test]
fn a_37_scene_scales_a_filtering_surface_s_own_light_by_one_minus_filter() {
    // A filtering slab (ambient 1) over black, seen head on. POV-Ray 3.7
    // (measured): with `#version 3.7` its own light is scaled by 1 - filter -
    // transmit; without a version (or before 3.7) by 1 - filter·max(r, g, b) -
    // transmit. The back face adds its light filtered by the front.
    let scene = |version: &str| {
        format!(
            "{version}global_settings {{ assumed_gamma 1.0 }}\n\
             camera {{ orthographic location <0, 0, -5> look_at 0 right x*2 up y*2 }}\n\
             box {{ <-1, -1, -0.1>, <1, 1, 0.1> pigment {{ rgbf <0.4, 0.9, 0.5, 0.85> }}\n\
             finish {{ ambient 1 diffuse 0 }} interior {{ ior 1.33 }} }}\n"
        )
    };
    for (name, version, want) in [
        ("filter_37", "#version 3.7;\n", [0.0804, 0.2383, 0.1069]),
        ("filter_legacy", "", [0.1260, 0.3733, 0.1674]),
    ] {
        let (w, px) = render(name, &scene(version), 4, 4);
        let c = px[(2 * w + 2) as usize];
        assert!(close(c, want, 2e-4), "{name}: {c:?} want {want:?}");
    }
}

#[test]
fn a_ray_meeting_another_object_inside_a_fading_interior_is_not_faded() {
    // A clear fading box (fade over 1 unit, power 2) seen from above, an
    // ambient-lit floor below. POV-Ray 3.7 (measured): a floor halfway up
    // inside the box shows at full brightness; one just below the box, reached
    // after the ray leaves through the box's bottom, is faded by 1/(1 + 1²).
    let scene = |floor: f64| {
        format!(
            "#version 3.7;\nglobal_settings {{ assumed_gamma 1.0 }}\n\
             camera {{ orthographic location <0, 10, 0> look_at 0 right x*0.2 up z*0.2 }}\n\
             plane {{ y, {floor} pigment {{ rgb 1 }} finish {{ ambient 1 diffuse 0 }} }}\n\
             box {{ <-3, 0, -3>, <3, 1, 3> pigment {{ rgbt 1 }} finish {{ ambient 0 diffuse 0 }}\n\
             interior {{ ior 1.0 fade_distance 1 fade_power 2 }} }}\n"
        )
    };
    for (name, floor, want) in [("fade_inside", 0.5, 1.0), ("fade_below", -0.001, 0.5)] {
        let (w, px) = render(name, &scene(floor), 4, 4);
        let c = px[(2 * w + 2) as usize];
        assert!(close(c, [want; 3], 2e-3), "{name}: {c:?} want {want}");
    }
}

#[test]
fn total_internal_reflection_returns_all_its_light() {
    // A clear box (transmit 0.9, ior 1.45) turned 30 degrees before an
    // ambient-lit white wall: rays reflected inside its left face by total
    // internal reflection. POV-Ray 3.7 (measured, 64 × 48, pixel (12, 20)):
    // 0.2283 of red, where scaling the reflected light by the transmit as
    // ordinary refraction would gives 0.9 × that.
    let scene = "#version 3.7;\nglobal_settings { assumed_gamma 1.0 max_trace_level 8 }\n\
        camera { location <0, 0, -8> look_at 0 angle 30 }\n\
        plane { z, 5 pigment { rgb 1 } finish { ambient 1 diffuse 0 } }\n\
        box { <-1, -1, -1>, <1, 1, 1> rotate y*30 pigment { rgbt <1, 1, 1, 0.9> } finish { ambient 0 diffuse 0 }\n\
        interior { ior 1.45 fade_distance 0.8 fade_power 2 fade_color <0.2, 0.4, 0.9> } }\n";
    let (w, px) = render("tir_weight", scene, 64, 48);
    let c = px[(20 * w + 12) as usize];
    assert!(close(c, [0.2283, 0.3606, 0.7296], 2e-3), "{c:?}");
}

#[test]
fn cells_hold_one_value_per_unit_cube() {
    // `cells` over x in [0, 4): four unit cells, each one flat grey in [0, 1),
    // not all the same (the cells are POV-Ray's; the values are rts's own).
    let scene = "#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\n\
        camera { orthographic location <2, 0.5, -5> look_at <2, 0.5, 0> right x*4 up y*1 }\n\
        plane { z, 0.5 pigment { cells color_map { [0 rgb 0] [1 rgb 1] } } finish { ambient 1 diffuse 0 } }\n";
    let (_, px) = render("cells", scene, 16, 4);
    let cell: Vec<f64> = (0..4).map(|k| px[4 * k][0]).collect();
    for k in 0..4 {
        for i in 0..4 {
            assert!(
                (px[4 * k + i][0] - cell[k]).abs() < 1e-9,
                "cell {k} not flat"
            );
        }
        assert!((0.0..1.0).contains(&cell[k]), "{cell:?}");
    }
    assert!(
        cell.windows(2).any(|w| (w[0] - w[1]).abs() > 0.01),
        "{cell:?}"
    );
}

/// POV-Ray's object pattern: the second entry inside the object, the first
/// outside, for pigments, textures and with a transformed object.
#[test]
fn object_pattern_picks_the_inside_entry() {
    let scene = "#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <0, 0, -5> look_at 0 right x*4 up y*3 }
#declare S = sphere { 0, 1 }
plane { z, 0
  pigment { object { S color rgb <1, 0, 0>, color rgb <0, 0, 1> } }
  finish { ambient 1 diffuse 0 } }
box { <1, -1.5, -0.1>, <2, 1.5, 0>
  texture { object { box { <-1, -1, -1>, <1, 0, 1> } translate x*1.5
    texture { pigment { rgb 1 } finish { ambient 1 diffuse 0 } },
    texture { pigment { rgb <0, 1, 0> } finish { ambient 1 diffuse 0 } } } } }";
    let px = render_support::render_source("object_pattern", "object", scene, 40, 30);
    let at = |x: usize, y: usize| px[y * 40 + x];
    assert_eq!(at(20, 15), [0.0, 0.0, 1.0], "inside the sphere");
    assert_eq!(at(3, 3), [1.0, 0.0, 0.0], "outside the sphere");
    assert_eq!(at(35, 20), [0.0, 1.0, 0.0], "inside the box (lower half)");
    assert_eq!(at(35, 5), [1.0, 1.0, 1.0], "outside the box (upper half)");
}

/// A clear box of `ior 1.5` in front of a checkerboard, optionally holding a
/// sphere.
fn nested_glass(inner: &str) -> String {
    format!(
        "#version 3.7;
global_settings {{ assumed_gamma 1.0 max_trace_level 10 }}
camera {{ location <0, 0, -5> look_at 0 angle 30 }}
plane {{ z, 3 pigment {{ checker rgb 1 rgb 0 scale 0.3 }} finish {{ ambient 1 diffuse 0 }} }}
box {{ -1, 1 pigment {{ rgbf 1 }} finish {{ ambient 0 diffuse 0 }} interior {{ ior 1.5 }} }}
{inner}"
    )
}

#[test]
fn nested_interiors_refract_by_the_ratio_of_their_indices() {
    // Measured on POV-Ray 3.7: a sphere of the glass's own index inside it is
    // invisible (no change of index at its surface); one of another index is not.
    let sphere = |ior: f64| {
        format!(
            "sphere {{ 0, 0.6 pigment {{ rgbf 1 }} finish {{ ambient 0 diffuse 0 }} interior {{ ior {ior} }} }}"
        )
    };
    let (_, alone) = render("nest_alone", &nested_glass(""), 48, 48);
    let (_, same) = render("nest_same", &nested_glass(&sphere(1.5)), 48, 48);
    let (_, other) = render("nest_other", &nested_glass(&sphere(1.2)), 48, 48);
    assert_eq!(alone, same);
    assert_ne!(alone, other);
}

#[test]
fn diffuse_back_lights_a_thin_sheet_from_behind() {
    // POV-Ray 3.7's `diffuse D, BACK`: a light behind a disc shows through it
    // by BACK times the cosine (measured: 61, 46, 31 of 255 here in both).
    let scene = |diffuse: &str| {
        format!(
            "global_settings {{ assumed_gamma 1.0 }}
camera {{ location <0, 0, -5> look_at 0 angle 20 }}
light_source {{ <0, 0, 10> rgb 1 }}
disc {{ 0, z, 2 pigment {{ rgb <0.8, 0.6, 0.4> }} finish {{ ambient 0 diffuse {diffuse} }} }}"
        )
    };
    let (w, lit) = render("diffuse_back", &scene("0.5, 0.3"), 20, 20);
    let centre = lit[(10 * w + 10) as usize];
    assert!(close(centre, [0.24, 0.18, 0.12], 0.01), "{centre:?}");
    let (_, dark) = render("diffuse_front", &scene("0.5"), 20, 20);
    assert!(close(dark[(10 * w + 10) as usize], [0.0; 3], 1e-6));
}

#[test]
fn reflection_exponent_raises_the_reflected_colour() {
    // POV-Ray 3.7 (measured, 8-bit): a mirror of reflection 0.5 over a
    // background of 0.25 shows 0.090 with exponent 0.8 and 0.031 with 0.5, of
    // 0.5 shows 0.212 and 0.125: amount · colour^(1 / exponent).
    for (b, e, want) in [
        (0.25, 0.8, 0.0884),
        (0.25, 0.5, 0.03125),
        (0.5, 0.8, 0.2102),
        (0.5, 0.5, 0.125),
    ] {
        for form in [
            format!("reflection {{ 0.5 exponent {e} }}"),
            format!("reflection_exponent {e} reflection 0.5"),
        ] {
            let scene = format!(
                "global_settings {{ assumed_gamma 1.0 }}
camera {{ location <0, 1, -3> look_at 0 angle 20 }}
background {{ rgb {b} }}
plane {{ y, 0 pigment {{ rgb 0 }} finish {{ ambient 0 diffuse 0 {form} }} }}"
            );
            let (w, px) = render("reflection_exponent", &scene, 10, 10);
            let got = px[(8 * w + 5) as usize][0];
            assert!((got - want).abs() < 0.002, "{form}, background {b}: {got}");
        }
    }
}

#[test]
fn uv_mapping_before_an_objects_texture_maps_it_by_uv() {
    // POV-Ray's `object { … uv_mapping texture { … } }` (scenes/advanced/
    // benchmark.pov) is `texture { uv_mapping pigment { … } }`.
    let scene = |tex: &str| {
        format!(
            "global_settings {{ assumed_gamma 1.0 }}
camera {{ location <1, 2, -3> look_at 0 angle 40 }}
light_source {{ <2, 5, -4> rgb 1 }}
sphere {{ 0, 1 {tex} }}"
        )
    };
    let checker = "pigment { checker rgb 1, rgb 0 scale 0.1 }";
    let (_, object_level) = render(
        "uv_object",
        &scene(&format!("uv_mapping texture {{ {checker} }}")),
        32,
        24,
    );
    let (_, pigment_level) = render(
        "uv_pigment",
        &scene(&format!("texture {{ uv_mapping {checker} }}")),
        32,
        24,
    );
    let (_, plain) = render(
        "uv_none",
        &scene(&format!("texture {{ {checker} }}")),
        32,
        24,
    );
    assert!(
        object_level == pigment_level,
        "uv_mapping before the texture differs"
    );
    assert!(
        object_level != plain,
        "uv_mapping before the texture had no effect"
    );
}

#[test]
fn palette_filter_and_transmit_change_one_palette_colour() {
    // A 2x1 palette PNG: index 0 red on the left, index 1 green on the right.
    let dir = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("render_textures");
    std::fs::create_dir_all(&dir).unwrap();
    let file = std::fs::File::create(dir.join("palette.png")).unwrap();
    let mut enc = png::Encoder::new(std::io::BufWriter::new(file), 2, 1);
    enc.set_color(png::ColorType::Indexed);
    enc.set_depth(png::BitDepth::Eight);
    enc.set_palette(vec![255, 0, 0, 0, 255, 0]);
    enc.write_header()
        .unwrap()
        .write_image_data(&[0, 1])
        .unwrap();
    // POV-Ray's `transmit PALETTE, AMOUNT`: the green half shows the blue
    // background through it; the red half stays.
    let scene = |mods: &str| {
        format!(
            "#version 3.7;
             global_settings {{ assumed_gamma 1.0 }}
             camera {{ orthographic location <0.5, 0.5, -1> look_at <0.5, 0.5, 0> right x up y }}
             background {{ rgb <0, 0, 1> }}
             polygon {{ 4, <0, 0>, <1, 0>, <1, 1>, <0, 1>
               pigment {{ image_map {{ png \"palette.png\" {mods} }} }}
               finish {{ ambient 1 diffuse 0 }} }}"
        )
    };
    let (w, px) = render("palette_transmit", &scene("transmit 1, 1"), 8, 4);
    let at = |x: u32, y: u32| px[(y * w + x) as usize];
    assert!(close(at(1, 2), [1.0, 0.0, 0.0], 1e-3), "{:?}", at(1, 2));
    assert!(close(at(6, 2), [0.0, 0.0, 1.0], 1e-3), "{:?}", at(6, 2));
    // `filter 0, 1` tints what is behind by red: blue behind red is black.
    let (w, px) = render("palette_filter", &scene("filter 0, 1"), 8, 4);
    let at = |x: u32, y: u32| px[(y * w + x) as usize];
    assert!(close(at(1, 2), [0.0, 0.0, 0.0], 1e-3), "{:?}", at(1, 2));
    assert!(close(at(6, 2), [0.0, 1.0, 0.0], 1e-3), "{:?}", at(6, 2));
}
