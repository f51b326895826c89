/*
 * pattern_tiling.c - the tiling pattern (reference manual, "Tiling
 * Pattern"): tilings of the x-z plane by polygons, the same whatever y.
 *
 * The manual numbers 27 tilings and gives each its count N of tile
 * types; a tile of type k takes the values k/N at its heart to (k+1)/N
 * at its edges, the range between being the bevel, the same for every
 * tile of the tiling.  Measured against povray 3.7 (function { pigment
 * { tiling n color_map { [0 rgb 0] [1 rgb 1] } } }), the bevel is linear
 * in the distance d to the tile's nearest edge: the value is (k + b) / N
 * with the bevel b = max(0, 1 - d / D), D the inradius of the tiling's
 * smallest tile (0 at a square's centre; the octagons of 7 are flat
 * inside).
 *
 * Each tiling here is a period rectangle [0, w) x [0, h) and the convex
 * tiles that cover it, which may reach out of it: a point is brought into
 * the rectangle and tried against the tiles of it and its eight
 * neighbours.  The tile that holds the point deepest wins, so on an edge
 * the first listed does; povray breaks such ties its own way, which only
 * shows on the edges themselves.
 *
 * Tilings 1 (squares), 2 (hexagons), 3 (triangles), 4 (rhombi), 5 (the
 * three rhombi of a cube seen along its diagonal), 6 (bricks in two
 * directions), 7 (octagons and squares), 8 (squares and triangles), 9
 * (hexagons and triangles), 10 (squares in offset rows), 11 (squares in
 * pinwheels of bricks), 12 (a basket weave with squares), 13 (squares
 * and trapezoids), 15 (squares of two sizes) and 18 (a basket weave)
 * are in; the others are refused by number when the scene is read
 * (zr__pattern_tiling_known).
 */
#include <math.h>
#include <stddef.h>

#include "scene/pattern.h"

#define MAX_CORNERS 8
#define MAX_TILES 20

typedef struct tile {
  int type;
  int n;                          /* corners, counterclockwise in x-z */
  double corner[MAX_CORNERS][2]; /* (x, z) */
} tile;

typedef struct tiling {
  int number;
  int types; /* N: the manual's "tiling type" */
  double w, h;
  double inradius; /* D, the bevel's width */
  int n_tiles;
  tile tiles[MAX_TILES];
} tiling;

#define S3 1.7320508075688772 /* sqrt(3) */
#define H3 0.8660254037844386 /* sqrt(3) / 2 */
#define L8 2.414213562373095  /* 1 + sqrt(2): tiling 7's period */
#define H8 1.2071067811865475 /* its octagons' inradius */
#define R2 0.7071067811865476 /* sqrt(2) / 2 */

/* An axis-aligned rectangle of type k. */
#define RECT(k, x0, z0, x1, z1)                                            \
  { k, 4, { {x0, z0}, {x1, z0}, {x1, z1}, {x0, z1} } }

/*
 * The tilings as measured (to 1e-7 off the edges of the tiles):
 *   1  unit squares from the origin;
 *   2  hexagons of unit side with a corner on +x, centred at (-1, 0)
 *      plus the lattice (3, 0), (1.5, sqrt(3) / 2);
 *   3  triangles of unit side, one on the x axis from 0 to 1, pointing
 *      up (+z, type 0) or down (type 1); povray gives the other type on
 *      the lines x = k / 2 through their corners, as if its own ties lay
 *      there, which this leaves alone;
 *   4  rhombi of unit side and 60 degrees, one from (0, 0), (1, 0) and
 *      (0.5, sqrt(3) / 2), all alike;
 *   5  the hexagons of 2 centred at (0.5, sqrt(3) / 2) instead, split
 *      from the centre to every other corner: types 0, 2 and 1
 *      counterclockwise from the rhombus below the centre;
 *   6  2 x 1 bricks along x (type 0) and 1 x 2 ones along z (type 1), in
 *      steps of (1, 1);
 *   7  octagons of unit side (type 1) centred on the lattice of side
 *      1 + sqrt(2), with squares turned 45 degrees (type 0) between them;
 *   8  rows of unit squares (type 2) along x, and between them rows of
 *      unit triangles pointing up (type 0) and down (type 1), each row
 *      of squares half a square along from the one below;
 *   9  hexagons of unit side (type 2) centred at (0.5, sqrt(3) / 2) plus
 *      the lattice (2, 0), (1, sqrt(3)), with a triangle pointing up
 *      (type 0) and one down (type 1) between each two;
 *  10  unit squares in rows along x, each row half a square along from
 *      the last, the square from the origin in the row above it;
 *  11  unit squares (type 0) on the lattice of side 3, each in a
 *      pinwheel of 2 x 1 bricks along x (type 1) and along z (type 2);
 *  12  four 1 x 2 bricks along z (type 2) filling [-1, 1] x [-2, 2],
 *      four 2 x 1 ones along x (type 1) filling [-2, 2] x [2, 4] and unit
 *      squares (type 0) from (1, 1) and (-2, 1), all repeated on the
 *      lattice (3, 3), (3, -3);
 *  13  squares of side sqrt(2) (type 0) centred on the lattice of side
 *      2 sqrt(2) from (sqrt(2), sqrt(2)), and between them trapezoids
 *      sqrt(2) / 2 wide, split down the middle of each gap: along z
 *      (type 2) and along x (type 1), meeting on the diagonals;
 *  15  unit squares (type 0) from the origin and the lattice (2, 1),
 *      (-1, 2), each with a 2 x 2 square (type 1) on top of it;
 *  18  2 x 2 squares of two bricks, along z (type 1) from the origin and
 *      along x (type 0) next to them, in a checkerboard.
 */
