#!/usr/bin/env bash
# casteljau on bspline models: eval (points, derivatives, --samples over
# [t_p, t_{n+1}], the domain check), convert (bezier-pieces, bspline, json;
# the formats refused), plot, and bad input (exit 2, one line on
# stderr naming the field, nothing written).
# Known values are worked by hand on dyadic data, so they are exact (below).
# Usage: bash bspline.sh CASTELJAU EXAMPLES_DIR
source "$(dirname "$0")/support/common.sh" "$@"

# --- eval ----------------------------------------------------------------------
# A uniform quadratic on [2, 4] (knots 2,2,2,3,4,4,4), P = (0,0) (2,4) (4,0) (6,4).
# By hand (The NURBS Book eq. 3.4-3.9): C(2) = P0, C(4) = P3, C(3) = (P1 + P2)/2 = (3,2);
# C'(2) = 2 (P1 - P0)/(3 - 2) = (4,8) and C'(4) = 2 (P3 - P2)/(4 - 3) = (4,8);
# first-derivative points Q = (4,8) (2,-4) (4,8) on knots 2,2,3,4,4, so C'' = (Q1 - Q0)/1 = (-2,-12)
# on [2,3) and (Q2 - Q1)/1 = (2,12) on [3,4]; C''' = 0.
model quad.json '{"type": "bspline", "degree": 2, "knots": [2,2,2,3,4,4,4], "control_points": [[0,0],[2,4],[4,0],[6,4]]}'
check "points at the ends and the knot" $'0,0\n3,2\n6,4' eval "$work/quad.json" --at 2 --at 3 --at 4
check "--samples over [t_p, t_{n+1}]" $'0,0\n3,2\n6,4' eval "$work/quad.json" --samples 3
check "first derivative at the ends" $'4,8\n4,8' eval "$work/quad.json" --at 2 --at 4 --derivative 1
check "second derivative, right span at a knot" $'-2,-12\n2,12\n2,12' eval "$work/quad.json" --at 2.5 --at 3 --at 4 --derivative 2
check "third derivative vanishes" "0,0" eval "$work/quad.json" --at 2.5 --derivative 3
printf 'u\n2\n# a comment\n3.5\n' > "$work/params.csv"
# C(3.5) on span [3,4): Cox-de Boor gives N_1 = 1/8, N_2 = 5/8, N_3 = 1/4 (the clamped end
# breaks the symmetry), so C = (2,4)/8 + 5 (4,0)/8 + (6,4)/4 = (4.25, 1.5).
check "--params" $'0,0\n4.25,1.5' eval "$work/quad.json" --params "$work/params.csv"
# The Rhino/openNURBS knot count (n + p - 1 = 5 knots) gives the same curve.
model rhino.json '{"type": "bspline", "degree": 2, "knots": [2,2,3,4,4], "control_points": [[0,0],[2,4],[4,0],[6,4]]}'
check "Rhino knots" $'0,0\n3,2\n4.25,1.5\n6,4' eval "$work/rhino.json" --at 2 --at 3 --at 3.5 --at 4
expect_error "parameter below the domain" "--at 1.5 is outside the domain [2, 4] of the bspline model in '$work/quad.json'" \
  eval "$work/quad.json" --at 1.5
printf '3\n5\n' > "$work/outside.csv"
expect_error "parameter above the domain" "outside.csv, line 2: 5 is outside the domain [2, 4]" \
  eval "$work/quad.json" --params "$work/outside.csv"
