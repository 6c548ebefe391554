//! The mesh camera (`mesh_camera { RAYS DISTRIBUTION MESH… [smooth] }`): which
//! face each pixel shoots from and where its ray goes, as measured on POV-Ray 3.7
//! with the same scenes (a gradient backdrop reads back where each ray landed).

mod render_support;

/// Renders `scene` at `w`×`h` with linear 16-bit output and returns its pixels.
fn render(name: &str, scene: &str, w: u32, h: u32) -> Vec<[f64; 3]> {
    render_support::render_source("render_mesh_camera", name, scene, w, h)
}

/// Red backdrop ahead (z = 10), blue behind (z = -10), each brightening along x
/// from 0 at x = 0 to 1 at x = 24: a pixel tells the plane and x its ray reached.
const BACKDROPS: &str = "global_settings { assumed_gamma 1.0 }\n\
    plane { z, 10 pigment { gradient x color_map { [0 rgb 0] [1 rgb <1, 0, 0>] } scale 24 } finish { ambient 1 diffuse 0 } }\n\
    plane { z, -10 pigment { gradient x color_map { [0 rgb 0] [1 rgb <0, 0, 1>] } scale 24 } finish { ambient 1 diffuse 0 } }\n";

/// Where the ray of each pixel landed: (`'R'` ahead or `'B'` behind, x), or
/// `None` for black.
fn landed(px: &[[f64; 3]]) -> Vec<Option<(char, f64)>> {
    px.iter()
        .map(|p| {
            if p[0] > 1e-4 {
                Some(('R', p[0] * 24.0))
            } else if p[2] > 1e-4 {
                Some(('B', p[2] * 24.0))
            } else {
                None
            }
        })
        .collect()
}

/// `n` small triangles per mesh with centroids at x = 0.5, 1.5, … (mesh `m`
/// shifted by 12 m), their right-hand normals along +z.
fn meshes(count: usize, n: usize) -> String {
    (0..count)
        .map(|m| {
            let tris: String = (0..n)
                .map(|i| {
                    let x = i as f64 + 0.5 + 12.0 * m as f64;
                    format!(
                        "triangle {{ <{}, -0.25, 0>, <{}, -0.25, 0>, <{}, 0.5, 0> }} ",
                        x - 0.25,
                        x + 0.5,
                        x - 0.25
                    )
                })
                .collect();
            format!("mesh {{ {tris}}} ")
        })
        .collect()
}

fn assert_landed(got: &[Option<(char, f64)>], want: &[Option<(char, f64)>]) {
    assert_eq!(got.len(), want.len());
    for (i, (g, w)) in got.iter().zip(want).enumerate() {
        match (g, w) {
            (Some((a, x)), Some((b, y))) => {
                assert!(
                    a == b && (x - y).abs() < 2e-3,
                    "pixel {i}: {g:?} want {w:?}"
                )
            }
            (None, None) => {}
            _ => panic!("pixel {i}: {g:?} want {w:?}"),
        }
    }
}

#[test]
fn distribution_0_shoots_from_face_row_times_width_plus_column() {
    // POV-Ray 3.7 (measured): face y·width + x from its centroid, against the
    // right-hand normal; the first two rows both use the first row of faces.
    let scene = format!(
        "{BACKDROPS}camera {{ mesh_camera {{ 1 0 {} }} location <0, 0, 0> }}\n",
        meshes(1, 24)
    );
    let got = landed(&render("dist0", &scene, 4, 3));
    let row = |r: usize| (0..4).map(move |x| Some(('B', (r * 4 + x) as f64 + 0.5)));
    let want: Vec<_> = row(0).chain(row(0)).chain(row(1)).collect();
    assert_landed(&got, &want);
    // `direction` with a negative z turns every ray round.
    let scene = scene.replace("location <0, 0, 0>", "location <0, 0, 0> direction -z");
    let got = landed(&render("dist0_reversed", &scene, 4, 3));
    assert!(
        got.iter().all(|g| g.is_some_and(|(c, _)| c == 'R')),
        "{got:?}"
    );
}

