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
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parents[2]


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
    tally = collections.Counter(e for e in errors.values() if e is not None)
    print("first errors, most common first:")
    for e, n in tally.most_common(30):
        print(f"{n:5}  {e}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
