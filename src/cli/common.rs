//! The front half of the pipeline for the CLI: load, parse, evaluate, print diagnostics.

use super::{MessageFormat, SceneArgs};
use rts::diag::{codes, render as diag_render, Diagnostic};
use rts::eval::{self, EvalOptions};
use rts::scene::Scene;
use rts::source::{FileAccess, SourceMap};
use std::io::{IsTerminal, Write};
use std::path::Path;

/// A loaded and evaluated scene with everything needed to print its diagnostics.
pub struct Loaded {
    /// The scene, unless it has errors.
    pub scene: Option<Scene>,
    /// All files read.
    pub sources: SourceMap,
    /// Every diagnostic.
    pub diagnostics: Vec<Diagnostic>,
}

/// Evaluation options from the command line.
pub fn eval_options(args: &SceneArgs, width: u32, height: u32) -> Result<EvalOptions, String> {
    let mut defines = Vec::new();
    for d in &args.define {
        let Some((name, value)) = d.split_once('=') else {
            return Err(format!("-D {d}: expected NAME=VALUE"));
        };
        let name = name.trim();
        if name.is_empty()
            || !name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_')
            || name.starts_with(|c: char| c.is_ascii_digit())
        {
            return Err(format!("-D {d}: `{name}` is not a valid name"));
        }
        defines.push((name.to_string(), value.to_string()));
    }
    Ok(EvalOptions {
        access: FileAccess {
            include_dirs: args.include.clone(),
            allowed: args.allow_path.clone(),
            unrestricted: args.allow_any_path,
        },
        defines,
        clock: args.clock.unwrap_or(0.0),
        clock_on: args.clock.is_some(),
        image_width: f64::from(width),
        image_height: f64::from(height),
        max_loop_iterations: args.max_loop_iterations,
        max_macro_depth: args.max_macro_depth,
        max_array_size: args.max_array_size,
        max_object_depth: args.max_object_depth,
        max_memory: args
            .max_memory
            .unwrap_or_else(rts::memory::default_eval_budget),
        max_macro_calls: args.max_macro_calls,
        max_string_length: usize::try_from(args.max_string_length).unwrap_or(usize::MAX),
        max_errors: args.max_errors.max(1),
        max_write: args.max_write,
        max_source_size: args.max_source_size,
        max_image_pixels: args.max_image_pixels,
        ..EvalOptions::default()
    })
}

/// A scene file read and parsed once, ready to be evaluated for any number of
/// frames.
pub struct Parsed {
    /// All files read (the scene, then includes as evaluation finds them).
    pub sources: SourceMap,
    /// The scene file's id.
    pub id: rts::span::FileId,
    /// The syntax tree: complete when there are no syntax errors, else the items
    /// that parsed (`None` when nothing could be).
    pub file: Option<rts::syntax::ast::File>,
    /// Syntax diagnostics.
    pub diagnostics: Vec<Diagnostic>,
    /// What one evaluation keeps for the next (includes, meshes).
    pub cache: eval::EvalCache,
    /// The isosurfaces the evaluations asked the render to check, not yet
    /// warned about.
    pub slope_checks: Vec<eval::SlopeCheck>,
    /// Where those warned about are.
    pub slope_warned: Vec<rts::span::Span>,
}

/// Reads and parses `path`, a regular file of at most `max_size` bytes. `Err` when
/// the file cannot be read at all. For a render (`defer`), long branch bodies
/// are read when taken ([`rts::syntax::parse_with`]).
pub fn parse(path: &Path, max_size: u64, defer: bool) -> Result<Parsed, String> {
    let mut sources = SourceMap::new();
    let name = path.display().to_string();
    let id = match eval::load_file_limited(&mut sources, path, name, max_size) {
        Ok(id) => id,
        Err(eval::LoadError::Io(e)) => return Err(format!("cannot read {}: {e}", path.display())),
        Err(eval::LoadError::NotRegular(k)) => {
            return Err(format!(
                "cannot read {}: it is {}, not a regular file; give the scene's file",
                path.display(),
                k.describe()
            ))
        }
        Err(eval::LoadError::TooLarge(limit)) => {
            return Err(format!(
                "cannot read {}: it is larger than {} (--max-source-size); check that it is the scene meant, or raise the limit with --max-source-size SIZE",
                path.display(),
                rts::memory::show_size(limit)
            ))
        }
        Err(eval::LoadError::Utf8(d)) => {
            let id = rts::span::FileId(0);
            return Ok(Parsed {
                sources,
                id,
                file: None,
                diagnostics: vec![*d],
                cache: eval::EvalCache::default(),
                slope_checks: Vec::new(),
                slope_warned: Vec::new(),
            });
        }
    };
    let text = sources.get(id).text.clone();
    let (file, diagnostics) = rts::syntax::parse_with(&text, id, 0, defer);
    // After syntax errors the items that parsed are still evaluated (for their
    // own errors), unless nothing could be parsed (the prepass stopped it).
    let evaluable = !rts::diag::has_errors(&diagnostics) || !file.unparsed.is_empty();
    let file = evaluable.then_some(file);
    Ok(Parsed {
        sources,
        id,
        file,
        diagnostics,
        cache: eval::EvalCache::default(),
        slope_checks: Vec::new(),
        slope_warned: Vec::new(),
    })
}

