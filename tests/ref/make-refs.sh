#!/bin/sh
# make-refs.sh - renders the POV-Ray reference images of the golden suite.
#
#   tests/ref/make-refs.sh [SCENE...]      (from anywhere; POVRAY=... to
#                                           pick the binary)
#
# Each scenes/NAME.pov becomes tests/ref/NAME.png, rendered by POV-Ray 3.7
# at 160x120 without antialiasing on one thread.  A scene that uses a
# zRcube extension has a POV-Ray twin scenes/NAME.ref.pov, which is
# rendered instead.  The command is recorded in tests/ref/README.md; keep
# the two in step.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
top=$(cd "$here/../.." && pwd)
povray=${POVRAY:-povray}
width=160
height=120

if [ $# -eq 0 ]; then
  # Scenes marked "// golden: skip WHY" on their first line have no
  # POV-Ray reference (see tests/golden.sh).
  set -- $(cd "$top/scenes" && ls *.pov | grep -v '\.ref\.pov$' |
           while read -r f; do
             head -n 1 "$f" | grep -q '^// golden: skip' ||
               echo "${f%.pov}"
           done)
fi
for name in "$@"; do
  src="$top/scenes/$name.pov"
  if [ -f "$top/scenes/$name.ref.pov" ]; then
    src="$top/scenes/$name.ref.pov"
  fi
  out="$here/$name.png"
  # +FN: PNG; -D: no display; -V: quiet; +WT1: one thread, as in bench/.
  "$povray" +I"$src" +O"$out" +W$width +H$height -A +FN -D -V +WT1 \
    +L"$top/scenes" >/dev/null 2>"$here/.$name.log" || {
    cat "$here/.$name.log" >&2
    rm -f "$here/.$name.log"
    echo "make-refs: POV-Ray failed on $src" >&2
    exit 1
  }
  rm -f "$here/.$name.log"
  echo "$out"
done
