#!/bin/sh
# ssim_stock.sh - SSIM of zRcube against POV-Ray 3.7 for named stock scenes.
#
#   bench/conform/ssim_stock.sh ZRCUBE REL.pov...   (REL under the examples dir)
#
# Renders each scene at 160x120, no antialiasing, one thread, with both
# renderers from the scene's folder (POV-Ray's render is cached in
# $CONFORM_CACHE, default /tmp/zr_conform_ref) and prints "ssim  REL",
# SSIM after a 2x2 box filter as ../shared/corpus/compare.py computes it.
set -u
zr=$1; shift
case $zr in /*) ;; *) zr=$(pwd)/$zr ;; esac
ex=/usr/share/doc/povray/examples
inc=/usr/share/povray-3.7/include
cache=${CONFORM_CACHE:-/tmp/zr_conform_ref}
out=${CONFORM_OUT:-/tmp/zr_conform_out}
mkdir -p "$cache" "$out"
here=$(cd "$(dirname "$0")" && pwd)
for rel in "$@"; do
    name=$(printf '%s' "$rel" | sed 's,/,_,g; s,\.pov$,,')
    dir=$(dirname "$ex/$rel")
    if [ ! -s "$cache/$name.png" ]; then
        ( cd "$dir" && timeout 120 povray +I"$ex/$rel" +O"$cache/$name.png" \
            +W160 +H120 -D -A +WT1 -GA +L"$inc" >/dev/null 2>&1 )
    fi
    rm -f "$out/$name.png"
    ( cd "$dir" && timeout 120 "$zr" +I"$ex/$rel" +O"$out/$name.png" \
        +W160 +H120 -D +WT1 >/dev/null 2>"$out/$name.err" )
    s=$(/usr/bin/python3 "$here/ssim.py" "$cache/$name.png" "$out/$name.png")
    printf '%s\t%s\n' "$s" "$rel"
done
