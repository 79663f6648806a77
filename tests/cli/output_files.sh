#!/usr/bin/env bash
# Where every command's output goes (issue 15): -o FILE replaces a regular
# file whole (rename into place) but writes a FIFO or a device in place (a
# rename replaced them by regular files); -o - is standard output for every
# command that takes -o; -o '' is refused; a symbolic link stays and its
# target is written, dangling or pointing at a FIFO; an output that is one of
# the inputs is refused, whatever the spelling, for every command; no
# temporary file is left behind. Usage: bash output_files.sh CASTELJAU EXAMPLES_DIR
source "$(dirname "$0")/support/common.sh" "$@"
polygon="$examples/notebook_polygon.csv"
ko() {
  echo "FAIL: $*"
  failures=$((failures + 1))
}
# kind PATH: what is at PATH itself (not followed): fifo, link, file, device or none.
kind() {
  if [[ -L "$1" ]]; then echo link; elif [[ -p "$1" ]]; then echo fifo; elif [[ -c "$1" ]]; then echo device
  elif [[ -f "$1" ]]; then echo file; else echo none; fi
}
# read_fifo FIFO OUT: a reader in the background that copies FIFO to OUT
# (given up after 10 s: a writer that replaced the FIFO never comes).
read_fifo() { timeout 10 cat "$1" >"$2" & }

model curve.json '{"type":"bezier","control_points":[[0,0],[1,2],[2,2],[4,1],[4,0]]}'
model patch.json '{"type":"bezier_surface","control_points":[[[0,0,0],[0,1,0]],[[1,0,0],[1,1,1]]]}'
cp "$examples/head.csv" "$work/head.csv"
printf '0.5\n' >"$work/t.csv"

# --- a FIFO stays a FIFO and gets the output ------------------------------------
mkfifo "$work/fifo"
read_fifo "$work/fifo" "$work/from_fifo"
"$casteljau" eval "$polygon" --at 0.5 -o "$work/fifo" 2>"$work/stderr" || ko "eval -o FIFO: exit $?: $(cat "$work/stderr")"
wait
[[ "$(cat "$work/from_fifo")" == "2.25,1.5" ]] || ko "eval -o FIFO: the reader got $(cat "$work/from_fifo")"
[[ $(kind "$work/fifo") == fifo ]] || ko "eval -o FIFO: the FIFO is now a $(kind "$work/fifo")"
# Figures go through the same writer (cairo encodes in memory).
mkfifo "$work/figure.png"
read_fifo "$work/figure.png" "$work/from_fifo"
"$casteljau" bernstein 3 -o "$work/figure.png" 2>"$work/stderr" || ko "bernstein -o FIFO: $(cat "$work/stderr")"
wait
[[ "$(head -c 4 "$work/from_fifo" | tail -c 3)" == "PNG" ]] || ko "bernstein -o FIFO: the reader got no PNG"
[[ $(kind "$work/figure.png") == fifo ]] || ko "bernstein -o FIFO: the FIFO is now a $(kind "$work/figure.png")"
rm -f "$work/fifo" "$work/figure.png" "$work/from_fifo"

# --- a character device is written in place ------------------------------------
# As root, a writer that renames would replace the system's /dev/null: test on
# a null device of our own then (a user cannot replace /dev/null, only fail).
null=/dev/null
if [[ $EUID -eq 0 ]] && mknod "$work/null" c 1 3 2>/dev/null && printf x >"$work/null" 2>/dev/null; then
  null="$work/null"
fi
"$casteljau" eval "$polygon" --samples 3 -o "$null" 2>"$work/stderr" || ko "eval -o $null: $(cat "$work/stderr")"
[[ $(kind "$null") == device ]] || ko "$null is no longer a device"

