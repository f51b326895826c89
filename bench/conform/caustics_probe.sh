#!/bin/sh
# caustics_probe.sh - measures povray 3.7's simulated caustics
# (interior { caustics P }): tests/caustics_check.pov rendered by povray
# at 16 bits in linear light (File_Gamma=1.0) with the caustic disc or
# slab, divided by the same render without caustics (P = 0).  The ratio
# is the factor by which the light through the surfaces grows.  What it
# printed here (povray 3.7.0.10):
#   0 0.25 0 2.0000 | 0 1 0 2.0000 | 10 1 0 1.5021 | 20 0.25 0 1.4967
#   20 0.5 0 1.2467 | 20 1 0 1.0609 | 40 0.25 0 1.0499 | 20 0.5 1 1.5543
# i.e. 1 + cos^(45 P) per crossed surface (cos 20 deg ^ 45 = 0.0609,
# cos 10 deg ^ 45 = 0.5021, (cos 40 deg ^ 45) ^ 0.25 = 0.0499, the slab
# 1.2467^2), whatever the ior (1.5 gives the same 1.2467) and filter
# (0.5 doubles at normal incidence too).  tests/test_caustics.sh holds
# these values.  Usage: bench/conform/caustics_probe.sh (needs povray,
# python3 with numpy).
set -eu
PY=${PYTHON:-/usr/bin/python3}
here=$(cd "$(dirname "$0")" && pwd)
scene=$here/../../tests/caustics_check.pov
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
render() { # th p slab -> linear value at the image centre
  povray +I"$scene" +Oout.png +W8 +H8 -D -A +WT1 -GA +FN16 File_Gamma=1.0 \
    Declare=TH="$1" Declare=P="$2" Declare=Slab="$3" >/dev/null 2>&1
  $PY -c "import sys; sys.path.insert(0, '$here'); import png16; print(png16.read('out.png')[4, 4, 0])"
}
for c in "0 0.25 0" "0 1 0" "10 1 0" "20 0.25 0" "20 0.5 0" "20 1 0" \
         "40 0.25 0" "20 0.5 1"; do
  set -- $c
  base=$(render "$1" 0 "$3")
  with=$(render "$1" "$2" "$3")
  $PY -c "print('$1 $2 $3 %.4f' % ($with / $base))"
done
