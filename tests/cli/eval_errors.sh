#!/usr/bin/env bash
# casteljau eval: every kind of bad input exits 2 with exactly one line on
# stderr, "casteljau: error: ...", naming what and where, and prints nothing
# on stdout. Usage: bash eval_errors.sh CASTELJAU EXAMPLES_DIR
source "$(dirname "$0")/support/common.sh" "$@"
polygon="$examples/notebook_polygon.csv"

# --- model JSON ---------------------------------------------------------------
expect_error "missing file" "cannot open '$work/none.json': No such file or directory" eval "$work/none.json" --at 0
model syntax.json $'{"type": "bezier",\n "control_points": [[0,0],[1,2],]}'
expect_error "syntax error" "syntax.json, line 2, column 33: syntax error" eval "$work/syntax.json" --at 0
model overflow.json '{"type": "bezier", "control_points": [[0,0],[1,1e999]]}'
expect_error "1e999" "overflow.json, line 1, column 48, control_points[1][1]: the number '1e999' overflows to infinity" \
  eval "$work/overflow.json" --at 0
model unknown.json '{"type": "bezier", "control_points": [[0,0]], "colour": "red"}'
expect_error "unknown field" "unknown.json, the top level: unknown field 'colour'" eval "$work/unknown.json" --at 0
model coons.json '{"models": [{"type": "coons"}]}'
expect_error "coons" "coons.json, models[0]: missing field 'boundaries' (u0, u1, v0, v1)" eval "$work/coons.json" --at 0,0
model notanumber.json '{"models": [{"type": "bezier", "control_points": [[0,0]]}, {"type": "bezier", "control_points": [[0,1],[1,"a"]]}]}'
expect_error "not a number" "notanumber.json, models[1].control_points[1][1]: expected a number, found the string 'a'" \
  eval "$work/notanumber.json" --at 0
model mixed.json '{"type": "bezier", "control_points": [[0,0],[1,2,3]]}'
expect_error "mixed dimensions" "mixed.json, control_points[1]: 3 coordinates, but control_points[0] has 2" \
  eval "$work/mixed.json" --at 0
model empty.json '{"type": "bezier", "control_points": []}'
expect_error "empty polygon" "empty.json, control_points: the control polygon is empty" eval "$work/empty.json" --at 0
model weight.json '{"type": "bezier", "control_points": [[0,0],[1,2]], "weights": [1, -2]}'
expect_error "negative weight" "weight.json, weights: weight 1" eval "$work/weight.json" --at 0
model weights.json '{"type": "bezier", "control_points": [[0,0],[1,2]], "weights": [1, 1, 1]}'
expect_error "weights count" "weights.json, weights: 3 weights for 2 control points" eval "$work/weights.json" --at 0
model newline.json '{"type": "bez
ier", "control_points": [[0]]}'
expect_error "raw newline in a string" "newline.json, line 1, column 14: syntax error" eval "$work/newline.json" --at 0
expect_error "directory" "is a directory, not a file" eval "$work" --at 0

# --- CSV point sets -------------------------------------------------------------
printf 'x,y\n0,0\n1,abc\n' > "$work/bad.csv"
expect_error "CSV field" "bad.csv, line 3, field 2: 'abc' is not a number" eval "$work/bad.csv" --at 0
printf 'x,y\n0,0\n1,2,3\n' > "$work/ragged.csv"
expect_error "CSV ragged" "ragged.csv, line 3: 3 fields, but the header on line 1 has 2" eval "$work/ragged.csv" --at 0
printf '0,nan\n' > "$work/nan.csv"
expect_error "CSV NaN" "nan.csv, line 1, field 2: 'nan' is NaN" eval "$work/nan.csv" --at 0
printf '0,inf\n' > "$work/inf.csv"
expect_error "CSV inf" "inf.csv, line 1, field 2: 'inf' is infinite" eval "$work/inf.csv" --at 0
printf '0,\n' > "$work/emptyfield.csv"
expect_error "CSV empty field" "emptyfield.csv, line 1, field 2: the value is empty" eval "$work/emptyfield.csv" --at 0
printf '# nothing\nx,y\n' > "$work/nopoints.csv"
expect_error "CSV no points" "nopoints.csv: no points after the header row on line 2" eval "$work/nopoints.csv" --at 0
printf '0,0\r\n1,2\r3\r\n' > "$work/cr.csv"
expect_error "CSV stray CR stays on one line" "cr.csv, line 2, field 2: '2\\x0d3' is not a number" eval "$work/cr.csv" --at 0

