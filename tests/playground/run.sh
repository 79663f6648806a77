#!/usr/bin/env bash
# run.sh PAGE_DIR CLI EXAMPLES: the playground (build-wasm/playground/) in
# Debian's Chromium, driven by npm's playwright-core (tests/playground/
# node_modules; make deps installs both), compared with the CLI of the
# default tree. Without chromium, playwright-core or the CLI the test is
# skipped (exit 77), except in CI, where it fails.
# CASTELJAU_PLAYGROUND_SHOTS=DIR also writes a screenshot of each view there.
set -euo pipefail
page=$1 cli=$2 examples=$3
here=$(cd "$(dirname "$0")" && pwd)
for needed in /usr/bin/chromium "$here/node_modules/playwright-core" "$cli" "$page/index.html"; do
  if [ ! -e "$needed" ]; then
    echo "playground: $needed is missing (make deps installs chromium and playwright-core, make build the CLI)"
    [ "${CI:-}" = true ] && exit 1
    exit 77
  fi
done
node "$here/page_test.mjs" "$page" "$cli" "$examples" ${CASTELJAU_PLAYGROUND_SHOTS:+"$CASTELJAU_PLAYGROUND_SHOTS"}
