#!/bin/sh
# peers.sh - zRcube against POV-Ray 3.7 and Tachyon 0.99 on the same
# geometry and camera, side by side in one run (issue 13).
#
#   bench/peers.sh BUILD_DIR
#
# bench/peers_gen.py writes the scenes into a temporary directory:
#   flake    the sphereflake, 7,381 reflective spheres on a plane, three
#            lights (POV `sphere`s, Tachyon `SPHERE`s);
#   terrain  a 256 x 256 height field as 130,050 flat triangles (one POV
#            `mesh` of `triangle`s, Tachyon `TRI`s), two lights;
#   csg      400 CSG pieces on a plane, POV-Ray and zRcube only (Tachyon
#            has no CSG).
# Each is rendered at every size of SIZES (default "512 2048", square),
# no antialiasing, one thread: zRcube `+WT1 -A`, POV-Ray `+WT1 -A -D`
# (its statistics stream on, for the ray counts),
# Tachyon `-numthreads 1` (its .dat camera sets no antialiasing).  Every
# command is timed whole in CPU seconds (user + system, /usr/bin/time),
# best of REPEAT runs (default 3), the three renderers taking turns:
# start-up, parse, build, trace and the image write.  zRcube runs as its
# real binary (BUILD_DIR/bin/.libs/zrcube with the library's folder on
# LD_LIBRARY_PATH when libtool built a wrapper), not the wrapper script.
#
# The first table gives the times and the ratios zRcube / Tachyon and
# zRcube / POV-Ray (the issue's targets: <= 1 and <= 0.4).  The second
# gives rays per second of tracing: zRcube's from its +V statistics (all
# rays: camera, reflected, refracted, shadow) over its render's CPU
# seconds, POV-Ray's from its statistics over its trace time (a wall
# clock: low under load); Tachyon prints no ray count, so its figure is
# camera rays over its ray tracing time (wall too).  The third gives the
# parse (zRcube's parse CPU seconds, which include its BVH, against
# Tachyon's "Scene Parsing Time" + "Preprocessing Time", wall) and the
# peak memory (/usr/bin/time's maximum resident set) of each whole
# process at the first size, and from those the bytes per primitive
# above an empty scene's footprint (flake: 7,381 spheres and the plane;
# terrain: 130,050 triangles).  The output is also written to
# bench/results/peers-DATE.txt unless PEERS_NO_SAVE is set.  Timings are
# printed, never asserted.
set -eu
if [ $# -lt 1 ]; then
  echo "usage: bench/peers.sh BUILD_DIR" >&2
  exit 2
fi
here=$(cd "$(dirname "$0")" && pwd)
build=$(cd "$1" && pwd)
sizes=${SIZES:-512 2048}
repeat=${REPEAT:-3}
povray=${POVRAY:-povray}
tachyon=${TACHYON:-tachyon}
python=${PYTHON:-/usr/bin/python3}

. "$here/zrexe.sh"
[ -x "$zrcube" ] || { echo "peers.sh: $zrcube is not built" >&2; exit 1; }
for tool in "$povray" "$tachyon" "$python" /usr/bin/time; do
  command -v "$tool" >/dev/null 2>&1 || {
    echo "peers.sh: $tool not found (apt-get install povray tachyon" \
         "python3 time)" >&2
    exit 77
  }
done

work=$(mktemp -d "${TMPDIR:-/tmp}/zr-peers.XXXXXX")
trap 'rm -rf "$work"' EXIT INT TERM
"$python" "$here/peers_gen.py" "$work"

# Runs "$@" once with its output in $work/log and its /usr/bin/time -v
# report in $work/time; prints the CPU seconds (user + system) of the
# whole process, or "fail".  CPU time, not wall time: this machine is
# shared, and a wall clock measures the other jobs as much as ours.
once() {
  if /usr/bin/time -v -o "$work/time" "$@" >"$work/log" 2>&1; then
    awk -F': ' '/User time \(seconds\)/ { u = $2 }
                /System time \(seconds\)/ { s = $2 }
                END { printf "%.3f\n", u + s }' "$work/time"
  else
    echo fail
  fi
}

# One run of "$@" tagged $1, kept as $work/$1.log and $work/$1.time when
# it is the best (least CPU) so far; its best is in $work/$1.best.
keep_best() {
  tag=$1
  shift
  best=$(cat "$work/$tag.best" 2>/dev/null || echo none)
  [ "$best" = fail ] && return 0
  t=$(once "$@")
  if [ "$t" = fail ]; then
    cp "$work/log" "$work/$tag.log"
    echo fail >"$work/$tag.best"
  elif [ "$best" = none ] ||
       [ "$(echo "$t $best" | awk '{ print ($1 < $2) }')" = 1 ]; then
    echo "$t" >"$work/$tag.best"
    cp "$work/log" "$work/$tag.log"
    cp "$work/time" "$work/$tag.time"
  fi
}

ratio() {
  echo "$1 $2" | awk '{ if ($1 == "fail" || $2 == "fail" || $1 == "-" ||
                           $2 == "-" || $2 <= 0) print "-";
                        else printf "%.2f", $1 / $2 }'
}

