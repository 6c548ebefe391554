#!/usr/bin/env python3
"""Front-end speed against POV-Ray 3.7: parse time of every sample scene both read.

For each .pov under POV-Ray's sample scenes (Debian `povray-examples`), from the scene's own
folder: POV-Ray's own "Parse Time" (`povray +W1 +H1 -D`), and rts's `seconds.parse_eval`
(`rts render -W 1 -H 1 --stats-json -`: parsing and evaluating the scene and its includes,
process start and rendering excluded). POV-Ray reports milliseconds, so anything under 1 ms
counts as 1 ms on both sides. A scene counts when both read it without error.

  apt-get install -y povray povray-examples povray-includes
  cargo build --release
  python3 tests/compare/parse_speed.py [--library /usr/share/povray-3.7/include] [--runs 3]

Reports the ratio POV-Ray / rts (above 1: rts is faster) per scene, the geometric mean over
all scenes and over those POV-Ray takes 20 ms or more to parse, and the slowest scenes for rts.
`--json FILE` writes every measurement.
"""

import argparse
import json
import math
import os
import pathlib
import re
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parents[2]
PARSE_TIME = re.compile(r"Parse Time:.*\(([\d.]+) seconds\)")


def pov_parse(scene: pathlib.Path, timeout: float) -> float | None:
    """POV-Ray's Parse Time in seconds, or None when it did not read the scene."""
    try:
        p = subprocess.run(
            ["povray", "+W1", "+H1", "-D", "-V", "+GS", "-GR", "+O/dev/null", "-F", scene.name],
            cwd=scene.parent,
            capture_output=True,
            text=True,
            timeout=timeout,
        )
    except subprocess.TimeoutExpired:
        return None
    m = PARSE_TIME.search(p.stdout + p.stderr)
    if not m or "Parse Error" in p.stderr:
        return None
    return float(m.group(1))


def rts_parse(rts: pathlib.Path, scene: pathlib.Path, timeout: float, extra: list[str]) -> float | None:
    """rts's parse+eval seconds, or None when it did not read the scene."""
    try:
        p = subprocess.run(
            [str(rts), "render", *extra, scene.name, "-W", "1", "-H", "1", "-o", "/dev/null",
             "--stats-json", "-", "-q", "--message-format", "human"],
            cwd=scene.parent,
            capture_output=True,
            text=True,
            timeout=timeout,
        )
    except subprocess.TimeoutExpired:
        return None
    if p.returncode != 0:
        return None
    try:
        return float(json.loads(p.stdout)["seconds"]["parse_eval"])
    except (ValueError, KeyError):
        return None


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--scenes", default="/usr/share/povray-3.7/scenes")
    ap.add_argument("--rts", default=str(ROOT / "target/release/rts"))
    ap.add_argument("--library", help="POV-Ray's include folder, put first on rts's -I path")
    ap.add_argument("--runs", type=int, default=1, help="best of N runs on each side")
    ap.add_argument("--timeout", type=float, default=60)
    ap.add_argument("--filter", default="", help="only scenes whose path contains this")
    ap.add_argument("--json", help="write every measurement to this file")
    args = ap.parse_args()
    rts = pathlib.Path(args.rts)
    extra = ["--allow-any-path"]
    if args.library:
        extra += ["-I", args.library]
    scenes = sorted(p for p in pathlib.Path(args.scenes).rglob("*.pov") if args.filter in str(p))
    rows = []
    for scene in scenes:
        pov = [pov_parse(scene, args.timeout) for _ in range(args.runs)]
        if any(t is None for t in pov):
            continue
        ours = [rts_parse(rts, scene, args.timeout, extra) for _ in range(args.runs)]
        if any(t is None for t in ours):
            continue
        p, r = max(min(pov), 0.001), max(min(ours), 0.001)
        rows.append({"scene": str(scene.relative_to(args.scenes)), "povray": p, "rts": r, "ratio": p / r})
        print(f"{p * 1000:9.1f} ms {r * 1000:9.1f} ms  {p / r:6.2f}x  {scene.relative_to(args.scenes)}", flush=True)
    if not rows:
        print("no scene read by both")
        return 1

    def geomean(xs):
        return math.exp(sum(math.log(x) for x in xs) / len(xs))

    heavy = [r for r in rows if r["povray"] >= 0.020]
    slow = sorted(rows, key=lambda r: r["ratio"])[:10]
    print()
    print(f"scenes read by both: {len(rows)}")
    print(f"geometric mean POV-Ray/rts: {geomean([r['ratio'] for r in rows]):.2f}x")
    if heavy:
        print(f"  over the {len(heavy)} POV-Ray parses in 20 ms or more: {geomean([r['ratio'] for r in heavy]):.2f}x")
    print(f"faster than POV-Ray on {sum(r['ratio'] > 1 for r in rows)}; more than 2x slower on "
          f"{sum(r['ratio'] < 0.5 for r in rows)}")
    print("slowest for rts:")
    for r in slow:
        print(f"  {r['ratio']:6.2f}x  {r['povray'] * 1000:7.1f} ms vs {r['rts'] * 1000:7.1f} ms  {r['scene']}")
    if args.json:
        pathlib.Path(args.json).write_text(json.dumps(rows, indent=1))
    return 0


if __name__ == "__main__":
    sys.exit(main())
