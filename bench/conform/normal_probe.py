#!/usr/bin/python3
"""normal_probe.py IMAGE.png: the shading normals of normal_probe.pov's
plane, read back from the picture.

The plane faces the camera; three parallel lights at 45 degrees, red from
+x, green from -x, blue from +y, light it with diffuse 1 and nothing
else, so (linear) R = (nz + nx)/sqrt 2, G = (nz - nx)/sqrt 2,
B = (nz + ny)/sqrt 2 as long as no light grazes.  Prints the median nx,
the means of nx, ny, nz and the root mean square of the tilt
|(nx, ny)| / nz over the picture."""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import png16  # noqa: E402

nx, ny, nz = png16.probe_normals(sys.argv[1])
t = np.sqrt(nx ** 2 + ny ** 2) / np.maximum(nz, 1e-9)
tx, ty = nx / np.maximum(nz, 1e-9), ny / np.maximum(nz, 1e-9)
# The spread of the tilt about its mean (a pattern whose tilt has a
# bias, as POV-Ray's wrinkles, keeps it out of this figure).
dev = np.sqrt(tx.var() + ty.var())
print("median_nx %.4f nx %.4f ny %.4f nz %.4f tilt_rms %.4f tilt_dev %.4f" % (
    np.median(nx), nx.mean(), ny.mean(), nz.mean(), np.sqrt((t ** 2).mean()),
    dev))
