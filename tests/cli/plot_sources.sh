#!/usr/bin/env bash
# casteljau plot and bernstein, issue 15: a CSV drawn as data beside a curve
# (distinct markers, a legend that says which is which), the extent of the
# Runge polynomial, errors from extreme inputs that name the file, and
# figures that finish (the Bernstein basis of degree 1000, the documented
# limit; a curve of degree 10,000 refused at once).
# Usage: bash plot_sources.sh <casteljau-binary> <repo>/examples
source "$(dirname "$0")/support/common.sh" "$@"

# svg_texts FILE: the text elements of an SVG, one per line.
svg_texts() { grep -o '<text[^>]*>[^<]*</text>' "$1" | sed 's/<[^>]*>//g'; }

# --- data points beside a curve ---------------------------------------------------
"$casteljau" interpolate "$examples/head.csv" --method c1-bezier -o "$work/head.json"
check "data points beside the interpolant" "" plot "$work/head.json" "$examples/head.csv" --data-points --points \
  -o "$work/head.svg"
svg_texts "$work/head.svg" >"$work/texts"
for entry in "head.csv (data points)" "control points"; do
  grep -qxF "$entry" "$work/texts" || { echo "FAIL: legend entry '$entry' missing"; failures=$((failures + 1)); }
done
# Data points are diamonds (closed four-point paths), control points discs.
grep -q '<circle' "$work/head.svg" || { echo "FAIL: no control point discs"; failures=$((failures + 1)); }
[[ $(grep -c "<polygon points=\"[^ ]* [^ ]* [^ ]* [^ ]*\" fill=\"#1f77b4\"" "$work/head.svg") -ge 20 ]] ||
  { echo "FAIL: fewer than 20 data point diamonds (19 points and the legend)"; failures=$((failures + 1)); }
check "the polyline through the data" "" plot "$work/head.json" "$examples/head.csv" --data-polyline -o "$work/p.svg"
svg_texts "$work/p.svg" | grep -qxF "head.csv (polyline)" ||
  { echo "FAIL: legend entry 'head.csv (polyline)' missing"; failures=$((failures + 1)); }
check "--points-only beside model JSON" "" plot "$work/head.json" "$examples/head.csv" --points-only -o "$work/q.svg"

# --- drawings (issue 39): one legend entry and one color per file, DXF and files
# without an extension read as every command reads them -----------------------------
check "a drawing beside a curve" "" plot "$examples/sailboat.svg" "$examples/semicircle.json" -o "$work/boat.svg"
svg_texts "$work/boat.svg" >"$work/texts"
[[ "$(grep -cxF "sailboat.svg" "$work/texts")" == 1 && "$(grep -c 'sailboat.svg\[' "$work/texts")" == 0 ]] ||
  { echo "FAIL: the drawing's legend: $(tr '\n' '|' <"$work/texts")"; failures=$((failures + 1)); }
grep -qxF "semicircle.json" "$work/texts" || { echo "FAIL: the curve's legend entry"; failures=$((failures + 1)); }
"$casteljau" convert "$examples/sailboat.svg" --to dxf -o "$work/boat.dxf"
check "a DXF drawing" "" plot "$work/boat.dxf" -o "$work/dxf.svg"
cp "$work/boat.dxf" "$work/boat"
check "a drawing without an extension" "" plot "$work/boat" -o "$work/noext.svg"

# --- the Runge exercise: the y axis holds the curve's dips to -59.78 ------------------
/usr/bin/env awk 'BEGIN { print "x,y"; for (i = 0; i <= 20; i++) { x = -1 + i / 10; printf "%.17g,%.17g\n", x, 1 / (1 + 25 * x * x) } }' \
  >"$work/runge.csv"
"$casteljau" interpolate "$work/runge.csv" --method lagrange --function -o "$work/r.json"
check "plot of the Runge polynomial" "" plot "$work/r.json" -o "$work/r.svg"
svg_texts "$work/r.svg" | grep -qx $'\u221260' ||
  { echo "FAIL: the y axis of the Runge plot does not reach -60: $(svg_texts "$work/r.svg" | tr '\n' ' ')"; failures=$((failures + 1)); }

