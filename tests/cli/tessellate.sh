#!/usr/bin/env bash
# casteljau tessellate: a unit NURBS sphere (one patch with a seam and two
# poles) gives a watertight mesh in each of OBJ, STL and PLY (format by the
# extension, any case); the summary line; two bilinear patches sharing an edge
# in opposite directions weld into one mesh; a tighter tolerance gives more
# triangles; a patch with a pole; bad input (exit 2, one line on stderr,
# nothing written): among it a tolerance whose triangles cannot fit, refused
# at once, and surfaces without area.
# Usage: bash tessellate.sh CASTELJAU EXAMPLES_DIR
source "$(dirname "$0")/support/common.sh" "$@"

fail_test() {
  echo "FAIL: $1"
  failures=$((failures + 1))
}

# The unit sphere: The NURBS Book's 9-point circle revolved meridian (degree 2 x 2).
model sphere.json '{"type":"bspline_surface","degree":[2,2],"knots":[[0,0,0,0.25,0.25,0.5,0.5,0.75,0.75,1,1,1],[0,0,0,0.5,0.5,1,1,1]],"control_points":[[[0,0,-1],[1,0,-1],[1,0,0],[1,0,1],[0,0,1]],[[0,0,-1],[1,1,-1],[1,1,0],[1,1,1],[0,0,1]],[[0,0,-1],[0,1,-1],[0,1,0],[0,1,1],[0,0,1]],[[0,0,-1],[-1,1,-1],[-1,1,0],[-1,1,1],[0,0,1]],[[0,0,-1],[-1,0,-1],[-1,0,0],[-1,0,1],[0,0,1]],[[0,0,-1],[-1,-1,-1],[-1,-1,0],[-1,-1,1],[0,0,1]],[[0,0,-1],[0,-1,-1],[0,-1,0],[0,-1,1],[0,0,1]],[[0,0,-1],[1,-1,-1],[1,-1,0],[1,-1,1],[0,0,1]],[[0,0,-1],[1,0,-1],[1,0,0],[1,0,1],[0,0,1]]],"weights":[[1,0.7071067811865476,1,0.7071067811865476,1],[0.7071067811865476,0.5,0.7071067811865476,0.5,0.7071067811865476],[1,0.7071067811865476,1,0.7071067811865476,1],[0.7071067811865476,0.5,0.7071067811865476,0.5,0.7071067811865476],[1,0.7071067811865476,1,0.7071067811865476,1],[0.7071067811865476,0.5,0.7071067811865476,0.5,0.7071067811865476],[1,0.7071067811865476,1,0.7071067811865476,1],[0.7071067811865476,0.5,0.7071067811865476,0.5,0.7071067811865476],[1,0.7071067811865476,1,0.7071067811865476,1]]}'

summary_pattern='^tessellate: [0-9]+ triangles, [0-9]+ vertices, watertight$'
for output in sphere.obj sphere.STL sphere.Ply; do
  if "$casteljau" tessellate "$work/sphere.json" --tolerance 0.01 -o "$work/$output" >"$work/out" 2>"$work/err"; then
    grep -Eq "$summary_pattern" "$work/out" || fail_test "$output: summary $(cat "$work/out")"
    [[ $(wc -l <"$work/out") -eq 1 ]] || fail_test "$output: more than one summary line"
    [[ ! -s "$work/err" ]] || fail_test "$output: stderr $(cat "$work/err")"
  else
    fail_test "$output: exit $?: $(cat "$work/err")"
  fi
done
triangles=$(sed -E 's/^tessellate: ([0-9]+) triangles.*/\1/' "$work/out")
# Each format by its signature: OBJ text, STL 84 + 50 t bytes, PLY header.
grep -q '^f 1//1 ' "$work/sphere.obj" || grep -q '^f ' "$work/sphere.obj" || fail_test "obj: no faces"
[[ $(grep -c '^f ' "$work/sphere.obj") -eq $triangles ]] || fail_test "obj: face count differs from the summary"
[[ $(stat -c %s "$work/sphere.STL") -eq $((84 + 50 * triangles)) ]] || fail_test "stl: size $(stat -c %s "$work/sphere.STL")"
[[ "$(head -c 40 "$work/sphere.Ply" | head -2 | tr '\n' ' ')" == "ply format binary_little_endian 1.0 " ]] ||
  fail_test "ply: header $(head -c 40 "$work/sphere.Ply")"

# A tighter tolerance: more triangles.
"$casteljau" tessellate "$work/sphere.json" --tolerance 0.001 -o "$work/fine.obj" >"$work/out" 2>/dev/null
fine=$(sed -E 's/^tessellate: ([0-9]+) triangles.*/\1/' "$work/out")
[[ $fine -gt $triangles ]] || fail_test "tolerance 0.001 gives $fine triangles, 0.01 gave $triangles"

# Two flat unit squares sharing the edge x = 1 (the second runs it the other
# way): one mesh of 8 triangles (a fan of 4 per square) and 8 vertices (6 corners,
# the shared edge's 2 once, and 2 centres)
# and open (not watertight: the outer boundary remains).
model squares.json '{"models": [
  {"type": "bezier_surface", "control_points": [[[0,0,0],[0,1,0]],[[1,0,0],[1,1,0]]]},
  {"type": "bezier_surface", "control_points": [[[2,1,0],[2,0,0]],[[1,1,0],[1,0,0]]]}]}'
