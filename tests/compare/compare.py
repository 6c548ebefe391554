#!/usr/bin/env python3
"""Render the same scene text with rts and POV-Ray 3.7 and compare the pictures and the speed.

For every scene in tests/compare/scenes/*.pov (plain POV-Ray 3.7 SDL that rts reads unchanged):

  * render it with POV-Ray (`povray +I... +W +H -D +A<aa> -J +WT<threads>`) and with rts
    (`rts render ... --antialias <aa> --jitter 0 --threads <threads>`);
  * compare the two 8-bit pictures: SSIM (Wang et al. 2004, 11x11 Gaussian window with
    sigma 1.5, K1 = 0.01, K2 = 0.03, on luma Y = 0.299 R + 0.587 G + 0.114 B; implemented
    here in numpy, no scikit-image needed; it matches skimage's structural_similarity with
    gaussian_weights=True, sigma=1.5, use_sample_covariance=False, data_range=255 to 1e-14)
    and the mean absolute error in 8-bit levels over the R, G, B channels;
  * time each renderer's render phase: POV-Ray's own "Photon + Radiosity + Trace Time"
    from the statistics it prints; rts's "seconds.render" from `--stats-json` when the
    binary has that option, else the "trace N s" of its summary line, else wall time.

Without POV-Ray (or with --reference) rts is compared against the committed 160x120
POV-Ray pictures in tests/compare/reference/ instead (no POV-Ray timing then).

Output: a table on stdout, and report.json + report.md + the pictures (pov/, rts/, diff/,
side/ = POV-Ray | rts | diff side by side)
in the output folder (default target/compare). Exit status 0 when every scene reaches
--min-ssim, 1 otherwise, 2 for bad usage or a missing tool.

Usage:
  python3 tests/compare/compare.py                          # 640x480, AA 0.3, 2 threads
  python3 tests/compare/compare.py --scenes 'camera_*,csg'  # a subset (fnmatch patterns)
  python3 tests/compare/compare.py --reference              # no POV-Ray needed
  python3 tests/compare/compare.py --bless                  # rewrite reference/ with POV-Ray
  python3 tests/compare/compare.py --pov-only               # time POV-Ray alone

It needs numpy and Pillow: when they cannot be imported it makes a venv in
target/compare-venv, installs them there (`pip install numpy pillow`) and runs itself again.
"""

from __future__ import annotations

import argparse
import fnmatch
import json
import os
import re
import shutil
import subprocess
import sys
import time
from dataclasses import asdict, dataclass, field
from pathlib import Path

HERE = Path(__file__).resolve().parent
REPO = HERE.parent.parent
SCENES = HERE / "scenes"
ASSETS = HERE / "assets"
REFERENCE = HERE / "reference"
# The settings of the committed reference pictures (see reference/README.md).
REF_SIZE = (160, 120)
REF_AA = 0.3


def ensure_dependencies() -> None:
    """Import numpy and Pillow, or make a venv with them and run this script again in it."""
    try:
        import numpy  # noqa: F401
        import PIL  # noqa: F401

        return
    except ImportError:
        pass
    if os.environ.get("RTS_COMPARE_IN_VENV") == "1":
        sys.exit("error: numpy and Pillow are still missing in the venv; install them: pip install numpy pillow")
    venv = REPO / "target" / "compare-venv"
    python = venv / "bin" / "python"
    if not python.exists():
        print(f"numpy/Pillow not found: making a venv in {venv} (pip install numpy pillow)", file=sys.stderr)
        made = subprocess.run([sys.executable, "-m", "venv", str(venv)], check=False)
        if made.returncode != 0:
            sys.exit(
                "error: cannot make a venv (on Debian: apt-get install -y python3-venv), "
                "or install the modules yourself: pip install numpy pillow"
            )
    installed = subprocess.run([str(python), "-m", "pip", "install", "-q", "numpy", "pillow"], check=False)
    if installed.returncode != 0:
        sys.exit("error: `pip install numpy pillow` failed in the venv")
    env = dict(os.environ, RTS_COMPARE_IN_VENV="1")
    os.execve(str(python), [str(python), str(Path(__file__).resolve()), *sys.argv[1:]], env)


ensure_dependencies()

import numpy as np  # noqa: E402
from PIL import Image  # noqa: E402

