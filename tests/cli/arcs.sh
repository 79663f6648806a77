#!/usr/bin/env bash
# casteljau arcs: cases worked by hand (a line is one segment, a square four
# and closed, the exact half circle one arc of bulge -1 from (-3, 0) to
# (3, 0): it turns clockwise over (0, 3)); the JSON document's fields; DXF
# output (by --to or -o FILE.dxf) read back by casteljau as the same
# segments, LWPOLYLINE entities, closed where the curve closes; an SVG
# drawing; the summary line; and bad input (exit 2, one line, nothing
# written). ezdxf reads the DXF too: tests/python/test_dxf_ezdxf.py.
# Usage: bash arcs.sh CASTELJAU EXAMPLES_DIR
source "$(dirname "$0")/support/common.sh" "$@"

fail_test() {
  echo "FAIL: $1"
  failures=$((failures + 1))
}

model line.json '{"type": "bezier", "control_points": [[0, 0], [4, 3]]}'
model square.json '{"type": "piecewise_bezier", "pieces": [[[0,0],[2,0]], [[2,0],[2,2]], [[2,2],[0,2]], [[0,2],[0,0]]]}'

# A line: one segment, bulge 0, its ends exactly.
"$casteljau" arcs "$work/line.json" --tolerance 0.1 >"$work/line.out" 2>"$work/line.err" ||
  fail_test "line: exit $?: $(cat "$work/line.err")"
grep -q '"closed": false, .*"segments": \[\[0, 0, 4, 3, 0\]\], "parameters": \[0, 1\]' "$work/line.out" ||
  fail_test "line: $(cat "$work/line.out")"
[[ "$(cat "$work/line.err")" == "arcs: 1 curve, 0 arcs and 1 line segment, within "*" of the curves (certified; tolerance 0.1)" ]] ||
  fail_test "line summary on stderr: $(cat "$work/line.err")"

# A square: four segments, closed.
"$casteljau" arcs "$work/square.json" --tolerance 0.1 -o "$work/square.json.out" >"$work/square.summary" ||
  fail_test "square: exit $?"
grep -q '"closed": true, .*"segments": \[\[0, 0, 2, 0, 0\], \[2, 0, 2, 2, 0\], \[2, 2, 0, 2, 0\], \[0, 2, 0, 0, 0\]\], "parameters": \[0, 1, 2, 3, 4\]' \
  "$work/square.json.out" || fail_test "square: $(cat "$work/square.json.out")"
[[ "$(cat "$work/square.summary")" == "arcs: 1 curve, 0 arcs and 4 line segments, within "* ]] ||
  fail_test "square summary on stdout with -o: $(cat "$work/square.summary")"

# The half circle: one arc, bulge -1 (a half turn, clockwise), ends exact, bound far below the tolerance.
"$casteljau" arcs "$examples/semicircle.json" --tolerance 0.01 -o "$work/semi.json" >/dev/null ||
  fail_test "semicircle: exit $?"
/usr/bin/python3 - "$work/semi.json" <<'EOF' || fail_test "semicircle JSON"
import json, sys
doc = json.load(open(sys.argv[1]))
assert doc["tolerance"] == 0.01, doc
[spline] = doc["splines"]
assert spline["curve"] == 0 and spline["closed"] is False, spline
[[x0, y0, x1, y1, bulge]] = spline["segments"]
assert (x0, y0, x1, y1) == (-3, 0, 3, 0), spline
assert abs(bulge + 1) < 1e-12, bulge
assert 0 <= spline["deviation_bound"] < 1e-9, spline
assert spline["parameters"] == [0, 1], spline
EOF

# DXF: by --to, or implied by -o FILE.dxf (any case); read back as the same pieces.
"$casteljau" arcs "$work/square.json" --tolerance 0.1 --to dxf >"$work/square.dxf" 2>/dev/null || fail_test "--to dxf: exit $?"
"$casteljau" arcs "$examples/semicircle.json" --tolerance 0.01 -o "$work/semi.DXF" >/dev/null || fail_test "-o .DXF: exit $?"
grep -q "^LWPOLYLINE$" "$work/square.dxf" || fail_test "square.dxf has no LWPOLYLINE"
grep -q "^LWPOLYLINE$" "$work/semi.DXF" || fail_test "semi.DXF has no LWPOLYLINE"
"$casteljau" info "$work/square.dxf" >"$work/square.info" 2>&1
grep -q "^elements: 1 (1 LWPOLYLINE)$" "$work/square.info" || fail_test "square.dxf info: $(cat "$work/square.info")"
grep -q "^Bezier pieces: 4 (4 of degree 1)$" "$work/square.info" || fail_test "square.dxf pieces: $(cat "$work/square.info")"
# The half circle read back: one rational arc, 3 pi long (9.42477796076938).
length=$("$casteljau" length "$work/semi.DXF")
/usr/bin/python3 -c "import math,sys; sys.exit(abs(float('$length') - 3 * math.pi) > 1e-12)" ||
  fail_test "semicircle through DXF: length $length"
