#!/usr/bin/python3
"""
probe.py - where zRcube's measured constants come from.

Some numbers in zRcube are neither in the POV-Ray 3.7 reference manual
nor derivable: they were measured on the `povray` binary, as a black
box.  Each probe below renders or #debug-s small scenes with povray,
prints what povray gives, and sets it beside the constant or curve the
code uses (the file and line named in the probe's title, whose comment
points back here).  Nothing is read from POV-Ray's source.

  /usr/bin/python3 bench/provenance/probe.py            # every probe
  /usr/bin/python3 bench/provenance/probe.py NAME ...   # some of them
  /usr/bin/python3 bench/provenance/probe.py --list

POVRAY=/path/to/povray picks the binary (default: povray on PATH).  The
script uses the standard library only and exits 77 when povray is
missing; it prints "N passed, N failed" (a probe fails when povray's
values no longer agree with the code's constant).  Renders are tiny
(one thread, no antialiasing) and take a few seconds each probe.
"""
import math
import os
import shutil
import struct
import subprocess
import sys
import tempfile
import zlib

POVRAY = os.environ.get("POVRAY") or shutil.which("povray") or ""
INCLUDE = "/usr/share/povray-3.7/include"


# ---- running povray ----

def render(workdir, scene, width, height, name="probe"):
    """Renders scene text at width x height into a 16-bit PPM with no
    gamma (File_Gamma=1 and assumed_gamma 1 in the scene give linear
    values).  Returns (exit status, messages, rows of (r, g, b))."""
    pov = os.path.join(workdir, name + ".pov")
    out = os.path.join(workdir, name + ".ppm")
    with open(pov, "w") as f:
        f.write(scene)
    if os.path.exists(out):
        os.remove(out)
    cmd = [POVRAY, "+I" + pov, "+O" + out, "+FP16", "+W%d" % width,
           "+H%d" % height, "-D", "-A", "+WT1", "File_Gamma=1.0",
           "+L" + INCLUDE, "+L" + workdir]
    r = subprocess.run(cmd, cwd=workdir, capture_output=True, text=True,
                       timeout=120)
    text = r.stdout + r.stderr
    if r.returncode != 0 or not os.path.exists(out):
        return r.returncode or 1, text, None
    return 0, text, read_ppm16(out)


def read_ppm16(path):
    data = open(path, "rb").read()
    fields, i = [], 0
    while len(fields) < 4:
        while data[i:i + 1].isspace():
            i += 1
        if data[i:i + 1] == b"#":
            while data[i:i + 1] != b"\n":
                i += 1
            continue
        j = i
        while not data[j:j + 1].isspace():
            j += 1
        fields.append(data[i:j])
        i = j
    i += 1
    w, h, top = int(fields[1]), int(fields[2]), int(fields[3])
    size = 2 if top > 255 else 1
    rows = []
    for y in range(h):
        row = []
        for x in range(w):
            px = []
            for c in range(3):
                k = i + ((y * w + x) * 3 + c) * size
                px.append(int.from_bytes(data[k:k + size], "big") / top)
            row.append(tuple(px))
        rows.append(row)
    return rows


def debug_values(workdir, scene):
    """Parses scene (which #debug-s lines "key=value") and returns the
    dict of those lines."""
    status, text, _ = render(workdir, scene + "\nsphere { 0, 1 }\n", 1, 1)
    values = {}
    for line in text.splitlines():
        if "=" in line and line.startswith("probe:"):
            key, value = line[len("probe:"):].split("=", 1)
            values[key.strip()] = value.strip()
    return status, values


def write_palette_png(path, palette, indices):
    """A one-row 8-bit palette PNG (colour type 3) of the given indices."""
    def chunk(kind, body):
        c = struct.pack(">I", len(body)) + kind + body
        return c + struct.pack(">I", zlib.crc32(kind + body) & 0xFFFFFFFF)
    ihdr = struct.pack(">IIBBBBB", len(indices), 1, 8, 3, 0, 0, 0)
    plte = b"".join(bytes(c) for c in palette)
    raw = b"\x00" + bytes(indices)
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", ihdr) +
                chunk(b"PLTE", plte) + chunk(b"IDAT", zlib.compress(raw)) +
                chunk(b"IEND", b""))


HEADER = "#version 3.7;\nglobal_settings { assumed_gamma 1 }\n"


# ---- the probes ----

