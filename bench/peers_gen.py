#!/usr/bin/python3
"""peers_gen.py - the scenes of bench/peers.sh in POV-Ray's and Tachyon's
formats (issue 13).

    bench/peers_gen.py OUT_DIR
    bench/peers_gen.py --smooth OUT_DIR

writes OUT_DIR/flake.pov and flake.dat (the sphereflake: 7,381 spheres,
four levels of nine children below one root, on a plane, three lights,
reflective spheres), OUT_DIR/terrain.pov and terrain.dat (a height field
of 256 x 256 vertices as 130,050 flat triangles: a POV `mesh` of
`triangle`s, Tachyon `TRI`s), OUT_DIR/csg.pov (CSG-heavy, POV-Ray and
zRcube only: Tachyon has no CSG), and OUT_DIR/empty.pov and empty.dat (a
camera and a light, for the start-up memory).  The resolution is given on each
renderer's command line, not in the files.  With --smooth it writes only
OUT_DIR/sterrain.pov and sterrain.dat: the terrain's grid as smooth
triangles with the surface's normals (`smooth_triangle`s, Tachyon `STRI`s),
for bench/mesh_parse.sh.

The two formats describe the same geometry seen by the same camera.  The
cameras match by measurement, not by a constant from either program:
Tachyon's `ZOOM 1` was measured here to show a half-width of 0.5 at
distance 1 on a square image (a sphere of radius 1 at distance 10 spans
20 of 200 pixels, the silhouette's tan = 1/sqrt(99)), which is a POV-Ray
camera with `right x up y direction z` (POV-Ray 3.7 manual, 2.3.1.1
"Placing the Camera": the image plane is `right` wide at distance
|direction|).  Both are left-handed with x right and y up (a triangle at
+x appears on the right in both).  Lighting and materials are as close as
the two shading languages allow (POV-Ray's `reflection` against Tachyon's
`SPECULAR`, which is its mirror coefficient); the benchmark times the
renderers, it does not compare their pictures.
"""
import math
import sys

# The camera both formats share: eye, target, and a square image.
FLAKE_EYE = (-3.2, 3.4, -4.6)
FLAKE_AT = (0.0, 1.2, 0.0)
TERRAIN_EYE = (0.0, 6.0, -9.0)
TERRAIN_AT = (0.0, 0.0, 0.5)


def sub(a, b):
    return tuple(x - y for x, y in zip(a, b))


def add(a, b):
    return tuple(x + y for x, y in zip(a, b))


def scale(a, s):
    return tuple(x * s for x in a)


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0])


def unit(a):
    return scale(a, 1.0 / math.sqrt(dot(a, a)))


def vec(a):
    return "<%.6f, %.6f, %.6f>" % a


def tvec(a):
    return "%.6f %.6f %.6f" % a


def camera_pov(eye, at):
    return ("camera { perspective location %s right x up y direction z\n"
            "  look_at %s }\n" % (vec(eye), vec(at)))


def camera_dat(eye, at):
    view = unit(sub(at, eye))
    up = unit(sub((0.0, 1.0, 0.0), scale(view, view[1])))
    return ("CAMERA\n  ZOOM 1.0\n  ASPECTRATIO 1.0\n  ANTIALIASING 0\n"
            "  RAYDEPTH 5\n  CENTER %s\n  VIEWDIR %s\n  UPDIR %s\n"
            "END_CAMERA\n" % (tvec(eye), tvec(view), tvec(up)))


def frame(axis):
    """Two unit vectors perpendicular to axis and to each other."""
    helper = (1.0, 0.0, 0.0) if abs(axis[0]) < 0.9 else (0.0, 0.0, 1.0)
    u = unit(cross(axis, helper))
    return u, cross(axis, u)


