#!/usr/bin/env bash
# run.sh CHECKER: Chromium reads the corpus (chromium_paths.mjs), then the
# checker compares its reading with casteljau's. Needs Debian's chromium and
# npm's playwright-core in tests/svg/node_modules (make deps installs both);
# without them the test is skipped (exit 77), except in CI, where it fails.
set -euo pipefail
checker=$1
here=$(cd "$(dirname "$0")" && pwd)
if [ ! -x /usr/bin/chromium ] || [ ! -d "$here/node_modules/playwright-core" ]; then
  echo "svg: Debian's chromium or npm's playwright-core is missing (make deps installs them)"
  [ "${CI:-}" = true ] && exit 1
  exit 77
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
node "$here/chromium_paths.mjs" "$here/path_corpus.txt" "$work/chromium.json"
"$checker" "$here/path_corpus.txt" "$work/chromium.json"
