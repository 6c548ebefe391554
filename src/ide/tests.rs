//! Tests of the analysis functions on small documents in a temporary folder.

use super::*;
use crate::diag::Severity;

/// A fresh folder under the target directory with the given files.
fn folder(name: &str, files: &[(&str, &str)]) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("rts-ide-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("dir");
    for (n, t) in files {
        std::fs::write(dir.join(n), t).expect("write");
    }
    dir
}

fn analyze_file(dir: &Path, name: &str) -> Analysis {
    let path = dir.join(name);
    let text = std::fs::read_to_string(&path).expect("read");
    analyze(&path, &text, &HashMap::new(), &editor_options(Vec::new()))
}

/// The position of the `n`th occurrence of `needle` (plus `delta` characters).
fn at(a: &Analysis, needle: &str, n: usize, delta: usize) -> Position {
    let off = a.text().match_indices(needle).nth(n).expect("needle").0 + delta;
    a.lines.position(a.text(), off)
}

const GOOD_HEAD: &str =
    "global_settings { assumed_gamma 1.0 }\nlight_source { <0, 5, -5> rgb 1 }\n";

#[test]
fn two_independent_errors_with_utf16_ranges() {
    let text = format!(
        "{GOOD_HEAD}// é😀\nsphere {{ 0, Radiuss }}\nbox {{ 0, 1 pigment {{ rgb Colr }} }}\n"
    );
    let dir = folder("errors", &[("s.rts", &text)]);
    let a = analyze_file(&dir, "s.rts");
    let d: Vec<_> = diagnostics(&a)
        .into_iter()
        .filter(|d| d.severity == Severity::Error)
        .collect();
    assert_eq!(d.len(), 2, "{d:#?}");
    assert_eq!(
        d[0].range.start,
        Position {
            line: 3,
            character: 12
        }
    );
    assert_eq!(
        d[0].range.end,
        Position {
            line: 3,
            character: 19
        }
    );
    assert_eq!(d[1].range.start.line, 4);
    assert!(d[0].code.contains("unknown"), "{}", d[0].code);
}

#[test]
fn errors_in_includes_show_at_the_include() {
    let dir = folder(
        "inc",
        &[
            ("lib.inc", "#declare Good = 1;\n#declare Bad = Nope;\n"),
            (
                "s.rts",
                &format!("{GOOD_HEAD}#include \"lib.inc\"\nsphere {{ 0, Good }}\n"),
            ),
        ],
    );
    let a = analyze_file(&dir, "s.rts");
    let d = diagnostics(&a);
    let e = d
        .iter()
        .find(|d| d.severity == Severity::Error)
        .expect("an error");
    assert_eq!(e.range.start.line, 2, "{e:#?}");
    assert!(e.message.starts_with("in lib.inc:2"), "{}", e.message);
    assert!(e
        .related
        .iter()
        .any(|r| r.location.path.ends_with("lib.inc")));
}

#[test]
fn macro_errors_relate_the_call_site() {
    let text = format!("{GOOD_HEAD}#macro Ball(P)\n  sphere {{ P, Missing }}\n#end\nBall(1)\n");
    let dir = folder("macro", &[("s.rts", &text)]);
    let a = analyze_file(&dir, "s.rts");
    let d = diagnostics(&a);
    let e = d
        .iter()
        .find(|d| d.severity == Severity::Error)
        .expect("error");
    assert_eq!(e.range.start.line, 3);
    assert!(
        e.related.iter().any(|r| r.location.range.start.line == 5),
        "{e:#?}"
    );
}

#[test]
fn hover_keywords_builtins_and_user_names() {
    let text =
        format!("{GOOD_HEAD}#declare R = 1.5;\nsphere {{ 0, R * sin(pi) finish {{ phong 1 }} }}\n");
    let dir = folder("hover", &[("s.rts", &text)]);
    let a = analyze_file(&dir, "s.rts");
    let (h, _) = hover(&a, at(&a, "phong", 0, 1)).expect("keyword hover");
    assert!(h.contains("Phong highlight"), "{h}");
    let (h, r) = hover(&a, at(&a, "R *", 0, 0)).expect("user hover");
    assert!(
        h.contains("#declare R = 1.5;") && h.contains("a float: `1.5`") && h.contains("s.rts:3"),
        "{h}"
    );
    assert_eq!(r.end.character - r.start.character, 1);
    let (h, _) = hover(&a, at(&a, "sin", 0, 0)).expect("builtin");
    assert!(h.contains("sin(A)"), "{h}");
    let (h, _) = hover(&a, at(&a, "#declare", 0, 2)).expect("directive");
    assert!(h.contains("#declare NAME = VALUE"), "{h}");
}

