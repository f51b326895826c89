#!/bin/sh
# test_interior_path.sh - a ray's path of media is a list of interiors:
# where it meets a surface it goes out of the part's interior if its
# path holds it, else into it, whichever side of the surface it meets
# (lib/trace/shade.c zr__media_cross).  tests/interior_path.pov: a glass
# half-sphere open at the back (clipped_by), so that a ray goes in
# through its surface and out through the cut where no surface is, and
# a sphere behind it.  povray 3.7 (pixels recorded below, 16x12; at
# 160x120 every case renders with 0 pixels more than 8 levels off):
#  1 two objects, two interiors: the sphere behind is entered (n 1.5 ->
#    1.2, the path still holds the half-sphere);
#  2 a merge of both with one interior, 3 the same union: the sphere
#    behind is met from outside but its interior is the path's, so the
#    ray goes out of the glass there (the old rule, "from outside always
#    in", bent nothing there: 166 levels off; advanced/wineglass.pov's
#    rim on its bowl);
#  4 interior { I } twice of one declared I: two interiors (in again);
#  5 a union, 6 a merge, whose parts have interiors of their own: in
#    again (deciding by the merge object, as the path did, went out);
#  7 a union of two overlapping closed spheres with one interior: out
#    where the ray meets the second from inside the first (255 off);
#  8 the same spheres as two copies of one declared sphere: two
#    interiors, in again (copies shared the interior: 255 off).
#
# Environment: ZR_SRCDIR, ZR_BUILDDIR (set by `make check`).
set -u
. "${ZR_SRCDIR:-$(cd "$(dirname "$0")/.." && pwd)}/tests/render_env.sh"
recorded_1="0,7=255,255,255 2,3=255,255,255 3,9=255,255,255 5,6=89,149,231 8,3=255,255,255 11,6=255,255,255"
recorded_2="0,5=89,149,231 3,2=89,149,231 5,2=89,149,231 7,3=89,149,231 8,13=255,255,255 11,10=255,255,255"
recorded_3="0,5=89,149,231 3,2=89,149,231 5,2=89,149,231 7,3=89,149,231 8,13=255,255,255 11,10=255,255,255"
recorded_4="0,5=255,255,255 3,2=255,255,255 5,2=255,255,255 7,3=255,255,255 8,13=89,149,231 11,10=89,149,231"
recorded_5="0,5=255,255,255 3,2=255,255,255 5,2=255,255,255 7,3=255,255,255 8,13=89,149,231 11,10=89,149,231"
recorded_6="0,5=255,255,255 3,2=255,255,255 5,2=255,255,255 7,3=255,255,255 8,13=89,149,231 11,10=89,149,231"
recorded_7="0,3=255,255,255 3,4=89,149,231 5,5=255,255,255 7,5=255,255,255 9,4=255,255,255 11,8=0,0,0"
recorded_8="0,3=0,0,0 3,4=0,0,0 5,5=0,0,0 7,5=0,0,0 9,4=89,149,231 11,8=255,255,255"
pixel_cases "$srcdir/tests/interior_path.pov" Case "1 2 3 4 5 6 7 8"
