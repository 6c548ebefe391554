#!/usr/bin/env python3
"""Regenerate the small PNG assets the comparison scenes read (deterministic).

assets/hf.png     64x64 8-bit grey height field: two smooth hills and a ripple.
assets/tiles.png  32x32 RGB image map: four coloured quadrants with a white cross.

Run: python3 tests/compare/make_assets.py  (needs numpy and Pillow).
"""

from pathlib import Path

import numpy as np
from PIL import Image

HERE = Path(__file__).resolve().parent


def height_field() -> Image.Image:
    n = 64
    y, x = np.mgrid[0:n, 0:n] / (n - 1)
    h = 0.7 * np.exp(-((x - 0.3) ** 2 + (y - 0.35) ** 2) / 0.03)
    h += 0.5 * np.exp(-((x - 0.72) ** 2 + (y - 0.65) ** 2) / 0.02)
    h += 0.08 * np.sin(12 * x) * np.cos(9 * y) + 0.1
    h = np.clip(h / h.max(), 0, 1)
    return Image.fromarray((h * 255).round().astype(np.uint8), "L")


def tiles() -> Image.Image:
    n = 32
    a = np.zeros((n, n, 3), np.uint8)
    a[: n // 2, : n // 2] = (220, 60, 50)
    a[: n // 2, n // 2 :] = (60, 170, 70)
    a[n // 2 :, : n // 2] = (50, 90, 210)
    a[n // 2 :, n // 2 :] = (230, 200, 60)
    a[n // 2 - 2 : n // 2 + 2, :] = 255
    a[:, n // 2 - 2 : n // 2 + 2] = 255
    return Image.fromarray(a, "RGB")


if __name__ == "__main__":
    out = HERE / "assets"
    out.mkdir(exist_ok=True)
    height_field().save(out / "hf.png")
    tiles().save(out / "tiles.png")
    print("wrote", out / "hf.png", out / "tiles.png")
