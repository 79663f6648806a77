#!/usr/bin/env bash
# CSV point sets written as spreadsheets and the seeds write them
# (docs/formats.md, "Point sets"): ';' or tab separators read like ',';
# decimal commas, rows with another separator and space-separated numbers
# exit 2 with one line that says what was found and what casteljau reads.
# Usage: bash csv_separators.sh CASTELJAU EXAMPLES_DIR
source "$(dirname "$0")/support/common.sh" "$@"
head_csv="$examples/head.csv"

# The head points (seed 000) with ';' and with tabs give the same interpolant
# as the shipped ',' file.
grep -v '^#' "$head_csv" | tr ',' ';' > "$work/head_semicolon.csv"
grep -v '^#' "$head_csv" | tr ',' '\t' > "$work/head_tab.csv"
reference=$("$casteljau" interpolate "$head_csv" --method c1-bezier --alpha 2)
check "';' separators" "$reference" interpolate "$work/head_semicolon.csv" --method c1-bezier --alpha 2
check "tab separators" "$reference" interpolate "$work/head_tab.csv" --method c1-bezier --alpha 2
check "eval of a ';' polygon" "2.25,1.5" eval <(printf 'x;y\n0;0\n1;2\n2;2\n4;1\n4;0\n') --at 0.5

# The issue's file: "x;y" then "9,5;5", as the seeds print numbers.
printf 'x;y\n9,5;5\n5,5;5\n1;7\n' > "$work/comma.csv"
expect_error "decimal commas" \
  "comma.csv, line 2, field 1: '9,5' uses ',' as the decimal mark; casteljau reads '.' as the decimal mark, and ',', ';' or tabs between values (convert with: sed 's/,/./g')" \
  interpolate "$work/comma.csv" --method c1-bezier
sed 's/,/./g' "$work/comma.csv" > "$work/converted.csv"
if ! "$casteljau" eval "$work/converted.csv" --at 0 >/dev/null 2>"$work/stderr"; then
  echo "FAIL: the hint's conversion does not read: $(cat "$work/stderr")"
  failures=$((failures + 1))
fi
printf 'x,y\n9.5;5\n' > "$work/mixed.csv"
expect_error "a row with another separator" "mixed.csv, line 2: 1 field, but the header on line 1 has 2" \
  eval "$work/mixed.csv" --at 0
expect_error "names both separators" "line 1 separates values by ',', this line has ';'" eval "$work/mixed.csv" --at 0
printf '9.5 5\n5.5 5\n' > "$work/spaces.csv"
expect_error "space-separated numbers" "spaces.csv, line 1, field 1: '9.5 5' holds numbers separated by spaces" \
  plot "$work/spaces.csv" -o "$work/spaces.svg"
[[ ! -e "$work/spaces.svg" ]] || { echo "FAIL: plot wrote a figure of a bad file"; failures=$((failures + 1)); }

finish csv_separators
