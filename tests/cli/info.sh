#!/usr/bin/env bash
# casteljau info: what a file holds, worked by hand for a small SVG drawing
# (two texts and an image left out), a DXF drawing in metres with handles,
# layers and entities left out, model JSON curves and a surface; errors exit 2.
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
expect_error "a missing file" "cannot open" info "$work/none.json"
expect_error "--units mm on model JSON" "millimetres are asked of model JSON" info "$examples/semicircle.json" --units mm
finish info
