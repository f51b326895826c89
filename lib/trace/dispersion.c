/*
 * dispersion.c - the spectrum of interior { dispersion D
 * dispersion_samples N } ("Dispersion").
 *
 * The manual says that D is the ratio of the violet to the red ior, that
 * "a spectrum is simulated" and that N is its number of colour steps; the
 * rest was measured with POV-Ray 3.7.0.10 (bench/conform/dispersion_probe.py
 * and .pov: a clear slab at 45 degrees before an emitting edge, where each
 * column shows which samples of the spectrum still see white):
 *
 * - A ray refracted into or out of such an interior becomes N rays; sample
 *   i (0 = red .. N - 1 = violet) refracts with ior * D^((i + 0.5) / N - 0.5)
 *   (N = 2, 3, 7 and 100, D = 1.2 and 0.8: within 3e-5 of the ratio).
 * - Sample i's colour is C((i + 1) / N) - C(i / N) of one fixed cumulative
 *   colour C(t), t from red (0) to violet (1); C(1) = (0.9938, 1, 0.9962),
 *   so a white seen through the slab turns a little green.  The table below
 *   is C at t = k / 100, read from povray's levels with N = 100 (16-bit
 *   linear output, each value within 2e-5); between its points C is
 *   linear.  N = 2, 3 and 7 computed from it equal povray's colours within
 *   5e-4 (an eighth of an 8-bit level).
 * - There is no jitter: every row of the probe is the same.
 * - Without an ior in the interior nothing disperses (interior { dispersion
 *   1.2 } alone leaves white white); with ior 1 it tints.
 */
#include "trace/dispersion.h"

#include <math.h>

#define STEPS 100

