#!/usr/bin/env bash
# casteljau interpolate: every method runs on the seeds' head and car and its
# output is a model that eval reads and that passes through the points; known
# values worked by hand; --closed with a repeated first point; -o writes
# atomically; bad input exits 2 with one line naming what is wrong and
# writes nothing. (The agreement with scipy is tests/python/test_interpolate_scipy.py.)
# Usage: bash interpolate.sh CASTELJAU EXAMPLES_DIR
source "$(dirname "$0")/support/common.sh" "$@"

# ok NAME ARGS...: exit 0, nothing on stderr, a model JSON on stdout (kept in $work/out.json).
ok() {
  local name=$1
  shift
  "$casteljau" "$@" >"$work/out.json" 2>"$work/stderr"
  local status=$?
  if [[ $status -ne 0 || -s "$work/stderr" || "$(head -c 9 "$work/out.json")" != '{"type":"' ]]; then
    echo "FAIL: $name: casteljau $*"
    echo "  exit $status, stderr: $(cat "$work/stderr"), stdout: $(head -c 200 "$work/out.json")"
    failures=$((failures + 1))
    return 1
  fi
}

# passes_through NAME FILE.csv PARAMS...: the model in $work/out.json evaluated at
# PARAMS gives the points of FILE.csv (data rows only), to 1e-12 of their scale.
passes_through() {
  local name=$1 points=$2
  shift 2
  local at=()
  for u in "$@"; do at+=(--at "$u"); done
  if ! "$casteljau" eval "$work/out.json" "${at[@]}" >"$work/eval.csv" 2>"$work/stderr"; then
    echo "FAIL: $name: eval: $(cat "$work/stderr")"
    failures=$((failures + 1))
    return
  fi
  grep -v '^#' "$points" | grep -v '^[a-z]' >"$work/data.csv"
  if ! paste -d, "$work/eval.csv" "$work/data.csv" | awk -F, '
      { half = NF / 2; for (k = 1; k <= half; k++) { d = $k - $(k + half); if (d < 0) d = -d;
          if (d > worst) worst = d; a = $(k + half); if (a < 0) a = -a; if (a > scale) scale = a } ; rows++ }
      END { exit !(rows > 0 && worst <= 1e-12 * scale) }'; then
    echo "FAIL: $name: the curve does not pass through the points"
    paste -d, "$work/eval.csv" "$work/data.csv" | head -5
    failures=$((failures + 1))
  fi
}

# near NAME EXPECTED ARGS...: like check, but each number within 1e-12 of the largest expected one.
near() {
  local name=$1 expected=$2
  shift 2
  local out status
  out=$("$casteljau" "$@" 2>"$work/stderr")
  status=$?
  if [[ $status -ne 0 || -s "$work/stderr" ]] || ! awk -v a="$out" -v b="$expected" 'BEGIN {
      n = split(a, ra, "\n"); if (n != split(b, rb, "\n")) exit 1
      for (i = 1; i <= n; i++) { if (split(ra[i], x, ",") != split(rb[i], y, ",")) exit 1
        for (k in y) { d = x[k] - y[k]; if (d < 0) d = -d; e[++c] = d; s = y[k] < 0 ? -y[k] : y[k]; if (s > scale) scale = s } }
      for (j = 1; j <= c; j++) if (e[j] > 1e-12 * scale) exit 1 }'; then
    echo "FAIL: $name: casteljau $*"
    echo "  exit $status, stdout: $(printf '%q' "$out"), stderr: $(cat "$work/stderr")"
    echo "  expected about: $(printf '%q' "$expected")"
    failures=$((failures + 1))
  fi
}

# uniform K: the parameters i/K, i = 0..K, as casteljau computes them (exact ends).
uniform() { awk -v k="$1" 'BEGIN { for (i = 0; i <= k; i++) printf "%.17g\n", i / k }'; }

