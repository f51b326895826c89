#!/bin/sh
# test_camera_normal.sh - a camera's normal { } (tests/camera_normal.pov):
# povray 3.7 takes the pattern at the point (u, v, 0) of the screen
# (u, v from -0.5 to 0.5, whatever the camera's place and aim) and tilts
# each ray as it would tilt a surface normal, in world axes.  The scene
# paints each ray's direction; seven pixels of each case (a plain
# camera, x*x and y*y slopes, a camera turned to +x, bumps on a moved
# camera) are povray's 16x12 values, recorded below (povray 3.7.0.10,
# -A +WT1 -GA); each channel must be within 2 levels.  Before, the
# pattern was taken one unit along the ray from the camera: 7 to 55
# levels off in cases 1, 3 and 4, and camera/normal.pov scored SSIM 0.65.
# With povray installed the whole pictures are compared too.
#
# Environment: ZR_SRCDIR, ZR_BUILDDIR (set by `make check`).
set -u
. "${ZR_SRCDIR:-$(cd "$(dirname "$0")/.." && pwd)}/tests/render_env.sh"
[ -x /usr/bin/python3 ] || { echo "no /usr/bin/python3: skipped"; exit 77; }
px="0,0 0,15 6,8 11,0 11,15 3,4 8,11"
recorded_0="138,215,243 224,215,243 191,184,255 138,153,243 224,153,243 162,203,252 209,170,252"
recorded_1="178,219,249 196,219,249 188,184,255 178,148,250 196,148,250 179,204,254 195,170,254"
recorded_2="133,184,246 227,184,246 191,187,255 133,190,246 227,190,246 162,189,253 209,185,253"
recorded_3="243,226,212 236,208,110 253,184,165 250,163,210 239,151,127 253,208,193 248,168,145"
recorded_4="115,218,234 220,210,247 171,201,253 132,136,236 226,147,240 123,213,239 208,174,252"
pixel_cases "$srcdir/tests/camera_normal.pov" Case "0 1 2 3 4" "$px"