peak_mib() {
  awk -F': ' '/Maximum resident set size/ { printf "%.0f", $2 / 1024 }' \
    "$1" 2>/dev/null || echo -
}
# The same in KiB, as time(1) gives it: bytes per primitive come from
# these (whole MiB made both renderers' 2 MiB of spheres look alike).
peak_kib() {
  awk -F': ' '/Maximum resident set size/ { printf "%d", $2 }' \
    "$1" 2>/dev/null || echo -
}

# The CPU seconds of one phase ("parse", "render") from zRcube's +V
# line "rank 0: wall s: ...; cpu s: parse P ... render R ...".
zr_cpu() {
  awk -v key="$2" '/rank 0: wall s:/ { sub(/.*cpu s: /, "")
                     for (i = 1; i < NF; i++) if ($i == key) print $(i + 1) }' "$1"
}

# Rays per second from zRcube's +V statistics (the block POV-Ray's
# layout: camera, shadow, reflected and refracted rays) over the CPU
# seconds of its render.
zr_rays() {
  awk -v t="$(zr_cpu "$1" render)" \
      '/^Rays:|^Shadow Ray Tests|^Reflected Rays|^Refracted Rays/ {
         for (i = 1; i <= NF; i++) if ($i ~ /^[0-9]+$/) { n += $i; break } }
       END { if (t > 0) printf "%.2f", n / t / 1e6; else print "-" }' "$1"
}

# Rays per second from POV-Ray's statistics: every "... Rays:" count of
# the ray statistics block over the trace time.
pov_rays() {
  awk '/^Rays:|^Shadow Ray Tests|^Reflected Rays|^Refracted Rays/ {
         for (i = 1; i <= NF; i++) if ($i ~ /^[0-9]+$/) { n += $i; break } }
       /Trace Time:/ { if (match($0, /\(([0-9.]+) seconds\)/))
                         t = substr($0, RSTART + 1, RLENGTH - 10) + 0 }
       END { if (t > 0) printf "%.2f", n / t / 1e6; else print "-" }' "$1"
}

tachyon_field() {
  awk -v key="$2" 'index($0, key) { for (i = 1; i <= NF; i++)
                                      if ($i ~ /^[0-9.]+$/) { print $i; exit } }' "$1"
}

{
echo "zRcube ($zrcube) vs $("$povray" --version 2>&1 | grep -m1 POV-Ray |
  sed 's/ *(.*//') and Tachyon $("$tachyon" /dev/null 2>&1 | grep -m1 -o 'Version [0-9.]*' |
  sed 's/Version //'), one thread, no AA, best of $repeat interleaved, CPU seconds (user + sys) of the whole process"
echo "host: $(uname -m), $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg)"
printf '%-8s %5s %9s %9s %9s %8s %8s\n' scene size zRcube_s POV_s \
  Tachyon_s zr/tach zr/pov
rays_lines=
mem_lines=
kib_lines=
first_size=${sizes%% *}
for size in $sizes; do
  for scene in flake terrain csg; do
    cd "$work"
    rm -f z.best p.best t.best
    # The three renderers take turns, round after round, so a change of
    # the machine's load falls on all of them alike.
    i=0
    while [ "$i" -lt "$repeat" ]; do
      keep_best z "$zrcube" "+I$scene.pov" "+Oz.png" "+W$size" "+H$size" \
        -A +WT1 +V -D
      keep_best p "$povray" "+I$scene.pov" "+Op.png" "+W$size" "+H$size" \
        -A +WT1 -D
      if [ -f "$scene.dat" ]; then
        keep_best t "$tachyon" "$scene.dat" -res "$size" "$size" \
          -numthreads 1 -format TARGA -o t.tga +V
      fi
      i=$((i + 1))
    done
    tz=$(cat z.best)
    tp=$(cat p.best)
    tt=-
    [ -f t.best ] && tt=$(cat t.best)
    printf '%-8s %5s %9s %9s %9s %8s %8s\n' "$scene" "$size" "$tz" "$tp" \
      "$tt" "$(ratio "$tz" "$tt")" "$(ratio "$tz" "$tp")"
    zr=$(zr_rays z.log)
    pr=$(pov_rays p.log)
    tr=-
    if [ "$tt" != - ] && [ "$tt" != fail ]; then
      tt_trace=$(tachyon_field t.log "Ray Tracing Time")
      tr=$(echo "$size $tt_trace" |
           awk '{ if ($2 > 0) printf "%.2f", $1 * $1 / $2 / 1e6; else print "-" }')
    fi
    rays_lines="$rays_lines$(printf '%-8s %5s %11s %11s %11s' "$scene" \
      "$size" "$zr" "$pr" "$tr")