static const double cumulative[STEPS + 1][3] = {
    {0.00000, 0.00000, 0.00000},
    {0.00687, 0.00000, 0.00000},
    {0.01547, 0.00000, 0.00000},
    {0.02582, 0.00000, 0.00000},
    {0.03856, 0.00000, 0.00000},
    {0.05315, 0.00000, 0.00000},
    {0.06918, 0.00000, 0.00000},
    {0.08696, 0.00000, 0.00000},
    {0.10660, 0.00000, 0.00000},
    {0.12740, 0.00000, 0.00000},
    {0.14929, 0.00000, 0.00000},
    {0.17296, 0.00000, 0.00000},
    {0.19750, 0.00000, 0.00000},
    {0.22289, 0.00000, 0.00000},
    {0.24942, 0.00000, 0.00000},
    {0.27675, 0.00000, 0.00000},
    {0.30468, 0.00038, 0.00000},
    {0.33330, 0.00171, 0.00000},
    {0.36248, 0.00562, 0.00000},
    {0.39191, 0.01115, 0.00000},
    {0.42161, 0.01830, 0.00000},
    {0.45164, 0.02811, 0.00000},
    {0.48167, 0.03934, 0.00000},
    {0.51167, 0.05199, 0.00000},
    {0.54156, 0.06654, 0.00000},
    {0.57121, 0.08264, 0.00000},
    {0.60056, 0.09996, 0.00000},
    {0.62947, 0.11872, 0.00000},
    {0.65766, 0.13892, 0.00000},
    {0.68531, 0.16008, 0.00000},
    {0.71240, 0.18219, 0.00000},
    {0.73823, 0.20578, 0.00000},
    {0.76326, 0.23006, 0.00000},
    {0.78744, 0.25499, 0.00000},
    {0.81012, 0.28090, 0.00000},
    {0.83149, 0.30750, 0.00000},
    {0.85176, 0.33455, 0.00000},
    {0.87053, 0.36207, 0.00000},
    {0.88736, 0.39017, 0.00000},
    {0.90277, 0.41851, 0.00000},
    {0.91670, 0.44700, 0.00000},
    {0.92790, 0.47578, 0.00000},
    {0.93742, 0.50459, 0.00000},
    {0.94524, 0.53339, 0.00000},
    {0.95035, 0.56210, 0.00000},
    {0.95305, 0.59060, 0.00000},
    {0.95430, 0.61888, 0.00006},
    {0.95430, 0.64681, 0.00027},
    {0.95430, 0.67420, 0.00276},
    {0.95430, 0.70114, 0.00674},
    {0.95430, 0.72760, 0.01221},
    {0.95430, 0.75308, 0.01997},
    {0.95430, 0.77787, 0.02905},
    {0.95430, 0.80198, 0.03944},
    {0.95430, 0.82502, 0.05162},
    {0.95430, 0.84691, 0.06516},
    {0.95430, 0.86786, 0.07976},
    {0.95430, 0.88766, 0.09572},
    {0.95430, 0.90587, 0.11312},
    {0.95430, 0.92291, 0.13143},
    {0.95430, 0.93880, 0.15061},
    {0.95430, 0.95245, 0.17118},
    {0.95430, 0.96474, 0.19248},
    {0.95430, 0.97565, 0.21448},
    {0.95430, 0.98441, 0.23745},
    {0.95430, 0.99120, 0.26110},
    {0.95430, 0.99640, 0.28528},
    {0.95430, 0.99956, 0.31006},
    {0.95430, 1.00000, 0.33544},
    {0.95430, 1.00000, 0.36117},
    {0.95430, 1.00000, 0.38720},
    {0.95430, 1.00000, 0.41366},
    {0.95430, 1.00000, 0.44028},
    {0.95430, 1.00000, 0.46703},
    {0.95430, 1.00000, 0.49392},
    {0.95430, 1.00000, 0.52081},
    {0.95430, 1.00000, 0.54762},
    {0.95430, 1.00000, 0.57429},
    {0.95430, 1.00000, 0.60078},
    {0.95430, 1.00000, 0.62702},
    {0.95430, 1.00000, 0.65299},
    {0.95430, 1.00000, 0.67848},
    {0.95430, 1.00000, 0.70352},
    {0.95441, 1.00000, 0.72811},
    {0.95509, 1.00000, 0.75198},
    {0.95630, 1.00000, 0.77514},
    {0.95790, 1.00000, 0.79770},
    {0.96001, 1.00000, 0.81939},
    {0.96246, 1.00000, 0.84009},
    {0.96513, 1.00000, 0.85995},
    {0.96800, 1.00000, 0.87900},
    {0.97108, 1.00000, 0.89650},
    {0.97420, 1.00000, 0.91304},
    {0.97733, 1.00000, 0.92860},
    {0.98035, 1.00000, 0.94260},
    {0.98325, 1.00000, 0.95515},
    {0.98602, 1.00000, 0.96652},
    {0.98854, 1.00000, 0.97639},
    {0.99065, 1.00000, 0.98434},
    {0.99240, 1.00000, 0.99095},
    {0.99380, 1.00000, 0.99620},
};

static zr_rgb cumulative_at(double t) {
  double x = t * STEPS;
  int k = (int)x;
  if (k < 0)
    return zr_rgb3(0, 0, 0);
  if (k >= STEPS)
    return zr_rgb3(cumulative[STEPS][0], cumulative[STEPS][1],
                   cumulative[STEPS][2]);
  double f = x - k;
  const double *a = cumulative[k], *b = cumulative[k + 1];
  return zr_rgb3(a[0] + (b[0] - a[0]) * f, a[1] + (b[1] - a[1]) * f,
                 a[2] + (b[2] - a[2]) * f);
}

zr_rgb zr__dispersion_colour(int i, int n) {
  zr_rgb hi = cumulative_at((double)(i + 1) / n);
  zr_rgb lo = cumulative_at((double)i / n);
  return zr_rgb3(hi.r - lo.r, hi.g - lo.g, hi.b - lo.b);
}

double zr__dispersion_u(int i, int n) { return (i + 0.5) / n - 0.5; }

double zr__dispersed_ior(const zr_interior *in, double u) {
  if (!zr__disperses(in))
    return in ? in->ior : 1.0;
  return in->ior * pow(in->dispersion, u);
}
