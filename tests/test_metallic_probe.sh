#!/bin/sh
# test_metallic_probe.sh - the metallic probes of bench/metallic_probe.sh
# (highlight and reflection tints by angle and amount) rendered by zrcube
# and by POV-Ray 3.7 (skipped, exit 77, without povray).  The pixel
# values must agree within 2e-3 and the tint strengths k within 6e-4:
# our curve is a fit to POV-Ray's whose largest error in k is 3.8e-4
# (bench/metallic_fit.py), and POV-Ray's 16-bit output is rounded.
#
# Environment: ZR_SRCDIR, ZR_BUILDDIR, POVRAY (set by `make check`).
set -u
srcdir=${ZR_SRCDIR:-$(cd "$(dirname "$0")/.." && pwd)}
zrcube=${ZR_BUILDDIR:-$(pwd)}/bin/zrcube
povray=${POVRAY:-povray}
if ! command -v "$povray" >/dev/null 2>&1; then
    echo "test_metallic_probe.sh: no povray, skipped"
    exit 77
fi
work=$(mktemp -d "${TMPDIR:-/tmp}/zr_metallic_probe.XXXXXX") || exit 99
trap 'rm -rf "$work"' EXIT
sh "$srcdir/bench/metallic_probe.sh" "$povray" > "$work/pov.txt"
sh "$srcdir/bench/metallic_probe.sh" "$zrcube" > "$work/zr.txt"
if [ "$(wc -l < "$work/pov.txt")" -lt 55 ]; then
    echo "test_metallic_probe.sh: POV-Ray's probe is incomplete" >&2
    exit 99
fi
paste -d '|' "$work/pov.txt" "$work/zr.txt" | awk -F '|' '
    {
        np = split($1, p, " "); nz = split($2, z, " ")
        if (np != 9 || nz != 9) { print "line " NR ": " $0; errors++; next }
        for (i = 1; i <= 4; i++)
            if (p[i] != z[i]) { print "line " NR ": " $0; errors++; next }
        for (i = 5; i <= 9; i++) {
            d = p[i] - z[i]; if (d < 0) d = -d
            if (d > (i <= 7 ? 2e-3 : 6e-4)) {
                print "POV-Ray " $1 "\n zrcube " $2; errors++; next
            }
        }
        checked++
    }
    END {
        print checked " metallic probes agree, " errors + 0 " differ"
        exit errors > 0
    }'
