"""Writes rtsblock.ttf: a tiny block font made for rts's tests and examples.

The glyphs are drawn here (no other font's outlines are used), so the font is
part of rts and under its licence (MIT OR Apache-2.0). Regenerate with
`pip install fonttools && python3 examples/assets/make_rtsblock.py`.

Glyphs (1000 units per em): .notdef (a box with a square hole), space, and
lower-case r, t, s, o, and x; `r` followed by `t` is kerned by -40 units.
Lines and quadratic curves only, as in TrueType fonts.
"""

import os

from fontTools.fontBuilder import FontBuilder
from fontTools.pens.ttGlyphPen import TTGlyphPen
from fontTools.ttLib.tables._k_e_r_n import KernTable_format_0, table__k_e_r_n


def poly(pen, pts):
    pen.moveTo(pts[0])
    for p in pts[1:]:
        pen.lineTo(p)
    pen.closePath()


def notdef(pen):
    poly(pen, [(50, 0), (50, 700), (450, 700), (450, 0)])
    poly(pen, [(150, 100), (350, 100), (350, 600), (150, 600)])


def r(pen):
    # A stem and an arm that curves right from its top.
    pen.moveTo((80, 0))
    pen.lineTo((80, 500))
    pen.lineTo((200, 500))
    pen.lineTo((200, 430))
    pen.qCurveTo((260, 500), (380, 500))
    pen.lineTo((380, 390))
    pen.qCurveTo((200, 390), (200, 300))
    pen.lineTo((200, 0))
    pen.closePath()


def t(pen):
    # A cross with a foot curving right.
    pen.moveTo((120, 0 + 120))
    pen.lineTo((120, 400))
    pen.lineTo((40, 400))
    pen.lineTo((40, 500))
    pen.lineTo((120, 500))
    pen.lineTo((120, 650))
    pen.lineTo((240, 650))
    pen.lineTo((240, 500))
    pen.lineTo((360, 500))
    pen.lineTo((360, 400))
    pen.lineTo((240, 400))
    pen.lineTo((240, 150))
    pen.qCurveTo((240, 100), (300, 100))
    pen.lineTo((360, 100))
    pen.lineTo((360, 0))
    pen.lineTo((240, 0))
    pen.qCurveTo((120, 0), (120, 120))
    pen.closePath()


def s(pen):
    # A squared-off S of five bars.
    poly(pen, [(40, 0), (40, 100), (300, 100), (300, 200), (40, 200), (40, 500),
               (400, 500), (400, 400), (140, 400), (140, 300), (400, 300), (400, 0)])


def o(pen):
    # A ring: outer and inner ellipse, each four quadratic arcs.
    def ring(cx, cy, rx, ry, clockwise):
        pts = [(cx + rx, cy), (cx, cy + ry), (cx - rx, cy), (cx, cy - ry)]
        ctl = [(cx + rx, cy + ry), (cx - rx, cy + ry), (cx - rx, cy - ry), (cx + rx, cy - ry)]
        order = [0, 1, 2, 3]
        if clockwise:
            pts = [pts[0], pts[3], pts[2], pts[1]]
            ctl = [ctl[3], ctl[2], ctl[1], ctl[0]]
        pen.moveTo(pts[0])
        for k in order:
            pen.qCurveTo(ctl[k], pts[(k + 1) % 4])
        pen.closePath()

    ring(250, 250, 210, 250, True)
    ring(250, 250, 100, 140, False)


def x(pen):
    poly(pen, [(40, 0), (190, 250), (40, 500), (160, 500), (250, 340), (340, 500),
               (460, 500), (310, 250), (460, 0), (340, 0), (250, 160), (160, 0)])


GLYPHS = {
    ".notdef": (notdef, 500),
    "space": (None, 250),
    "r": (r, 400),
    "t": (t, 400),
    "s": (s, 440),
    "o": (o, 500),
    "x": (x, 500),
}


def main():
    order = list(GLYPHS)
    fb = FontBuilder(1000, isTTF=True)
    fb.setupGlyphOrder(order)
    fb.setupCharacterMap({32: "space", ord("r"): "r", ord("t"): "t", ord("s"): "s",
                          ord("o"): "o", ord("x"): "x"})
    glyphs = {}
    for name, (draw, _) in GLYPHS.items():
        pen = TTGlyphPen(None)
        if draw:
            draw(pen)
        glyphs[name] = pen.glyph()
    fb.setupGlyf(glyphs)
    metrics = {}
    for name, (_, adv) in GLYPHS.items():
        g = glyphs[name]
        g.recalcBounds(fb.font["glyf"])
        metrics[name] = (adv, getattr(g, "xMin", 0))
    fb.setupHorizontalMetrics(metrics)
    fb.setupHorizontalHeader(ascent=800, descent=-200)
    fb.setupNameTable({"familyName": "RtsBlock", "styleName": "Regular"})
    fb.setupOS2(sTypoAscender=800, usWinAscent=800, usWinDescent=200)
    fb.setupPost()
    kern = table__k_e_r_n()
    kern.version = 0
    sub = KernTable_format_0()
    sub.version = 0
    sub.coverage = 1
    sub.format = 0
    sub.kernTable = {("r", "t"): -40}
    kern.kernTables = [sub]
    fb.font["kern"] = kern
    out = os.path.join(os.path.dirname(os.path.abspath(__file__)), "rtsblock.ttf")
    fb.save(out)
    print(out, os.path.getsize(out), "bytes")


if __name__ == "__main__":
    main()
