#!/bin/sh
# gradient_wrap_probe.sh [RENDERER] - prints the gradient values of
# bench/conform/gradient_wrap_probe.pov as RENDERER (default povray)
# computes them: x, value, value with frequency 3.  povray 3.7.0.10's
# table is recorded in tests/test_gradient_wrap.sh; the rule it gives
# (lib/scene/pattern.c zr__pattern_wave): a value above 1 keeps its
# fraction, then fmod(v frequency + phase, 1.00001), plus 1 while
# negative.
set -u
renderer=${1:-povray}
here=$(cd "$(dirname "$0")" && pwd)
case $renderer in */*) renderer=$(cd "$(dirname "$renderer")" &&
    pwd)/$(basename "$renderer") ;; esac
tmp=$(mktemp -d "${TMPDIR:-/tmp}/zr_gradwrap.XXXXXX") || exit 1
trap 'rm -rf "$tmp"' EXIT
cp "$here/gradient_wrap_probe.pov" "$tmp/"
cd "$tmp" || exit 1
case $renderer in
*povray*) timeout 60 "$renderer" +Igradient_wrap_probe.pov -D +W1 +H1 -F \
    >/dev/null 2>&1 ;;
*) timeout 60 "$renderer" +Igradient_wrap_probe.pov --parse-only -q \
    >/dev/null 2>&1 ;;
esac
cat gradient_wrap.txt
