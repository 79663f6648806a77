#!/usr/bin/env bash
# Extreme numbers in models (issue 15): knot spans of subnormal width (whose
# reciprocal overflows; they crashed eval with SIGSEGV), knots whose vector
# is wider than the largest double (they evaluated to (0,0) silently), a
# surface with such u-knots (tessellate worked 22 s before refusing), and
# coordinates and weights beyond the ranges a valid object evaluates in
# (core/tolerance.hpp). Each is refused at once: exit 2, one line naming the
# knots or the value, nothing on stdout, nothing written.
# Usage: bash extreme_knots.sh CASTELJAU EXAMPLES_DIR
source "$(dirname "$0")/support/common.sh" "$@"

# --- the issue's commands ------------------------------------------------------
model subnormal.json '{"type":"bspline","degree":1,"knots":[0,0,5e-324,5e-324],"control_points":[[0,0],[1,1]]}'
span_message="knots 1 and 2 (0 and 5e-324) are 5e-324 apart, less than the narrowest knot span 1e-100"
expect_error "subnormal span, --at" "$span_message" eval "$work/subnormal.json" --at 0
for n in 1 2 3; do
  expect_error "subnormal span, --samples $n" "$span_message" eval "$work/subnormal.json" --samples "$n"
done
model tiny.json '{"type":"bspline","degree":1,"knots":[0,0,1e-310,1e-310],"control_points":[[0,0],[1,1]]}'
expect_error "1e-310 span" "knots 1 and 2 (0 and 1e-310) are 1e-310 apart, less than the narrowest knot span 1e-100" \
  eval "$work/tiny.json" --at 0
model wide.json '{"type":"bspline","degree":1,"knots":[-1e308,-1e308,1e308,1e308],"control_points":[[0,0],[1,1]]}'
expect_error "knots wider than a double" "knot 0 is -1e+308, outside [-1e+100, 1e+100], the range of knots" \
  eval "$work/wide.json" --at 0

# A surface with subnormal u-knots: refused before any tessellation work.
model surface.json '{"type":"bspline_surface","degree":[1,1],"knots":[[0,0,5e-324,5e-324],[0,0,1,1]],"control_points":[[[0,0,0],[0,1,0]],[[1,0,0],[1,1,1]]]}'
started=$SECONDS
expect_error "surface u-knots" "knots 1 and 2 (0 and 5e-324) are 5e-324 apart" \
  tessellate "$work/surface.json" --tolerance 0.01 -o "$work/mesh.obj"
if (( SECONDS - started > 2 )); then
  echo "FAIL: the surface took $((SECONDS - started)) s to be refused"
  failures=$((failures + 1))
fi
if [[ -e "$work/mesh.obj" ]]; then
  echo "FAIL: tessellate wrote mesh.obj for a refused surface"
  failures=$((failures + 1))
fi
model surface_v.json '{"type":"bspline_surface","degree":[1,1],"knots":[[0,0,1,1],[0,0,1e-310,1e-310]],"control_points":[[[0,0,0],[0,1,0]],[[1,0,0],[1,1,1]]]}'
expect_error "surface v-knots" "knots 1 and 2 (0 and 1e-310) are 1e-310 apart" eval "$work/surface_v.json" --at 0,0

# --- the neighbours: coordinates and weights -------------------------------------
model far.json '{"type":"bezier","control_points":[[-1e308,0],[1e308,0]]}'
expect_error "coordinate 1e308" "coordinate 0 of control point 0 is -1e+308, outside [-1e+100, 1e+100], the range of coordinates" \
  eval "$work/far.json" --at 0.5 --derivative 1
model light.json '{"type":"bspline","degree":1,"knots":[0,0,1,1],"control_points":[[0,0],[1,1]],"weights":[1,1e-320]}'
expect_error "weight 1e-320" "weight 1 is 1e-320, outside [1e-50, 1e+50], the range of weights" \
  eval "$work/light.json" --at 0.5

# --- what stays valid: a span of one ulp, the edges of the ranges -----------------
model ulp.json '{"type":"bspline","degree":1,"knots":[1,1,1.0000000000000002,1.0000000000000002],"control_points":[[0,0],[1,1]]}'
check "one-ulp span" $'0,0\n1,1' eval "$work/ulp.json" --at 1 --at 1.0000000000000002
# The corner of the ranges: the narrowest span, the widest weight ratio and
# the largest coordinates; C'(0) = (w1 / w0) (P1 - P0) / h = 2e300 (by hand),
# to rounding.
model edges.json '{"type":"bspline","degree":1,"knots":[0,0,1e-100,1e-100],"control_points":[[-1e100,0],[1e100,0]],"weights":[1e-50,1e50]}'
slope=$("$casteljau" eval "$work/edges.json" --at 0 --derivative 1 2>"$work/stderr")
if ! awk -F, -v s="$slope" 'BEGIN { split(s, c, ","); r = c[1] / 2e300; exit !(r > 1 - 1e-14 && r < 1 + 1e-14 && c[2] == 0) }'; then
  echo "FAIL: the edges of the ranges: C'(0) = $slope ($(cat "$work/stderr")), expected 2e300,0"
  failures=$((failures + 1))
fi

finish extreme_knots