# ---------------------------------------------------------------------------------------------
# Picture metrics


def luma(rgb: np.ndarray) -> np.ndarray:
    """Rec. 601 luma of an 8-bit RGB array, as float64 in 0..255."""
    rgb = rgb.astype(np.float64)
    return 0.299 * rgb[..., 0] + 0.587 * rgb[..., 1] + 0.114 * rgb[..., 2]


def _gaussian_filter_valid(img: np.ndarray, size: int = 11, sigma: float = 1.5) -> np.ndarray:
    """Separable Gaussian filter, 'valid' region only (as Wang et al.'s reference code)."""
    x = np.arange(size) - (size - 1) / 2
    g = np.exp(-(x**2) / (2 * sigma**2))
    g /= g.sum()
    rows = np.lib.stride_tricks.sliding_window_view(img, size, axis=1) @ g
    return np.lib.stride_tricks.sliding_window_view(rows, size, axis=0) @ g


def ssim(a: np.ndarray, b: np.ndarray) -> float:
    """Mean SSIM of two greyscale float images in 0..255 (Wang, Bovik, Sheikh, Simoncelli 2004)."""
    if min(a.shape) < 11:
        raise ValueError("SSIM needs pictures of at least 11x11 pixels")
    c1 = (0.01 * 255) ** 2
    c2 = (0.03 * 255) ** 2
    mu_a = _gaussian_filter_valid(a)
    mu_b = _gaussian_filter_valid(b)
    var_a = _gaussian_filter_valid(a * a) - mu_a**2
    var_b = _gaussian_filter_valid(b * b) - mu_b**2
    cov = _gaussian_filter_valid(a * b) - mu_a * mu_b
    num = (2 * mu_a * mu_b + c1) * (2 * cov + c2)
    den = (mu_a**2 + mu_b**2 + c1) * (var_a + var_b + c2)
    return float(np.mean(num / den))


def load_rgb(path: Path) -> np.ndarray:
    """An image file as an 8-bit RGB array (16-bit PNGs are reduced to 8 bits)."""
    img = Image.open(path)
    if img.mode in ("I;16", "I;16B", "I"):
        arr = np.asarray(img, dtype=np.float64) / 257.0
        return np.repeat(np.round(arr).astype(np.uint8)[..., None], 3, axis=2)
    return np.asarray(img.convert("RGB"))


def compare_pictures(pov: Path, rts: Path, diff: Path) -> dict:
    """SSIM, mean and max absolute error between two pictures; writes an amplified diff picture."""
    a = load_rgb(pov)
    b = load_rgb(rts)
    if a.shape != b.shape:
        raise ValueError(f"sizes differ: POV-Ray {a.shape[1]}x{a.shape[0]}, rts {b.shape[1]}x{b.shape[0]}")
    d = np.abs(a.astype(np.int16) - b.astype(np.int16))
    diff.parent.mkdir(parents=True, exist_ok=True)
    amplified = np.clip(d * 4, 0, 255).astype(np.uint8)
    Image.fromarray(amplified, "RGB").save(diff)
    side = diff.parent.parent / "side" / diff.name  # POV-Ray | rts | diff, to look at
    side.parent.mkdir(parents=True, exist_ok=True)
    Image.fromarray(np.concatenate([a, b, amplified], axis=1), "RGB").save(side)
    return {
        "ssim": ssim(luma(a), luma(b)),
        "mae": float(d.mean()),
        "max": int(d.max()),
        "over_8_levels": float((d.max(axis=2) > 8).mean()),
    }


# ---------------------------------------------------------------------------------------------
# Renderers


@dataclass
class Run:
    """The outcome of one renderer on one scene."""

    ok: bool
    wall: float
    render: float | None = None  # the render phase, seconds
    render_source: str = ""  # where `render` comes from
    parse: float | None = None
    error: str = ""
    camera_rays: int | None = None  # primary rays, anti-aliasing samples included


def _first_error_line(text: str) -> str:
    lines = [ln.strip() for ln in text.splitlines() if ln.strip()]
    for ln in lines:
        if "error" in ln.lower():
            return ln.replace(str(SCENES) + os.sep, "")[:300]
    return (lines[0] if lines else "no output")[:300]


