//! The command line: `rts render`, `rts check`, `rts lsp`, `rts watch`, `rts merge`. One file per subcommand.

mod assemble;
mod check;
mod common;
mod frame;
mod interrupt;
mod lsp;
mod manifest;
mod merge;
mod outputs;
mod path_opts;
mod render;
mod sequence;
mod size;
mod stats;
mod still_shard;
mod unused;
mod watch;

use clap::{Parser, Subcommand, ValueEnum};
use std::path::PathBuf;

/// The stack of every thread that evaluates, builds or renders a scene: walks
/// over deeply nested objects and macros recurse (their depth is limited by
/// `--max-object-depth` and `--max-macro-depth`, sized to fit in this).
pub const STACK_SIZE: usize = 512 << 20;

/// A pool of `threads` render threads (`--threads`), each with [`STACK_SIZE`]
/// of stack, as the global pool's (see `main`).
pub fn thread_pool(threads: usize) -> Result<rayon::ThreadPool, rayon::ThreadPoolBuildError> {
    rayon::ThreadPoolBuilder::new()
        .stack_size(STACK_SIZE)
        .num_threads(threads.max(1))
        .build()
}

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
    #[arg(help_heading = "Files", short = 'D', value_name = "NAME=VALUE")]
    pub define: Vec<String>,
    /// Search DIR for #include files (after the including file's folder).
    #[arg(help_heading = "Files", short = 'I', value_name = "DIR")]
    pub include: Vec<PathBuf>,
    /// Also allow the scene to read files under DIR.
    #[arg(help_heading = "Files", long, value_name = "DIR")]
    pub allow_path: Vec<PathBuf>,
    /// Allow the scene to read any file.
    #[arg(help_heading = "Files", long)]
    pub allow_any_path: bool,
    /// How to print diagnostics.
    #[arg(help_heading = "Output", long, value_enum, default_value_t = MessageFormat::Human)]
    pub message_format: MessageFormat,
    /// Stop after this many loop iterations in total.
    #[arg(
        help_heading = "Limits",
        long,
        value_name = "N",
        default_value_t = 20_000_000
    )]
    pub max_loop_iterations: u64,
    /// Stop when macros nest deeper than this.
    #[arg(
        help_heading = "Limits",
        long,
        value_name = "N",
        default_value_t = 1_000
    )]
    pub max_macro_depth: usize,
    /// Refuse arrays with more elements than this.
    #[arg(help_heading = "Limits", long, value_name = "N", default_value_t = 1 << 22)]
    pub max_array_size: usize,
    /// Refuse objects nested deeper than this (CSG inside CSG, clipped_by;
    /// unions of unions are flattened and do not count).
    #[arg(
        help_heading = "Limits",
        long,
        value_name = "N",
        default_value_t = 10_000
    )]
    pub max_object_depth: u32,
    /// Stop when evaluating the scene has taken this much memory (e.g. 2G,
    /// 512M) [default: half the machine's memory, at most 8G].
    #[arg(help_heading = "Limits", long, value_name = "SIZE", value_parser = size::parse_size)]
    pub max_memory: Option<u64>,
    /// Stop after this many macro calls in all.
    #[arg(
        help_heading = "Limits",
        long,
        value_name = "N",
        default_value_t = 10_000_000
    )]
    pub max_macro_calls: u64,
    /// Refuse strings longer than this (e.g. 64M).
    #[arg(help_heading = "Limits", long, value_name = "SIZE", value_parser = size::parse_size, default_value = "64M")]
    pub max_string_length: u64,
    /// Stop evaluating after this many errors.
    #[arg(help_heading = "Limits", long, value_name = "N", default_value_t = 100)]
    pub max_errors: usize,
    /// Refuse a scene or #include file (or a file #fopen reads) larger than SIZE
    /// (`64M`, `1G`).
    #[arg(help_heading = "Limits", long, value_name = "SIZE", default_value = "256M", value_parser = size::parse_size)]
    pub max_source_size: u64,
    /// Stop when the files the scene writes with #write would hold more than SIZE
    /// in all.
    #[arg(help_heading = "Limits", long, value_name = "SIZE", default_value = "256M", value_parser = size::parse_size)]
    pub max_write: u64,
    /// Most pixels the image files a scene reads may hold together (each file
    /// once); checked before decoding.
    #[arg(help_heading = "Limits", long, value_name = "N", default_value_t = rts::eval::DEFAULT_MAX_IMAGE_PIXELS)]
    pub max_image_pixels: u64,
    /// The value of `clock` in the scene: a still at that time (without it,
    /// `clock` is 0, or a frame's time when rendering a sequence).
    #[arg(
        help_heading = "Animation",
        long,
        value_name = "T",
        allow_negative_numbers = true
    )]
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
    /// Stack the row bands of a still (`rts render --shard I/N`) into one image.
    Merge(merge::MergeArgs),
}

/// For an unknown short option whose other-case twin exists (`-w` for `-W`),
/// the message to print instead of clap's (which suggests `-- -w`).
pub fn case_twin_error(e: &clap::Error, argv: &[String]) -> Option<String> {
    use clap::error::{ContextKind, ContextValue, ErrorKind};
    use clap::CommandFactory;
    if e.kind() != ErrorKind::UnknownArgument {
        return None;
    }
    let Some(ContextValue::String(arg)) = e.get(ContextKind::InvalidArg) else {
        return None;
    };
    let mut chars = arg.strip_prefix('-')?.chars();
    let (Some(c), None) = (chars.next(), chars.next()) else {
        return None;
    };
    let twin = if c.is_ascii_lowercase() {
        c.to_ascii_uppercase()
    } else {
        c.to_ascii_lowercase()
    };
    let cli = Cli::command();
    let sub = argv.iter().skip(1).find_map(|a| cli.find_subcommand(a))?;
    let known = sub.get_arguments().find(|a| a.get_short() == Some(twin))?;
    let long = known
        .get_long()
        .map(|l| format!(" (--{l})"))
        .unwrap_or_default();
    let name = sub.get_name().to_string();
    let usage = sub
        .clone()
        .bin_name(format!("rts {name}"))
        .render_usage()
        .to_string();
    Some(format!(
        "error: unknown option '{arg}'\n\n  tip: options are case-sensitive: did you mean '-{twin}'{long}?\n\n{usage}\n\nFor more information, try 'rts {name} --help'."
    ))
}

/// Runs the command line and returns the exit status.
pub fn run(cli: Cli) -> i32 {
    match cli.command {
        Command::Render(args) => render::run(&args),
        Command::Check(args) => check::run(&args),
        Command::Lsp(args) => lsp::run(&args),
        Command::Watch(args) => watch::run(&args),
        Command::Merge(args) => merge::run(&args),
    }
}