# --- parameters -------------------------------------------------------------------
expect_error "--at above" "--at 1.5 is outside the domain [0, 1] of the bezier model in '$polygon'" eval "$polygon" --at 1.5
expect_error "--at below" "--at -0.5 is outside the domain [0, 1]" eval "$polygon" --at 0.5 --at -0.5
expect_error "--at nan" "--at: 'nan' is NaN, numbers must be finite" eval "$polygon" --at nan
expect_error "--at inf" "--at: 'inf' is infinite" eval "$polygon" --at inf
expect_error "--at 1e999" "--at: '1e999' overflows to infinity" eval "$polygon" --at 1e999
expect_error "--at abc" "--at: 'abc' is not a number" eval "$polygon" --at abc
model two.json '{"models": [{"type": "piecewise_bezier", "pieces": [[[0],[1]], [[1],[2]]]}, {"type": "bezier", "control_points": [[0]]}]}'
expect_error "--at outside the second model" "--at 1.5 is outside the domain [0, 1] of models[1] (bezier)" \
  eval "$work/two.json" --at 1.5
printf 't\n0.5\n1.25\n' > "$work/params.csv"
expect_error "--params outside" "params.csv, line 3: 1.25 is outside the domain [0, 1]" eval "$polygon" --params "$work/params.csv"
printf 't\n0.5\nhalf\n' > "$work/badparams.csv"
expect_error "--params bad" "badparams.csv, line 3, field 1: 'half' is not a number" eval "$polygon" --params "$work/badparams.csv"
printf '0.5,1\n' > "$work/wideparams.csv"
expect_error "--params two columns" "wideparams.csv, line 1: 2 fields, expected one number per line" \
  eval "$polygon" --params "$work/wideparams.csv"
expect_error "--params missing" "cannot open '$work/none.csv'" eval "$polygon" --params "$work/none.csv"
expect_error "--samples 0" "--samples: 0 samples" eval "$polygon" --samples 0
expect_error "--samples -3" "--samples: '-3' is not a whole number" eval "$polygon" --samples -3
expect_error "--samples 2.5" "--samples: '2.5' is not a whole number" eval "$polygon" --samples 2.5
expect_error "--samples huge" "--samples: 10000001 is more than the limit of 10000000" eval "$polygon" --samples 10000001
expect_error "--samples beyond 64 bits" "is more than the limit of 10000000" eval "$polygon" --samples 99999999999999999999999
expect_error "total over the limit" "2 models at 6000000 parameters is 12000000 evaluations, more than the limit" \
  eval "$work/two.json" --samples 6000000
expect_error "--derivative -1" "--derivative: '-1' is not a whole number" eval "$polygon" --at 0 --derivative -1
expect_error "--derivative 1001" "--derivative: 1001 is more than the limit of 1000" eval "$polygon" --at 0 --derivative 1001
expect_error "nothing to evaluate" "nothing to evaluate" eval "$polygon"

# --- command line -----------------------------------------------------------------
expect_error "unknown option" "--bogus" eval "$polygon" --at 0 --bogus
expect_error "missing MODEL" "MODEL" eval --at 0
expect_error "-o into a missing folder" "cannot write '$work/no/such/out.csv': No such file or directory" \
  eval "$polygon" --at 0 -o "$work/no/such/out.csv"

finish "eval errors"
