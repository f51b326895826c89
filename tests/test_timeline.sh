#!/bin/sh
# test_timeline.sh - ZRCUBE_TIMELINE (lib/par/par.c's zr__par_mark,
# read by bench/timeline.sh): under mpirun -n 2 every rank prints each
# step of a run once, in the order of the run, with wall times that do
# not go back and CPU times that do not shrink; rank 0's lines name it
# and rank 1's name it; without the variable no such line is printed;
# and the image is the same bytes either way, with rows taken from the
# shared counter or dealt.
#
# Environment: ZR_SRCDIR, ZR_BUILDDIR (set by `make check`).
TEST_NAME=timeline
. "${ZR_SRCDIR:-$(cd "$(dirname "$0")/.." && pwd)}/tests/cli_env.sh"
cd "$work" || exit 99
cat >s.pov <<'POV'
#version 3.7;
camera { location <0, 1, -3> look_at 0 }
light_source { <2, 4, -3> rgb 1 }
sphere { 0, 1 pigment { rgb <1, 0.5, 0.2> } }
POV
failed=0
fail() { echo "FAIL: $*"; failed=1; }
run() { # run OUT.png LOG [env...]
  png=$1 log=$2
  shift 2
  env "$@" ASAN_OPTIONS="$MPI_ASAN" timeout 120 "$MPIRUN" --bind-to none \
    -n 2 "$ZRCUBE" +Is.pov +W64 +H48 -D +WT1 "+O$png" </dev/null \
    >"$log" 2>&1 || { echo "mpirun -n 2 failed:"; tail -5 "$log"; exit 1; }
}
run with.png with.log ZRCUBE_TIMELINE=1
run without.png without.log -u ZRCUBE_TIMELINE
if grep -q 'zrcube: timeline:' without.log; then
  fail "timeline lines without ZRCUBE_TIMELINE"
fi
cmp -s with.png without.png || fail "the image differs with the timeline"
# The steps every rank passes, in order (the render's chunks between
# "all ranks ready" and "last chunk done" vary with the machine); on
# one host the ranks take rows from a shared counter ("rows shared").
steps='main() entered
MPI joined (zr__par_init)
parse start
parse end
image: allocating
render start (image and writer ready)
render: buffers ready
render: all ranks ready
render: rows shared
render: last chunk done
render end
image written
MPI_Finalize
leaving main()'
for rank in 0 1; do
  grep "^zrcube: timeline: rank $rank wall " with.log >"r$rank.txt"
  sed 's/^zrcube: timeline: rank [0-9]* wall [0-9.]* cpu [0-9.]* thread [0-9.]* //' \
    "r$rank.txt" | grep -v '^render: \(tail \)\{0,1\}\(chunk rendered\|chunk gathered\|rows of this rank done\)$' \
    >"steps$rank.txt"
  printf '%s\n' "$steps" >want.txt
  if ! cmp -s want.txt "steps$rank.txt"; then
    fail "rank $rank's steps are not the run's:"
    diff want.txt "steps$rank.txt" | head -10
  fi
  grep -q 'render: \(tail \)\{0,1\}chunk rendered$' "r$rank.txt" ||
    fail "rank $rank: no chunk of the render"
  # Wall, process CPU and thread CPU never go back.
  awk '{ if (NR > 1 && ($6 < w || $8 < c || $10 < t)) bad = NR
         w = $6; c = $8; t = $10 }
       END { exit bad ? 1 : 0 }' "r$rank.txt" ||
    fail "rank $rank: a time goes back: $(head -3 "r$rank.txt")"
done
# Where the shared window cannot be made (Open MPI without its
# shared-memory one-sided component) and with ZRCUBE_ROWS=static, the
# ranks deal rows out statically: the same bytes.
run pt2pt.png pt2pt.log ZRCUBE_TIMELINE=1 OMPI_MCA_osc=pt2pt
run static.png static.log ZRCUBE_TIMELINE=1 ZRCUBE_ROWS=static
for t in pt2pt static; do
  cmp -s with.png "$t.png" || fail "$t: the image differs"
  n=$(grep -c 'render: rows dealt$' "$t.log")
  [ "$n" = 2 ] || fail "$t: $n ranks dealt rows, expected 2"
  grep -q 'render: rows shared$' "$t.log" && fail "$t: rows shared"
done
[ "$failed" = 0 ] && echo "1 passed, 0 failed" || echo "0 passed, 1 failed"
exit "$failed"
