#!/bin/sh
# layering.sh - the folders of lib/ include one another only downward.
#
#   bench/layering.sh [SOURCE_DIR]        (default: the tree it sits in)
#
# The folders form a chain that follows the data (README, "Layering"):
#
#   core < image < fn < scene < trace < radiosity < gi < sdl < par
#
# A file in one folder may include headers of its own folder and of the
# folders before it in the chain, never of one after it.  The grammar's
# generated headers (pov-parse.h, pov-scan.h) belong to the parser and
# so to lib/sdl alone; <mpi.h> belongs to lib/par alone.  Headers
# outside lib/ (zrcube.h, config.h, the tables under bench/) are free.
#
# Each offending line is printed as FILE:LINE: error: ..., and the exit
# status is 1 when there is one, else 0.  tests/test_layering.sh runs it
# on the tree and on a copy with an upward include planted, which it
# must refuse.
set -u
top=${1:-$(cd "$(dirname "$0")/.." && pwd)}
[ -d "$top/lib" ] || { echo "layering.sh: $top has no lib/" >&2; exit 2; }
cd "$top" || exit 2

order="core image fn scene trace radiosity gi sdl par"

# The folder's place in the chain, or nothing when it is not in it.
rank() {
  i=0
  for f in $order; do
    if [ "$f" = "$1" ]; then
      echo $i
      return
    fi
    i=$((i + 1))
  done
}

status=0
# Every lib folder must have its place, so a new one cannot slip by.
for dir in lib/*/; do
  folder=$(basename "$dir")
  if [ -z "$(rank "$folder")" ]; then
    echo "lib/$folder: error: folder not in the layer order ($order)"
    status=1
  fi
done

# FILE:LINE:#include ... for every include of every lib source.
grep -n '^[[:space:]]*#[[:space:]]*include[[:space:]]*[<"]' \
  lib/*/*.c lib/*/*.h >"${TMPDIR:-/tmp}/zr_layering.$$" || true
while IFS= read -r line; do
  file=${line%%:*}
  rest=${line#*:}
  lineno=${rest%%:*}
  text=${rest#*:}
  src=$(echo "$file" | cut -d/ -f2)
  target=$(echo "$text" | sed -n 's/.*include[[:space:]]*[<"]\([^">]*\)[">].*/\1/p')
  case $target in
  mpi.h)
    if [ "$src" != par ]; then
      echo "$file:$lineno: error: <mpi.h> outside lib/par"
      status=1
    fi
    continue ;;
  pov-parse.h | pov-scan.h)
    if [ "$src" != sdl ]; then
      echo "$file:$lineno: error: the grammar's $target outside lib/sdl"
      status=1
    fi
    continue ;;
  */*) ;;
  *) continue ;; # a system header or one beside the file
  esac
  folder=${target%%/*}
  to=$(rank "$folder")
  [ -n "$to" ] || continue # not a lib folder (../../bench/..., ...)
  from=$(rank "$src")
  [ -n "$from" ] || continue # reported above
  if [ "$to" -gt "$from" ]; then
    echo "$file:$lineno: error: lib/$src includes $target," \
         "which is above it ($order)"
    status=1
  fi
done <"${TMPDIR:-/tmp}/zr_layering.$$"
rm -f "${TMPDIR:-/tmp}/zr_layering.$$"
exit $status
