#!/bin/sh
# same_bytes.sh - whether two builds of zRcube write the same image
# bytes for a list of scenes: the check a change for speed owes
# (common rule: performance work keeps main's bytes).
#
#   bench/same_bytes.sh OLD NEW SCENE...
#
# OLD and NEW are build folders (their bin/.libs/zrcube runs with their
# lib/.libs on LD_LIBRARY_PATH, as bench/zrexe.sh does) or folders
# holding a copy of the program beside its libzrcube.so.*.  A SCENE is
# a .pov path, absolute or relative to POV-Ray's examples
# (/usr/share/doc/povray/examples).  Each is rendered by both at
# 160x120 (SIZE="+W.. +H.." to change), one thread, without display,
# once without antialiasing (-A) and once with +A0.3, from the scene's
# own folder with POV-Ray's include folder on the library path; the
# PNGs are compared with cmp.  One line a scene and setting: "same",
# "DIFFER", or "fail" (a render that failed: its exit status for each
# build).  The exit status is 1 when some images differ or only one
# build failed.
set -u
if [ $# -lt 3 ]; then
  echo "usage: bench/same_bytes.sh OLD NEW SCENE..." >&2
  exit 2
fi
examples=/usr/share/doc/povray/examples
include=/usr/share/povray-3.7/include
size=${SIZE:-+W160 +H120}
work=$(mktemp -d "${TMPDIR:-/tmp}/zr-same.XXXXXX")
trap 'rm -rf "$work"' EXIT
trap 'exit 130' INT TERM

# The program and library folder of a build folder or of a copy.
program() {
  if [ -x "$1/bin/.libs/zrcube" ]; then
    echo "$1/bin/.libs/zrcube $1/lib/.libs"
  else
    echo "$1/zrcube $1"
  fi
}
set -- "$(cd "$1" && pwd)" "$(cd "$2" && pwd)" "$@"
old=$(program "$1")
new=$(program "$2")
shift 4
status=0
same=0
total=0
for scene in "$@"; do
  case $scene in
    /*) path=$scene ;;
    *) path=$examples/$scene ;;
  esac
  dir=$(dirname "$path")
  for aa in -A +A0.3; do
    rcs=
    for tag in old new; do
      if [ $tag = old ]; then set -- $old; else set -- $new; fi
      # shellcheck disable=SC2086
      (cd "$dir" && LD_LIBRARY_PATH=$2 "$1" "$path" $size +WT1 -D $aa \
          +L"$include" +L"$dir" +O"$work/$tag.png" >"$work/$tag.log" 2>&1)
      rcs="$rcs $?"
    done
    total=$((total + 1))
    case $rcs in
      " 0 0")
        if cmp -s "$work/old.png" "$work/new.png"; then
          verdict=same
          same=$((same + 1))
        else
          verdict=DIFFER
          status=1
        fi
        ;;
      *)
        verdict="fail$rcs"
        set -- $rcs
        [ "$1" = "$2" ] || status=1
        ;;
    esac
    printf '%-50s %-6s %s\n' "$scene" "$aa" "$verdict"
    rm -f "$work/old.png" "$work/new.png"
  done
done
echo "same: $same of $total"
exit $status