def probe_image_map_index(workdir):
    """lib/sdl/build.c, zr__sdl_image_map_index: the palette entry of
    "transmit INDEX, AMOUNT" is trunc(INDEX + 0.01).  A two-entry
    palette image (entry 0 red, entry 1 green) is mapped over the view
    in front of a blue background; the entry given transmit 1 shows
    blue.  Bisection finds the INDEX where entry 1 starts and where the
    index leaves the range at each end."""
    write_palette_png(os.path.join(workdir, "pal.png"),
                      [(255, 0, 0), (0, 255, 0)], [0, 1])

    def entry(index):
        scene = HEADER + """
camera { orthographic location <0.5, 0.5, -5> look_at <0.5, 0.5, 0>
         right x up y }
background { rgb <0, 0, 1> }
plane { -z, 0
  pigment { image_map { png "pal.png"
                        transmit %.6f, 1 } }
  finish { ambient 1 diffuse 0 } }
""" % index
        status, text, rows = render(workdir, scene, 2, 1)
        if status != 0:
            return None  # povray refuses the index
        blue = [px[2] > 0.5 for px in rows[0]]
        return blue.index(True) if True in blue else -1

    def edge(lo, hi, want_lo):
        # The point in [lo, hi] where entry() stops giving want_lo.
        for _ in range(14):
            mid = 0.5 * (lo + hi)
            if entry(mid) == want_lo:
                lo = mid
            else:
                hi = mid
        return 0.5 * (lo + hi)

    ones = edge(0.9, 1.0, 0)      # entry 1 from here on
    top = edge(1.95, 2.05, 1)     # out of range from here on
    bottom = edge(-0.95, -1.05, 0)  # out of range below this
    print("  entry 1 from INDEX %.4f; out of range from %.4f; "
          "below %.4f" % (ones, top, bottom))
    print("  at these INDEX values povray picks:",
          ", ".join("%g -> %s" % (k, entry(k)) for k in
                    (-1.02, -1.005, 0.985, 0.995, 1.989, 1.991)))
    offsets = (1 - ones, 2 - top, -1 - bottom)
    print("  offset added before truncation: %.4f, %.4f, %.4f "
          "(zRcube: 0.01)" % offsets)
    return all(abs(o - 0.01) < 0.002 for o in offsets)


MEDIA_SCENE = """#version %s;
global_settings { assumed_gamma 1 }
camera { location <0, 0, -4> look_at 0 }
box { -1, 1 hollow pigment { rgbt 1 }
  interior { media { %s
    emission 1.5
    density { spherical color_map { [0 rgb 0] [0.5 rgb 0.2]
                                    [1 rgb 1] } scale 1.2 } } } }
"""


def probe_media_defaults(workdir):
    """lib/sdl/build_media.c, zr__sdl_media_new: the media defaults.
    The manual's table ("Media") says samples 1, 1 and, from 3.5 on,
    method 3 with one interval; povray renders a medium without those
    items the same as with "samples 10, 10" (and differently from
    "samples 1, 1"); under #version 3.1 the same as "method 1
    intervals 10 samples 1, 1"."""
    def image(version, items):
        status, text, rows = render(workdir, MEDIA_SCENE % (version, items),
                                    24, 18)
        if status != 0:
            raise RuntimeError(text[-2000:])
        return rows

    ok = True
    plain = image("3.7", "")
    for items, want in (("samples 10, 10", True), ("samples 1, 1", False),
                        ("method 3 intervals 1 samples 10, 10", True)):
        same = image("3.7", items) == plain
        print("  #version 3.7: default %s \"%s\"" %
              ("==" if same else "!=", items))
        ok = ok and same == want
    old = image("3.1", "")
    for items, want in (("method 1 intervals 10 samples 1, 1", True),
                        ("method 3 intervals 1 samples 10, 10", False)):
        same = image("3.1", items) == old
        print("  #version 3.1: default %s \"%s\"" %
              ("==" if same else "!=", items))
        ok = ok and same == want
    print("  zRcube: 3.5 and later method 3, intervals 1, samples 10, 10;"
          " before, method 1, intervals 10, samples 1, 1")
    return ok


def smoothstep(t):
    t = min(1.0, max(0.0, t))
    return t * t * (3 - 2 * t)