# --- every method on the head (19 points) and the car (26 points) ------------------------
for set in head car; do
  file="$examples/$set.csv"
  count=$(grep -v '^#' "$file" | grep -vc '^[a-z]')
  m=$((count - 1))
  mapfile -t t < <(uniform "$m")
  mapfile -t pieces < <(seq 0 "$m")
  ok "$set c1-bezier" interpolate "$file" --method c1-bezier && passes_through "$set c1-bezier" "$file" "${pieces[@]}"
  ok "$set c1-bezier alpha 2" interpolate "$file" --method c1-bezier --alpha 2 &&
    passes_through "$set c1-bezier alpha 2" "$file" "${pieces[@]}"
  ok "$set c1-bezier closed" interpolate "$file" --method c1-bezier --closed
  for param in uniform chord centripetal; do
    ok "$set catmull-rom $param" interpolate "$file" --method catmull-rom --param "$param"
    ok "$set catmull-rom $param closed" interpolate "$file" --method catmull-rom --param "$param" --closed
    for end in natural not-a-knot; do
      ok "$set cubic $end $param" interpolate "$file" --method cubic --end "$end" --param "$param"
    done
    ok "$set cubic clamped $param" interpolate "$file" --method cubic --end clamped --param "$param" \
      --start-tangent 1,0 --end-tangent 0,-1
    ok "$set cubic periodic $param" interpolate "$file" --method cubic --end periodic --closed --param "$param"
    ok "$set natural q=3 $param" interpolate "$file" --method natural --order 3 --param "$param"
    ok "$set lagrange $param" interpolate "$file" --method lagrange --param "$param"
  done
  ok "$set cubic uniform" interpolate "$file" --method cubic && passes_through "$set cubic" "$file" "${t[@]}"
  for degree in 1 2 3 4 5 7; do
    ok "$set bspline $degree" interpolate "$file" --method bspline --degree "$degree" &&
      passes_through "$set bspline $degree" "$file" "${t[@]}"
  done
  ok "$set natural q=1" interpolate "$file" --method natural --order 1 && passes_through "$set natural q=1" "$file" "${t[@]}"
  ok "$set natural q=2" interpolate "$file" --method natural && passes_through "$set natural q=2" "$file" "${t[@]}"
  ok "$set lagrange chebyshev" interpolate "$file" --method lagrange --nodes chebyshev
  ok "$set catmull-rom" interpolate "$file" --method catmull-rom && passes_through "$set catmull-rom" "$file" "${t[@]}"
  # Hermite: the points with tangent columns (central differences, one-sided at the ends).
  grep -v '^#' "$file" | grep -v '^[a-z]' | awk -F, '{ x[NR] = $1; y[NR] = $2 } END {
      print "x,y,dx,dy"
      for (i = 1; i <= NR; i++) { a = i > 1 ? i - 1 : i; b = i < NR ? i + 1 : i
        printf "%s,%s,%.17g,%.17g\n", x[i], y[i], (x[b] - x[a]) * 2, (y[b] - y[a]) * 2 } }' >"$work/${set}_tangents.csv"
  ok "$set hermite" interpolate "$work/${set}_tangents.csv" --method hermite && passes_through "$set hermite" "$file" "${t[@]}"
  ok "$set hermite closed" interpolate "$work/${set}_tangents.csv" --method hermite --closed --param centripetal
done

# --- known values, worked by hand -------------------------------------------------------
# c1-bezier on P = (0,0) (3,3) (6,0), alpha = 1 (seed 000): Q_0 = P_0 + 2(P_1 - P_0)/3 = (2,2),
# R_0 = P_1 - (P_2 - P_0)/3 = (1,3), Q_1 = P_1 + (P_2 - P_0)/3 = (5,3), R_1 = P_2 - 2(P_2 - P_1)/3 = (4,2).
printf 'x,y\n0,0\n3,3\n6,0\n' >"$work/three.csv"
check "c1-bezier worked example" \
  '{"type":"piecewise_bezier","pieces":[[[0,0],[2,2],[1,3],[3,3]],[[3,3],[5,3],[4,2],[6,0]]]}' \
  interpolate "$work/three.csv" --method c1-bezier
