//! `rts merge [PARTS...] -o OUT`: stacks the row bands that `rts render --shard
//! I/N` wrote for a still into the file one run writes, byte for byte. Without
//! PARTS it takes every `OUT-stem.part-I-of-N.EXT.manifest.json` in OUT's
//! folder. Parts of another scene or other options, missing or overlapping
//! bands, and part files changed since their manifest are refused.

use super::still_shard::{self, PartManifest};
use super::{EXIT_ERRORS, EXIT_OK, EXIT_USAGE};
use rts::diag::codes;
use rts::output::{Format, StoredImage};
use std::path::{Path, PathBuf};

/// Arguments of `rts merge`.
#[derive(Debug, clap::Args)]
pub struct MergeArgs {
    /// Part files (`still.part-2-of-3.png`) or their manifests
    /// (`still.part-2-of-3.png.manifest.json`). Without any, every part of OUT
    /// in OUT's folder.
    #[arg(value_name = "PARTS")]
    pub parts: Vec<PathBuf>,
    /// The merged image: the name the shards were rendered with (`-o` of
    /// `rts render`); `-` writes it to standard output.
    #[arg(short = 'o', long = "output", value_name = "OUT")]
    pub output: PathBuf,
    /// Print nothing but errors.
    #[arg(short, long)]
    pub quiet: bool,
}

/// Prints `error[code]: msg` and gives the exit status of a failed merge.
fn fail(code: &str, msg: impl std::fmt::Display) -> i32 {
    eprintln!("error[{code}]: {msg}");
    EXIT_ERRORS
}

/// The manifests of the parts of `out` in its folder, by name.
fn discover(out: &Path) -> Vec<PathBuf> {
    let name = out
        .file_name()
        .map_or_else(String::new, |s| s.to_string_lossy().into_owned());
    let (stem, ext) = match name.rfind('.') {
        Some(k) if k > 0 => (&name[..k], &name[k..]),
        _ => (name.as_str(), ""),
    };
    let prefix = format!("{stem}.part-");
    let suffix = format!("{ext}.manifest.json");
    let dir = match out.parent() {
        Some(d) if !d.as_os_str().is_empty() => d.to_path_buf(),
        _ => PathBuf::from("."),
    };
    let Ok(rd) = std::fs::read_dir(&dir) else {
        return Vec::new();
    };
    let mut found: Vec<PathBuf> = rd
        .flatten()
        .filter(|e| {
            let f = e.file_name().to_string_lossy().into_owned();
            f.strip_prefix(&prefix)
                .and_then(|r| r.strip_suffix(&suffix))
                .and_then(|mid| mid.split_once("-of-"))
                .is_some_and(|(i, n)| i.parse::<u32>().is_ok() && n.parse::<u32>().is_ok())
        })
        .map(|e| out.with_file_name(e.file_name()))
        .collect();
    found.sort();
    found
}

/// The options lines that differ between two manifests, for a message.
fn differing_lines(a: &str, b: &str) -> String {
    let (la, lb): (Vec<&str>, Vec<&str>) = (a.lines().collect(), b.lines().collect());
    let mut out = Vec::new();
    for k in 0..la.len().max(lb.len()) {
        let (x, y) = (la.get(k).copied(), lb.get(k).copied());
        if x != y {
            out.push(format!(
                "    `{}`\n    vs `{}`",
                x.unwrap_or("(nothing)"),
                y.unwrap_or("(nothing)")
            ));
        }
    }
    out.join("\n")
}

