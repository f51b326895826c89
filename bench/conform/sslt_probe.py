#!/usr/bin/python3
"""sslt_probe.py - measures povray 3.7's subsurface light transport (SSLT)
on two black-box scenes and prints the tables lib/trace/subsurface.c uses.

The manual ("Subsurface Light Transport") says: the pigment gives the
material's overall appearance, `translucency` the strength of the effect,
the interior's ior matters, mm_per_unit sets the scale (default 10), and
points to Jensen et al., "A Practical Model for Subsurface Light
Transport" (2001).  Its sample scene gives marble as pigment <0.83, 0.79,
0.75> (that paper's diffuse reflectance of marble) and translucency
<0.4562, 0.3811, 0.3325>, which is 1 / (sigma_s' + sigma_a) of the paper's
marble in mm: the mean free path.  What the manual does not say is
measured here:

1. gain G(R, ior): a slab lit and seen head-on, far from edges, renders
   G * R * E where R = pigment * diffuse and E the irradiance; plain
   diffuse renders R * E.  Rendered for a grid of R and ior.
2. the spread: a slab half in shadow (edge along z); the profile across
   the edge is fitted by the dipole of Jensen et al. (half-plane integral
   of R_d(r)) with its reduced albedo alpha' free, for each R.  The table
   gives 1 - alpha' (the reduced absorption fraction) against R.
3. angles: the same lit slab with the light and the camera tilted, to
   check that the gain follows the Fresnel transmittance at both ends
   (printed for information; the model uses Fresnel's law there).

Usage: bench/conform/sslt_probe.py [--quick]   (needs povray, numpy, scipy,
ImageMagick's convert).  Output: C initialisers on stdout.
"""
import os, subprocess, sys, tempfile
import numpy as np
from scipy import integrate, optimize

SLAB = r'''
global_settings { assumed_gamma 1.0 mm_per_unit MM subsurface { samples SAMP, 50 }
  ambient_light 0 }
camera { orthographic location <0,10,0> look_at <0,0,0> right x*2*W up z*2*W*H/WID
  rotate x*VA }
light_source { <0,100,0> rgb LI parallel point_at 0 rotate z*LA }
#if (EDGE) box { <0,4,-100>, <100,5,100> pigment { rgb 0 } no_image } #end
#if (PLANE) plane { y, 0 #else box { <-100,-10,-100>, <100,0,100> #end
  pigment { rgb PC }
  finish { ambient 0 diffuse 1 subsurface { translucency TR } }
  interior { ior IOR } }
'''


def render(work, wid, hei, **kw):
    kw.setdefault("PLANE", 0)
    kw.setdefault("LI", 1)
    src = '#version 3.7;\n' + ''.join('#declare %s = %s;\n' % (k, v) for k, v in kw.items())
    src += '#declare WID = %d; #declare H = %d;\n' % (wid, hei) + SLAB
    pov = os.path.join(work, 's.pov')
    png = os.path.join(work, 's.png')
    with open(pov, 'w') as fh:
        fh.write(src)
    subprocess.run(['povray', '+I' + pov, '+O' + png, '+W%d' % wid,
                    '+H%d' % hei, '-D', '-A', '-GA', '+FN8', 'File_Gamma=srgb',
                    '+WT1'], check=True, stdout=subprocess.DEVNULL,
                   stderr=subprocess.DEVNULL, cwd=work)
    raw = subprocess.run(['convert', png, '-depth', '8', 'rgb:-'],
                         check=True, capture_output=True).stdout
    c = np.frombuffer(raw, dtype='u1').astype(float) / 255.0
    # sRGB codes to linear (IEC 61966-2-1)
    lin = np.where(c <= 0.04045, c / 12.92, ((c + 0.055) / 1.055) ** 2.4)
    return lin.reshape(hei, wid, 3)


def A_of(eta):
    """Boundary term of the dipole (Jensen et al., eq. for F_dr)."""
    fdr = -1.440 / eta ** 2 + 0.710 / eta + 0.668 + 0.0636 * eta
    return (1 + fdr) / (1 - fdr)


def rd(r, q, A):
    """Dipole diffuse reflectance per area at distance r (mm), for
    sigma_t' = 1 / mm and reduced absorption fraction q = 1 - alpha'."""
    a = 1.0 - q
    st = 1.0
    sig = np.sqrt(3.0 * q) * st
    zr = 1.0 / st
    zv = zr * (1 + 4 * A / 3)
    dr = np.sqrt(r * r + zr * zr)
    dv = np.sqrt(r * r + zv * zv)
    return a / (4 * np.pi) * (zr * (sig * dr + 1) * np.exp(-sig * dr) / dr ** 3
                              + zv * (sig * dv + 1) * np.exp(-sig * dv) / dv ** 3)