# --- -o - is standard output for every command that takes -o ---------------------
check "eval -o -" "2.25,1.5" eval "$polygon" --at 0.5 -o -
"$casteljau" convert "$polygon" --to bspline -o - >"$work/stdout" 2>"$work/stderr" &&
  grep -q '"type":"bspline"' "$work/stdout" || ko "convert -o -: $(cat "$work/stdout" "$work/stderr")"
"$casteljau" interpolate "$work/head.csv" --method c1-bezier -o - >"$work/stdout" 2>"$work/stderr" &&
  grep -q '"piecewise_bezier"' "$work/stdout" || ko "interpolate -o -: $(cat "$work/stderr")"
# fit and tessellate: the model or mesh on stdout, their summary line on stderr.
"$casteljau" fit "$work/head.csv" --degree 3 --control-points 6 -o - >"$work/stdout" 2>"$work/stderr" || ko "fit -o -"
grep -q '"type":"bspline"' "$work/stdout" && ! grep -q '^fit:' "$work/stdout" || ko "fit -o -: stdout $(head -c 80 "$work/stdout")"
grep -q '^fit: 6 control points' "$work/stderr" || ko "fit -o -: the summary is not on stderr: $(cat "$work/stderr")"
"$casteljau" tessellate "$work/patch.json" --tolerance 0.1 -o - >"$work/stdout" 2>"$work/stderr" || ko "tessellate -o -"
grep -q '^f ' "$work/stdout" && grep -q '^v ' "$work/stdout" || ko "tessellate -o -: no OBJ on stdout"
grep -q '^tessellate: ' "$work/stderr" || ko "tessellate -o -: the summary is not on stderr: $(cat "$work/stderr")"
"$casteljau" plot "$work/curve.json" -o - >"$work/stdout" 2>"$work/stderr" || ko "plot -o -: $(cat "$work/stderr")"
[[ "$(head -c 5 "$work/stdout")" == "<?xml" ]] || ko "plot -o -: no SVG on stdout"
"$casteljau" bernstein 4 -o - >"$work/stdout" 2>"$work/stderr" || ko "bernstein -o -: $(cat "$work/stderr")"
grep -q '</svg>' "$work/stdout" || ko "bernstein -o -: no SVG on stdout"
# With -o FILE the summary stays on stdout, as before.
"$casteljau" tessellate "$work/patch.json" --tolerance 0.1 -o "$work/patch.obj" >"$work/stdout" 2>/dev/null
grep -q '^tessellate: ' "$work/stdout" || ko "tessellate -o FILE: the summary left stdout"

# --- -o '' is refused by every command, before any work --------------------------
expect_error "eval -o ''" "-o '': the file name is empty (-o - is standard output)" eval "$polygon" --at 0.5 -o ''
expect_error "convert -o ''" "-o '': the file name is empty" convert "$polygon" --to json -o ''
expect_error "plot -o ''" "-o '': the file name is empty" plot "$work/curve.json" -o ''
expect_error "tessellate --output ''" "-o '': the file name is empty" tessellate "$work/patch.json" --tolerance 0.1 --output ''
expect_error "fit -o ''" "-o '': the file name is empty" fit "$work/head.csv" --degree 3 --control-points 6 -o ''
expect_error "bernstein -o ''" "-o '': the file name is empty" bernstein 3 -o ''
expect_error "interpolate -o ''" "-o '': the file name is empty" interpolate "$work/head.csv" --method c1-bezier -o ''

# --- symbolic links: the link stays, its target gets the output -----------------
printf 'old\n' >"$work/target.csv"
ln -s target.csv "$work/link.csv"
"$casteljau" eval "$polygon" --at 0.5 -o "$work/link.csv" || ko "eval -o LINK"
[[ $(kind "$work/link.csv") == link && "$(cat "$work/target.csv")" == "2.25,1.5" ]] ||
  ko "eval -o LINK: link $(kind "$work/link.csv"), target $(cat "$work/target.csv")"
