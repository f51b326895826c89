#!/usr/bin/python3
"""ssim.py REF.png OUT.png: SSIM after a 2x2 box filter, 8-bit RGB, as
../shared/corpus/compare.py computes it; prints '-' when OUT is missing."""
import sys
import numpy as np
from skimage import io
from skimage.metrics import structural_similarity


def load(path):
    img = np.asarray(io.imread(path))
    if img.dtype == np.uint16:
        img = (img.astype(np.float64) / 257.0).round()
    img = img.astype(np.float64)
    if img.ndim == 2:
        img = np.stack([img] * 3, axis=-1)
    img = img[..., :3]
    h, w = img.shape[0] // 2 * 2, img.shape[1] // 2 * 2
    img = img[:h, :w]
    return (img[0::2, 0::2] + img[1::2, 0::2] + img[0::2, 1::2]
            + img[1::2, 1::2]) / 4.0


try:
    a = load(sys.argv[1])
    b = load(sys.argv[2])
except Exception:
    print('-')
    sys.exit(0)
if a.shape != b.shape:
    print('-')
    sys.exit(0)
print('%.4f' % structural_similarity(a, b, channel_axis=-1, data_range=255.0))
