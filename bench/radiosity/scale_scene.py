#!/usr/bin/env python3
"""scale_scene.py - scenes for bench/radiosity_scale.sh (issue 11, item 4).

  scale_scene.py mesh N     a closed room (a box seen from inside) lit by
                            an emitting ceiling square, with a bumpy
                            ball as one mesh2 of about N triangles
  scale_scene.py boxes N    the same room with about N surfaces: boxes of
                            six faces each on a grid over the floor

The scene goes to standard output.  Every surface is Lambertian; the
scenes are deterministic (no random numbers).
"""
import math
import sys


def room(out):
    out.append('#version 3.7;')
    out.append('global_settings { assumed_gamma 1.0 }')
    out.append('camera { location <5, 5, 0.5> look_at <5, 3, 10> '
               'angle 70 }')
    out.append('#declare W = texture { pigment { rgb 0.7 } '
               'finish { diffuse 1 ambient 0 } }')
    # The room: a box seen from inside, one surface per face.
    out.append('box { <0, 0, 0>, <10, 10, 10> texture { W } }')
    # The lamp: a thin emitting slab just under the ceiling.
    out.append('box { <4, 9.9, 4>, <6, 9.95, 6> texture { pigment { rgb 1 } '
               'finish { diffuse 0 ambient 0 emission 10 } } }')


def mesh(n_faces, out):
    # A ball of radius 2.5 at the room's centre, bumped so its faces do
    # not all lie on one sphere: n_lat x n_lon quads, two triangles each,
    # the poles fans.
    n_lon = max(4, int(round(math.sqrt(n_faces))))
    n_lat = max(3, int(round(n_faces / (2.0 * n_lon))) + 1)
    verts = []
    for i in range(n_lat + 1):
        th = math.pi * i / n_lat
        for j in range(n_lon):
            ph = 2 * math.pi * j / n_lon
            r = 2.5 * (1 + 0.08 * math.sin(5 * th) * math.cos(4 * ph))
            verts.append((5 + r * math.sin(th) * math.cos(ph),
                          4 + r * math.cos(th),
                          5 + r * math.sin(th) * math.sin(ph)))
    faces = []
    for i in range(n_lat):
        for j in range(n_lon):
            a = i * n_lon + j
            b = i * n_lon + (j + 1) % n_lon
            c = a + n_lon
            d = b + n_lon
            if i > 0:
                faces.append((a, b, d))
            if i < n_lat - 1:
                faces.append((a, d, c))
    out.append('mesh2 {')
    out.append('  vertex_vectors { %d,' % len(verts))
    out.append(',\n'.join('    <%.6f, %.6f, %.6f>' % v for v in verts))
    out.append('  }')
    out.append('  face_indices { %d,' % len(faces))
    out.append(',\n'.join('    <%d, %d, %d>' % f for f in faces))
    out.append('  }')
    out.append('  texture { W }')
    out.append('}')
    return len(faces)


def boxes(n_surfs, out):
    # Six surfaces a box; k x k boxes on the floor, small enough to leave
    # the room open between them.
    n = max(1, (n_surfs - 12) // 6)
    k = int(math.ceil(math.sqrt(n)))
    step = 8.0 / k
    made = 0
    for i in range(k):
        for j in range(k):
            if made == n:
                break
            x = 1 + (i + 0.25) * step
            z = 1 + (j + 0.25) * step
            h = 0.5 + 2.0 * ((i * 7 + j * 3) % 5) / 5.0
            out.append('box { <%.4f, 0, %.4f>, <%.4f, %.4f, %.4f> '
                       'texture { W } }' % (x, z, x + 0.5 * step, h,
                                            z + 0.5 * step))
            made += 1
    return 12 + 6 * made


def main():
    if len(sys.argv) != 3 or sys.argv[1] not in ('mesh', 'boxes'):
        sys.stderr.write('usage: scale_scene.py mesh|boxes N\n')
        return 2
    out = []
    room(out)
    n = int(sys.argv[2])
    count = mesh(n, out) if sys.argv[1] == 'mesh' else boxes(n, out)
    out.insert(0, '// %s: %d %s' % (sys.argv[1], count,
                                   'faces' if sys.argv[1] == 'mesh'
                                   else 'surfaces'))
    sys.stdout.write('\n'.join(out) + '\n')
    return 0


if __name__ == '__main__':
    sys.exit(main())
