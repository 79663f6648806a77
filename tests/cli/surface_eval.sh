#!/usr/bin/env bash
# casteljau eval on surfaces (issue 5): --at u,v, two-column --params, the
# N x N --samples grid (u the slow index), --derivative ku,kv, and bad input
# (exit 2, one error line naming what and where, nothing on stdout).
# Reference values are worked by hand on a 2 x 3 Bézier patch P_ij (i along
# u, degree 1; j along v, degree 2): x = u, y = 2v,
# z = (1-u) * 2v(1-v) + u * (1 + 2v(1-v)).
# Usage: bash surface_eval.sh CASTELJAU EXAMPLES_DIR
source "$(dirname "$0")/support/common.sh" "$@"

model patch.json '{"type": "bezier_surface", "control_points": [[[0,0,0],[0,1,1],[0,2,0]], [[1,0,1],[1,1,2],[1,2,1]]]}'
check "point at (0.5,0.5) and a corner" $'0.5,1,1\n1,0,1' eval "$work/patch.json" --at 0.5,0.5 --at 1,0
check "blanks around u and v" '0.5,1,1' eval "$work/patch.json" --at ' 0.5 , 0.5 '
check "3 x 3 grid, u the slow index" $'0,0,0\n0,1,0.5\n0,2,0\n0.5,0,0.5\n0.5,1,1\n0.5,2,0.5\n1,0,1\n1,1,1.5\n1,2,1' \
  eval "$work/patch.json" --samples 3
check "one sample is the corner (u0, v0)" '0,0,0' eval "$work/patch.json" --samples 1
check "dS/du = P_1j - P_0j" '1,0,1' eval "$work/patch.json" --at 0,0 --derivative 1,0
check "dS/dv = 2 (P_01 - P_00)" '0,2,2' eval "$work/patch.json" --at 0,0 --derivative 0,1
check "d2S/dv2 = 2 (P_00 - 2 P_01 + P_02)" '0,0,-4' eval "$work/patch.json" --at 0,0.3 --derivative 0,2
check "d2S/du2 of a degree-1 direction" '0,0,0' eval "$work/patch.json" --at 0.3,0.3 --derivative 2,0
check "0 is the point for a surface too" '0.5,1,1' eval "$work/patch.json" --at 0.5,0.5 --derivative 0
printf 'u,v\n# a comment\n0,0\n0.5,1\n' >"$work/uv.csv"
check "two-column params with header and comment" $'0,0,0\n0.5,2,0.5' eval "$work/patch.json" --params "$work/uv.csv"
check "order: --at, then --params, then --samples" $'1,0,1\n0,0,0\n0.5,2,0.5\n0,0,0' \
  eval "$work/patch.json" --samples 1 --params "$work/uv.csv" --at 1,0

# A Coons patch of four straight edges of the unit square is the bilinear
# patch: P(u,v) = (u, v).
model square.json '{"type": "coons", "boundaries": {
  "u0": {"type": "bezier", "control_points": [[0,0],[0,1]]},
  "u1": {"type": "bspline", "degree": 1, "knots": [0,0,2,2], "control_points": [[1,0],[1,1]]},
  "v0": {"type": "piecewise_bezier", "pieces": [[[0,0],[0.5,0]], [[0.5,0],[1,0]]]},
  "v1": {"type": "bezier", "control_points": [[0,1],[1,1]]}}}'
check "bilinear Coons patch" $'0.25,0.75\n1,0.5' eval "$work/square.json" --at 0.25,0.75 --at 1,0.5


# A B-spline surface with a non-unit domain, and a file of several models:
# each is evaluated in order; a curve and a surface can be sampled together.
model spline.json '{"type": "bspline_surface", "degree": [1,1], "knots": [[0,0,2,2],[1,1,3,3]],
  "control_points": [[[0,0,0],[0,1,0]], [[1,0,0],[1,1,4]]]}'
