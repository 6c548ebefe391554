//! Arbitrary input never panics: random text, random soups of real tokens and
//! generated scenes go through parse and evaluate (from the fuzz asset folder,
//! with the fuzz targets' budgets), and those that evaluate without errors are
//! built and rendered at 8×6 by both renderers, as the `render` fuzz target does
//! (fuzz/README.md).

#[path = "../fuzz/fuzz_targets/harness.rs"]
mod harness;

use proptest::prelude::*;
use rts::eval::eval;
use rts::render::Pass;
use rts::source::SourceMap;

/// Runs `text` through the whole pipeline; whether it was rendered.
fn check(text: String) -> bool {
    // The CLI runs scenes on a large stack; so does the harness.
    harness::on_big_stack(move || {
        let mut sources = SourceMap::new();
        let id = sources.add("fuzz.rts", Some(harness::scene_path()), text.clone());
        let (file, diags) = rts::syntax::parse(&text, id);
        if rts::diag::has_errors(&diags) {
            for d in &diags {
                let _ = rts::diag::render::human(d, &sources, false);
            }
            return false;
        }
        let options = rts::eval::EvalOptions {
            max_loop_iterations: 10_000,
            max_macro_depth: 50,
            ..harness::options()
        };
        let out = eval(&file, id, &mut sources, &options);
        for d in &out.diagnostics {
            let _ = rts::diag::render::short(d, &sources);
            let _ = rts::diag::render::json(d, &sources);
        }
        if rts::diag::has_errors(&out.diagnostics) {
            return false;
        }
        harness::build_render(out.scene, Pass::Beauty);
        true
    })
}

/// Numbers a scene may hold, ordinary and extreme.
const NUMBERS: &[&str] = &[
    "0", "1", "-1", "0.5", "2", "3", "-0.25", "1e-9", "1e9", "1e300", "-1e300", "1e-300",
];

fn number() -> impl Strategy<Value = String> {
    proptest::sample::select(NUMBERS).prop_map(str::to_string)
}

/// Sizes, amounts and factors: above 0, some tiny, some huge.
const POSITIVE: &[&str] = &[
    "1", "0.5", "2", "3", "0.01", "1e-9", "1e9", "1e300", "1e-300",
];

fn positive() -> impl Strategy<Value = String> {
    proptest::sample::select(POSITIVE).prop_map(str::to_string)
}

fn vector() -> impl Strategy<Value = String> {
    (number(), number(), number()).prop_map(|(a, b, c)| format!("<{a}, {b}, {c}>"))
}

/// A pigment, finish, normal, interior or transform.
fn modifier() -> impl Strategy<Value = String> {
    prop_oneof![
        vector().prop_map(|v| format!("pigment {{ rgb {v} }}")),
        (vector(), number())
            .prop_map(|(v, f)| format!("pigment {{ rgbf <0.5, 0.5, 0.5, {f}> translate {v} }}")),
        positive().prop_map(|f| format!("pigment {{ checker rgb 1 rgb 0 scale {f} }}")),
        (positive(), number())
            .prop_map(|(f, t)| format!("pigment {{ bozo turbulence {t} scale {f} }}")),
        Just("pigment { image_map { png \"tiny.png\" interpolate 2 } }".to_string()),
        (number(), positive()).prop_map(|(r, p)| format!("finish {{ reflection {r} phong {p} }}")),
        number().prop_map(|f| format!("normal {{ bumps {f} scale 0.1 }}")),
        positive().prop_map(|f| format!("interior {{ ior {f} }}")),
        vector().prop_map(|v| format!("translate {v}")),
        (positive(), positive(), positive())
            .prop_map(|(a, b, c)| format!("scale <{a}, {b}, -{c}>")),
        vector().prop_map(|v| format!("rotate {v}")),
        Just("hollow".to_string()),
    ]
}