#[test]
fn location_z_moves_each_ray_along_its_direction() {
    // A green slab from z = -2 to -1 across the rays (which go towards -z):
    // starting 3 units along, past it, the rays see the blue backdrop.
    let slab = "box { <-100, -1, -2>, <100, 1, -1> pigment { rgb <0, 1, 0> } finish { ambient 1 diffuse 0 } }\n";
    for (z, blue) in [(0.0, false), (3.0, true)] {
        let scene = format!(
            "{BACKDROPS}{slab}camera {{ mesh_camera {{ 1 0 {} }} location <0, 0, {z}> }}\n",
            meshes(1, 4)
        );
        let px = render(&format!("offset_{z}"), &scene, 4, 1);
        assert_eq!(px[0][2] > 1e-4, blue, "location z {z}: {:?}", px[0]);
        assert_eq!(px[0][1] > 0.5, !blue, "location z {z}: {:?}", px[0]);
    }
}

#[test]
fn distributions_1_and_2_sum_or_split_the_meshes_and_0_averages_rays() {
    let two = meshes(2, 12);
    let cam = |rays: u32, dist: u32| {
        format!("{BACKDROPS}camera {{ mesh_camera {{ {rays} {dist} {two} }} }}\n")
    };
    // 1: the faces of both meshes in turn (mesh 1 starts at face 12).
    let got = landed(&render("dist1", &cam(1, 1), 6, 4));
    let face = |f: usize| Some(('B', f as f64 + 0.5));
    let want: Vec<_> = [0, 0, 1, 2]
        .iter()
        .flat_map(|&r| (0..6).map(move |x| face(r * 6 + x)))
        .collect();
    assert_landed(&got, &want);
    // 0 with two rays: the mean of face p of each mesh; past both, black.
    let got = landed(&render("dist0_two_rays", &cam(2, 0), 6, 4));
    let mean = |p: usize| (p < 12).then(|| ('B', ((p as f64 + 0.5) + (p as f64 + 12.5)) / 2.0));
    let want: Vec<_> = [0, 0, 1, 2]
        .iter()
        .flat_map(|&r| (0..6).map(move |x| mean(r * 6 + x)))
        .collect();
    assert_landed(&got, &want);
    // 2: the left half from mesh 0, the right from mesh 1, face row·3 + x.
    let got = landed(&render("dist2", &cam(1, 2), 6, 4));
    let want: Vec<_> = [0usize, 0, 1, 2]
        .iter()
        .flat_map(|&r| {
            (0..6).map(move |x| {
                let m = x / 3;
                Some(('B', (r * 3 + x) as f64 + 0.5 + 12.0 * m as f64))
            })
        })
        .collect();
    assert_landed(&got, &want);
}

#[test]
fn distribution_3_finds_the_face_by_uv_and_smooth_follows_the_normals() {
    // A 24 × 2 quad whose u runs along x: pixel column k of 8 starts at u = k/8,
    // x = 3k (column 0 is on the quad's edge). With `smooth` and normals
    // tilting from <-1, 0, 1> to <1, 0, 1> along x the rays fan out:
    // x + 10 (2u - 1) at the red backdrop, wrapping every 24.
    let quad = |n0: &str, n1: &str, smooth: &str| {
        format!(
            "{BACKDROPS}camera {{ mesh_camera {{ 1 3 mesh {{\n\
             smooth_triangle {{ <0, -1, 0>, {n0}, <24, 1, 0>, {n1}, <24, -1, 0>, {n1} uv_vectors <0, 0>, <1, 1>, <1, 0> }}\n\
             smooth_triangle {{ <0, -1, 0>, {n0}, <0, 1, 0>, {n0}, <24, 1, 0>, {n1} uv_vectors <0, 0>, <0, 1>, <1, 1> }}\n\
             }} {smooth} }} }}\n"
        )
    };
    let got = landed(&render(
        "dist3_flat",
        &quad("<-1, 0, 1>", "<1, 0, 1>", ""),
        8,
        2,
    ));
    for k in 1..8 {
        assert_landed(&got[k..k + 1], &[Some(('R', 3.0 * k as f64))]);
    }
    let got = landed(&render(
        "dist3_smooth",
        &quad("<-1, 0, 1>", "<1, 0, 1>", "smooth"),
        8,
        2,
    ));
    for k in 1..8 {
        let u = k as f64 / 8.0;
        let x = (24.0 * u + 10.0 * (2.0 * u - 1.0)).rem_euclid(24.0);
        assert_landed(&got[k..k + 1], &[Some(('R', x))]);
    }
}
