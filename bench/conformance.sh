#!/bin/sh
# conformance.sh - does zRcube render the picture POV-Ray 3.7 renders?
#
#   bench/conformance.sh [BUILD_DIR] [stock|corpus|all] [extra options]
#
# stock:  POV-Ray's example scenes (povray-examples), rendered by both
#         renderers at 160x120, no AA, one thread (bench/conformance.py;
#         POV-Ray's images are cached in bench/out/conformance/povray).
# corpus: the real-world scenes of ../shared/corpus against their POV-Ray
#         references (its compare.py), when that folder is present.
# Prints one line per scene and a summary line per set (SSIM >= 0.95 is a
# match, >= 0.80 close).  Tables go to bench/out/conformance/*.tsv.
# Needs /usr/bin/python3 with numpy and skimage (python3-skimage).
set -u
here=$(cd "$(dirname "$0")" && pwd)
top=$(cd "$here/.." && pwd)
build=$(cd "${1:-$top/build}" && pwd)
set_=${2:-all}
[ $# -ge 2 ] && shift 2 || shift $#
. "$here/zrexe.sh"
zr=$zrcube
out=$here/out/conformance
mkdir -p "$out"
py=/usr/bin/python3
if ! $py -c 'import numpy, skimage' 2>/dev/null; then
  echo "conformance.sh: needs python3-numpy and python3-skimage" >&2
  exit 77
fi
rc=0
case $set_ in stock|all)
  $py "$here/conformance.py" --zrcube "$zr" --out "$out" "$@" |
    tee "$out/stock.tsv" || rc=1 ;;
esac
case $set_ in corpus|all)
  corpus=$top/../shared/corpus
  if [ -f "$corpus/compare.py" ]; then
    $py "$corpus/compare.py" --timeout 60 --out "$out/corpus" \
      --renderer "$zr +I{scene} +O{out} +W160 +H120 -D +WT1" "$@" |
      tee "$out/corpus.tsv" || rc=1
  else
    echo "conformance.sh: $corpus not found; corpus skipped" >&2
  fi ;;
esac
exit $rc