def flake(centre, radius, axis, depth, out):
    """The sphereflake: a sphere and nine children a third its size,
    six around its equator and three above, each touching it."""
    out.append((centre, radius))
    if depth == 0:
        return
    u, v = frame(axis)
    child = radius / 3.0
    dirs = []
    for i in range(6):
        a = i * math.pi / 3.0
        dirs.append(add(scale(u, math.cos(a)), scale(v, math.sin(a))))
    elevation = math.radians(55.0)
    for i in range(3):
        a = i * 2.0 * math.pi / 3.0 + math.pi / 6.0
        side = add(scale(u, math.cos(a)), scale(v, math.sin(a)))
        dirs.append(unit(add(scale(side, math.cos(elevation)),
                             scale(axis, math.sin(elevation)))))
    for d in dirs:
        flake(add(centre, scale(d, radius + child)), child, d, depth - 1, out)


LIGHTS = [((-6.0, 8.0, -6.0), 0.6), ((5.0, 7.0, -4.0), 0.5),
          ((1.0, 9.0, 6.0), 0.4)]


def write_flake(dirname):
    spheres = []
    flake((0.0, 1.0, 0.0), 1.0, (0.0, 1.0, 0.0), 4, spheres)
    assert len(spheres) == 7381
    with open(dirname + "/flake.pov", "w") as f:
        f.write("// sphereflake: %d spheres on a plane, 3 lights, "
                "reflection (bench/peers_gen.py)\n" % len(spheres))
        f.write("#version 3.7;\nglobal_settings { assumed_gamma 1 "
                "max_trace_level 5 }\n")
        f.write("background { rgb <0.1, 0.1, 0.2> }\n")
        f.write(camera_pov(FLAKE_EYE, FLAKE_AT))
        for pos, c in LIGHTS:
            f.write("light_source { %s, rgb %.3f }\n" % (vec(pos), c))
        f.write("#declare Ball = texture { pigment { rgb <0.9, 0.8, 0.6> }"
                " finish { ambient 0.1 diffuse 0.7 reflection 0.4 } }\n")
        f.write("plane { y, 0 texture { pigment { rgb <0.4, 0.5, 0.4> }"
                " finish { ambient 0.1 diffuse 0.8 } } }\n")
        for c, r in spheres:
            f.write("sphere { %s, %.6f texture { Ball } }\n" % (vec(c), r))
    with open(dirname + "/flake.dat", "w") as f:
        f.write("BEGIN_SCENE\n  RESOLUTION 512 512\n")
        f.write(camera_dat(FLAKE_EYE, FLAKE_AT))
        f.write("BACKGROUND 0.1 0.1 0.2\n")
        for pos, c in LIGHTS:
            f.write("LIGHT CENTER %s RAD 0.01 COLOR %.3f %.3f %.3f\n"
                    % (tvec(pos), c, c, c))
        f.write("TEXDEF ball AMBIENT 0.1 DIFFUSE 0.7 SPECULAR 0.4 "
                "OPACITY 1.0 COLOR 0.9 0.8 0.6 TEXFUNC 0\n")
        f.write("TEXDEF ground AMBIENT 0.1 DIFFUSE 0.8 SPECULAR 0.0 "
                "OPACITY 1.0 COLOR 0.4 0.5 0.4 TEXFUNC 0\n")
        f.write("PLANE CENTER 0 0 0 NORMAL 0 1 0 ground\n")
        for c, r in spheres:
            f.write("SPHERE CENTER %s RAD %.6f ball\n" % (tvec(c), r))
        f.write("END_SCENE\n")


def height(x, z):
    return (0.6 * math.sin(0.9 * x) * math.cos(0.7 * z)
            + 0.25 * math.sin(2.3 * x + 1.1 * z)
            + 0.1 * math.cos(5.1 * z - 3.7 * x))


def grid_triangles(pts):
    """Two triangles for each cell of a grid of points (rows of rows)."""
    tris = []
    for j in range(len(pts) - 1):
        for i in range(len(pts[j]) - 1):
            a, b = pts[j][i], pts[j][i + 1]
            c, d = pts[j + 1][i], pts[j + 1][i + 1]
            tris.append((a, b, c))
            tris.append((b, d, c))
    return tris