# The seed 003 semicircle as an exact NURBS (two quarter arcs): ends and top exact.
model semicircle.json '{"type": "bspline", "degree": 2, "knots": [0,0,0,0.5,0.5,1,1,1], "control_points": [[-3,0],[-3,3],[0,3],[3,3],[3,0]], "weights": [1,0.7071067811865476,1,0.7071067811865476,1]}'
check "NURBS semicircle" $'-3,0\n0,3\n3,0' eval "$work/semicircle.json" --samples 3
# Start tangent of a rational quadratic: 2 (w1/w0) (P1 - P0)/(1/2) = (0, 12 w1) = (0, 6 sqrt 2), up to
# the rounding of the quotient rule (A4.2), a few ulps of the scale 12.
out=$("$casteljau" eval "$work/semicircle.json" --at 0 --derivative 1)
if ! awk -F, -v line="$out" 'BEGIN { split(line, c, ","); ex = c[1]; ey = c[2] - 6 * sqrt(2);
       exit !(NF == 0 && c[1] != "" && ex * ex < 1e-28 && ey * ey < 1e-28) }'; then
  echo "FAIL: NURBS start tangent: $out"
  failures=$((failures + 1))
fi

# --- convert -----------------------------------------------------------------------
# bezier-pieces: piece i on [i, i+1]; the quadratic's pieces meet at (3,2) and end at P3.
check "convert --to bezier-pieces" \
  '{"type":"piecewise_bezier","pieces":[[[0,0],[2,4],[3,2]],[[3,2],[4,0],[6,4]]]}' \
  convert "$work/quad.json" --to bezier-pieces
"$casteljau" convert "$work/quad.json" --to bezier-pieces -o "$work/pieces.json" || failures=$((failures + 1))
check "pieces evaluate like the B-spline" $'0,0\n3,2\n6,4' eval "$work/pieces.json" --at 0 --at 1 --at 2
# ... and back: joints become double knots on [0, 2].
check "pieces --to bspline" \
  '{"type":"bspline","degree":2,"knots":[0,0,0,1,1,2,2,2],"control_points":[[0,0],[2,4],[3,2],[4,0],[6,4]]}' \
  convert "$work/pieces.json" --to bspline
check "bezier --to bspline" \
  '{"type":"bspline","degree":4,"knots":[0,0,0,0,0,1,1,1,1,1],"control_points":[[0,0],[1,2],[2,2],[4,1],[4,0]]}' \
  convert "$examples/notebook_polygon.csv" --to bspline
check "bspline --to bspline is the identity" \
  '{"type":"bspline","degree":2,"knots":[2,2,2,3,4,4,4],"control_points":[[0,0],[2,4],[4,0],[6,4]]}' \
  convert "$work/rhino.json" --to bspline
check "convert --to json" \
  '{"type":"bspline","degree":2,"knots":[0,0,0,0.5,0.5,1,1,1],"control_points":[[-3,0],[-3,3],[0,3],[3,3],[3,0]],"weights":[1,0.7071067811865476,1,0.7071067811865476,1]}' \
  convert "$work/semicircle.json" --to json
# Rational pieces stay rational.
"$casteljau" convert "$work/semicircle.json" --to bezier-pieces -o "$work/arcs.json" || failures=$((failures + 1))
check "rational pieces" $'-3,0\n0,3\n3,0' eval "$work/arcs.json" --at 0 --at 1 --at 2
# Several models: {"models": [...]} in, the same out.
model two.json '{"models": [{"type": "bezier", "control_points": [[0,0],[1,1]]}, {"type": "bspline", "degree": 1, "knots": [0,0,1,1], "control_points": [[1,1],[2,0]]}]}'
check "several models" \
  $'{"models":[\n{"type":"bspline","degree":1,"knots":[0,0,1,1],"control_points":[[0,0],[1,1]]},\n{"type":"bspline","degree":1,"knots":[0,0,1,1],"control_points":[[1,1],[2,0]]}\n]}' \
  convert "$work/two.json" --to bspline

printf 'keep' > "$work/existing.svg"
model space.json '{"type": "bezier", "control_points": [[0,0,0],[1,1,1]]}'
expect_error "--to svg of a 3D curve" "--to svg: the bezier model in '$work/space.json' lives in R^3, SVG drawings are plane" \
  convert "$work/space.json" --to svg -o "$work/existing.svg"
