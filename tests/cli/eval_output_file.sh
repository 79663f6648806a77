#!/usr/bin/env bash
# casteljau eval -o FILE: writes exactly what stdout would get, prints nothing
# on stdout; on error leaves no file (and an existing one untouched) and no
# temporary file behind. Usage: bash eval_output_file.sh CASTELJAU EXAMPLES_DIR
source "$(dirname "$0")/support/common.sh" "$@"
polygon="$examples/notebook_polygon.csv"
fail() {
  echo "FAIL: $*"
  failures=$((failures + 1))
}

# Success: the file holds what stdout would have held; stdout stays empty.
"$casteljau" eval "$polygon" --samples 11 >"$work/expected.csv" || fail "eval to stdout"
"$casteljau" eval "$polygon" --samples 11 -o "$work/out.csv" >"$work/stdout" 2>"$work/stderr" || fail "eval -o"
cmp -s "$work/expected.csv" "$work/out.csv" || fail "-o file differs from stdout"
[[ -s "$work/stdout" ]] && fail "-o printed on stdout"
[[ -s "$work/stderr" ]] && fail "-o printed on stderr"
[[ $(wc -l <"$work/out.csv") -eq 11 ]] || fail "-o file does not have 11 lines"
[[ $(head -n 6 "$work/out.csv" | tail -n 1) == "2.25,1.5" ]] || fail "-o file: B(0.5) is not 2.25,1.5"

# The output is itself a point set casteljau reads: as a control polygon its
# end points are the curve's ends, unchanged.
"$casteljau" eval "$work/out.csv" --at 0 --at 1 >"$work/ends.csv" || fail "reading the output back"
[[ "$(cat "$work/ends.csv")" == $'0,0\n4,0' ]] || fail "output read back: ends are $(cat "$work/ends.csv")"

# Replacing an existing file.
"$casteljau" eval "$polygon" --at 0.5 --output "$work/out.csv" || fail "eval --output over an existing file"
[[ "$(cat "$work/out.csv")" == "2.25,1.5" ]] || fail "existing file not replaced"

# Errors: no file is created, an existing file is left as it was.
"$casteljau" eval "$polygon" --at 2 -o "$work/new.csv" 2>/dev/null
[[ $? -eq 2 ]] || fail "out-of-domain -o did not exit 2"
[[ -e "$work/new.csv" ]] && fail "an error left a file behind"
"$casteljau" eval "$work/missing.json" --at 0 -o "$work/new.csv" 2>/dev/null
[[ -e "$work/new.csv" ]] && fail "a missing model left a file behind"
printf 'keep me\n' >"$work/kept.csv"
"$casteljau" eval "$polygon" --at abc -o "$work/kept.csv" 2>/dev/null
[[ "$(cat "$work/kept.csv")" == "keep me" ]] || fail "an error changed an existing file"

# Standard output that cannot be written is not bad input: exit 1, one line.
if [[ -w /dev/full ]]; then
  "$casteljau" eval "$polygon" --samples 5 >/dev/full 2>"$work/stderr"
  status=$?
  [[ $status -eq 1 ]] || fail "writing to a full device exited $status, not 1"
  [[ $(wc -l <"$work/stderr") -eq 1 && "$(cat "$work/stderr")" == "casteljau: error: cannot write to standard output: "* ]] ||
    fail "writing to a full device: stderr is $(cat "$work/stderr")"
fi

# Nothing else in the folder: no temporary files left by any of the above.
extra=$(ls -A "$work" | grep -v -x -e expected.csv -e out.csv -e stdout -e stderr -e ends.csv -e kept.csv)
[[ -z "$extra" ]] && true || fail "left behind: $extra"

finish "eval output file"
