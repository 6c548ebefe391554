//! `rts lsp`: a Language Server on stdio (tower-lsp-server), a thin protocol layer over
//! [`rts::ide`]. Documents are analysed on open, change and save; documents that
//! include a changed file are analysed again. Analysis runs on a thread of its own
//! ([`worker`]) under `catch_unwind`, so a bug shows as a missing answer, never as a
//! dead server, and a slow scene never stops the server from reading the next edit,
//! which cancels it; nothing but protocol goes to stdout.

mod worker;

use rts::diag::Severity;
use rts::eval::EvalOptions;
use rts::ide::{self, index::OutlineKind, Analysis};
use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Mutex};
use std::time::Duration;
use tower_lsp_server::jsonrpc::Result;
use tower_lsp_server::ls_types as lsp;
use tower_lsp_server::{Client, LanguageServer, LspService, Server};

/// Arguments of `rts lsp`.
#[derive(Debug, clap::Args)]
pub struct LspArgs {
    /// Search DIR for #include files (after the including file's folder).
    #[arg(short = 'I', value_name = "DIR")]
    pub include: Vec<PathBuf>,
    /// Accepted for editors that pass it; the server always speaks over stdio.
    #[arg(long)]
    pub stdio: bool,
}

/// An open document.
struct Doc {
    path: PathBuf,
    text: String,
    version: i32,
    analysis: Option<Arc<Analysis>>,
    /// Counts the analyses asked for; only the newest one's result is kept.
    generation: u64,
    /// The cancellation flag of the analysis running for the current text,
    /// `None` when `analysis` is of the current text.
    pending: Option<Arc<AtomicBool>>,
}

impl Doc {
    fn new(path: PathBuf, text: String, version: i32) -> Doc {
        Doc {
            path,
            text,
            version,
            analysis: None,
            generation: 0,
            pending: None,
        }
    }
}

struct State {
    docs: HashMap<lsp::Uri, Doc>,
    options: EvalOptions,
    /// The client can watch files for us (include files changed outside the editor).
    watch_files: bool,
    /// Woken whenever an analysis is stored.
    ready: Arc<tokio::sync::Notify>,
}

struct Backend {
    client: Client,
    state: Arc<Mutex<State>>,
    worker: worker::Worker,
}

/// How long a request waits for the analysis of the text it is about before
/// it answers from the previous one.
const WAIT_FOR_ANALYSIS: Duration = Duration::from_secs(2);

/// Runs the server until the client exits; returns the exit status.
pub fn run(args: &LspArgs) -> i32 {
    let runtime = match tokio::runtime::Builder::new_current_thread().build() {
        Ok(r) => r,
        Err(e) => {
            eprintln!("error: cannot start the language server: {e}");
            return super::EXIT_ERRORS;
        }
    };
    let options = ide::editor_options(args.include.clone());
    let worker = match worker::Worker::start() {
        Ok(w) => w,
        Err(e) => {
            eprintln!("error: cannot start the language server's analysis thread: {e}");
            return super::EXIT_ERRORS;
        }
    };
    runtime.block_on(async move {
        let state = Arc::new(Mutex::new(State {
            docs: HashMap::new(),
            options,
            watch_files: false,
            ready: Arc::new(tokio::sync::Notify::new()),
        }));
        let (service, socket) = LspService::new(|client| Backend {
            client,
            state,
            worker,
        });
        Server::new(tokio::io::stdin(), tokio::io::stdout(), socket)
            .serve(service)
            .await;
    });
    super::EXIT_OK
}

fn lock(state: &Mutex<State>) -> std::sync::MutexGuard<'_, State> {
    state
        .lock()
        .unwrap_or_else(std::sync::PoisonError::into_inner)
}

/// Runs `f` and turns a panic into `None` (the panic message goes to stderr).
fn guarded<T>(f: impl FnOnce() -> T) -> Option<T> {
    std::panic::catch_unwind(std::panic::AssertUnwindSafe(f)).ok()
}

/// The folder the built-in library is written to so editors can open its files.
fn stdlib_dir() -> PathBuf {
    std::env::temp_dir().join(format!("rts-stdlib-{}", env!("CARGO_PKG_VERSION")))
}

