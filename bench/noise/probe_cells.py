#!/usr/bin/python3
"""probe_cells.py - records POV-Ray 3.7's cells pattern at random points
and writes tests/noise/cells.txt, which tests/test_noise.c checks
zRcube against.  Rerunning it rewrites the file byte for byte (fixed
seed).  Run: bench/noise/probe_cells.py [output]

What the measurements show: cells is one value per unit cell, and that
value is the x coordinate (within its cell) of crackle's feature point
of the same cell: entry H of bench/noise/crackle_tables.h's
crackle_points, H the noise's hash of the cell with crackle's offset
3072.  The script checks that on every point it reads (crackle's table
holds the points to about 1e-12, so it allows 1e-9) and stops if one
disagrees.
"""
import os
import re
import sys
import numpy as np

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, here)
from povprobe import function  # noqa: E402



def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(
        here, "..", "..", "tests", "noise", "cells.txt")
    src = open(os.path.join(here, "noise_tables.h")).read()
    body = src[src.index("noise_hash[4096] = {") + 20:]
    T = [int(t) for t in body[:body.index("}")].replace("\n", "").split(",")
         if t.strip()]
    crackle = open(os.path.join(here, "crackle_tables.h")).read()
    off = int(re.search(r"CRACKLE_HASH_OFFSET (\d+)", crackle).group(1))
    R = [float(m) for m in re.findall(r"\{([0-9.]+), [0-9.]+, [0-9.]+\}",
                                      crackle)]
    if len(R) != 4096:
        sys.exit("probe_cells: crackle_tables.h has %d points" % len(R))
    rng = np.random.default_rng(16)
    P = rng.uniform(-3000, 3000, size=(600, 3))
    # Far out every coordinate past the 32-bit range is the cell -2^31
    # (all of these print one value).
    P = np.vstack([P, [[-2147483648.5, 0.5, 0.5], [3e9, 0.5, 0.5],
                       [1e30, 0.5, 0.5], [-1e30, 0.5, 0.5]]])
    v = function("pattern { cells }", [tuple(p) for p in P])
    lines = ["# x y z value: POV-Ray 3.7's cells, written by "
             "bench/noise/probe_cells.py"]
    for p, val in zip(P, v):
        c = [int(np.floor(a)) if -2**31 <= np.floor(a) < 2**31 else -2**31
             for a in p]
        h = T[T[T[(c[0] + off) & 4095] ^ ((c[1] + off) & 4095)]
              ^ ((c[2] + off) & 4095)]
        if abs(R[h] - val) > 1e-9:
            sys.exit("probe_cells: cell %s: povray %.17g, crackle's x %.17g"
                     % (c, val, R[h]))
        lines.append("%.6f %.6f %.6f %.17g" % (p[0], p[1], p[2], val)
                     if abs(p).max() < 1e6 else
                     "%r %r %r %.17g" % (p[0], p[1], p[2], val))
    with open(out, "w") as f:
        f.write("\n".join(lines) + "\n")
    print("probe_cells: %d points, all crackle's x of the cell" % len(P))


if __name__ == "__main__":
    main()
