#!/usr/bin/python3
"""gi_record_probe.py - how many irradiance-cache records POV-Ray 3.7 makes
in each pretrace pass, against the radiosity block's settings.

The scene: a plane of diffuse grey under a white sky_sphere, seen straight
down by an orthographic camera 10 units above it (every pixel at one
distance, 4 x 3 units across 160 x 120 pixels), so that each record's
harmonic mean distance is infinite and its reuse radius is maximum_reuse
times 10.  povray +V prints the records of each pass ("Pass  Depth 0");
with --zrcube the same scene is rendered by zRcube and its total
(the statistics line of -V) printed beside.

usage: bench/gi_record_probe.py [--zrcube BIN] [--reflectance] NAME=VALUE,... [...]
  names: PIG (the plane's grey, 0.5), CAM (0: orthographic, 1:
  pneumaticBoat's), EB (error_bound 0.2), NC (nearest_count 9), NC2 (its second
  value, 0 none), LEF (low_error_factor 0.5), MAXR (maximum_reuse 0.2),
  MINR (minimum_reuse 0.015), PS / PE (pretrace_start / _end in pixels,
  64 / 2), COUNT (50), AS (always_sample, 0).
Each argument is one setting; it prints one line: the setting, povray's
records per pass and total, and zRcube's total.
"""
import os, re, subprocess, sys, tempfile

SCENE = r'''
global_settings { assumed_gamma 1.0
  radiosity { pretrace_start PS/image_width pretrace_end PE/image_width
    count COUNT nearest_count NC #if (NC2 > 0) , NC2 #end
    error_bound EB low_error_factor LEF recursion_limit 1
    maximum_reuse MAXR minimum_reuse MINR always_sample AS } }
#if (CAM = 0)
camera { orthographic location <0, 10, 0> look_at <0, 0, 0>
         right x*4 up y*3 }
#else
camera { location <1, 5, -4> look_at <0, 2, 0> }
#end
sky_sphere { pigment { rgb 1 } }
plane { y, 0 pigment { rgb PIG } finish { diffuse 0.6 ambient 0 } }
'''

DEFAULTS = dict(EB=0.2, NC=9, NC2=0, LEF=0.5, MAXR=0.2, MINR=0.015, PS=64,
                PE=2, COUNT=50, AS=0, PIG=0.5, CAM=0)

# --reflectance: the settings the dark-surface rule of lib/gi/cache.c
# (REFLECTANCE_FULL, REFLECTANCE_GROWTH) was fitted to: pneumaticBoat's
# camera over a sky-lit plane of diffuse 0.6 and grey PIG.  povray
# 3.7 (2026-12-03), records in all: PIG 0.5: NC 1 3179, NC 9 6379;
# PIG 0.2: NC 1 882, NC 3 1139, NC 9 3207; PIG 0.05: NC 1 495, NC 3 779,
# NC 9 1751; PIG 0.02: NC 9 1595.  The error_bound that gives PIG 0.2's
# count at PIG 0.5 is about 0.48 (EB 0.4: 3614 + 406, 0.6: 1571 + 406),
# 2.4 times 0.2 for 2.5 times less reflectance.
REFLECTANCE = ["CAM=1,PIG=%s,NC=%s" % (g, n) for g in ("0.5", "0.2", "0.05",
               "0.02") for n in ("1", "3", "9")] + \
              ["CAM=1,EB=%s" % e for e in ("0.3", "0.4", "0.6")]


def povray(settings, d):
    decl = "".join("#declare %s = %s;\n" % kv for kv in settings.items())
    path = os.path.join(d, "p.pov")
    with open(path, "w") as f:
        f.write(decl + SCENE)
    out = subprocess.run(["povray", "+W160", "+H120", "-D", "-A", "+WT1",
                          "+V", "+Ip.pov", "+O" + os.path.join(d, "p.png")],
                         cwd=d, capture_output=True, text=True).stderr
    passes = re.findall(r"^\s+(\d\+?|Final)\s+(\d+)\s+\d+\s*$", out, re.M)
    return passes


def zrcube(binary, d):
    out = subprocess.run([binary, "+W160", "+H120", "-D", "-A", "+WT1",
                          "+V", "+Ip.pov", "+O" + os.path.join(d, "z.png")],
                         cwd=d, capture_output=True, text=True).stderr
    m = re.search(r"irradiance cache: (\d+) records", out)
    return m.group(1) if m else "?"


def main(argv):
    binary = None
    if len(argv) > 1 and argv[0] == "--zrcube":
        binary, argv = os.path.abspath(argv[1]), argv[2:]
    if argv and argv[0] == "--reflectance":
        argv = argv[1:] + REFLECTANCE
    with tempfile.TemporaryDirectory() as d:
        for arg in argv or [""]:
            s = dict(DEFAULTS)
            for kv in filter(None, arg.split(",")):
                k, v = kv.split("=")
                s[k] = v
            passes = povray(s, d)
            line = "%-40s povray %s total %d" % (
                arg or "defaults",
                " ".join("%s:%s" % p for p in passes),
                sum(int(n) for _, n in passes))
            if binary:
                line += "  zrcube %s" % zrcube(binary, d)
            print(line, flush=True)


if __name__ == "__main__":
    main(sys.argv[1:])
