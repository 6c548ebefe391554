//! The evaluator's state for one run, how failures are reported with the
//! include/macro chain that led to them, and what the end of a run checks
//! (unused names, gamma, lights).

use super::budget::Spent;
use super::context::Context;
use super::file_io::{OpenFile, Overlay};
use super::images::ImageCache;
use super::scope::Scopes;
use super::trace::BuiltObjects;
use crate::diag::{codes, Diagnostic, Label};
use crate::eval::objects::mesh_cache::MeshCache;
use crate::eval::objects::text::FontCache;
use crate::eval::{EvalCache, EvalOptions, Evaluated};
use crate::scene::{Scene, Texture};
use crate::source::SourceMap;
use crate::span::{FileId, Span};
use crate::syntax::ast;
use std::path::PathBuf;
use std::sync::Arc;

/// A failure while evaluating: the diagnostic to report, or `None` when the cause was
/// already reported (a poisoned value).
#[derive(Debug)]
pub(crate) struct Fail(Option<Box<Diagnostic>>);

impl From<Diagnostic> for Fail {
    fn from(d: Diagnostic) -> Fail {
        Fail(Some(Box::new(d)))
    }
}

impl Fail {
    /// A failure that reports nothing (its cause was reported already).
    pub(crate) fn silent() -> Fail {
        Fail(None)
    }
}

/// Result of evaluation steps.
pub(crate) type R<T> = Result<T, Fail>;

/// The evaluator's state for one run.
pub(crate) struct Evaluator<'a> {
    pub(crate) sources: &'a mut SourceMap,
    pub(crate) options: &'a EvalOptions,
    pub(crate) scope: Scopes,
    pub(crate) diags: Vec<Diagnostic>,
    /// The isosurfaces the render is to check (`EvalOptions::sample_gradients` off).
    pub(crate) slope_checks: Vec<crate::eval::SlopeCheck>,
    pub(crate) scene: Scene,
    pub(crate) camera_seen: Option<Span>,
    /// Include and macro-call sites on the way to the current item, outermost first.
    pub(crate) trace: Vec<Label>,
    pub(crate) default_texture: Arc<Texture>,
    pub(crate) loop_iterations: u64,
    pub(crate) macro_depth: usize,
    pub(crate) include_stack: Vec<FileId>,
    pub(crate) scene_dir: Option<PathBuf>,
    pub(crate) rand_streams: Vec<u64>,
    /// Set by `#error` and limits: evaluation stops.
    pub(crate) stopped: bool,
    /// The language version set by the last `#version` (a standard include file
    /// sets 3.7 when none was, as POV-Ray's own do); `None` when never set.
    pub(crate) language_version: Option<f64>,
    /// Include files parsed so far (`None`: it had syntax errors, already reported).
    pub(crate) parsed_includes: rustc_hash::FxHashMap<FileId, Option<std::rc::Rc<ast::File>>>,
    /// Meshes kept from earlier evaluations of the same scene.
    pub(crate) mesh_cache: MeshCache,
    /// Decoded images, kept from earlier evaluations of the same scene.
    pub(crate) images: ImageCache,
    /// Pixels of the images this evaluation reads (each file counted once),
    /// against [`EvalOptions::max_image_pixels`].
    pub(crate) image_pixels: u64,
    /// Fonts read by `text` objects, by file.
    pub(crate) fonts: FontCache,
    /// Data files found (for the animation manifest's scene hash).
    pub(crate) data_files: std::cell::RefCell<Vec<PathBuf>>,
    /// What the items being expanded are inside (see `context.rs`).
    pub(crate) ctx: Context,
    /// Objects built for `trace`, `min_extent` and `max_extent`.
    pub(crate) built_objects: BuiltObjects,
    /// Files written by `#write` in this evaluation (see `file_io.rs`).
    pub(crate) written: Overlay,
    /// Bytes the files being written hold so far, all together (see
    /// [`EvalOptions::max_write`]).
    pub(crate) written_bytes: u64,
    /// Files opened for writing, closed at the end if the scene does not.
    pub(crate) open_writes: Vec<std::rc::Rc<std::cell::RefCell<OpenFile>>>,
    /// Names declared `deprecated`, with whether a `once` warning was given.
    pub(crate) deprecated:
        rustc_hash::FxHashMap<crate::syntax::Sym, (ast::Deprecation, std::cell::Cell<bool>)>,
    /// Names ever opened by `#fopen` (closing one twice is allowed).
    pub(crate) files_seen: rustc_hash::FxHashSet<crate::syntax::Sym>,
    /// Names whose last `#fopen` failed (and was reported): their `#read` and
    /// `#write` report nothing more.
    pub(crate) files_failed: rustc_hash::FxHashSet<crate::syntax::Sym>,
    /// `light_group`s made so far (each takes one bit of the objects' masks).
    pub(crate) light_groups: u32,
    /// What the evaluation has spent of its budgets (see `budget.rs`).
    pub(crate) spent: Spent,
    /// Parts of the file were skipped after syntax errors: warnings about the
    /// scene as a whole (no light, unused names) would only mislead.
    pub(crate) partial: bool,
    /// Built-in library items not evaluated yet (see `lazy.rs`).
    pub(crate) pending: super::lazy::Pending,
    /// The unit being evaluated read a per-frame value (see `reuse.rs`).
    pub(crate) moving: std::cell::Cell<bool>,
    /// What the unit being evaluated reported (see `reuse.rs`).
    pub(crate) unit_diags: Option<Vec<Diagnostic>>,
    /// Changes with each `#default` (see `reuse.rs`).
    pub(crate) default_stamp: u64,
    /// Units evaluated once for all frames (see `reuse.rs`).
    pub(crate) reuse: super::reuse::Reuse,
    /// Bodies of macros read token by token, parsed at their calls (see
    /// `token_level.rs`).
    pub(crate) token_bodies: super::token_level::TokenBodies,
}