/// An object: a shape, a mesh from the asset folder, or CSG of objects.
fn object() -> impl Strategy<Value = String> {
    let leaf = prop_oneof![
        (vector(), positive()).prop_map(|(c, r)| format!("sphere {{ {c}, {r}")),
        (vector(), vector()).prop_map(|(a, b)| format!("box {{ {a}, {b}")),
        (vector(), number()).prop_map(|(n, d)| format!("plane {{ {n}, {d}")),
        (vector(), vector(), positive()).prop_map(|(a, b, r)| format!("cylinder {{ {a}, {b}, {r}")),
        (positive(), positive()).prop_map(|(a, b)| format!("torus {{ {a}, {b}")),
        (vector(), vector(), vector()).prop_map(|(a, b, c)| format!("triangle {{ {a}, {b}, {c}")),
        (positive(), vector())
            .prop_map(|(d, o)| format!("text {{ ttf \"tiny.ttf\" \"rts ox\" {d}, {o}")),
        Just("mesh { obj_file \"tiny.obj\" inside_vector y".to_string()),
        Just("mesh { ply_file \"tiny.ply\"".to_string()),
        Just("height_field { png \"tiny.png\" smooth".to_string()),
    ]
    .prop_map(|head| format!("{head} }}"));
    leaf.prop_recursive(3, 12, 3, |inner| {
        (
            proptest::sample::select(&["union", "difference", "intersection", "merge"][..]),
            proptest::collection::vec(inner, 1..4),
            proptest::collection::vec(modifier(), 0..3),
        )
            .prop_map(|(csg, children, mods)| {
                format!("{csg} {{ {} {} }}", children.join(" "), mods.join(" "))
            })
    })
    .prop_flat_map(|o| {
        proptest::collection::vec(modifier(), 0..3)
            .prop_map(move |mods| format!("object {{ {o} {} }}", mods.join(" ")))
    })
}

/// A whole scene: camera, lights, objects and sometimes global settings.
fn scene() -> impl Strategy<Value = String> {
    let camera = prop_oneof![
        (vector(), vector()).prop_map(|(l, a)| format!("camera {{ location {l} look_at {a} }}")),
        vector().prop_map(|l| format!("camera {{ orthographic location {l} look_at 0 }}")),
        proptest::sample::select(&["1", "60", "180", "360"][..])
            .prop_map(|a| format!("camera {{ fisheye angle {a} location -3*z look_at 0 }}")),
    ];
    let light = prop_oneof![
        vector().prop_map(|l| format!("light_source {{ {l} color rgb 1 }}")),
        vector().prop_map(|l| format!("light_source {{ {l} color rgb 1 spotlight point_at 0 }}")),
        vector().prop_map(|l| format!(
            "light_source {{ {l} color rgb 1 area_light x, z, 2, 2 jitter }}"
        )),
    ];
    let global = prop_oneof![
        Just(String::new()),
        Just("global_settings { max_trace_level 3 }".to_string()),
        Just("global_settings { photons { count 50 } }".to_string()),
        Just("global_settings { radiosity { count 4 } }".to_string()),
        Just("fog { distance 5 color rgb 0.5 }".to_string()),
    ];
    (
        camera,
        proptest::collection::vec(light, 0..3),
        proptest::collection::vec(object(), 0..4),
        global,
    )
        .prop_map(|(c, l, o, g)| format!("{g}\n{c}\n{}\n{}\n", l.join("\n"), o.join("\n")))
}

const TOKENS: &[&str] = &[
    "sphere",
    "{",
    "}",
    "<",
    ">",
    ",",
    "0",
    "1",
    "-1",
    "2.5",
    "x",
    "y",
    "pigment",
    "finish",
    "phong",
    "rgb",
    "color",
    "#declare",
    "#local",
    "A",
    "=",
    ";",
    "#if",
    "(",
    ")",
    "#end",
    "#else",
    "#while",
    "#macro",
    "M",
    "M(",
    "#for",
    "I",
    "#switch",
    "#case",
    "#break",
    "array[2]",
    "[",
    "]",
    ".x",
    "+",
    "*",
    "/",
    "?",
    ":",
    "\"s\"",
    "camera",
    "light_source",
    "union",
    "object",
    "translate",
    "scale",
    "0",
    "checker",
    "reflection",
    "#include",
    "\"colors.inc\"",
    "#debug",
    "plane",
    "box",
    "triangle",
    "/*",
    "*/",
    "//",
    "\n",
    "!",
    "&",
    "|",
];

proptest! {
    #![proptest_config(ProptestConfig { cases: 300, .. ProptestConfig::default() })]

    #[test]
    fn random_text_never_panics(s in "\\PC{0,200}") {
        check(s);
    }

    #[test]
    fn generated_scenes_build_and_render_without_a_panic(text in scene()) {
        check(text);
    }

    #[test]
    fn token_soup_never_panics(idx in proptest::collection::vec(0..TOKENS.len(), 0..60)) {
        let text = idx.iter().map(|i| TOKENS[*i]).collect::<Vec<_>>().join(" ");
        check(text);
    }
}

/// The generated scenes mostly evaluate without errors, so the test above does
/// build and render (a generator whose scenes all failed would test nothing).
#[test]
fn most_generated_scenes_are_rendered() {
    use proptest::strategy::ValueTree;
    use proptest::test_runner::TestRunner;
    let mut runner = TestRunner::deterministic();
    let strategy = scene();
    let total = 40;
    let rendered = (0..total)
        .filter(|_| check(strategy.new_tree(&mut runner).unwrap().current()))
        .count();
    assert!(rendered * 2 >= total, "only {rendered} of {total} rendered");
}