#[test]
fn completion_in_finish_offers_only_finish_keywords() {
    let text = format!("{GOOD_HEAD}#declare F = finish {{ phong 1 }}\n#macro M(A, optional B) A #end\nsphere {{ 0, 1 finish {{  }} }}\n");
    let dir = folder("complete", &[("s.rts", &text), ("parts.inc", "")]);
    let a = analyze_file(&dir, "s.rts");
    let items = completion(&a, at(&a, "finish {  }", 0, 9));
    let labels: Vec<&str> = items.iter().map(|i| i.label.as_str()).collect();
    assert!(
        labels.contains(&"phong") && labels.contains(&"reflection"),
        "{labels:?}"
    );
    assert!(
        !labels.contains(&"sphere") && !labels.contains(&"translate"),
        "{labels:?}"
    );
    assert!(labels.contains(&"F"));
    let m = items.iter().find(|i| i.label == "M").expect("macro");
    assert_eq!(m.detail, "#macro M(A, optional B)");
    assert_eq!(m.snippet.as_deref(), Some("M(${1:A}, ${2:B})"));
    // At top level: objects, not finish keywords.
    let top = completion(
        &a,
        Position {
            line: 2,
            character: 0,
        },
    );
    assert!(top.iter().any(|i| i.label == "sphere") && !top.iter().any(|i| i.label == "phong"));
}

#[test]
fn completion_of_include_names() {
    let dir = folder("incname", &[("s.rts", "#include \"pa"), ("parts.inc", "")]);
    let a = analyze_file(&dir, "s.rts");
    let items = completion(&a, at(&a, "pa", 0, 2));
    assert_eq!(
        items.iter().map(|i| i.label.as_str()).collect::<Vec<_>>(),
        ["parts.inc"]
    );
    let dir = folder("incname2", &[("s.rts", "#include \"co")]);
    let a = analyze_file(&dir, "s.rts");
    assert!(completion(&a, at(&a, "co", 0, 2))
        .iter()
        .any(|i| i.label == "colors.inc"));
}

#[test]
fn definition_and_references_across_includes() {
    let dir = folder(
        "nav",
        &[
            (
                "lib.inc",
                "#declare Size = 2;\n#macro Ball(P) sphere { P, Size } #end\n",
            ),
            (
                "s.rts",
                &format!(
                    "{GOOD_HEAD}#include \"lib.inc\"\nBall(<0, Size, 0>)\nbox {{ 0, Size }}\n"
                ),
            ),
        ],
    );
    let a = analyze_file(&dir, "s.rts");
    let def = definition(&a, at(&a, "Ball(", 0, 1)).expect("def");
    assert!(def.path.ends_with("lib.inc"));
    assert_eq!(
        def.range.start,
        Position {
            line: 1,
            character: 7
        }
    );
    let def = definition(&a, at(&a, "Size, 0", 0, 0)).expect("def");
    assert_eq!(
        def.range.start,
        Position {
            line: 0,
            character: 9
        }
    );
    let refs = references(&a, at(&a, "Size }", 0, 0), true);
    // The declaration, its use in the macro, and two uses in the scene.
    assert_eq!(refs.len(), 4, "{refs:#?}");
    assert_eq!(references(&a, at(&a, "Size }", 0, 0), false).len(), 3);
    // On the include's file name: the file.
    let inc = definition(&a, at(&a, "lib.inc", 0, 2)).expect("file");
    assert!(inc.path.ends_with("lib.inc"));
}

#[test]
fn macro_parameters_resolve_inside_their_macro() {
    let text = "#declare P = 1;\n#macro M(P) P #end\n#declare Q = P;\n";
    let dir = folder("params", &[("s.rts", text)]);
    let a = analyze_file(&dir, "s.rts");
    let inside = definition(&a, at(&a, ") P", 0, 2)).expect("param");
    assert_eq!(
        inside.range.start,
        Position {
            line: 1,
            character: 9
        }
    );
    let outside = definition(&a, at(&a, "= P", 0, 2)).expect("global");
    assert_eq!(
        outside.range.start,
        Position {
            line: 0,
            character: 9
        }
    );
}

#[test]
fn outline_lists_declarations_macros_and_objects() {
    let text = format!("{GOOD_HEAD}camera {{ location -5*z look_at 0 }}\n#declare T = texture {{ pigment {{ rgb 1 }} }}\n#macro M() #end\nunion {{ sphere {{ 0, 1 }} box {{ 0, 1 }} }}\n");
    let dir = folder("outline", &[("s.rts", &text)]);
    let a = analyze_file(&dir, "s.rts");
    let names: Vec<(&str, index::OutlineKind)> = outline(&a)
        .iter()
        .map(|o| (o.name.as_str(), o.kind))
        .collect();
    use index::OutlineKind::*;
    assert_eq!(
        names,
        [
            ("global_settings", Settings),
            ("light_source", Light),
            ("camera", Camera),
            ("T", Variable),
            ("M", Macro),
            ("union", Object)
        ]
    );
    assert_eq!(outline(&a)[5].children.len(), 2);
}

