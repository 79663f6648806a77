#!/usr/bin/env bash
# casteljau closest: nearest points known in closed form (the NURBS half
# circle of radius 3 about the origin: along the ray through the query; a
# segment's orthogonal projection; the end when the foot falls beyond it),
# --points files and repeated --point, --all with the ends and corners, a
# 3D curve, point inversion on a surface, and bad input: exit 2, one line on
# stderr, nothing on stdout.
# Usage: bash closest.sh CASTELJAU EXAMPLES_DIR
source "$(dirname "$0")/support/common.sh" "$@"

check "half circle from above" "$(printf 'query,t,distance,x,y\n0,0.5,2,0,3')" \
  closest "$examples/semicircle.json" --point 0,5
model segment.json '{"type": "bezier", "control_points": [[0,0],[4,2]]}'
check "projection and ends" "$(printf 'query,t,distance,x,y\n0,0.5,2.23606797749979,2,1\n1,1,5.0990195135927845,4,2\n2,0,1,0,0')" \
  closest "$work/segment.json" --point 1,3 --point 9,1 --point=-1,0
printf 'x,y\n1,3\n# a comment\n9,1\n' >"$work/queries.csv"
check "--points after --point" "$(printf 'query,t,distance,x,y\n0,0,1,0,0\n1,0.5,2.23606797749979,2,1\n2,1,5.0990195135927845,4,2')" \
  closest "$work/segment.json" --point=-1,0 --points "$work/queries.csv"
# From the centre every point is at distance 3: the two ends are the local minima.
check "--all from the centre" "$(printf 'query,t,distance,x,y\n0,0,3,-3,0\n0,1,3,3,0')" \
  closest "$examples/semicircle.json" --point 0,0 --all
# The parabola y = x^2 from (0, 1): minima at x = -+1/sqrt(2), the left one first.
model parabola.json '{"type": "bezier", "control_points": [[-1,1],[0,-1],[1,1]]}'
out=$("$casteljau" closest "$work/parabola.json" --point 0,1 --all 2>&1)
/usr/bin/python3 - "$out" <<'PY' || { echo "FAIL: --all on the parabola: $out"; failures=$((failures + 1)); }
import math, sys
lines = sys.argv[1].splitlines()
rows = [tuple(map(float, line.split(","))) for line in lines[1:]]
x = 1 / math.sqrt(2)
expected = [(0, (1 - x) / 2, math.sqrt(3) / 2, -x, 0.5), (0, (1 + x) / 2, math.sqrt(3) / 2, x, 0.5)]
sys.exit(lines[0] != "query,t,distance,x,y" or len(rows) != 2 or
         any(abs(a - b) > 1e-15 for r, e in zip(rows, expected) for a, b in zip(r, e)))
PY
model helix.json '{"type": "bezier", "control_points": [[0,0,0],[1,0,1],[1,1,2]]}'
check "3D header" "$(printf 'query,t,distance,x,y,z\n0,0,1,0,0,0')" closest "$work/helix.json" --point 0,0,-1
"$casteljau" closest "$work/segment.json" --point 1,3 -o "$work/out.csv" 2>"$work/stderr" &&
  [[ $(wc -l <"$work/out.csv") -eq 2 ]] || { echo "FAIL: -o"; failures=$((failures + 1)); }

expect_error "no query" "closest needs query points: --point X,Y[,Z] or --points FILE.csv" closest "$work/segment.json"
expect_error "wrong dimension" "the query points have 3 coordinates, the bezier model in" \
  closest "$work/segment.json" --point 1,2,3
expect_error "mixed dimensions" "--point 1,2,3 has 3 coordinates, the first query has 2" \
  closest "$work/segment.json" --point 1,2 --point 1,2,3
expect_error "not a number" "--point: 'a' is not a number" closest "$work/segment.json" --point a,1
printf '1,2\n1,nan\n' >"$work/bad.csv"
expect_error "a bad row" "bad.csv" closest "$work/segment.json" --points "$work/bad.csv"
# Point inversion on the NURBS sphere of radius 1: along the ray, the pole from above.
out=$("$casteljau" closest "$examples/sphere.json" --point 0,0,5 --point 3,4,0 2>&1)
/usr/bin/python3 - "$out" <<'PY' || { echo "FAIL: sphere: $out"; failures=$((failures + 1)); }
import sys
lines = sys.argv[1].splitlines()
rows = [tuple(map(float, line.split(","))) for line in lines[1:]]
ok = lines[0] == "query,u,v,distance,x,y,z" and len(rows) == 2
ok = ok and abs(rows[0][3] - 4) < 1e-12 and max(abs(a - b) for a, b in zip(rows[0][4:], (0, 0, 1))) < 1e-12
ok = ok and abs(rows[1][3] - 4) < 1e-12 and max(abs(a - b) for a, b in zip(rows[1][4:], (0.6, 0.8, 0))) < 1e-12
sys.exit(not ok)
PY
expect_error "--all on a surface" "--all (every local minimum) is for curves; the bspline_surface model in" \
  closest "$examples/sphere.json" --point 0,0,5 --all
model two.json '{"models": [{"type": "bezier", "control_points": [[0,0],[3,4]]}, {"type": "bezier", "control_points": [[0,0],[1,0]]}]}'
# Two curves: the nearest of both, its index in the column curve. (4, 1) is
# 2.6 from the first segment, (0, 0)-(3, 4), at t = 0.64 (the foot (1.92,
# 2.56)), and sqrt(10) from the second's end (1, 0); (0.5, -2) is 2 from
# the second at t = 0.5, sqrt(4.25) from the first's start.
check "two models" $'query,curve,t,distance,x,y\n0,0,0.64,2.6,1.92,2.56\n1,1,0.5,2,0.5,0' \
  closest "$work/two.json" --point 4,1 --point 0.5,-2
# --all: every local minimum of both, the global first, then by curve and parameter.
check "two models, --all" $'query,curve,t,distance,x,y\n0,1,0.5,2,0.5,0\n0,0,0,2.0615528128088303,0,0' \
  closest "$work/two.json" --point 0.5,-2 --all
model mixed.json '{"models": [{"type": "bezier", "control_points": [[0,0],[3,4]]}, {"type": "bezier", "control_points": [[0,0,0],[1,0,0]]}]}'
expect_error "two spaces" "the query points have 2 coordinates, models[1] (bezier) in" closest "$work/mixed.json" --point 0,0
expect_error "missing file" "nothing.json" closest "$work/nothing.json" --point 0,0

finish closest
