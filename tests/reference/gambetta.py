#!/usr/bin/env python3
"""Reference renderer for seed 003 (Gambetta, "Computer Graphics from Scratch").

This is an independent, literal implementation of the seed's ray-tracing
pseudocode and of its four-sphere scene, used to check that
examples/seed_gambetta.rts (rendered by rts or by POV-Ray) reproduces the
seed's model pixel for pixel.

The model, as the seed states it:
  * camera at the origin, viewport 1 x 1 at distance d = 1, x right, y up,
    z forward; one ray per pixel;
  * lights with scalar intensities: ambient (adds its intensity), point
    (shadow ray to the light, t in [0.001, 1]) and directional (shadow ray
    t in [0.001, inf));
  * i = sum of ambient + per unshadowed light: I * N.L/|L| (when > 0) plus
    I * (R.V / (|R||V|))^s (when R.V > 0), R = 2N(N.L) - L, V = -D;
  * local = colour * i (colour in 0..255, not clamped until output);
  * r = reflective; if depth <= 0 or r <= 0 the local colour is returned,
    else local * (1 - r) + r * trace(reflected ray, depth - 1);
  * rays that hit nothing return the background colour (white here, as in
    the book); the top-level call uses depth 3 and t_min = 1 (rays start
    at the projection plane);
  * output: each channel clamped to 0..255 and rounded; no gamma curve.

Only the Python 3 standard library is used.

Usage:
  gambetta.py render [-W 256] [-H 256] [--corner] [--tmin T] -o out.png
  gambetta.py compare a.png b.png [--max-diff N] [--max-mean M]
      prints the max / mean absolute channel difference; with limits given,
      exits with status 1 when either is exceeded (for use in tests)

Pixel sampling: by default each ray goes through the centre of its pixel
(px + 0.5), the usual convention of ray tracers and the one POV-Ray uses. With
--corner it goes through the pixel's corner, as the book's integer canvas
loop literally does (x from -Cw/2 to Cw/2 - 1).

--tmin T replaces the seed's 0.001 offset for shadow and reflection rays. The
red sphere is half sunk into the yellow one, and near the circle where they
meet a reflected ray may start closer than 0.001 to the other sphere; the
seed's offset then skips that hit. Renderers with a much smaller offset (as
POV-Ray has) differ there, on a few dozen pixels; pass
--tmin 1e-5 to take that effect out of a comparison.
"""
import math
import struct
import sys
import zlib

INF = float("inf")

# ---- the seed's scene -------------------------------------------------------
BACKGROUND = (255.0, 255.0, 255.0)
VIEWPORT = 1.0          # viewport width and height
PLANE_D = 1.0           # projection plane distance
RECURSION_DEPTH = 3
SECONDARY_T_MIN = 0.001  # the seed's t_min for shadow and reflection rays

# (centre, radius, colour 0..255, specular exponent or -1, reflective)
SPHERES = [
    ((0.0, -1.0, 3.0), 1.0, (255.0, 0.0, 0.0), 500.0, 0.2),
    ((-2.0, 1.0, 3.0), 1.0, (0.0, 0.0, 255.0), 500.0, 0.3),
    ((2.0, 1.0, 3.0), 1.0, (0.0, 255.0, 0.0), 10.0, 0.4),
    ((0.0, -5001.0, 0.0), 5000.0, (255.0, 255.0, 0.0), 1000.0, 0.5),
]

# (kind, intensity, position or direction)
LIGHTS = [
    ("ambient", 0.2, None),
    ("point", 0.6, (2.0, 1.0, 0.0)),
    ("directional", 0.2, (1.0, 4.0, 4.0)),
]


# ---- small vector helpers ----------------------------------------------------
def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def add(a, b):
    return (a[0] + b[0], a[1] + b[1], a[2] + b[2])


def mul(a, k):
    return (a[0] * k, a[1] * k, a[2] * k)


def length(a):
    return math.sqrt(dot(a, a))


# ---- the seed's pseudocode ---------------------------------------------------
def intersect_ray_sphere(o, d, sphere):
    centre, radius = sphere[0], sphere[1]
    co = sub(o, centre)
    a = dot(d, d)
    b = 2.0 * dot(co, d)
    c = dot(co, co) - radius * radius
    disc = b * b - 4.0 * a * c
    if disc < 0.0:
        return INF, INF
    root = math.sqrt(disc)
    return (-b + root) / (2.0 * a), (-b - root) / (2.0 * a)


def closest_intersection(o, d, t_min, t_max):
    closest_t, closest = INF, None
    for sphere in SPHERES:
        t1, t2 = intersect_ray_sphere(o, d, sphere)
        if t_min <= t1 <= t_max and t1 < closest_t:
            closest_t, closest = t1, sphere
        if t_min <= t2 <= t_max and t2 < closest_t:
            closest_t, closest = t2, sphere
    return closest, closest_t


def compute_lighting(p, n, v, s):
    i = 0.0
    for kind, intensity, vec in LIGHTS:
        if kind == "ambient":
            i += intensity
            continue
        if kind == "point":
            l, t_max = sub(vec, p), 1.0
        else:
            l, t_max = vec, INF
        blocker, _ = closest_intersection(p, l, SECONDARY_T_MIN, t_max)
        if blocker is not None:
            continue
        n_dot_l = dot(n, l)
        if n_dot_l > 0.0:
            i += intensity * n_dot_l / (length(n) * length(l))
        if s != -1:
            r = sub(mul(n, 2.0 * dot(n, l)), l)
            r_dot_v = dot(r, v)
            if r_dot_v > 0.0:
                i += intensity * (r_dot_v / (length(r) * length(v))) ** s
    return i


