#!/bin/sh
# Black-box measurements of the pattern warps (issue 17): the point a
# pattern sees after each warp, as a renderer computes it.
#
# Usage: bench/warp_probe.sh [RENDERER]      (default: povray)
#
# RENDERER is povray or a zrcube binary.  For each case a scene is made
# whose three pattern functions read back the warped point,
#   function { pattern { function { 0.5 + x / S } warp { ... } } }
# (and the same for y and z; S keeps the value inside [0, 1), where a
# function pattern returns it unchanged: outside it wraps), and
# `#write` prints, per probe point P, a line
#   CASE  P.x P.y P.z  ->  W.x W.y W.z
# where W is the warped point.  lib/scene/warp.c cites the lines it
# takes its rules from, and tests/test_warp.sh compares both renderers
# on all of them.
set -u
renderer=${1:-povray}
case $renderer in */*) renderer=$(cd "$(dirname "$renderer")" &&
    pwd)/$(basename "$renderer") ;; esac
tmp=$(mktemp -d "${TMPDIR:-/tmp}/zr_warp_probe.XXXXXX") || exit 1
trap 'rm -rf "$tmp"' EXIT

# probe NAME SCALE 'WARP...' 'point1' 'point2' ...
probe() {
    name=$1 scale=$2 warp=$3
    shift 3
    f=$tmp/$name.pov
    {
        echo '#version 3.7;'
        echo 'global_settings { assumed_gamma 1 }'
        for c in x y z; do
            echo "#declare F$c = function { pattern {"
            echo "  function { 0.5 + $c / $scale } $warp } }"
        done
        echo '#fopen Out "'"$name.txt"'" write'
        echo '#macro Show(P)'
        echo ' #write(Out, "'"$name"' ", vstr(3, P, " ", 0, 6), " -> ",'
        echo '   str((Fx(P.x, P.y, P.z) - 0.5) * '"$scale"', 0, 9), " ",'
        echo '   str((Fy(P.x, P.y, P.z) - 0.5) * '"$scale"', 0, 9), " ",'
        echo '   str((Fz(P.x, P.y, P.z) - 0.5) * '"$scale"', 0, 9), "\n")'
        echo '#end'
        for p in "$@"; do
            echo "Show(<$p>)"
        done
        echo '#fclose Out'
        echo 'camera { location -z look_at 0 }'
        echo 'sphere { 0, 1 pigment { rgb 1 } }'
    } > "$f"
    rm -f "$tmp/$name.txt"
    case $renderer in
    *povray*)
        ( cd "$tmp" && timeout 30 "$renderer" +I"$f" -D +W1 +H1 -F \
            >/dev/null 2>&1 )
        ;;
    *)
        ( cd "$tmp" && timeout 30 "$renderer" +I"$f" --parse-only -q \
            >/dev/null 2>&1 )
        ;;
    esac
    if [ -s "$tmp/$name.txt" ]; then
        cat "$tmp/$name.txt"
    else
        echo "$name failed"
    fi
}

# Repeat (manual: "Repeat Warp"): blocks along x, offset, flip, a
# negative width, and flips of the repeat axis itself.
probe repeat 1000 'warp { repeat 2*x }' \
    '0.5,0.25,0.125' '2.5,0.25,0.125' '-0.5,0.25,0.125' '-2.5,0.25,0.125' \
    '4,0,0' '-4,0,0' '1.999,0,0'
probe repeat_offset 1000 'warp { repeat 2*x offset <0.1,0.2,0.3> }' \
    '0.5,1,1' '2.5,1,1' '4.5,1,1' '-1.5,1,1' '-3.5,1,1'
probe repeat_flip_yz 1000 'warp { repeat 2*x flip <0,1,1> }' \
    '0.5,0.25,0.125' '2.5,0.25,0.125' '4.5,0.25,0.125' \
    '-1.5,0.25,0.125' '-3.5,0.25,0.125'
probe repeat_flip_x 1000 'warp { repeat 2*x flip x }' \
    '0.5,0.25,0.125' '2.5,0.25,0.125' '3.5,0.25,0.125' \
    '-1.5,0.25,0.125' '-0.5,0.25,0.125' '4.5,0,0'
probe repeat_flip_offset 1000 \
    'warp { repeat 2*x flip <1,1,0> offset <0.1,0.2,0.3> }' \
    '0.5,0.25,0.125' '2.5,0.25,0.125' '-1.5,0.25,0.125'
probe repeat_neg 1000 'warp { repeat -2*y }' \
    '0,0.5,0' '0,2.5,0' '0,-0.5,0' '0,-2.5,0'
probe repeat_neg_flip 1000 'warp { repeat -2*y flip y offset x }' \
    '0,0.5,0' '0,2.5,0' '0,-0.5,0' '0,-2.5,0' '0,-4.5,0'
probe repeat_z 1000 'warp { repeat 0.5*z flip <1,0,1> }' \
    '0.25,0.5,0.1' '0.25,0.5,0.6' '0.25,0.5,-0.1'
# Far from the origin: 2^24 + 1.5 widths.
probe repeat_far 8 'warp { repeat x }' \
    '16777217.5,0,0' '16777216.5,0,0' '1000000.25,0,0' \
    '100000000.5,0,0'

# Black hole ("Black Hole Warp"): along a line through the centre.
probe hole 1000 'warp { black_hole <1,0,0>, 2 }' \
    '1,0,0' '1.5,0,0' '2,0,0' '2.5,0,0' '3,0,0' '3.5,0,0' \
    '1,1,0' '0,0,0' '-0.5,0,0'
probe hole_falloff 1000 'warp { black_hole 0, 1 falloff 1 strength 0.5 }' \
    '0.25,0,0' '0.5,0,0' '0.75,0,0' '0,0,0.5'
probe hole_strong 1000 'warp { black_hole 0, 1 strength 3 }' \
    '0.1,0,0' '0.25,0,0' '0.5,0,0' '0.75,0,0'
probe hole_inverse 1000 'warp { black_hole 0, 1 inverse }' \
    '0.25,0,0' '0.5,0,0' '0.75,0,0' '0,-0.5,0'
probe hole_inverse_strong 1000 \
    'warp { black_hole 0, 1 strength 4 inverse }' \
    '0.25,0,0' '0.5,0,0' '0.75,0,0'
probe hole_falloff0 1000 'warp { black_hole 0, 1 falloff 0 }' \
    '0.25,0,0' '0.9,0,0' '1.1,0,0'
# Repeated: the spacing and the centre adjusted (manual: "it will be
# increased"), blocks on both sides of 0.
probe hole_repeat 1000 'warp { black_hole <0.5,0,0>, 1 repeat <3,0,0> }' \
    '0.5,0,0' '1,0,0' '2,0,0' '2.5,0,0' '3.5,0,0' '4,0,0' '-2,0,0' \
    '-1,0,0'
probe hole_repeat_ok 1000 \
    'warp { black_hole <1.5,1.5,0>, 1 repeat <4,4,0> }' \
    '2,1.5,0' '6,1.5,0' '2,5.5,0' '-2,-2.5,0' '2,1.5,7'

# Planar ("Mapping using warps").
probe planar 1000 'warp { planar }' \
    '0.3,0.2,0.1' '-1,2,5'
probe planar_y 1000 'warp { planar y, 0.5 }' \
    '0.3,0.2,0.1' '-1,2,5' '2,-3,4'
probe planar_n 1000 'warp { planar <1,2,3>, 0.25 }' \
    '0.3,0.2,0.1' '-1,2,5'

# Cylindrical: angle about y, height, distance from the y axis.
probe cyl 1000 'warp { cylindrical }' \
    '1,0.3,0' '0,0.3,1' '-1,0.3,0' '0,0.3,-1' '1,0.3,1' '1,0.3,-1' \
    '2,-0.7,0' '-2,0.1,-0.0001' '-2,0.1,0.0001' '0,5,0' \
    '1,0.3,-0.000000001'
probe cyl_exp 1000 'warp { cylindrical dist_exp 1 }' \
    '1,0.3,0' '0,0.3,1' '0,0.3,2' '-3,0.3,0' '0,0.3,-0.5'
probe cyl_exp2 1000 'warp { cylindrical dist_exp 2.5 }' \
    '0,0.3,2' '-0.5,-1,0'

# Spherical: longitude, latitude, distance from the origin.
probe sph 1000 'warp { spherical }' \
    '1,0,0' '0,0,1' '-1,0,0' '0,0,-1' '1,1,0' '1,-1,0' '0,2,0' \
    '0,-2,0' '0,0,0' '2,1,-1' '0,0.0001,0' '0,-3,0.000001'
probe sph_exp 1000 'warp { spherical dist_exp 1 }' \
    '2,0,0' '0,0,2' '1,1,1' '0,3,0'

# Toroidal: angle about y, angle about the tube, distance from the
# ring of radius major_radius.
probe tor 1000 'warp { toroidal }' \
    '2,0,0' '1,1,0' '0.5,0,0' '1,-1,0' '0,0,1.5' '0,0.5,-1' \
    '1,0,0' '0,0,0' '0,3,0' '-1.5,0.25,0.25'
probe tor_r 1000 'warp { toroidal major_radius 2 dist_exp 1 }' \
    '3,0,0' '2,0.5,0' '1,0,0' '0,-1,2' '2,0,0'

# Orientation: the (u, v, distance) point sent along other axes.
probe sph_ox 1000 'warp { spherical orientation x }' \
    '1,0,0' '0,0,1' '1,1,0' '2,1,-1' '0,-1,0.5'
probe sph_oy 1000 'warp { spherical orientation y }' \
    '1,0,0' '0,0,1' '1,1,0' '2,1,-1' '0,-1,0.5'
probe sph_o123 1000 'warp { spherical orientation <1,2,3> }' \
    '1,0,0' '0,0,1' '1,1,0' '2,1,-1' '0,-1,0.5'
probe sph_o68 1000 'warp { spherical orientation <0.6,0.8,0> }' \
    '1,0,0' '0,0,1' '1,1,0' '2,1,-1' '0,-1,0.5'
probe sph_oneg 1000 'warp { spherical orientation <-1,0.5,0.2> }' \
    '1,0,0' '0,0,1' '1,1,0' '2,1,-1' '0,-1,0.5'
probe sph_onz 1000 'warp { spherical orientation -z }' \
    '1,0,0' '0,0,1' '1,1,0' '2,1,-1' '0,-1,0.5'
probe cyl_oy 1000 'warp { cylindrical orientation y dist_exp 1 }' \
    '1,0.3,0' '0,0.3,2' '2,1,-1'
probe tor_oz2 1000 'warp { toroidal orientation <0,0,2> }' \
    '2,0,0' '1,1,0'

probe sph_oy_exp 1000 'warp { spherical orientation y dist_exp 1 }' \
    '1,0,0' '2,1,-1'
probe tor_ox 1000 'warp { toroidal orientation x }' \
    '2,0,0' '1,1,0' '0,0.5,-1'
probe cyl_onx 1000 'warp { cylindrical orientation -x }' \
    '1,0.3,0' '2,1,-1'

# On the axis (or at the centre) with another orientation: is the
# point left as it is, or mapped with u = 0?
probe axis_cyl 1000 'warp { cylindrical orientation y }' '0,0.3,0' '0,-2,0'
probe axis_sph 1000 'warp { spherical orientation x }' '0,2,0' '0,-1,0'
probe axis_tor 1000 'warp { toroidal orientation x }' '0,3,0' '0,0,0'

# Transforms before and after a warp ("Warp": in the order written).
probe frame_before 1000 'scale 2 warp { repeat x }' \
    '0.5,0,0' '1.5,0,0' '2.5,0,0'
probe frame_after 1000 'warp { repeat x } scale 2' \
    '0.5,0,0' '1.5,0,0' '2.5,0,0'

# Far away: how large a warped coordinate may grow (offsets of 1e15
# per block), and whether a coordinate that is already large is cut.
probe far 1e18 'warp { repeat x offset 1e15*y }' \
    '0.5,0,0' '50.5,0,0' '99.5,0,0' '100.5,0,0' '101.5,0,0' \
    '150.5,0,0' '-99.5,0,0' '-101.5,0,0' '-300.5,0,0'
probe far_in 1e18 'warp { repeat 1e30*x }' \
    '1,2e17,0' '1,-3e17,0' '1,0,4e17'
probe far_fine 1e18 'warp { repeat x offset 1e14*y }' \
    '999.5,0,0' '1000.5,0,0' '1001.5,0,0'
probe far_exp 1e18 'warp { cylindrical dist_exp 20 }' \
    '0,0,-7' '0,0,-7.2' '0,0,-30'

# Cubic (manual: "maps an area in the x-y plane between <0,0> and <1,1>
# around the origin in the same way as uv-mapping an origin-centered
# cube-shaped box would"): a point on each face, two distances, inside
# the cube, and the ties between faces (edges and corners), which tell
# which face wins.  (The origin itself gives NaN in POV-Ray: left out.)
probe cubic 1000 'warp { cubic }' \
    '-1,0.2,0.3' '1,0.2,0.3' '0.2,-1,0.3' '0.2,1,0.3' '0.2,0.3,-1' \
    '0.2,0.3,1' '-2,0.2,0.3' '2,0.2,0.3' '0.2,-2,0.3' '0.2,2,0.3' \
    '0.2,0.3,-2' '0.2,0.3,2' '-0.5,0.2,0.3' '0.5,0.2,0.3' \
    '0.1,0.7,-0.4' '-3,-1,2' '-1,0.9,-0.9' '0,0,1e-9' '1e-300,0,0'
probe cubic_tie 1000 'warp { cubic }' \
    '0.5,0.5,0.5' '1,1,0.5' '1,0.5,1' '0.5,1,1' '-1,-1,0.5' '-1,0.5,-1' \
    '0.5,-1,-1' '1,-1,1' '-1,1,-1' '0.5,-1,1' '-1,0.5,1' '0.5,1,-1' \
    '1,0.5,-1' '1,1,1' '-1,-1,-1' '1,-1,-1' '-1,1,1'
probe cubic_frame 1000 'warp { cubic } scale 2' \
    '1,0.2,0.3' '0.2,0.3,-3'
probe cubic_turb 1000 'warp { cubic } warp { turbulence 0.3 }' \
    '1,0.2,0.3' '0.2,0.3,-3' '-0.7,0.4,0.1'

# No warp at all: the pattern still gets coordinates cut to +-1e17
# (lib/scene/warp.c, PATTERN_COORD_MAX).
probe far_nowarp 1e18 '' \
    '1,2e17,0' '1,-3e17,0' '4e17,0,1' '1,0,9e16'