def total(q, A):
    s = np.sqrt(3 * q)
    return (1 - q) / 2 * (1 + np.exp(-4 / 3 * A * s)) * np.exp(-s)


def beyond(d, q, A):
    """Share of the dipole's reflectance farther than d from a line."""
    f = lambda r: rd(r, q, A) * 2 * r * np.arccos(min(1.0, d / r))
    return integrate.quad(f, d, np.inf, limit=400)[0] / total(q, A)


def main():
    quick = '--quick' in sys.argv
    samp = 100 if quick else 400
    Rs = [0.05, 0.1, 0.2, 0.3, 0.5, 0.7, 0.9]
    iors = [1.0, 1.33, 1.5, 2.0]
    with tempfile.TemporaryDirectory() as work:
        print('/* sslt_probe.py: gain G(R, ior), rows R = %s, columns ior = %s */'
              % (Rs, iors))
        print('static const double sslt_gain[%d][%d] = {' % (len(Rs), len(iors)))
        for R in Rs:
            row = []
            for eta in iors:
                img = render(work, 16, 16, MM=10, SAMP=samp, W=2, VA=0, LA=0,
                             EDGE=0, PC=R, TR=1, IOR=eta)
                row.append(img[..., 0].mean() / R)
            print('  {' + ', '.join('%.4f' % g for g in row) + '},')
        print('};')
        # The spread, from a shadow edge: 64 pixels over 4 units, 10 mm/unit.
        W, MM, wid = 2.0, 10.0, 64
        A = A_of(1.5)
        print('/* sslt_probe.py: 1 - alpha\' fitted to shadow-edge profiles, '
              'ior 1.5, translucency 1, rows R = %s (rms misfit in comments) */'
              % Rs)
        print('static const double sslt_absorb[%d] = {' % len(Rs))
        for R in Rs:
            img = render(work, wid, 8, MM=MM, SAMP=samp, W=W, VA=0, LA=0,
                         EDGE=1, PC=R, TR=1, IOR=1.5)
            prof = img[..., 0].mean(axis=0)
            lit = prof[-6:].mean()
            # the lit side is the larger end
            if prof[:6].mean() > lit:
                prof = prof[::-1]
                lit = prof[-6:].mean()
            idx = range(wid // 2 - 14, wid // 2 + 14)
            px = 2 * W / wid * MM  # mm per pixel

            def misfit(lq):
                q = float(np.exp(lq))
                e = 0.0
                for i in idx:
                    d = (wid / 2 - i - 0.5) * px
                    b = beyond(abs(d), q, A)
                    pred = b if d > 0 else 1 - b
                    e += (pred - prof[i] / lit) ** 2
                return e / len(idx)
            res = optimize.minimize_scalar(misfit, bounds=(np.log(1e-4),
                                                           np.log(0.9)),
                                           method='bounded',
                                           options={'xatol': 0.02})
            print('  %.5f, /* R %.2f: rms %.4f */' %
                  (np.exp(res.x), R, np.sqrt(res.fun)))
        print('};')
        print('/* sslt_probe.py: a plane over a box (half-space over a slab), '
              'head-on, ior 1.5, rows R as above */')
        print('static const double sslt_plane[%d] = {' % len(Rs))
        vals = []
        for R in Rs:
            pl = render(work, 16, 16, MM=10, SAMP=samp, W=2, VA=0, LA=0,
                        EDGE=0, PC=R, TR=1, IOR=1.5, PLANE=1, LI=0.4)[..., 0].mean()
            bx = render(work, 16, 16, MM=10, SAMP=samp, W=2, VA=0, LA=0,
                        EDGE=0, PC=R, TR=1, IOR=1.5, LI=0.4)[..., 0].mean()
            vals.append(pl / bx)
        print('  ' + ', '.join('%.4f' % v for v in vals))
        print('};')
        print('/* sslt_probe.py: gain at tilted light LA / view VA over '
              'head-on, R 0.3, ior 1.5 (Fresnel transmittance ratio beside) */')
        base = render(work, 16, 16, MM=10, SAMP=samp, W=2, VA=0, LA=0,
                      EDGE=0, PC=0.3, TR=1, IOR=1.5)[..., 0].mean()
        for la, va in ((45, 0), (70, 0), (0, 45), (0, 70)):
            v = render(work, 16, 16, MM=10, SAMP=samp, W=2, VA=va, LA=la,
                       EDGE=0, PC=0.3, TR=1, IOR=1.5)[..., 0].mean()
            v /= np.cos(np.radians(la))
            print('/*   LA %d VA %d: %.4f */' % (la, va, v / base))


if __name__ == '__main__':
    main()