def trace_ray(o, d, t_min, t_max, depth):
    sphere, t = closest_intersection(o, d, t_min, t_max)
    if sphere is None:
        return BACKGROUND
    p = add(o, mul(d, t))
    n = sub(p, sphere[0])
    n = mul(n, 1.0 / length(n))
    local = mul(sphere[2], compute_lighting(p, n, mul(d, -1.0), sphere[3]))
    r = sphere[4]
    if depth <= 0 or r <= 0.0:
        return local
    view = mul(d, -1.0)
    refl_dir = sub(mul(n, 2.0 * dot(n, view)), view)
    reflected = trace_ray(p, refl_dir, SECONDARY_T_MIN, INF, depth - 1)
    return add(mul(local, 1.0 - r), mul(reflected, r))


def render(width, height, corner=False):
    """Rows of (r, g, b) byte tuples, top row first."""
    off = 0.0 if corner else 0.5
    rows = []
    for sy in range(height):
        row = []
        for sx in range(width):
            x = (sx + off - width / 2.0) * VIEWPORT / width
            y = (height / 2.0 - sy - off) * VIEWPORT / height
            c = trace_ray((0.0, 0.0, 0.0), (x, y, PLANE_D), 1.0, INF, RECURSION_DEPTH)
            row.append(tuple(int(round(min(255.0, max(0.0, ch)))) for ch in c))
        rows.append(row)
    return rows


# ---- minimal PNG writing / reading (8-bit RGB or RGBA, no interlace) ---------
def write_png(path, rows):
    h, w = len(rows), len(rows[0])
    raw = b"".join(b"\x00" + bytes(ch for px in row for ch in px) for row in rows)

    def chunk(tag, data):
        return (struct.pack(">I", len(data)) + tag + data
                + struct.pack(">I", zlib.crc32(tag + data) & 0xFFFFFFFF))

    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n")
        f.write(chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0)))
        f.write(chunk(b"IDAT", zlib.compress(raw, 9)))
        f.write(chunk(b"IEND", b""))


def read_png(path):
    """Rows of (r, g, b) tuples from an 8-bit RGB/RGBA non-interlaced PNG."""
    data = open(path, "rb").read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG"
    pos, idat = 8, b""
    while pos < len(data):
        n = struct.unpack(">I", data[pos:pos + 4])[0]
        tag, body = data[pos + 4:pos + 8], data[pos + 8:pos + 8 + n]
        if tag == b"IHDR":
            w, h, bits, ctype, _, _, interlace = struct.unpack(">IIBBBBB", body)
            assert bits == 8 and ctype in (2, 6) and interlace == 0, "unsupported PNG"
        elif tag == b"IDAT":
            idat += body
        pos += 12 + n
    bpp = 3 if ctype == 2 else 4
    raw, stride = zlib.decompress(idat), w * bpp
    prev, rows, i = bytearray(stride), [], 0
    for _ in range(h):
        ftype, line = raw[i], bytearray(raw[i + 1:i + 1 + stride])
        i += 1 + stride
        for k in range(stride):
            a = line[k - bpp] if k >= bpp else 0
            b = prev[k]
            c = prev[k - bpp] if k >= bpp else 0
            if ftype == 1:
                line[k] = (line[k] + a) & 255
            elif ftype == 2:
                line[k] = (line[k] + b) & 255
            elif ftype == 3:
                line[k] = (line[k] + (a + b) // 2) & 255
            elif ftype == 4:
                pa, pb, pc = abs(b - c), abs(a - c), abs(a + b - 2 * c)
                pred = a if pa <= pb and pa <= pc else (b if pb <= pc else c)
                line[k] = (line[k] + pred) & 255
        rows.append([tuple(line[k:k + 3]) for k in range(0, stride, bpp)])
        prev = line
    return rows


def compare(path_a, path_b):
    a, b = read_png(path_a), read_png(path_b)
    assert len(a) == len(b) and len(a[0]) == len(b[0]), "image sizes differ"
    diffs = [abs(ca - cb) for ra, rb in zip(a, b) for pa, pb in zip(ra, rb)
             for ca, cb in zip(pa, pb)]
    worst = max(diffs)
    mean = sum(diffs) / len(diffs)
    over1 = sum(1 for d in diffs if d > 1) / len(diffs)
    print("max %d  mean %.4f  channels off by more than 1: %.3f%%"
          % (worst, mean, 100.0 * over1))
    return worst, mean


def main(argv):
    global SECONDARY_T_MIN
    if len(argv) >= 3 and argv[0] == "compare" and len(argv) % 2 == 1:
        limits = dict(zip(argv[3::2], argv[4::2]))
        if set(limits) <= {"--max-diff", "--max-mean"}:
            worst, mean = compare(argv[1], argv[2])
            too_far = (worst > float(limits.get("--max-diff", "inf"))
                       or mean > float(limits.get("--max-mean", "inf")))
            return 1 if too_far else 0
    if len(argv) >= 1 and argv[0] == "render":
        w = h = 256
        out, corner, k = None, False, 1
        while k < len(argv):
            if argv[k] == "-W":
                w, k = int(argv[k + 1]), k + 2
            elif argv[k] == "-H":
                h, k = int(argv[k + 1]), k + 2
            elif argv[k] == "-o":
                out, k = argv[k + 1], k + 2
            elif argv[k] == "--corner":
                corner, k = True, k + 1
            elif argv[k] == "--tmin":
                SECONDARY_T_MIN, k = float(argv[k + 1]), k + 2
            else:
                break
        if out is not None and k == len(argv):
            write_png(out, render(w, h, corner))
            return 0
    print(__doc__)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
