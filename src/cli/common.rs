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
    /// All files read.
    pub sources: SourceMap,
    /// The scene, when evaluation found no error.
    pub scene: Option<Scene>,
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
        clock: args.clock,
        image_width: f64::from(width),
        image_height: f64::from(height),
        max_loop_iterations: args.max_loop_iterations,
        max_macro_depth: args.max_macro_depth,
        max_array_size: args.max_array_size,
        ..EvalOptions::default()
    })
}

/// Reads, parses and evaluates `path`. `Err` when the file cannot be read at all.
pub fn load(path: &Path, options: &EvalOptions) -> Result<Loaded, String> {
    let mut sources = SourceMap::new();
    let name = path.display().to_string();
    let id = match eval::load_file(&mut sources, path, name) {
        Ok(id) => id,
        Err(eval::LoadError::Io(e)) => return Err(format!("cannot read {}: {e}", path.display())),
        Err(eval::LoadError::Utf8(d)) => {
            return Ok(Loaded {
                sources,
                scene: None,
                diagnostics: vec![*d],
            })
        }
    };
    let text = sources.get(id).text.clone();
    let (file, mut diagnostics) = rts::syntax::parse(&text, id);
    if rts::diag::has_errors(&diagnostics) {
        return Ok(Loaded {
            sources,
            scene: None,
            diagnostics,
        });
    }
    let evaluated = eval::eval(&file, id, &mut sources, options);
    diagnostics.extend(evaluated.diagnostics);
    let scene = (!rts::diag::has_errors(&diagnostics)).then_some(evaluated.scene);
    Ok(Loaded {
        sources,
        scene,
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
