#!/usr/bin/python3
"""gi_truth.py - the emissive Cornell box's error against a truth that
can be trusted, and where that error sits (issue 11).

  gi_truth.py [--truth T.pfm] [--map OUT.png] [--second T2.pfm] IMAGE.pfm...
  gi_truth.py --reduce WxH OUT.pfm [--truth T.pfm]

The truth defaults to ../shared/reference/cbox_emissive-256.pfm (4096
samples a pixel at 256x256).  An IMAGE of another size (128x128, as
bench/gi_error.sh renders) is compared with the truth reduced to its
size by the mean of each block of truth pixels: a pixel of a box-filtered
path tracer is the mean radiance over its area, so the mean of the 2x2
pixels that tile it is the same quantity with 4x the samples.  The score
is tests/imgcmp --rmse's: both pictures clipped to [0, 1] in linear
light, 2x2 box filtered, RMS difference over the truth's clipped mean.

Each pixel is labelled by the surface its centre sees (the scene's
triangles, read from scenes/cornell.pov, hit by the camera's rays here
in numpy: floor, ceiling, back, green and red walls, light, short block's top
and sides, tall block's top and sides), and the squared error is split
among the labels: "share" is the label's part of the total squared error,
"rel" the label's own RMS error over the whole picture's clipped mean.
"edges" are the 2x2 blocks whose pixels see more than one label, where
antialiasing, not global illumination, decides.

--second T2.pfm: a second truth of the same scene (another seed or
renderer); the score between the two truths, from which each one's noise
is sqrt(score^2 / 2) when they carry equal noise.
--reduce WxH OUT.pfm: writes the truth reduced to W x H (the truth that
bench/gi_error.sh scores the emissive box against).
--map OUT.png: a picture of the error per box-filtered pixel (grey,
|image - truth| / truth mean, white at 0.5; red where the image is too
bright, blue where too dark).
"""
import os
import re
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
TOP = os.path.dirname(HERE)
SCENE = os.path.join(TOP, "scenes", "cornell.pov")
TRUTH = os.path.join(TOP, "..", "shared", "reference", "cbox_emissive-256.pfm")


def read_pfm(path):
    with open(path, "rb") as f:
        kind = f.readline().strip()
        if kind != b"PF":
            sys.exit("gi_truth.py: %s: not a colour PFM" % path)
        dims = f.readline().split()
        while len(dims) < 2:
            dims += f.readline().split()
        w, h = int(dims[0]), int(dims[1])
        scale = float(f.readline())
        data = np.frombuffer(f.read(w * h * 12), "<f4" if scale < 0 else ">f4")
    # PFM rows go bottom to top.
    return data.reshape(h, w, 3)[::-1].astype(np.float64)


