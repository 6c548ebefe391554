//! Options that do nothing in the mode a render runs in: the classic renderer
//! or the path tracer, a still or a sequence. Each one given is a warning that
//! says why and what would use it, so no option is silently ignored.

use super::render::{PassName, RenderArgs};

/// How the render runs, as decided from the options and the scene.
#[derive(Clone, Copy, Debug)]
pub struct Mode {
    /// The path tracer renders (else the classic renderer).
    pub path_traced: bool,
    /// A sequence of frames is rendered (else one picture).
    pub sequence: bool,
}

/// One warning per option given that has no effect in `mode`.
pub fn warnings(args: &RenderArgs, mode: Mode) -> Vec<String> {
    let mut out = Vec::new();
    let given = |name: &str, yes: bool, out: &mut Vec<String>, why: &str| {
        if yes {
            out.push(format!("{name} has no effect: {why}"));
        }
    };
    let p = &args.path;
    if mode.path_traced {
        // (--antialias and --pass are errors there: see `path_opts`.)
        let why = "the path tracer renders this scene; it takes --spp (or --time-limit) instead";
        given("--samples", args.samples.is_some(), &mut out, why);
        for (name, yes) in [
            ("--aa-depth", args.aa_depth.is_some()),
            ("--jitter", args.jitter.is_some()),
            ("--aa-gamma", args.aa_gamma.is_some()),
        ] {
            given(name, yes, &mut out, why);
        }
    } else {
        let why = "it is a path tracer option, and the classic renderer renders this scene (add --integrator path to path trace it)";
        for (name, yes) in [
            ("--spp", p.spp.is_some()),
            ("--time-limit", p.time_limit.is_some()),
            ("--max-depth", p.max_depth.is_some()),
            ("--clamp", p.clamp.is_some()),
            ("--pixel-filter", p.pixel_filter.is_some()),
            ("--resume", p.resume),
            ("--checkpoint", p.checkpoint.is_some()),
            ("--save-every", p.save_every.is_some()),
            ("--aov", !p.aov.is_empty()),
            ("--denoise", p.denoise),
        ] {
            given(name, yes, &mut out, why);
        }
        if args.antialias.is_none() {
            let why = "it tunes --antialias, which is not given";
            given("--aa-depth", args.aa_depth.is_some(), &mut out, why);
            given("--jitter", args.jitter.is_some(), &mut out, why);
            given("--aa-gamma", args.aa_gamma.is_some(), &mut out, why);
        }
    }
    given(
        "--depth-max",
        args.depth_max.is_some() && args.pass != PassName::Depth,
        &mut out,
        "it is the distance drawn black by --pass depth",
    );
    if !mode.sequence {
        let why = "it applies to the frames of a sequence, and this renders one picture";
        // (A still's --shard skips a complete part unless --force.)
        given("--force", args.force && args.shard.is_none(), &mut out, why);
    }
    out
}
