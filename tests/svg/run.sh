#!/usr/bin/env bash
# run.sh CHECKER CASTELJAU EXAMPLES: Chromium reads SVG (chromium_paths.mjs,
# chromium_drawings.mjs), then the checker compares its reading with
# casteljau's: the path data corpus; the drawings of drawings/ and the SVG
# files of examples/; and what `casteljau convert --to svg` writes of those
# drawings and of the plane curve models of examples/. Needs Debian's
# chromium and npm's playwright-core in tests/svg/node_modules (make deps
# installs both); without them the test is skipped (exit 77), except in CI,
# where it fails.
set -euo pipefail
checker=$1 casteljau=$2 examples=$3
here=$(cd "$(dirname "$0")" && pwd)
if [ ! -x /usr/bin/chromium ] || [ ! -d "$here/node_modules/playwright-core" ]; then
  echo "svg: Debian's chromium or npm's playwright-core is missing (make deps installs them)"
  [ "${CI:-}" = true ] && exit 1
  exit 77
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

echo "== path data =="
node "$here/chromium_paths.mjs" "$here/path_corpus.txt" "$work/paths.json"
"$checker" paths "$here/path_corpus.txt" "$work/paths.json"

echo "== drawings read =="
mkdir "$work/drawings" "$work/written"
cp "$here"/drawings/*.svg "$examples"/*.svg "$work/drawings/"
node "$here/chromium_drawings.mjs" "$work/drawings" "$work/drawings.json"
"$checker" drawings "$work/drawings" "$work/drawings.json"

echo "== drawings written =="
# The drawings, and the plane curves of examples/ (exact cubics, NURBS
# circles and arcs, higher degrees), written at the default tolerance.
# notebook_curve: degree 4; semicircle: rational; quad, spline: exact.
cp "$examples"/notebook_curve.json "$examples"/semicircle.json "$examples"/quad.json "$examples"/spline.json \
   "$work/drawings/"
# Text set in a font (y up, like every model): written upright, so Chromium's
# points, y negated, lie on the glyphs (issue 39: the SVG was upside down).
font=/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf
if [ -f "$font" ]; then "$casteljau" text Fg --font "$font" --size 10 -o "$work/drawings/text_fg.json"; fi
for original in "$work"/drawings/*; do
  name=$(basename "$original")
  "$casteljau" convert "$original" --to svg -o "$work/written/$name.svg" >/dev/null
done
node "$here/chromium_drawings.mjs" "$work/written" "$work/written.json"
"$checker" written "$work/drawings" "$work/written.json"
