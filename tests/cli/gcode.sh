#!/usr/bin/env bash
# casteljau gcode: the exact half circle as one G2 (the whole program), its
# summary line; --lines (G1 only), --units in (G20, 5 decimals), --decimals,
# --dialect linuxcnc (G91.1 G64 P), passes (--depth, --step-down), feeds and
# safe height; several inputs (model JSON, CSV, SVG, DXF) in one program,
# each named in the header; standard output; and bad input (exit 2, one line
# on stderr, nothing written): options out of range, surfaces, curves in
# space, a missing file, --arcs with --lines.
# The motion as cncjs's interpreter reads it: tests/gcode/.
# Usage: bash gcode.sh CASTELJAU EXAMPLES_DIR
source "$(dirname "$0")/support/common.sh" "$@"

fail_test() {
  echo "FAIL: $1"
  failures=$((failures + 1))
}
# has FILE NAME PATTERN: FILE holds a line matching the extended regex PATTERN.
has() { grep -Eq "$3" "$1" || fail_test "$2: no line /$3/ in $(cat "$1")"; }
# count FILE PATTERN: the number of lines matching PATTERN.
count() { grep -Ec "$2" "$1" || true; }

semicircle="$examples/semicircle.json"
version=$(sed -nE 's/^project\(casteljau VERSION ([0-9.]+).*/\1/p' "$examples/../CMakeLists.txt")

# --- the half circle of radius 3, from (-3, 0) over (0, 3) to (3, 0): one G2 ---
"$casteljau" gcode "$semicircle" --tolerance 0.01 -o "$work/semi.nc" >"$work/out" 2>"$work/err" ||
  fail_test "semicircle: exit $?: $(cat "$work/err")"
[[ "$(cat "$work/out")" == "gcode: 1 contour, 1 arc (G2/G3) and 0 lines (G1) in 1 pass, within 0.01 mm of the curves" ]] ||
  fail_test "semicircle summary: $(cat "$work/out")"
