#!/bin/sh
# test_continue.sh - a render killed with SIGKILL about half-way and
# continued with +C writes the same bytes as one never interrupted
# (issue 12), with 1 rank and with 2 ranks under mpirun (also with
# +UA), and with the irradiance cache saved beside the state file; a
# state file of other options is refused with a message.
#
# The render keeps its state file (image.png.zrstate) after every band
# of rows here (--state-interval=0); the test reads the file's band
# flags (state.c: 8 bytes of magic, 8 of fingerprint, 5 int32 of
# layout, then one byte a band and pass) and kills the render once
# about half of them are set.
set -u
TEST_NAME=test_continue
. "$(dirname "$0")/cli_env.sh"
cd "$work" || exit 99

failures=0
fail() {
  echo "FAIL: $*" >&2
  failures=$((failures + 1))
}

cat >scene.pov <<'POV'
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -6> look_at <0, 0.5, 0> }
light_source { <4, 6, -5> rgb 1 area_light x, z, 5, 5 jitter adaptive 1 }
plane { y, 0 pigment { checker rgb 1 rgb 0.2 } finish { reflection 0.3 } }
#for (I, 0, 6)
  sphere { <I - 3, 0.6, 0>, 0.45
    pigment { rgbf <1, I / 7, 0.5, 0.6> }
    finish { phong 0.8 reflection 0.2 } interior { ior 1.4 } }
#end
POV
# The same scene lit by a sky too, so the irradiance cache is used
# (and the render lasts long enough to be killed half-way).
{ sed 's/global_settings { assumed_gamma 1.0 }/global_settings { assumed_gamma 1.0 radiosity { count 30 } }/' scene.pov
  echo 'sky_sphere { pigment { gradient y color_map { [0 rgb 1] [1 rgb <0.3, 0.5, 1>] } } }'
} >sky.pov
grep -q radiosity sky.pov || exit 99

# done_fraction FILE: bands done over all bands (in percent), or -1.
done_percent() {
  [ -s "$1" ] || { echo -1; return; }
  set -- "$1" $(od -A n -t d4 -j 16 -N 20 "$1")
  [ $# -eq 6 ] || { echo -1; return; }
  flags=$(( $4 * $5 ))
  ones=$(od -A n -t u1 -v -j 36 -N "$flags" "$1" | tr -s ' ' '\n' |
    grep -c '^1$')
  echo $(( 100 * ones / flags ))
}

# descendants PID: the processes PID started, their children first.
descendants() {
  for child in $(ps -o pid= --ppid "$1" 2>/dev/null); do
    descendants "$child"
    echo "$child"
  done
}

# check NAME SCENE [LAUNCH...] -- ARGS: the uninterrupted render, then
# one killed at about half (SIGKILL) and continued with +C.
check() {
  c_name=$1 c_scene=$2
  shift 2
  launch=""
  while [ "$1" != "--" ]; do launch="$launch $1"; shift; done
  shift
  $launch "$ZRCUBE" "$c_scene" "$@" "+O$c_name.ref.png" \
    >"$c_name.ref.out" 2>"$c_name.ref.err" ||
    { fail "$c_name: the uninterrupted render failed"; return; }
  $launch "$ZRCUBE" "$c_scene" "$@" "+O$c_name.png" --state-interval=0 \
    >"$c_name.1.out" 2>"$c_name.1.err" &
  pid=$!
  state="$c_name.png.zrstate"
  tries=0 pct=-1
  while [ "$tries" -lt 3000 ]; do
    pct=$(done_percent "$state")
    [ "$pct" -ge 40 ] && break
    kill -0 "$pid" 2>/dev/null || break
    sleep 0.02
    tries=$((tries + 1))
  done
  # kill -9 the render: the ranks first (the launcher's descendants,
  # which this test started), then the launcher.
  for p in $(descendants "$pid"); do kill -KILL "$p" 2>/dev/null; done
  kill -KILL "$pid" 2>/dev/null
  wait "$pid" 2>/dev/null
  sleep 0.2
  if [ -e "$c_name.png" ]; then
    echo "$c_name: the render finished before it could be killed" \
         "(machine too fast); continuing from its state anyway" >&2
  fi
  [ -e "$state" ] || { fail "$c_name: no state file after the kill"; return; }
  pct=$(done_percent "$state")
  [ "$pct" -ge 100 ] && fail "$c_name: killed after the end ($pct%)"
  echo "$c_name: killed at $pct% of the bands" >&2
  rm -f "$c_name.png"
  $launch "$ZRCUBE" "$c_scene" "$@" "+O$c_name.png" +C \
    >"$c_name.2.out" 2>"$c_name.2.err" ||
    { fail "$c_name: +C failed: $(cat "$c_name.2.err")"; return; }
  grep -q "continuing" "$c_name.2.err" ||
    fail "$c_name: +C did not continue: $(cat "$c_name.2.err")"
  cmp -s "$c_name.ref.png" "$c_name.png" ||
    fail "$c_name: the continued image differs from the uninterrupted one"
  [ -e "$state" ] && fail "$c_name: the state file is left after the end"
  if grep -q -e 'Sanitizer' -e 'runtime error:' "$c_name".*.err; then
    fail "$c_name: sanitizer report"
  fi
}

check serial scene.pov -- +W160 +H120 +A0.1 +WT1 -V
check mpi scene.pov env ASAN_OPTIONS="$MPI_ASAN" $MPIRUN -n 2 -- \
  +W160 +H120 +A0.1 +WT1 -V
check cache sky.pov -- +W160 +H120 +A0.1 +WT1 -V
# +UA: 4 floats a pixel in the state file, across 2 ranks.
check alpha scene.pov env ASAN_OPTIONS="$MPI_ASAN" $MPIRUN -n 2 -- \
  +W160 +H120 +A0.1 +WT1 -V +UA
[ -e cache.png.zrstate.gi ] && fail "cache: the saved cache is left"

# A state file of other options is refused, and kept.
"$ZRCUBE" scene.pov +W40 +H30 +Oother.png --state-interval=0 \
  >/dev/null 2>&1 &
pid=$!
while kill -0 "$pid" 2>/dev/null && ! [ -s other.png.zrstate ]; do
  sleep 0.01
done
kill -KILL "$pid" 2>/dev/null
wait "$pid" 2>/dev/null
if [ -e other.png.zrstate ]; then
  rm -f other.png
  "$ZRCUBE" scene.pov +W40 +H30 +A0.2 +Oother.png +C >other.out 2>other.err &&
    fail "other: +C with other options succeeded"
  grep -q "refusing the state file 'other.png.zrstate': it was made by another scene or other options" other.err ||
    fail "other: wrong message: $(cat other.err)"
  [ -e other.png.zrstate ] || fail "other: the refused state file is gone"
else
  echo "other: the render ended before it wrote a state file" >&2
fi

[ "$failures" -eq 0 ] || { echo "test_continue.sh: $failures failure(s)" >&2; exit 1; }
exit 0
