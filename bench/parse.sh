#!/bin/sh
# parse.sh - zRcube's parser against POV-Ray 3.7's on parse-heavy scenes,
# in the same run (issue 3).
#
#   bench/parse.sh BUILD_DIR
#
# Generates three scenes into a temporary directory:
#   while   a #while of WHILE_N iterations (default 1,000,000), each making
#           a sphere;
#   macro   MACRO_N (default 100,000) calls of a macro that makes a sphere;
#   mesh2   one mesh2 of a MESH_SIDE x MESH_SIDE grid (default 1000:
#           1,000,000 vertices, 1,996,002 triangles, an 80 MB file that
#           takes POV-Ray a few seconds).
# CASES picks some of them (default "while macro mesh2").
# Every object sits behind the camera, so POV-Ray's 1x1 render traces
# nothing that hits.
#
# zRcube runs `BUILD_DIR/bin/zrcube --parse-only`; its time is the parse
# time it prints (reading, lexing, the directive engine and grammar, and
# the scene's finishing, which builds its BVH).  POV-Ray has no parse-only
# mode: it runs `povray -D +W1 +H1 +WT1` and its times are the "Parse
# Time" and the "Bounding Time" (its bounding hierarchy, built after the
# parse) its statistics print.  "ratio" is zRcube / POV-Ray's parse time,
# the issue's figure, which charges zRcube for its BVH but not POV-Ray;
# "ratio+b" is zRcube / (POV-Ray's parse + bounding), like for like.
# Below 1 is faster.  Peak memory is /usr/bin/time -v's maximum resident
# set size of each whole process.  A scene zRcube cannot parse yet is
# reported as "not supported yet" with its first error.  Timings are
# printed, never asserted.
set -eu
if [ $# -lt 1 ]; then
  echo "usage: bench/parse.sh BUILD_DIR" >&2
  exit 2
fi
build=$(cd "$1" && pwd)
zrcube=$build/bin/zrcube
povray=${POVRAY:-povray}
while_n=${WHILE_N:-1000000}
macro_n=${MACRO_N:-100000}
mesh_side=${MESH_SIDE:-1000}
cases=${CASES:-while macro mesh2}
[ -x "$zrcube" ] || { echo "parse.sh: $zrcube is not built" >&2; exit 1; }
command -v "$povray" >/dev/null ||
  { echo "parse.sh: $povray not found" >&2; exit 1; }
[ -x /usr/bin/time ] ||
  { echo "parse.sh: /usr/bin/time (GNU time) is needed" >&2; exit 1; }

work=$(mktemp -d "${TMPDIR:-/tmp}/zr-parse.XXXXXX")
trap 'rm -rf "$work"' EXIT INT TERM

# ---- the scenes ----

head_of_scene() {
  cat <<'EOF'
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 0, 0> look_at <0, 0, 1> }
light_source { <0, 10, 0>, rgb 1 }
EOF
}

{
  head_of_scene
  cat <<EOF
#declare I = 0;
#while (I < $while_n)
  sphere { <mod(I, 1000), div(I, 1000), -10>, 0.25 }
  #declare I = I + 1;
#end
EOF
} >"$work/while.pov"

{
  head_of_scene
  cat <<EOF
#macro Ball(N)
  sphere { <mod(N, 1000), div(N, 1000), -10>, 0.25 }
#end
#declare I = 0;
#while (I < $macro_n)
  Ball(I)
  #declare I = I + 1;
#end
EOF
} >"$work/macro.pov"

{
  head_of_scene
  awk -v n="$mesh_side" 'BEGIN {
    printf "mesh2 {\n  vertex_vectors { %d,\n", n * n
    for (j = 0; j < n; j++)
      for (i = 0; i < n; i++)
        printf "    <%d, %.4f, %d>%s\n", i, sin(i * 0.1) * cos(j * 0.1),
               -10 - j, (i == n - 1 && j == n - 1) ? "" : ","
    printf "  }\n  face_indices { %d,\n", 2 * (n - 1) * (n - 1)
    for (j = 0; j < n - 1; j++)
      for (i = 0; i < n - 1; i++) {
        a = j * n + i
        last = (i == n - 2 && j == n - 2)
        printf "    <%d, %d, %d>, <%d, %d, %d>%s\n", a, a + 1, a + n,
               a + 1, a + n + 1, a + n, last ? "" : ","
      }
    printf "  }\n  pigment { rgb 1 }\n}\n"
  }'
} >"$work/mesh2.pov"

# ---- measuring ----

# The maximum resident set size, in MiB, from a /usr/bin/time -v log.
peak_mib() {
  awk -F': ' '/Maximum resident set size/ { printf "%.0f", $2 / 1024 }' "$1"
}

# Runs zrcube on scene $1; sets z_time, z_mem, z_note.
run_zrcube() {
  z_time=-
  z_mem=-
  z_note=
  if /usr/bin/time -v "$zrcube" --parse-only -q "$1" \
      >"$work/z.out" 2>"$work/z.err"; then
    z_time=$(awk -F': ' '/^parse seconds/ { print $2 }' "$work/z.out")
    z_mem=$(peak_mib "$work/z.err")
  else
    first=$(grep -m1 'error:' "$work/z.err" | sed 's/^[^ ]*: error: //')
    case $first in
      *"not supported"*|*"unknown directive"*)
        z_note="not supported yet: $first" ;;
      *)
        z_note="failed: ${first:-see $work/z.err}" ;;
    esac
  fi
}

# Runs POV-Ray on scene $1; sets p_time, p_bound, p_mem.
run_povray() {
  p_time=-
  p_bound=-
  p_mem=-
  if /usr/bin/time -v "$povray" "+I$1" "+O$work/p.png" -D +W1 +H1 +WT1 \
      >"$work/p.out" 2>"$work/p.err"; then
    p_time=$(sed -n 's/.*Parse Time:.*(\([0-9.]*\) seconds).*/\1/p' \
             "$work/p.err" | head -1)
    p_bound=$(sed -n 's/.*Bounding Time:.*(\([0-9.]*\) seconds).*/\1/p' \
              "$work/p.err" | head -1)
    p_mem=$(peak_mib "$work/p.err")
  else
    p_time=fail
  fi
}

printf '%-7s %10s %10s %12s %7s %8s %8s %8s\n' scene "zrcube s" \
  "povray s" "bounding s" ratio "ratio+b" "zr MiB" "pov MiB"
for name in $cases; do
  scene=$work/$name.pov
  run_zrcube "$scene"
  run_povray "$scene"
  if [ -n "$z_note" ]; then
    printf '%-7s %10s %10s %12s %7s %8s %8s %8s  zrcube %s\n' "$name" - \
      "$p_time" "$p_bound" - - - "$p_mem" "$z_note"
    continue
  fi
  ratio=$(echo "$z_time $p_time" |
          awk '{ if ($2 > 0) printf "%.3f", $1 / $2; else print "-" }')
  ratio_b=$(echo "$z_time $p_time $p_bound" |
            awk '{ if ($2 + $3 > 0) printf "%.3f", $1 / ($2 + $3);
                   else print "-" }')
  printf '%-7s %10s %10s %12s %7s %8s %8s %8s\n' "$name" "$z_time" \
    "$p_time" "$p_bound" "$ratio" "$ratio_b" "$z_mem" "$p_mem"
done
echo "(while: $while_n iterations; macro: $macro_n calls; mesh2:" \
  "${mesh_side}x$mesh_side vertices; one run each; ratio = zrcube /" \
  "povray parse, ratio+b = zrcube / (povray parse + bounding))"