static const tiling tilings[] = {
    {1, 1, 1, 1, 0.5, 1, {{0, 4, {{0, 0}, {1, 0}, {1, 1}, {0, 1}}}}},
    {2, 1, 3, S3, H3, 2,
     {{0, 6, {{0, 0}, {-0.5, H3}, {-1.5, H3}, {-2, 0}, {-1.5, -H3},
              {-0.5, -H3}}},
      {0, 6, {{1.5, H3}, {1, S3}, {0, S3}, {-0.5, H3}, {0, 0}, {1, 0}}}}},
    {3, 2, 1, S3, S3 / 6, 4,
     {{0, 3, {{0, 0}, {1, 0}, {0.5, H3}}},
      {1, 3, {{0.5, H3}, {1, 0}, {1.5, H3}}},
      {0, 3, {{0.5, H3}, {1.5, H3}, {1, S3}}},
      {1, 3, {{0.5, H3}, {1, S3}, {0, S3}}}}},
    {4, 1, 1, S3, H3 / 2, 2,
     {{0, 4, {{0, 0}, {1, 0}, {1.5, H3}, {0.5, H3}}},
      {0, 4, {{0.5, H3}, {1.5, H3}, {2, S3}, {1, S3}}}}},
    {5, 3, 3, S3, S3 / 4, 6,
     {{0, 4, {{0.5, H3}, {0, 0}, {1, 0}, {1.5, H3}}},
      {2, 4, {{0.5, H3}, {1.5, H3}, {1, S3}, {0, S3}}},
      {1, 4, {{0.5, H3}, {0, S3}, {-0.5, H3}, {0, 0}}},
      {0, 4, {{2, S3}, {1.5, H3}, {2.5, H3}, {3, S3}}},
      {2, 4, {{2, S3}, {3, S3}, {2.5, 3 * H3}, {1.5, 3 * H3}}},
      {1, 4, {{2, S3}, {1.5, 3 * H3}, {1, S3}, {1.5, H3}}}}},
    {6, 2, 4, 4, 0.5, 8,
     {RECT(0, 1, 0, 3, 1), RECT(0, 2, 1, 4, 2), RECT(0, 3, 2, 5, 3),
      RECT(0, 4, 3, 6, 4), RECT(1, 0, 0, 1, 2), RECT(1, 1, 1, 2, 3),
      RECT(1, 2, 2, 3, 4), RECT(1, 3, 3, 4, 5)}},
    {7, 2, L8, L8, 0.5, 2,
     {{1, 8, {{H8, 0.5}, {0.5, H8}, {-0.5, H8}, {-H8, 0.5}, {-H8, -0.5},
              {-0.5, -H8}, {0.5, -H8}, {H8, -0.5}}},
      {0, 4, {{L8 / 2 + R2, L8 / 2}, {L8 / 2, L8 / 2 + R2},
              {L8 / 2 - R2, L8 / 2}, {L8 / 2, L8 / 2 - R2}}}}},
    {8, 3, 1, 2 + S3, S3 / 6, 6,
     {RECT(2, 0, 0, 1, 1),
      {0, 3, {{0, 1}, {1, 1}, {0.5, 1 + H3}}},
      {1, 3, {{0.5, 1 + H3}, {1, 1}, {1.5, 1 + H3}}},
      RECT(2, 0.5, 1 + H3, 1.5, 2 + H3),
      {0, 3, {{0.5, 2 + H3}, {1.5, 2 + H3}, {1, 2 + S3}}},
      {1, 3, {{1, 2 + S3}, {1.5, 2 + H3}, {2, 2 + S3}}}}},
    {9, 3, 2, 2 * S3, S3 / 6, 6,
     {{2, 6, {{1.5, H3}, {1, S3}, {0, S3}, {-0.5, H3}, {0, 0}, {1, 0}}},
      {2, 6, {{2.5, 3 * H3}, {2, 2 * S3}, {1, 2 * S3}, {0.5, 3 * H3},
              {1, S3}, {2, S3}}},
      {0, 3, {{1, 0}, {2, 0}, {1.5, H3}}},
      {0, 3, {{0, S3}, {1, S3}, {0.5, 3 * H3}}},
      {1, 3, {{0.5, -H3}, {1, 0}, {0, 0}}},
      {1, 3, {{1.5, H3}, {2, S3}, {1, S3}}}}},
    {10, 1, 1, 2, 0.5, 2, {RECT(0, -0.5, -1, 0.5, 0), RECT(0, 0, 0, 1, 1)}},
    {11, 3, 3, 3, 0.5, 5,
     {RECT(0, 1, 1, 2, 2), RECT(2, 0, 0, 1, 2), RECT(1, 1, 0, 3, 1),
      RECT(2, 2, 1, 3, 3), RECT(1, 0, 2, 2, 3)}},
    {12, 3, 6, 6, 0.5, 20,
     {RECT(2, -1, -2, 0, 0), RECT(2, -1, 0, 0, 2), RECT(2, 0, -2, 1, 0),
      RECT(2, 0, 0, 1, 2), RECT(1, -2, 2, 0, 3), RECT(1, 0, 2, 2, 3),
      RECT(1, -2, 3, 0, 4), RECT(1, 0, 3, 2, 4), RECT(0, 1, 1, 2, 2),
      RECT(0, -2, 1, -1, 2), RECT(2, 2, 1, 3, 3), RECT(2, 2, 3, 3, 5),
      RECT(2, 3, 1, 4, 3), RECT(2, 3, 3, 4, 5), RECT(1, 1, 5, 3, 6),
      RECT(1, 3, 5, 5, 6), RECT(1, 1, 6, 3, 7), RECT(1, 3, 6, 5, 7),
      RECT(0, 4, 4, 5, 5), RECT(0, 1, 4, 2, 5)}},
    {13, 3, 4 * R2, 4 * R2, R2 / 2, 5,
     {{0, 4, {{R2, R2}, {3 * R2, R2}, {3 * R2, 3 * R2}, {R2, 3 * R2}}},
      {2, 4, {{0, 0}, {R2, R2}, {R2, 3 * R2}, {0, 4 * R2}}},
      {2, 4, {{4 * R2, 0}, {4 * R2, 4 * R2}, {3 * R2, 3 * R2}, {3 * R2, R2}}},
      {1, 4, {{0, 0}, {4 * R2, 0}, {3 * R2, R2}, {R2, R2}}},
      {1, 4, {{0, 4 * R2}, {R2, 3 * R2}, {3 * R2, 3 * R2}, {4 * R2, 4 * R2}}}}},
    {15, 2, 5, 5, 0.5, 10,
     {RECT(0, 0, 0, 1, 1), RECT(1, 0, 1, 2, 3), RECT(0, 2, 1, 3, 2),
      RECT(1, 2, 2, 4, 4), RECT(0, 4, 2, 5, 3), RECT(1, 4, 3, 6, 5),
      RECT(0, 1, 3, 2, 4), RECT(1, 1, 4, 3, 6), RECT(0, 3, 4, 4, 5),
      RECT(1, 3, 5, 5, 7)}},
    {18, 2, 4, 4, 0.5, 8,
     {RECT(1, 0, 0, 1, 2), RECT(1, 1, 0, 2, 2), RECT(0, 0, 2, 2, 3),
      RECT(0, 0, 3, 2, 4), RECT(0, 2, 0, 4, 1), RECT(0, 2, 1, 4, 2),
      RECT(1, 2, 2, 3, 4), RECT(1, 3, 2, 4, 4)}},
};