# The sailboat: 19 subpaths, 19 polylines, as many segments as the JSON.
"$casteljau" arcs "$examples/sailboat.svg" --tolerance 0.01 -o "$work/boat.json" >/dev/null || fail_test "sailboat: exit $?"
"$casteljau" arcs "$examples/sailboat.svg" --tolerance 0.01 -o "$work/boat.dxf" >"$work/boat.summary" || fail_test "sailboat dxf"
"$casteljau" info "$work/boat.dxf" >"$work/boat.info" 2>&1
grep -q "^elements: 19 (19 LWPOLYLINE)$" "$work/boat.info" || fail_test "boat.dxf: $(cat "$work/boat.info")"
# Every line segment a piece of degree 1, every arc a bulge (the reader cuts arcs of more than a half turn in two).
read -r lines arcs < <(/usr/bin/python3 -c "
import json
segments = [s for spline in json.load(open('$work/boat.json'))['splines'] for s in spline['segments']]
print(sum(s[4] == 0 for s in segments), sum(s[4] != 0 for s in segments))")
grep -q "^Bezier pieces: [0-9]* ($lines of degree 1, " "$work/boat.info" || fail_test "boat.dxf: $lines lines: $(cat "$work/boat.info")"
bulges=$(awk '/^ENTITIES$/ { inside = 1 } inside && /^ENDSEC$/ { inside = 0 } inside && /^ 42$/ { n++ } END { print n + 0 }' "$work/boat.dxf")
[[ $bulges -eq $arcs ]] || fail_test "boat.dxf: $bulges bulges for $arcs arcs"
[[ "$(cat "$work/boat.summary")" =~ ^arcs:\ 19\ curves,\ [0-9]+\ arcs\ and\ [0-9]+\ line\ segments,\ within\ 0\.0099[0-9]*\ of ]] ||
  fail_test "sailboat summary: $(cat "$work/boat.summary")"

# Bad input: one line, exit 2, nothing written.
model surface.json '{"type": "bezier_surface", "control_points": [[[0,0,0],[1,0,0]],[[0,1,0],[1,1,1]]]}'
model space.json '{"type": "bezier", "control_points": [[0, 0, 0], [1, 2, 3]]}'
expect_error "tolerance 0" "--tolerance: 0 is not a distance > 0" arcs "$work/line.json" --tolerance 0
expect_error "tolerance -1" "--tolerance: -1 is not a distance > 0" arcs "$work/line.json" --tolerance -1
expect_error "tolerance nan" "--tolerance" arcs "$work/line.json" --tolerance nan
expect_error "tolerance missing" "--tolerance is required" arcs "$work/line.json"
expect_error "format" "--to: 'svg' is not json or dxf" arcs "$work/line.json" --tolerance 0.1 --to svg -o "$work/bad.json"
expect_error "surface" "arcs fits plane curves; the bezier_surface model in '$work/surface.json' is a surface" arcs "$work/surface.json" --tolerance 0.1 -o "$work/bad.json"
expect_error "space curve" "lives in R^3" arcs "$work/space.json" --tolerance 0.1 -o "$work/bad.json"
expect_error "missing file" "cannot open '$work/none.json'" arcs "$work/none.json" --tolerance 0.1
printf '<svg xmlns="http://www.w3.org/2000/svg" width="10" height="10"/>' >"$work/empty.svg"
expect_error "empty drawing" "the drawing has no path or shape to read" arcs "$work/empty.svg" --tolerance 0.1 -o "$work/bad.dxf"
[[ ! -e "$work/bad.json" && ! -e "$work/bad.dxf" ]] || fail_test "an error left a file"

finish arcs
