#!/usr/bin/env python3
"""How many of POV-Ray's own sample scenes rts reads, and what stops the rest.

Runs `rts check` on every .pov under POV-Ray's sample scene folder (Debian package
`povray-examples`: /usr/share/povray-3.7/scenes), from the scene's own folder, and
tallies the first error of each scene. With --render, the scenes that check clean
are also rendered small, to catch failures past evaluation.

  apt-get install -y povray-examples
  cargo build --release
  python3 tests/compare/census.py [--scenes DIR] [--render] [--list]

Prints the count that check clean and the first errors, most common first.
"""

import argparse
import collections
import json
import pathlib
import os
import shutil
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "tests/reference"))
import gambetta  # noqa: E402  (its PNG reader: the standard library only)


def first_error(rts: pathlib.Path, scene: pathlib.Path, timeout: float, extra: list[str]) -> str | None:
    """The first error of `rts check` on `scene` as "code | message", or None."""
    try:
        p = subprocess.run(
            [str(rts), "check", "--message-format", "json", *extra, scene.name],
            cwd=scene.parent,
            capture_output=True,
            text=True,
            timeout=timeout,
        )
    except subprocess.TimeoutExpired:
        return "timeout | rts check did not finish"
    for line in (p.stdout + p.stderr).splitlines():
        try:
            d = json.loads(line)
        except json.JSONDecodeError:
            continue
        if d.get("severity") == "error":
            return f"{d.get('code')} | {d.get('message', '')[:100]}"
    if p.returncode != 0:
        return f"exit {p.returncode} | no error diagnostic"
    return None


def renders(rts: pathlib.Path, scene: pathlib.Path, timeout: float, extra: list[str]) -> bool:
    """Whether `rts render` of `scene` at 80x60 succeeds."""
    with tempfile.TemporaryDirectory() as tmp:
        try:
            p = subprocess.run(
                [str(rts), "render", *extra, scene.name, "-o", f"{tmp}/out.png", "-W", "80", "-H", "60", "-q"],
                cwd=scene.parent,
                capture_output=True,
                timeout=timeout,
            )
        except subprocess.TimeoutExpired:
            return False
        return p.returncode == 0


def compare_with_povray(
    rts: pathlib.Path, scene: pathlib.Path, out: pathlib.Path, size: tuple[int, int], timeout: float, extra: list[str]
) -> float | str:
    """Renders `scene` with both renderers (no anti-aliasing) into `out`/{pov,rts}; the mean
    absolute channel difference in levels, or why there is none."""
    w, h = size
    name = str(scene.with_suffix(".png")).replace("/", "_").lstrip("_")
    pov_png, rts_png = out / "pov" / name, out / "rts" / name
    pov_png.parent.mkdir(parents=True, exist_ok=True)
    rts_png.parent.mkdir(parents=True, exist_ok=True)
    # POV-Ray's default I/O security lets it write only under the current folder.
    local = scene.parent / f".rts-census-{os.getpid()}.png"
    try:
        subprocess.run(
            ["povray", f"+I{scene.name}", f"+O{local.name}", f"+W{w}", f"+H{h}", "-D", "-V", "-A", "+FN8", "-GP"],
            cwd=scene.parent,
            capture_output=True,
            timeout=timeout,
        )
        if not local.exists():
            return "povray failed"
        shutil.move(local, pov_png)
        p = subprocess.run(
            [str(rts), "render", *extra, scene.name, "-o", str(rts_png), "-W", str(w), "-H", str(h), "-q"],
            cwd=scene.parent,
            capture_output=True,
            timeout=timeout,
        )
    except subprocess.TimeoutExpired:
        local.unlink(missing_ok=True)
        return "timeout"
    if p.returncode != 0 or not rts_png.exists():
        return "rts failed"
    a, b = gambetta.read_png(str(pov_png)), gambetta.read_png(str(rts_png))
    if len(a) != len(b) or len(a[0]) != len(b[0]):
        return "sizes differ"
    total = sum(abs(x - y) for ra, rb in zip(a, b) for pa, pb in zip(ra, rb) for x, y in zip(pa, pb))
    return total / (len(a) * len(a[0]) * 3)


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--scenes", type=pathlib.Path, default=pathlib.Path("/usr/share/povray-3.7/scenes"))
    ap.add_argument("--rts", type=pathlib.Path, default=ROOT / "target/release/rts")
    ap.add_argument("--render", action="store_true", help="also render the clean scenes at 80x60")
    ap.add_argument("--list", action="store_true", help="print every scene with its first error")
    ap.add_argument("--timeout", type=float, default=60)
    ap.add_argument(
        "--library",
        type=pathlib.Path,
        action="append",
        default=[],
        help="search DIR for include and data files (rts -I DIR), as a POV-Ray user's Library_Path "
        "would: e.g. /usr/share/povray-3.7/include, which then comes before rts's own include files",
    )
    ap.add_argument(
        "--compare",
        type=pathlib.Path,
        metavar="DIR",
        help="also render every clean scene with POV-Ray and rts at 160x120 without anti-aliasing, "
        "keep the pictures in DIR/{pov,rts} and list the scenes by mean difference, largest first",
    )
    args = ap.parse_args()
    if not args.scenes.is_dir():
        print(f"no sample scenes at {args.scenes} (apt-get install -y povray-examples)", file=sys.stderr)
        return 2
    scenes = sorted(args.scenes.rglob("*.pov"))
    extra = [a for d in args.library for a in ("-I", str(d))]
    errors: dict[pathlib.Path, str | None] = {s: first_error(args.rts, s, args.timeout, extra) for s in scenes}
    clean = [s for s, e in errors.items() if e is None]
    if args.list:
        for s, e in errors.items():
            print(f"{s.relative_to(args.scenes)}: {e or 'ok'}")
    print(f"{len(clean)} of {len(scenes)} scenes check clean")
    if args.render:
        failed = [s for s in clean if not renders(args.rts, s, args.timeout, extra)]
        print(f"{len(clean) - len(failed)} of them render at 80x60" + "".join(f"\n  failed: {s}" for s in failed))
    if args.compare:
        diffs = {s: compare_with_povray(args.rts, s, args.compare, (160, 120), args.timeout, extra) for s in clean}
        ranked = sorted(diffs.items(), key=lambda kv: -kv[1] if isinstance(kv[1], float) else -1e9)
        lines = [f"{d:8.2f}  {s.relative_to(args.scenes)}" if isinstance(d, float) else f"{d:>8}  {s.relative_to(args.scenes)}" for s, d in ranked]
        (args.compare / "differences.txt").write_text("\n".join(lines) + "\n")
        close = sum(isinstance(d, float) and d < 2.0 for d in diffs.values())
        print(f"{close} of {len(diffs)} clean scenes are within 2 levels of POV-Ray (mean); worst first:")
        print("\n".join(lines[:40]))
    tally = collections.Counter(e for e in errors.values() if e is not None)
    print("first errors, most common first:")
    for e, n in tally.most_common(30):
        print(f"{n:5}  {e}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