# --- extreme inputs: the error names the file (and the model) -----------------------
# Coordinates beyond 1e100 are refused by the model's make() (core/tolerance.hpp,
# kMaxCoordinate); the figure's own range checks are tested in plot_sources_test.cpp.
model big.json '{"type":"bezier","control_points":[[-1e308,0],[1e308,1]]}'
expect_error "too wide, named" "big.json, control_points: coordinate 0 of control point 0 is -1e+308, outside" \
  plot "$work/big.json" -o "$work/x.svg"
model two.json '{"models":[{"type":"bezier","control_points":[[0,0],[1,1]]},{"type":"bezier","control_points":[[0,-1e308],[1,1e308]]}]}'
expect_error "too wide, model named" "two.json, models[1].control_points: coordinate 1 of control point 0 is -1e+308" \
  plot "$work/two.json" -o "$work/x.svg"
model near.json '{"type":"bezier","control_points":[[1e10,0],[1e10,1],[10000000001,1],[10000000001,0]]}'
expect_error "cannot certify, named" "near.json: " plot "$work/near.json" -o "$work/x.svg"
model surface.json '{"type":"bezier_surface","control_points":[[[0,0,0],[1,0,1e308]],[[0,1,0],[1e308,-1e308,1e308]]]}'
expect_error "surface too wide, named" "surface.json, control_points: coordinate 2 of control point [0][1] is 1e+308" \
  plot "$work/surface.json" -o "$work/x.svg"
[[ -e "$work/x.svg" ]] && { echo "FAIL: a failed plot wrote x.svg"; failures=$((failures + 1)); }

# --- figures that finish, or refuse at once ------------------------------------------
# In a pipe, no progress line; with CASTELJAU_PROGRESS=always, the degree 1000
# (the documented limit, about 1.4 s) shows one once it has run a second.
check "the Bernstein basis of degree 300" "" bernstein 300 -o "$work/b.svg"
start=$(date +%s%N)
CASTELJAU_PROGRESS=always "$casteljau" bernstein 1000 -o "$work/b.svg" 2>"$work/progress"
elapsed_ms=$(( ($(date +%s%N) - start) / 1000000 ))
if ! tr '\r' '\n' <"$work/progress" | sed 's/\x1b\[K//g' | grep -v '^$' | grep -qvE '^casteljau bernstein: [0-9]+ %$'; then :; else
  echo "FAIL: bernstein's stderr holds more than its progress line"; failures=$((failures + 1))
fi
[[ -s "$work/b.svg" ]] || { echo "FAIL: bernstein 1000 wrote no figure"; failures=$((failures + 1)); }
if [[ $elapsed_ms -ge 1500 ]] && ! grep -qE 'casteljau bernstein: [0-9]+ %' "$work/progress"; then
  echo "FAIL: bernstein 1000 ran $elapsed_ms ms without a progress line"; failures=$((failures + 1))
fi
awk 'BEGIN { print "x,y"; srand(7); for (i = 0; i <= 10000; i++) printf "%.6f,%.6f\n", rand(), rand() }' >"$work/high.csv"
expect_error "degree 10000 refused" "high.csv: a curve of degree 10000 is beyond what a figure draws" \
  plot "$work/high.csv" -o "$work/x.svg"
# A construction is drawn up to degree 200 (n(n+1)/2 segments), refused beyond.
head -n 202 "$work/high.csv" >"$work/degree200.csv"
head -n 203 "$work/high.csv" >"$work/degree201.csv"
"$casteljau" plot "$work/degree200.csv" --construction 0.5 -o "$work/c200.svg" ||
  { echo "FAIL: the construction of degree 200 was refused"; failures=$((failures + 1)); }
expect_error "construction of degree 201 refused" \
  "--construction: degree201.csv has degree 201, whose construction is 20301 segments, too many to show (at most degree 200)" \
  plot "$work/degree201.csv" --construction 0.5 -o "$work/c201.svg"

finish plot_sources