static const tiling *find(int number) {
  for (size_t i = 0; i < sizeof tilings / sizeof tilings[0]; i++)
    if (tilings[i].number == number)
      return &tilings[i];
  return NULL;
}

bool zr__pattern_tiling_known(int number) { return find(number) != NULL; }

/* The distance from (x, z) to t's nearest edge, negative outside. */
static double depth(const tile *t, double x, double z) {
  double d = INFINITY;
  for (int i = 0; i < t->n; i++) {
    const double *a = t->corner[i], *b = t->corner[(i + 1) % t->n];
    double ex = b[0] - a[0], ez = b[1] - a[1];
    double s = (ex * (z - a[1]) - ez * (x - a[0])) / hypot(ex, ez);
    d = fmin(d, s);
  }
  return d;
}

double zr__pattern_tiling(int number, zr_vec3 p) {
  const tiling *tl = find(number);
  if (!tl)
    return 0;
  double x = p.x - tl->w * floor(p.x / tl->w);
  double z = p.z - tl->h * floor(p.z / tl->h);
  double best = -INFINITY;
  int type = 0;
  for (int i = -1; i <= 1; i++)
    for (int j = -1; j <= 1; j++)
      for (int k = 0; k < tl->n_tiles; k++) {
        double d = depth(&tl->tiles[k], x - i * tl->w, z - j * tl->h);
        if (d > best) {
          best = d;
          type = tl->tiles[k].type;
        }
      }
  double bevel = 1 - fmin(fmax(best, 0) / tl->inradius, 1);
  return (type + bevel) / tl->types;
}
