#!/usr/bin/env bash
# casteljau gallery DIR: every file that index.html links to exists and is
# non-empty, every figure has its SVG and PNG, and the PNGs are PNGs.
# Usage: bash gallery_index.sh <casteljau-binary> <repo>/examples
set -euo pipefail
casteljau="$1"
examples="$2"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
failures=0
check() { if ! eval "$2"; then echo "FAIL: $1"; failures=$((failures + 1)); fi; }

"$casteljau" gallery "$work/gallery" --examples "$examples" >"$work/stdout" 2>"$work/stderr"
check "gallery exits 0 with nothing on stderr" '[ ! -s "$work/stderr" ]'
check "index.html written" '[ -s "$work/gallery/index.html" ]'

# Every src= and href= target of index.html (relative links only).
links="$(grep -oE '(src|href)="[^"#:]+"' "$work/gallery/index.html" | sed -E 's/^(src|href)="//; s/"$//' | sort -u)"
count=0
for f in $links; do
  count=$((count + 1))
  check "linked file $f exists and is non-empty" '[ -s "$work/gallery/$f" ]'
done
check "index.html links at least 40 files (got $count)" '[ "$count" -ge 40 ]'

# Each figure: an SVG and a PNG, the SVG an SVG document, the PNG a PNG.
for svg in "$work"/gallery/*.svg; do
  name="${svg%.svg}"
  check "$(basename "$name").png exists" '[ -s "$name.png" ]'
  check "$(basename "$svg") is SVG" 'head -c 200 "$svg" | grep -q "<svg "'
  check "$(basename "$svg") has no curve commands" '! grep -q "<path" "$svg"'
  check "$(basename "$name").png is PNG" '[ "$(head -c 8 "$name.png" | od -An -tx1 | tr -d " \n")" = "89504e470d0a1a0a" ]'
  check "$(basename "$svg") is linked from index.html" 'grep -q "src=\"$(basename "$svg")\"" "$work/gallery/index.html"'
done
# The interpolation figures of issue 3 (23 to 29), each with a caption.
for name in 23_head_interpolants 24_car_interpolants 25_runge 26_natural_splines 27_smoothing 28_head_methods 29_car_methods; do
  check "figure $name is in the gallery" '[ -s "$work/gallery/$name.svg" ] && grep -q "<figure id=\"$name\">" "$work/gallery/index.html"'
done
# The surface figures of issue 5 (30 to 34), each with a caption.
for name in 30_bezier_patch 31_coons_blendings 32_bspline_surface_local_control 33_nurbs_sphere_torus 34_tessellation_tolerances; do
  check "figure $name is in the gallery" '[ -s "$work/gallery/$name.svg" ] && grep -q "<figure id=\"$name\">" "$work/gallery/index.html"'
done
# No temporary files left behind.
check "no temporary files" '[ -z "$(find "$work/gallery" -name ".*tmp*")" ]'

# Progress: stderr above is a pipe, so it stayed empty. CASTELJAU_PROGRESS=always
# forces the line "casteljau gallery: N %" there, once the work has run for a
# second (cli/progress.hpp): then stderr holds that line, rewritten in place,
# and nothing else; the same stdout line.
start=$(date +%s%N)
CASTELJAU_PROGRESS=always "$casteljau" gallery "$work/gallery_progress" --examples "$examples" >"$work/stdout_p" 2>"$work/stderr_p"
elapsed_ms=$(( ($(date +%s%N) - start) / 1000000 ))
check "gallery with progress: the same stdout" '[ "$(sed "s/gallery_progress/gallery/" "$work/stdout_p")" = "$(cat "$work/stdout")" ]'
check "gallery with progress: stderr holds only progress lines" \
  '! tr "\r" "\n" <"$work/stderr_p" | sed "s/\x1b\[K//g" | grep -v "^$" | grep -qvE "^casteljau gallery: [0-9]+ %$"'
if [ "$elapsed_ms" -ge 1500 ]; then
  check "gallery with progress ($elapsed_ms ms): a 'casteljau gallery: N %' line" \
    'tr "\r" "\n" <"$work/stderr_p" | grep -qE "casteljau gallery: [0-9]+ %"'
else
  echo "note: the gallery took $elapsed_ms ms, under the second before a progress line shows"
fi

# gallery --help lists every section of the gallery, not only its Bézier figures
# (read with line breaks and indents squeezed: help is wrapped to the terminal).
"$casteljau" gallery --help >"$work/help"
for section in "01-16 Bézier curves" "17-22 B-splines and NURBS" "23-29 interpolation" "30-34 surfaces"; do
  check "gallery --help lists '$section'" 'tr -s " \n" "  " <"$work/help" | grep -qF "$section"'
done

# A folder that cannot be created: exit 2, one line, nothing written.
touch "$work/file"
set +e
"$casteljau" gallery "$work/file/sub" --examples "$examples" >"$work/out2" 2>"$work/err2"
status=$?
set -e
check "gallery into a path under a file exits 2 (got $status)" '[ "$status" -eq 2 ]'
check "one error line" '[ "$(wc -l <"$work/err2")" -eq 1 ] && grep -q "^casteljau: error: " "$work/err2"'

# A missing examples folder: exit 2, one line naming the file.
set +e
"$casteljau" gallery "$work/g2" --examples "$work/nowhere" >"$work/out3" 2>"$work/err3"
status=$?
set -e
check "missing examples exits 2 (got $status)" '[ "$status" -eq 2 ]'
check "missing examples: one line naming notebook_polygon.csv" '[ "$(wc -l <"$work/err3")" -eq 1 ] && grep -q "notebook_polygon.csv" "$work/err3"'
check "missing examples: no gallery files" '[ -z "$(ls -A "$work/g2" 2>/dev/null)" ]'

checks=$((count + 5 * $(ls "$work"/gallery/*.svg | wc -l) + 23))
echo "$((checks - failures)) passed, $failures failed"
[ "$failures" -eq 0 ]