#[test]
fn semantic_tokens_classify_words() {
    let text = "#declare R = 1; // c\n#macro M(P) P #end\nsphere { 0, R * sin(pi) }\n/* a\nb */";
    let dir = folder("tokens", &[("s.rts", text)]);
    let a = analyze_file(&dir, "s.rts");
    let toks = semantic_tokens(&a);
    let ty = |line: u32, start: u32| {
        let t = toks
            .iter()
            .find(|t| t.line == line && t.start == start)
            .expect("token");
        (TOKEN_TYPES[t.token_type as usize], t.modifiers)
    };
    assert_eq!(ty(0, 0), ("keyword", 0));
    assert_eq!(ty(0, 9), ("variable", 1));
    assert_eq!(ty(0, 13), ("number", 0));
    assert_eq!(ty(0, 16), ("comment", 0));
    assert_eq!(ty(1, 7), ("function", 1));
    assert_eq!(ty(1, 9).0, "parameter");
    assert_eq!(ty(2, 0), ("keyword", 0));
    assert_eq!(ty(2, 16).0, "function");
    assert_eq!(ty(2, 20), ("variable", 6));
    // A block comment over two lines gives two tokens.
    assert_eq!(ty(3, 0).0, "comment");
    assert_eq!(ty(4, 0).0, "comment");
}

#[test]
fn overlays_win_over_the_disk() {
    let dir = folder(
        "overlay",
        &[
            ("lib.inc", "#declare A = 1;\n"),
            ("s.rts", "#include \"lib.inc\"\n#declare B = A + Z;\n"),
        ],
    );
    let path = dir.join("s.rts");
    let text = std::fs::read_to_string(&path).expect("read");
    let mut overlays = HashMap::new();
    overlays.insert(
        canonical(&dir.join("lib.inc")),
        "#declare A = 1;\n#declare Z = 2;\n".to_string(),
    );
    let a = analyze(&path, &text, &overlays, &editor_options(Vec::new()));
    assert!(
        !crate::diag::has_errors(&a.raw_diagnostics),
        "{:#?}",
        a.raw_diagnostics
    );
    assert!(a
        .included_paths()
        .contains(&canonical(&dir.join("lib.inc"))));
}

#[test]
fn broken_documents_still_answer() {
    // An unclosed block: the parser gives up, the lexical features still work.
    let text = "#declare R = 1;\nsphere { 0, 1 finish { ph";
    let dir = folder("broken", &[("s.rts", text)]);
    let a = analyze_file(&dir, "s.rts");
    assert!(!diagnostics(&a).is_empty());
    let items = completion(&a, at(&a, "{ ph", 0, 4));
    assert!(items.iter().any(|i| i.label == "phong"));
    assert!(hover(&a, at(&a, "finish", 0, 1)).is_some());
    assert!(!semantic_tokens(&a).is_empty());
}

/// The editor reports what `rts check` reports: on every error fixture, the same codes
/// at the same places (parse, then evaluate when the parse is clean).
#[test]
fn same_diagnostics_as_check_on_the_fixtures() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fixtures/err");
    let options = EvalOptions::default();
    let mut n = 0;
    for e in std::fs::read_dir(&root).expect("dir").flatten() {
        let path = e.path();
        let Ok(text) = std::fs::read_to_string(&path) else {
            continue;
        };
        if path.extension().is_none_or(|x| x != "rts") {
            continue;
        }
        let mut sources = SourceMap::new();
        let id = sources.add(
            path.display().to_string(),
            Some(canonical(&path)),
            text.clone(),
        );
        let (file, mut want) = crate::syntax::parse(&text, id);
        if !crate::diag::has_errors(&want) || !file.unparsed.is_empty() {
            want.extend(eval::eval(&file, id, &mut sources, &options).diagnostics);
        }
        let a = analyze(&path, &text, &HashMap::new(), &options);
        let key = |d: &[Diagnostic], s: &SourceMap| {
            d.iter()
                .map(|d| {
                    (
                        d.code,
                        s.get(d.span.file).name.clone(),
                        d.span.start,
                        d.span.end,
                    )
                })
                .collect::<Vec<_>>()
        };
        assert_eq!(
            key(&a.raw_diagnostics, &a.sources),
            key(&want, &sources),
            "{}",
            path.display()
        );
        n += 1;
    }
    assert!(n > 20, "only {n} fixtures");
}

#[test]
fn an_include_file_is_a_library_not_a_scene() {
    // No camera, light or gamma is expected of it, and its declarations are
    // for the scenes that include it.
    let dir = folder(
        "library",
        &[(
            "lib.inc",
            "#declare Lib_Size = 2;\nsphere { 0, Lib_Size }\n#macro Lib_Ball(P) sphere { P, 1 } #end\n",
        )],
    );
    let a = analyze_file(&dir, "lib.inc");
    assert!(diagnostics(&a).is_empty(), "{:?}", diagnostics(&a));
}