# The natural cubic through (0,0) (1,0) (2,0) at t = 0, 1/2, 1: knots t_0^4, t_1, t_2^4.
printf 'x,y\n0,0\n1,0\n2,0\n' >"$work/line.csv"
out=$("$casteljau" interpolate "$work/line.csv" --method cubic --end natural 2>&1)
if [[ "$out" != *'"knots":[0,0,0,0,0.5,1,1,1,1]'* ]]; then
  echo "FAIL: natural cubic knots: $out"
  failures=$((failures + 1))
fi
# It reproduces the line: C(1/4) = (1/2, 0), C(3/4) = (3/2, 0).
near "natural cubic reproduces a line" $'0.5,0\n1.5,0' \
  eval <("$casteljau" interpolate "$work/line.csv" --method cubic --end natural) --at 0.25 --at 0.75
# --function: x is the parameter, the result the curve (x, s(x)) over [x_0, x_n]; Lagrange
# through three points of y = x^2 is that parabola: (2.5, 6.25) halfway.
printf 'x,y\n1,1\n2,4\n4,16\n' >"$work/square.csv"
near "lagrange --function: the parabola y = x^2 on [1, 4]" $'1,1\n2.5,6.25\n4,16' \
  eval <("$casteljau" interpolate "$work/square.csv" --method lagrange --function) --at 0 --at 0.5 --at 1
# A natural cubic reproduces the line y = 2x + 1 (its second derivative is 0 everywhere).
printf 'x,y\n1,3\n2,5\n4,9\n' >"$work/affine.csv"
near "natural q=2 --function reproduces a line" $'1.5,4\n3.25,7.5' \
  eval <("$casteljau" interpolate "$work/affine.csv" --method natural --function) --at 1.5 --at 3.25

# --- closed: a last point equal to the first is dropped ------------------------------------
{ cat "$work/three.csv"; echo "0,0"; } >"$work/three_closed.csv"
for method in c1-bezier catmull-rom cubic; do
  a=$("$casteljau" interpolate "$work/three.csv" --method "$method" --closed 2>&1)
  b=$("$casteljau" interpolate "$work/three_closed.csv" --method "$method" --closed 2>&1)
  if [[ -z "$a" || "$a" != "$b" ]]; then
    echo "FAIL: $method --closed with the first point repeated last differs: $a / $b"
    failures=$((failures + 1))
  fi
done
# Closed (cyclic neighbours): Q_0 = P_0 + (P_1 - P_2)/3 = (-1,1), R_0 = (1,3), Q_1 = (5,3),
# R_1 = P_2 - (P_0 - P_1)/3 = (7,1), Q_2 = P_2 + (P_0 - P_1)/3 = (5,-1), R_2 = P_0 - (P_1 - P_2)/3 = (1,-1).
check "c1-bezier closed has m+1 pieces" \
  '{"type":"piecewise_bezier","pieces":[[[0,0],[-1,1],[1,3],[3,3]],[[3,3],[5,3],[7,1],[6,0]],[[6,0],[5,-1],[1,-1],[0,0]]]}' \
  interpolate "$work/three_closed.csv" --method c1-bezier --closed

# --- -o: written atomically, nothing on stdout ---------------------------------------------
out=$("$casteljau" interpolate "$examples/head.csv" --method cubic -o "$work/head.json" 2>&1)
if [[ -n "$out" || ! -s "$work/head.json" ]]; then
  echo "FAIL: -o writes the file and prints nothing ($out)"
  failures=$((failures + 1))
fi
check "-o and stdout give the same model" "$(cat "$work/head.json")" interpolate "$examples/head.csv" --method cubic

# --- bad input: exit 2, one line, nothing written --------------------------------------------
printf 'x,y\n0,0\n1,1\n' >"$work/two.csv"
printf 'x,y\n0,0\n1,1\n1,1\n2,0\n3,1\n' >"$work/duplicate.csv"
printf 'x,y\n0,0\n1,nan\n2,0\n' >"$work/nan.csv"
printf 'x,y\n0,0\n2,1\n2,3\n3,1\n' >"$work/x_repeats.csv"
printf 'x,y\n0,0\n2,1\n1,3\n3,1\n' >"$work/x_decreases.csv"
printf 'x,y\n0,0\n' >"$work/one.csv"
expect_error "unknown method" "--method 'spline': unknown method, expected c1-bezier" \
  interpolate "$work/two.csv" --method spline