check "bilinear B-spline on [0,2] x [1,3]" $'0.5,0.5,1\n1,1,4' eval "$work/spline.json" --at 1,2 --at 2,3
model mixed.json '{"models": [{"type": "bezier", "control_points": [[0,0],[2,2]]},
  {"type": "bezier_surface", "control_points": [[[0,0,0],[0,1,0]], [[1,0,0],[1,1,1]]]}]}'
check "curve then surface, sampled" $'0,0\n2,2\n0,0,0\n0,1,0\n1,0,0\n1,1,1' eval "$work/mixed.json" --samples 2
lines=$("$casteljau" eval "$work/spline.json" --samples 40 | wc -l)
[[ $lines -eq 1600 ]] || { echo "FAIL: --samples 40 gives $lines lines, expected 1600"; failures=$((failures + 1)); }

# --- bad input ------------------------------------------------------------------
expect_error "a single number for a surface" "--at: '0.5' is not a parameter pair u,v (a surface takes u,v)" \
  eval "$work/patch.json" --at 0.5
expect_error "a derivative order too high for a surface" \
  "--derivative 60,41: ku + kv = 101 is more than the limit of 100 for a surface" \
  eval "$work/patch.json" --at 0.5,0.5 --derivative 60,41
expect_error "three numbers" "--at: '0,1,2' is not a parameter pair u,v" eval "$work/patch.json" --at 0,1,2
expect_error "not a number" "--at: 'x' is not a number (a surface takes u,v)" eval "$work/patch.json" --at 0,x
expect_error "u outside" "--at 1.5,0 is outside the domain [0, 1] x [0, 1] of the bezier_surface model in '$work/patch.json'" \
  eval "$work/patch.json" --at 1.5,0
expect_error "v outside a B-spline domain" "--at 1,0.5 is outside the domain [0, 2] x [1, 3] of the bspline_surface model" \
  eval "$work/spline.json" --at 1,0.5
printf '0\n0.5\n' >"$work/one.csv"
expect_error "one-column params" "one.csv: 1 column, a surface's parameters are two columns u,v" \
  eval "$work/patch.json" --params "$work/one.csv"
printf 'u,v\n0,0\n0.5,2\n' >"$work/out.csv"
expect_error "params outside" "out.csv, row 2: (0.5, 2) is outside the domain [0, 1] x [0, 1]" \
  eval "$work/patch.json" --params "$work/out.csv"
expect_error "one derivative order" "--derivative 1: a surface takes two orders ku,kv" \
  eval "$work/patch.json" --at 0,0 --derivative 1
expect_error "bad derivative order" "--derivative: 'x' is not a whole number" \
  eval "$work/patch.json" --at 0,0 --derivative 1,x
expect_error "u,v for a curve" "(u,v is for surfaces; a curve takes one T)" eval "$work/mixed.json" --at 0,0
expect_error "grid too large" "1 model at these parameters (N x N for a surface) is 16000000 evaluations, more than the limit of 10000000" eval "$work/patch.json" --samples 4000
model ragged.json '{"type": "bezier_surface", "control_points": [[[0,0],[1,0]], [[0,1]]]}'
expect_error "ragged net" "ragged.json, control_points[1]: row 1 has 1 point, row 0 has 2" eval "$work/ragged.json" --at 0,0
model open.json '{"type": "coons", "boundaries": {
  "u0": {"type": "bezier", "control_points": [[0,0],[0,1]]},
  "u1": {"type": "bezier", "control_points": [[1,0],[1,1]]},
  "v0": {"type": "bezier", "control_points": [[0,0],[1,0.5]]},
  "v1": {"type": "bezier", "control_points": [[0,1],[1,1]]}}}'
expect_error "corners that do not meet" "open.json, boundaries: " eval "$work/open.json" --at 0,0
model nov1.json '{"type": "coons", "boundaries": {
  "u0": {"type": "bezier", "control_points": [[0,0],[0,1]]},
  "u1": {"type": "bezier", "control_points": [[1,0],[1,1]]},
  "v0": {"type": "bezier", "control_points": [[0,0],[1,0]]}}}'
expect_error "missing boundary" "nov1.json, boundaries: missing boundary 'v1'" eval "$work/nov1.json" --at 0,0

finish surface_eval