[[ "$(cat "$work/existing.svg")" == keep ]] || { echo "FAIL: --to svg touched its output"; failures=$((failures + 1)); }
model space4.json '{"type": "bezier", "control_points": [[0,0,0,0],[1,1,1,1]]}'
for format in iges step; do
  expect_error "--to $format of a curve in R^4" "--to $format: the bezier model in '$work/space4.json' lives in R^4" \
    convert "$work/space4.json" --to "$format" -o "$work/x.$format"
  [[ ! -e "$work/x.$format" ]] || { echo "FAIL: --to $format wrote a file"; failures=$((failures + 1)); }
done
expect_error "--to gcode" "--to gcode: not a conversion of curves; casteljau gcode writes it" \
  convert "$work/quad.json" --to gcode -o "$work/x.gcode"
expect_error "--to unknown" "--to 'nurbs': unknown format" convert "$work/quad.json" --to nurbs
expect_error "--to missing" "--to" convert "$work/quad.json"
model gap.json '{"type": "piecewise_bezier", "pieces": [[[0,0],[1,1]], [[2,2],[3,3]]]}'
expect_error "pieces that do not meet" "--to bspline: the piecewise_bezier model in '$work/gap.json': piece 1 starts" \
  convert "$work/gap.json" --to bspline -o "$work/gap-out.json"
[[ ! -e "$work/gap-out.json" ]] || { echo "FAIL: a failed convert wrote a file"; failures=$((failures + 1)); }

# --- plot ----------------------------------------------------------------------------
if "$casteljau" plot "$work/semicircle.json" "$work/quad.json" -o "$work/plot.svg" 2>"$work/stderr" &&
   grep -q '<svg' "$work/plot.svg" && [[ ! -s "$work/stderr" ]]; then :; else
  echo "FAIL: plot of bspline models: $(cat "$work/stderr")"
  failures=$((failures + 1))
fi

# --- bad input: one line, exit 2, the field named ----------------------------------------
points='"control_points": [[0,0],[1,2],[2,2],[4,1]]'
model decreasing.json "{\"type\": \"bspline\", \"degree\": 2, \"knots\": [0,0,0,0.7,0.5,1,1], $points}"
expect_error "decreasing knots" "decreasing.json, knots: knot 4 (0.5) is smaller than knot 3 (0.7), knots must be non-decreasing" \
  eval "$work/decreasing.json" --at 0
model count.json "{\"type\": \"bspline\", \"degree\": 2, \"knots\": [0,0,0,1,1,1], $points}"
expect_error "wrong knot count" "count.json, knots: 6 knots" \
  eval "$work/count.json" --at 0
model zero.json "{\"type\": \"bspline\", \"degree\": 2, \"knots\": [0,0,0,0.5,1,1,1], \"weights\": [1,0,1,1], $points}"
expect_error "zero weight" "zero.json, weights: weight 1" eval "$work/zero.json" --at 0
model nan.json "{\"type\": \"bspline\", \"degree\": 2, \"knots\": [0,0,0,NaN,1,1,1], $points}"
expect_error "NaN knot (not JSON)" "nan.json, line 1, column 50: syntax error" eval "$work/nan.json" --at 0
expect_error "NaN parameter" "--at: 'nan' is NaN" eval "$work/quad.json" --at nan
model degree.json "{\"type\": \"bspline\", \"degree\": 4, \"knots\": [0,0,0,0,0,1,1,1,1], $points}"
expect_error "too few control points" "degree.json, control_points: 4 control points, a B-spline of degree 4 needs at least 5" \
  eval "$work/degree.json" --at 0
model nested.json "{\"models\": [{\"type\": \"bezier\", \"control_points\": [[0,0]]}, {\"type\": \"bspline\", \"degree\": 2, \"knots\": [0,0,0,0.5,1,1,1], \"weights\": [1,1,-1,1], $points}]}"
expect_error "weight path in a list" "nested.json, models[1].weights: weight 2" \
  convert "$work/nested.json" --to bezier-pieces
expect_error "plot of a bad model" "zero.json, weights: weight 1" plot "$work/zero.json" -o "$work/bad.svg"
[[ ! -e "$work/bad.svg" ]] || { echo "FAIL: plot wrote a figure of a bad model"; failures=$((failures + 1)); }

finish "bspline CLI"
