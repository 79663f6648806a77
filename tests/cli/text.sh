#!/usr/bin/env bash
# casteljau text: glyph outlines as model JSON (one closed curve per contour),
# in font units or --size, and its errors (exit 2, one line).
# Usage: bash text.sh CASTELJAU EXAMPLES_DIR
source "$(dirname "$0")/support/common.sh" "$@"
font=/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf
if [[ ! -f $font ]]; then echo "text: fonts-dejavu-core is not installed"; [[ "${CI:-}" == true ]] && exit 1; exit 0; fi

# "l" in DejaVu Sans is one rectangle: 4 lines, closed, in font units.
"$casteljau" text l --font "$font" -o "$work/l.json"
count=$(grep -o piecewise_bezier "$work/l.json" | wc -l)
[[ $count == 1 ]] || { echo "FAIL: l has $count contours"; failures=$((failures + 1)); }
[[ "$("$casteljau" eval "$work/l.json" --at 0)" == "$("$casteljau" eval "$work/l.json" --at 4)" ]] ||
  { echo "FAIL: the contour of l is not closed"; failures=$((failures + 1)); }
# --size 2048 is DejaVu's em (2048 units): the same numbers.
check "--size of one em is font units" "$(cat "$work/l.json")" text l --font "$font" --size 2048
# "o" has two contours; "i" two (the dot and the stem); a space none.
count=$("$casteljau" text o --font "$font" | grep -o piecewise_bezier | wc -l)
[[ $count == 2 ]] || { echo "FAIL: o has $count contours"; failures=$((failures + 1)); }
expect_error "only a space" "the text draws no outline" text " " --font "$font"
expect_error "not a font" "is not a font FreeType reads: unknown file format" text a --font "$examples/quad.json"
expect_error "no font" "cannot open the font" text a --font "$work/none.ttf"
expect_error "--size 0" "--size: 0 is not an em size > 0" text a --font "$font" --size 0
# A size that puts a glyph beyond the range of coordinates (1e100) is refused
# naming the glyph and the largest size the text allows (issue 39: it aborted);
# that largest size is accepted.
expect_error "--size beyond the coordinates" \
  "the size 1e+101 puts glyph 43 (for U+0048, character 0) 7.29e+100 from the origin, beyond 1e+100, the range of coordinates: this text allows a size of at most 1.06e+100" \
  text Hi --font "$font" --size 1e101
"$casteljau" text Hi --font "$font" --size 1.06e100 -o "$work/huge.json" ||
  { echo "FAIL: the largest size named is refused"; failures=$((failures + 1)); }
expect_error "bad UTF-8" "the text is not UTF-8: byte 2 (0xff)" text $'a\xff' --font "$font"
finish text