/// The URI of a path of the analysis (`<stdlib>/NAME` maps to a copy on disk).
fn uri_of(path: &Path) -> Option<lsp::Uri> {
    if let Ok(name) = path.strip_prefix("<stdlib>") {
        let name = name.to_str()?;
        let (_, text) = rts::eval::STDLIB.iter().find(|(n, _)| *n == name)?;
        let dir = stdlib_dir();
        let file = dir.join(name);
        // In the shared temporary folder: read a regular file only (never wait on
        // a FIFO put there), and replace it by a rename, never writing through a
        // link someone else made.
        let current = rts::files::read_regular(&file, text.len() as u64).ok();
        if current.as_deref() != Some(text.as_bytes()) {
            use std::io::Write;
            std::fs::create_dir_all(&dir).ok()?;
            let mut out = rts::files::create(&file, rts::files::Policy::FileNoLink).ok()?;
            out.write_all(text.as_bytes()).ok()?;
            out.commit().ok()?;
        }
        return lsp::Uri::from_file_path(&file);
    }
    lsp::Uri::from_file_path(path)
}

fn pos(p: lsp::Position) -> ide::Position {
    ide::Position {
        line: p.line,
        character: p.character,
    }
}

fn range(r: ide::Range) -> lsp::Range {
    lsp::Range {
        start: lsp::Position::new(r.start.line, r.start.character),
        end: lsp::Position::new(r.end.line, r.end.character),
    }
}

fn location(l: &ide::Location) -> Option<lsp::Location> {
    Some(lsp::Location {
        uri: uri_of(&l.path)?,
        range: range(l.range),
    })
}

fn diagnostic(d: &ide::IdeDiagnostic) -> lsp::Diagnostic {
    let related: Vec<lsp::DiagnosticRelatedInformation> = d
        .related
        .iter()
        .filter_map(|r| {
            Some(lsp::DiagnosticRelatedInformation {
                location: location(&r.location)?,
                message: r.message.clone(),
            })
        })
        .collect();
    lsp::Diagnostic {
        range: range(d.range),
        severity: Some(match d.severity {
            Severity::Error => lsp::DiagnosticSeverity::ERROR,
            Severity::Warning => lsp::DiagnosticSeverity::WARNING,
            Severity::Note => lsp::DiagnosticSeverity::INFORMATION,
        }),
        code: Some(lsp::NumberOrString::String(d.code.to_string())),
        source: Some("rts".into()),
        message: d.message.clone(),
        related_information: (!related.is_empty()).then_some(related),
        ..Default::default()
    }
}

fn symbol(o: &ide::index::OutlineItem, a: &Analysis) -> lsp::DocumentSymbol {
    #[allow(deprecated)]
    lsp::DocumentSymbol {
        name: o.name.clone(),
        detail: (!o.detail.is_empty()).then(|| o.detail.clone()),
        kind: match o.kind {
            OutlineKind::Variable => lsp::SymbolKind::VARIABLE,
            OutlineKind::Macro => lsp::SymbolKind::FUNCTION,
            OutlineKind::Object => lsp::SymbolKind::OBJECT,
            OutlineKind::Camera => lsp::SymbolKind::CLASS,
            OutlineKind::Light => lsp::SymbolKind::EVENT,
            OutlineKind::Settings => lsp::SymbolKind::NAMESPACE,
        },
        tags: None,
        deprecated: None,
        range: range(a.range(o.span)),
        selection_range: range(a.range(o.name_span)),
        children: (!o.children.is_empty())
            .then(|| o.children.iter().map(|c| symbol(c, a)).collect()),
    }
}

impl Backend {
    /// The analysis of an open document, of its current text when that
    /// analysis finishes within [`WAIT_FOR_ANALYSIS`], else the last one.
    async fn analysis(&self, uri: &lsp::Uri) -> Option<Arc<Analysis>> {
        let until = tokio::time::Instant::now() + WAIT_FOR_ANALYSIS;
        loop {
            let ready = lock(&self.state).ready.clone();
            let notified = ready.notified();
            tokio::pin!(notified);
            notified.as_mut().enable();
            {
                let st = lock(&self.state);
                let doc = st.docs.get(uri)?;
                if doc.pending.is_none() {
                    return doc.analysis.clone();
                }
            }
            if tokio::time::timeout_at(until, notified).await.is_err() {
                return lock(&self.state).docs.get(uri)?.analysis.clone();
            }
        }
    }

    /// Analyses `uri` and the open documents that include it; publishes diagnostics.
    async fn refresh(&self, uri: &lsp::Uri) {
        let Some(changed) = lock(&self.state)
            .docs
            .get(uri)
            .map(|d| ide::canonical(&d.path))
        else {
            return;
        };
        self.refresh_path(Some(uri), &changed);
    }