[[ ! -s "$work/err" ]] || fail_test "semicircle: stderr $(cat "$work/err")"
expected="(casteljau $version: RS-274/NGC program for GRBL)
(source: $semicircle)
(tolerance 0.01 mm: the path within it of the curves; the rounding of its numbers to 4 decimals takes at most 0.0005 of it)
(units mm [G21], absolute [G90], XY plane [G17], feed per minute [G94])
(depth 1.0000 in 1 pass, safe height 5.0000, feed 600.0000, plunge feed 200.0000)
(1 contour: 1 arc [G2 G3], 0 lines [G1])
(box of the cuts: X -3.0000 to 3.0000, Y 0.0000 to 3.0000)
(cuts 9.4248 mm, plunges 6.0000, rapid moves 3.0000 in the plane [3.0000 in the input's order]; about 3 s at the feeds, rapid moves not counted)
G21 G90 G17 G94
G0 Z5.0000
G0 X-3.0000 Y0.0000
G1 Z-1.0000 F200.0000
G2 X3.0000 Y0.0000 I3.0000 J0.0000 F600.0000
G0 Z5.0000
M2"
[[ "$(cat "$work/semi.nc")" == "$expected" ]] || fail_test "semicircle program: $(cat "$work/semi.nc")"

# --- standard output: the program alone on stdout, the summary on stderr ---
"$casteljau" gcode "$semicircle" --tolerance 0.01 >"$work/stdout.nc" 2>"$work/err"
cmp -s "$work/stdout.nc" "$work/semi.nc" || fail_test "stdout differs from -o"
grep -q '^gcode: 1 contour' "$work/err" || fail_test "stdout: the summary is not on stderr: $(cat "$work/err")"

# --- --lines: G1 only ---
"$casteljau" gcode "$semicircle" --tolerance 0.01 --lines -o "$work/lines.nc" >"$work/out"
[[ $(count "$work/lines.nc" '^G[23] ') -eq 0 ]] || fail_test "--lines wrote arcs"
[[ $(count "$work/lines.nc" '^G1 X') -gt 10 ]] || fail_test "--lines: too few lines"
grep -q "0 arcs (G2/G3) and" "$work/out" || fail_test "--lines summary: $(cat "$work/out")"

# --- the decimals follow the tolerance: rounding takes at most a tenth of it ---
"$casteljau" gcode "$semicircle" --tolerance 0.0001 -o "$work/fine.nc" >/dev/null
has "$work/fine.nc" "fine" '^G2 X3\.000000 Y0\.000000 I3\.000000 J0\.000000 F600\.000000$'

# --- inches: G20, 5 decimals, the inch defaults ---
"$casteljau" gcode "$semicircle" --tolerance 0.001 --units in -o "$work/inch.nc" >/dev/null
has "$work/inch.nc" "inch" '^G20 G90 G17 G94$'
has "$work/inch.nc" "inch" '^G0 Z0\.20000$'
has "$work/inch.nc" "inch" '^G1 Z-0\.04000 F8\.00000$'
has "$work/inch.nc" "inch" '^G2 X3\.00000 Y0\.00000 I3\.00000 J0\.00000 F24\.00000$'

# --- decimals, dialect, passes, feeds, safe height ---
"$casteljau" gcode "$semicircle" --tolerance 0.01 --decimals 6 --dialect linuxcnc --depth 2 --step-down 0.75 \
  --safe-z 10 --feed 1200 --plunge-feed 300 -o "$work/options.nc" >"$work/out"
has "$work/options.nc" "linuxcnc" '^G91\.1 G64 P0\.000001$'
has "$work/options.nc" "linuxcnc" 'program for LinuxCNC'
has "$work/options.nc" "safe height" '^G0 Z10\.000000$'
has "$work/options.nc" "passes" '^\(depth 2\.000000 in 3 passes,'
for z in -0.666667 -1.333333 -2.000000; do has "$work/options.nc" "pass $z" "^G1 Z$z( F300\.000000)?$"; done
[[ $(count "$work/options.nc" '^G2 ') -eq 2 && $(count "$work/options.nc" '^G3 ') -eq 1 ]] ||
  fail_test "passes: an open contour runs back and forth (G2, G3, G2): $(grep -E '^G[23]' "$work/options.nc")"
has "$work/options.nc" "feed" 'F1200\.000000$'
grep -q "in 3 passes" "$work/out" || fail_test "passes summary: $(cat "$work/out")"
if grep -Eq '^G(64|91\.1|5)' "$work/semi.nc"; then fail_test "grbl: G64, G91.1 or G5 written"; fi

# --- several inputs of every kind: one program, each source named ---
"$casteljau" convert "$semicircle" --to dxf -o "$work/semi.dxf"
"$casteljau" gcode "$semicircle" "$examples/notebook_polygon.csv" "$examples/sailboat.svg" "$work/semi.dxf" \
  --tolerance 0.01 -o "$work/all.nc" >"$work/out" 2>"$work/err" || fail_test "every kind: $(cat "$work/err")"
for source in semicircle.json notebook_polygon.csv sailboat.svg semi.dxf; do
  has "$work/all.nc" "sources" "^\(source: .*$source\)$"
done
grep -Eq '^gcode: 2[0-9] contours' "$work/out" || fail_test "every kind: summary $(cat "$work/out")"
[[ $(count "$work/all.nc" '^M2$') -eq 1 ]] || fail_test "every kind: one program end"

# --- --origin: the box's lower-left corner or centre at X0 Y0 (the half circle's box is -3..3 x 0..3) ---
"$casteljau" gcode "$semicircle" --tolerance 0.01 --origin lower-left -o "$work/ll.nc" >/dev/null
has "$work/ll.nc" "lower-left" '^\(the drawing moved by X 3\.0000 Y 0\.0000: its box.s lower-left corner at X0 Y0\)$'
has "$work/ll.nc" "lower-left" '^\(box of the cuts: X 0\.0000 to 6\.0000, Y 0\.0000 to 3\.0000\)$'
has "$work/ll.nc" "lower-left" '^G2 X6\.0000 Y0\.0000 I3\.0000 J0\.0000 F600\.0000$'
"$casteljau" gcode "$semicircle" --tolerance 0.01 --origin centre -o "$work/centre.nc" >/dev/null
has "$work/centre.nc" "centre" '^\(box of the cuts: X -3\.0000 to 3\.0000, Y -1\.5000 to 1\.5000\)$'
has "$work/centre.nc" "centre" '^G2 X3\.0000 Y-1\.5000 I3\.0000 J0\.0000 F600\.0000$'
if grep -q "moved by" "$work/semi.nc"; then fail_test "--origin drawing (the default) moved the drawing"; fi

# --- the preview: plot OUT.nc [--source MODEL] ---
"$casteljau" gcode "$semicircle" --tolerance 0.01 --step-down 0.5 -o "$work/semi2.nc" >/dev/null
"$casteljau" plot "$work/semi2.nc" --source "$semicircle" -o "$work/preview.svg" 2>"$work/err" ||
  fail_test "plot a program: $(cat "$work/err")"
has "$work/preview.svg" "preview title" 'semi2\.nc: 2 arcs, 0 lines, 2 plunges'
for label in "rapid moves \(G0\)" "source curves" "arcs \(G2, G3\)" "plunges"; do
  has "$work/preview.svg" "preview legend" "$label"
done
expect_error "a program with --comb" "--comb applies to curves and surfaces, not to a G-code program" \
  plot "$work/semi2.nc" --comb -o "$work/bad.svg"
expect_error "--source without a program" "--source goes with a G-code program (.nc, .ngc, .gcode, .tap)" \
  plot "$semicircle" --source "$semicircle" -o "$work/bad.svg"
expect_error "two programs" "a G-code program is plotted alone" plot "$work/semi2.nc" "$work/semi.nc" -o "$work/bad.svg"
printf 'G21\nG91\nG1 X1\n' >"$work/incremental.nc"
expect_error "a program it does not read" "incremental.nc: line 2: G91 is not read" plot "$work/incremental.nc" -o "$work/bad.svg"
[[ ! -e "$work/bad.svg" ]] || fail_test "an error left $work/bad.svg"

# --- bad input: exit 2, one line, nothing written ---
model space.json '{"type": "bezier", "control_points": [[0,0,0],[1,1,1]]}'
gc() { echo gcode "$@" -o "$work/bad.nc"; }
expect_error "no tolerance" "--tolerance is required" $(gc "$semicircle")
expect_error "tolerance 0" "--tolerance: 0 is not a distance > 0" $(gc "$semicircle" --tolerance 0)
expect_error "tolerance x" "--tolerance: 'x' is not a number" $(gc "$semicircle" --tolerance x)
expect_error "units" "--units: 'cm' is not mm or in" $(gc "$semicircle" --tolerance 0.01 --units cm)
expect_error "origin" "--origin: 'middle' is not drawing, lower-left or centre" $(gc "$semicircle" --tolerance 0.01 --origin middle)
expect_error "dialect" "--dialect: 'marlin' is not grbl or linuxcnc" $(gc "$semicircle" --tolerance 0.01 --dialect marlin)
expect_error "decimals 3" "--decimals: 3 is outside 4..8" $(gc "$semicircle" --tolerance 0.01 --decimals 3)
# The tolerance is the whole budget: rounding to the decimals (5 units of the last) must leave some of it.
expect_error "tolerance under the rounding" \
  "--tolerance: tolerance 0.0005 mm is not above what rounding to 4 decimals may move the path (0.0005 mm)" \
  $(gc "$semicircle" --tolerance 0.0005 --decimals 4)
expect_error "tolerance finer than 8 decimals" \
  "--tolerance: tolerance 1e-08 inch is below what 8 decimals can carry (rounding moves the path by up to 5e-08 inch)" \
  $(gc "$semicircle" --tolerance 1e-8 --units in)
expect_error "depth -1" "--depth: -1 is not > 0" $(gc "$semicircle" --tolerance 0.01 --depth -1)
expect_error "feed 0" "--feed: 0 is not > 0" $(gc "$semicircle" --tolerance 0.01 --feed 0)
expect_error "safe-z huge" "safe height 10000000 is not a length > 0 and at most 1000000" \
  $(gc "$semicircle" --tolerance 0.01 --safe-z 1e7)
expect_error "too many passes" "takes more than 10000 passes" \
  $(gc "$semicircle" --tolerance 0.01 --step-down 0.00001)
expect_error "arcs and lines" "--arcs excludes --lines" $(gc "$semicircle" --tolerance 0.01 --arcs --lines)
expect_error "a surface" "gcode cuts plane curves; the bezier_surface model in '$examples/patch.json' is a surface" \
  $(gc "$examples/patch.json" --tolerance 0.01)
expect_error "a space curve" "gcode cuts plane curves; the bezier model in '$work/space.json' lives in R^3" \
  $(gc "$work/space.json" --tolerance 0.01)
model point.json '{"type": "bezier", "control_points": [[1,1],[1,1]]}'
expect_error "a single point" "'$work/point.json': arc fitting needs a curve of nonzero length, this one is a single point" \
  $(gc "$work/point.json" --tolerance 0.01)
expect_error "a single point, lines" "a toolpath needs a curve of nonzero length, this one is a single point" \
  $(gc "$work/point.json" --tolerance 0.01 --lines)
printf '<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 10 10"></svg>' >"$work/empty.svg"
expect_error "an empty drawing" "the drawing has no path or shape to read" $(gc "$work/empty.svg" --tolerance 0.01)
expect_error "missing file" "cannot open '$work/none.json'" $(gc "$work/none.json" --tolerance 0.01)
expect_error "output is the input" "is the input INPUT" gcode "$semicircle" --tolerance 0.01 -o "$semicircle"
[[ ! -e "$work/bad.nc" ]] || fail_test "an error left $work/bad.nc"

finish gcode