check "two squares" "tessellate: 8 triangles, 8 vertices, not watertight (6 boundary edges, 0 non-manifold edges, 0 inconsistently oriented edges, 0 degenerate triangles)" \
  tessellate "$work/squares.json" --tolerance 0.1 -o "$work/squares.obj"

# --- bad input: exit 2, one line, nothing written ---------------------------------
model curve.json '{"models": [{"type": "bezier_surface", "control_points": [[[0,0,0],[0,1,0]],[[1,0,0],[1,1,0]]]},
  {"type": "bezier", "control_points": [[0,0],[1,1]]}]}'
expect_error "a curve" "models[1] (bezier) in" tessellate "$work/curve.json" --tolerance 0.1 -o "$work/x.obj"
model flat.json '{"type": "bezier_surface", "control_points": [[[0,0],[0,1]],[[1,0],[1,1]]]}'
expect_error "2D surface" "is in R^2" tessellate "$work/flat.json" --tolerance 0.1 -o "$work/x.obj"
expect_error "zero tolerance" "--tolerance: 0 is not > 0" tessellate "$work/sphere.json" --tolerance 0 -o "$work/x.obj"
expect_error "bad tolerance" "--tolerance:" tessellate "$work/sphere.json" --tolerance abc -o "$work/x.obj"
expect_error "tiny tolerance" "below what double precision can check" tessellate "$work/sphere.json" --tolerance 1e-15 -o "$work/x.obj"
expect_error "extension" "does not end in .obj, .stl or .ply" tessellate "$work/sphere.json" --tolerance 0.1 -o "$work/x.txt"
expect_error "missing file" "cannot open" tessellate "$work/none.json" --tolerance 0.1 -o "$work/x.obj"
expect_error "no output" "output" tessellate "$work/sphere.json" --tolerance 0.1
expect_error "missing folder" "cannot write" tessellate "$work/sphere.json" --tolerance 0.1 -o "$work/no/x.obj"

# Issue 15: --tolerance 1e-9 worked 14.6 s before refusing for 10^7 triangles;
# the estimate refuses before any refinement and suggests a tolerance (with
# progress forced on, the one error line is still all of stderr).
CASTELJAU_PROGRESS=always expect_error "estimated count" \
  "triangles at tolerance 1e-09 (estimated from the surfaces' second differences), more than the limit of 10000000; a tolerance of " \
  tessellate "$work/sphere.json" --tolerance 1e-9 -o "$work/x.stl"
grep -Eq '^casteljau: error: .*/sphere.json: the tessellation needs at least [0-9]+ triangles .* of [0-9.e+-]+ or larger should fit$' \
  "$work/stderr" || fail_test "estimated count: $(cat "$work/stderr")"

# Issue 15: all control points equal gave "0 triangles, 1 vertices, watertight".
# A surface without area (a point, or a curve: the ruled surface between a curve
# and itself) is refused by name; one edge collapsed (a pole) is a surface.
model point.json '{"type": "bezier_surface", "control_points": [[[1,2,3],[1,2,3]],[[1,2,3],[1,2,3]]]}'
expect_error "a point" "point.json: patch 0 is degenerate: every point of it is (1, 2, 3), and a point has no triangles" \
  tessellate "$work/point.json" --tolerance 0.01 -o "$work/x.stl"
model ruled.json '{"type": "bspline_surface", "degree": [2, 1], "knots": [[0,0,0,1,1,1],[0,0,1,1]],
  "control_points": [[[0,0,0],[0,0,0]],[[1,1,0],[1,1,0]],[[2,0,0],[2,0,0]]]}'
expect_error "a curve" "ruled.json: patch 0 is degenerate: it has zero area (its points lie on one curve)" \
  tessellate "$work/ruled.json" --tolerance 0.01 -o "$work/x.stl"
model second.json '{"models": [
  {"type": "bezier_surface", "control_points": [[[0,0,0],[0,1,0]],[[1,0,0],[1,1,0]]]},
  {"type": "bezier_surface", "control_points": [[[5,5,5],[5,5,5]],[[5,5,5],[5,5,5]]]}]}'
expect_error "one of two" "second.json: patch 1 is degenerate: every point of it is (5, 5, 5)" \
  tessellate "$work/second.json" --tolerance 0.01 -o "$work/x.stl"
model cone.json '{"type": "bezier_surface", "control_points": [[[0,0,1],[0,0,1]],[[1,0,0],[0,1,0]]]}'
"$casteljau" tessellate "$work/cone.json" --tolerance 0.01 -o "$work/cone.stl" >"$work/out" 2>"$work/err" ||
  fail_test "pole: exit $?: $(cat "$work/err")"
grep -Eq '^tessellate: [1-9][0-9]* triangles, .* not watertight \([0-9]+ boundary edges, 0 non-manifold edges, 0 inconsistently oriented edges, 0 degenerate triangles\)$' "$work/out" ||
  fail_test "pole: summary $(cat "$work/out")"
[[ ! -e "$work/x.obj" && ! -e "$work/x.txt" && ! -e "$work/x.stl" ]] || fail_test "a mesh was written for bad input"

finish tessellate