def probe_spotlight_curve(workdir):
    """lib/trace/lights.c, zr__light_cone: a spotlight's factor between
    radius and falloff is the smoothstep 3t^2 - 2t^3 of t = (cos a -
    cos falloff) / (cos radius - cos falloff), times cos(a)^tightness.
    A white plane (ambient 0, diffuse 1) under a spotlight 10 units up
    pointing straight down; a pixel at x on the plane is lit at angle
    a = atan(x / 10) with N.L = cos a, so factor = value / cos a."""
    worst = 0.0
    w = 121
    for radius, falloff, tight in ((10, 30, 0), (0, 40, 0), (15, 25, 5)):
        scene = HEADER + """
camera { orthographic location <0, 20, 0> look_at 0
         right x * 20 up z * 20 * 3 / %d }
plane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }
light_source { <0, 10, 0> rgb 1 spotlight point_at 0
  radius %g falloff %g tightness %g }
""" % (w, radius, falloff, tight)
        status, text, rows = render(workdir, scene, w, 3)
        if status != 0:
            raise RuntimeError(text[-2000:])
        cr, cf = (math.cos(math.radians(v)) for v in (radius, falloff))
        shown = []
        for i in range(w // 2, w):
            x = 20 * ((i + 0.5) / w - 0.5)
            c = 10 / math.hypot(x, 10)
            measured = rows[1][i][0] / c
            if c <= cf:
                ours = 0.0
            elif c >= cr:
                ours = 1.0
            else:
                ours = smoothstep((c - cf) / (cr - cf))
            ours *= c ** tight
            worst = max(worst, abs(measured - ours))
            if i % 6 == 0:
                shown.append("%.1f:%.4f/%.4f" %
                              (math.degrees(math.acos(c)), measured, ours))
        print("  radius %g falloff %g tightness %g (angle:povray/zRcube)" %
              (radius, falloff, tight))
        print("   ", " ".join(shown))
    print("  largest difference %.2e" % worst)
    return worst < 2e-3


def probe_cylinder_curve(workdir):
    """lib/trace/lights.c, zr__light_cone: a cylinder light's factor is
    the smoothstep of t = (falloff - d) / (falloff - radius) in the
    distance d from its axis, times (1 - d / falloff)^tightness.  The
    plane is lit along the axis (N.L = 1), so a pixel is the factor."""
    worst = 0.0
    w = 121
    for radius, falloff, tight in ((2, 6, 0), (1, 8, 3)):
        scene = HEADER + """
camera { orthographic location <0, 20, 0> look_at 0
         right x * 20 up z * 20 * 3 / %d }
plane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }
light_source { <0, 10, 0> rgb 1 cylinder point_at 0
  radius %g falloff %g tightness %g }
""" % (w, radius, falloff, tight)
        status, text, rows = render(workdir, scene, w, 3)
        if status != 0:
            raise RuntimeError(text[-2000:])
        shown = []
        for i in range(w // 2, w):
            d = abs(20 * ((i + 0.5) / w - 0.5))
            measured = rows[1][i][0]
            if d >= falloff:
                ours = 0.0
            elif d <= radius:
                ours = 1.0
            else:
                ours = smoothstep((falloff - d) / (falloff - radius))
            ours *= (1 - d / falloff) ** tight if d < falloff else 0.0
            worst = max(worst, abs(measured - ours))
            if i % 6 == 0:
                shown.append("%.2f:%.4f/%.4f" % (d, measured, ours))
        print("  radius %g falloff %g tightness %g (d:povray/zRcube)" %
              (radius, falloff, tight))
        print("   ", " ".join(shown))
    print("  largest difference %.2e" % worst)
    return worst < 2e-3


def probe_brick_colours(workdir):
    """lib/scene/texture.c, zr__pigment_set_pattern: brick's default
    colours.  The manual ("Brick") only says "a default deep red and
    dark gray"; a brick pigment without colours, ambient 1, shows the
    two values."""
    scene = HEADER + """
camera { orthographic location <0, 0, -10> look_at 0 right x * 16
         up y * 12 }
plane { -z, 0 pigment { brick } finish { ambient 1 diffuse 0 } }
"""
    status, text, rows = render(workdir, scene, 32, 24)
    if status != 0:
        raise RuntimeError(text[-2000:])
    seen = {}
    for row in rows:
        for px in row:
            key = tuple(round(c, 4) for c in px)
            seen[key] = seen.get(key, 0) + 1
    found = sorted(seen, key=lambda k: -seen[k])
    print("  colours seen (pixels):",
          ", ".join("<%g, %g, %g> (%d)" % (k + (seen[k],)) for k in found))
    want = [(0.6, 0.15, 0.15), (0.5, 0.5, 0.5)]
    print("  zRcube: brick <0.6, 0.15, 0.15>, mortar <0.5, 0.5, 0.5>")
    return sorted(found) == sorted(want)


def probe_unbounded_extent(workdir):
    """lib/sdl/build_pattern.c, zr__sdl_extent: min_extent and
    max_extent of an object without finite bounds (a plane)."""
    status, values = debug_values(workdir, HEADER + """
#declare P = plane { y, 0 }
#debug concat("probe:min=", vstr(3, min_extent(P), ",", 0, -1), "\\n")
#debug concat("probe:max=", vstr(3, max_extent(P), ",", 0, -1), "\\n")
""")
    print("  min_extent %s, max_extent %s (zRcube: -1e10 and 1e10 on each"
          " axis)" % (values.get("min"), values.get("max")))
    try:
        lo = [float(v) for v in values["min"].split(",")]
        hi = [float(v) for v in values["max"].split(",")]
    except (KeyError, ValueError):
        return False
    return all(v == -1e10 for v in lo) and all(v == 1e10 for v in hi)


def probe_rounded_box_offset(workdir):
    """lib/sdl/function.c, f_rounded_box (internal 60): the distance to
    the box shrunk by the radius, less the radius, less 1e-6.  povray's
    values (#debug, 9 decimals) at points inside, near and outside the
    box are set beside the plain distance; their difference is the
    offset."""
    points = [(0, 0, 0), (0.45, 0, 0), (0.49, 0.55, 0), (-0.6, -0.7, 0.1),
              (2, 0, 0), (0.3, 0.3, 0.3), (1, 1, 1)]
    r, half = 0.1, (0.5, 0.6, 0.7)
    lines = "".join(
        '#debug concat("probe:%d=", str(f_rounded_box(%g, %g, %g, %g, '
        '%g, %g, %g), 0, 9), "\\n")\n' % ((i,) + pt + (r,) + half)
        for i, pt in enumerate(points))
    status, values = debug_values(workdir, HEADER +
                                  '#include "functions.inc"\n' + lines)
    offsets = []
    for i, pt in enumerate(points):
        d = [max(abs(c) - (h - r), 0.0) for c, h in zip(pt, half)]
        plain = math.sqrt(sum(v * v for v in d)) - r
        try:
            got = float(values[str(i)])
        except (KeyError, ValueError):
            return False
        offsets.append(plain - got)
        print("  f_rounded_box%s: povray %.9f, distance %.9f, below by "
              "%.2e" % (pt, got, plain, plain - got))
    print("  zRcube subtracts 1e-6")
    return all(abs(o - 1e-6) < 2e-9 for o in offsets)


def probe_field_clip(workdir):
    """lib/sdl/function.c, field(): internal functions with a "field
    strength" parameter are clipped to [-10, 10]; plain distances are
    not."""
    cases = [("f_paraboloid(0, 11, 0, 1)", 10.0),
             ("f_paraboloid(0, -30, 0, 1)", -10.0),
             ("f_paraboloid(0, 3, 0, 1)", None),
             ("f_sphere(20, 0, 0, 1)", 19.0)]
    lines = "".join('#debug concat("probe:%d=", str(%s, 0, 6), "\\n")\n'
                    % (i, e) for i, (e, _) in enumerate(cases))
    status, values = debug_values(workdir, HEADER +
                                  '#include "functions.inc"\n' + lines)
    ok = True
    for i, (e, want) in enumerate(cases):
        got = values.get(str(i))
        print("  %s = %s%s" % (e, got, "" if want is None else
                                " (zRcube %g)" % want))
        try:
            v = float(got)
        except (TypeError, ValueError):
            return False
        if want is not None and abs(v - want) > 1e-6:
            ok = False
        if want is None and abs(v) >= 10:
            ok = False
    return ok


def magnet_count(kind, c, iterations, bailout, settled):
    """The exterior-1 value of magnet 1 or 2 (mandel form, z0 = 0) at
    c, as lib/scene/pattern_more.c computes it with the given bailout
    (on |z|^2) and settling distance (on |z - 1|^2); 1 for interior."""
    z = 0j
    for n in range(iterations):
        if kind == 1:
            den = 2 * z + c - 2
            q = (z * z + c - 1) / den if den != 0 else 1e30
        else:
            c1, c2 = c - 1, c - 2
            den = 3 * z * z + 3 * c2 * z + c1 * c2 + 1
            q = (z ** 3 + 3 * c1 * z + c1 * c2) / den if den != 0 else 1e30
        z = q * q
        if abs(z) ** 2 > bailout or abs(z - 1) ** 2 < settled:
            return n / iterations
    return 1.0


def probe_magnet_limits(workdir):
    """lib/scene/pattern_more.c, MAGNET_BAILOUT and MAGNET_SETTLED: a
    magnet orbit escapes when |z|^2 exceeds 1e4 or it comes within 0.01
    of the fixed point 1 (|z - 1|^2 < 1e-4).  povray's exterior counts
    (function { pattern { magnet N mandel 30 } }, #debug) on a grid of
    points are compared with the iteration run for a range of both
    limits; the probe prints which limits reproduce every value."""
    pts = [(-2 + 0.37 * i, -1.6 + 0.29 * j) for i in range(14)
           for j in range(12)]
    pts += [(1.2 + 0.13 * k, 0.3 + 0.07 * k) for k in range(12)]
    got = {}
    for kind in (1, 2):
        lines = "".join(
            '#debug concat("probe:%d=", str(F(%g, %g, 0), 0, 9), "\\n")\n'
            % (i, x, y) for i, (x, y) in enumerate(pts))
        status, values = debug_values(
            workdir, HEADER + "#declare F = function { pattern { magnet %d "
            "mandel 30 } }\n" % kind + lines)
        try:
            got[kind] = [float(values[str(i)]) for i in range(len(pts))]
        except (KeyError, ValueError):
            print("  povray gave no values")
            return False
    bailouts = [4, 100, 1000, 2000, 3000, 5000, 1e4, 2e4, 1e5, 1e6]
    settles = [0, 1e-6, 1e-5, 1e-4, 1e-3, 1e-2]
    fits = []
    for b in bailouts:
        for st in settles:
            bad = 0
            for kind in (1, 2):
                for (x, y), v in zip(pts, got[kind]):
                    ours = magnet_count(kind, complex(x, y), 30, b, st)
                    if abs(ours - v) > 1e-6 and abs(ours % 1.0 - v) > 1e-6:
                        bad += 1
            if bad == 0:
                fits.append((b, st))
    print("  %d points x 2 kinds; limits (|z|^2 bailout, |z-1|^2 settle) "
          "that reproduce all of povray's values:" % len(pts))
    print("   ", ", ".join("(%g, %g)" % f for f in fits) or "none")
    print("  zRcube: (1e4, 1e-4)")
    return (1e4, 1e-4) in fits


def omnimax_direction(a, u, v, curve, widest):
    """The unit ray (right, up, direction parts) of lib/trace/camera.c's
    omnimax at image point (u, v), or None where it shoots none."""
    span = 1.0 if a < 1.0 else min(a, widest)
    r90, v0 = 0.5 * min(a, span), -0.5 * (span - 1.0)
    x, y = u * a, v - v0
    r = math.hypot(x, y)
    rho = r / r90
    if rho > 1.0:
        return None
    theta = rho * (curve[0] + rho * rho * (curve[1] + rho * rho * curve[2]))
    cx, cy = (x / r, y / r) if r > 0 else (0.0, 0.0)
    if math.sin(theta) * cy + math.cos(theta) < 0:
        return None
    return (math.sin(theta) * cx, math.sin(theta) * cy, math.cos(theta))


def probe_omnimax_curve(workdir):
    """lib/trace/camera.c, OMNIMAX_CURVE and OMNIMAX_WIDEST: the
    omnimax lens curve theta(rho) = 1.411284 rho - 0.094448 rho^3 +
    0.256789 rho^5 and the widest aspect 1.28344.  The camera sits in a
    unit sphere whose colour is its point, that is the ray's direction
    (three renders, one per axis); every pixel's povray direction is
    set beside ours, and the odd quintic is fitted again to povray's
    (rho, theta) pairs."""
    curve, widest = (1.411284, -0.094448, 0.256789), 1.28344
    w, h = 64, 48
    worst, mask_bad, pairs = 0.0, 0, []
    for right in (1.33, 0.75, 1.0, 1.2, 2.0):
        chans = []
        for axis in "xyz":
            scene = HEADER + """
camera { omnimax location 0 direction z right x * %g up y }
sphere { 0, 1 hollow
  pigment { function { %s * 0.5 + 0.5 } color_map { [0 rgb 0] [1 rgb 1] } }
  finish { ambient 1 diffuse 0 } }
""" % (right, axis)
            status, text, rows = render(workdir, scene, w, h)
            if status != 0:
                raise RuntimeError(text[-2000:])
            chans.append(rows)
        a = right / 1.0
        for j in range(h):
            for i in range(w):
                px = [chans[k][j][i][0] * 2 - 1 for k in range(3)]
                shot = abs(math.sqrt(sum(c * c for c in px)) - 1) < 0.01
                u, v = (i + 0.5) / w - 0.5, 0.5 - (j + 0.5) / h
                ours = omnimax_direction(a, u, v, curve, widest)
                if (ours is not None) != shot:
                    mask_bad += 1
                    continue
                if ours is None:
                    continue
                dot = sum(p * q for p, q in zip(px, ours))
                dot /= math.sqrt(sum(c * c for c in px))
                worst = max(worst, math.degrees(math.acos(min(1.0, dot))))
                if right == 1.33:
                    span = min(a, widest)
                    r90, v0 = 0.5 * span, -0.5 * (span - 1.0)
                    rho = math.hypot(u * a, v - v0) / r90
                    pairs.append((rho, math.acos(max(-1.0, min(1.0,
                                                               px[2])))))
    # Least squares for theta = c1 rho + c3 rho^3 + c5 rho^5.
    m = [[0.0] * 3 for _ in range(3)]
    rhs = [0.0] * 3
    for rho, theta in pairs:
        basis = (rho, rho ** 3, rho ** 5)
        for r_ in range(3):
            rhs[r_] += basis[r_] * theta
            for c_ in range(3):
                m[r_][c_] += basis[r_] * basis[c_]
    for col in range(3):  # Gauss-Jordan on the 3 x 3 system
        piv = m[col][col]
        for c_ in range(3):
            m[col][c_] /= piv
        rhs[col] /= piv
        for r_ in range(3):
            if r_ != col:
                f = m[r_][col]
                for c_ in range(3):
                    m[r_][c_] -= f * m[col][c_]
                rhs[r_] -= f * rhs[col]
    print("  pixels whose ray/no-ray differs: %d; largest angle between "
          "povray's and our rays: %.4f degrees" % (mask_bad, worst))
    print("  fit to povray (right 1.33, %d pixels): theta = %.6f rho %+.6f "
          "rho^3 %+.6f rho^5" % ((len(pairs),) + tuple(rhs)))
    print("  zRcube: theta = 1.411284 rho - 0.094448 rho^3 + 0.256789 rho^5,"
          " widest aspect 1.28344")
    return mask_bad == 0 and worst < 0.02


ZRCUBE = os.environ.get("ZRCUBE") or os.path.join(
    os.path.dirname(os.path.abspath(__file__)), "..", "..", "build", "bin",
    "zrcube")

PATCH_VIEWS = [
    "camera { location <1.5, 1.5, -6> look_at <1.5, 1.5, 0> }\n"
    "light_source { <-5, 10, -10> rgb 1 }",
    "camera { location <-3, 5, -4> look_at <1.5, 1.5, 0> angle 50 }\n"
    "light_source { <8, 2, -3> rgb 1 }",
]

PATCH_SCENE = HEADER + """%s
bicubic_patch { type 1 flatness %g u_steps %d v_steps %d
  <0, 0, 2>, <1, 0, 0>, <2, 0, 0>, <3, 0,-2>,
  <0, 1, 0>, <1, 1, 0>, <2, 1, 0>, <3, 1, 0>,
  <0, 2, 0>, <1, 2, 0>, <2, 2, 0>, <3, 2, 0>,
  <0, 3, 2>, <1, 3, 0>, <2, 3, 0>, <3, 3, -2>
  pigment { rgb 1 } finish { ambient 0 diffuse 1 } }
"""


def render_zrcube(workdir, scene, width, height):
    pov = os.path.join(workdir, "z.pov")
    out = os.path.join(workdir, "z.ppm")
    with open(pov, "w") as f:
        f.write(scene)
    r = subprocess.run([ZRCUBE, "+I" + pov, "+O" + out, "+W%d" % width,
                        "+H%d" % height, "-D", "+WT1"], cwd=workdir,
                       capture_output=True, text=True, timeout=120)
    if r.returncode != 0:
        raise RuntimeError(r.stderr[-2000:])
    return read_ppm16(out)


def patch_steps(draw, view):
    """For flatness 0.3, 0.1, 0.03 and 0.01 (u_steps = v_steps = 8 as
    the limit), the uniform u_steps = v_steps (flatness 0) whose render
    is nearest (mean absolute difference) to the adaptive one."""
    def flat(rows):
        return [c for row in rows for px in row for c in px]

    def diff(a, b):
        return sum(abs(x - y) for x, y in zip(a, b)) / len(a)
    uniform = {n: flat(draw(PATCH_SCENE % (view, 0, n, n)))
               for n in range(1, 8)}
    steps = []
    for f in (0.3, 0.1, 0.03, 0.01):
        im = flat(draw(PATCH_SCENE % (view, f, 8, 8)))
        d = {n: diff(im, uniform[n]) for n in uniform}
        steps.append(min(d, key=d.get))
    return steps


def probe_patch_flatness(workdir):
    """lib/sdl/build_surface.c, patch_tolerance: a bicubic patch piece
    is flat enough when its control points lie within flatness / 20 of
    the patch's size from its plane.  The manual only says that smaller
    flatness subdivides more ("Bicubic Patch").  On two views of the
    manual's patch, each flatness is matched to the uniform subdivision
    it looks like, for povray and (when built) for zRcube; the scale
    1/20 makes the two agree."""
    def pov(scene):
        status, text, rows = render(workdir, scene, 160, 120)
        if status != 0:
            raise RuntimeError(text[-2000:])
        return rows
    ok = True
    for k, view in enumerate(PATCH_VIEWS):
        theirs = patch_steps(pov, view)
        print("  view %d: flatness 0.3, 0.1, 0.03, 0.01 look like uniform "
              "steps %s in povray" % (k + 1, theirs))
        if os.path.exists(ZRCUBE):
            ours = patch_steps(
                lambda sc: render_zrcube(workdir, sc, 160, 120), view)
            print("          and %s in zRcube (%s)" %
                  (ours, os.path.normpath(ZRCUBE)))
            ok = ok and ours == theirs
        else:
            print("          (no zRcube at %s: povray only)" % ZRCUBE)
    return ok


def probe_rainbow_falloff(workdir):
    """lib/trace/atmosphere.c, apply_rainbow: a rainbow arc fades
    between falloff_angle / 2 and arc_angle / 2 (around its direction,
    from up) by the smoothstep 3 t^2 - 2 t^3, t going from 1 to 0.  A
    white rainbow over a black sky, seen along its direction; each
    pixel in the middle of the band is its weight."""
    w, h = 96, 72
    worst, shown = 0.0, {}
    for arc, falloff in ((180, 60), (300, 100)):
        scene = HEADER + """
camera { location 0 direction z right x * 1.33 up y }
background { rgb 0 }
rainbow { angle 20 width 10 distance 1e7 direction <0, 0, 1> up y
  arc_angle %g falloff_angle %g
  color_map { [0 rgb 1] [1 rgb 1] } }
""" % (arc, falloff)
        status, text, rows = render(workdir, scene, w, h)
        if status != 0:
            raise RuntimeError(text[-2000:])
        for j in range(h):
            for i in range(w):
                u, v = (i + 0.5) / w - 0.5, 0.5 - (j + 0.5) / h
                x, y, z = u * 1.33, v, 1.0
                a = math.degrees(math.acos(z / math.sqrt(x * x + y * y + 1)))
                if abs(a - 20) > 3:
                    continue
                phi = math.degrees(math.atan2(abs(x), y))
                if phi > arc / 2:
                    ours = 0.0
                elif phi > falloff / 2:
                    ours = smoothstep(1 - (phi - falloff / 2) /
                                      (0.5 * (arc - falloff)))
                else:
                    ours = 1.0
                got = rows[j][i][0]
                worst = max(worst, abs(got - ours))
                bucket = int(phi // 15)
                if bucket not in shown:
                    shown[bucket] = "%.0f:%.4f/%.4f" % (phi, got, ours)
        print("  arc %g falloff %g (phi:povray/zRcube)" % (arc, falloff))
        print("   ", " ".join(shown[k] for k in sorted(shown)))
        shown = {}
    print("  largest difference %.2e" % worst)
    return worst < 2e-3


def probe_normal_amount(workdir):
    """lib/sdl/build.c, zr__sdl_normal_pattern: a normal pattern
    written without an amount has bump size 0.5.  For several patterns
    a lit plane with "normal { PATTERN }" is compared byte for byte
    with "PATTERN 0.5" and "PATTERN 0.4"."""
    def image(normal):
        scene = HEADER + """
camera { location <0, 3, -4> look_at 0 }
light_source { <-3, 6, -5> rgb 1 }
plane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 0.8 phong 0.5 }
  normal { %s scale 0.7 } }
""" % normal
        status, text, rows = render(workdir, scene, 48, 36)
        if status != 0:
            raise RuntimeError(text[-2000:])
        return rows
    ok = True
    for pattern, after in (("bumps", ""), ("ripples", ""), ("wood", ""),
                           ("leopard", ""), ("gradient x", ""),
                           ("granite", "")):
        plain = image(pattern + after)
        half = image(pattern + " 0.5" + after) == plain
        other = image(pattern + " 0.4" + after) == plain
        print("  %-10s default %s 0.5, %s 0.4" %
              (pattern, "==" if half else "!=", "==" if other else "!="))
        ok = ok and half and not other
    return ok


def probe_reflection_exponent(workdir):
    """lib/trace/shade.c, reflection: with reflection { r exponent e }
    the reflected colour c counts as r * c^(1/e) (the manual only says
    lower exponents darken middle and low intensities).  A black mirror
    (no ambient, no diffuse) seen from above reflects a grey sky L."""
    worst = 0.0
    for r, e, sky in ((1, 0.5, 0.3), (1, 2, 0.3), (0.5, 2, 0.6),
                      (0.7, 0.7, 0.8), (0.4, 3, 0.05)):
        scene = HEADER + """
camera { location <0, 1, -1> look_at 0 }
background { rgb %g }
plane { y, 0 pigment { rgb 0 } finish { ambient 0 diffuse 0
  reflection { %g exponent %g } } }
""" % (sky, r, e)
        status, text, rows = render(workdir, scene, 4, 4)
        if status != 0:
            raise RuntimeError(text[-2000:])
        got = rows[3][1][1]
        ours = r * sky ** (1 / e)
        worst = max(worst, abs(got - ours))
        print("  reflection %g exponent %g, sky %g: povray %.5f, "
              "r c^(1/e) %.5f, (r c)^(1/e) %.5f" %
              (r, e, sky, got, ours, (r * sky) ** (1 / e)))
    return worst < 1e-3


def ovus_extent(a, b, k, y):
    """The distance from the y axis of lib/sdl/build_iso.c's ovus
    surface at height y, with lemon radius R = k max(a, b)."""
    r = k * max(a, b)
    h = ((r - a) ** 2 - (r - b) ** 2 + a * a) / (2 * a)
    c = math.sqrt(max(0.0, (r - a) ** 2 - h * h))
    y0 = -h * a / (r - a)
    y1 = h + r * (a - h) / (r - b)
    if y < y0:
        return math.sqrt(max(0.0, a * a - y * y))
    if y > y1:
        return math.sqrt(max(0.0, b * b - (y - a) ** 2))
    return math.sqrt(max(0.0, r * r - (y - h) ** 2)) - c


def probe_ovus_lemon(workdir):
    """lib/sdl/build_iso.c, zr__sdl_ovus: the lemon joining an ovus's
    spheres is the circle of radius 2 max(a, b) tangent inside both
    (the manual: "automatically computed").  trace() along -x onto
    ovus objects of several radius ratios, at heights through the
    lemon; the probe prints which multiplier k of R = k max(a, b) fits
    every distance."""
    shapes = [(1, 0.6), (1, 1.5), (0.8, 0.3), (1, 1)]
    ks = [1.5, 1.75, 2, 2.25, 2.5, 3]
    lines, cases = "", []
    for a, b in shapes:
        top = a + b
        for j in range(1, 12):
            y = -a + (top + a) * j / 12
            lines += ('#declare O = ovus { %g, %g }\n#declare N = <0, 0, 0>;'
                      '\n#declare P = trace(O, <5, %g, 0>, <-1, 0, 0>, N);\n'
                      '#debug concat("probe:%d=", str(P.x, 0, 9), "\\n")\n'
                      % (a, b, y, len(cases)))
            cases.append((a, b, y))
    status, values = debug_values(workdir, HEADER + lines)
    try:
        got = [float(values[str(i)]) for i in range(len(cases))]
    except (KeyError, ValueError):
        print("  povray gave no values")
        return False
    # povray's trace() misses an ovus of equal radii exactly at the seams
    # (it returns <0, 0, 0>): those rays say nothing about the lemon.
    missed = [i for i, v in enumerate(got) if v == 0.0]
    if missed:
        print("  povray's trace() missed at %s: left out" % ", ".join(
            "ovus {%g, %g} y = %g" % cases[i] for i in missed))
    fits = []
    for k in ks:
        worst = 0.0
        for i, (a, b, y) in enumerate(cases):
            if i not in missed:
                worst = max(worst, abs(got[i] - ovus_extent(a, b, k, y)))
        print("  R = %g max(a, b): largest difference %.2e" % (k, worst))
        if worst < 1e-4:
            fits.append(k)
    print("  %d traces on ovus %s; zRcube: R = 2 max(a, b)" %
          (len(cases), ", ".join("{%g, %g}" % s for s in shapes)))
    return fits == [2]


PROBES = [
    ("image_map_index", probe_image_map_index),
    ("media_defaults", probe_media_defaults),
    ("spotlight_curve", probe_spotlight_curve),
    ("cylinder_curve", probe_cylinder_curve),
    ("brick_colours", probe_brick_colours),
    ("unbounded_extent", probe_unbounded_extent),
    ("rounded_box_offset", probe_rounded_box_offset),
    ("field_clip", probe_field_clip),
    ("magnet_limits", probe_magnet_limits),
    ("omnimax_curve", probe_omnimax_curve),
    ("patch_flatness", probe_patch_flatness),
    ("rainbow_falloff", probe_rainbow_falloff),
    ("normal_amount", probe_normal_amount),
    ("reflection_exponent", probe_reflection_exponent),
    ("ovus_lemon", probe_ovus_lemon),
]


def main(argv):
    if "--list" in argv:
        for name, fn in PROBES:
            print("%-18s %s" % (name, fn.__doc__.split(":")[0].strip()))
        return 0
    if not POVRAY or not os.path.exists(POVRAY):
        print("povray not found: probes skipped")
        return 77
    names = [a for a in argv if not a.startswith("-")]
    unknown = [n for n in names if n not in dict(PROBES)]
    if unknown:
        print("unknown probe(s): %s (see --list)" % ", ".join(unknown))
        return 2
    passed = failed = 0
    for name, fn in PROBES:
        if names and name not in names:
            continue
        print("%s: %s" % (name, fn.__doc__.split(":")[0].strip()))
        with tempfile.TemporaryDirectory(prefix="zr-probe-") as workdir:
            try:
                ok = fn(workdir)
            except (RuntimeError, subprocess.TimeoutExpired) as e:
                print("  povray failed: %s" % e)
                ok = False
        print("  %s" % ("agrees" if ok else "DIFFERS"))
        passed += ok
        failed += not ok
    print("%d passed, %d failed" % (passed, failed))
    return 0 if failed == 0 else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