    /// Analyses `uri` (when given) and the open documents that include the file
    /// `changed`, on the analysis thread; each document's diagnostics are
    /// published when its analysis ends, unless a newer one was asked for
    /// meanwhile (which cancels it).
    fn refresh_path(&self, uri: Option<&lsp::Uri>, changed: &Path) {
        let mut st = lock(&self.state);
        let overlays: HashMap<PathBuf, String> = st
            .docs
            .values()
            .map(|d| (ide::canonical(&d.path), d.text.clone()))
            .collect();
        let options = st.options.clone();
        let ready = st.ready.clone();
        let targets: Vec<lsp::Uri> = st
            .docs
            .iter()
            .filter(|(u, d)| {
                Some(*u) == uri
                    || d.analysis
                        .as_ref()
                        .is_some_and(|a| a.included_paths().iter().any(|p| p == changed))
            })
            .map(|(u, _)| u.clone())
            .collect();
        for u in targets {
            let Some(doc) = st.docs.get_mut(&u) else {
                continue;
            };
            if let Some(old) = doc.pending.take() {
                old.store(true, Ordering::Relaxed);
            }
            let cancel = Arc::new(AtomicBool::new(false));
            doc.pending = Some(cancel.clone());
            doc.generation += 1;
            let (generation, version) = (doc.generation, doc.version);
            let mut options = options.clone();
            options.interrupt.cancel = Some(cancel);
            let (reply, answer) = tokio::sync::oneshot::channel();
            let job = worker::Job {
                path: doc.path.clone(),
                text: doc.text.clone(),
                overlays: overlays.clone(),
                options,
                reply,
            };
            if !self.worker.submit(job) {
                doc.pending = None;
                continue;
            }
            let (state, client, ready) = (self.state.clone(), self.client.clone(), ready.clone());
            tokio::spawn(async move {
                let analysis = answer.await.ok().flatten();
                let published = {
                    let mut st = lock(&state);
                    let Some(doc) = st.docs.get_mut(&u) else {
                        return;
                    };
                    if doc.generation != generation {
                        return; // a newer analysis of this document is on its way
                    }
                    doc.pending = None;
                    let diags = analysis.as_ref().and_then(|a| {
                        guarded(|| {
                            ide::diagnostics(a)
                                .iter()
                                .map(diagnostic)
                                .collect::<Vec<_>>()
                        })
                    });
                    if analysis.is_some() {
                        doc.analysis = analysis.map(Arc::new);
                    }
                    diags
                };
                ready.notify_waiters();
                if let Some(diags) = published {
                    client.publish_diagnostics(u, diags, Some(version)).await;
                }
            });
        }
    }
}

fn to_path(uri: &lsp::Uri) -> PathBuf {
    uri.to_file_path()
        .map(|p| p.into_owned())
        .unwrap_or_else(|| PathBuf::from(uri.as_str()))
}

impl LanguageServer for Backend {
    async fn initialize(&self, params: lsp::InitializeParams) -> Result<lsp::InitializeResult> {
        // `initializationOptions: { "includeDirs": ["…"] }` adds -I folders.
        if let Some(dirs) = params
            .initialization_options
            .as_ref()
            .and_then(|o| o.get("includeDirs"))
            .and_then(|d| d.as_array())
        {
            let mut st = lock(&self.state);
            st.options
                .access
                .include_dirs
                .extend(dirs.iter().filter_map(|d| d.as_str()).map(PathBuf::from));
        }
        lock(&self.state).watch_files = params
            .capabilities
            .workspace
            .as_ref()
            .and_then(|w| w.did_change_watched_files.as_ref())
            .and_then(|d| d.dynamic_registration)
            .unwrap_or(false);
        let legend = lsp::SemanticTokensLegend {
            token_types: ide::TOKEN_TYPES
                .iter()
                .map(|t| lsp::SemanticTokenType::from(*t))
                .collect(),
            token_modifiers: ide::TOKEN_MODIFIERS
                .iter()
                .map(|t| lsp::SemanticTokenModifier::from(*t))
                .collect(),
        };
        Ok(lsp::InitializeResult {
            capabilities: lsp::ServerCapabilities {
                text_document_sync: Some(lsp::TextDocumentSyncCapability::Options(
                    lsp::TextDocumentSyncOptions {
                        open_close: Some(true),
                        change: Some(lsp::TextDocumentSyncKind::FULL),
                        save: Some(lsp::TextDocumentSyncSaveOptions::Supported(true)),
                        ..Default::default()
                    },
                )),
                hover_provider: Some(lsp::HoverProviderCapability::Simple(true)),
                completion_provider: Some(lsp::CompletionOptions {
                    trigger_characters: Some(vec!["#".into(), "\"".into(), "/".into()]),
                    ..Default::default()
                }),
                definition_provider: Some(lsp::OneOf::Left(true)),
                references_provider: Some(lsp::OneOf::Left(true)),
                document_symbol_provider: Some(lsp::OneOf::Left(true)),
                document_formatting_provider: Some(lsp::OneOf::Left(true)),
                semantic_tokens_provider: Some(
                    lsp::SemanticTokensOptions {
                        legend,
                        full: Some(lsp::SemanticTokensFullOptions::Bool(true)),
                        ..Default::default()
                    }
                    .into(),
                ),
                ..Default::default()
            },
            server_info: Some(lsp::ServerInfo {
                name: "rts".into(),
                version: Some(env!("CARGO_PKG_VERSION").into()),
            }),
            ..Default::default()
        })
    }

