# Shared by the CLI test scripts (tests/cli/*.sh), which start with
#   source "$(dirname "$0")/support/common.sh" "$@"
# and end with `finish NAME`. Arguments: CASTELJAU EXAMPLES_DIR.
# Sets casteljau, examples, work (a temporary folder removed on exit) and
# failures; defines check, expect_error, model and finish.
set -u
casteljau=$1
examples=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0

# check NAME EXPECTED ARGS...: stdout must be EXPECTED, stderr empty, exit 0.
check() {
  local name=$1 expected=$2
  shift 2
  local out err status
  out=$("$casteljau" "$@" 2>"$work/stderr")
  status=$?
  err=$(cat "$work/stderr")
  if [[ $status -ne 0 || "$out" != "$expected" || -n "$err" ]]; then
    echo "FAIL: $name: casteljau $*"
    echo "  exit $status, stdout: $(printf '%q' "$out"), stderr: $err"
    echo "  expected stdout: $(printf '%q' "$expected")"
    failures=$((failures + 1))
  fi
}

# expect_error NAME EXPECTED_SUBSTRING ARGS...: exit 2, nothing on stdout,
# exactly one line "casteljau: error: ..." containing EXPECTED_SUBSTRING.
expect_error() {
  local name=$1 expected=$2
  shift 2
  "$casteljau" "$@" >"$work/stdout" 2>"$work/stderr"
  local status=$?
  local lines message
  lines=$(wc -l <"$work/stderr")
  message=$(cat "$work/stderr")
  if [[ $status -ne 2 || -s "$work/stdout" || $lines -ne 1 || "$message" != "casteljau: error: "* ||
        "$message" != *"$expected"* ]]; then
    echo "FAIL: $name: casteljau $*"
    echo "  exit $status (expected 2), stdout bytes $(wc -c <"$work/stdout"), stderr lines $lines"
    echo "  stderr: $message"
    echo "  expected to contain: $expected"
    failures=$((failures + 1))
  fi
}

# model FILE TEXT: writes TEXT (a model JSON) to $work/FILE.
model() { printf '%s' "$2" > "$work/$1"; }

# finish NAME: the summary line; exit status 1 if anything failed.
finish() {
  if [[ $failures -ne 0 ]]; then
    echo "$failures failure(s)"
    exit 1
  fi
  echo "$1: all passed"
}
