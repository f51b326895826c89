#!/usr/bin/python3
"""
media_shadow.py - light that crosses a medium on its way to a surface,
measured on povray (black box) and set beside zrcube.

A floor (white, diffuse 1, ambient 0) is seen from straight above by an
orthographic camera; a point light at <20, 20, 0> lights it across a
hollow slab 8 <= x <= 9 that holds a medium and that the camera does
not see.  The light a floor pixel gets, divided by what it gets without
the slab, is the transmittance along that pixel's shadow ray.  With
density { gradient x } the density along the ray runs from 0 to 1
across the slab, so where the shadow ray's samples lie shows in the
result:  exact, the optical depth is absorption * L / 2 (L the ray's
length in the slab, about sqrt 2); samples that cover only the first
part of each interval give less.

  /usr/bin/python3 bench/media_shadow.py [ZRCUBE]
  /usr/bin/python3 bench/media_shadow.py --steps SAMPLES [ZRCUBE]

prints, per case, the mean transmittance over the middle row of the
floor for povray and zrcube and, for the gradient cases, the mean
density the transmittance stands for (-ln T / (absorption * L)).
Exits 77 without povray.  Renders are 32x4 pixels, one thread.
"""
import math
import os
import shutil
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "conform"))
import png16  # noqa: E402

POVRAY = os.environ.get("POVRAY") or shutil.which("povray") or ""

SCENE = r"""
#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <0, 10, 0> look_at <0, 0, 0> sky z
         right x * 4 up z * 0.5 }
plane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }
light_source { <20, 20, 0> rgb 1 }
%s
"""

SLAB = ("box { <8, -1, -10>, <9, 30, 10> pigment { rgbf 1 } hollow "
        "interior { media { %s } } }")

# name, absorption (for the mean density), medium or atmosphere text
CASES = [
    ("absorb 1", 1, SLAB % "absorption 1"),
    ("scatter 0.5", 0.5, SLAB % "scattering { 1, 0.5 }"),
]
for method, ivs, smp in [(3, 1, "1, 1"), (3, 1, "3"), (3, 1, "5"),
                         (3, 1, "9"), (3, 2, "3"), (3, 3, "5"),
                         (3, 1, "3 jitter 0.5"), (2, 1, "4, 4"),
                         (1, 1, "50, 50")]:
    CASES.append(("grad m%d i%d s%s" % (method, ivs, smp), 1,
                  SLAB % ("absorption 1 density { function { x - 8 } } "
                          "method %d intervals %d samples %s"
                          % (method, ivs, smp))))

W, H = 32, 4


def read_png16(path):
    """Red channel of a 16-bit RGB PNG, rows top to bottom, 0..1
    (conform/png16.py decodes it)."""
    img = png16.read(path)
    if img.shape[2] != 3:
        raise ValueError("%s: not RGB" % path)
    return img[..., 0].tolist()


def render(tool, tmp, text, tag):
    pov = os.path.join(tmp, tag + ".pov")
    with open(pov, "w") as f:
        f.write(text)
    out = os.path.join(tmp, tag + ".png")
    if os.path.exists(out):
        os.remove(out)
    cmd = [POVRAY if tool == "povray" else tool, "+I" + pov, "+O" + out,
           "+FN16", "File_Gamma=1.0", "+W%d" % W, "+H%d" % H, "-D", "+WT1"]
    if tool == "povray":
        cmd.append("-A")
    subprocess.run(cmd, cwd=tmp, capture_output=True, timeout=300)
    if not os.path.exists(out):
        return None
    # Both write linear codes under File_Gamma=1.0.
    row = read_png16(out)[H // 2]
    return row


def path_lengths():
    """The length inside the slab of each pixel's shadow ray."""
    out = []
    for x in range(W):
        # Pixel centres from x = -2 to 2 (orthographic, right 4 units).
        px = -2 + 4 * (x + 0.5) / W
        dx, dy = 20 - px, 20.0
        n = math.hypot(dx, dy)
        out.append(n / dx)  # length per unit x, slab 1 unit thick
    return out


def step_cases(samples):
    out = []
    for i in range(1, 40):
        f = i / 40.0
        out.append(("step %.3f" % f, 1, SLAB % (
            "absorption 1 density { function { x - 8 } density_map { "
            "[0 rgb 0] [%.5f rgb 0] [%.5f rgb 1] [1 rgb 1] } } method 3 "
            "intervals 1 samples %s" % (f, f + 1e-5, samples))))
    return out


def main():
    global CASES
    if len(sys.argv) > 2 and sys.argv[1] == "--steps":
        CASES = step_cases(sys.argv[2])
        del sys.argv[1:3]
    if not POVRAY:
        print("media_shadow.py: no povray")
        return 77
    tools = [("povray", "povray")]
    if len(sys.argv) > 1:
        tools.append(("zrcube", os.path.abspath(sys.argv[1])))
    lengths = path_lengths()
    with tempfile.TemporaryDirectory() as tmp:
        base = {name: render(t, tmp, SCENE % "", name + "0")
                for name, t in tools}
        print("# case\t" + "\t".join("%s_T\t%s_density" % (n, n)
                                     for n, _ in tools))
        for label, absorb, body in CASES:
            cols = []
            for name, t in tools:
                row = render(t, tmp, SCENE % body, name + "c")
                if row is None or base[name] is None:
                    cols += ["-", "-"]
                    continue
                # The middle half of the row (away from the edges).
                xs = range(W // 4, 3 * W // 4)
                ts = [row[x] / base[name][x] for x in xs]
                ds = [-math.log(max(row[x] / base[name][x], 1e-12)) /
                      (absorb * lengths[x]) for x in xs]
                cols += ["%.4f" % (sum(ts) / len(ts)),
                         "%.4f" % (sum(ds) / len(ds))]
            print(label + "\t" + "\t".join(cols))
            sys.stdout.flush()
    return 0


if __name__ == "__main__":
    sys.exit(main())
