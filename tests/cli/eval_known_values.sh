#!/usr/bin/env bash
# casteljau eval: known values through the command line, and output that
# reads back (in Python, an independent reader) to the same doubles.
# Usage: bash eval_known_values.sh CASTELJAU EXAMPLES_DIR
source "$(dirname "$0")/support/common.sh" "$@"

# Seed 004's worked example: the notebook polygon gives B(0.5) = (2.25, 1.5).
check "notebook B(0.5)" "2.25,1.5" eval "$examples/notebook_polygon.csv" --at 0.5
# The same curve as model JSON.
cat > "$work/notebook.json" <<'JSON'
{"type": "bezier", "control_points": [[0,0],[1,2],[2,2],[4,1],[4,0]]}
JSON
check "notebook B(0.5), JSON" "2.25,1.5" eval "$work/notebook.json" --at 0.5
# End points interpolate; --at values come out in the order given.
check "ends" $'4,0\n0,0\n2.25,1.5' eval "$examples/notebook_polygon.csv" --at 1 --at 0 --at=0.5
# End tangents (seed 004): B'(0) = n (P1 - P0) = (4,8), B'(1) = n (P4 - P3) = (0,-4).
check "tangents" $'4,8\n0,-4' eval "$examples/notebook_polygon.csv" --at 0 --at 1 --derivative 1
# Degree 4: the fifth derivative vanishes.
check "fifth derivative" "0,0" eval "$examples/notebook_polygon.csv" --at 0.3 --derivative 5
# --samples N: N evenly spaced parameters, ends included; N = 1 is the start.
check "samples 3" $'0,0\n2.25,1.5\n4,0' eval "$examples/notebook_polygon.csv" --samples 3
check "samples 1" "0,0" eval "$examples/notebook_polygon.csv" --samples 1
# A quarter circle as a rational quadratic: the point at t = 1/2 is (1/sqrt2, 1/sqrt2)
# up to rounding; exactly what the library computes, checked by radius below.
cat > "$work/arc.json" <<'JSON'
{"type": "bezier", "control_points": [[1,0],[1,1],[0,1]], "weights": [1, 0.7071067811865476, 1]}
JSON
check "arc ends" $'1,0\n0,1' eval "$work/arc.json" --at 0 --at 1
# A piecewise curve: domain [0, 2], piece i on [i, i+1]; several models in order.
cat > "$work/two.json" <<'JSON'
{"models": [
  {"type": "piecewise_bezier", "pieces": [[[0,0],[2,2]], [[2,2],[4,2],[4,0]]]},
  {"type": "bezier", "control_points": [[1],[3]]}
]}
JSON
check "several models" $'0,0\n1,1\n2,2\n3.5,1.5\n4,0\n1\n1.5\n2\n2.5\n3' eval "$work/two.json" --samples 5
cat > "$work/piecewise.json" <<'JSON'
{"type": "piecewise_bezier", "pieces": [[[0,0],[2,2]], [[2,2],[4,2],[4,0]]]}
JSON
check "piecewise at 1.5 and 2" $'3.5,1.5\n4,0' eval "$work/piecewise.json" --at 1.5 --at 2
# At a junction, derivatives come from the piece to the right.
check "piecewise derivative at junction" $'2,2\n4,0' eval "$work/piecewise.json" --at 0.5 --at 1 --derivative 1
# --params: a one-column CSV with comments and a header.
printf '# parameters\nt\n0.5\n\n1\n' > "$work/params.csv"
check "params" $'2.25,1.5\n4,0' eval "$examples/notebook_polygon.csv" --params "$work/params.csv"
# --help works.
if ! "$casteljau" eval --help | grep -q -- "--samples"; then
  echo "FAIL: eval --help does not describe --samples"
  failures=$((failures + 1))
fi

# Output reads back to the same doubles. On the line from 0 to 1, B(t) = t
# exactly, so evaluating at awkward doubles must print them back unchanged:
# Python (an independent, correctly rounding reader) compares the bits.
cat > "$work/line.json" <<'JSON'
{"type": "bezier", "control_points": [[0],[1]]}
JSON
cat > "$work/awkward.csv" <<'CSV'
t
0.1
0.30000000000000004
0.3333333333333333
5e-324
2.2250738585072014e-308
0.9999999999999999
1e-17
0.7071067811865476
CSV
"$casteljau" eval "$work/line.json" --params "$work/awkward.csv" > "$work/out.csv"
if ! /usr/bin/python3 - "$work/awkward.csv" "$work/out.csv" <<'PY'
import sys
params = [float(x) for x in open(sys.argv[1]).read().split()[1:]]
lines = open(sys.argv[2]).read().splitlines()
assert len(lines) == len(params), (lines, params)
for text, t in zip(lines, params):
    value = float(text)
    assert value.hex() == t.hex(), (text, t)
    # Shortest round trip: no shorter decimal reads back to the same double
    # (Python's repr is the shortest; allow its '0.1' vs our '0.1', 5e-324 vs 5e-324).
    assert len(text) <= len(repr(value)), (text, repr(value))
PY
then
  echo "FAIL: output does not read back to the same doubles"
  failures=$((failures + 1))
fi
# The arc: every sample lies on the unit circle (radius within a few ulps),
# read back by Python.
"$casteljau" eval "$work/arc.json" --samples 101 > "$work/arc.csv"
if ! /usr/bin/python3 - "$work/arc.csv" <<'PY'
import math, sys
lines = open(sys.argv[1]).read().splitlines()
assert len(lines) == 101
for line in lines:
    x, y = map(float, line.split(","))
    assert abs(math.hypot(x, y) - 1) < 1e-15, line
PY
then
  echo "FAIL: arc samples are not on the unit circle"
  failures=$((failures + 1))
fi

finish "eval known values"
