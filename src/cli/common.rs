//! The front half of the pipeline for the CLI: load, parse, evaluate, print diagnostics.

use super::{MessageFormat, SceneArgs};
use rts::diag::{render as diag_render, Diagnostic};
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
    /// The syntax tree, when the file parsed without errors.
    pub file: Option<rts::syntax::ast::File>,
    /// Syntax diagnostics.
    pub diagnostics: Vec<Diagnostic>,
    /// What one evaluation keeps for the next (includes, meshes).
    pub cache: eval::EvalCache,
}

/// Reads and parses `path`. `Err` when the file cannot be read at all.
pub fn parse(path: &Path) -> Result<Parsed, String> {
    let mut sources = SourceMap::new();
    let name = path.display().to_string();
    let id = match eval::load_file(&mut sources, path, name) {
        Ok(id) => id,
        Err(eval::LoadError::Io(e)) => return Err(format!("cannot read {}: {e}", path.display())),
        Err(eval::LoadError::Utf8(d)) => {
            let id = rts::span::FileId(0);
            return Ok(Parsed {
                sources,
                id,
                file: None,
                diagnostics: vec![*d],
                cache: eval::EvalCache::default(),
            });
        }
    };
    let text = sources.get(id).text.clone();
    let (file, diagnostics) = rts::syntax::parse(&text, id);
    let file = (!rts::diag::has_errors(&diagnostics)).then_some(file);
    Ok(Parsed {
        sources,
        id,
        file,
        diagnostics,
        cache: eval::EvalCache::default(),
    })
}

impl Parsed {
    /// Evaluates the scene with `options`: the scene when there was no error, and
    /// the evaluation's diagnostics.
    pub fn eval(&mut self, options: &EvalOptions) -> (Option<Scene>, Vec<Diagnostic>) {
        let Some(file) = &self.file else {
            return (None, Vec::new());
        };
        let evaluated =
            eval::eval_cached(file, self.id, &mut self.sources, options, &mut self.cache);
        let scene = (!rts::diag::has_errors(&evaluated.diagnostics)).then_some(evaluated.scene);
        (scene, evaluated.diagnostics)
    }
}

/// Reads, parses and evaluates `path`. `Err` when the file cannot be read at all.
pub fn load(path: &Path, options: &EvalOptions) -> Result<Loaded, String> {
    let mut parsed = parse(path)?;
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
    let stdout = std::io::stdout();
    let mut out = stdout.lock();
    let stderr = std::io::stderr();
    let color = stderr.is_terminal() && std::env::var_os("NO_COLOR").is_none();
    let mut err = stderr.lock();
    for d in diags {
        let _ = match format {
            MessageFormat::Human => write!(err, "{}", diag_render::human(d, sources, color)),
            MessageFormat::Short => writeln!(out, "{}", diag_render::short(d, sources)),
            MessageFormat::Json => writeln!(out, "{}", diag_render::json(d, sources)),
        };
    }
}
