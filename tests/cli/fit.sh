#!/usr/bin/env bash
# casteljau fit: least squares with N control points, refinement to a
# tolerance, smoothing (λ given or chosen by GCV); the model JSON on stdout or
# in -o FILE, the one-line summary (stdout with -o, stderr without); bad input
# (exit 2, one line on stderr naming what and where, nothing written).
# Known values: a straight line fitted by one linear piece with interpolated
# ends is the segment P_0 P_m exactly; polynomial data of degree <= p are
# reproduced by least squares; the tolerance is checked by evaluating the
# written model at the data's x with `casteljau eval` (awk, relative to the data).
# Usage: bash fit.sh CASTELJAU EXAMPLES_DIR
source "$(dirname "$0")/support/common.sh" "$@"

fail_test() {
  echo "FAIL: $1"
  failures=$((failures + 1))
}

# run_fit NAME ARGS...: casteljau fit ARGS, must exit 0; stdout in $work/out, stderr in $work/err.
run_fit() {
  local name=$1
  shift
  if ! "$casteljau" fit "$@" >"$work/out" 2>"$work/err"; then
    fail_test "$name: casteljau fit $* exited $?: $(cat "$work/err")"
    return 1
  fi
}

summary_pattern='^fit: [0-9]+ control points, max error [^ ]+ at point [0-9]+, rms error [^ ]+, lambda [^ ]+( \(gcv\))?, gcv [^ ]+, effective degrees of freedom [^ ]+$'

# --- least squares -------------------------------------------------------------------
# Points on the segment (0,0)-(4,1), uniform parameters i/4: degree 1 with 2
# control points and interpolated ends is the segment itself, on knots 0,0,1,1.
printf 'x,y\n0,0\n1,0.25\n2,0.5\n3,0.75\n4,1\n' > "$work/line.csv"
if run_fit "segment" "$work/line.csv" --degree 1 --control-points 2; then
  expected='{"type":"bspline","degree":1,"knots":[0,0,1,1],"control_points":[[0,0],[4,1]]}'
  [[ "$(cat "$work/out")" == "$expected" ]] || fail_test "segment: stdout $(cat "$work/out"), expected $expected"
  # Without -o the summary goes to stderr (the model owns stdout).
  grep -Eq "$summary_pattern" "$work/err" || fail_test "segment: summary on stderr: $(cat "$work/err")"
  [[ $(wc -l <"$work/err") -eq 1 ]] || fail_test "segment: more than one line on stderr"
fi

# y = x^2 at x = 0..6 (--function): a quadratic with 4 control points on the knots
# of The NURBS Book eq. 9.68-9.69 (d = 7/2: one interior knot (t_2 + t_3)/2 = 2.5)
# reproduces it; with -o the summary goes to stdout and the file holds the model.
printf '0,0\n1,1\n2,4\n3,9\n4,16\n5,25\n6,36\n' > "$work/square.csv"
if run_fit "quadratic data" "$work/square.csv" --function --free-ends --degree 2 --control-points 4 -o "$work/square.json"; then
  grep -Eq "$summary_pattern" "$work/out" || fail_test "quadratic data: summary on stdout: $(cat "$work/out")"
  [[ ! -s "$work/err" ]] || fail_test "quadratic data: stderr not empty: $(cat "$work/err")"
  grep -q '"knots":\[0,0,0,2.5,6,6,6\]' "$work/square.json" || fail_test "quadratic data: knots $(cat "$work/square.json")"
  values=$("$casteljau" eval "$work/square.json" --at 0 --at 1.5 --at 2.5 --at 6)
  if ! awk -F, 'BEGIN { split("0 1.5 2.5 6", x, " ") }
                { e = $1 - x[NR]; f = $2 - x[NR] * x[NR]; if (e * e + f * f > 1e-24) bad = 1 }
                END { exit bad || NR != 4 }' <<<"$values"; then
    fail_test "quadratic data: C(x) != (x, x^2): $values"
  fi
