#!/bin/sh
# Black-box measurements of julia_fractal (issue 17): where rays first
# meet the fractal, as POV-Ray 3.7 or zrcube computes it with the SDL
# function trace(), for fractals whose shape follows from the escape
# rule alone (few iterations), so the escape radius, which iterates are
# tested, the bounding of the object and the hypercomplex algebra can be
# read off.
#
# Usage: bench/julia_probe.sh [RENDERER]      (default: povray)
#
# Prints per case a line
#   CASE  +x: X  +y: Y  d: D  in: I
# X: where a ray from <-5, 0, 0> along +x first meets the object (its x,
# negative), Y: the same from <0, -5, 0> along +y (its y), D: from
# -5 <1,1,1>/sqrt(3) along the diagonal (the distance from the origin
# with sign, negative), I: inside() at <0.05, 0.05, 0.05>.  "none": no
# hit.  precision 1000 makes the step small (0.001) so the hit is the
# escape boundary to about 1e-3 or better.
set -u
renderer=${1:-povray}
case $renderer in */*) renderer=$(cd "$(dirname "$renderer")" &&
    pwd)/$(basename "$renderer") ;; esac
tmp=$(mktemp -d "${TMPDIR:-/tmp}/zr_julia_probe.XXXXXX") || exit 1
trap 'rm -rf "$tmp"' EXIT

# probe NAME 'julia_fractal body'
probe() {
    name=$1 body=$2
    f=$tmp/$name.pov
    cat > "$f" <<EOF
#version 3.7;
global_settings { assumed_gamma 1 }
#declare J = julia_fractal { $body precision 1000 }
#declare N = <0, 0, 0>;
#macro Hit(From, Dir, Axis)
  #local P = trace(J, From, Dir, N);
  #if (vlength(N) = 0) "none" #else
    #if (Axis = 3) str(-vlength(P), 0, 6) #else str(P.x + P.y, 0, 6) #end
  #end
#end
#fopen Out "$name.txt" write
#write(Out, "$name +x: ", Hit(<-5, 0, 0>, x, 0), " +y: ",
  Hit(<0, -5, 0>, y, 1), " d: ", Hit(-5 * <1, 1, 1> / sqrt(3),
  <1, 1, 1> / sqrt(3), 3), " in: ", str(inside(J, <0.05, 0.05, 0.05>),
  0, 0), "\n")
#fclose Out
camera { location -z look_at 0 }
EOF
    rm -f "$tmp/$name.txt"
    case $renderer in
    *povray*)
        ( cd "$tmp" && timeout 60 "$renderer" +I"$f" -D +W1 +H1 -F \
            >/dev/null 2>&1 ) ;;
    *)
        ( cd "$tmp" && timeout 60 "$renderer" +I"$f" --parse-only -q \
            >/dev/null 2>&1 ) ;;
    esac
    if [ -s "$tmp/$name.txt" ]; then cat "$tmp/$name.txt"
    else echo "$name failed"; fi
}

# One iteration tests h0 alone: the object is a ball of the escape
# radius, unless something else bounds it.  Quaternions.
for a in 0 0.25 0.5 1 1.5 2 3 5; do
    probe "q1_p$a" "<$a, 0, 0, 0> quaternion sqr max_iteration 1"
done
probe q1_py1 "<0, 1, 0, 0> quaternion sqr max_iteration 1"
probe q1_pw2 "<0, 0, 0.6, 0.8> quaternion sqr max_iteration 1"
# Two and three iterations: h1 = h0^2 + p (and h2) are tested too?
for a in 0 0.5 1 2; do
    probe "q2_p$a" "<$a, 0, 0, 0> quaternion sqr max_iteration 2"
    probe "q3_p$a" "<$a, 0, 0, 0> quaternion sqr max_iteration 3"
done
probe q2_p1.5 "<1.5, 0, 0, 0> quaternion sqr max_iteration 2"
probe q2_pi15 "<0, 1.5, 0, 0> quaternion sqr max_iteration 2"
probe q2_slice "<0.3, 0, 0, 0> quaternion sqr max_iteration 2
  slice <0, 0, 0, 1>, 0.5"
probe q2_cube "<0.3, 0, 0, 0> quaternion cube max_iteration 2"
probe q2_cube1 "<1, 0, 0, 0> quaternion cube max_iteration 2"
# Hypercomplex: the same, then the algebra (a slice at w = 0.5 brings
# in k, so h0^2 shows k k; the manual's table says kk = -1, while
# ij = k with commuting i, j gives kk = i i j j = +1).
for a in 0 0.5 1 3; do
    probe "h1_p$a" "<$a, 0, 0, 0> hypercomplex sqr max_iteration 1"
done
for a in 0 0.5 2; do
    probe "h2_p$a" "<$a, 0, 0, 0> hypercomplex sqr max_iteration 2"
done
probe h2_p5 "<5, 0, 0, 0> hypercomplex sqr max_iteration 2"
probe h6_recip0 "<0, 0, 0, 0> hypercomplex reciprocal max_iteration 6"
probe h3_recip0 "<0, 0, 0, 0> hypercomplex reciprocal max_iteration 3"
probe h2_w05 "<0, 0, 0, 0> hypercomplex sqr max_iteration 2
  slice <0, 0, 0, 1>, 0.5"
probe h2_w1 "<0.2, 0.1, 0, 0> hypercomplex sqr max_iteration 2
  slice <0, 0, 0, 1>, 1"
probe h2_skew "<0.1, 0.2, 0.3, 0.4> hypercomplex sqr max_iteration 2
  slice <0, 0, 1, 1>, 0.3"
probe h3_skew "<-0.2, 0.3, -0.1, 0.2> hypercomplex sqr max_iteration 3
  slice <0.2, 0.3, 0.4, 0.8>, 0.1"
probe h2_cube "<0.1, 0.2, 0.3, 0.4> hypercomplex cube max_iteration 2
  slice <0, 0, 1, 1>, 0.3"
probe h2_exp "<0.1, 0.2, 0.3, 0.4> hypercomplex exp max_iteration 2
  slice <0, 0, 1, 1>, 0.3"
probe h2_recip "<0.1, 0.2, 0.3, 0.4> hypercomplex reciprocal
  max_iteration 2 slice <0, 0, 1, 1>, 0.3"
probe h2_sin "<0.1, 0.2, 0.3, 0.4> hypercomplex sin max_iteration 2
  slice <0, 0, 1, 1>, 0.3"
probe h2_pwr "<0.1, 0.2, 0.3, 0.4> hypercomplex pwr(2, 0.5)
  max_iteration 2 slice <0, 0, 1, 1>, 0.3"
