//! Analytic render checks of functions and isosurfaces: an isosurface of a
//! sphere's function looks like the `sphere` (alone and in CSG), and the
//! `function` pattern of `x` is `gradient x`.

mod render_support;

/// Renders `scene` at 48×36 with linear 16-bit output; pixels in 0..1.
fn render(name: &str, scene: &str) -> Vec<[f64; 3]> {
    render_support::render_source("render_isosurface", name, scene, 48, 36)
}

/// The mean absolute difference of two pictures and how many pixels differ
/// by more than `tol` in some channel.
fn diff(a: &[[f64; 3]], b: &[[f64; 3]], tol: f64) -> (f64, usize) {
    let mut sum = 0.0;
    let mut off = 0;
    for (p, q) in a.iter().zip(b) {
        let d: Vec<f64> = (0..3).map(|i| (p[i] - q[i]).abs()).collect();
        sum += d.iter().sum::<f64>() / 3.0;
        if d.iter().any(|x| *x > tol) {
            off += 1;
        }
    }
    (sum / a.len() as f64, off)
}

const SETUP: &str = "global_settings { assumed_gamma 1.0 }\n\
    camera { location <0, 1, -4> look_at 0 angle 50 }\n\
    light_source { <3, 5, -4> rgb 1 }\n\
    plane { y, -1 pigment { rgb 0.6 } }\n";

#[test]
fn isosurface_of_a_sphere_function_is_the_sphere() {
    let tex = "pigment { rgb <1, 0.5, 0.2> } finish { phong 0.5 }";
    let iso = render(
        "iso_sphere",
        &format!(
            "{SETUP}isosurface {{ function {{ sqrt(x*x + y*y + z*z) - 1 }} \
             contained_by {{ box {{ -2, 2 }} }} accuracy 0.0001 {tex} }}"
        ),
    );
    let sph = render("sphere", &format!("{SETUP}sphere {{ 0, 1 {tex} }}"));
    let (mean, off) = diff(&iso, &sph, 0.02);
    assert!(mean < 0.002 && off <= 8, "mean {mean}, {off} pixels differ");
}

#[test]
fn isosurface_in_csg_cuts_like_the_sphere() {
    let cut = |obj: &str| {
        format!(
            "{SETUP}difference {{ box {{ <-0.8, -0.8, -0.8>, <0.8, 0.8, 0.8> }} {obj} \
             pigment {{ rgb <0.3, 0.6, 1> }} rotate <-20, 30, 0> }}"
        )
    };
    let iso = render(
        "iso_csg",
        &cut("isosurface { function { sqrt(x*x + y*y + z*z) - 1 } contained_by { box { -2, 2 } } accuracy 0.0001 all_intersections }"),
    );
    let sph = render("sphere_csg", &cut("sphere { 0, 1 }"));
    let (mean, off) = diff(&iso, &sph, 0.02);
    assert!(mean < 0.002 && off <= 8, "mean {mean}, {off} pixels differ");
}

#[test]
fn function_pattern_of_x_is_gradient_x() {
    let plane = |pattern: &str| {
        format!(
            "{SETUP}plane {{ z, 1 pigment {{ {pattern} color_map {{ [0 rgb <1, 0, 0>] [1 rgb <0, 0, 1>] }} scale 0.7 }} \
             finish {{ ambient 1 diffuse 0 }} }}"
        )
    };
    let f = render("function_x", &plane("function { x }"));
    let g = render("gradient_x", &plane("gradient x"));
    assert_eq!(diff(&f, &g, 0.0).1, 0);
}
