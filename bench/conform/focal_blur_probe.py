#!/usr/bin/python3
"""focal_blur_probe.py - how wide a lens POV-Ray 3.7's focal blur uses.

A small bright sphere far behind the focal plane, on a black
background, is drawn by every lens sample at a different place: its
blurred image is the lens disc, scaled by d / f (1 - f / z) pixels per
unit of lens (d the direction's length, f the focal distance, z the
sphere's distance, in pixels of W / |right| per screen unit).  The
image's spread (the light-weighted standard deviation of the pixel
positions, R / 2 per axis for a uniform disc of radius R) gives the
lens radius, printed as a fraction of `aperture`:

    bench/conform/focal_blur_probe.py [RENDERER]

RENDERER is povray (the default) or a zrcube binary.  POV-Ray 3.7.0.10
prints 0.25 (+-0.02) in every case (2026-12-03): the lens radius is
aperture / 4, not the aperture / 2 a diameter would give, whatever the
direction, aperture and focal distance; lib/trace/camera.c follows and
tests/test_focal_blur.sh checks zrcube against these cases.
"""
import os
import subprocess
import sys
import tempfile

import numpy as np
from skimage import io

W, H = 160, 120
# name: direction length d, |right|, aperture, focal distance f, sphere z
CASES = [("a", 1.0, 4.0 / 3.0, 0.5, 1.0, 20.0),
         ("b", 2.0, 4.0 / 3.0, 0.5, 1.0, 20.0),
         ("c", 1.0, 4.0 / 3.0, 1.0, 1.0, 20.0),
         ("e", 1.0, 4.0 / 3.0, 0.5, 2.0, 40.0)]


def scene(d, right, ap, f, z):
    r = 0.3 * z / 20.0  # 1.8 pixels at d = 1
    return f"""#version 3.7;
global_settings {{ assumed_gamma 1 }}
camera {{ location 0 direction {d}*z right {right}*x up y
  focal_point <0, 0, {f}> aperture {ap} blur_samples 200, 200 }}
sphere {{ <0, 0, {z}>, {r} pigment {{ rgb 1 }}
  finish {{ ambient 1 diffuse 0 }} }}
"""


def render(renderer, pov, png):
    if os.path.basename(renderer) == "povray":
        cmd = [renderer, "+I" + pov, "+O" + png, f"+W{W}", f"+H{H}", "-D",
               "-A", "+WT1", "-GA"]
    else:
        cmd = [renderer, "+I" + pov, "+O" + png, f"+W{W}", f"+H{H}", "-D",
               "+WT1"]
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL,
                   stderr=subprocess.DEVNULL)


def main():
    renderer = sys.argv[1] if len(sys.argv) > 1 else "povray"
    with tempfile.TemporaryDirectory() as tmp:
        for name, d, right, ap, f, z in CASES:
            pov = os.path.join(tmp, name + ".pov")
            png = os.path.join(tmp, name + ".png")
            with open(pov, "w") as fh:
                fh.write(scene(d, right, ap, f, z))
            render(renderer, pov, png)
            img = io.imread(png)[..., 0].astype(float)
            ys, xs = np.nonzero(img)
            w = img[ys, xs]
            var = 0.0
            for c in (xs, ys):
                m = np.average(c, weights=w)
                var += np.average((c - m) ** 2, weights=w)
            radius_px = 2.0 * np.sqrt(var / 2.0)
            px_per_lens = d / f * (1.0 - f / z) * W / right
            print(f"{name} lens_radius/aperture "
                  f"{radius_px / px_per_lens / ap:.3f} pixels {len(xs)}")


main()