ln -s made.csv "$work/dangling.csv"
"$casteljau" eval "$polygon" --at 0 -o "$work/dangling.csv" || ko "eval -o DANGLING"
[[ $(kind "$work/dangling.csv") == link && "$(cat "$work/made.csv")" == "0,0" ]] ||
  ko "eval -o DANGLING: link $(kind "$work/dangling.csv"), target $(cat "$work/made.csv" 2>&1)"
mkfifo "$work/pipe"
ln -s pipe "$work/to_pipe.csv"
read_fifo "$work/pipe" "$work/from_pipe"
"$casteljau" eval "$polygon" --at 1 -o "$work/to_pipe.csv" || ko "eval -o LINK-TO-FIFO"
wait
[[ "$(cat "$work/from_pipe")" == "4,0" ]] || ko "eval -o LINK-TO-FIFO: the reader got $(cat "$work/from_pipe")"
[[ $(kind "$work/to_pipe.csv") == link && $(kind "$work/pipe") == fifo ]] ||
  ko "eval -o LINK-TO-FIFO: link $(kind "$work/to_pipe.csv"), FIFO $(kind "$work/pipe")"
rm -f "$work/pipe" "$work/to_pipe.csv" "$work/from_pipe"

# --- an output that is an input is refused, the input untouched ------------------
cp "$work/curve.json" "$work/kept.json"
same="writing the output would destroy it"
expect_error "eval MODEL -o MODEL" "-o '$work/curve.json' is the input MODEL '$work/curve.json': $same" \
  eval "$work/curve.json" --at 0.5 -o "$work/curve.json"
expect_error "eval ./ spelling" "is the input MODEL" eval "$work/curve.json" --at 0.5 -o "$work/./curve.json"
mkdir "$work/sub"
expect_error "eval ../ spelling" "is the input MODEL" eval "$work/curve.json" --at 0.5 -o "$work/sub/../curve.json"
ln -s curve.json "$work/curve_link.json"
expect_error "eval through a link" "is the input MODEL" eval "$work/curve_link.json" --at 0.5 -o "$work/curve.json"
ln "$work/curve.json" "$work/curve_hard.json"
expect_error "eval a hard link" "is the input MODEL" eval "$work/curve.json" --at 0.5 -o "$work/curve_hard.json"
expect_error "eval --params" "is the input --params '$work/t.csv'" eval "$work/curve.json" --params "$work/t.csv" -o "$work/t.csv"
expect_error "convert" "is the input MODEL" convert "$work/curve.json" --to json -o "$work/curve.json"
expect_error "interpolate" "is the input POINTS" interpolate "$work/head.csv" --method c1-bezier -o "$work/head.csv"
expect_error "fit" "is the input POINTS" fit "$work/head.csv" --degree 3 --control-points 6 -o "$work/head.csv"
expect_error "plot, the second input" "is the input INPUT '$work/head.csv'" \
  plot "$work/curve.json" "$work/head.csv" --points-only -o "$work/head.csv"
expect_error "tessellate" "is the input SURFACE" tessellate "$work/patch.json" --tolerance 0.1 -o "$work/patch.json"
cmp -s "$work/curve.json" "$work/kept.json" || ko "a refused output changed the input"
cmp -s "$work/head.csv" "$examples/head.csv" || ko "a refused output changed head.csv"
[[ "$(cat "$work/t.csv")" == "0.5" ]] || ko "a refused output changed t.csv"
# Reading and writing one FIFO or device is not a lost file: allowed.
"$casteljau" eval "$polygon" --params /dev/stdin --at 0 -o "$null" <"$null" 2>"$work/stderr"
[[ "$(cat "$work/stderr")" != *"is the input"* ]] || ko "/dev/stdin in, /dev/null out refused as the same file"

# --- no temporary file anywhere --------------------------------------------------
[[ -z "$(find "$work" -name '.*tmp-*')" ]] || ko "left behind: $(find "$work" -name '.*tmp-*')"

finish "output files"
