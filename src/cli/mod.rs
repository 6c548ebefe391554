//! The command line: `rts render`, `rts check`, `rts lsp`, `rts watch`. One file per subcommand.

mod assemble;
mod check;
mod common;
mod frame;
mod lsp;
mod manifest;
mod path_opts;
mod render;
mod sequence;
#[allow(dead_code)] // used by the budget flags landing next
mod size;
mod stats;
mod watch;

use clap::{Parser, Subcommand, ValueEnum};
use std::path::PathBuf;

/// Exit status: success.
pub const EXIT_OK: i32 = 0;
/// Exit status: the scene has errors, or the render failed.
pub const EXIT_ERRORS: i32 = 1;
/// Exit status: bad usage.
pub const EXIT_USAGE: i32 = 2;

/// `rts`: a POV-Ray-compatible scene language and ray tracer.
#[derive(Debug, Parser)]
#[command(name = "rts", version, about, long_about = None)]
pub struct Cli {
    /// What to do.
    #[command(subcommand)]
    pub command: Command,
}

/// How diagnostics are printed.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, ValueEnum)]
pub enum MessageFormat {
    /// Graphical reports with source excerpts (stderr).
    #[default]
    Human,
    /// One line per diagnostic: `FILE:LINE:COL: error[CODE]: MESSAGE`.
    Short,
    /// One JSON object per diagnostic per line (stdout).
    Json,
}

/// Options shared by every command that reads a scene.
#[derive(Debug, clap::Args, Clone)]
pub struct SceneArgs {
    /// Define NAME as VALUE before the scene is read (`-D Radius=2`, `-D Name="\"a\""`).
    #[arg(short = 'D', value_name = "NAME=VALUE")]
    pub define: Vec<String>,
    /// Search DIR for #include files (after the including file's folder).
    #[arg(short = 'I', value_name = "DIR")]
    pub include: Vec<PathBuf>,
    /// Also allow the scene to read files under DIR.
    #[arg(long, value_name = "DIR")]
    pub allow_path: Vec<PathBuf>,
    /// Allow the scene to read any file.
    #[arg(long)]
    pub allow_any_path: bool,
    /// How to print diagnostics.
    #[arg(long, value_enum, default_value_t = MessageFormat::Human)]
    pub message_format: MessageFormat,
    /// Stop after this many loop iterations in total.
    #[arg(long, value_name = "N", default_value_t = 20_000_000)]
    pub max_loop_iterations: u64,
    /// Stop when macros nest deeper than this.
    #[arg(long, value_name = "N", default_value_t = 1_000)]
    pub max_macro_depth: usize,
    /// Refuse arrays with more elements than this.
    #[arg(long, value_name = "N", default_value_t = 1 << 22)]
    pub max_array_size: usize,
    /// Most pixels the image files a scene reads may hold together (each file
    /// once); checked before decoding.
    #[arg(long, value_name = "N", default_value_t = rts::eval::DEFAULT_MAX_IMAGE_PIXELS)]
    pub max_image_pixels: u64,
    /// Evaluate (and render) the scene as a still at this `clock` value.
    #[arg(long, value_name = "T", allow_negative_numbers = true)]
    pub clock: Option<f64>,
}

/// The subcommands.
#[derive(Debug, Subcommand)]
pub enum Command {
    /// Render a scene to an image.
    Render(Box<render::RenderArgs>),
    /// Parse and evaluate scenes without rendering; report problems.
    Check(check::CheckArgs),
    /// Run the language server on stdin/stdout (for editors).
    Lsp(lsp::LspArgs),
    /// Re-render a scene whenever it or a file it includes changes.
    Watch(watch::WatchArgs),
}

/// Runs the command line and returns the exit status.
pub fn run(cli: Cli) -> i32 {
    match cli.command {
        Command::Render(args) => render::run(&args),
        Command::Check(args) => check::run(&args),
        Command::Lsp(args) => lsp::run(&args),
        Command::Watch(args) => watch::run(&args),
    }
}
