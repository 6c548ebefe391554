"""Writes hills.png, the height map of examples/height_field.rts: a 128x128
16-bit grey image of a few smooth hills around a valley (deterministic)."""
import math
import os
from PIL import Image

N = 128
HILLS = [(0.3, 0.35, 0.18, 0.9), (0.7, 0.3, 0.22, 0.7), (0.55, 0.75, 0.16, 1.0),
         (0.2, 0.8, 0.12, 0.5), (0.85, 0.8, 0.1, 0.4)]


def height(i, j):
    x, z = i / (N - 1), j / (N - 1)
    h = 0.03 * math.sin(23 * x) * math.cos(19 * z) + 0.02 * math.sin(41 * x + 31 * z)
    for cx, cz, r, a in HILLS:
        h += a * math.exp(-((x - cx) ** 2 + (z - cz) ** 2) / (2 * r * r))
    return h


H = [[height(i, j) for i in range(N)] for j in range(N)]
lo, hi = min(map(min, H)), max(map(max, H))
img = Image.new("I;16", (N, N))
px = img.load()
for j in range(N):
    for i in range(N):
        px[i, j] = int((H[j][i] - lo) / (hi - lo) * 65535 * 0.98)
img.save(os.path.join(os.path.dirname(os.path.abspath(__file__)), "hills.png"))
