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

# CASTELJAU_PROGRESS=always forces the progress line "casteljau gallery: N %"
# into this pipe once the work has run for a second (cli/progress.hpp):
# stderr holds that line, rewritten in place, and nothing else.
start=$(date +%s%N)
CASTELJAU_PROGRESS=always "$casteljau" gallery "$work/gallery" --examples "$examples" >"$work/stdout" 2>"$work/stderr"
elapsed_ms=$(( ($(date +%s%N) - start) / 1000000 ))
check "gallery exits 0 with only progress lines on stderr" \
  '! tr "\r" "\n" <"$work/stderr" | sed "s/\x1b\[K//g" | grep -v "^$" | grep -qvE "^casteljau gallery: [0-9]+ %$"'
if [ "$elapsed_ms" -ge 1500 ]; then
  check "gallery ($elapsed_ms ms): a 'casteljau gallery: N %' line" 'grep -qE "casteljau gallery: [0-9]+ %" "$work/stderr"'
else
  echo "note: the gallery took $elapsed_ms ms, under the second before a progress line shows"
fi
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

# Without CASTELJAU_PROGRESS, nothing on a pipe: the same gallery again, the
# same stdout and an empty stderr. Under AddressSanitizer the gallery costs
# about 50 s of CPU: a sanitizer build (the binary links libasan) renders it
# once, above.
if ldd "$casteljau" 2>/dev/null | grep -q libasan; then
  echo "note: skipped under the sanitizer: the gallery without progress"
else
  "$casteljau" gallery "$work/gallery_quiet" --examples "$examples" >"$work/stdout_q" 2>"$work/stderr_q"
  check "gallery without CASTELJAU_PROGRESS: nothing on stderr" '[ ! -s "$work/stderr_q" ]'
  check "gallery without CASTELJAU_PROGRESS: the same stdout" \
    '[ "$(sed "s/gallery_quiet/gallery/" "$work/stdout_q")" = "$(cat "$work/stdout")" ]'
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