def terrain_pov_head(f, what):
    """The POV terrain's header, up to its open mesh."""
    f.write("// %s (bench/peers_gen.py)\n" % what)
    f.write("#version 3.7;\nglobal_settings { assumed_gamma 1 }\n")
    f.write("background { rgb <0.5, 0.6, 0.8> }\n")
    f.write(camera_pov(TERRAIN_EYE, TERRAIN_AT))
    for pos, c in LIGHTS[:2]:
        f.write("light_source { %s, rgb %.3f }\n" % (vec(pos), c))
    f.write("mesh {\n")


TERRAIN_POV_TAIL = ("  texture { pigment { rgb <0.6, 0.55, 0.4> }"
                    " finish { ambient 0.1 diffuse 0.8 } }\n}\n")


def terrain_dat_head(f):
    """The Tachyon terrain's header, up to its triangles."""
    f.write("BEGIN_SCENE\n  RESOLUTION 512 512\n")
    f.write(camera_dat(TERRAIN_EYE, TERRAIN_AT))
    f.write("BACKGROUND 0.5 0.6 0.8\n")
    for pos, c in LIGHTS[:2]:
        f.write("LIGHT CENTER %s RAD 0.01 COLOR %.3f %.3f %.3f\n"
                % (tvec(pos), c, c, c))
    f.write("TEXDEF land AMBIENT 0.1 DIFFUSE 0.8 SPECULAR 0.0 "
            "OPACITY 1.0 COLOR 0.6 0.55 0.4 TEXFUNC 0\n")


def write_terrain(dirname):
    n = 256
    size = 10.0
    pts = [[(-size / 2 + size * i / (n - 1),
             height(-size / 2 + size * i / (n - 1),
                    -size / 2 + size * j / (n - 1)),
             -size / 2 + size * j / (n - 1)) for i in range(n)]
           for j in range(n)]
    tris = grid_triangles(pts)
    assert len(tris) == 130050
    with open(dirname + "/terrain.pov", "w") as f:
        terrain_pov_head(f, "terrain: %d triangles in one mesh, 2 lights"
                         % len(tris))
        for t in tris:
            f.write("  triangle { %s, %s, %s }\n" % tuple(vec(p) for p in t))
        f.write(TERRAIN_POV_TAIL)
    with open(dirname + "/terrain.dat", "w") as f:
        terrain_dat_head(f)
        for t in tris:
            f.write("TRI V0 %s V1 %s V2 %s land\n" % tuple(tvec(p) for p in t))
        f.write("END_SCENE\n")


def height_normal(x, z):
    """The unit normal of the height field at (x, z), from height()'s
    derivatives."""
    dx = (0.6 * 0.9 * math.cos(0.9 * x) * math.cos(0.7 * z)
          + 0.25 * 2.3 * math.cos(2.3 * x + 1.1 * z)
          + 0.1 * 3.7 * math.sin(5.1 * z - 3.7 * x))
    dz = (-0.6 * 0.7 * math.sin(0.9 * x) * math.sin(0.7 * z)
          + 0.25 * 1.1 * math.cos(2.3 * x + 1.1 * z)
          - 0.1 * 5.1 * math.sin(5.1 * z - 3.7 * x))
    return unit((-dx, 1.0, -dz))


def write_smooth_terrain(dirname):
    """The terrain's grid as 130,050 smooth triangles (POV
    `smooth_triangle`s with the surface's normal at each corner, Tachyon
    `STRI`s): sterrain.pov and sterrain.dat, for bench/mesh_parse.sh."""
    n = 256
    size = 10.0
    def at(i, j):
        x = -size / 2 + size * i / (n - 1)
        z = -size / 2 + size * j / (n - 1)
        return (x, height(x, z), z), height_normal(x, z)
    pts = [[at(i, j) for i in range(n)] for j in range(n)]
    tris = grid_triangles(pts)
    with open(dirname + "/sterrain.pov", "w") as f:
        terrain_pov_head(f, "smooth terrain: %d smooth triangles in one mesh"
                         % len(tris))
        for t in tris:
            f.write("  smooth_triangle { %s, %s, %s, %s, %s, %s }\n"
                    % tuple(vec(v) for p in t for v in p))
        f.write(TERRAIN_POV_TAIL)
    with open(dirname + "/sterrain.dat", "w") as f:
        terrain_dat_head(f)
        for t in tris:
            f.write("STRI V0 %s V1 %s V2 %s N0 %s N1 %s N2 %s land\n"
                    % (tvec(t[0][0]), tvec(t[1][0]), tvec(t[2][0]),
                       tvec(t[0][1]), tvec(t[1][1]), tvec(t[2][1])))
        f.write("END_SCENE\n")


