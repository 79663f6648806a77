#!/usr/bin/env bash
# casteljau info: what a file holds, worked by hand for a small SVG drawing
# (two texts and an image left out), a DXF drawing in metres with handles,
# layers and entities left out, model JSON curves and a surface; errors exit 2.
# Also the note other commands print of what a drawing left out, and --strict.
# Usage: bash info.sh CASTELJAU EXAMPLES_DIR
source "$(dirname "$0")/support/common.sh" "$@"

# info_is NAME EXPECTED FILE [ARGS...]: the report, its first line without
# the file's folder, is EXPECTED; nothing on stderr, exit 0.
info_is() {
  local name=$1 expected=$2 file=$3
  shift 3
  local out status
  out=$("$casteljau" info "$file" "$@" 2>"$work/stderr")
  status=$?
  out=${out/#"$(dirname "$file")/"/}
  if [[ $status -ne 0 || "$out" != "$expected" || -s "$work/stderr" ]]; then
    echo "FAIL: $name: exit $status, stderr: $(cat "$work/stderr")"
    diff <(echo "$expected") <(echo "$out")
    failures=$((failures + 1))
  fi
}

model drawing.svg '<svg xmlns="http://www.w3.org/2000/svg" width="100mm" height="50mm" viewBox="0 0 200 100">
<text x="1" y="2">hi</text><text x="1" y="20">there</text><image href="a.png" width="3" height="3"/>
<path id="a" d="M0 0L10 10M20 20L30 30"/><circle id="c" cx="50" cy="50" r="10"/>
</svg>'
info_is "an SVG drawing" "$(cat <<'OUT'
drawing.svg: SVG drawing, upright: y up from its page's bottom edge (y = 100 in the file)
unit: none stated (the root's user units; --units mm reads millimetres)
models: 3 (3 piecewise_bezier), in R^2
elements: 2 (1 path, 1 circle)
ids: a, c
Bezier pieces: 6 (2 of degree 1, 4 rational of degree 2)
box: x from 0 to 60, y from 40 to 100
skipped: 3 (2 text, 1 image)
  line 2: <text> (text is not read: convert it to paths)
  line 2: <text> (text is not read: convert it to paths)
  line 2: <image> (not vector geometry)
OUT
)" "$work/drawing.svg"
out=$("$casteljau" info "$work/drawing.svg" --units mm)
[[ "$(echo "$out" | sed -n 2p)" == "unit: millimetres" && "$(echo "$out" | sed -n 7p)" == "box: x from 0 to 30, y from 20 to 50" ]] ||
  { echo "FAIL: info --units mm: $out"; failures=$((failures + 1)); }

model drawing.dxf $'0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n6\n0\nENDSEC\n0\nSECTION\n2\nENTITIES\n0\nLINE\n5\n2A\n8\nwalls\n10\n0\n20\n0\n11\n3\n21\n4\n0\nLINE\n5\n2B\n8\nwalls\n10\n0\n20\n0\n11\n3\n21\n0\n0\nTEXT\n8\n0\n1\nhello\n0\nINSERT\n8\n0\n2\nblock\n0\nENDSEC\n0\nEOF\n'
info_is "a DXF drawing" "$(cat <<'OUT'
drawing.dxf: DXF drawing
unit: metres ($INSUNITS 6, 1000 mm each)
models: 2 (2 bezier), in R^2
elements: 2 (2 LINE)
handles: 2A, 2B
layers: walls (2 entities)
Bezier pieces: 2 (2 of degree 1)
box: x from 0 to 3, y from 0 to 4
skipped: 2 (1 TEXT, 1 INSERT)
  line 43: TEXT
  line 49: INSERT
OUT
)" "$work/drawing.dxf"

info_is "model JSON" "$(cat <<'OUT'
semicircle.json: model JSON
unit: none (model JSON and CSV numbers have no unit)
models: 1 (1 bspline), in R^2
Bezier pieces: 2 (2 rational of degree 2)
box: x from -3 to 3, y from 0 to 3
skipped: nothing
OUT
)" "$examples/semicircle.json"
out=$("$casteljau" info "$examples/sphere.json")
[[ "$(echo "$out" | tail -2 | head -1)" == "box: x from -1 to 1, y from -1 to 1, z from -1 to 1 (surfaces: their control points' box)" ]] ||
  { echo "FAIL: info of a surface: $out"; failures=$((failures + 1)); }