    async fn initialized(&self, _: lsp::InitializedParams) {
        if !lock(&self.state).watch_files {
            return;
        }
        let options = lsp::DidChangeWatchedFilesRegistrationOptions {
            watchers: ["**/*.rts", "**/*.inc", "**/*.pov"]
                .iter()
                .map(|g| lsp::FileSystemWatcher {
                    glob_pattern: lsp::GlobPattern::String((*g).to_string()),
                    kind: None,
                })
                .collect(),
        };
        let registration = lsp::Registration {
            id: "rts-watch-includes".into(),
            method: "workspace/didChangeWatchedFiles".into(),
            register_options: serde_json::to_value(options).ok(),
        };
        let _ = self.client.register_capability(vec![registration]).await;
    }

    async fn did_change_watched_files(&self, params: lsp::DidChangeWatchedFilesParams) {
        // An include changed outside the editor: check the open scenes that read it.
        for change in params.changes {
            let path = ide::canonical(&to_path(&change.uri));
            self.refresh_path(None, &path);
        }
    }

    async fn shutdown(&self) -> Result<()> {
        Ok(())
    }

    async fn did_open(&self, params: lsp::DidOpenTextDocumentParams) {
        let doc = params.text_document;
        lock(&self.state).docs.insert(
            doc.uri.clone(),
            Doc::new(to_path(&doc.uri), doc.text, doc.version),
        );
        self.refresh(&doc.uri).await;
    }

    async fn did_change(&self, params: lsp::DidChangeTextDocumentParams) {
        let uri = params.text_document.uri;
        {
            let mut st = lock(&self.state);
            let Some(doc) = st.docs.get_mut(&uri) else {
                return;
            };
            // Full sync: the last change holds the whole text.
            if let Some(change) = params.content_changes.into_iter().last() {
                doc.text = change.text;
            }
            doc.version = params.text_document.version;
        }
        self.refresh(&uri).await;
    }

    async fn did_save(&self, params: lsp::DidSaveTextDocumentParams) {
        if let Some(text) = params.text {
            if let Some(doc) = lock(&self.state).docs.get_mut(&params.text_document.uri) {
                doc.text = text;
            }
        }
        self.refresh(&params.text_document.uri).await;
    }

    async fn did_close(&self, params: lsp::DidCloseTextDocumentParams) {
        let uri = params.text_document.uri;
        if let Some(doc) = lock(&self.state).docs.remove(&uri) {
            if let Some(c) = doc.pending {
                c.store(true, Ordering::Relaxed);
            }
        }
        self.client.publish_diagnostics(uri, Vec::new(), None).await;
    }

    async fn hover(&self, params: lsp::HoverParams) -> Result<Option<lsp::Hover>> {
        let p = params.text_document_position_params;
        let Some(a) = self.analysis(&p.text_document.uri).await else {
            return Ok(None);
        };
        Ok(guarded(|| ide::hover(&a, pos(p.position)))
            .flatten()
            .map(|(md, r)| lsp::Hover {
                contents: lsp::HoverContents::Markup(lsp::MarkupContent {
                    kind: lsp::MarkupKind::Markdown,
                    value: md,
                }),
                range: Some(range(r)),
            }))
    }

