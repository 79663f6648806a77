#!/usr/bin/env bash
# run.sh READER CHECKER CASTELJAU EXAMPLES: `casteljau gcode` writes programs
# for the head and the car of seed 000 (their C1 Bézier interpolants), the
# exact NURBS half circle (one G2), a NURBS circle, a degree-7 Bézier curve,
# an SVG drawing, a DXF drawing and a word set in DejaVu Sans, at tolerances
# from 0.1 to 0.0001, with arcs and with lines only, in mm and in inches,
# for GRBL and LinuxCNC, in one pass and in several. READER interprets each:
# - rs274: LinuxCNC's own interpreter (Debian's linuxcnc-uspace,
#   /usr/bin/rs274 through rs274_motion.py);
# - cncjs: npm's gcode-toolpath, what cncjs runs (interpret.mjs; node and
#   tests/gcode/node_modules, which make deps installs);
# and the checker compares the motion it read with the curves, both ways
# (gcode_check.cpp). Without the reader the test is skipped (exit 77),
# except in CI, where it fails. Prints one line a program: its counts, size
# and the largest distances measured (docs/cnc.md quotes them).
set -euo pipefail
reader=$1 checker=$2 casteljau=$3 examples=$4
here=$(cd "$(dirname "$0")" && pwd)
export NODE_PATH=/usr/share/nodejs
missing() {
  echo "gcode: $1 (make deps installs it)"
  [ "${CI:-}" = true ] && exit 1
  exit 77
}
case $reader in
  rs274) command -v rs274 >/dev/null || missing "LinuxCNC's rs274 (Debian linuxcnc-uspace) is missing" ;;
  cncjs)
    command -v node >/dev/null && [ -d "$here/node_modules/gcode-toolpath" ] ||
      missing "node or npm's gcode-toolpath is missing"
    ;;
  *) echo "usage: run.sh rs274|cncjs CHECKER CASTELJAU EXAMPLES"; exit 2 ;;
esac
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0

# case_of NAME MODEL TOLERANCE [gcode options...]: write, interpret, compare.
case_of() {
  local name=$1 model=$2 tolerance=$3 dialect=grbl
  shift 3
  [[ " $* " == *" --dialect linuxcnc "* ]] && dialect=linuxcnc
  if ! "$casteljau" gcode "$model" --tolerance "$tolerance" "$@" -o "$work/$name.nc" >"$work/$name.summary"; then
    echo "FAIL: $name: casteljau gcode $model $*"
    failures=$((failures + 1))
    return
  fi
  # The decimals the program carries, from its header.
  local decimals step=0
  decimals=$(sed -n 's/.*rounding of its numbers to \([0-9]*\) decimals.*/\1/p' "$work/$name.nc")
  if [[ $reader == rs274 ]]; then
    # rs274 prints 4 decimals: a program written with more is read to 1e-4.
    ((decimals > 4)) && step=0.0001
    /usr/bin/python3 "$here/rs274_motion.py" "$work/$name.nc" "$work/$name.motion.json"
  else
    node "$here/interpret.mjs" "$work/$name.nc" "$work/$name.motion.json"
  fi
  echo -n "$name ($*; $decimals decimals, $(wc -c <"$work/$name.nc") bytes): $(sed 's/^gcode: //' "$work/$name.summary"); "
  "$checker" "$model" "$work/$name.motion.json" "$tolerance" "$dialect" "$step" || failures=$((failures + 1))
}

"$casteljau" interpolate "$examples/head.csv" --method c1-bezier -o "$work/head.json"
"$casteljau" interpolate "$examples/car.csv" --method c1-bezier -o "$work/car.json"
# A NURBS circle of radius 5 about (1, 2): four quarter arcs, weights sqrt(2)/2 at the corners.
w=0.7071067811865476
cat >"$work/circle.json" <<EOF
{"type": "bspline", "degree": 2, "knots": [0,0,0,0.25,0.25,0.5,0.5,0.75,0.75,1,1,1],
 "control_points": [[6,2],[6,7],[1,7],[-4,7],[-4,2],[-4,-3],[1,-3],[6,-3],[6,2]],
 "weights": [1,$w,1,$w,1,$w,1,$w,1]}
EOF
cat >"$work/degree7.json" <<'EOF'
{"type": "bezier", "control_points": [[0,0],[10,30],[20,-10],[30,40],[40,0],[50,30],[60,-20],[70,10]]}
EOF
# A DXF drawing: the head as exact SPLINE entities.
"$casteljau" convert "$work/head.json" --to dxf -o "$work/head.dxf" >/dev/null
# A word: its glyph outlines at 20 mm.
font=/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf
[[ -f $font ]] || missing "the font $font (fonts-dejavu-core) is missing"
"$casteljau" text casteljau --font "$font" --size 20 -o "$work/word.json"

# Every curve at every tolerance, arcs and lines (docs/cnc.md quotes the
# counts); cncjs, which reads the same doubles as rs274 but to full
# precision, at 0.01 and 0.0001.
cp "$examples/semicircle.json" "$work/semicircle.json"
tolerances="0.1 0.01 0.001 0.0001"
[[ $reader == cncjs ]] && tolerances="0.01 0.0001"
for tolerance in $tolerances; do
  for curve in head car word degree7 semicircle circle; do
    case_of "$curve-$tolerance" "$work/$curve.json" "$tolerance"
    case_of "$curve-lines-$tolerance" "$work/$curve.json" "$tolerance" --lines
  done
done
case_of degree7-linuxcnc "$work/degree7.json" 0.0001 --dialect linuxcnc --decimals 7
case_of head-inch "$work/head.json" 0.001 --units in
case_of head-passes "$work/head.json" 0.01 --depth 3 --step-down 1 --dialect linuxcnc
case_of sailboat "$examples/sailboat.svg" 0.01
case_of head-dxf "$work/head.dxf" 0.01
case_of word-lines-inch "$work/word.json" 0.01 --lines --units in

# The exact half circle is one G2 (and nothing else cuts); the circle two arcs.
cuts=$(grep -cE '^G[123] X' "$work/semicircle-0.01.nc" || true)
g2=$(grep -cE '^G2 ' "$work/semicircle-0.01.nc" || true)
if [[ $cuts -ne 1 || $g2 -ne 1 ]]; then
  echo "FAIL: the half circle is not one G2: $cuts cuts, $g2 G2"
  failures=$((failures + 1))
fi
arcs=$(grep -cE '^G[23] ' "$work/circle-0.0001.nc" || true)
if [[ $arcs -ne 2 ]]; then echo "FAIL: the circle is $arcs arcs, not 2"; failures=$((failures + 1)); fi
# Three passes of the head: three plunges; GRBL programs hold nothing GRBL refuses.
plunges=$(grep -cE '^G1 Z' "$work/head-passes.nc" || true)
if [[ $plunges -ne 3 ]]; then echo "FAIL: head in 3 passes plunges $plunges times"; failures=$((failures + 1)); fi
if grep -lE '^G(64|5|91\.1)' "$work"/head-0.01.nc "$work"/car-0.01.nc "$work"/semicircle-0.01.nc; then
  echo "FAIL: a GRBL program holds G64, G5 or G91.1"
  failures=$((failures + 1))
fi

if [[ $failures -ne 0 ]]; then
  echo "$failures failure(s)"
  exit 1
fi
echo "gcode: every program read by $reader as casteljau's curves"
