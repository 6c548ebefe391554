//! The binary as users run it: exit codes, diagnostic formats, and every example
//! parsed, evaluated and smoke-rendered.

use std::path::Path;
use std::process::Command;

fn rts(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_rts"))
        .args(args)
        .output()
        .expect("run rts");
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

fn write(name: &str, text: &str) -> String {
    let dir = std::env::temp_dir().join(format!("rts-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p.display().to_string()
}

/// Checks `text` and returns the JSON diagnostics' codes.
fn codes(name: &str, text: &str) -> Vec<String> {
    let p = write(name, text);
    let (code, out, _) = rts(&["check", &p, "--message-format", "json"]);
    let codes: Vec<String> = out
        .lines()
        .map(|l| serde_json::from_str::<serde_json::Value>(l).expect("json line"))
        .filter(|v| v["severity"] == "error")
        .map(|v| v["code"].as_str().unwrap().to_string())
        .collect();
    assert_eq!(code, if codes.is_empty() { 0 } else { 1 }, "{text}");
    codes
}

#[test]
fn every_example_checks_and_renders() {
    for entry in std::fs::read_dir(Path::new(env!("CARGO_MANIFEST_DIR")).join("examples")).unwrap()
    {
        let p = entry.unwrap().path();
        if p.extension().and_then(|e| e.to_str()) != Some("rts") {
            continue;
        }
        let s = p.display().to_string();
        let (code, _, err) = rts(&["check", &s]);
        assert_eq!(code, 0, "{s}: {err}");
        let out = std::env::temp_dir().join(format!(
            "rts-smoke-{}.png",
            p.file_stem().unwrap().to_string_lossy()
        ));
        let (code, _, err) = rts(&[
            "render",
            &s,
            "-o",
            &out.display().to_string(),
            "-W",
            "64",
            "-H",
            "48",
            "-q",
        ]);
        assert_eq!(code, 0, "{s}: {err}");
        assert!(std::fs::metadata(&out).unwrap().len() > 100);
    }
}

#[test]
fn exit_codes() {
    let ok = write("ok.rts", "#version 3.7; global_settings { assumed_gamma 1 } sphere { 0, 1 pigment { rgb 1 } } light_source { <1,2,3> rgb 1 }");
    assert_eq!(rts(&["check", &ok]).0, 0);
    let bad = write("bad.rts", "sphere { 0, -1 }");
    assert_eq!(rts(&["check", &bad]).0, 1);
    assert_eq!(rts(&["render", &bad, "-o", "/tmp/x.png"]).0, 1);
    assert_eq!(rts(&["check"]).0, 2);
    assert_eq!(rts(&["check", &ok, "--message-format", "yaml"]).0, 2);
}

#[test]
fn json_has_the_documented_fields() {
    let p = write("json.rts", "#declare A = 1;\nsphere { <0,0,0>, B }\n");
    let (code, out, _) = rts(&["check", &p, "--message-format", "json"]);
    assert_eq!(code, 1);
    let v: serde_json::Value = serde_json::from_str(out.lines().next().unwrap()).unwrap();
    assert_eq!(v["code"], "rts::eval::unknown_identifier");
    assert_eq!(v["line"], 2);
    assert_eq!(v["column"], 19);
    assert_eq!(v["end_column"], 20);
    for k in [
        "severity", "message", "file", "end_line", "help", "labels", "notes",
    ] {
        assert!(v.get(k).is_some(), "missing {k}");
    }
    let (_, short, _) = rts(&["check", &p, "--message-format", "short"]);
    assert!(
        short.contains(":2:19: error[rts::eval::unknown_identifier]: unknown identifier `B`"),
        "{short}"
    );
}

#[test]
fn each_diagnostic_class() {
    let cases: &[(&str, &str)] = &[
        ("sphere { 0, 1 ]", "rts::syntax::unmatched_delimiter"),
        ("sphere { 0, 1", "rts::syntax::unclosed_delimiter"),
        ("#declare S = \"abc\n", "rts::syntax::unclosed_string"),
        ("/* never closed", "rts::syntax::unclosed_comment"),
        ("#if (1)\n", "rts::syntax::unclosed_directive"),
        ("#end", "rts::syntax::stray_directive"),
        ("#delcare A = 1;", "rts::syntax::unknown_directive"),
        ("sphere { <0,0,0> 1 * }", "rts::syntax::expected"),
        ("#declare A = Undeclared;", "rts::eval::unknown_identifier"),
        (
            "sphere { 0, 1 finish { phong_sise 3 } }",
            "rts::eval::unknown_identifier",
        ),
        (
            "sphere { 0, 1 finish { phong 1 checker } }",
            "rts::eval::unknown_parameter",
        ),
        ("#declare A = sqrt(\"x\");", "rts::eval::type_mismatch"),
        ("#macro M(A) #end M(1, 2)", "rts::eval::arity"),
        (
            "#macro M(A, A) #end",
            "rts::eval::duplicate_macro_parameter",
        ),
        ("#declare A = 1 / 0;", "rts::eval::division_by_zero"),
        ("#declare A = sqrt(-1);", "rts::eval::domain_error"),
        ("#declare A = ln(0);", "rts::eval::domain_error"),
        (
            "#declare A = array[2] {1, 2}; #declare B = A[2];",
            "rts::eval::index_out_of_range",
        ),
        (
            "#declare A = 1; #declare B = A.x;",
            "rts::eval::bad_component",
        ),
        ("sphere { 0, -1 }", "rts::eval::invalid_size"),
        ("#error \"stop\"", "rts::scene::error"),
        ("#include \"missing.inc\"", "rts::io::file_not_found"),
        ("#include \"/etc/hostname\"", "rts::io::file_not_allowed"),
        ("#while (1) #end", "rts::limit::loop_iterations"),
        ("#macro R() R() #end R()", "rts::limit::macro_recursion"),
        (
            "finish { phong 1 phong 2 }",
            "rts::eval::duplicate_parameter",
        ),
        ("sphere { 0, 1 scale 0 }", "rts::eval::degenerate_transform"),
    ];
    for (i, (text, code)) in cases.iter().enumerate() {
        let got = codes(&format!("case{i}.rts"), text);
        assert!(
            got.iter().any(|c| c == code),
            "{text}: expected {code}, got {got:?}"
        );
    }
}

#[test]
fn nesting_and_invalid_utf8_are_diagnostics() {
    let deep = format!(
        "#declare A = {}1{};",
        "(".repeat(20_000),
        ")".repeat(20_000)
    );
    assert_eq!(codes("deep.rts", &deep), vec!["rts::limit::nesting_depth"]);
    let dir = std::env::temp_dir().join(format!("rts-cli-{}", std::process::id()));
    let p = dir.join("utf8.rts");
    std::fs::write(&p, b"#declare A = 1;\xff\n").unwrap();
    let (code, out, _) = rts(&[
        "check",
        &p.display().to_string(),
        "--message-format",
        "short",
    ]);
    assert_eq!(code, 1);
    assert!(
        out.contains("rts::source::invalid_utf8") && out.contains("offset 15"),
        "{out}"
    );
}

#[test]
fn several_independent_errors_in_one_run() {
    let got = codes(
        "many.rts",
        "#declare A = B1;\n#declare C = 1/0;\nsphere { 0, -2 }\n",
    );
    assert_eq!(got.len(), 3, "{got:?}");
    let got = codes(
        "syn.rts",
        "sphere { <0,0,0> 1 * }\nplane { y, 0 }\nbox { 0, 1 + }\n",
    );
    assert_eq!(got.len(), 2, "{got:?}");
}

#[test]
fn include_chain_and_macro_call_site_are_noted() {
    let inc = write("inner.inc", "#declare Z = 1;\nsphere { 0, -1 }\n");
    let _ = inc;
    let main = write(
        "outer.rts",
        "#include \"inner.inc\"\n#macro M() sphere { 0, -3 } #end\nM()\n",
    );
    let (code, out, _) = rts(&["check", &main, "--message-format", "json"]);
    assert_eq!(code, 1);
    let lines: Vec<serde_json::Value> = out
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    assert!(lines[0]["file"].as_str().unwrap().ends_with("inner.inc"));
    assert!(
        lines[0]["notes"].to_string().contains("included from here"),
        "{}",
        lines[0]
    );
    assert!(
        lines[1]["notes"]
            .to_string()
            .contains("in macro `M` called here"),
        "{}",
        lines[1]
    );
}

#[test]
fn same_bytes_on_one_and_many_threads() {
    let scene = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("examples/showcase.rts")
        .display()
        .to_string();
    let a = std::env::temp_dir().join("rts-t1.png");
    let b = std::env::temp_dir().join("rts-t4.png");
    assert_eq!(
        rts(&[
            "render",
            &scene,
            "-o",
            &a.display().to_string(),
            "-W",
            "96",
            "-H",
            "72",
            "--threads",
            "1",
            "-q"
        ])
        .0,
        0
    );
    assert_eq!(
        rts(&[
            "render",
            &scene,
            "-o",
            &b.display().to_string(),
            "-W",
            "96",
            "-H",
            "72",
            "--threads",
            "4",
            "-q"
        ])
        .0,
        0
    );
    assert_eq!(std::fs::read(a).unwrap(), std::fs::read(b).unwrap());
}

fn showcase() -> String {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("examples/showcase.rts")
        .display()
        .to_string()
}

fn tmp(name: &str) -> String {
    let dir = std::env::temp_dir().join(format!("rts-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir.join(name).display().to_string()
}

#[test]
fn antialias_and_samples_same_bytes_on_one_and_four_threads() {
    let scene = showcase();
    for (i, mode) in [
        &["--antialias", "0.3"][..],
        &["--antialias", "0.1", "--aa-depth", "2", "--jitter", "0.5"],
        &["--samples", "4", "--seed", "7"],
    ]
    .iter()
    .enumerate()
    {
        let mut outs = Vec::new();
        for threads in ["1", "4"] {
            let out = tmp(&format!("aa{i}-{threads}.png"));
            let mut args = vec![
                "render",
                &scene,
                "-o",
                &out,
                "-W",
                "64",
                "-H",
                "48",
                "-q",
                "--threads",
                threads,
            ];
            args.extend_from_slice(mode);
            let (code, _, err) = rts(&args);
            assert_eq!(code, 0, "{mode:?}: {err}");
            outs.push(std::fs::read(&out).unwrap());
        }
        assert_eq!(outs[0], outs[1], "{mode:?}");
    }
}

#[test]
fn stats_json_crop_and_formats() {
    let scene = showcase();
    let out = tmp("crop.exr");
    let stats = tmp("stats.json");
    let (code, stdout, err) = rts(&[
        "render",
        &scene,
        "-o",
        &out,
        "-W",
        "64",
        "-H",
        "48",
        "--crop",
        "10,5,42,29",
        "--antialias",
        "0.3",
        "--stats-json",
        &stats,
    ]);
    assert_eq!(code, 0, "{err}");
    assert!(stdout.is_empty());
    // Human statistics on stderr (not a terminal: no progress bar).
    assert!(err.contains("Mrays/s") && err.contains("render"), "{err}");
    let img = image::open(&out).unwrap();
    assert_eq!((img.width(), img.height()), (32, 24));
    let v: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&stats).unwrap()).unwrap();
    assert_eq!(v["format"], "exr");
    assert_eq!(v["pixels"], 32 * 24);
    assert_eq!(v["crop"], serde_json::json!([10, 5, 42, 29]));
    assert_eq!(v["sampling"]["mode"], "antialias");
    assert!(v["rays"]["total"].as_u64().unwrap() >= v["rays"]["camera"].as_u64().unwrap());
    for stage in ["parse_eval", "build", "render", "write", "total"] {
        assert!(v["seconds"][stage].as_f64().unwrap() >= 0.0, "{stage}");
    }
    // JSON to stdout with `-`, nothing else there; -q silences stderr.
    let (code, stdout, err) = rts(&[
        "render",
        &scene,
        "-o",
        &tmp("s.png"),
        "-W",
        "16",
        "-H",
        "12",
        "--pass",
        "normal",
        "--format",
        "ppm",
        "--stats-json",
        "-",
        "-q",
    ]);
    assert_eq!(code, 0, "{err}");
    assert!(err.is_empty(), "{err}");
    let v: serde_json::Value = serde_json::from_str(stdout.trim()).unwrap();
    assert_eq!(v["pass"], "normal");
    assert_eq!(v["format"], "ppm");
    assert!(std::fs::read(tmp("s.png")).unwrap().starts_with(b"P6"));
}

#[test]
fn render_option_errors_are_usage_errors() {
    let scene = showcase();
    let out = tmp("bad.png");
    for (args, words) in [
        (&["--antialias", "0.3", "--samples", "4"][..], "together"),
        (&["--crop", "0,0,100,10"], "X1 <= 64"),
        (&["--crop", "1,2,3"], "four whole numbers"),
        (&["--antialias=-1"], "0 or more"),
        (&["--antialias", "0.3", "--aa-depth", "10"], "1 to 9"),
        (&["--samples", "0"], "1 to"),
        (&["--pass", "depth", "--depth-max", "0"], "positive"),
    ] {
        let mut a = vec!["render", &scene, "-o", &out, "-W", "64", "-H", "48"];
        a.extend_from_slice(args);
        let (code, _, err) = rts(&a);
        assert_eq!(code, 2, "{args:?}: {err}");
        assert!(err.contains(words), "{args:?}: {err}");
    }
    let (code, _, err) = rts(&["render", &scene, "-o", &tmp("x.jpg"), "-W", "8", "-H", "8"]);
    assert_eq!(code, 2);
    assert!(err.contains(".jpg") && err.contains("--format"), "{err}");
}

#[test]
fn seed_002_depth_and_normal_passes() {
    // Seed 002 draws depth as grey (white at the eye, black at maxDepth 20) and the
    // normal as colour (n * 0.5 + 0.5). Here in POV-Ray's left-handed axes: the
    // spheres face the camera along -z (blue near 0), the floor is up (green 255).
    let scene = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("examples/seed_milo_yip.rts")
        .display()
        .to_string();
    let (d, n) = (tmp("milo-depth.png"), tmp("milo-normal.png"));
    for (pass, out, extra) in [
        ("depth", &d, &["--depth-max", "20"][..]),
        ("normal", &n, &[][..]),
    ] {
        let mut args = vec![
            "render", &scene, "-o", out, "-W", "64", "-H", "64", "--pass", pass, "-q",
        ];
        args.extend_from_slice(extra);
        let (code, _, err) = rts(&args);
        assert_eq!(code, 0, "{err}");
    }
    let d = image::open(&d).unwrap().to_rgb8();
    let n = image::open(&n).unwrap().to_rgb8();
    // Sky: nothing hit, black in both.
    assert_eq!(d.get_pixel(0, 0).0, [0, 0, 0]);
    assert_eq!(n.get_pixel(0, 0).0, [0, 0, 0]);
    // Sphere centres are about 17.4 units away: grey 255 * (1 - 17.4 / 20) ≈ 33.
    let g = d.get_pixel(16, 24).0;
    assert!(
        g[0] == g[1] && g[1] == g[2] && (25..45).contains(&g[0]),
        "{g:?}"
    );
    // The floor just below the camera is nearer, so brighter.
    assert!(d.get_pixel(32, 60).0[0] > 120);
    assert_eq!(n.get_pixel(32, 60).0, [128, 255, 128]);
    let s = n.get_pixel(48, 24).0;
    assert!(s[2] < 20, "{s:?}");
}

#[test]
fn render_writes_files_and_check_does_not() {
    let dir = std::env::temp_dir().join(format!("rts-fileio-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let scene = dir.join("scene.rts");
    std::fs::write(
        &scene,
        "#fopen F \"written.txt\" write\n#write (F, \"n = \", 1/3, \", v = \", <1, 2, 3>, \"\\n\")\n#fclose F\n\
         #fopen B \"written.bin\" write\n#write (B, uint8 65, sint16be -2)\n\
         sphere { 0, 1 pigment { rgb 1 } } light_source { <0, 5, -5> rgb 1 }\n",
    )
    .unwrap();
    let written = dir.join("written.txt");
    let (code, _, err) = rts(&["check", scene.to_str().unwrap()]);
    assert_eq!(code, 0, "{err}");
    assert!(!written.exists(), "rts check must not write files");
    let out = dir.join("out.png");
    let (code, _, err) = rts(&[
        "render",
        scene.to_str().unwrap(),
        "-o",
        out.to_str().unwrap(),
        "--width",
        "8",
        "--height",
        "8",
    ]);
    assert_eq!(code, 0, "{err}");
    // POV-Ray 3.7 writes the same bytes for the same directives.
    assert_eq!(
        std::fs::read_to_string(&written).unwrap(),
        "n = 0.333333, v = <1,2,3> \n"
    );
    // A file left open is closed at the end of the scene.
    assert_eq!(
        std::fs::read(dir.join("written.bin")).unwrap(),
        [65, 0xff, 0xfe]
    );
}

/// Links in a folder the user names with -I are followed (POV-Ray's include folder
/// links its fonts from elsewhere); links in the scene's own folder are not.
#[cfg(unix)]
#[test]
fn links_are_followed_in_include_folders_only() {
    let root = std::env::temp_dir().join(format!("rts-links-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&root);
    for d in ["scene", "lib", "elsewhere"] {
        std::fs::create_dir_all(root.join(d)).unwrap();
    }
    std::fs::write(root.join("elsewhere/target.inc"), "#declare Linked = 1;\n").unwrap();
    std::os::unix::fs::symlink(
        root.join("elsewhere/target.inc"),
        root.join("lib/linked.inc"),
    )
    .unwrap();
    std::os::unix::fs::symlink(
        root.join("elsewhere/target.inc"),
        root.join("scene/own.inc"),
    )
    .unwrap();
    let scene = root.join("scene/a.rts");
    std::fs::write(
        &scene,
        "#include \"linked.inc\"\n#if (Linked) sphere { 0, 1 } #end\n",
    )
    .unwrap();
    let lib = root.join("lib");
    let (code, out, err) = rts(&[
        "check",
        scene.to_str().unwrap(),
        "-I",
        lib.to_str().unwrap(),
    ]);
    assert_eq!(code, 0, "{out}{err}");
    std::fs::write(&scene, "#include \"own.inc\"\nsphere { 0, 1 }\n").unwrap();
    let (code, out, _) = rts(&[
        "check",
        scene.to_str().unwrap(),
        "--message-format",
        "short",
    ]);
    assert_eq!(code, 1);
    assert!(out.contains("rts::io::file_not_allowed"), "{out}");
}

#[test]
fn image_maps_decode_pixels_as_povray_3_7_does() {
    // A flat (128, 64, 200) picture seen head on with ambient 1: the file values
    // (written with gamma 1) show how the picture was decoded. Expected values
    // are POV-Ray 3.7's on the same scenes.
    let dir = std::env::temp_dir().join(format!("rts-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    image::RgbImage::from_pixel(4, 4, image::Rgb([128, 64, 200]))
        .save(dir.join("flat.png"))
        .unwrap();
    for (head, gamma, want) in [
        (
            "#version 3.7; global_settings { assumed_gamma 1.0 }",
            "",
            [55, 13, 147],
        ),
        (
            "#version 3.7; global_settings { assumed_gamma 1.0 }",
            "gamma 1.5",
            [91, 32, 177],
        ),
        ("global_settings { assumed_gamma 1.0 }", "", [128, 64, 200]),
    ] {
        let scene = write(
            "flat_image.pov",
            &format!(
                "{head}
                camera {{ orthographic location <0.5, 0.5, -1> look_at <0.5, 0.5, 0> right x up y }}
                plane {{ z, 0 pigment {{ image_map {{ png \"flat.png\" {gamma} }} }} finish {{ ambient 1 diffuse 0 }} }}"
            ),
        );
        let out = dir.join("flat_out.png").display().to_string();
        let (code, _, err) = rts(&[
            "render", &scene, "-o", &out, "-W", "4", "-H", "4", "--gamma", "1.0", "-q",
        ]);
        assert_eq!(code, 0, "{err}");
        let got = image::open(&out).unwrap().to_rgb8().get_pixel(1, 1).0;
        assert_eq!(got, want, "{head} {gamma}");
    }
}

/// An isosurface far steeper than its `max_gradient`: `rts check` warns from a
/// grid of samples before any render; `rts render` (which does not sample)
/// warns once after the picture from the slopes its rays met, as POV-Ray does,
/// and not at all when the bound holds.
#[test]
fn max_gradient_is_warned_about_by_check_and_after_a_render() {
    let scene = |g: f64| {
        format!(
            "#version 3.7;\nglobal_settings {{ assumed_gamma 1.0 }}\n\
             camera {{ location <0, 0, -4> look_at 0 }}\n\
             light_source {{ <5, 5, -5> color rgb 1 }}\n\
             isosurface {{\n  function {{ x*x + y*y + z*z - 1 + 0.3*sin(20*z) }}\n  \
             max_gradient {g}\n  contained_by {{ box {{ -2, 2 }} }}\n  pigment {{ color rgb 1 }}\n}}\n"
        )
    };
    let warnings = |out: &str| -> Vec<String> {
        out.lines()
            .map(|l| serde_json::from_str::<serde_json::Value>(l).expect("json line"))
            .filter(|v| v["code"] == "rts::lint::max_gradient")
            .map(|v| v["message"].as_str().unwrap().to_string())
            .collect()
    };
    let low = write("iso_low.rts", &scene(0.5));
    let (code, out, err) = rts(&["check", &low, "--message-format", "json"]);
    assert_eq!(code, 0, "{err}");
    let w = warnings(&out);
    assert_eq!(w.len(), 1, "{out}");
    assert!(w[0].contains("measured"), "{w:?}");
    let png = std::env::temp_dir().join(format!("rts-iso-{}.png", std::process::id()));
    let png = png.display().to_string();
    let render = |p: &str| {
        let (code, out, err) = rts(&[
            "render",
            p,
            "-W",
            "40",
            "-H",
            "30",
            "-o",
            &png,
            "-q",
            "--message-format",
            "json",
        ]);
        assert_eq!(code, 0, "{err}");
        warnings(&out)
    };
    let w = render(&low);
    assert_eq!(w.len(), 1, "{w:?}");
    assert!(w[0].contains("the render met"), "{w:?}");
    // The slope along the camera's rays is at most 2 + 6 = 8 here: 12 holds.
    let high = write("iso_high.rts", &scene(12.0));
    assert_eq!(render(&high), Vec::<String>::new());
}

/// `rts render` reads the long bodies of `#if`/`#switch` branches only when
/// it takes them, as POV-Ray skips the branches it does not take: a syntax
/// error in a branch not taken stops `rts check` (which reads every branch)
/// but not a render; a branch taken in a loop is read once and placed each
/// time; the picture is the one a full reading gives.
#[test]
fn render_reads_only_the_branches_it_takes() {
    let pad = "// padding that makes the branch long enough to be left unread\n".repeat(6);
    let scene = format!(
        "#version 3.7;\nglobal_settings {{ assumed_gamma 1 }}\n\
         camera {{ location <0, 2, -8> look_at 0 }}\n\
         light_source {{ <2, 5, -5> rgb 1 }}\n\
         #declare Broken = 0;\n\
         #if (Broken)\n{pad}  sphere {{ <0, 0, 0> 1 * }}\n#else\n{pad}  #declare R = 0.3;\n#end\n\
         #for (I, 0, 5)\n\
           #switch (mod(I, 2))\n\
             #case (0)\n{pad}    sphere {{ <I - 2.5, 0, 0>, R pigment {{ rgb <1, 0, 0> }} }}\n\
             #break\n\
             #else\n{pad}    box {{ <I - 2.8, -0.3, -0.3>, <I - 2.2, 0.3, 0.3> pigment {{ rgb 1 }} }}\n\
           #end\n\
         #end\n"
    );
    let p = write("deferred_branches.rts", &scene);
    let (code, _, err) = rts(&["check", &p]);
    assert_eq!(code, 1, "check reads the branch not taken: {err}");
    assert!(err.contains("rts::syntax::expected"), "{err}");
    let out = tmp("deferred_branches.png");
    let stats = tmp("deferred_branches.json");
    let (code, _, err) = rts(&[
        "render",
        &p,
        "-o",
        &out,
        "-W",
        "32",
        "-H",
        "24",
        "--stats-json",
        &stats,
    ]);
    assert_eq!(code, 0, "the render skips it: {err}");
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&stats).unwrap()).unwrap();
    assert_eq!(json["objects"], 6, "{json}");
    // The same scene without the broken sphere, read whole (no branch is
    // long enough to be left unread once the padding goes): the same picture.
    let whole = scene
        .replace(&pad, "")
        .replace("sphere { <0, 0, 0> 1 * }", "");
    let whole = write("deferred_whole.rts", &whole);
    let out_whole = tmp("deferred_whole.png");
    let (code, _, err) = rts(&["render", &whole, "-o", &out_whole, "-W", "32", "-H", "24"]);
    assert_eq!(code, 0, "{err}");
    assert_eq!(
        std::fs::read(&out).unwrap(),
        std::fs::read(&out_whole).unwrap()
    );
}