def reduce_to(img, h, w):
    H, W = img.shape[:2]
    if (H, W) == (h, w):
        return img
    if H % h or W % w:
        sys.exit("gi_truth.py: the truth's %dx%d is no multiple of %dx%d"
                 % (W, H, w, h))
    return img.reshape(h, H // h, w, W // w, 3).mean(axis=(1, 3))


def box2(a):
    h, w = a.shape[0] // 2 * 2, a.shape[1] // 2 * 2
    a = a[:h, :w]
    return a.reshape(h // 2, 2, w // 2, 2, *a.shape[2:]).mean(axis=(1, 3))


def rel_rmse(img, truth):
    a = box2(np.clip(img, 0, 1))
    t = box2(np.clip(truth, 0, 1))
    return np.sqrt(np.mean((a - t) ** 2)) / t.mean(), a, t


# ---- pixel labels from the scene's triangles ----

def scene_triangles():
    text = open(SCENE).read()
    unions = re.findall(r"union\s*\{(.*?)\n\}", text, re.S)
    tris, ids = [], []
    num = r"<\s*([-\d.]+)\s*,\s*([-\d.]+)\s*,\s*([-\d.]+)\s*>"
    for k, body in enumerate(unions):
        for t in re.findall(r"triangle\s*\{\s*%s\s*,\s*%s\s*,\s*%s" %
                            (num, num, num), body):
            tris.append(np.array(t, float).reshape(3, 3))
            ids.append((k, len([i for i in ids if i[0] == k])))
    return tris, ids


# union order in scenes/cornell.pov: light, white room (floor 2, ceiling
# 2, back 2), green wall (x = 0), red wall, short block (top 2, sides 8),
# tall block (top 2, sides 8).
def label_of(uid):
    k, i = uid
    if k == 0:
        return "light"
    if k == 1:
        return ("floor", "ceiling", "back")[i // 2]
    if k == 2:
        return "green wall"
    if k == 3:
        return "red wall"
    part = "short" if k == 4 else "tall"
    return part + (" top" if i < 2 else " sides")


def labels(h, w):
    # The scene's camera: location, direction <0,0,1> lengthened so the
    # right vector (length 1) spans angle 39.5 degrees, up <0,1,0>,
    # right <-1,0,0>.
    loc = np.array([27.8, 27.3, -80.0])
    dlen = 0.5 / np.tan(np.radians(39.5) / 2)
    ys, xs = np.mgrid[0:h, 0:w]
    u = (xs + 0.5) / w - 0.5
    v = 0.5 - (ys + 0.5) / h
    d = np.stack([-u, v, np.full_like(u, dlen)], axis=-1).reshape(-1, 3)
    best = np.full(len(d), np.inf)
    lab = np.full(len(d), -1)
    tris, ids = scene_triangles()
    for n, t in enumerate(tris):
        e1, e2 = t[1] - t[0], t[2] - t[0]
        p = np.cross(d, e2)
        det = p @ e1
        ok = np.abs(det) > 1e-12
        inv = np.where(ok, 1.0 / np.where(ok, det, 1.0), 0.0)
        s = loc - t[0]
        a = (p @ s) * inv
        q = np.cross(s, e1)
        b = (d @ q) * inv
        tt = (q @ e2) * inv
        hit = ok & (a >= 0) & (b >= 0) & (a + b <= 1) & (tt > 1e-9) & (tt < best)
        best[hit] = tt[hit]
        lab[hit] = n
    names = [label_of(i) for i in ids]
    return np.array([names[i] if i >= 0 else "none" for i in lab]).reshape(h, w)


def report(path, truth_full, lab_cache):
    img = read_pfm(path)
    h, w = img.shape[:2]
    truth = reduce_to(truth_full, h, w)
    e, a, t = rel_rmse(img, truth)
    if (h, w) not in lab_cache:
        lab_cache[(h, w)] = labels(h, w)
    lab = lab_cache[(h, w)]
    # A box-filtered pixel's label: its four pixels' label when they
    # agree, else "edges".
    l4 = lab[:h // 2 * 2, :w // 2 * 2].reshape(h // 2, 2, w // 2, 2)
    l4 = l4.transpose(0, 2, 1, 3).reshape(h // 2, w // 2, 4)
    same = (l4 == l4[..., :1]).all(axis=-1)
    blab = np.where(same, l4[..., 0], "edges")
    sq = ((a - t) ** 2).sum(axis=-1)
    mean = t.mean()
    total = sq.sum()
    print("%s (%dx%d): rel_rmse %.4f against the truth reduced to its size"
          % (os.path.basename(path), w, h, e))
    print("  %-12s %6s %7s %7s %8s" % ("label", "pixels", "share", "rel",
                                      "bias"))
    for name in sorted(set(blab.ravel()), key=lambda s: -sq[blab == s].sum()):
        m = blab == name
        bias = (a[m] - t[m]).mean() / max(t[m].mean(), 1e-12)
        print("  %-12s %6d %6.1f%% %7.4f %+7.1f%%" %
              (name, m.sum(), 100 * sq[m].sum() / total,
               np.sqrt(sq[m].sum() / (3 * m.size)) / mean, 100 * bias))
    return img, truth, a, t


def write_map(path, a, t):
    diff = (a - t).mean(axis=-1) / t.mean()
    mag = np.clip(np.abs(diff) / 0.5, 0, 1)
    rgb = np.stack([mag, mag, mag], axis=-1)
    rgb[..., 2] = np.where(diff < 0, mag, mag * 0.3)
    rgb[..., 0] = np.where(diff > 0, mag, mag * 0.3)
    rgb[..., 1] = mag * 0.3
    from skimage import io, transform
    big = transform.resize(rgb, (rgb.shape[0] * 4, rgb.shape[1] * 4),
                           order=0)
    io.imsave(path, (big * 255).astype(np.uint8), check_contrast=False)


def write_pfm(path, img):
    h, w = img.shape[:2]
    with open(path, "wb") as f:
        f.write(b"PF\n%d %d\n-1.0\n" % (w, h))
        f.write(img[::-1].astype("<f4").tobytes())


def main(argv):
    truth_path, map_path, second, reduce = TRUTH, None, None, None
    files = []
    it = iter(argv)
    for arg in it:
        if arg == "--truth":
            truth_path = next(it)
        elif arg == "--map":
            map_path = next(it)
        elif arg == "--second":
            second = next(it)
        elif arg == "--reduce":
            w, h = (int(v) for v in next(it).split("x"))
            reduce = (w, h, next(it))
        else:
            files.append(arg)
    truth = read_pfm(truth_path)
    if reduce is not None:
        write_pfm(reduce[2], reduce_to(truth, reduce[1], reduce[0]))
        return 0
    cache = {}
    if second is not None:
        t2 = read_pfm(second)
        h, w = t2.shape[:2]
        e, _, _ = rel_rmse(t2, reduce_to(truth, h, w))
        print("%s against %s at %dx%d: %.4f" % (os.path.basename(second),
              os.path.basename(truth_path), w, h, e))
    for f in files:
        img, tr, a, t = report(f, truth, cache)
        if map_path is not None:
            write_map(map_path, a, t)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