/// Runs `rts merge`.
pub fn run(args: &MergeArgs) -> i32 {
    let out = &args.output;
    let out_format = Format::from_path(out);
    if out_format.is_none() && !super::outputs::is_stream(out) {
        eprintln!(
            "error: cannot write `{}`: use .png, .ppm, .exr or .hdr (the name the shards were rendered with)",
            out.display()
        );
        return EXIT_USAGE;
    }
    let manifests: Vec<PathBuf> = if args.parts.is_empty() {
        discover(out)
    } else {
        args.parts
            .iter()
            .map(|p| {
                if p.to_string_lossy().ends_with(".manifest.json") {
                    p.clone()
                } else {
                    still_shard::manifest_path(p)
                }
            })
            .collect()
    };
    if manifests.is_empty() {
        let part = still_shard::part_path(out, 1, 2);
        return fail(
            codes::MERGE_MISSING_BAND,
            format!(
                "no parts of `{}` found (files such as `{}` with its `.manifest.json`): render them with `rts render SCENE -o {} --shard I/N`, or name the parts",
                out.display(),
                part.display(),
                out.display()
            ),
        );
    }
    let mut parts: Vec<(PathBuf, PartManifest)> = Vec::new();
    for m in &manifests {
        match PartManifest::load(m) {
            Ok(pm) => {
                let part = m.with_file_name(&pm.file);
                parts.push((part, pm));
            }
            Err(e) => {
                return fail(
                    codes::MERGE_BAD_PART,
                    format!("{e}: render that shard again, or leave it out"),
                )
            }
        }
    }
    // One scene, one set of options.
    let (p0, m0) = (&parts[0].0, parts[0].1.clone());
    for (p, m) in &parts[1..] {
        if m.scene_hash != m0.scene_hash {
            return fail(
                codes::MERGE_DIFFERENT_SCENE,
                format!(
                    "`{}` and `{}` were rendered from different scenes (scene hash {} and {}: the scene file, an include or a data file changed between them): render every shard again from the same files",
                    p0.display(),
                    p.display(),
                    m0.scene_hash,
                    m.scene_hash
                ),
            );
        }
        if m.key != m0.key {
            return fail(
                codes::MERGE_DIFFERENT_OPTIONS,
                format!(
                    "`{}` and `{}` were rendered with different options:\n{}\nrender every shard with the same options",
                    p0.display(),
                    p.display(),
                    differing_lines(&m0.options, &m.options)
                ),
            );
        }
    }
    let format = match m0.format.parse::<Format>() {
        Ok(f) => f,
        Err(_) => {
            return fail(
                codes::MERGE_BAD_PART,
                format!("`{}` names an unknown format `{}`", p0.display(), m0.format),
            )
        }
    };
    if let Some(f) = out_format {
        if f != format {
            eprintln!(
                "error: the parts are {} files and `{}` names {}: give -o the name the shards were rendered with (`{}`)",
                format.extension().to_uppercase(),
                out.display(),
                f.extension().to_uppercase(),
                m0.output
            );
            return EXIT_USAGE;
        }
    }
    // Bands in order, every row once.
    parts.sort_by_key(|(_, m)| (m.rows[0], m.rows[1]));
    let same_n = parts.iter().all(|(_, m)| m.shard[1] == m0.shard[1]);
    let missing = |from: u32, to: u32| -> String {
        let n = m0.shard[1];
        let shards: Vec<String> = (1..=n)
            .filter(|&i| still_shard::band(m0.height, i, n).is_ok_and(|(a, b)| a < to && b > from))
            .map(|i| format!("{i}/{n}"))
            .collect();
        if same_n && !shards.is_empty() {
            format!(
                "rows {from}..{to} of `{}` are in no part: render --shard {} (and merge again)",
                m0.output,
                shards.join(", --shard ")
            )
        } else {
            format!(
                "rows {from}..{to} of `{}` are in no part: render the shard that holds them",
                m0.output
            )
        }
    };
    let mut row = 0u32;
    for (k, (p, m)) in parts.iter().enumerate() {
        let [y0, y1] = m.rows;
        if y0 > row {
            return fail(codes::MERGE_MISSING_BAND, missing(row, y0));
        }
        if y0 < row || y1 <= y0 {
            let other = &parts[k.saturating_sub(1)].0;
            return fail(
                codes::MERGE_OVERLAPPING_BANDS,
                format!(
                    "`{}` (rows {y0}..{y1}) overlaps `{}`: parts of different splits (--shard I/N with another N) or the same shard twice; name the parts to merge, or remove the stale ones",
                    p.display(),
                    other.display()
                ),
            );
        }
        row = y1;
    }
    if row < m0.height {
        return fail(codes::MERGE_MISSING_BAND, missing(row, m0.height));
    }
    let mut images = Vec::with_capacity(parts.len());
    for (p, m) in &parts {
        let again = format!("render --shard {}/{} again", m.shard[0], m.shard[1]);
        if !m.matches_file(p) {
            return fail(
                codes::MERGE_BAD_PART,
                format!(
                    "`{}` is not the file its manifest recorded (missing, or changed since): {again}",
                    p.display()
                ),
            );
        }
        let img = match StoredImage::read(p, format, u64::from(m.width) * u64::from(m.height)) {
            Ok(i) => i,
            Err(e) => return fail(codes::MERGE_BAD_PART, format!("{e}: {again}")),
        };
        let depth_ok = match img.bit_depth() {
            Some(rts::output::BitDepth::Eight) => m.bit_depth == 8 || format.is_float(),
            Some(rts::output::BitDepth::Sixteen) => m.bit_depth == 16,
            None => format.is_float(),
        };
        if img.width != m.width || img.height != m.rows[1] - m.rows[0] || !depth_ok {
            return fail(
                codes::MERGE_BAD_PART,
                format!(
                    "`{}` is {}x{}, not the {}x{} band its manifest says: {again}",
                    p.display(),
                    img.width,
                    img.height,
                    m.width,
                    m.rows[1] - m.rows[0]
                ),
            );
        }
        images.push(img);
    }
    let merged = match StoredImage::stack(images) {
        Ok(m) => m,
        Err(e) => return fail(codes::MERGE_BAD_PART, e),
    };
    if let Err(e) = merged.write(out, format) {
        eprintln!("error: {e}");
        return EXIT_ERRORS;
    }
    if !args.quiet {
        eprintln!(
            "merged {} parts ({}x{}) → {}",
            parts.len(),
            merged.width,
            merged.height,
            out.display()
        );
    }
    EXIT_OK
}
