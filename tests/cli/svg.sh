#!/usr/bin/env bash
# casteljau on SVG drawings: every MODEL-taking command reads them (one curve
# per subpath, upright, the root's user units or --units mm), convert --to svg
# writes them (exact for lines, quadratics and cubics: the same doubles read
# back; other pieces as cubics within --tolerance, stated), and bad drawings
# (malformed XML, path data in error, --units on a file without units) are
# refused with one line naming the file, line and element, exit 2.
# Known values are worked by hand on dyadic data, so they are exact.
# Usage: bash svg.sh CASTELJAU EXAMPLES_DIR
source "$(dirname "$0")/support/common.sh" "$@"

# A square of side 4 drawn as a path in a group moved by (1, 2), and a line in
# a 10 x 10 mm drawing whose viewBox is 0 0 20 20 (a user unit is 0.5 mm).
# Read upright: y = 20 - y_file, up from the page's bottom edge.
model square.svg '<svg xmlns="http://www.w3.org/2000/svg" width="10mm" height="10mm" viewBox="0 0 20 20">
<g transform="translate(1 2)"><path id="sq" d="M0 0 h4 v4 h-4 z"/></g>
<line x1="0" y1="0" x2="8" y2="6"/></svg>'
check "eval reads each subpath" $'1,18\n5,18\n0,20\n8,14' eval "$work/square.svg" --at 0 --at 1
check "length of each curve" $'16\n10' length "$work/square.svg"
check "length in mm" $'8\n5' length "$work/square.svg" --units mm
model one.svg '<svg width="10mm" height="10mm" viewBox="0 0 20 20"><line x1="0" y1="0" x2="8" y2="6"/></svg>'
# In mm, from (0, 10) to (4, 7): the page is 10 mm high.
check "closest on a drawing with one subpath" $'query,t,distance,x,y\n0,0.5,0,2,8.5' \
  closest "$work/one.svg" --units mm --point 2,8.5
# Several curves: the nearest of them all and its curve. (3, 10) is 4 below
# the square's lower side (y = 14, its third piece: t = 2.5 at (3, 14)) and
# 6.2 from the line (0, 20) - (8, 14).
check "closest on two curves" $'query,curve,t,distance,x,y\n0,0,2.5,4,3,14' closest "$work/square.svg" --point 3,10
# Among the drawing's curves: the line y = 20 - 3x/4 enters the square
# through its upper side (y = 18) at x = 8/3 and leaves through its right
# side (x = 5) at y = 16.25.
"$casteljau" intersect "$work/square.svg" >"$work/among.json" || { echo "FAIL: intersect among"; failures=$((failures + 1)); }
/usr/bin/python3 - "$work/among.json" <<'EOF2' || { echo "FAIL: intersections among the drawing's curves: $(cat "$work/among.json")"; failures=$((failures + 1)); }
import json, sys
found = json.load(open(sys.argv[1]))["intersections"]
expected = [(0, 1, (8 / 3 - 1) / 4, 1 / 3, (8 / 3, 18)), (0, 1, 1 + 1.75 / 4, 5 / 8, (5, 16.25))]
assert len(found) == 2, found
for x, (ca, cb, a, b, point) in zip(found, expected):
    assert x["kind"] == "transversal" and (x["curve_a"], x["curve_b"]) == (ca, cb), x
    assert abs(x["a"] - a) < 1e-12 and abs(x["b"] - b) < 1e-12, x
    assert max(abs(p - q) for p, q in zip(x["point"], point)) < 1e-12, x
EOF2
check "--units user is the default" $'16\n10' length "$work/square.svg" --units user
expect_error "--units cm" "--units: 'cm' is not user or mm" length "$work/square.svg" --units cm
model line.json '{"type": "bezier", "control_points": [[0,0],[1,1]]}'
expect_error "--units mm on model JSON" "millimetres are asked of model JSON, whose numbers have no unit" \
  length "$work/line.json" --units mm
