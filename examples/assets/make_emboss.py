"""Writes emboss.png, the bump map of examples/pattern_blending.rts: a 64x64
8-bit grey image of raised discs on a flat ground, with a soft ramp across it
(deterministic)."""
import math
import os
from PIL import Image

N = 64
img = Image.new("L", (N, N))
px = img.load()
for j in range(N):
    for i in range(N):
        v = 40 + i  # a gentle ramp: barely tilts a bump_map
        cx, cy = (i % 16) - 7.5, (j % 16) - 7.5
        if math.hypot(cx, cy) < 5.0:
            v += 120  # a one-pixel step: draws an outline
        px[i, j] = v
img.save(os.path.join(os.path.dirname(os.path.abspath(__file__)), "emboss.png"))
