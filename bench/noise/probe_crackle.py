#!/usr/bin/python3
"""probe_crackle.py - reconstructs the feature points of POV-Ray 3.7's
crackle pattern from povray's output and writes
bench/noise/crackle_tables.h, which lib/scene/pattern.c includes.
Rerunning it rewrites the header byte for byte.
Run: bench/noise/probe_crackle.py [output.h]

What the measurements show:
 1. crackle form <1, 0, 0> is the distance d1 to the nearest feature
    point.  Five values around a point (the point and steps of 0.02 along
    each axis and the diagonal) fix that nearest point by trilateration;
    the fifth checks the other four (to 1e-9).  Every unit cell holds one
    feature point.
 2. Cells whose points sit at the same place in their cell are cells with
    the same 12-bit hash T[T[T[x'] ^ y'] ^ z'] of noise_tables.h's
    permutation T, x' = (x + K) & 4095, with a K of crackle's own: the
    script finds K from random cells (the only order and offset that
    groups them right) and reads the point of every hash value from the
    4096 cells (x, 0, 0).  A second reading of every hash must agree.
 3. The pattern is clamp(form . (d1, d2, d3), 0, 1) over the 27 cells
    around the point, metric m measuring (|dx|^m + |dy|^m + |dz|^m)^(1/m),
    offset a fourth coordinate; solid gives the noise (generator 2) at
    the nearest feature point.  bench/noise/probe_patterns.py records
    values that tests/test_noise.c checks.
"""
import itertools
import os
import re
import sys
import numpy as np

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, here)
from povprobe import function  # noqa: E402

OFFS = np.array([[0, 0, 0], [0.02, 0, 0], [0, 0.02, 0], [0, 0, 0.02],
                 [0.015, 0.015, 0.015]])


def fail(msg):
    sys.stderr.write("probe_crackle: " + msg + "\n")
    sys.exit(1)


def read_hash():
    src = open(os.path.join(here, "noise_tables.h")).read()
    body = src[src.index("noise_hash[4096] = {") + 20:]
    body = body[:body.index("}")]
    return np.array([int(t) for t in body.replace("\n", "").split(",")
                     if t.strip()])


def nearest_points(S):
    """The feature point nearest each sample point (NaN where the five
    distances disagree, i.e. two points are about as near)."""
    pts = (S[:, None, :] + OFFS[None]).reshape(-1, 3)
    d = np.array(function("pattern { crackle form <1, 0, 0> }",
                          [tuple(p) for p in pts])).reshape(len(S), 5)
    out = np.full(S.shape, np.nan)
    A = 2 * (OFFS[1:4] - OFFS[0])
    for n, dd in enumerate(d):
        b = ((OFFS[1:4] ** 2).sum(1) - (OFFS[0] ** 2).sum() -
             (dd[1:4] ** 2 - dd[0] ** 2))
        f = np.linalg.solve(A, b)
        if abs(np.linalg.norm(OFFS[4] - f) - dd[4]) < 1e-9:
            out[n] = f + S[n]
    return out


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(
        here, "crackle_tables.h")
    T = read_hash()
    sub = np.array(list(itertools.product((0.25, 0.75), repeat=3)))
    rng = np.random.default_rng(3072)
    # Step 2a: random cells give points that repeat: find the hash.
    S = rng.uniform(0, 40, size=(1200, 3))
    F = nearest_points(S)
    F = F[~np.isnan(F[:, 0])]
    cells = np.floor(F).astype(np.int64)
    frac = F - cells
    _, first = np.unique(cells, axis=0, return_index=True)
    cells, frac = cells[first], frac[first]
    groups = {}
    for i, o in enumerate(frac):
        groups.setdefault(tuple(np.round(o, 9)), []).append(i)
    groups = [g for g in groups.values() if len(g) > 1]
    found = []
    for K in range(4096):
        q = (cells + K) & 4095
        h = T[T[T[q[:, 0]] ^ q[:, 1]] ^ q[:, 2]]
        if all(len(set(h[g])) == 1 for g in groups) and \
                len(set(h.tolist())) == len(set(map(tuple, np.round(
                    frac, 9)))):
            found.append(K)
    print("step 2: %d cells, %d repeated points, offsets K: %s"
          % (len(cells), len(groups), found))
    if len(found) != 1:
        fail("no single hash offset groups the repeated points")
    K = found[0]
    # Step 2b: the point of every hash value, from the cells (x, 0, 0).
    S = (np.array([[x, 0, 0] for x in range(4096)], float)[:, None, :] +
         sub[None]).reshape(-1, 3)
    F = nearest_points(S)
    F = F[~np.isnan(F[:, 0])]
    cells = np.floor(F).astype(np.int64)
    q = (cells + K) & 4095
    h = T[T[T[q[:, 0]] ^ q[:, 1]] ^ q[:, 2]]
    table = np.full((4096, 3), np.nan)
    worst = 0.0
    for hh, o in zip(h, F - cells):
        if np.isnan(table[hh, 0]):
            table[hh] = o
        else:
            worst = max(worst, np.abs(table[hh] - o).max())
    missing = int(np.isnan(table[:, 0]).sum())
    print("step 2: %d hash values read, %d missing, readings agree to %.1e"
          % (4096 - missing, missing, worst))
    if missing or worst > 1e-9:
        fail("the feature point table is incomplete or inconsistent")
    with open(out, "w") as f:
        f.write("/* crackle_tables.h - the feature points of POV-Ray 3.7's "
                "crackle pattern,\n   written by bench/noise/probe_crackle.py"
                " from povray's output (do not\n   edit).  See "
                "lib/scene/pattern.c for their use. */\n\n")
        f.write("/* The offset added to cell coordinates before the noise's "
                "hash. */\n#define CRACKLE_HASH_OFFSET %d\n\n" % K)
        f.write("/* The feature point's place in its unit cell, by hash. */\n"
                "static const double crackle_points[4096][3] = {\n")
        for row in table:
            f.write("    {%.13f, %.13f, %.13f},\n" % tuple(row))
        f.write("};\n")
    print("wrote", out)


if __name__ == "__main__":
    main()