def write_csg(dirname):
    """A 20 x 20 grid of CSG pieces: boxes with holes (difference),
    rounded dice (intersection), unions of cylinders, and a merge."""
    with open(dirname + "/csg.pov", "w") as f:
        f.write("// CSG-heavy: a 20 x 20 grid of differences, intersections,"
                " unions and merges (bench/peers_gen.py)\n")
        f.write("#version 3.7;\nglobal_settings { assumed_gamma 1 }\n")
        f.write("background { rgb <0.2, 0.2, 0.3> }\n")
        f.write(camera_pov((0.0, 14.0, -16.0), (0.0, 0.0, 0.0)))
        for pos, c in LIGHTS[:2]:
            f.write("light_source { %s, rgb %.3f }\n"
                    % (vec(scale(pos, 2.0)), c))
        f.write("plane { y, 0 pigment { checker rgb 0.3 rgb 0.7 } }\n")
        f.write("#declare Piece = array[4] {\n"
                "  difference { box { -0.5, 0.5 }\n"
                "    cylinder { -x, x, 0.3 } cylinder { -y, y, 0.3 }\n"
                "    cylinder { -z, z, 0.3 } },\n"
                "  intersection { box { -0.5, 0.5 } sphere { 0, 0.68 } },\n"
                "  union { cylinder { -0.5*x, 0.5*x, 0.2 }\n"
                "    cylinder { -0.5*z, 0.5*z, 0.2 } sphere { 0, 0.3 } },\n"
                "  merge { sphere { -0.15*x, 0.35 } sphere { 0.15*x, 0.35 }\n"
                "    pigment { rgbf <0.8, 0.9, 1, 0.6> }"
                " finish { reflection 0.1 } }\n"
                "}\n")
        f.write("#declare I = 0;\n#while (I < 400)\n"
                "  object { Piece[mod(I, 4)]\n"
                "    scale 0.5 rotate <17 * I, 31 * I, 0>\n"
                "    translate <0.6 * mod(I, 20) - 5.7, 0.4,"
                " 0.6 * div(I, 20) - 5.7>\n"
                "    pigment { rgb <0.5 + 0.5 * mod(I, 3) / 2, 0.6,"
                " 0.9 - 0.4 * mod(I, 5) / 4> } }\n"
                "  #declare I = I + 1;\n#end\n")


def write_empty(dirname):
    """The camera and a light alone: the start-up memory of each
    renderer, which peers.sh subtracts to state bytes per primitive."""
    with open(dirname + "/empty.pov", "w") as f:
        f.write("#version 3.7;\nglobal_settings { assumed_gamma 1 }\n")
        f.write(camera_pov(FLAKE_EYE, FLAKE_AT))
        f.write("light_source { <0, 10, 0>, rgb 1 }\n")
    with open(dirname + "/empty.dat", "w") as f:
        f.write("BEGIN_SCENE\n  RESOLUTION 512 512\n")
        f.write(camera_dat(FLAKE_EYE, FLAKE_AT))
        f.write("LIGHT CENTER 0 10 0 RAD 0.01 COLOR 1 1 1\n")
        f.write("END_SCENE\n")


def main():
    if len(sys.argv) == 3 and sys.argv[1] == "--smooth":
        write_smooth_terrain(sys.argv[2])
        return 0
    if len(sys.argv) != 2:
        sys.stderr.write("usage: peers_gen.py [--smooth] OUT_DIR\n")
        return 2
    write_flake(sys.argv[1])
    write_terrain(sys.argv[1])
    write_csg(sys.argv[1])
    write_empty(sys.argv[1])
    return 0


if __name__ == "__main__":
    sys.exit(main())