expect_error "method required" "--method is required" interpolate "$work/two.csv"
expect_error "unknown end condition" "--end: unknown end condition 'free'" \
  interpolate "$work/two.csv" --method cubic --end free
expect_error "unknown parameterization" "--param: unknown parameterization 'arc'" \
  interpolate "$work/two.csv" --method cubic --param arc
expect_error "unknown nodes" "--nodes 'gauss': unknown nodes, expected uniform or chebyshev" \
  interpolate "$work/two.csv" --method lagrange --nodes gauss
expect_error "clamped without tangents" "--end clamped needs both end tangents" \
  interpolate "$examples/head.csv" --method cubic --end clamped
expect_error "clamped with one tangent" "--end clamped needs both end tangents" \
  interpolate "$examples/head.csv" --method cubic --end clamped --start-tangent 1,0
expect_error "tangent of the wrong dimension" "--end-tangent: 3 coordinates given, the points have 2" \
  interpolate "$examples/head.csv" --method cubic --end clamped --start-tangent 1,0 --end-tangent 1,0,0
expect_error "tangent not a number" "--start-tangent: 'a' is not a number" \
  interpolate "$examples/head.csv" --method cubic --end clamped --start-tangent a,0 --end-tangent 1,0
expect_error "tangents without clamped" "need --end clamped" \
  interpolate "$examples/head.csv" --method cubic --end natural --start-tangent 1,0 --end-tangent 1,0
expect_error "periodic without --closed" "--end periodic makes a closed curve: add --closed" \
  interpolate "$examples/head.csv" --method cubic --end periodic
expect_error "--closed with an end condition" "--closed needs --end periodic" \
  interpolate "$examples/head.csv" --method cubic --end natural --closed
expect_error "--closed for a method without closed curves" "--closed does not apply to --method lagrange" \
  interpolate "$examples/head.csv" --method lagrange --closed
expect_error "--function for a method without functions" "--function does not apply to --method catmull-rom" \
  interpolate "$examples/head.csv" --method catmull-rom --function
expect_error "--param for c1-bezier" "--param does not apply to --method c1-bezier" \
  interpolate "$examples/head.csv" --method c1-bezier --param chord
expect_error "--alpha 0" "--alpha: 0 is not > 0" interpolate "$examples/head.csv" --method c1-bezier --alpha 0
expect_error "--alpha nan" "--alpha: 'nan' is NaN" interpolate "$examples/head.csv" --method c1-bezier --alpha nan
expect_error "--degree 0" "--degree: 0 is outside 1.." interpolate "$examples/head.csv" --method bspline --degree 0
expect_error "--degree x" "--degree: 'x' is not a whole number" interpolate "$examples/head.csv" --method bspline --degree x
expect_error "--order 0" "--order: 0 is outside 1.." interpolate "$examples/head.csv" --method natural --order 0
# Fewer points than the method needs.
expect_error "one point" "one.csv: interpolation needs at least 2 points, got 1" \
  interpolate "$work/one.csv" --method cubic --end natural
expect_error "not-a-knot with 2 points" "two.csv: " interpolate "$work/two.csv" --method cubic --end not-a-knot
expect_error "periodic with 2 points" "two.csv: " interpolate "$work/two.csv" --method cubic --closed
expect_error "c1-bezier with 1 point" "one.csv: " interpolate "$work/one.csv" --method c1-bezier
expect_error "bspline degree above the point count" "two.csv: " \
  interpolate "$work/two.csv" --method bspline --degree 3
expect_error "natural q=3 with 2 points" "two.csv: " interpolate "$work/two.csv" --method natural --order 3
# Consecutive duplicate points.
expect_error "duplicate points, chord parameters" \
  "duplicate.csv: points 1 and 2 coincide, chord parameters need distinct consecutive points" \
  interpolate "$work/duplicate.csv" --method cubic --param chord
