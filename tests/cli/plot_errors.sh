#!/usr/bin/env bash
# casteljau plot and bernstein: good figures in every format, and bad input
# (exit 2, exactly one line "casteljau: error: ..." on stderr, no output file).
# Usage: bash plot_errors.sh <casteljau-binary> <repo>/examples
set -uo pipefail
casteljau="$1"
examples="$2"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
passed=0
failed=0
ok() { passed=$((passed + 1)); }
ko() { echo "FAIL: $*"; failed=$((failed + 1)); }

# expect_error OUTPUT_FILE ARGS...: exit 2, one stderr line, OUTPUT_FILE absent.
expect_error() {
  local output="$1"
  shift
  "$casteljau" "$@" >"$work/stdout" 2>"$work/stderr"
  local status=$?
  local what="casteljau $*"
  [ "$status" -eq 2 ] && ok || ko "$what: exit $status, expected 2"
  [ "$(wc -l <"$work/stderr")" -eq 1 ] && grep -q '^casteljau: error: ' "$work/stderr" && ok ||
    ko "$what: stderr is not one error line: $(cat "$work/stderr")"
  [ ! -s "$work/stdout" ] && ok || ko "$what: wrote to stdout"
  [ ! -e "$output" ] && ok || ko "$what: wrote $output"
  [ -z "$(find "$work" -name '.*tmp*')" ] && ok || ko "$what: left a temporary file"
}

# expect_figure FILE MAGIC ARGS...: exit 0 and FILE starts with MAGIC (hex).
expect_figure() {
  local file="$1" magic="$2"
  shift 2
  "$casteljau" "$@" >"$work/stdout" 2>"$work/stderr"
  local status=$?
  [ "$status" -eq 0 ] && ok || ko "casteljau $*: exit $status: $(cat "$work/stderr")"
  [ "$(head -c $((${#magic} / 2)) "$file" | od -An -tx1 | tr -d ' \n')" = "$magic" ] && ok ||
    ko "casteljau $*: $file does not start with $magic"
  rm -f "$file"
}

svg=3c3f786d6c   # "<?xml"
png=89504e470d0a1a0a
pdf=255044462d   # "%PDF-"

# --- figures that work -------------------------------------------------------
cat >"$work/curve.json" <<'JSON'
{"type": "bezier", "control_points": [[0,0],[1,2],[2,2],[4,1],[4,0]]}
JSON
cat >"$work/pieces.json" <<'JSON'
{"type": "piecewise_bezier", "pieces": [[[0,0],[1,1],[2,1],[3,0]], [[3,0],[4,-1],[5,-1],[6,0]]]}
JSON
expect_figure "$work/a.svg" "$svg" plot "$work/curve.json" -o "$work/a.svg" --control-polygon --points --construction 0.5
expect_figure "$work/a.png" "$png" plot "$work/curve.json" "$examples/semicircle.csv" -o "$work/a.png" --comb --basis
expect_figure "$work/a.pdf" "$pdf" plot "$examples/spiral_10.csv" -o "$work/a.pdf" --points --tangents
expect_figure "$work/b.svg" "$svg" plot "$work/pieces.json" -o "$work/b.svg" --construction 1.5 --tangents
expect_figure "$work/c.svg" "$svg" plot "$examples/head.csv" --points-only -o "$work/c.svg"
# --points-only (the older name of --data-points) is no longer refused beside model JSON.
expect_figure "$work/c.svg" "$svg" plot "$work/curve.json" "$examples/head.csv" --points-only -o "$work/c.svg"
expect_figure "$work/d.png" "$png" bernstein 20 -o "$work/d.png" --without-ends
expect_figure "$work/d.pdf" "$pdf" bernstein 3 -o "$work/d.pdf"
# A construction drawn with the right point: C(0.5) = (2.25, 1.5) in the legend.
"$casteljau" plot "$work/curve.json" -o "$work/e.svg" --construction 0.5 &&
  grep -q 'C(0.5) = (2.25, 1.5)' "$work/e.svg" && ok || ko "construction legend names C(0.5) = (2.25, 1.5)"
rm -f "$work/e.svg"
# --help on each command.
for command in plot bernstein gallery; do
  "$casteljau" "$command" --help >"$work/help" 2>&1 && grep -q -- "-o\|DIR" "$work/help" && ok || ko "$command --help"
done

# --- bad input ---------------------------------------------------------------
expect_error "$work/x.gif" plot "$work/curve.json" -o "$work/x.gif"
expect_error "$work/x" plot "$work/curve.json" -o "$work/x"
expect_error "$work/x.svg" plot "$work/missing.json" -o "$work/x.svg"
expect_error "$work/x.svg" plot "$work/curve.txt" -o "$work/x.svg"
expect_error "$work/x.svg" plot "$work/curve.json" -o "$work/x.svg" --construction 1.5
expect_error "$work/x.svg" plot "$work/curve.json" -o "$work/x.svg" --construction abc
expect_error "$work/x.svg" plot "$work/curve.json" -o "$work/x.svg" --construction nan
expect_error "$work/x.svg" plot "$work/curve.json"
expect_error "$work/x.svg" plot -o "$work/x.svg"
expect_error "$work/nodir/x.svg" plot "$work/curve.json" -o "$work/nodir/x.svg"
expect_error "$work/nodir/x.png" plot "$work/curve.json" -o "$work/nodir/x.png"
printf '{"type": "bezier", "control_points": [[0,0],[1,"a"]]}\n' >"$work/bad.json"
expect_error "$work/x.svg" plot "$work/bad.json" -o "$work/x.svg"
printf 'x,y\n0,0\n1,abc\n' >"$work/bad.csv"
expect_error "$work/x.png" plot "$work/bad.csv" -o "$work/x.png"
expect_error "$work/x.svg" bernstein 0 -o "$work/x.svg"
expect_error "$work/x.svg" bernstein -3 -o "$work/x.svg"
expect_error "$work/x.svg" bernstein 2.5 -o "$work/x.svg"
expect_error "$work/x.svg" bernstein 1 --without-ends -o "$work/x.svg"
expect_error "$work/x.svg" bernstein 100000 -o "$work/x.svg"
expect_error "$work/x.bmp" bernstein 5 -o "$work/x.bmp"
expect_error "$work/x.svg" bernstein -o "$work/x.svg"

# An existing output is kept when the command fails.
echo "keep me" >"$work/keep.svg"
"$casteljau" plot "$work/bad.json" -o "$work/keep.svg" 2>/dev/null
[ "$(cat "$work/keep.svg")" = "keep me" ] && ok || ko "a failed plot replaced an existing file"

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