impl Parsed {
    /// The `max_gradient` warnings of the renders so far (POV-Ray's, after a
    /// render): each isosurface is warned about once.
    pub fn slope_warnings(&mut self) -> Vec<Diagnostic> {
        let mut out = Vec::new();
        self.slope_checks.retain(|c| match c.warning() {
            Some(w) => {
                out.push(w);
                self.slope_warned.push(c.span);
                false
            }
            None => true,
        });
        out
    }

    /// Evaluates the scene with `options`: the scene when there was no error, and
    /// the evaluation's diagnostics.
    pub fn eval(&mut self, options: &EvalOptions) -> (Option<Scene>, Vec<Diagnostic>) {
        let Some(file) = &self.file else {
            return (None, Vec::new());
        };
        let evaluated =
            eval::eval_cached(file, self.id, &mut self.sources, options, &mut self.cache);
        for check in evaluated.slope_checks {
            // An item evaluated again for a later frame: its new isosurface is
            // the one the next render meets (the last one's was checked after
            // its render); one warned about already is not checked again.
            if self.slope_warned.contains(&check.span) {
                continue;
            }
            match self.slope_checks.iter_mut().find(|c| c.span == check.span) {
                Some(old) => *old = check,
                None => self.slope_checks.push(check),
            }
        }
        let scene = (!rts::diag::has_errors(&evaluated.diagnostics)).then_some(evaluated.scene);
        (scene, evaluated.diagnostics)
    }
}

/// Reads, parses and evaluates `path`. `Err` when the file cannot be read at all.
pub fn load(path: &Path, options: &EvalOptions) -> Result<Loaded, String> {
    let mut parsed = parse(path, options.max_source_size, options.defer_branches)?;
    let (scene, diags) = parsed.eval(options);
    let mut diagnostics = std::mem::take(&mut parsed.diagnostics);
    diagnostics.extend(diags);
    Ok(Loaded {
        scene,
        sources: parsed.sources,
        diagnostics,
    })
}

/// Prints diagnostics in the chosen format: human to stderr, short and JSON to stdout.
pub fn print(diags: &[Diagnostic], sources: &SourceMap, format: MessageFormat) {
    Messages::new(format, false).print(diags, sources, None);
}

/// Prints the diagnostics of the evaluations of one scene: human to stderr,
/// short and JSON to stdout. Each message is printed once however many
/// evaluations (the frames of a sequence) report it; a frame's messages are
/// headed with its number; `-q` leaves out the scene's `#debug` text (in
/// the human format).
pub struct Messages {
    format: MessageFormat,
    quiet: bool,
    seen: rustc_hash::FxHashSet<u64>,
}

impl Messages {
    /// A printer in `format`; `quiet` drops `#debug` text.
    pub fn new(format: MessageFormat, quiet: bool) -> Messages {
        Messages {
            format,
            quiet,
            seen: Default::default(),
        }
    }

    /// Prints the diagnostics not printed before; `frame`: the frame of a
    /// sequence they come from.
    pub fn print(&mut self, diags: &[Diagnostic], sources: &SourceMap, frame: Option<u32>) {
        use std::hash::{Hash, Hasher};
        let stdout = std::io::stdout();
        let mut out = stdout.lock();
        let stderr = std::io::stderr();
        let color = stderr.is_terminal() && std::env::var_os("NO_COLOR").is_none();
        let mut err = stderr.lock();
        // A frame's `#debug` texts run together until a line ends, as they
        // would print; its lines are then headed with the frame number.
        let mut debug_text = String::new();
        for d in diags {
            // -q silences `#debug` as it prints for people; tools that asked
            // for short or JSON lines still get it.
            if self.quiet && d.code == codes::USER_DEBUG && self.format == MessageFormat::Human {
                continue;
            }
            let mut h = rustc_hash::FxHasher::default();
            (d.code, d.span, &d.message).hash(&mut h);
            if !self.seen.insert(h.finish()) {
                continue;
            }
            let _ = match self.format {
                MessageFormat::Human if frame.is_some() && d.code == codes::USER_DEBUG => {
                    debug_text.push_str(&diag_render::human(d, sources, color));
                    Ok(())
                }
                MessageFormat::Human => {
                    if !debug_text.is_empty() {
                        let _ = write!(err, "{}", with_frame(&debug_text, true, frame));
                        debug_text.clear();
                    }
                    let text = diag_render::human(d, sources, color);
                    write!(
                        err,
                        "{}",
                        with_frame(&text, d.code == codes::USER_WARNING, frame)
                    )
                }
                MessageFormat::Short => writeln!(out, "{}", diag_render::short(d, sources)),
                MessageFormat::Json => {
                    let mut j = diag_render::json(d, sources);
                    if let Some(f) = frame {
                        j["frame"] = f.into();
                    }
                    writeln!(out, "{j}")
                }
            };
        }
        if !debug_text.is_empty() {
            let _ = write!(err, "{}", with_frame(&debug_text, true, frame));
        }
    }
}

/// A human report headed with the frame it comes from: each line of a scene's
/// own text (`lines`: `#debug`, `#warning`) starts with `frame N: `, other
/// reports get a heading line.
fn with_frame(text: &str, lines: bool, frame: Option<u32>) -> String {
    let Some(f) = frame else {
        return text.to_string();
    };
    if lines {
        let mut s: String = text
            .split_inclusive('\n')
            .map(|l| format!("frame {f}: {l}"))
            .collect();
        if !s.ends_with('\n') {
            s.push('\n');
        }
        s
    } else {
        format!("frame {f}:\n{text}")
    }
}
