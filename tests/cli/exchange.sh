#!/usr/bin/env bash
# casteljau convert --to iges|step: files for CAD from model JSON, CSV, SVG
# and DXF inputs, curves and surfaces, the summary line, the date from
# SOURCE_DATE_EPOCH (same input, same bytes), the file name from -o, and the
# refusals (exit 2, one line, nothing written). OpenCASCADE reads these files
# in tests/exchange/occt_exchange_test.cpp. Usage: bash exchange.sh CASTELJAU EXAMPLES_DIR
source "$(dirname "$0")/support/common.sh" "$@"
export SOURCE_DATE_EPOCH=1796374800  # 2026-12-04T09:00:00Z

# A curve and a surface, to both formats.
"$casteljau" convert "$examples/semicircle.json" --to iges -o "$work/semi.igs" >"$work/summary" 2>"$work/stderr" ||
  { echo "FAIL: convert --to iges"; failures=$((failures + 1)); }
[[ "$(cat "$work/summary")" == "convert: 1 curve and 0 surfaces to IGES 5.3 (entities 126 and 128), exact (every knot, control point and weight as it is), labelled millimetres (the input states no unit)" && ! -s "$work/stderr" ]] ||
  { echo "FAIL: the IGES summary: $(cat "$work/summary") $(cat "$work/stderr")"; failures=$((failures + 1)); }
[[ "$(tail -c1 "$work/summary" | wc -l)" == 1 ]] || { echo "FAIL: the summary line ends without a newline"; failures=$((failures + 1)); }
"$casteljau" convert "$examples/semicircle.json" --to svg -o "$work/semi.svg" >"$work/svg-summary"
[[ "$(tail -c1 "$work/svg-summary" | wc -l)" == 1 ]] || { echo "FAIL: the svg summary line ends without a newline"; failures=$((failures + 1)); }
awk 'length($0) != 80 { bad = 1 } END { exit bad }' "$work/semi.igs" ||
  { echo "FAIL: an IGES record is not 80 columns"; failures=$((failures + 1)); }
grep -q '8Hsemi.igs' "$work/semi.igs" || { echo "FAIL: the IGES file is named after -o"; failures=$((failures + 1)); }
grep -q '15H20261204.090000' "$work/semi.igs" || { echo "FAIL: the IGES date is SOURCE_DATE_EPOCH's"; failures=$((failures + 1)); }
[[ "$(cut -c1-8 "$work/semi.igs" | sed -n '/^     126$/p' | wc -l)" == 2 ]] ||
  { echo "FAIL: one entity 126 (two directory records)"; failures=$((failures + 1)); }

"$casteljau" convert "$examples/sphere.json" --to step -o "$work/sphere.stp" >"$work/summary" ||
  { echo "FAIL: convert --to step"; failures=$((failures + 1)); }
[[ "$(cat "$work/summary")" == "convert: 0 curves and 1 surface to STEP AP214, exact (every knot, control point and weight as it is), labelled millimetres (the input states no unit)" ]] ||
  { echo "FAIL: the STEP summary: $(cat "$work/summary")"; failures=$((failures + 1)); }
grep -q "^FILE_NAME('sphere.stp','2026-12-04T09:00:00'," "$work/sphere.stp" ||
  { echo "FAIL: the STEP header names the file and the date"; failures=$((failures + 1)); }
grep -q "B_SPLINE_SURFACE_WITH_KNOTS" "$work/sphere.stp" && grep -q "RATIONAL_B_SPLINE_SURFACE" "$work/sphere.stp" ||
  { echo "FAIL: the sphere is a rational B-spline surface"; failures=$((failures + 1)); }

# To standard output: the file there, the summary on standard error; the same bytes twice.
"$casteljau" convert "$examples/patch.json" --to step >"$work/one.stp" 2>"$work/stderr"
"$casteljau" convert "$examples/patch.json" --to step >"$work/two.stp" 2>/dev/null
cmp -s "$work/one.stp" "$work/two.stp" || { echo "FAIL: the same input gives other bytes"; failures=$((failures + 1)); }
grep -q "^convert: 0 curves and 1 surface to STEP" "$work/stderr" ||
  { echo "FAIL: the summary goes to stderr when the file goes to stdout"; failures=$((failures + 1)); }
grep -q "^FILE_NAME('patch.json'," "$work/one.stp" ||
  { echo "FAIL: on stdout the file is named after the input"; failures=$((failures + 1)); }

# Every input format: a CSV polygon, an SVG drawing, a DXF drawing.
for input in "$examples/notebook_polygon.csv" "$examples/sailboat.svg"; do
  for format in iges step; do
    "$casteljau" convert "$input" --to "$format" -o "$work/out.$format" >/dev/null ||
      { echo "FAIL: convert $input --to $format"; failures=$((failures + 1)); }
  done
done
"$casteljau" convert "$examples/semicircle.json" --to dxf -o "$work/semi.dxf"
"$casteljau" convert "$work/semi.dxf" --to iges -o "$work/from-dxf.igs" >/dev/null ||
  { echo "FAIL: a DXF drawing to IGES"; failures=$((failures + 1)); }

# Refusals: nothing written.
expect_error "--tolerance is for svg" "--tolerance applies to --to svg (the cubics' distance); --to iges is exact" \
  convert "$examples/semicircle.json" --to iges --tolerance 0.1 -o "$work/no.igs"
model point.json '{"type": "bezier", "control_points": [[1,2]]}'
expect_error "degree 0" "--to step: model 0 (bezier) has degree 0 (steps, not a curve); STEP B-splines have degree >= 1" \
  convert "$work/point.json" --to step -o "$work/no.stp"
model gap.json '{"type": "piecewise_bezier", "pieces": [[[0,0],[1,1]], [[2,2],[3,3]]]}'
expect_error "pieces that do not meet" "--to iges: model 0 (piecewise_bezier): piece 1 starts" \
  convert "$work/gap.json" --to iges -o "$work/no.igs"
for file in no.igs no.stp; do
  [[ ! -e "$work/$file" ]] || { echo "FAIL: a refused convert wrote $file"; failures=$((failures + 1)); }
done
finish exchange
