#!/usr/bin/python3
"""
media_curvature_probe.py - when POV-Ray 3.7's media method 3 halves a
cell (lib/trace/media.c, cell_means()), measured black-box with
bench/media_quadrature.py's slab: an orthographic ray through a hollow
box 0 <= z <= D holding an emitting, absorbing medium whose density is a
function of z, over black.  Each case is rendered with the default
aa_threshold and with aa_threshold 100 (or aa_level 1: no halving);
equal values mean povray halved no cell.

Session 9 (povray 3.7.0.10):
  ramp (density z, absorption 5, samples 3): 0.24814 with or without
      halving allowed: a linear density is never halved, though its
      samples differ (the old rule, any difference between neighbouring
      samples, halved it: 0.18184);
  z^2: 0.13701 against 0.14273 unhalved: a curved one is halved, and the
      halved cells' light is the mean of the halves' coefficients times
      the cell's length, dimmed by the cells before it (0.13707; summed
      one half after the other, 0.11306);
  density steps (samples 3, 5, 9, 30): halved, as before.
So the test is the middle sample's distance from the mean of the ends
(the largest channel of |j| + |k| differences), times the interval's
length, against aa_threshold / 6: for a step, half of the old
neighbour difference against aa_threshold / 3, the bracket
bench/media_quadrature.py measured.

  /usr/bin/python3 bench/conform/media_curvature_probe.py [ZRCUBE]
Exits 77 without povray.
"""
import os
import shutil
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                ".."))
from media_shadow import read_png16  # noqa: E402

POVRAY = os.environ.get("POVRAY") or shutil.which("povray") or ""
SLAB = r"""
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0, 0, -50> look_at 0
         right 0.01 * x up 0.01 * y }
background { rgb 0 }
box { <-1, -1, 0>, <1, 1, %(D)g> hollow pigment { rgbt 1 }
  interior { media { emission %(e)g absorption %(a)g %(extra)s } } }
"""
def run(r, D, e, a, extra):
    if r is None:
        return "-"
    open('s.pov','w').write(SLAB % dict(D=D, e=e, a=a, extra=extra))
    if r == 'pov':
        subprocess.run([POVRAY,'+Is.pov','+Os.png','+W1','+H1','-D','-A','+WT1','-GA','+FN16','File_Gamma=1'],capture_output=True)
    else:
        subprocess.run([r,'+Is.pov','+Os.png','+W1','+H1','-D','-A','+WT1','+FN16','File_Gamma=1'],capture_output=True)
    v = read_png16('s.png')[0][0]
    return round(v,5)
cases = [
 ('ramp s3 default', 1, 1, 5, 'method 3 samples 3 density { function { z } }'),
 ('ramp s3 thr100', 1, 1, 5, 'method 3 samples 3 aa_threshold 100 density { function { z } }'),
 ('ramp s3 aal1', 1, 1, 5, 'method 3 samples 3 aa_level 1 density { function { z } }'),
 ('curv s3 default', 1, 1, 5, 'method 3 samples 3 density { function { z*z } }'),
 ('curv s3 thr100', 1, 1, 5, 'method 3 samples 3 aa_threshold 100 density { function { z*z } }'),
 ('step s3 default', 1, 1, 0, 'method 3 samples 3 density { function { z > 0.05 } }'),
 ('step s3 thr100', 1, 1, 0, 'method 3 samples 3 aa_threshold 100 density { function { z > 0.05 } }'),
 ('step s30 default', 1, 1, 0, 'method 3 samples 30,30 density { function { z > 0.01 } }'),
 ('step s30 thr100', 1, 1, 0, 'method 3 samples 30,30 aa_threshold 100 density { function { z > 0.01 } }'),
 ('step s9 default', 1, 1, 0, 'method 3 samples 9,9 density { function { z > 0.03 } }'),
 ('step s9 thr100', 1, 1, 0, 'method 3 samples 9,9 aa_threshold 100 density { function { z > 0.03 } }'),
 ('step s5 default', 1, 1, 0, 'method 3 samples 5,5 density { function { z > 0.03 } }'),
 ('step s5 thr100', 1, 1, 0, 'method 3 samples 5,5 aa_threshold 100 density { function { z > 0.03 } }'),
]
if not POVRAY:
    sys.exit(77)
zr = os.path.abspath(sys.argv[1]) if len(sys.argv) > 1 else None
os.chdir(tempfile.mkdtemp())
for name, D, e, a, extra in cases:
    p = run('pov', D, e, a, extra); z = run(zr, D, e, a, extra)
    print("%-20s pov %s  zr %s" % (name, p, z))