# Every other command notes what a drawing left out on stderr (one line, the
# answer unchanged), and --strict refuses it (issue 39, item 6).
out=$("$casteljau" length "$work/drawing.svg" 2>"$work/note")
[[ "$(cat "$work/note")" == "casteljau: note: $work/drawing.svg: 3 elements are not read (2 text, 1 image); casteljau info $work/drawing.svg lists them" &&
   "$(echo "$out" | wc -l)" == 3 ]] || { echo "FAIL: the note of what was skipped: $(cat "$work/note")"; failures=$((failures + 1)); }
expect_error "--strict refuses an SVG drawing with text" \
  "drawing.svg: 3 elements are not read (2 text, 1 image), and --strict refuses them: line 2: <text> (text is not read: convert it to paths)" \
  length "$work/drawing.svg" --strict
expect_error "--strict refuses a DXF drawing with TEXT and INSERT" \
  "drawing.dxf: 2 elements are not read (1 TEXT, 1 INSERT), and --strict refuses them: line 43: TEXT" \
  eval "$work/drawing.dxf" --at 0 --strict
expect_error "--strict on convert --to svg" "and --strict refuses them" convert "$work/drawing.svg" --to svg --strict
expect_error "--strict on gcode" "and --strict refuses them" gcode "$work/drawing.svg" --tolerance 0.1 --strict
# A drawing with nothing to read is refused by convert --to svg as by the
# others (it wrote an empty drawing 1e-300 wide).
model text.svg '<svg xmlns="http://www.w3.org/2000/svg"><text>hi</text></svg>'
expect_error "convert --to svg of nothing" "text.svg: the drawing has no path or shape to read (line 1: <text> (text is not read: convert it to paths))" \
  convert "$work/text.svg" --to svg

# Selecting models (issue 39, item 10): --model N (as errors count them),
# --id (an SVG id, a DXF handle), --layer (DXF); together they must all match.
out=$("$casteljau" length "$work/drawing.svg" --id c 2>/dev/null)
[[ "$out" == 62.83185307179586 ]] || { echo "FAIL: --id c: $out"; failures=$((failures + 1)); }
out=$("$casteljau" length "$work/drawing.svg" --id a --model 1 2>/dev/null)
[[ "$out" == 14.142135623730953 ]] || { echo "FAIL: --id a --model 1: $out"; failures=$((failures + 1)); }
out=$("$casteljau" length "$work/drawing.dxf" --layer walls --id 2B 2>/dev/null)
[[ "$out" == 3 ]] || { echo "FAIL: --layer walls --id 2B: $out"; failures=$((failures + 1)); }
out=$("$casteljau" closest "$examples/sailboat.svg" --id hull --point 100,10)
[[ "$(echo "$out" | tail -1 | cut -d, -f1)" == 0 ]] || { echo "FAIL: closest --id hull: $out"; failures=$((failures + 1)); }
"$casteljau" convert "$work/drawing.svg" --to svg --id c -o "$work/c.svg" 2>/dev/null >/dev/null
[[ "$(grep -c '<path' "$work/c.svg")" == 1 ]] || { echo "FAIL: convert --to svg --id c: $(cat "$work/c.svg")"; failures=$((failures + 1)); }
expect_error "--id that matches nothing" "'$work/drawing.svg' has no id 'zz' (ids: a, c)" length "$work/drawing.svg" --id zz
expect_error "--layer that matches nothing" "'$work/drawing.dxf' has no layer 'roof' (layers: walls)" length "$work/drawing.dxf" --layer roof
expect_error "--model beyond the models" "--model 9: '$work/drawing.svg' holds 3 models (models[0] to models[2])" \
  length "$work/drawing.svg" --model 9
expect_error "--model that is no number" "--model: 'x' is not a whole number" length "$examples/semicircle.json" --model x

expect_error "a missing file" "cannot open" info "$work/none.json"
expect_error "--units mm on model JSON" "millimetres are asked of model JSON" info "$examples/semicircle.json" --units mm
finish info
