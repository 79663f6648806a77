#!/usr/bin/env bash
# What the command line says about itself (issue 15): an unknown subcommand
# or option is named with the nearest known name; --version is CMake's
# project() version; --help is wrapped to COLUMNS (80 in a pipe) and every
# subcommand's help ends with an example that runs as written; a reader that
# closes the pipe early gives exit 1 (not death by SIGPIPE, 141) and no
# message. Usage: bash cli_messages.sh CASTELJAU EXAMPLES_DIR
source "$(dirname "$0")/support/common.sh" "$@"
# Absolute paths: the examples run in a folder of their own.
casteljau="$(cd "$(dirname "$casteljau")" && pwd)/$(basename "$casteljau")"
examples="$(cd "$examples" && pwd)"
ko() {
  echo "FAIL: $*"
  failures=$((failures + 1))
}
subcommands=(eval plot bernstein gallery convert interpolate fit tessellate)

# --- unknown subcommands and options ----------------------------------------------
expect_error "a long spelling" "unknown subcommand 'evaluate'; did you mean 'eval'?" evaluate x.csv
expect_error "a typo" "unknown subcommand 'tesselate'; did you mean 'tessellate'?" tesselate s.json
expect_error "a transposition" "unknown subcommand 'fti'; did you mean 'fit'?" fti points.csv
expect_error "a prefix" "unknown subcommand 'interp'; did you mean 'interpolate'?" interp points.csv
expect_error "nothing near" "unknown subcommand 'bogus' (the subcommands: eval, plot, bernstein, gallery, convert, interpolate, fit, tessellate, length, closest, intersect, text, gcode, info, arcs)" bogus
expect_error "an unknown option of casteljau" "unknown option '--verison' for casteljau; did you mean '--version'?" --verison
expect_error "an unknown option before the subcommand" "unknown option '--bogus' for casteljau (casteljau --help lists them)" \
  --bogus eval "$examples/notebook_polygon.csv" --at 0
expect_error "no arguments at all" "a subcommand is required: eval, plot, bernstein, gallery, convert, interpolate, fit, tessellate, length, closest, intersect, text, gcode, info, arcs (casteljau --help says what each does)"
polygon="$examples/notebook_polygon.csv"
expect_error "an option typo" "unknown option '--atx' for eval; did you mean '--at'?" eval "$polygon" --atx 0.5
expect_error "a singular" "unknown option '--sample' for eval; did you mean '--samples'?" eval "$polygon" --sample 3
expect_error "an option with =" "unknown option '--derivate' for eval; did you mean '--derivative'?" eval "$polygon" --at 0 --derivate=1
expect_error "an option far from all" "unknown option '--bogus' for eval (casteljau eval --help lists them)" eval "$polygon" --bogus
expect_error "another subcommand's option" "unknown option '--tolerence' for tessellate; did you mean '--tolerance'?" \
  tessellate s.json --tolerence 0.1 -o s.obj
expect_error "an extra argument" "unexpected argument 'extra' for convert (casteljau convert --help shows its usage)" \
  convert "$polygon" extra --to json

# --- --version: CMake's project() version, written once --------------------------
version=$(sed -nE 's/^project\(casteljau VERSION ([0-9.]+).*/\1/p' "$examples/../CMakeLists.txt")
[[ -n "$version" ]] || ko "no version in CMakeLists.txt's project()"
check "--version" "casteljau $version" --version

# --- --help: wrapped, an example per subcommand, each example runs ----------------
# too_long WIDTH FILE: the lines longer than WIDTH characters, except example
# commands (a command is never wrapped, so that it stays copyable).
too_long() { grep -v '^  casteljau ' "$2" | LC_ALL=C.UTF-8 grep -E ".{$(($1 + 1)),}"; }
"$casteljau" --help >"$work/help" 2>&1 || ko "--help exit $?"
[[ -z "$(too_long 80 "$work/help")" ]] || ko "--help in a pipe: lines over 80: $(too_long 80 "$work/help" | head -1)"
for sub in "${subcommands[@]}"; do
  grep -Eq "^  $sub +[A-Z]" "$work/help" || ko "--help does not list $sub with its summary"
done
mkdir "$work/run"
ln -s "$examples" "$work/run/examples"
for sub in "${subcommands[@]}"; do
  "$casteljau" "$sub" --help >"$work/help" 2>&1 || ko "$sub --help: exit $?"
  [[ -z "$(too_long 80 "$work/help")" ]] || ko "$sub --help: lines over 80: $(too_long 80 "$work/help" | head -1)"
  COLUMNS=60 "$casteljau" "$sub" --help >"$work/help60" 2>&1
  [[ -z "$(too_long 60 "$work/help60")" ]] || ko "$sub --help, COLUMNS=60: lines over 60: $(too_long 60 "$work/help60" | head -1)"
  example=$(grep -A1000 '^Example (' "$work/help" | grep -m1 "^  casteljau $sub ")
  [[ -n "$example" ]] || { ko "$sub --help has no example"; continue; }
  read -ra words <<<"${example#  casteljau }"
  missing=""
  for word in "${words[@]}"; do [[ "$word" == examples/* && ! -e "$work/run/$word" ]] && missing=$word; done
  if [[ -n "$missing" ]]; then
    echo "note: $sub's example needs $missing, not in examples/ yet: not run"
  elif [[ "$sub" == gallery ]]; then
    : # every seed figure takes seconds: gallery_index.sh runs the gallery
  else
    (cd "$work/run" && "$casteljau" "${words[@]}") >"$work/stdout" 2>"$work/stderr" ||
      ko "$sub's example failed: $example: $(cat "$work/stderr")"
  fi
done
[[ "$(cd "$work/run" && "$casteljau" eval examples/notebook_polygon.csv --at 0.5)" == "2.25,1.5" ]] ||
  ko "eval's example does not print what its help says (2.25,1.5)"

# --- a closed pipe: exit 1, no message, no SIGPIPE ---------------------------------
# 200000 points are more than a pipe holds, so the write fails once head leaves.
set -o pipefail
first=$("$casteljau" eval "$polygon" --samples 200000 2>"$work/stderr" | head -n 1)
status=$?
set +o pipefail
[[ $status -eq 1 ]] || ko "eval | head -1 exited $status, not 1 (141 is death by SIGPIPE)"
[[ "$first" == "0,0" ]] || ko "eval | head -1 printed $first"
[[ ! -s "$work/stderr" ]] || ko "a closed pipe printed: $(cat "$work/stderr")"

finish "cli messages"
