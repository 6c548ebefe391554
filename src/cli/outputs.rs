//! Every file a render writes, checked before anything is rendered (see
//! docs/cli.md, "Output files"): missing folders are created, and a target that
//! cannot be written (a folder, a block device, a path through a file) is an
//! error now rather than after a long render.

use super::render::RenderArgs;
use rts::files::{Policy, Target};
use std::path::Path;

/// Whether `path` is written as a stream: `-` (standard output), a FIFO or a
/// character device such as `/dev/null`.
pub fn is_stream(path: &Path) -> bool {
    matches!(
        rts::files::target(path, Policy::Stream),
        Ok(Target::Stdout | Target::Stream(_))
    )
}

/// Checks that `path` can be written as `policy` allows, creating its folder;
/// `what` names it in the error.
pub fn prepare(path: &Path, policy: Policy, what: &str) -> Result<(), String> {
    rts::files::prepare(path, policy)
        .map(|_| ())
        .map_err(|e| format!("cannot write {what} `{}`: {e}", path.display()))
}

/// Checks the image `output` and every other file the options name.
pub fn prepare_all(args: &RenderArgs, output: &Path) -> Result<(), String> {
    prepare(output, Policy::Stream, "the image")?;
    if let Some(p) = args.stats_json.as_deref().filter(|p| p.as_os_str() != "-") {
        prepare(p, Policy::Stream, "statistics")?;
    }
    for (p, what) in [(&args.gif, "the GIF"), (&args.apng, "the APNG")] {
        if let Some(p) = p {
            prepare(p, Policy::Stream, what)?;
        }
    }
    // ffmpeg seeks back in an MP4, and checkpoints are renamed into place.
    if let Some(p) = &args.mp4 {
        prepare(p, Policy::FileOnly, "the MP4")?;
    }
    if let Some(p) = &args.path.checkpoint {
        prepare(p, Policy::FileOnly, "the checkpoint")?;
    }
    Ok(())
}