POV_PIXELS = re.compile(r"Pixels:\s+(\d+)\s+Samples:\s+(\d+)")
POV_TIME = re.compile(r"(Parse|Bounding|Photon|Radiosity|Trace) Time:.*?\(\s*([\d.]+) seconds\)")


def parse_povray_times(stderr: str) -> dict[str, float]:
    """POV-Ray's statistics: {'Parse': s, 'Bounding': s, 'Photon': s, 'Radiosity': s, 'Trace': s}."""
    times: dict[str, float] = {}
    for m in POV_TIME.finditer(stderr):
        times[m.group(1)] = times.get(m.group(1), 0.0) + float(m.group(2))
    return times


def run_povray(
    povray: str, scene: Path, out: Path, size, aa: float, threads: int, timeout: float, extra: list[str] = ()
) -> Run:
    """Renders with POV-Ray in the scene's folder.

    POV-Ray's default I/O security (povray.conf) lets it write only to the current folder and
    /tmp, so it writes a hidden file next to the scene, which is then moved to `out`.
    """
    w, h = size
    local = scene.parent / f".rts-compare-{os.getpid()}-{scene.stem}.png"
    cmd = [povray, f"+I{scene.name}", f"+O{local.name}", f"+W{w}", f"+H{h}", "-D", "-V", "+FN8", f"+WT{threads}", "-GP"]
    cmd += [f"+A{aa}", "-J"] if aa > 0 else ["-A"]
    cmd += list(extra)
    out.parent.mkdir(parents=True, exist_ok=True)
    t0 = time.perf_counter()
    try:
        p = subprocess.run(cmd, check=False, cwd=scene.parent, capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        local.unlink(missing_ok=True)
        return Run(False, timeout, error=f"timed out after {timeout:.0f} s")
    wall = time.perf_counter() - t0
    if p.returncode != 0 or not local.exists():
        local.unlink(missing_ok=True)
        return Run(False, wall, error=_first_error_line(p.stderr + p.stdout))
    shutil.move(local, out)
    t = parse_povray_times(p.stderr + p.stdout)
    px = POV_PIXELS.search(p.stderr + p.stdout)
    rays = int(px.group(1)) + int(px.group(2)) if px else None
    if "Trace" in t:
        render = t.get("Photon", 0.0) + t.get("Radiosity", 0.0) + t["Trace"]
        return Run(True, wall, render, "povray stats (photon+radiosity+trace)", t.get("Parse"), camera_rays=rays)
    return Run(True, wall, wall, "wall clock", camera_rays=rays)


RTS_TRACE = re.compile(r"trace\s+([\d.]+)\s*s")
RTS_PARSE = re.compile(r"parse\+eval\s+([\d.]+)\s*s")


def rts_options(rts: str) -> str:
    """The text of `rts render --help`, to see which options this build has."""
    p = subprocess.run([rts, "render", "--help"], check=False, capture_output=True, text=True)
    return p.stdout + p.stderr


def run_rts(
    rts: str,
    help_text: str,
    scene: Path,
    out: Path,
    size,
    aa: float,
    threads: int,
    timeout: float,
    extra: list[str] = (),
) -> Run:
    w, h = size
    cmd = [rts, "render", str(scene), "-o", str(out), "-W", str(w), "-H", str(h), "--threads", str(threads)]
    cmd += ["--allow-path", str(ASSETS), "--message-format", "short"]
    notes = []
    if aa > 0:
        if "--antialias" in help_text:
            cmd += ["--antialias", str(aa)]
            if "--jitter" in help_text:
                cmd += ["--jitter", "0"]
        else:
            notes.append("this rts has no --antialias: rendered without")
    stats_path = None
    if "--stats-json" in help_text:
        stats_path = out.with_suffix(".stats.json")
        stats_path.unlink(missing_ok=True)
        cmd += ["--stats-json", str(stats_path)]
    cmd += list(extra)
    out.parent.mkdir(parents=True, exist_ok=True)
    out.unlink(missing_ok=True)
    t0 = time.perf_counter()
    try:
        p = subprocess.run(cmd, check=False, capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return Run(False, timeout, error=f"timed out after {timeout:.0f} s")
    wall = time.perf_counter() - t0
    text = p.stderr + p.stdout
    if p.returncode != 0 or not out.exists():
        return Run(False, wall, error=_first_error_line(text))
    run = Run(True, wall, wall, "wall clock", error="; ".join(notes))
    if stats_path and stats_path.exists():
        try:
            stats = json.loads(stats_path.read_text())
            secs = stats.get("seconds", {})
            if isinstance(stats.get("camera_samples"), int):
                run.camera_rays = stats["camera_samples"]
            if "render" in secs:
                run.render, run.render_source = float(secs["render"]), "rts --stats-json"
                run.parse = secs.get("parse_eval")
                return run
        except (ValueError, AttributeError):
            pass
    m = RTS_TRACE.search(text)
    if m:
        run.render, run.render_source = float(m.group(1)), "rts summary line (trace)"
        mp = RTS_PARSE.search(text)
        run.parse = float(mp.group(1)) if mp else None
    return run


# ---------------------------------------------------------------------------------------------
# The comparison


@dataclass
class Row:
    """One scene's line of the report."""

    scene: str
    status: str = ""
    detail: str = ""
    ssim: float | None = None
    mae: float | None = None
    max_diff: int | None = None
    pov_render_s: float | None = None
    pov_wall_s: float | None = None
    rts_render_s: float | None = None
    rts_wall_s: float | None = None
    ratio: float | None = None  # rts render / POV-Ray render; below 1 means rts is faster
    rts_time_source: str = ""
    pov_time_source: str = ""
    pov_camera_rays: int | None = None  # POV-Ray's "Pixels" + "Samples"
    rts_camera_rays: int | None = None  # rts's `camera_samples` (--stats-json)
    pictures: dict = field(default_factory=dict)


def parse_size(text: str) -> tuple[int, int]:
    m = re.fullmatch(r"(\d+)[xX](\d+)", text.strip())
    if not m or int(m.group(1)) < 11 or int(m.group(2)) < 11:
        raise argparse.ArgumentTypeError(f"--size {text}: expected WxH, each at least 11 (e.g. 640x480)")
    return int(m.group(1)), int(m.group(2))


def select_scenes(patterns: str | None) -> list[Path]:
    all_scenes = sorted(SCENES.glob("*.pov"))
    if not patterns:
        return all_scenes
    pats = [p.strip().removesuffix(".pov") for p in patterns.split(",") if p.strip()]
    return [s for s in all_scenes if any(fnmatch.fnmatch(s.stem, p) or p in s.stem for p in pats)]


def fmt(x, spec: str) -> str:
    return "-" if x is None else format(x, spec)


def table(rows: list[Row], min_ssim: float) -> list[str]:
    head = f"{'scene':<20} {'status':<10} {'SSIM':>6} {'MAE':>6} {'max':>4} {'POV s':>7} {'rts s':>7} {'rts/POV':>7}  detail"
    lines = [head, "-" * len(head)]
    for r in rows:
        lines.append(
            f"{r.scene:<20} {r.status:<10} {fmt(r.ssim, '.3f'):>6} {fmt(r.mae, '.2f'):>6} {fmt(r.max_diff, 'd'):>4} "
            f"{fmt(r.pov_render_s, '.3f'):>7} {fmt(r.rts_render_s, '.3f'):>7} {fmt(r.ratio, '.2f'):>7}  {r.detail}"
        )
    ok = sum(r.status == "ok" for r in rows)
    compared = [r for r in rows if r.status != "pov only"]
    if compared:
        lines.append(f"{ok}/{len(compared)} scenes reach SSIM >= {min_ssim}")
    timed = [r for r in rows if r.pov_render_s is not None]
    if timed:
        total = sum(r.pov_render_s for r in timed)
        lines.append(f"POV-Ray render time, {len(timed)} scenes: {total:.2f} s")
    both = [r for r in rows if r.ratio is not None]
    if both:
        ratio = sum(r.rts_render_s for r in both) / sum(r.pov_render_s for r in both)
        lines.append(f"rts / POV-Ray render time over the {len(both)} scenes both rendered: {ratio:.2f}")
    return lines


def markdown(rows: list[Row], settings: dict) -> str:
    out = [
        "# rts vs POV-Ray 3.7",
        "",
        f"Settings: {json.dumps(settings)}",
        "",
        (
            "Render times are the render phase only (POV-Ray: photon + radiosity + trace time from its own "
            "statistics; rts: `seconds.render` of `--stats-json`, else the trace time of its summary line, "
            "else wall time). Ratio = rts / POV-Ray (below 1: rts is faster)."
        ),
        "",
        "| scene | status | SSIM | MAE (levels) | max | POV-Ray render s | rts render s | rts/POV "
        "| POV-Ray camera rays | rts camera rays | detail |",
        "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---|",
    ]
    for r in rows:
        detail = r.detail.replace("|", "\\|")
        out.append(
            f"| {r.scene} | {r.status} | {fmt(r.ssim, '.3f')} | {fmt(r.mae, '.2f')} | {fmt(r.max_diff, 'd')} | "
            f"{fmt(r.pov_render_s, '.3f')} | {fmt(r.rts_render_s, '.3f')} | {fmt(r.ratio, '.2f')} | "
            f"{fmt(r.pov_camera_rays, 'd')} | {fmt(r.rts_camera_rays, 'd')} | {detail} |"
        )
    return "\n".join(out) + "\n"


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--size", type=parse_size, default=(640, 480), help="WxH (default 640x480)")
    ap.add_argument("--aa", type=float, default=0.3, help="anti-aliasing threshold, 0 = off (POV +A, rts --antialias)")
    ap.add_argument("--threads", type=int, default=2, help="threads for both renderers (POV +WT)")
    ap.add_argument("--scenes", help="comma-separated fnmatch patterns of scene names (default: all)")
    ap.add_argument("--rts", default=str(REPO / "target" / "release" / "rts"), help="the rts binary")
    ap.add_argument("--povray", default="povray", help="the POV-Ray 3.7 binary")
    ap.add_argument("--out", type=Path, default=REPO / "target" / "compare", help="output folder")
    ap.add_argument("--min-ssim", type=float, default=0.95, help="SSIM a scene must reach (default 0.95)")
    ap.add_argument("--timeout", type=float, default=600, help="seconds per render before giving up")
    ap.add_argument("--reference", action="store_true", help="compare with reference/*.png, no POV-Ray needed")
    ap.add_argument(
        "--rts-arg",
        action="append",
        default=[],
        metavar="ARG",
        help="extra argument for `rts render` (repeat; e.g. --rts-arg=--aa-depth --rts-arg=4)",
    )
    ap.add_argument(
        "--pov-arg",
        action="append",
        default=[],
        metavar="ARG",
        help="extra POV-Ray option (repeat; e.g. --pov-arg=+R4)",
    )
    ap.add_argument("--pov-only", action="store_true", help="render and time POV-Ray alone (no rts, no comparison)")
    ap.add_argument("--bless", action="store_true", help="render reference/*.png (160x120, AA 0.3) with POV-Ray")
    args = ap.parse_args(argv)

    scenes = select_scenes(args.scenes)
    if not scenes:
        print(f"error: no scene in {SCENES} matches {args.scenes!r}", file=sys.stderr)
        return 2
    povray = shutil.which(args.povray)
    if args.bless:
        if not povray:
            print("error: POV-Ray 3.7 is needed for --bless: apt-get install -y povray", file=sys.stderr)
            return 2
        REFERENCE.mkdir(exist_ok=True)
        for s in scenes:
            r = run_povray(povray, s, REFERENCE / f"{s.stem}.png", REF_SIZE, REF_AA, 1, args.timeout)
            print(f"{s.stem:<20} {'written' if r.ok else 'POV-Ray error: ' + r.error}")
        return 0
    use_reference = args.reference
    if not use_reference and not povray:
        print(
            f"POV-Ray 3.7 (`{args.povray}`) is not installed: install it with `apt-get install -y povray`.\n"
            f"Comparing with the committed {REF_SIZE[0]}x{REF_SIZE[1]} reference pictures instead (no POV-Ray timing).",
            file=sys.stderr,
        )
        use_reference = True
    size, aa = (REF_SIZE, REF_AA) if use_reference else (args.size, args.aa)
    if use_reference and (args.size != (640, 480) or args.aa != 0.3):
        print(f"note: --reference renders at {size[0]}x{size[1]}, AA {aa} (the reference settings)", file=sys.stderr)

    rts = args.rts if os.sep in args.rts else (shutil.which(args.rts) or args.rts)
    if args.pov_only:
        if use_reference:
            print("error: --pov-only needs POV-Ray: apt-get install -y povray", file=sys.stderr)
            return 2
        help_text = "--antialias"
    elif not Path(rts).exists():
        print(f"error: no rts binary at {rts}: build it with `cargo build --release`", file=sys.stderr)
        return 2
    else:
        help_text = rts_options(rts)
    if aa > 0 and "--antialias" not in help_text and not use_reference:
        print("note: this rts has no --antialias: both renderers run without anti-aliasing", file=sys.stderr)
        aa = 0.0

    out = args.out.resolve()
    settings = {
        "size": f"{size[0]}x{size[1]}",
        "aa": aa,
        "jitter": "off",
        "threads": args.threads,
        "against": "reference pictures" if use_reference else ("nothing (--pov-only)" if args.pov_only else "povray"),
        "rts": str(rts),
        "min_ssim": args.min_ssim,
        "rts_args": args.rts_arg,
        "pov_args": args.pov_arg,
    }
    print(f"comparing {len(scenes)} scenes: {json.dumps(settings)}\n", file=sys.stderr)
    rows: list[Row] = []
    for s in scenes:
        row = Row(s.stem)
        rows.append(row)
        pov_png = REFERENCE / f"{s.stem}.png" if use_reference else out / "pov" / f"{s.stem}.png"
        rts_png = out / "rts" / f"{s.stem}.png"
        diff_png = out / "diff" / f"{s.stem}.png"
        if use_reference:
            if not pov_png.exists():
                row.status, row.detail = "no ref", f"{pov_png.name} missing (run --bless)"
                print(table([row], args.min_ssim)[2], flush=True)
                continue
        else:
            pr = run_povray(povray, s, pov_png, size, aa, args.threads, args.timeout, args.pov_arg)
            row.pov_wall_s, row.pov_render_s, row.pov_time_source = pr.wall, pr.render, pr.render_source
            row.pov_camera_rays = pr.camera_rays
            if not pr.ok:
                row.status, row.detail = "pov error", pr.error
                print(table([row], args.min_ssim)[2], flush=True)
                continue
            if args.pov_only:
                row.status, row.detail = "pov only", f"wall {pr.wall:.2f} s, parse {fmt(pr.parse, '.3f')} s"
                print(table([row], args.min_ssim)[2], flush=True)
                continue
        rr = run_rts(rts, help_text, s, rts_png, size, aa, args.threads, args.timeout, args.rts_arg)
        row.rts_wall_s, row.rts_render_s, row.rts_time_source = rr.wall, rr.render, rr.render_source
        row.rts_camera_rays = rr.camera_rays
        if not rr.ok:
            row.status, row.detail = "rts error", rr.error
            print(table([row], args.min_ssim)[2], flush=True)
            continue
        if row.pov_render_s and row.rts_render_s:
            row.ratio = row.rts_render_s / row.pov_render_s
        try:
            m = compare_pictures(pov_png, rts_png, diff_png)
        except ValueError as e:
            row.status, row.detail = "mismatch", str(e)
            print(table([row], args.min_ssim)[2], flush=True)
            continue
        row.ssim, row.mae, row.max_diff = m["ssim"], m["mae"], m["max"]
        row.status = "ok" if m["ssim"] >= args.min_ssim else "low ssim"
        row.detail = rr.error
        row.pictures = {
            "pov": str(pov_png),
            "rts": str(rts_png),
            "diff": str(diff_png),
            "side": str(out / "side" / rts_png.name),
        }
        print(table([row], args.min_ssim)[2], flush=True)

    lines = table(rows, args.min_ssim)
    print("\n" + "\n".join(lines))
    out.mkdir(parents=True, exist_ok=True)
    (out / "report.json").write_text(json.dumps({"settings": settings, "scenes": [asdict(r) for r in rows]}, indent=2))
    (out / "report.md").write_text(markdown(rows, settings))
    print(f"\nreport: {out / 'report.md'}, {out / 'report.json'}; pictures in {out}/{{pov,rts,diff,side}}")
    return 0 if all(r.status in ("ok", "pov only") for r in rows) else 1


if __name__ == "__main__":
    sys.exit(main())
