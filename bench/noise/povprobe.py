"""povprobe.py - evaluates scene-language expressions in POV-Ray 3.7.

The probe scripts of bench/noise/ use it to read POV-Ray's values: each
call writes a scene that declares what the caller gives, evaluates an
expression of X, Y and Z at every point of a list with #debug and
str(value, 0, 20), runs `povray` on it for a 1x1 image without output,
and returns the printed numbers.  POVRAY in the environment picks the
binary; POVRAY_INCLUDE the include folder (functions.inc).
"""
import os
import subprocess
import tempfile

POVRAY = os.environ.get("POVRAY", "povray")
INCLUDE = os.environ.get("POVRAY_INCLUDE", "/usr/share/povray-3.7/include")

# Points per povray run: one run for thousands of points is fine, but a
# scene of a hundred thousand array elements parses slowly.
CHUNK = 20000


def _run(decl, expr, pts, settings):
    with tempfile.TemporaryDirectory() as d:
        with open(os.path.join(d, "probe.pov"), "w") as f:
            f.write('#version 3.7;\n#include "functions.inc"\n')
            f.write("global_settings { assumed_gamma 1 %s }\n" % settings)
            f.write(decl + "\n")
            f.write("#declare N = %d;\n#declare A = array[N][3] {\n" % len(pts))
            f.write(",\n".join("{%r, %r, %r}" % (float(p[0]), float(p[1]),
                                                 float(p[2])) for p in pts))
            f.write("}\n#for (I, 0, N - 1)\n"
                    "  #declare X = A[I][0]; #declare Y = A[I][1];"
                    " #declare Z = A[I][2];\n"
                    '  #debug concat(str(%s, 0, 20), "\\n")\n#end\n' % expr)
        subprocess.run([POVRAY, "+Iprobe.pov", "-D", "+W1", "+H1", "-F",
                        "-GA", "+GDdebug.txt", "+L" + INCLUDE], cwd=d,
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                       check=False)
        path = os.path.join(d, "debug.txt")
        out = [float(l) for l in open(path)] if os.path.exists(path) else []
    if len(out) != len(pts):
        raise RuntimeError("povray printed %d values for %d points (%s)"
                           % (len(out), len(pts), expr))
    return out


def evaluate(decl, expr, pts, settings=""):
    """The value of expr (of X, Y, Z and what decl declares) at pts."""
    out = []
    for i in range(0, len(pts), CHUNK):
        out += _run(decl, expr, pts[i:i + CHUNK], settings)
    return out


def function(body, pts, settings=""):
    """The values of function { body } at pts."""
    return evaluate("#declare F = function { %s }" % body, "F(X, Y, Z)",
                    pts, settings)
