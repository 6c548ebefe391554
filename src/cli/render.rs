//! `rts render SCENE [-o OUT] [-W W] [-H H]`.

use super::{common, SceneArgs, EXIT_ERRORS};
use std::path::PathBuf;

/// Arguments of `rts render`.
#[derive(Debug, clap::Args)]
pub struct RenderArgs {
    /// The scene file.
    #[arg(value_name = "SCENE")]
    pub scene_file: PathBuf,
    /// Output image (format from the extension).
    #[arg(short = 'o', long = "output", value_name = "OUT")]
    pub output: Option<PathBuf>,
    /// Image width in pixels.
    #[arg(short = 'W', long = "width", default_value_t = 800)]
    pub width: u32,
    /// Image height in pixels.
    #[arg(short = 'H', long = "height", default_value_t = 600)]
    pub height: u32,
    /// Options for reading the scene.
    #[command(flatten)]
    pub scene: SceneArgs,
}

/// Renders the scene.
pub fn run(args: &RenderArgs) -> i32 {
    let options = match common::eval_options(&args.scene, args.width, args.height) {
        Ok(o) => o,
        Err(e) => {
            eprintln!("error: {e}");
            return super::EXIT_USAGE;
        }
    };
    match common::load(&args.scene_file, &options) {
        Ok(loaded) => {
            common::print(&loaded.diagnostics, &loaded.sources, args.scene.message_format);
            if loaded.scene.is_none() {
                return EXIT_ERRORS;
            }
            eprintln!("error: rendering is not wired up in this build");
            EXIT_ERRORS
        }
        Err(e) => {
            eprintln!("error: {e}");
            EXIT_ERRORS
        }
    }
}
