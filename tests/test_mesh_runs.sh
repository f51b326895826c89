#!/bin/sh
# test_mesh_runs.sh - meshes made of triangle runs (lib/sdl/tokens.c keeps
# the corners of "triangle { <a>, <b>, <c> }" with plain numbers; a mesh
# of such runs, one after another in one file, takes them as its vertex
# array in build_mesh.c, anything else copies them; smooth_triangle runs
# keep corners and normals, which a mesh of them takes likewise) draw the
# same picture as the same meshes without runs: tests/mesh_runs.pov (runs
# alone, runs around a face with an expression, a smooth_triangle, a
# textured face, an included file; a loop and a declared mesh that reuse
# the same runs; smooth runs alone, with plain runs between or before
# them, in a loop, before a textured face)
# against a copy whose every vector is in parentheses, which the lexer
# leaves to the grammar.  A face that took the wrong corners, or a mesh
# that lost faces, shows in the picture.
#
# Environment: ZR_SRCDIR, ZR_BUILDDIR (set by `make check`).
set -u
. "${ZR_SRCDIR:-$(cd "$(dirname "$0")/.." && pwd)}/tests/render_env.sh"
cp "$srcdir/tests/mesh_runs.pov" "$srcdir/tests/mesh_runs.inc" .
vectors='s/<\([-0-9.]*\),\([-0-9.]*\),\([-0-9.]*\)>/(<\1,\2,\3>)/g'
sed -e "$vectors" -e 's/mesh_runs\.inc/plain.inc/' mesh_runs.pov >plain.pov
sed -e "$vectors" mesh_runs.inc >plain.inc
grep -q '(<0,0,0>)' plain.pov || { echo "plain.pov: no vector changed" >&2; exit 1; }
for scene in mesh_runs plain; do
  timeout 60 "$zrcube" +I$scene.pov +O$scene.png +W160 +H120 -D +WT1 \
    </dev/null >$scene.log 2>&1 || { cat $scene.log >&2; exit 1; }
done
cmp mesh_runs.png plain.png ||
  { echo "meshes of runs and without runs differ" >&2; exit 1; }
# Every mesh is there: 16 objects (4 meshes, 3 from the loop, 2 uses of
# M, the mesh around the include, 4 smooth meshes and 2 from their loop;
# M's declaration is not one) in both.
for scene in mesh_runs plain; do
  "$zrcube" --parse-only $scene.pov >$scene.info 2>&1
  grep -q '^objects: 16$' $scene.info ||
    { cat $scene.info >&2; echo "$scene: not 16 objects" >&2; exit 1; }
done
echo "ok: the same picture with and without runs"