"
    if [ "$size" = "$first_size" ]; then
      zp=$(zr_cpu z.log parse)
      tpz=-
      if [ -f "$scene.dat" ] && [ "$tt" != fail ]; then
        tpz=$(echo "$(tachyon_field t.log "Scene Parsing Time")" \
                   "$(tachyon_field t.log "Preprocessing Time")" |
              awk '{ printf "%.3f", $1 + $2 }')
      fi
      mem_lines="$mem_lines$(printf '%-8s %9s %9s %7s %8s %8s %9s' "$scene" \
        "${zp:--}" "$tpz" "$(ratio "${zp:--}" "$tpz")" "$(peak_mib z.time)" \
        "$(peak_mib p.time)" \
        "$([ -f t.time ] && [ -f "$scene.dat" ] && peak_mib t.time || echo -)")
"
      kib_lines="$kib_lines$scene $(peak_kib z.time) $([ -f t.time ] &&
        [ -f "$scene.dat" ] && peak_kib t.time || echo -)
"
    fi
    rm -f t.time
  done
done
# Bytes per primitive: the peak resident memory above an empty scene's
# (camera and light) at the first size, over the number of primitives.
cd "$work"
/usr/bin/time -v -o ze.time "$zrcube" +Iempty.pov +Oz.png "+W$first_size" \
  "+H$first_size" -A +WT1 -D >/dev/null 2>&1 || true
/usr/bin/time -v -o te.time "$tachyon" empty.dat -res "$first_size" \
  "$first_size" -numthreads 1 -format TARGA -o t.tga >/dev/null 2>&1 || true
per_prim() { # scene-KiB empty-KiB count
  echo "$1 $2 $3" | awk '{ if ($1 ~ /^[0-9]+$/ && $2 ~ /^[0-9]+$/)
                             printf "%.0f", ($1 - $2) * 1024 / $3;
                           else print "-" }'
}
echo
echo "rays per second (millions) while tracing (zRcube: CPU clock;" \
  "POV-Ray, Tachyon: their wall clocks); Tachyon: camera rays only"
printf '%-8s %5s %11s %11s %11s\n' scene size zRcube POV-Ray Tachyon
printf '%s' "$rays_lines"
echo
echo "parse (zRcube: parse + BVH, CPU; Tachyon: parse + preprocessing," \
  "wall) and" \
  "peak memory of the whole process, ${first_size}^2"
printf '%-8s %9s %9s %7s %8s %8s %9s\n' scene zr_parse tach_parse ratio \
  zr_MiB pov_MiB tach_MiB
printf '%s' "$mem_lines"
echo
echo "bytes per primitive above an empty scene (zRcube $(peak_mib ze.time)" \
  "MiB, Tachyon $(peak_mib te.time) MiB), ${first_size}^2"
printf '%-8s %9s %9s\n' scene zRcube Tachyon
for scene in flake terrain; do
  case $scene in flake) count=7382 ;; terrain) count=130050 ;; esac
  printf '%-8s %9s %9s\n' "$scene" \
    "$(per_prim "$(echo "$kib_lines" | awk -v s=$scene '$1 == s { print $2 }')" \
       "$(peak_kib ze.time)" $count)" \
    "$(per_prim "$(echo "$kib_lines" | awk -v s=$scene '$1 == s { print $3 }')" \
       "$(peak_kib te.time)" $count)"
done
} | if [ -n "${PEERS_NO_SAVE:-}" ]; then cat; else
  mkdir -p "$here/results"
  tee "$here/results/peers-$(date -u +%Y-%m-%d-%H%M).txt"
fi
