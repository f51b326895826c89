#!/bin/sh
# Parse every stock POV-Ray 3.7 example scene (povray-examples) with
# `zrcube --parse-only` and list, per scene, ok or the first error.
# Prints a summary: how many parse, and the most common first errors.
# Usage: bench/stock.sh [ZRCUBE] [OUTDIR]
# Each scene gets 20 s; a timeout counts as a failure.
set -u
zr=${1:-build/bin/zrcube}
out=${2:-bench/out/stock}
ex=/usr/share/doc/povray/examples
inc=/usr/share/povray-3.7/include
if [ ! -d "$ex" ]; then
    echo "stock.sh: $ex missing (apt-get install povray-examples)" >&2
    exit 77
fi
mkdir -p "$out"
list="$out/list.txt"
: > "$list"
find "$ex" -name '*.pov' | sort | while read -r f; do
    dir=$(dirname "$f")
    err=$( cd "$dir" && timeout 20 "$OLDPWD/$zr" --parse-only -q \
        +L"$inc" +L"$dir" "$f" 2>&1 >/dev/null )
    rc=$?
    rel=${f#$ex/}
    if [ $rc -eq 0 ]; then
        echo "ok $rel" >> "$list"
    elif [ $rc -eq 124 ]; then
        echo "FAIL $rel: timeout" >> "$list"
    else
        first=$(printf '%s\n' "$err" | grep -m1 'error' )
        echo "FAIL $rel: ${first:-exit $rc}" >> "$list"
    fi
done
total=$(wc -l < "$list")
ok=$(grep -c '^ok ' "$list")
echo "stock scenes parsed: $ok / $total"
grep '^FAIL' "$list" | sed 's/^[^:]*: //; s/^[^ ]*:[0-9]*:[0-9]*: //' |
    sort | uniq -c | sort -rn | head -40
