//! `rts lsp` as editors run it: a real process speaking JSON-RPC over its stdio.

use serde_json::{json, Value};
use std::io::{BufRead, BufReader, Read, Write};
use std::path::{Path, PathBuf};
use std::process::{Child, ChildStdin, Command, Stdio};
use std::sync::mpsc;
use std::time::Duration;

struct Server {
    child: Child,
    stdin: ChildStdin,
    messages: mpsc::Receiver<Value>,
    next_id: i64,
}

impl Server {
    fn start() -> Server {
        let mut child = Command::new(env!("CARGO_BIN_EXE_rts"))
            .arg("lsp")
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(Stdio::inherit())
            .spawn()
            .expect("spawn rts lsp");
        let stdin = child.stdin.take().expect("stdin");
        let stdout = child.stdout.take().expect("stdout");
        let (tx, messages) = mpsc::channel();
        std::thread::spawn(move || {
            let mut r = BufReader::new(stdout);
            loop {
                let mut len = None;
                loop {
                    let mut line = String::new();
                    if r.read_line(&mut line).unwrap_or(0) == 0 {
                        return;
                    }
                    let line = line.trim_end();
                    if line.is_empty() {
                        break;
                    }
                    // Every header line must be a protocol header: nothing else may
                    // reach stdout.
                    let (name, value) = line.split_once(": ").expect("a header line");
                    if name.eq_ignore_ascii_case("content-length") {
                        len = Some(value.parse::<usize>().expect("length"));
                    }
                }
                let mut body = vec![0; len.expect("Content-Length")];
                r.read_exact(&mut body).expect("body");
                let v: Value = serde_json::from_slice(&body).expect("JSON body");
                if tx.send(v).is_err() {
                    return;
                }
            }
        });
        Server {
            child,
            stdin,
            messages,
            next_id: 1,
        }
    }

    fn send(&mut self, msg: Value) {
        let body = msg.to_string();
        write!(self.stdin, "Content-Length: {}\r\n\r\n{body}", body.len()).expect("write");
        self.stdin.flush().expect("flush");
    }

    fn notify(&mut self, method: &str, params: Value) {
        self.send(json!({"jsonrpc": "2.0", "method": method, "params": params}));
    }

    fn recv(&mut self) -> Value {
        self.messages
            .recv_timeout(Duration::from_secs(20))
            .expect("a message from the server within 20 s")
    }

    /// Sends a request and returns its result (notifications met on the way are
    /// dropped).
    fn request(&mut self, method: &str, params: Value) -> Value {
        let id = self.next_id;
        self.next_id += 1;
        self.send(json!({"jsonrpc": "2.0", "id": id, "method": method, "params": params}));
        loop {
            let m = self.recv();
            if m.get("id") == Some(&json!(id)) {
                assert!(m.get("error").is_none(), "{method}: {m}");
                return m["result"].clone();
            }
        }
    }

    /// The next diagnostics published for `uri`.
    fn diagnostics(&mut self, uri: &str) -> Vec<Value> {
        loop {
            let m = self.recv();
            if m["method"] == "textDocument/publishDiagnostics" && m["params"]["uri"] == uri {
                return m["params"]["diagnostics"]
                    .as_array()
                    .expect("array")
                    .clone();
            }
        }
    }
}