/// The longest include/macro chain shown in full: the innermost and outermost steps
/// are kept around a gap.
const MAX_TRACE: usize = 12;

/// The chain innermost first, with runs of the same step (recursion) merged into one
/// "(N times)" step and the middle of a very long chain left out. Returns the steps
/// and how many were left out.
fn compress_trace(trace: &[Label]) -> (Vec<Label>, usize) {
    let mut steps: Vec<(Label, usize)> = Vec::new();
    for l in trace.iter().rev() {
        match steps.last_mut() {
            Some((last, n)) if last.span == l.span && last.message == l.message => *n += 1,
            _ => steps.push((l.clone(), 1)),
        }
    }
    let mut out: Vec<Label> = steps
        .into_iter()
        .map(|(mut l, n)| {
            if n > 1 {
                l.message = format!("{} ({n} times)", l.message);
            }
            l
        })
        .collect();
    let mut omitted = 0;
    if out.len() > MAX_TRACE {
        let keep_tail = MAX_TRACE / 2;
        omitted = out.len() - MAX_TRACE;
        out.drain(MAX_TRACE - keep_tail..out.len() - keep_tail);
    }
    (out, omitted)
}

impl<'a> Evaluator<'a> {
    /// An evaluator for the file `file_id` of `sources`, taking what `cache`
    /// kept from the last evaluation of the same scene.
    pub(crate) fn start(
        file_id: FileId,
        sources: &'a mut SourceMap,
        options: &'a EvalOptions,
        cache: &mut EvalCache,
    ) -> Evaluator<'a> {
        let scene_dir = sources.get(file_id).dir().map(PathBuf::from);
        cache.meshes.begin();
        cache.images.begin();
        let mut records = std::mem::take(&mut cache.records);
        let on = options.reuse && options.clock_on;
        if on {
            records.begin(options);
        }
        let scope = Scopes::new();
        scope.next_stamp.set(records.next_stamp.max(1));
        Evaluator {
            sources,
            options,
            scope,
            diags: Vec::new(),
            slope_checks: Vec::new(),
            scene: Scene::default(),
            camera_seen: None,
            trace: Vec::new(),
            default_texture: Arc::new(Texture::default()),
            loop_iterations: 0,
            macro_depth: 0,
            include_stack: vec![file_id],
            scene_dir,
            rand_streams: Vec::new(),
            stopped: false,
            language_version: None,
            parsed_includes: std::mem::take(&mut cache.parsed_includes),
            mesh_cache: std::mem::take(&mut cache.meshes),
            images: std::mem::take(&mut cache.images),
            image_pixels: 0,
            data_files: Default::default(),
            fonts: Default::default(),
            ctx: Context::default(),
            built_objects: Default::default(),
            written: Default::default(),
            written_bytes: 0,
            open_writes: Vec::new(),
            files_seen: Default::default(),
            files_failed: Default::default(),
            deprecated: Default::default(),
            light_groups: 0,
            spent: Spent::start(),
            partial: false,
            pending: Default::default(),
            moving: Default::default(),
            unit_diags: None,
            default_stamp: 0,
            reuse: super::reuse::Reuse::new(records),
            token_bodies: Default::default(),
        }
    }

    /// Turns units on (after the command line's definitions) when the options
    /// ask for them (see `reuse.rs`).
    pub(crate) fn start_units(&mut self) {
        self.reuse.on = self.options.reuse && self.options.clock_on;
    }

    /// Closes what the scene left open, gives `cache` what the next evaluation
    /// of the scene may reuse, and makes the result.
    pub(crate) fn finish_run(mut self, cache: &mut EvalCache) -> Evaluated {
        let main = self.include_stack[0];
        self.close_all_files(Span::new(main, 0, 0));
        cache.parsed_includes = std::mem::take(&mut self.parsed_includes);
        cache.meshes = std::mem::take(&mut self.mesh_cache);
        cache.meshes.end();
        cache.images = std::mem::take(&mut self.images);
        cache.images.end();
        cache.data_files.extend(self.data_files.take());
        self.reuse.records.next_stamp = self.scope.next_stamp.get();
        cache.records = std::mem::take(&mut self.reuse.records);
        self.finish_scene()
    }

    /// Records a failure with the current include/macro chain.
    pub(crate) fn report(&mut self, fail: Fail) {
        if let Some(mut d) = fail.0 {
            let (trace, omitted) = compress_trace(&self.trace);
            d.trace.extend(trace);
            if omitted > 0 {
                d.notes.push(format!(
                    "{omitted} more steps of the include/macro chain are not shown"
                ));
            }
            self.record(*d);
        }
    }

    /// Records a warning or note.
    pub(crate) fn warn(&mut self, d: Diagnostic) {
        self.report(d.into());
    }

    pub(crate) fn define_command_line(&mut self) {
        let defines = self.options.defines.clone();
        for (name, value) in defines {
            let text = format!("#declare {name} = {value};\n");
            let id = self
                .sources
                .add(format!("<-D {name}={value}>"), None, text.clone());
            let (file, diags) = crate::syntax::parse(&text, id);
            if !diags.is_empty() {
                let span = Span::new(id, 0, text.len().saturating_sub(1));
                self.diags.push(
                    Diagnostic::error(codes::BAD_DEFINE, span, format!("cannot use `-D {name}={value}`"))
                        .with_help("write -D NAME=VALUE with a name and an expression, e.g. -D Radius=2 or -D Name=\\\"text\\\""),
                );
                continue;
            }
            self.moving.set(false);
            self.run_top(&file.items);
            // The same definition gives the same value in every frame unless
            // it reads the clock (see `reuse.rs`).
            if !self.moving.get() {
                let mut h = rustc_hash::FxHasher::default();
                std::hash::Hash::hash(&(&name, &value), &mut h);
                let stamp = std::hash::Hasher::finish(&h) | 1 << 63;
                self.scope.set_stamp(0, crate::syntax::intern(&name), stamp);
            }
        }
    }

    /// Every word written in the bodies of the global macros.
    fn names_in_macro_bodies(&self) -> rustc_hash::FxHashSet<String> {
        let mut words = rustc_hash::FxHashSet::default();
        for m in self.scope.global_macros() {
            let (Some(first), Some(last)) = (m.body.first(), m.body.last()) else {
                continue;
            };
            let (a, b) = (first.span(), last.span());
            if a.file != b.file || a.start > b.end {
                continue;
            }
            let text = &self.sources.get(a.file).text;
            let Some(body) = text.get(a.start as usize..b.end as usize) else {
                continue;
            };
            words.extend(
                body.split(|c: char| !(c.is_alphanumeric() || c == '_'))
                    .filter(|w| !w.is_empty())
                    .map(str::to_string),
            );
        }
        words
    }

    fn finish_scene(mut self) -> Evaluated {
        self.note_repeats();
        // An include file checked on its own (`rts check lib.inc`, the editor)
        // is a library, not a scene: no camera, light or gamma is expected of
        // it, and its declarations are for the scenes that include it.
        let library = self
            .sources
            .get(self.include_stack[0])
            .path
            .as_deref()
            .and_then(|p| p.extension())
            .is_some_and(|e| e.eq_ignore_ascii_case("inc"));
        let warn = !library && !self.partial;
        if !crate::diag::has_errors(&self.diags) {
            let main = self.include_stack[0];
            let in_macros = self.names_in_macro_bodies();
            for (name, span) in self.scope.unused_globals().into_iter().filter(|_| warn) {
                // A name a macro's text refers to is used whenever the macro
                // is called, even if this run never called it.
                if span.file != main
                    || name.name().starts_with('_')
                    || in_macros.contains(&*name.name())
                {
                    continue;
                }
                self.diags.push(
                    Diagnostic::warning(
                        codes::UNUSED_DECLARE,
                        span,
                        format!("`{name}` is declared but never used"),
                    )
                    .with_label("never used after this")
                    .with_help(format!(
                        "remove the declaration, or name it `_{name}` to keep it unused on purpose"
                    )),
                );
            }
            self.scene.global.pre_3_7 = self.language_version.is_none_or(|v| v < 3.7);
            if self.scene.global.assumed_gamma.is_none() {
                // POV-Ray 3.7 assumes 1.0 in a 3.7 scene; in a scene of an older
                // version, or of none, it turns gamma handling off (measured).
                let legacy = self.language_version.is_none_or(|v| v < 3.7);
                self.scene.global.gamma_off = legacy;
                let help = if legacy {
                    "add `#version 3.7;` and `global_settings { assumed_gamma 1.0 }`; without either, POV-Ray and rts turn gamma handling off (colours are written to the file as they are)"
                } else {
                    "add `global_settings { assumed_gamma 1.0 }` (POV-Ray 3.7 assumes 1.0 and warns too)"
                };
                if warn {
                    self.diags.push(
                        Diagnostic::warning(
                            codes::NO_GAMMA,
                            Span::new(self.include_stack[0], 0, 0),
                            "the scene does not set assumed_gamma",
                        )
                        .with_help(help),
                    );
                }
            }
            if warn
                && self.scene.lights.is_empty()
                && !self.scene.objects.is_empty()
                && self.scene.global.path_tracing.is_none()
            {
                let help = if self.scene.global.radiosity.is_some() {
                    "add `light_source { <10, 10, -10> color rgb 1 }`; radiosity will gather only the background, sky and `emission`"
                } else {
                    "add `light_source { <10, 10, -10> color rgb 1 }`; only ambient light will show"
                };
                self.diags.push(
                    Diagnostic::warning(
                        codes::NO_LIGHTS,
                        Span::new(self.include_stack[0], 0, 0),
                        "the scene has no light sources",
                    )
                    .with_help(help),
                );
            }
        }
        let globals = if self.options.describe_globals {
            self.scope.globals()
        } else {
            Vec::new()
        };
        Evaluated {
            scene: self.scene,
            diagnostics: self.diags,
            globals,
            slope_checks: self.slope_checks,
        }
    }
}
