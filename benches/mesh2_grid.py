#!/usr/bin/env python3
"""A height-field grid exported as a POV-Ray `mesh2`, as a modelling tool writes it.

    python3 benches/mesh2_grid.py [N] [OUT.inc]

N x N vertices (default 708: 501,264 vertices and 999,698 triangles, about 36 MB at
5 decimals) in `vertex_vectors`, two triangles per grid cell in `face_indices`,
declared as `Terrain`. `benches/frontend.rs` builds the same text in Rust (its
"mesh2 grid" case); this script makes the file for the command line, e.g.

    python3 benches/mesh2_grid.py 708 /tmp/grid.inc
    printf '#include "grid.inc"\\nobject { Terrain }\\n' > /tmp/grid.pov
    /usr/bin/time -v rts check /tmp/grid.pov
"""
import math
import sys


def main() -> None:
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 708
    out = sys.argv[2] if len(sys.argv) > 2 else "grid.inc"
    with open(out, "w") as f:
        f.write("#declare Terrain = mesh2 {\n  vertex_vectors {\n    %d,\n" % (n * n))
        for j in range(n):
            for i in range(n):
                x = i / (n - 1) * 10 - 5
                z = j / (n - 1) * 10 - 5
                y = 0.5 * math.sin(x * 1.3) * math.cos(z * 0.7)
                f.write("    <%.5f, %.5f, %.5f>,\n" % (x, y, z))
        f.write("  }\n  face_indices {\n    %d,\n" % (2 * (n - 1) * (n - 1)))
        for j in range(n - 1):
            for i in range(n - 1):
                a = j * n + i
                b, c = a + 1, a + n
                d = c + 1
                f.write("    <%d, %d, %d>, <%d, %d, %d>,\n" % (a, b, d, a, d, c))
        f.write("  }\n}\n")


if __name__ == "__main__":
    main()