    async fn completion(
        &self,
        params: lsp::CompletionParams,
    ) -> Result<Option<lsp::CompletionResponse>> {
        let p = params.text_document_position;
        // Complete against the text as it is now: wait for its analysis.
        let Some(a) = self.analysis(&p.text_document.uri).await else {
            return Ok(None);
        };
        let items = guarded(|| ide::completion(&a, pos(p.position))).unwrap_or_default();
        let items = items
            .into_iter()
            .map(|c| {
                use ide::CompletionKind as K;
                lsp::CompletionItem {
                    kind: Some(match c.kind {
                        K::Keyword | K::Directive => lsp::CompletionItemKind::KEYWORD,
                        K::Variable => lsp::CompletionItemKind::VARIABLE,
                        K::Macro | K::Function => lsp::CompletionItemKind::FUNCTION,
                        K::Constant => lsp::CompletionItemKind::CONSTANT,
                        K::File => lsp::CompletionItemKind::FILE,
                    }),
                    detail: Some(c.detail),
                    insert_text_format: c.snippet.as_ref().map(|_| lsp::InsertTextFormat::SNIPPET),
                    text_edit: c.replace.map(|r| {
                        lsp::CompletionTextEdit::Edit(lsp::TextEdit {
                            range: range(r),
                            new_text: c.label.clone(),
                        })
                    }),
                    insert_text: c.snippet,
                    label: c.label,
                    ..Default::default()
                }
            })
            .collect();
        Ok(Some(lsp::CompletionResponse::Array(items)))
    }

    async fn goto_definition(
        &self,
        params: lsp::GotoDefinitionParams,
    ) -> Result<Option<lsp::GotoDefinitionResponse>> {
        let p = params.text_document_position_params;
        let Some(a) = self.analysis(&p.text_document.uri).await else {
            return Ok(None);
        };
        Ok(guarded(|| ide::definition(&a, pos(p.position)))
            .flatten()
            .and_then(|l| location(&l))
            .map(lsp::GotoDefinitionResponse::Scalar))
    }

    async fn references(&self, params: lsp::ReferenceParams) -> Result<Option<Vec<lsp::Location>>> {
        let p = params.text_document_position;
        let Some(a) = self.analysis(&p.text_document.uri).await else {
            return Ok(None);
        };
        let locs =
            guarded(|| ide::references(&a, pos(p.position), params.context.include_declaration))
                .unwrap_or_default();
        Ok(Some(locs.iter().filter_map(location).collect()))
    }

    async fn document_symbol(
        &self,
        params: lsp::DocumentSymbolParams,
    ) -> Result<Option<lsp::DocumentSymbolResponse>> {
        let Some(a) = self.analysis(&params.text_document.uri).await else {
            return Ok(None);
        };
        let symbols = guarded(|| ide::outline(&a).iter().map(|o| symbol(o, &a)).collect());
        Ok(symbols.map(lsp::DocumentSymbolResponse::Nested))
    }

    async fn formatting(
        &self,
        params: lsp::DocumentFormattingParams,
    ) -> Result<Option<Vec<lsp::TextEdit>>> {
        let Some(a) = self.analysis(&params.text_document.uri).await else {
            return Ok(None);
        };
        let unit = if params.options.insert_spaces {
            " ".repeat(params.options.tab_size.clamp(1, 16) as usize)
        } else {
            "\t".to_string()
        };
        let text = a.text();
        let Some(formatted) = guarded(|| ide::format(text, &unit)) else {
            return Ok(None);
        };
        if formatted == text {
            return Ok(Some(Vec::new()));
        }
        let whole = ide::LineIndex::new(text).range(text, 0, text.len());
        Ok(Some(vec![lsp::TextEdit {
            range: range(whole),
            new_text: formatted,
        }]))
    }

    async fn semantic_tokens_full(
        &self,
        params: lsp::SemanticTokensParams,
    ) -> Result<Option<lsp::SemanticTokensResult>> {
        let Some(a) = self.analysis(&params.text_document.uri).await else {
            return Ok(None);
        };
        let Some(tokens) = guarded(|| ide::semantic_tokens(&a)) else {
            return Ok(None);
        };
        let mut data = Vec::with_capacity(tokens.len());
        let (mut line, mut start) = (0, 0);
        for t in tokens {
            let delta_line = t.line - line;
            let delta_start = if delta_line == 0 {
                t.start - start
            } else {
                t.start
            };
            data.push(lsp::SemanticToken {
                delta_line,
                delta_start,
                length: t.length,
                token_type: t.token_type,
                token_modifiers_bitset: t.modifiers,
            });
            line = t.line;
            start = t.start;
        }
        Ok(Some(lsp::SemanticTokensResult::Tokens(
            lsp::SemanticTokens {
                result_id: None,
                data,
            },
        )))
    }
}