model nosize.svg '<svg viewBox="0 0 10 10"><path d="M0 0L1 1"/></svg>'
expect_error "--units mm without a size" "millimetres need the root <svg>'s width and height" \
  length "$work/nosize.svg" --units mm

# --- bad drawings ----------------------------------------------------------------
model broken.svg $'<svg>\n<path d="M0 0 L1 1">\n</svg>'
expect_error "malformed XML" "broken.svg, line 3, column 3: not well-formed XML: Start-end tags mismatch" \
  eval "$work/broken.svg" --at 0
model pathdata.svg $'<svg>\n<path id="p" d="M0 0 L1 1 L2 x"/></svg>'
expect_error "path data in error" "pathdata.svg, line 2, <path id='p'>: path data, character 14 ('x'): expected a number, 'L' takes x y" \
  eval "$work/pathdata.svg" --at 0
model text.svg '<svg><text>only words</text></svg>'
expect_error "nothing to read" "the drawing has no path or shape to read (line 1: <text> (text is not read" \
  length "$work/text.svg"
model html.svg '<html><body/></html>'
expect_error "not an SVG root" "the root element is <html>, an SVG drawing's is <svg>" length "$work/html.svg"

# --- convert --to svg ---------------------------------------------------------------
# Exact: the written drawing reads back to the same doubles.
model cubic.json '{"type": "bezier", "control_points": [[0.1,0.2],[1,3],[2.5,-1],[4,0.3]]}'
"$casteljau" convert "$work/cubic.json" --to svg -o "$work/cubic.svg" > "$work/summary"
[[ "$(cat "$work/summary")" == "convert: 1 curve to SVG, every piece exact" ]] ||
  { echo "FAIL: exact summary: $(cat "$work/summary")"; failures=$((failures + 1)); }
check "the cubic reads back exactly" "$("$casteljau" eval "$work/cubic.json" --samples 9)" \
  eval "$work/cubic.svg" --samples 9
"$casteljau" convert "$work/square.svg" --to svg -o "$work/written.svg" > /dev/null
[[ "$(grep -c '<path' "$work/written.svg")" == 2 && "$(grep -c 'id="sq"' "$work/written.svg")" == 1 ]] ||
  { echo "FAIL: the drawing written back: $(cat "$work/written.svg")"; failures=$((failures + 1)); }
check "the square reads back exactly" "$("$casteljau" eval "$work/square.svg" --samples 5)" \
  eval "$work/written.svg" --samples 5
# Rational and higher-degree pieces: cubics within the tolerance, which the summary states.
"$casteljau" convert "$examples/semicircle.json" --to svg --tolerance 1e-4 -o "$work/semi.svg" > "$work/summary"
if ! grep -qE '^convert: 1 curve to SVG, 2 rational or higher-degree pieces replaced by [0-9]+ cubics within [0-9.e-]+ \(--tolerance 0.0001\)$' "$work/summary"; then
  echo "FAIL: semicircle summary: $(cat "$work/summary")"; failures=$((failures + 1))
fi
grep -q 'replaced by' "$work/semi.svg" || { echo "FAIL: the file does not state its tolerance"; failures=$((failures + 1)); }
# Every sampled point of the written semicircle is within 1e-4 of the circle of radius 3.
if ! "$casteljau" eval "$work/semi.svg" --samples 200 | awk -F, '{ r = sqrt($1 * $1 + $2 * $2); d = r - 3;
     if (d < 0) d = -d; if (d > m) m = d } END { exit !(m <= 1e-4) }'; then
  echo "FAIL: the written semicircle leaves the circle"; failures=$((failures + 1))
fi
expect_error "--tolerance 0" "--tolerance: 0 is not a distance > 0" convert "$examples/semicircle.json" --to svg --tolerance 0
expect_error "--tolerance for json" "--tolerance applies to --to svg" convert "$examples/semicircle.json" --to json --tolerance 1
expect_error "a surface to svg" "is a surface; surfaces go to iges and step" convert "$examples/patch.json" --to svg
finish svg
