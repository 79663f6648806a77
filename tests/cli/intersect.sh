#!/usr/bin/env bash
# casteljau intersect: the JSON of interfaces.md for crossings, a tangency
# with its multiplicity, an overlap (a curve and its own middle), the self-
# intersection of a loop, an empty result; and bad input: exit 2, one line on
# stderr, nothing on stdout.
# Usage: bash intersect.sh CASTELJAU EXAMPLES_DIR
source "$(dirname "$0")/support/common.sh" "$@"

model a.json '{"type": "bezier", "control_points": [[0,0],[2,2]]}'
model b.json '{"type": "bezier", "control_points": [[0,2],[2,0]]}'
check "crossing lines" "$(printf '{"intersections": [\n  {"kind": "transversal", "a": 0.5, "b": 0.5, "point": [1, 1]}\n]}')" \
  intersect "$work/a.json" "$work/b.json"
model parabola.json '{"type": "bezier", "control_points": [[-1,1],[0,-1],[1,1]]}'
model axis.json '{"type": "bezier", "control_points": [[-2,0],[2,0]]}'
out=$("$casteljau" intersect "$work/parabola.json" "$work/axis.json" 2>&1)
/usr/bin/python3 - "$out" <<'PY' || { echo "FAIL: tangent: $out"; failures=$((failures + 1)); }
import json, sys
x = json.loads(sys.argv[1])["intersections"]
sys.exit(not (len(x) == 1 and x[0]["kind"] == "tangent" and x[0]["multiplicity"] == 2 and
              abs(x[0]["a"] - 0.5) < 1e-7 and abs(x[0]["b"] - 0.5) < 1e-7))
PY
model cubic.json '{"type": "bezier", "control_points": [[0,0],[1,3],[2,-3],[3,0]]}'
# Its middle third, [1/4, 3/4], by de Casteljau: the overlap.
model middle.json '{"type": "bezier", "control_points": [[0.75,0.84375],[1.25,0.65625],[1.75,-0.65625],[2.25,-0.84375]]}'
check "overlap" "$(printf '{"intersections": [\n  {"kind": "overlap", "a": [0.25, 0.75], "b": [0, 1]}\n]}')" \
  intersect "$work/cubic.json" "$work/middle.json"
model loop.json '{"type": "bezier", "control_points": [[0,0],[2,2],[-1,2],[1,0]]}'
out=$("$casteljau" intersect "$work/loop.json" 2>&1)
/usr/bin/python3 - "$out" <<'PY' || { echo "FAIL: self-intersection: $out"; failures=$((failures + 1)); }
import json, math, sys
x = json.loads(sys.argv[1])["intersections"]
s = (5 - math.sqrt(15)) / 10
sys.exit(not (len(x) == 1 and x[0]["kind"] == "transversal" and abs(x[0]["a"] - s) < 1e-15 and
              abs(x[0]["b"] - (1 - s)) < 1e-15 and x[0]["a"] < x[0]["b"]))
PY
model far.json '{"type": "bezier", "control_points": [[10,10],[11,11]]}'
check "none" '{"intersections": []}' intersect "$work/a.json" "$work/far.json"
"$casteljau" intersect "$work/a.json" "$work/b.json" -o "$work/out.json" 2>"$work/stderr" &&
  /usr/bin/python3 -c "import json,sys; json.load(open(sys.argv[1]))" "$work/out.json" ||
  { echo "FAIL: -o"; failures=$((failures + 1)); }

model space.json '{"type": "bezier", "control_points": [[0,0,0],[1,1,1]]}'
expect_error "a 2D and a 3D curve" "intersections need curves in one space, the first lives in R^2, the second in R^3" \
  intersect "$work/a.json" "$work/space.json"
model space2.json '{"type": "bezier", "control_points": [[0,1,0],[1,0,1]]}'
check "crossing lines in space" \
  "$(printf '{"intersections": [\n  {"kind": "transversal", "a": 0.5, "b": 0.5, "point": [0.5, 0.5, 0.5]}\n]}')" \
  intersect "$work/space.json" "$work/space2.json"
model line1d.json '{"type": "bezier", "control_points": [[0],[1]]}'
expect_error "a 1D curve" "intersections need curves in R^2 or more, the first lives in R^1" \
  intersect "$work/line1d.json" "$work/line1d.json"
expect_error "a surface" "intersect takes curves; the bezier_surface model in" intersect "$examples/patch.json"
expect_error "bad tolerance" "--tolerance: 0 is not > 0" intersect "$work/a.json" "$work/b.json" --tolerance 0
model two.json '{"models": [{"type": "bezier", "control_points": [[0,0],[3,4]]}, {"type": "bezier", "control_points": [[0,0],[1,0]]}]}'
# A alone with two curves: they meet at their common start (0, 0).
check "two models" \
  "$(printf '{"intersections": [\n  {"kind": "transversal", "curve_a": 0, "curve_b": 1, "a": 0, "b": 0, "point": [0, 0]}\n]}')" \
  intersect "$work/two.json"
expect_error "two models and B" "intersect A B takes one curve per file; '$work/two.json' holds 2 models" \
  intersect "$work/two.json" "$work/a.json"
expect_error "missing file" "nothing.json" intersect "$work/a.json" "$work/nothing.json"

finish intersect
