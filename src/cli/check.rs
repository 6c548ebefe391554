//! `rts check FILE… [--message-format human|short|json]`.

use super::{common, SceneArgs, EXIT_ERRORS, EXIT_OK};
use std::path::PathBuf;

/// Arguments of `rts check`.
#[derive(Debug, clap::Args)]
pub struct CheckArgs {
    /// Scene files to check.
    #[arg(required = true, value_name = "SCENE")]
    pub scenes: Vec<PathBuf>,
    /// Options for reading scenes.
    #[command(flatten)]
    pub scene: SceneArgs,
}

/// Parses and evaluates each file; exit 0 when none has an error.
pub fn run(args: &CheckArgs) -> i32 {
    let options = match common::eval_options(&args.scene, 800, 600) {
        Ok(o) => o,
        Err(e) => {
            eprintln!("error: {e}");
            return super::EXIT_USAGE;
        }
    };
    let mut failed = false;
    for path in &args.scenes {
        match common::load(path, &options) {
            Ok(loaded) => {
                common::print(
                    &loaded.diagnostics,
                    &loaded.sources,
                    args.scene.message_format,
                );
                failed |= rts::diag::has_errors(&loaded.diagnostics);
            }
            Err(e) => {
                eprintln!("error: {e}");
                failed = true;
            }
        }
    }
    if failed {
        EXIT_ERRORS
    } else {
        EXIT_OK
    }
}
