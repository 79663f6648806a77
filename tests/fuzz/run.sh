#!/usr/bin/env bash
# run.sh FUZZER NAME SECONDS WORK [fresh|campaign]: runs one libFuzzer target for
# SECONDS on its seed corpus (tests/fuzz/corpus/NAME) and its dictionary
# (when it has one), growing the corpus in WORK/corpus/NAME (kept between
# runs: `make fuzz` continues where it stopped; `fresh`, as the smoke tests
# pass, empties it first so that every smoke run starts from the seeds alone;
# `campaign` keeps going past findings, in libFuzzer's fork mode, so that a
# long run uses all of its time and collects every finding instead of
# stopping at the first)
# and writing what crashes, hangs or leaks to WORK/findings/NAME/. Each input may take at most 10 s and 2 GB (a hang or
# an unbounded allocation is a finding, not a slow run). Prints libFuzzer's
# final statistics; exit status non-zero on a finding.
set -euo pipefail
fuzzer=$1 name=$2 seconds=$3 work=$4 fresh=${5:-}
here=$(cd "$(dirname "$0")" && pwd)
# A fresh (smoke) run is seeded: the same inputs on every machine, so that
# `make test` passes or fails for the code, never for the fuzzer's dice (CI
# once drew a new slow input in its 4 s); `make fuzz` explores at random.
seed=()
mode=()
if [ "$fresh" = fresh ]; then rm -rf "$work/corpus/$name"; seed=(-seed=1); fi
if [ "$fresh" = campaign ]; then mode=(-fork=1 -ignore_timeouts=1 -ignore_ooms=1 -ignore_crashes=1); fi
mkdir -p "$work/corpus/$name" "$work/findings/$name"
options=("${seed[@]}" "${mode[@]}" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -malloc_limit_mb=2048 -print_final_stats=1
         -artifact_prefix="$work/findings/$name/")
if [ -f "$here/dictionaries/$name.dict" ]; then options+=(-dict="$here/dictionaries/$name.dict"); fi
exec "$fuzzer" "${options[@]}" "$work/corpus/$name" "$here/corpus/$name"
