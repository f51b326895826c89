#!/bin/sh
# Parse every stock POV-Ray 3.7 example scene (povray-examples) with
# `zrcube --parse-only` and list, per scene, ok or the first error.
# When POV-Ray 3.7 is installed, each scene is also handed to it (an
# 8x6 image, no display, nothing written) to learn which scenes POV-Ray
# itself parses and renders: issue 3's target is the share of those.
# Prints a summary: how many parse, and the most common first errors.
# Usage: bench/stock.sh [ZRCUBE] [OUTDIR]
# Each scene gets 20 s with zRcube and 60 s with POV-Ray; a zRcube
# timeout counts as a failure, a POV-Ray timeout as a render (it got
# past parsing).  POVRAY=none skips POV-Ray; a list from an earlier run
# (OUTDIR/povray.txt) is reused unless STOCK_POVRAY_AGAIN=1.
set -u
zr=${1:-build/bin/zrcube}
case $zr in /*) ;; *) zr=$(pwd)/$zr ;; esac
out=${2:-bench/out/stock}
ex=/usr/share/doc/povray/examples
inc=/usr/share/povray-3.7/include
povray=${POVRAY:-povray}
if [ ! -d "$ex" ]; then
    echo "stock.sh: $ex missing (apt-get install povray-examples)" >&2
    exit 77
fi
mkdir -p "$out"
list="$out/list.txt"
plist="$out/povray.txt"
: > "$list"
use_povray=0
if [ "$povray" != none ] && command -v "$povray" >/dev/null 2>&1; then
    use_povray=1
    if [ -s "$plist" ] && [ "${STOCK_POVRAY_AGAIN:-0}" != 1 ]; then
        use_povray=2
    else
        : > "$plist"
    fi
fi
tmp=$(mktemp -d "${TMPDIR:-/tmp}/zr_stock.XXXXXX") || exit 1
trap 'rm -rf "$tmp"' EXIT
find "$ex" -name '*.pov' | sort | while read -r f; do
    dir=$(dirname "$f")
    rel=${f#$ex/}
    err=$( cd "$dir" && timeout 20 "$zr" --parse-only -q \
        +L"$inc" +L"$dir" "$f" 2>&1 >/dev/null )
    rc=$?
    if [ $rc -eq 0 ]; then
        echo "ok $rel" >> "$list"
    elif [ $rc -eq 124 ]; then
        echo "FAIL $rel: timeout" >> "$list"
    else
        first=$(printf '%s\n' "$err" | grep -m1 'error' )
        echo "FAIL $rel: ${first:-exit $rc}" >> "$list"
    fi
    if [ $use_povray = 1 ]; then
        ( cd "$dir" && timeout 60 "$povray" +I"$f" +W8 +H6 -D -F +WT1 \
            +L"$inc" +L"$dir" +O"$tmp/out.png" >/dev/null 2>"$tmp/err" )
        prc=$?
        # "Possible Parse Error" is only a warning.
        if { [ $prc -eq 0 ] || [ $prc -eq 124 ]; } &&
            ! grep 'Parse Error' "$tmp/err" | grep -qv 'Possible Parse'
        then
            echo "ok $rel" >> "$plist"
        else
            echo "FAIL $rel: $(grep -v 'Possible Parse' "$tmp/err" |
                grep -m1 -i 'error')" >> "$plist"
        fi
    fi
done
total=$(wc -l < "$list")
ok=$(grep -c '^ok ' "$list")
echo "stock scenes parsed: $ok / $total"
if [ $use_povray != 0 ]; then
    pov_ok=$(grep -c '^ok ' "$plist")
    both=$(grep '^ok ' "$plist" | cut -d' ' -f2 | sort > "$tmp/p"
           grep '^ok ' "$list" | cut -d' ' -f2 | sort > "$tmp/z"
           comm -12 "$tmp/p" "$tmp/z" | wc -l)
    echo "POV-Ray 3.7 renders: $pov_ok / $total"
    echo "of those, zRcube parses: $both / $pov_ok" \
         "($(awk "BEGIN { printf \"%.1f\", 100 * $both / $pov_ok }")%)"
fi
grep '^FAIL' "$list" | sed 's/^[^:]*: //; s/^[^ ]*:[0-9]*:[0-9]*: //' |
    sort | uniq -c | sort -rn | head -40