expect_error "duplicate points, centripetal parameters" "points 1 and 2 coincide, centripetal parameters" \
  interpolate "$work/duplicate.csv" --method catmull-rom --param centripetal
# NaN in the data: the CSV reader names the line and field.
expect_error "NaN coordinate" "nan.csv, line 3, field 2: 'nan' is NaN, numbers must be finite" \
  interpolate "$work/nan.csv" --method cubic
# --function: x must increase strictly.
expect_error "repeated x" "x_repeats.csv: x must increase strictly: point 2 has x = 2, point 1 has x = 2" \
  interpolate "$work/x_repeats.csv" --method cubic --function
expect_error "decreasing x" "x must increase strictly: point 2 has x = 1, point 1 has x = 2" \
  interpolate "$work/x_decreases.csv" --method lagrange --function
expect_error "--function with --param" "--function takes x" \
  interpolate "$work/x_decreases.csv" --method natural --function --param chord
# Each method says what it reads (issue 15): hermite a point then its tangent, 2d columns
# with d >= 2 (the head's x,y alone once gave a 1-D curve with y as tangents).
hermite_columns="hermite reads points and tangents: 2d columns (x,y,dx,dy in 2D, x,y,z,dx,dy,dz in 3D)"
expect_error "hermite with points only" "head.csv: $hermite_columns, got 2 columns" \
  interpolate "$examples/head.csv" --method hermite
printf 'x,y,z\n0,0,0\n1,1,1\n' >"$work/odd.csv"
expect_error "hermite with an odd number of columns" "odd.csv: $hermite_columns, got 3 columns" \
  interpolate "$work/odd.csv" --method hermite
# One column is no plane or space curve, for every method; --function needs x and y.
printf 'x\n0\n1\n2\n3\n4\n' >"$work/column.csv"
expect_error "hermite with one column" "column.csv: $hermite_columns, got 1 column" \
  interpolate "$work/column.csv" --method hermite
for method in c1-bezier catmull-rom cubic bspline lagrange natural; do
  expect_error "$method with one column" \
    "column.csv: $method interpolates points of 2 or more columns (x,y or x,y,z), got 1 column" \
    interpolate "$work/column.csv" --method "$method"
done
for method in cubic bspline lagrange natural; do
  expect_error "$method --function with one column" \
    "column.csv: a function y(x) needs at least 2 columns (x and y), got 1" \
    interpolate "$work/column.csv" --method "$method" --function
done
# A closed curve needs 3 points: each closed method says so.
printf 'x,y,dx,dy\n0,0,1,0\n1,1,0,1\n' >"$work/two_tangents.csv"
expect_error "closed c1-bezier with 2 points" "two.csv: a closed c1-bezier curve needs at least 3 points, got 2" \
  interpolate "$work/two.csv" --method c1-bezier --closed
expect_error "closed catmull-rom with 2 points" \
  "two.csv: a closed Catmull-Rom spline needs at least 3 points, got 2" \
  interpolate "$work/two.csv" --method catmull-rom --closed
expect_error "closed cubic with 2 points" \
  "two.csv: cubic interpolation with periodic ends needs at least 3 points, got 2" \
  interpolate "$work/two.csv" --method cubic --closed
expect_error "closed hermite with 2 points" \
  "two_tangents.csv: a closed Hermite interpolation needs at least 3 points, got 2" \
  interpolate "$work/two_tangents.csv" --method hermite --closed
expect_error "bspline degree 3 with 2 points" \
  "two.csv: degree-3 B-spline interpolation needs at least 4 points, got 2" \
  interpolate "$work/two.csv" --method bspline
expect_error "missing file" "cannot open" interpolate "$work/nowhere.csv" --method cubic
# Nothing is written on error.
"$casteljau" interpolate "$work/duplicate.csv" --method cubic --param chord -o "$work/never.json" 2>/dev/null
if [[ -e "$work/never.json" ]]; then
  echo "FAIL: an output file was written on bad input"
  failures=$((failures + 1))
fi

finish interpolate