fi

# --- tolerance -------------------------------------------------------------------------
# y = sin(x / 5) at x = 0..200 with tolerance 1e-4: every point within 1e-4 at its x.
awk 'BEGIN { for (i = 0; i <= 200; ++i) printf "%d,%.17g\n", i, sin(i / 5) }' > "$work/sine.csv"
cut -d, -f1 "$work/sine.csv" > "$work/sine_x.csv"
if run_fit "tolerance" "$work/sine.csv" --function --degree 3 --tolerance 1e-4 -o "$work/sine.json"; then
  "$casteljau" eval "$work/sine.json" --params "$work/sine_x.csv" > "$work/sine_fit.csv"
  if ! paste -d, "$work/sine.csv" "$work/sine_fit.csv" |
       awk -F, '{ e = ($1 - $3) ^ 2 + ($2 - $4) ^ 2; if (e > worst) worst = e }
                END { exit !(NR == 201 && worst <= 1e-8) }'; then
    fail_test "tolerance: a point is farther than 1e-4 from the fit"
  fi
  count=$(sed -E 's/^fit: ([0-9]+) control points.*/\1/' "$work/out")
  [[ $count -lt 201 ]] || fail_test "tolerance: $count control points for 201 points"
fi

# --- smoothing ---------------------------------------------------------------------------
if run_fit "gcv" "$examples/head.csv" --degree 3 --smoothing gcv --param chord -o "$work/head.json"; then
  grep -Eq '^fit: .*lambda [^ ]+ \(gcv\), gcv ' "$work/out" || fail_test "gcv: summary $(cat "$work/out")"
  grep -q '"type":"bspline","degree":3' "$work/head.json" || fail_test "gcv: model $(cat "$work/head.json")"
fi
# Points on a line: the line has no penalty and no residual, so every λ gives the line itself
# (up to the rounding of the normal equations, whose condition grows with λ).
if run_fit "lambda on a line" "$work/line.csv" --degree 3 --smoothing 10 --free-ends -o "$work/flat.json"; then
  values=$("$casteljau" eval "$work/flat.json" --at 0 --at 0.5 --at 1)
  awk -F, 'BEGIN { split("0 2 4", x, " ") } { e = ($1 - x[NR]) ^ 2 + ($2 - x[NR] / 4) ^ 2; if (e > 1e-20) bad = 1 }
           END { exit bad || NR != 3 }' <<<"$values" || fail_test "lambda on a line: not the line: $values"
fi

# --- bad input ------------------------------------------------------------------------------
printf '0,0\n1,1\n2,0\n' > "$work/three.csv"
expect_error "too few points" "three.csv: a fit of degree 3 needs at least 4 points, got 3" \
  fit "$work/three.csv" --degree 3 --control-points 4
expect_error "more control points than points" "6 control points for 5 points" \
  fit "$work/line.csv" --degree 3 --control-points 6
printf '0,0\n1,nan\n2,0\n3,1\n4,2\n' > "$work/nan.csv"
expect_error "NaN" "nan.csv, line 2, field 2: 'nan' is NaN" fit "$work/nan.csv" --degree 3 --control-points 4
printf '0,0\n1,1\n1,1\n2,0\n3,1\n' > "$work/duplicate.csv"
expect_error "duplicate points with chord" "points 1 and 2 coincide" \
  fit "$work/duplicate.csv" --degree 2 --control-points 4 --param chord
expect_error "negative lambda" "--smoothing: λ = -1 is negative" fit "$work/line.csv" --degree 3 --smoothing -1
expect_error "zero tolerance" "--tolerance: 0 is not > 0" fit "$work/line.csv" --degree 3 --tolerance 0
expect_error "missing file" "cannot open '$work/missing.csv'" fit "$work/missing.csv" --degree 3 --control-points 4
expect_error "neither count nor tolerance" "fit needs --control-points N or --tolerance E" fit "$work/line.csv" --degree 3
expect_error "count and tolerance" "--control-points and --tolerance exclude each other" \
  fit "$work/line.csv" --degree 3 --control-points 4 --tolerance 0.1
