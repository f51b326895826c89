"""png16.py: read an 8- or 16-bit non-interlaced RGB/RGBA/grey PNG into a
float array in [0, 1] (numpy and zlib only: skimage's reader drops 16-bit
files to 8 bits)."""
import struct
import zlib

import numpy as np


def read(path):
    data = open(path, 'rb').read()
    assert data[:8] == b'\x89PNG\r\n\x1a\n', path
    pos, idat = 8, b''
    while pos < len(data):
        n, kind = struct.unpack('>I4s', data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + n]
        if kind == b'IHDR':
            w, h, depth, ctype, _, _, inter = struct.unpack('>IIBBBBB', body)
        elif kind == b'IDAT':
            idat += body
        pos += 12 + n
    assert inter == 0 and depth in (8, 16), path
    chans = {0: 1, 2: 3, 4: 2, 6: 4}[ctype]
    bpp = chans * depth // 8
    stride = w * bpp
    raw = zlib.decompress(idat)
    out = np.zeros((h, stride), np.uint8)
    prev = np.zeros(stride, np.int32)
    for y in range(h):
        f = raw[y * (stride + 1)]
        line = np.frombuffer(raw, np.uint8, stride, y * (stride + 1) + 1)
        cur = line.astype(np.int32)
        if f == 2:
            cur = (cur + prev) & 255
        elif f != 0:
            cur = cur.copy()
            for x in range(stride):
                a = cur[x - bpp] if x >= bpp else 0
                b = prev[x]
                c = prev[x - bpp] if x >= bpp else 0
                if f == 1:
                    cur[x] = (cur[x] + a) & 255
                elif f == 3:
                    cur[x] = (cur[x] + (a + b) // 2) & 255
                else:
                    p = a + b - c
                    pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                    pr = a if pa <= pb and pa <= pc else (b if pb <= pc else c)
                    cur[x] = (cur[x] + pr) & 255
        out[y] = cur
        prev = cur
    if depth == 16:
        v = out.reshape(h, w * chans, 2).astype(np.float64)
        img = (v[..., 0] * 256 + v[..., 1]) / 65535.0
    else:
        img = out.astype(np.float64) / 255.0
    return img.reshape(h, w, chans)


def probe_normals(path):
    """The shading normal (nx, ny, nz) of each pixel of a render of
    normal_probe.pov's set-up: a plane facing the camera lit with diffuse
    1 by three parallel lights at 45 degrees, red from +x, green from -x,
    blue from +y, so (linear) R = (nz + nx)/sqrt 2, G = (nz - nx)/sqrt 2,
    B = (nz + ny)/sqrt 2 while no light grazes."""
    a = read(path)[..., :3]
    a = np.where(a <= 0.04045, a / 12.92, ((a + 0.055) / 1.055) ** 2.4)
    r, g, b = a[..., 0], a[..., 1], a[..., 2]
    s = 2 ** 0.5
    nx, nz = (r - g) / s, (r + g) / s
    return nx, s * b - nz, nz
