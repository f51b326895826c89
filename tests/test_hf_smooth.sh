#!/bin/sh
# test_hf_smooth.sh - a smooth height field's normals as POV-Ray 3.7 makes
# them (lib/trace/obj_height_field.c vertex_normal and crossing_normal;
# lib/sdl/build_hf.c keeps a function's samples as 16-bit codes):
# per grid point the unit normals of the four quarters between its
# neighbours, summed, kept as multiples of 1/32767 toward zero in grid
# units, and blended bilinearly over the square.  The normals below are
# povray 3.7.0.10's, from trace() through #debug (tests/hf_smooth.pov,
# 5 x 5 samples of 0.3 x y + 0.6 x^2 - 0.4 y^3 + 0.3, and of the ramp x,
# whose grid points povray gives slope 2, not 1); each component must be
# within 2e-4.  The tree before this test (central differences blended
# over the triangle) was off by up to 0.19 (ramp: -0.70711 0.70711 0).
#
# Environment: ZR_SRCDIR, ZR_BUILDDIR (set by `make check`).
set -u
. "${ZR_SRCDIR:-$(cd "$(dirname "$0")/.." && pwd)}/tests/render_env.sh"
timeout 60 "$zrcube" +I"$srcdir/tests/hf_smooth.pov" +Oz.png +W8 +H8 -D \
  +WT1 </dev/null >z.log 2>&1 || { cat z.log >&2; exit 1; }
cat > want.txt <<'WANT'
normal hf 0.50 0.50 -0.68883 0.70712 -0.15967
normal hf 0.25 0.25 -0.46558 0.70712 -0.53218
normal hf 0.75 0.25 -0.82649 0.44723 -0.34189
normal hf 0.50 0.00 -0.67314 0.44723 -0.58896
normal hf 0.60 0.30 -0.71763 0.61537 -0.32607
normal hf 0.30 0.60 -0.42243 0.89735 -0.12770
normal hf 0.70 0.80 -0.67158 0.73474 0.09561
normal ramp 0.50 0.50 -0.89442 0.44724 0.00000
normal ramp 0.62 0.40 -0.89442 0.44724 0.00000
WANT
grep '^normal ' z.log > got.txt
awk 'NR == FNR { want[FNR] = $0; n = FNR; next }
     { split(want[FNR], w, " "); bad = 0
       for (k = 5; k <= 7; k++) { d = $k - w[k]; if (d < 0) d = -d
                                  if (d > 2e-4) bad = 1 }
       print $0 (bad ? "   FAIL, povray: " want[FNR] : "   ok"); fails += bad }
     END { if (FNR != n) { print "got " FNR " lines, want " n; fails++ }
           exit fails > 0 }' want.txt got.txt