impl Drop for Server {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

fn uri(path: &Path) -> String {
    format!("file://{}", path.display())
}

fn folder(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("rts-lsp-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("dir");
    dir.canonicalize().expect("canonical")
}

fn errors(diags: &[Value]) -> Vec<&Value> {
    diags.iter().filter(|d| d["severity"] == 1).collect()
}

fn range(d: &Value) -> (u64, u64, u64, u64) {
    let r = &d["range"];
    let n = |v: &Value| v.as_u64().expect("number");
    (
        n(&r["start"]["line"]),
        n(&r["start"]["character"]),
        n(&r["end"]["line"]),
        n(&r["end"]["character"]),
    )
}

#[test]
fn a_session_as_an_editor_has_it() {
    let dir = folder("session");
    std::fs::write(
        dir.join("lib.inc"),
        "#declare Size = 2;\n#macro Ball(P) sphere { P, Size } #end\n",
    )
    .expect("write");
    let scene = dir.join("scene.rts");
    let broken = "global_settings { assumed_gamma 1.0 }\n\
light_source { <0, 5, -5> rgb 1 }\n\
#include \"lib.inc\"\n\
#declare Radius = 1.5; // ünïcödé 😀\n\
sphere { 0, Radius pigment { rgb Colr } }\n\
box { 0, Sizee finish { phong 1 } }\n\
Ball(<0, Size, 0>)\n";
    std::fs::write(&scene, broken).expect("write");
    let scene_uri = uri(&scene);

    let mut s = Server::start();
    let init = s.request(
        "initialize",
        json!({"processId": null, "rootUri": uri(&dir), "capabilities": {}}),
    );
    let caps = &init["capabilities"];
    assert_eq!(caps["hoverProvider"], true);
    assert!(caps["completionProvider"].is_object());
    assert!(caps["semanticTokensProvider"]["legend"]["tokenTypes"].is_array());
    s.notify("initialized", json!({}));

    // Two independent errors, both reported, with the right ranges.
    s.notify(
        "textDocument/didOpen",
        json!({"textDocument": {"uri": scene_uri, "languageId": "rts", "version": 1, "text": broken}}),
    );
    let diags = s.diagnostics(&scene_uri);
    let errs = errors(&diags);
    assert_eq!(errs.len(), 2, "{diags:#?}");
    assert_eq!(range(errs[0]), (4, 33, 4, 37), "{:#}", errs[0]);
    assert_eq!(range(errs[1]), (5, 9, 5, 14), "{:#}", errs[1]);
    assert_eq!(errs[0]["code"], "rts::eval::unknown_identifier");
    assert_eq!(errs[0]["source"], "rts");

    // Fix one: one is left.
    let fixed = broken.replace("Colr", "1");
    s.notify(
        "textDocument/didChange",
        json!({"textDocument": {"uri": scene_uri, "version": 2}, "contentChanges": [{"text": fixed}]}),
    );
    let diags = s.diagnostics(&scene_uri);
    let errs = errors(&diags);
    assert_eq!(errs.len(), 1, "{diags:#?}");
    assert_eq!(range(errs[0]), (5, 9, 5, 14));

    // Hover a keyword and a user's name.
    let h = s.request(
        "textDocument/hover",
        json!({"textDocument": {"uri": scene_uri}, "position": {"line": 5, "character": 17}}),
    );
    let text = h["contents"]["value"].as_str().expect("markdown");
    assert!(text.contains("finish {"), "{text}");
    let h = s.request(
        "textDocument/hover",
        json!({"textDocument": {"uri": scene_uri}, "position": {"line": 4, "character": 13}}),
    );
    let text = h["contents"]["value"].as_str().expect("markdown");
    assert!(
        text.contains("#declare Radius = 1.5;") && text.contains("a float: `1.5`"),
        "{text}"
    );
    assert_eq!(h["range"]["start"]["character"], 12);

    // Complete inside `finish { }`: finish keywords, not objects.
    let c = s.request(
        "textDocument/completion",
        json!({"textDocument": {"uri": scene_uri}, "position": {"line": 5, "character": 24}}),
    );
    let labels: Vec<&str> = c
        .as_array()
        .expect("items")
        .iter()
        .map(|i| i["label"].as_str().expect("label"))
        .collect();
    assert!(
        labels.contains(&"phong") && labels.contains(&"specular"),
        "{labels:?}"
    );
    assert!(
        !labels.contains(&"sphere") && !labels.contains(&"pigment"),
        "{labels:?}"
    );

    // Go to a definition in the included file.
    let d = s.request(
        "textDocument/definition",
        json!({"textDocument": {"uri": scene_uri}, "position": {"line": 6, "character": 1}}),
    );
    assert_eq!(d["uri"], uri(&dir.join("lib.inc")));
    assert_eq!(d["range"]["start"], json!({"line": 1, "character": 7}));

    // References, outline and semantic tokens answer too.
    let r = s.request(
        "textDocument/references",
        json!({"textDocument": {"uri": scene_uri}, "position": {"line": 6, "character": 9},
               "context": {"includeDeclaration": true}}),
    );
    assert_eq!(r.as_array().expect("locations").len(), 3, "{r:#}");
    let o = s.request(
        "textDocument/documentSymbol",
        json!({"textDocument": {"uri": scene_uri}}),
    );
    let names: Vec<&str> = o
        .as_array()
        .expect("symbols")
        .iter()
        .map(|x| x["name"].as_str().expect("name"))
        .collect();
    assert_eq!(
        names,
        ["global_settings", "light_source", "Radius", "sphere", "box"]
    );
    let t = s.request(
        "textDocument/semanticTokens/full",
        json!({"textDocument": {"uri": scene_uri}}),
    );
    assert_eq!(t["data"].as_array().expect("data").len() % 5, 0);
    let f = s.request(
        "textDocument/formatting",
        json!({"textDocument": {"uri": scene_uri}, "options": {"tabSize": 2, "insertSpaces": true}}),
    );
    assert!(f.is_array(), "{f}");

    // Opening the include and breaking it re-checks the scene that includes it.
    let lib_uri = uri(&dir.join("lib.inc"));
    s.notify(
        "textDocument/didOpen",
        json!({"textDocument": {"uri": lib_uri, "languageId": "rts", "version": 1,
               "text": "#declare Size = 2;\n#macro Ball(P) sphere { P, Size } #end\n"}}),
    );
    // Both the include and the scene that includes it are checked (in either order).
    let mut seen = std::collections::HashSet::new();
    while seen.len() < 2 {
        let m = s.recv();
        if m["method"] == "textDocument/publishDiagnostics" {
            seen.insert(m["params"]["uri"].as_str().expect("uri").to_string());
        }
    }
    s.notify(
        "textDocument/didChange",
        json!({"textDocument": {"uri": lib_uri, "version": 2},
               "contentChanges": [{"text": "#declare Size = Oops;\n#macro Ball(P) sphere { P, Size } #end\n"}]}),
    );
    let scene_diags = s.diagnostics(&scene_uri);
    let errs = errors(&scene_diags);
    assert!(
        errs.iter().any(|e| e["message"]
            .as_str()
            .expect("message")
            .starts_with("in lib.inc:1")
            && range(e).0 == 2),
        "{scene_diags:#?}"
    );

    // A clean shutdown.
    let r = s.request("shutdown", Value::Null);
    assert!(r.is_null());
    s.notify("exit", Value::Null);
    let status = s.child.wait().expect("exit");
    assert!(status.success());
}

#[test]
fn garbage_documents_do_not_stop_the_server() {
    let dir = folder("garbage");
    let mut s = Server::start();
    s.request("initialize", json!({"capabilities": {}}));
    s.notify("initialized", json!({}));
    let texts = [
        "sphere { <1, 2",
        "#macro M( #end }}}} ]]",
        "\u{0}\u{1}😀\"\\",
        "#while (1) #end",
        "#declare A = array[3] { 1, 2, 3 }; A[7]",
        "/* /* */",
    ];
    for (i, t) in texts.iter().enumerate() {
        let u = uri(&dir.join(format!("g{i}.rts")));
        s.notify(
            "textDocument/didOpen",
            json!({"textDocument": {"uri": u, "languageId": "rts", "version": 1, "text": t}}),
        );
        let _ = s.diagnostics(&u);
        for (line, character) in [(0, 0), (0, 3), (0, 200), (9, 9)] {
            let pos = json!({"textDocument": {"uri": u}, "position": {"line": line, "character": character}});
            s.request("textDocument/hover", pos.clone());
            s.request("textDocument/completion", pos.clone());
            s.request("textDocument/definition", pos);
        }
        s.request(
            "textDocument/semanticTokens/full",
            json!({"textDocument": {"uri": u}}),
        );
    }
}

/// The VS Code grammar highlights every keyword of the grammar and every built-in, so
/// it cannot drift from the language.
#[test]
fn the_vscode_grammar_knows_every_word() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(root.join("editors/vscode/syntaxes/rts.tmLanguage.json"))
        .expect("grammar");
    let g: Value = serde_json::from_str(&text).expect("JSON");
    assert_eq!(g["scopeName"], "source.rts");
    let words = g["repository"]["words"]["patterns"]
        .as_array()
        .expect("patterns");
    let alternatives = |scope: &str| -> Vec<String> {
        let m = words
            .iter()
            .find(|p| p["name"] == scope)
            .and_then(|p| p["match"].as_str())
            .expect(scope);
        let inner = m.trim_start_matches("\\b(").trim_end_matches(")\\b");
        inner.split('|').map(str::to_string).collect()
    };
    let keywords = alternatives("keyword.other.rts");
    for k in rts::syntax::keywords::KEYWORDS {
        assert!(
            keywords.iter().any(|w| w == k),
            "`{k}` missing from the grammar"
        );
    }
    let functions = alternatives("support.function.builtin.rts");
    let constants = alternatives("constant.language.rts");
    for (i, b) in rts::eval::BUILTIN_NAMES.iter().enumerate() {
        let list = if rts::eval::is_builtin_function(i) {
            &functions
        } else {
            &constants
        };
        assert!(
            list.iter().any(|w| w == b),
            "built-in `{b}` missing from the grammar"
        );
    }
}

/// An include changed outside the editor (the client watches files for the server):
/// the open scene that includes it is checked again.
#[test]
fn includes_changed_on_disk_recheck_the_scene() {
    let dir = folder("watched");
    let lib = dir.join("lib.inc");
    std::fs::write(&lib, "#declare Size = 2;\n").expect("write");
    let scene = dir.join("scene.rts");
    let text = "global_settings { assumed_gamma 1.0 }\n\
light_source { <0, 5, -5> rgb 1 }\n#include \"lib.inc\"\nsphere { 0, Size }\n";
    let scene_uri = uri(&scene);
    let mut s = Server::start();
    s.request(
        "initialize",
        json!({"capabilities": {"workspace": {"didChangeWatchedFiles": {"dynamicRegistration": true}}}}),
    );
    s.notify("initialized", json!({}));
    // The server asks the client to watch scene files; answer it.
    let reg = loop {
        let m = s.recv();
        if m["method"] == "client/registerCapability" {
            break m;
        }
    };
    assert_eq!(
        reg["params"]["registrations"][0]["method"],
        "workspace/didChangeWatchedFiles"
    );
    s.send(json!({"jsonrpc": "2.0", "id": reg["id"], "result": null}));
    s.notify(
        "textDocument/didOpen",
        json!({"textDocument": {"uri": scene_uri, "languageId": "rts", "version": 1, "text": text}}),
    );
    assert!(errors(&s.diagnostics(&scene_uri)).is_empty());
    std::fs::write(&lib, "#declare Sizes = 2;\n").expect("write");
    s.notify(
        "workspace/didChangeWatchedFiles",
        json!({"changes": [{"uri": uri(&lib), "type": 2}]}),
    );
    let diags = s.diagnostics(&scene_uri);
    let errs = errors(&diags);
    assert_eq!(errs.len(), 1, "{diags:#?}");
    assert_eq!(range(errs[0]).0, 3);
}

#[test]
fn an_endless_loop_being_typed_is_cancelled_by_the_next_edit() {
    let dir = folder("endless");
    let scene = dir.join("loop.rts");
    let scene_uri = uri(&scene);
    // A loop that forgot its step and makes a sphere on every pass: alone it
    // runs until the editor's budgets end it.
    let endless = "#declare I = 0;\n#while (I < 10)\n  sphere { <I, 0, 0>, 1 }\n#end\n";
    let fixed = "#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\n\
                 light_source { <0, 5, -5> rgb 1 }\n\
                 #declare I = 0;\n#while (I < 10)\n  sphere { <I, 0, 0>, 1 }\n  \
                 #declare I = I + 1;\n#end\n";
    let mut s = Server::start();
    s.request("initialize", json!({"processId": null, "capabilities": {}}));
    s.notify("initialized", json!({}));
    s.notify(
        "textDocument/didOpen",
        json!({"textDocument": {"uri": scene_uri, "languageId": "rts", "version": 1, "text": endless}}),
    );
    // The next keystrokes arrive while the loop evaluates: the server reads
    // them at once, and the analysis of the older text is dropped.
    s.notify(
        "textDocument/didChange",
        json!({"textDocument": {"uri": scene_uri, "version": 2},
               "contentChanges": [{"text": fixed}]}),
    );
    let m = loop {
        let m = s.recv();
        if m["method"] == "textDocument/publishDiagnostics" {
            break m;
        }
    };
    // The first diagnostics published are the fixed text's: none.
    assert_eq!(m["params"]["version"], 2, "{m}");
    assert!(
        errors(m["params"]["diagnostics"].as_array().unwrap()).is_empty(),
        "{m}"
    );
    // And a request about the document answers from the new text.
    let symbols = s.request(
        "textDocument/documentSymbol",
        json!({"textDocument": {"uri": scene_uri}}),
    );
    assert!(symbols.to_string().contains("light"), "{symbols}");
}

#[test]
fn a_runaway_loop_alone_ends_at_the_editors_budget() {
    let dir = folder("runaway");
    let scene = dir.join("loop.rts");
    let scene_uri = uri(&scene);
    let endless = "#declare I = 0;\n#while (I < 10)\n  sphere { <I, 0, 0>, 1 }\n#end\n";
    let mut s = Server::start();
    s.request("initialize", json!({"processId": null, "capabilities": {}}));
    s.notify("initialized", json!({}));
    s.notify(
        "textDocument/didOpen",
        json!({"textDocument": {"uri": scene_uri, "languageId": "rts", "version": 1, "text": endless}}),
    );
    let diags = s.diagnostics(&scene_uri);
    let codes: Vec<&Value> = errors(&diags).iter().map(|d| &d["code"]).collect();
    assert_eq!(codes.len(), 1, "{diags:?}");
    assert!(
        [
            "rts::limit::memory",
            "rts::limit::loop_iterations",
            "rts::limit::time"
        ]
        .iter()
        .any(|c| codes[0] == c),
        "{diags:?}"
    );
}
