#!/bin/sh
# radiosity_scale.sh - how hierarchical radiosity grows with a scene
# (issue 11, item 4: "a 100,000-triangle mesh in a closed room solves
# hierarchically in under 60 s on one core; links per surface stay flat
# as the scene grows 10x").
#
#   bench/radiosity_scale.sh BUILD_DIR [--quick]
#
# Scenes, made by bench/radiosity/scale_scene.py: a closed room (a box
# seen from inside) lit by an emitting slab under its ceiling, with
#   mesh N    one bumpy ball, a mesh2 of about N triangles (1k, 10k,
#             100k; --quick: 1k, 10k)
#   boxes N   about N surfaces: boxes of six faces on the floor (100,
#             1000, 10000; --quick: 100)
# Each is solved with --gi=hierarchical at the default BF_eps on one
# thread and rendered at 8x6 (the picture is not the point).  The solve's
# CPU seconds are the whole command's (user + system, /usr/bin/time)
# less those of the same command with --gi=off (parse, bounding volumes
# and the tiny render), so they are the solve's alone; memory is the
# peak resident set of each, and their difference.  Links and elements
# are those --radiosity-stats prints; "links per surface" counts a
# mesh's faces as its surfaces (the quantity that must stay flat as the
# scene grows), "links per element" the leaves.
#
# Writes $RADSCALE_OUT (default bench/out/radiosity_scale)/scale.tsv
# (scene, faces_or_surfaces, solve_cpu, total_cpu, links, elements,
# links_per_surface, links_per_element, rss_kb, rss_off_kb) and with
# gnuplot bench/radiosity/scale.png (kept in the tree, shown in the
# README) when the full ladder ran to its end, else $RADSCALE_OUT/scale.png.
# Timings are printed, never asserted.
#
# Environment: RADSCALE_OUT, RADSCALE_TIMEOUT (seconds a run may take,
# default 900), RADSCALE_CASES (e.g. "mesh:1000 boxes:100").
set -eu
. "$(dirname "$0")/build_args.sh"
. "$here/zrexe.sh" # the real program, not libtool's wrapper
limit=${RADSCALE_TIMEOUT:-900}
out=${RADSCALE_OUT:-$here/out/radiosity_scale}
[ -x "$zrcube" ] || { echo "radiosity_scale.sh: $zrcube is not built" >&2; exit 1; }
[ -x /usr/bin/time ] || { echo "radiosity_scale.sh: needs /usr/bin/time" >&2; exit 1; }
py=/usr/bin/python3
[ -x "$py" ] || py=python3
if [ $quick -eq 1 ]; then
  cases=${RADSCALE_CASES:-"mesh:1000 mesh:10000 boxes:100"}
else
  cases=${RADSCALE_CASES:-"mesh:1000 mesh:10000 mesh:100000 boxes:100 boxes:1000 boxes:10000"}
fi
mkdir -p "$out"
work=$(mktemp -d "${TMPDIR:-/tmp}/zr-radscale.XXXXXX")
trap 'rm -rf "$work"' EXIT INT TERM

# Runs zrcube on the scene with the given GI options; sets cpu (user +
# system seconds) and rss (peak KB), or returns 1.
run() { # scene, options...
  scene=$1
  shift
  if (cd "$work" && /usr/bin/time -f '%U %S %M' -o "$work/time" \
        timeout "$limit" "$zrcube" "$scene" +W8 +H6 -D +WT1 -q "$@" \
        +O"$work/out.png") >"$work/log" 2>&1; then
    set -- $(tail -n 1 "$work/time")
    cpu=$(awk -v u="$1" -v s="$2" 'BEGIN { printf "%.2f", u + s }')
    rss=$3
    return 0
  fi
  sed 's/^/    /' "$work/log" | tail -n 3 >&2
  return 1
}

stat() { # key: its value in the last --radiosity-stats output
  sed -n "s/.* $1=\([^ ]*\).*/\1/p" "$work/log" | head -n 1
}

tsv=$out/scale.tsv
# The chart kept in the tree (README) is redrawn only from the full
# ladder run to its end; a quick run, a chosen RADSCALE_CASES or a failed
# case draws $out/scale.png instead.
complete=1
[ "$quick" = 0 ] && [ -z "${RADSCALE_CASES:-}" ] || complete=0
printf 'scene\tsize\tsolve_cpu\ttotal_cpu\tlinks\telements\tlinks_per_surface\tlinks_per_element\trss_kb\trss_off_kb\n' >"$tsv"
printf '%-6s %7s %9s %9s %9s %9s %9s %9s %9s\n' scene size solve_cpu \
  total links elements l/surf l/elem rss_MB
for c in $cases; do
  kind=${c%%:*} n=${c#*:}
  scene=$work/$kind$n.pov
  "$py" "$here/radiosity/scale_scene.py" "$kind" "$n" >"$scene"
  size=$(sed -n '1s/^\/\/ [a-z]*: \([0-9]*\) .*/\1/p' "$scene")
  if ! run "$scene" --gi=off; then
    echo "radiosity_scale.sh: $kind $n failed without radiosity" >&2
    complete=0
    continue
  fi
  cpu_off=$cpu rss_off=$rss
  if ! run "$scene" --gi=hierarchical --radiosity-stats; then
    printf '%s\t%s\tfail\tfail\t-\t-\t-\t-\t-\t%s\n' "$kind" "$size" \
      "$rss_off" >>"$tsv"
    printf '%-6s %7s %9s\n' "$kind" "$size" fail
    complete=0
    continue
  fi
  links=$(stat links) elements=$(stat elements)
  surfaces=$(stat surfaces)
  # A mesh's faces are its surfaces: the room's and the lamp's 12 plus
  # the faces.
  [ "$kind" = mesh ] && surfaces=$((surfaces - 1 + size))
  awk -v k="$kind" -v n="$size" -v c="$cpu" -v c0="$cpu_off" -v l="$links" \
    -v e="$elements" -v s="$surfaces" -v m="$rss" -v m0="$rss_off" 'BEGIN {
      solve = c - c0; if (solve < 0) solve = 0
      printf "%s\t%s\t%.2f\t%.2f\t%d\t%d\t%.2f\t%.2f\t%d\t%d\n", k, n, solve,
        c, l, e, l / s, l / e, m, m0 >> "'"$tsv"'"
      printf "%-6s %7s %9.2f %9.2f %9d %9d %9.2f %9.2f %9.1f\n", k, n, solve,
        c, l, e, l / s, l / e, m / 1024 }'
done
echo "table: $tsv"
chart=$out/scale.png
[ "$complete" = 1 ] && chart=$here/radiosity/scale.png
if command -v gnuplot >/dev/null; then
  gnuplot -e "tsv='$tsv'; png='$chart'" \
    "$here/radiosity/scale.gp" && echo "chart: $chart" ||
    echo "radiosity_scale.sh: gnuplot failed" >&2
fi
