#!/usr/bin/env python3
"""Converts the npm package `bunny` (index.js: exports.positions, exports.cells, 0-based) to
scenes/meshes/bunny.obj, once. Usage: convert_bunny.py PATH/TO/index.js [OUT.obj]

Checks on the way that the mesh is closed (every edge shared by exactly two faces, in opposite
directions, i.e. consistently wound) and that its signed volume is positive (outward normals);
a mesh wound inwards is flipped, any other failure stops the conversion."""
import json
import re
import sys
from collections import Counter

HEADER = """\
# The Stanford bunny (reduced), from the npm package `bunny` 1.0.1 by Mikola Lysenko
# (https://github.com/mikolalysenko/bunny, index.js), licence: Public Domain (its package.json).
# Attribution: the bunny is part of the Stanford 3D Scanning Repository
# (http://graphics.stanford.edu/data/3Dscanrep/#bunny), scanned by Greg Turk and Marc Levoy, 1994.
# Converted by scenes/meshes/convert_bunny.py: {vertices} vertices, {faces} triangles, closed,
# wound outwards (signed volume {volume:.6f}); coordinates unchanged (the renderer places the mesh).
"""


def read_array(text, name):
    match = re.search(r"exports\.%s\s*=\s*(\[.*?\]\])" % name, text, re.S)
    if not match:
        sys.exit("%s: no exports.%s = [[...]] found" % (SOURCE, name))
    return json.loads(match.group(1))


def signed_volume(positions, cells):
    total = 0.0
    for i, j, k in cells:
        (ax, ay, az), (bx, by, bz), (cx, cy, cz) = positions[i], positions[j], positions[k]
        total += ax * (by * cz - bz * cy) - ay * (bx * cz - bz * cx) + az * (bx * cy - by * cx)
    return total / 6.0


def check_closed_and_consistent(cells):
    directed = Counter()
    for i, j, k in cells:
        for a, b in ((i, j), (j, k), (k, i)):
            directed[(a, b)] += 1
    for (a, b), n in directed.items():
        if n != 1 or directed.get((b, a), 0) != 1:
            sys.exit("%s: edge %d-%d is used %d times in this direction and %d in the other: "
                     "the mesh is not closed and consistently wound" % (SOURCE, a, b, n, directed.get((b, a), 0)))


def main():
    global SOURCE
    if len(sys.argv) not in (2, 3):
        sys.exit(__doc__)
    SOURCE = sys.argv[1]
    out = sys.argv[2] if len(sys.argv) == 3 else "bunny.obj"
    with open(SOURCE, encoding="utf-8") as f:
        text = f.read()
    positions, cells = read_array(text, "positions"), read_array(text, "cells")
    for c in cells:
        if len(c) != 3 or not all(0 <= i < len(positions) for i in c):
            sys.exit("%s: cell %r is not a triangle of vertices 0..%d" % (SOURCE, c, len(positions) - 1))
    check_closed_and_consistent(cells)
    volume = signed_volume(positions, cells)
    if volume < 0:
        cells = [[i, k, j] for i, j, k in cells]
        volume = -volume
    if not volume > 0:
        sys.exit("%s: zero volume" % SOURCE)
    with open(out, "w", encoding="utf-8") as f:
        f.write(HEADER.format(vertices=len(positions), faces=len(cells), volume=volume))
        for x, y, z in positions:
            f.write("v %r %r %r\n" % (float(x), float(y), float(z)))
        for i, j, k in cells:
            f.write("f %d %d %d\n" % (i + 1, j + 1, k + 1))
    print("%s: %d vertices, %d triangles, signed volume %.6f" % (out, len(positions), len(cells), volume))


if __name__ == "__main__":
    main()