expect_error "tolerance and smoothing" "--tolerance and --smoothing exclude each other" \
  fit "$work/line.csv" --degree 3 --tolerance 0.1 --smoothing gcv
expect_error "smoothing of degree 1" "smoothing needs degree 2 or more" fit "$work/line.csv" --degree 1 --smoothing 0.5
expect_error "lambda 0 with knots at every parameter" "give λ > 0 or fewer control points" \
  fit "$work/line.csv" --degree 3 --smoothing 0
expect_error "--smoothing not a number" "--smoothing: 'much' is not a number" fit "$work/line.csv" --degree 3 --smoothing much
expect_error "--param with --function" "--param does not apply" \
  fit "$work/line.csv" --degree 2 --control-points 3 --function --param chord
printf '0,0\n2,1\n1,2\n3,3\n' > "$work/backwards.csv"
expect_error "x not increasing with --function" "x must increase strictly" \
  fit "$work/backwards.csv" --degree 1 --control-points 2 --function
expect_error "degree 0" "--degree: 0 is outside 1.." fit "$work/line.csv" --degree 0 --control-points 2
expect_error "tolerance not reached" "the tolerance 1e-300 is not reached" \
  fit "$examples/head.csv" --degree 3 --tolerance 1e-300
# One column is no plane or space curve (issue 15's neighbour of hermite's columns).
printf 'y\n0\n1\n4\n9\n16\n' > "$work/column.csv"
expect_error "one column" "column.csv: fit approximates points of 2 or more columns (x,y or x,y,z), got 1 column" \
  fit "$work/column.csv" --degree 2 --control-points 3
# λ far outside the data's scale λ₀ = tr(BᵀB)/tr(Ω) (issue 15: "normal equations are
# singular" said nothing of λ): 200 noisy points of a sine, the noise seeded.
awk 'BEGIN { srand(15); for (i = 0; i < 200; ++i) printf "%.17g,%.17g\n", i / 199, sin(6 * i / 199) + 0.05 * (rand() - 0.5) }' \
  > "$work/noisy.csv"
expect_error "lambda too large" \
  "noisy.csv: the smoothing λ = 1e+308 is too large for these data: λ·tr(Ω) outweighs tr(BᵀB) by about 10^" \
  fit "$work/noisy.csv" --degree 3 --smoothing 1e308 --free-ends
expect_error "lambda too large names the meaningful range" "towards a straight line) is the range GCV searches here" \
  fit "$work/noisy.csv" --degree 3 --smoothing 1e308
expect_error "lambda too small for knots at every parameter" \
  "the smoothing λ = 1e-308 is too small for these data: λ·tr(Ω) is about 10^" \
  fit "$work/noisy.csv" --degree 3 --smoothing 1e-308
run_fit "tiny lambda with fewer control points than points" "$work/noisy.csv" --degree 3 --smoothing 1e-308 \
  --control-points 10 -o "$work/tiny.json"
expect_error "lambda infinite" "--smoothing: 'inf' is infinite" fit "$work/noisy.csv" --degree 3 --smoothing inf
expect_error "lambda NaN" "--smoothing: 'nan' is NaN" fit "$work/noisy.csv" --degree 3 --smoothing nan
expect_error "lambda overflows" "--smoothing: '1e309' overflows" fit "$work/noisy.csv" --degree 3 --smoothing 1e309
# Nothing is written on bad input.
printf 'keep' > "$work/keep.json"
expect_error "bad input leaves -o alone" "needs at least 4 points" \
  fit "$work/three.csv" --degree 3 --control-points 4 -o "$work/keep.json"
[[ "$(cat "$work/keep.json")" == keep ]] || fail_test "bad input touched the output file"

finish fit
