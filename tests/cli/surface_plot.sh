#!/usr/bin/env bash
# casteljau plot on surfaces (issue 5): SVG iso-curves and control nets in
# the orthographic view, PNG/PDF with the shaded panel, --view, and bad input
# (exit 2, one error line, no output file).
# Usage: bash surface_plot.sh CASTELJAU EXAMPLES_DIR
source "$(dirname "$0")/support/common.sh" "$@"

# figure NAME FILE MAGIC_HEX ARGS...: exit 0, nothing on stderr, FILE starts with MAGIC.
figure() {
  local name=$1 file=$2 magic=$3
  shift 3
  "$casteljau" "$@" >"$work/stdout" 2>"$work/stderr"
  local status=$?
  local head
  head=$(head -c $((${#magic} / 2)) "$file" 2>/dev/null | od -An -tx1 | tr -d ' \n')
  if [[ $status -ne 0 || -s "$work/stderr" || "$head" != "$magic" ]]; then
    echo "FAIL: $name: casteljau $* (exit $status, magic $head, stderr $(cat "$work/stderr"))"
    failures=$((failures + 1))
  fi
}
# no_file NAME FILE: FILE was not written.
no_file() { if [[ -e "$2" ]]; then echo "FAIL: $1: $2 written"; failures=$((failures + 1)); fi; }

model patch.json '{"type": "bezier_surface", "control_points": [
  [[0,0,0],[0,1,0.5],[0,2,0.5],[0,3,0]], [[1,0,0.5],[1,1,2],[1,2,1.6],[1,3,0.4]],
  [[2,0,0.4],[2,1,1.8],[2,2,2.6],[2,3,0.9]], [[3,0,0],[3,1,0.5],[3,2,1],[3,3,0.3]]]}'
model coons.json '{"type": "coons", "blending": "cubic", "boundaries": {
  "u0": {"type": "bezier", "control_points": [[0,0,0],[0,0.5,1],[0,1,0]]},
  "u1": {"type": "bezier", "control_points": [[1,0,0],[1,1,0]]},
  "v0": {"type": "bezier", "control_points": [[0,0,0],[1,0,0]]},
  "v1": {"type": "bezier", "control_points": [[0,1,0],[0.5,1,-1],[1,1,0]]}}}'
model plane.json '{"type": "bezier_surface", "control_points": [[[0,0],[0,1]], [[1,0],[1.5,1.5]]]}'
model nurbs.json '{"type": "bspline_surface", "degree": [2,1], "knots": [[0,0,0,1,1,1],[0,0,1,1]],
  "control_points": [[[1,0,0],[1,0,1]], [[1,1,0],[1,1,1]], [[0,1,0],[0,1,1]]],
  "weights": [[1,1],[0.7071067811865476,0.7071067811865476],[1,1]]}'

svg=3c3f786d6c  # "<?xml"
png=89504e470d0a1a0a
pdf=25504446  # "%PDF"
figure "SVG of a Bézier patch" "$work/patch.svg" $svg plot "$work/patch.json" -o "$work/patch.svg"
figure "SVG with the control net and points" "$work/net.svg" $svg plot "$work/patch.json" -o "$work/net.svg" \
  --control-polygon --points
figure "PNG (shaded)" "$work/patch.png" $png plot "$work/patch.json" -o "$work/patch.png" --control-polygon
figure "PDF (shaded)" "$work/patch.pdf" $pdf plot "$work/patch.json" -o "$work/patch.pdf"
figure "Coons patch PNG" "$work/coons.png" $png plot "$work/coons.json" -o "$work/coons.png" --control-polygon
figure "NURBS cylinder quarter PNG" "$work/nurbs.png" $png plot "$work/nurbs.json" -o "$work/nurbs.png"
figure "several surfaces, another view" "$work/two.svg" $svg plot "$work/patch.json" "$work/coons.json" \
  -o "$work/two.svg" --view 30,60 --iso-curves 5
figure "a plane surface (PNG: no shading)" "$work/plane.png" $png plot "$work/plane.json" -o "$work/plane.png"

# The SVG holds the iso-curves as polylines: 11 + 11 curves, and with the
# net 4 + 4 more; more lines with the net than without.
plain=$(grep -c '<polyline' "$work/patch.svg")
with_net=$(grep -c '<polyline' "$work/net.svg")
if [[ $plain -lt 22 || $with_net -lt $((plain + 8)) ]]; then
  echo "FAIL: polylines: $plain without the net (expected >= 22), $with_net with it (expected >= $((plain + 8)))"
  failures=$((failures + 1))
fi
grep -q 'orthographic view, azimuth -60°, elevation 30°' "$work/patch.svg" ||
  { echo "FAIL: the SVG does not name its view"; failures=$((failures + 1)); }
grep -q 'azimuth 30°, elevation 60°' "$work/two.svg" ||
  { echo "FAIL: --view 30,60 is not the view drawn"; failures=$((failures + 1)); }
# The PNG with the shaded panel is wider than the SVG without it.
png_width=$(od -An -tu1 -j16 -N4 "$work/patch.png" | awk '{print $1*16777216 + $2*65536 + $3*256 + $4}')
if [[ $png_width -le 900 ]]; then echo "FAIL: PNG width $png_width, expected the two-panel figure"; failures=$((failures + 1)); fi

# --- bad input ------------------------------------------------------------------
expect_error "--view without a comma" "--view: '30' is not a pair azimuth,elevation in degrees" \
  plot "$work/patch.json" -o "$work/bad1.svg" --view 30
no_file "--view 30" "$work/bad1.svg"
expect_error "elevation beyond 90" "--view: elevation 100 is not in [-90, 90]" \
  plot "$work/patch.json" -o "$work/bad2.svg" --view 0,100
no_file "--view 0,100" "$work/bad2.svg"
expect_error "--view with curves only" "--view applies to surfaces" \
  plot "$examples/notebook_polygon.csv" -o "$work/bad3.svg" --view 0,10
expect_error "curves and surfaces together" "plot draws curves and surfaces in separate figures" \
  plot "$work/patch.json" "$examples/notebook_polygon.csv" -o "$work/bad4.svg"
no_file "mixed" "$work/bad4.svg"
expect_error "--comb on a surface" "--comb applies to curves, not to surfaces" plot "$work/patch.json" -o "$work/bad5.svg" --comb
expect_error "--construction on a surface" "--construction applies to curves" \
  plot "$work/patch.json" -o "$work/bad6.svg" --construction 0.5
expect_error "one iso-curve" "--iso-curves: 1 is not in [2, 1000]" plot "$work/patch.json" -o "$work/bad7.svg" --iso-curves 1
model line.json '{"type": "bezier_surface", "control_points": [[[0],[1]], [[2],[3]]]}'
expect_error "a surface in R^1" "a bezier_surface in R^1 cannot be drawn" plot "$work/line.json" -o "$work/bad8.svg"
model weights.json '{"type": "bezier_surface", "control_points": [[[0,0,0],[0,1,0]], [[1,0,0],[1,1,1]]], "weights": [[1,1]]}'
expect_error "weights not matching the net" "weights.json, weights: 1 row of weights for a control net of 2 rows" \
  plot "$work/weights.json" -o "$work/bad9.png"
no_file "bad weights" "$work/bad9.png"

finish surface_plot
