#!/usr/bin/python3
"""probe_patterns.py - records POV-Ray 3.7's values of the noise
functions and the noise-based patterns at random points and writes
tests/noise/patterns.txt, which tests/test_noise.c checks zRcube
against.  Rerunning it rewrites the file byte for byte (fixed seeds).
Run: bench/noise/probe_patterns.py [output]

Each case is a name, the function povray evaluates and the points.  The
formulas lib/scene/pattern.c uses for them were found with these values
and the noise of bench/noise/probe_noise.py (for noise_generator 2; for
generator 1, c(n) is generator 1's noise and agate clamps every octave):
  bozo, spotted, bumps  the noise n(p);      dents  n(p)^3;
  wrinkles  half the sum over 10 octaves i of c(n(2^i p)) / 2^i, where
            c(n) = 2 n - 0.5 clamped to [0, 1];
  granite   the sum over 6 octaves i of |c(n(4 2^i p)) - 0.5| / 2^i;
  agate     (0.5 + 0.5 sin(2 pi (1.1 z + 1.3 agate_turb s)))^0.77 with
            s = c(n(p)) + the sum over octaves i = 1..5 of
            (2 n(2^i p) - 0.5) / 2^i (agate_turb 0 leaves the 1.1 z);
  turbulence  the point moves by turbulence times the sum over octaves i
            of omega^i D(lambda^i p), D the vector noise; omega (and
            agate_turb) act as single-precision numbers (0.7 is off by
            the float's rounding, 8e-9);
  marble's turbulence moves x alone, by turbulence.x times the sum over
            octaves i of omega^i c(n(lambda^i p)), c unclamped after the
            first octave (as agate's);
  wood's turbulence moves each coordinate a by
            sin(2 pi turbulence.a (a + T.a)), T the vector turbulence.
The gradient cases use positive points: povray's wrap of a negative
pattern value is 1e-5 a unit off its fraction.  Marble's and wood's
triangle wave is off by 1e-5 times the whole part of the value too, so
their points stay below 2.5 and the test allows them 2e-4.  Points where a gradient wraps (value within 1e-6 of 0 or 1) are
left out: the two renderers may round them to either side.
"""
import os
import sys
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from povprobe import function  # noqa: E402

CASES = [
    ("noise", "f_noise3d(x, y, z)"),
    ("noise1", "f_noise_generator(x, y, z, 1)"),
    ("noise3", "f_noise_generator(x, y, z, 3)"),
    ("bozo3", "pattern { bozo noise_generator 3 }"),
    ("dents3", "pattern { dents noise_generator 3 }"),
    ("wrinkles3", "pattern { wrinkles noise_generator 3 }"),
    ("granite3", "pattern { granite noise_generator 3 }"),
    ("agate3", "pattern { agate noise_generator 3 }"),
    ("bozo", "pattern { bozo }"),
    ("bozo1", "pattern { bozo noise_generator 1 }"),
    ("spotted", "pattern { spotted }"),
    ("bumps", "pattern { bumps }"),
    ("dents", "pattern { dents }"),
    ("dents1", "pattern { dents noise_generator 1 }"),
    ("wrinkles", "pattern { wrinkles }"),
    ("wrinkles1", "pattern { wrinkles noise_generator 1 }"),
    ("granite1", "pattern { granite noise_generator 1 }"),
    ("agate1", "pattern { agate noise_generator 1 }"),
    ("granite", "pattern { granite }"),
    ("agate", "pattern { agate }"),
    ("agate04", "pattern { agate agate_turb 0.4 }"),
    ("turbx", "pattern { gradient x turbulence 0.3 }"),
    ("turby", "pattern { gradient y turbulence <0.2, 0.4, 0.1> "
              "octaves 3 omega 0.7 lambda 2.5 }"),
    ("turbz", "pattern { gradient z warp { turbulence 0.25 octaves 8 } }"),
    ("bozoturb", "pattern { bozo turbulence 0.5 }"),
    ("marbleturb", "pattern { marble turbulence 0.7 octaves 3 omega 0.6 "
                   "lambda 2.3 }"),
    ("marbleturb1", "pattern { marble turbulence 0.3 noise_generator 1 }"),
    ("woodturb", "pattern { wood turbulence <0.1, 0.5, 1> octaves 5 }"),
    ("woodturb2", "pattern { wood turbulence 0.04 octaves 3 }"),
    ("crackle", "pattern { crackle }"),
    ("crackle100", "pattern { crackle form <1, 0, 0> }"),
    ("crackle011", "pattern { crackle form <0, 1, 1> }"),
    ("crackle_m1", "pattern { crackle metric 1 }"),
    ("crackle_m3", "pattern { crackle metric 3 }"),
    ("crackle_off", "pattern { crackle offset 0.5 }"),
    ("crackle_solid", "pattern { crackle solid }"),
]


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(
        os.path.dirname(os.path.abspath(__file__)), "..", "..", "tests",
        "noise", "patterns.txt")
    rng = np.random.default_rng(1616)
    lines = ["# case x y z value: POV-Ray 3.7's value, written by "
             "bench/noise/probe_patterns.py"]
    for name, body in CASES:
        P = np.round(rng.uniform(-20, 20, size=(400, 3)), 6)
        if name.startswith(("marble", "wood")):
            # Their triangle wave wraps 1e-5 a unit off (see above): keep
            # the coordinates below 2.5.
            P = np.abs(P) / 8
        elif "turb" in name and name != "bozoturb":
            # gradient's wrap of negative values drifts by about 1e-5 a
            # unit in povray (a separate matter): positive points only.
            P = np.abs(P)
        v = function(body, [tuple(p) for p in P])
        n = 0
        for p, x in zip(P, v):
            if "turb" in name and not 1e-6 < x < 1 - 1e-6:
                continue
            lines.append("%s %.6f %.6f %.6f %.17g" % (name, p[0], p[1],
                                                        p[2], x))
            n += 1
        print("%-13s %4d points, values %.4f to %.4f" % (name, n, min(v),
                                                         max(v)))
    with open(out, "w") as f:
        f.write("\n".join(lines) + "\n")
    print("wrote", out)


if __name__ == "__main__":
    main()
