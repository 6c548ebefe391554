#!/usr/bin/env python3
"""Embree's single-ray rate on the `benches/mesh.rs` workload, for comparison.

The same wavy 1,002,528-triangle grid over [-1, 1]² and the same 1024² primary
rays from (0, 3, -2) as `cargo bench --bench mesh`, traced by Embree 4 through
`embreex` (`pip install embreex numpy`; rtcIntersect1 per ray). Prints the BVH
build time and Mrays/s (wall and per CPU second, as the bench does) on 1 thread
and on `--threads` threads (the rays split in equal parts, one `run` call each;
whether that runs in parallel depends on embreex releasing the GIL).

Usage: python3 tests/compare/embree_mesh.py [--threads 2] [--repeat 3]
"""

from __future__ import annotations

import argparse
import time
from concurrent.futures import ThreadPoolExecutor

import numpy as np
from embreex import rtcore_scene
from embreex.mesh_construction import TriangleMesh


def grid(n: int) -> tuple[np.ndarray, np.ndarray]:
    """Vertices and triangles of benches/mesh.rs's `grid(n)` (f32 positions)."""
    v = n + 1
    i, j = np.meshgrid(np.arange(v), np.arange(v))
    x = (i.astype(np.float32) / np.float32(n) * np.float32(2.0) - np.float32(1.0)).ravel()
    z = (j.astype(np.float32) / np.float32(n) * np.float32(2.0) - np.float32(1.0)).ravel()
    y = np.float32(0.1) * np.sin(x * np.float32(20.0)) * np.cos(z * np.float32(17.0))
    verts = np.stack([x, y.astype(np.float32), z], axis=1).astype(np.float32)
    jj, ii = np.meshgrid(np.arange(n), np.arange(n), indexing="ij")
    k = (jj * v + ii).ravel()
    a = np.stack([k, k + 1, k + v], axis=1)
    b = np.stack([k + 1, k + v + 1, k + v], axis=1)
    tris = np.empty((2 * n * n, 3), dtype=np.int32)
    tris[0::2] = a
    tris[1::2] = b
    return verts, tris


def rays(res: int) -> tuple[np.ndarray, np.ndarray]:
    """The bench's primary rays: origin (0, 3, -2) towards a res² grid on y = 0."""
    i, j = np.meshgrid(np.arange(res), np.arange(res))
    tx = i.ravel() / res * 2.0 - 1.0
    tz = j.ravel() / res * 2.0 - 1.0
    o = np.array([0.0, 3.0, -2.0])
    d = np.stack([tx - o[0], np.zeros_like(tx) - o[1], tz - o[2]], axis=1)
    d /= np.linalg.norm(d, axis=1, keepdims=True)
    origins = np.broadcast_to(o, d.shape).astype(np.float32).copy()
    return origins, d.astype(np.float32)


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--repeat", type=int, default=3)
    args = ap.parse_args()
    verts, tris = grid(708)
    origins, dirs = rays(1024)
    t = time.perf_counter()
    scene = rtcore_scene.EmbreeScene()
    TriangleMesh(scene, verts, tris)
    # Embree builds lazily, on the first query: time that with one ray.
    scene.run(origins[:1], dirs[:1])
    build = time.perf_counter() - t
    print(f"embree: {len(tris)} triangles, build + first ray {build:.3f} s")
    n = len(origins)
    for threads in sorted({1, args.threads}):
        parts = np.array_split(np.arange(n), threads)
        best = float("inf")
        best_cpu = float("inf")
        hits = 0
        for _ in range(args.repeat):
            t, c = time.perf_counter(), time.process_time()
            with ThreadPoolExecutor(threads) as pool:
                out = list(pool.map(lambda p: scene.run(origins[p], dirs[p]), parts))
            best = min(best, time.perf_counter() - t)
            best_cpu = min(best_cpu, time.process_time() - c)
            hits = sum(int((o >= 0).sum()) for o in out)
        print(
            f"embree: {threads} thread(s): {n} rays ({hits} hits) in {best:.3f} s wall, "
            f"{best_cpu:.2f} CPU s: {n / best / 1e6:.2f} Mrays/s, "
            f"{n / best_cpu / 1e6:.2f} Mrays per CPU second"
        )


if __name__ == "__main__":
    main()
