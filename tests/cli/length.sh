#!/usr/bin/env bash
# casteljau length and eval --arc-length: known lengths (the NURBS half
# circle of radius 3 is 3 pi; a segment 3-4-5; the parabola y = x^2 on [0, 2],
# sqrt(17) + asinh(4)/4; sub-ranges; one line per model, piecewise curves and
# CSV input too), the arc-length samples of the half circle at exact angles,
# and bad input: exit 2, one line on stderr, nothing on stdout.
# Usage: bash length.sh CASTELJAU EXAMPLES_DIR
source "$(dirname "$0")/support/common.sh" "$@"

# close NAME EXPECTED TOLERANCE ARGS...: one number within TOLERANCE of EXPECTED, exit 0.
close() {
  local name=$1 expected=$2 tolerance=$3
  shift 3
  local out
  if ! out=$("$casteljau" "$@" 2>"$work/stderr"); then
    echo "FAIL: $name: exit $?: $(cat "$work/stderr")"
    failures=$((failures + 1))
    return
  fi
  if ! /usr/bin/python3 -c "import sys; sys.exit(abs(float('$out') - ($expected)) > $tolerance)"; then
    echo "FAIL: $name: got $out, expected $expected within $tolerance"
    failures=$((failures + 1))
  fi
}

close "half circle" "3 * 3.141592653589793" 1e-13 length "$examples/semicircle.json"
close "quarter of it" "1.5 * 3.141592653589793" 1e-13 length "$examples/semicircle.json" --from 0.5
close "a loose tolerance" "3 * 3.141592653589793" 1e-3 length "$examples/semicircle.json" --tolerance 1e-3
model segment.json '{"type": "bezier", "control_points": [[0,0],[3,4]]}'
check "segment" "5" length "$work/segment.json"
check "middle of the segment" "2.5" length "$work/segment.json" --from 0.25 --to 0.75
model parabola.json '{"type": "bezier", "control_points": [[0,0],[1,0],[2,4]]}'
close "parabola" "17 ** 0.5 + __import__('math').asinh(4) / 4" 1e-12 length "$work/parabola.json"
model two.json '{"models": [{"type": "bezier", "control_points": [[0,0],[3,4]]},
  {"type": "piecewise_bezier", "pieces": [{"type": "bezier", "control_points": [[0,0],[1,0]]}, {"type": "bezier", "control_points": [[1,0],[1,2]]}]}]}'
check "one line per curve" "$(printf '5\n3')" length "$work/two.json"
printf '0,0\n6,8\n' >"$work/line.csv"
check "a CSV polygon" "10" length "$work/line.csv"
# Weights 1, 1e20, 1: the conic hugs its control polygon, 2 sqrt 2 long to
# 1e-20 (issue 39: it printed 0); 1e10 was refused for its quadrature budget.
printf '{"type": "bezier", "control_points": [[0, 0], [1, 1], [2, 0]], "weights": [1, 1e20, 1]}' >"$work/corner.json"
out=$("$casteljau" length "$work/corner.json" 2>&1)
/usr/bin/python3 -c "import math, sys; sys.exit(abs(float('$out') - 2 * math.sqrt(2)) > 1e-11)" ||
  { echo "FAIL: length of weights 1, 1e20, 1: $out"; failures=$((failures + 1)); }
printf '{"type": "bezier", "control_points": [[0, 0], [1, 1], [2, 0]], "weights": [1, 1e10, 1]}' >"$work/corner.json"
"$casteljau" length "$work/corner.json" >/dev/null 2>&1 || { echo "FAIL: length of weights 1, 1e10, 1 refused"; failures=$((failures + 1)); }
# A unit circle and a half-unit line at (1e6, 1e6), as a survey drawing holds
# them: measured at the default tolerance (issue 39: the circle was refused).
printf '0\nSECTION\n2\nENTITIES\n0\nCIRCLE\n10\n1000000\n20\n1000000\n40\n1\n0\nLINE\n10\n1000000\n20\n1000000\n11\n1000000.5\n21\n1000000\n0\nENDSEC\n0\nEOF\n' >"$work/far.dxf"
out=$("$casteljau" length "$work/far.dxf" 2>&1)
/usr/bin/python3 - "$out" <<'PY' || { echo "FAIL: length far from the origin: $out"; failures=$((failures + 1)); }
import math, sys
a, b = map(float, sys.argv[1].split())
sys.exit(abs(a - 2 * math.pi) > 1e-11 or b != 0.5)
PY
# The half-unit line at 1e6 is written to SVG exactly (a line needs no
# approximation; its tolerance was refused as below what doubles certify).
check "a line far from the origin to SVG" "convert: 1 curve to SVG, every piece exact" \
  convert "$work/far.dxf" --model 1 --to svg -o "$work/far.svg"
"$casteljau" length "$examples/semicircle.json" -o "$work/length.txt" 2>"$work/stderr" &&
  [[ $(wc -l <"$work/length.txt") -eq 1 ]] || { echo "FAIL: -o"; failures=$((failures + 1)); }

# Equal arc-length samples of the half circle: at 0, 45, 90, 135, 180 degrees.
out=$("$casteljau" eval "$examples/semicircle.json" --samples 5 --arc-length 2>&1)
/usr/bin/python3 - "$out" <<'PY' || { echo "FAIL: eval --arc-length: $out"; failures=$((failures + 1)); }
import math, sys
rows = [tuple(map(float, line.split(","))) for line in sys.argv[1].splitlines()]
expected = [(-3 * math.cos(k * math.pi / 4), 3 * math.sin(k * math.pi / 4)) for k in range(5)]
sys.exit(len(rows) != 5 or any(math.dist(a, b) > 1e-11 for a, b in zip(rows, expected)))
PY

expect_error "a surface" "length measures curves; the bezier_surface model in" length "$examples/patch.json"
expect_error "--from outside" "the arc-length range's start 9 is outside the domain [0, 8]" \
  length "$examples/spline.json" --from 9
expect_error "backwards" "the arc-length range [0.75, 0.25] runs backwards" \
  length "$work/segment.json" --from 0.75 --to 0.25
expect_error "zero tolerance" "the arc-length tolerance is 0, it must be finite and > 0" \
  length "$work/segment.json" --tolerance 0
expect_error "tiny tolerance" "the arc-length tolerance 1e-20 is below 1e-14 of the curve's size 5" \
  length "$work/segment.json" --tolerance 1e-20
expect_error "not a number" "--tolerance: 'x' is not a number" length "$work/segment.json" --tolerance x
expect_error "missing file" "nothing.json" length "$work/nothing.json"
expect_error "--arc-length alone" "--arc-length spaces the --samples points along the curve: give --samples N too" \
  eval "$examples/semicircle.json" --arc-length
expect_error "--arc-length on a surface" "--arc-length spaces points along curves" \
  eval "$examples/patch.json" --samples 3 --arc-length

finish length
