#!/bin/sh
# SSIM of zRcube against POV-Ray 3.7 on every stock example that uses
# media or warps, for one or two zrcube builds (before and after a
# change), with POV-Ray's own convergence beside it.  This replaces the
# two earlier copies (media_before_after.sh, media_ssim.sh).
#
# Usage: bench/media_warp_ssim.sh AFTER [BEFORE] [OUTDIR]
#   AFTER, BEFORE: zrcube commands (words split on blanks, so
#   "env LD_LIBRARY_PATH=/tmp/old/lib /tmp/old/zrcube" works; a path
#   relative to the current folder is made absolute).  Without BEFORE
#   only AFTER is rendered.
#
# A scene counts when the scene or a file of its own folder that it
# #includes holds one of the words media, warp, media_attenuation or
# media_interaction (grep -w; hollow1.pov has only media_attenuation,
# balcony.pov's warps are in building.inc and terrain.inc).
# MEDIA_WARP_ONLY=regex keeps only the scenes whose path matches,
# MEDIA_WARP_SKIP=regex leaves out those that match.
#
# Each scene is rendered at 160x120, no antialiasing, one thread, from
# its own folder, as /work/shared/corpus/compare.py does; SSIM is taken
# on 8-bit RGB after a 2x2 box filter (skimage).  POV-Ray's pictures are
# kept in OUTDIR/ref (default bench/out/media_warp) and reused; with
# POVRAY_CACHE=DIR, DIR/<path with / as _>.png is copied in first (e.g.
# the conformance run's cache).  For scenes with media POV-Ray also
# renders a copy with 4 times the samples (bench/media_more_samples.py)
# unless MEDIA_WARP_NO4X=1: the SSIM of its two pictures says whether
# POV-Ray's own image is converged.  Renders get MEDIA_WARP_TIMEOUT
# seconds each (default 600).  Prints one line per scene:
#   scene  before  after  povray_vs_povray4x  after_seconds
# ("-" where not rendered, exit-N when a renderer failed).
# Exits 77 without povray or its examples.
set -u
mk_cmd() {
    set -- $1
    case $1 in /*|env) ;; *) [ -e "$1" ] && set -- "$(pwd)/$1" ${2+"$@"} ;; esac
    echo "$*"
}
[ $# -ge 1 ] || { echo "usage: $0 AFTER [BEFORE] [OUTDIR]" >&2; exit 2; }
after=$(mk_cmd "$1")
before=${2:+$(mk_cmd "$2")}
out=${3:-bench/out/media_warp}
mkdir -p "$out/ref" "$out/before" "$out/after"
out=$(cd "$out" && pwd)
here=$(cd "$(dirname "$0")" && pwd)
ex=/usr/share/doc/povray/examples
inc=/usr/share/povray-3.7/include
tmo=${MEDIA_WARP_TIMEOUT:-600}
if [ ! -d "$ex" ] || ! command -v povray >/dev/null 2>&1; then
    echo "media_warp_ssim.sh: needs povray and povray-examples" >&2
    exit 77
fi
tmp=$(mktemp -d "${TMPDIR:-/tmp}/zr_mw.XXXXXX") || exit 1
trap 'rm -rf "$tmp"' EXIT
words='-e media -e warp -e media_attenuation -e media_interaction'

ssim() {
    [ -s "$1" ] && [ -s "$2" ] || { echo -; return; }
    /usr/bin/python3 - "$1" "$2" <<'PY'
import sys
import numpy as np
from skimage import io
from skimage.metrics import structural_similarity
def load(p):
    a = np.asarray(io.imread(p))
    if a.dtype == np.uint16:
        a = (a / 257.0).round()
    a = a.astype(np.float64)
    if a.ndim == 2:
        a = np.stack([a] * 3, axis=-1)
    return a[..., :3]
def box2(a):
    h, w = a.shape[0] // 2 * 2, a.shape[1] // 2 * 2
    a = a[:h, :w]
    return (a[0::2, 0::2] + a[1::2, 0::2] + a[0::2, 1::2] + a[1::2, 1::2]) / 4
a, b = load(sys.argv[1]), load(sys.argv[2])
if a.shape != b.shape:
    print('size')
else:
    print('%.4f' % structural_similarity(box2(a), box2(b), channel_axis=2,
                                         data_range=255.0))
PY
}

# The scenes: those that say a word themselves, and those that include a
# file of their own folder that does.
(cd "$ex" && find . -name '*.pov' | sed 's|^\./||' | sort) > "$tmp/all"
while read -r rel; do
    dir=$ex/$(dirname "$rel")
    if grep -qw $words "$ex/$rel"; then
        echo "$rel"
        continue
    fi
    for f in $(sed -n 's/^[[:space:]]*#include[[:space:]]*"\([^"]*\)".*/\1/p' \
               "$ex/$rel"); do
        if [ -f "$dir/$f" ] && grep -qw $words "$dir/$f"; then
            echo "$rel"
            break
        fi
    done
done < "$tmp/all" | grep -E "${MEDIA_WARP_ONLY:-.}" |
    grep -vE "${MEDIA_WARP_SKIP:-^\$}" > "$tmp/list"

# render WHICH CMD REL NAME: zrcube CMD's picture of REL in OUT/WHICH.
render() {
    dir=$ex/$(dirname "$3")
    rm -f "$out/$1/$4.png"
    (cd "$dir" && timeout "$tmo" $2 +I"$ex/$3" +O"$out/$1/$4.png" \
        +W160 +H120 -D +WT1 +L"$inc" +L"$dir" \
        </dev/null >/dev/null 2>"$out/$1/$4.log")
}

printf '# scene\tbefore\tafter\tpovray_vs_povray4x\tafter_seconds\n'
while read -r rel; do
    dir=$ex/$(dirname "$rel")
    name=$(echo "$rel" | sed 's|/|_|g; s|\.pov$||')
    ref=$out/ref/$name.png
    ref4=$out/ref/$name.4x.png
    if [ ! -s "$ref" ] && [ -n "${POVRAY_CACHE:-}" ] &&
       [ -s "$POVRAY_CACHE/$name.png" ]; then
        cp "$POVRAY_CACHE/$name.png" "$ref"
    fi
    [ -s "$ref" ] ||
        (cd "$dir" && timeout "$tmo" povray +I"$ex/$rel" +O"$ref" \
            +W160 +H120 -D -A +WT1 -GA +L"$inc" +L"$dir" \
            </dev/null >/dev/null 2>&1) || rm -f "$ref"
    conv=-
    if [ "${MEDIA_WARP_NO4X:-0}" != 1 ] && grep -qw media "$ex/$rel"; then
        if [ ! -s "$ref4" ]; then
            /usr/bin/python3 "$here/media_more_samples.py" "$ex/$rel" \
                "$tmp/s.pov" 4 >/dev/null
            (cd "$dir" && timeout "$tmo" povray +I"$tmp/s.pov" +O"$ref4" \
                +W160 +H120 -D -A +WT1 -GA +L"$inc" +L"$dir" \
                </dev/null >/dev/null 2>&1) || rm -f "$ref4"
        fi
        conv=$(ssim "$ref" "$ref4")
    fi
    b=-
    if [ -n "$before" ]; then
        if render before "$before" "$rel" "$name"; then
            b=$(ssim "$ref" "$out/before/$name.png")
        else
            b=exit-$?
        fi
    fi
    t0=$(date +%s.%N)
    if render after "$after" "$rel" "$name"; then
        a=$(ssim "$ref" "$out/after/$name.png")
    else
        a=exit-$?
    fi
    t1=$(date +%s.%N)
    printf '%s\t%s\t%s\t%s\t%.1f\n' "$rel" "$b" "$a" "$conv" \
        "$(echo "$t1 - $t0" | bc)"
done < "$tmp/list"
