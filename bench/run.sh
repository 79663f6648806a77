#!/usr/bin/env bash
# Runs every benchmark binary built in build-bench/bench/ (the hardware probe
# w0 first, then W1..W6, whichever exist), each pinned to one core, 3
# repetitions in random interleaving, and writes Google Benchmark's JSON to
# out/bench/<name>.json (console output to out/bench/<name>.txt). W1 and W5
# run a second time unpinned with CASTELJAU_BENCH_ALL_CORES=1 for their
# all-core rows (<name>-all-cores.json). Prints one line per row: median
# throughput, min-max over the repetitions, and the accuracy counters the row
# reports. Finally bench/report.py merges every file into
# out/bench/results.json and writes out/bench/RESULTS.md.
# Exits non-zero if a binary fails or a row reported an error (a benchmark
# whose output check failed calls SkipWithError).
#
# W1/W2 rows of scipy come from bench/w1_scipy.py, the Python module's W1 rows
# from bench/w1_python.py, W4 rows from
# bench/w4_scipy.py and the W5 row from bench/w5_scipy.py (run by
# /usr/bin/python3, pinned the same way) when Debian's scipy is installed.
#
# Environment: CASTELJAU_BENCH_DIR (default build-bench/bench),
# CASTELJAU_BENCH_CPU (default 0), CASTELJAU_BENCH_OUT (default out/bench),
# CASTELJAU_BENCH_FILTER (a --benchmark_filter regex, default all),
# CASTELJAU_BENCH_BUILD_SECONDS (how long `make bench` spent building, for RESULTS.md).
set -euo pipefail
cd "$(dirname "$0")/.."

bench_dir="${CASTELJAU_BENCH_DIR:-build-bench/bench}"
cpu="${CASTELJAU_BENCH_CPU:-0}"
out_dir="${CASTELJAU_BENCH_OUT:-out/bench}"
filter="${CASTELJAU_BENCH_FILTER:-.}"
mkdir -p "$out_dir"
# W10 writes its generated drawings here, for the Python peers to read.
export CASTELJAU_BENCH_DATA="${CASTELJAU_BENCH_DATA:-$out_dir/w10}"

pin=()
if command -v taskset >/dev/null 2>&1; then pin=(taskset -c "$cpu"); fi

binaries=()
for candidate in "$bench_dir"/w*; do
  [[ -f "$candidate" && -x "$candidate" ]] && binaries+=("$candidate")
done
if [[ ${#binaries[@]} -eq 0 ]]; then
  echo "run.sh: no benchmark binaries in $bench_dir (build the bench preset first)" >&2
  exit 1
fi

started=$(date +%s)
load_at_start="$(cut -d" " -f1-3 /proc/loadavg)"
echo "started: $(date -u '+%Y-%m-%d %H:%M UTC')"
echo "machine: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ *//'), $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg)"
# Prints one line per row of a Google Benchmark JSON file; fails if a row
# reported an error.
summarize() {
  /usr/bin/python3 - "$1" <<'EOF'
import json, sys
from collections import OrderedDict

data = json.load(open(sys.argv[1]))
rows = OrderedDict()
failed = False
for b in data["benchmarks"]:
    name = b.get("run_name", b["name"]).removesuffix("/real_time")
    row = rows.setdefault(name, {"reps": [], "median": None, "error": None,
                                 "order": (b.get("family_index", 0), b.get("per_family_instance_index", 0))})
    if b.get("error_occurred"):
        row["error"] = b.get("error_message", "error")
        failed = True
    elif b.get("run_type") == "aggregate":
        if b.get("aggregate_name") == "median":
            row["median"] = b
    else:
        row["reps"].append(b)

def rate(b):
    if "items_per_second" in b:
        return "%9.1f M/s" % (b["items_per_second"] / 1e6)
    return "%9.3f %s" % (b["real_time"], b.get("time_unit", "ns"))

skip = {"name", "run_name", "run_type", "repetitions", "repetition_index", "threads", "iterations",
        "real_time", "cpu_time", "time_unit", "items_per_second", "bytes_per_second", "family_index",
        "per_family_instance_index", "aggregate_name", "aggregate_unit", "error_occurred", "error_message"}
width = max((len(n) for n in rows), default=10)
for name, row in sorted(rows.items(), key=lambda item: item[1]["order"]):
    if row["error"]:
        print("   %-*s  FAILED: %s" % (width, name, row["error"]))
        continue
    med = row["median"] or (row["reps"][0] if row["reps"] else None)
    if med is None:
        continue
    spread = ""
    values = [r["items_per_second"] / 1e6 for r in row["reps"] if "items_per_second" in r]
    if len(values) > 1:
        spread = " [%.1f-%.1f]" % (min(values), max(values))
    elif "items_per_second" not in med and len(row["reps"]) > 1:  # time per fit (W4)
        times = [r["real_time"] for r in row["reps"]]
        spread = " [%.3f-%.3f]" % (min(times), max(times))
    counters = " ".join("%s=%.3g" % (k, v) for k, v in med.items()
                        if k not in skip and isinstance(v, (int, float)))
    print("   %-*s %s%s %s" % (width, name, rate(med), spread, counters))
sys.exit(1 if failed else 0)
EOF
}

# run_binary BINARY JSON [COMMAND PREFIX...]: one Google Benchmark binary.
run_binary() {
  local binary="$1" json="$2"
  shift 2
  local name
  name="$(basename "$json" .json)"
  echo "== $(basename "$binary") -> $json"
  if ! "$@" "$binary" \
      --benchmark_filter="$filter" \
      --benchmark_repetitions=3 --benchmark_min_time=0.25 \
      --benchmark_enable_random_interleaving=true \
      --benchmark_report_aggregates_only=false \
      --benchmark_out="$json" --benchmark_out_format=json \
      >"$out_dir/$name.txt" 2>&1; then
    echo "   $name failed (see $out_dir/$name.txt)"
    status=1
    return
  fi
  if [[ ! -s "$json" ]]; then
    echo "   (no row of $name matches the filter '$filter')"
    return
  fi
  summarize "$json" || status=1
}

rm -f "$out_dir"/*.json "$out_dir"/*.txt "$out_dir/RESULTS.md"
status=0
for binary in "${binaries[@]}"; do
  name="$(basename "$binary")"
  run_binary "$binary" "$out_dir/$name.json" "${pin[@]}"
  case "$name" in
    w1_w2_bspline | w5_surface)
      run_binary "$binary" "$out_dir/$name-all-cores.json" env CASTELJAU_BENCH_ALL_CORES=1 ;;
  esac
done

# The rows measured from Python (bench/w<k>_scipy.py, bench/w1_python.py),
# when Debian's scipy is there and the filter matches one of the script's row
# names: run_python_rows SCRIPT "ROW NAMES" [extra arguments]. W1/W2: scipy's
# BSpline and casteljau's Python module; W4: make_interp_spline and
# CubicSpline; W5: bisplev on the same knots and coefficients.
run_python_rows() {
  local script="$1" rows="$2"
  shift 2
  [[ "$rows" =~ $filter ]] || return 0
  /usr/bin/python3 -c "import scipy" >/dev/null 2>&1 || return 0
  local json="$out_dir/${script%.py}.json"
  echo "== $script -> $json"
  if "${pin[@]}" /usr/bin/python3 "bench/$script" --repetitions 3 --out "$json" "$@" \
      >"$out_dir/${script%.py}.txt" 2>&1; then
    summarize "$json" || status=1
  else
    echo "   $script failed (see $out_dir/${script%.py}.txt)"
    summarize "$json" || true
    status=1
  fi
}
run_python_rows w1_scipy.py "W1/sorted/scipy-BSpline W1/random/scipy-BSpline W2/sorted/scipy-BSpline"
if [[ -d "${CASTELJAU_PYTHONPATH:-build-bench/python}/casteljau" ]]; then
  run_python_rows w1_python.py "W1/sorted/casteljau-python W1/random/casteljau-python-alloc" --filter "$filter"
fi
run_python_rows w4_scipy.py "W4/n10000/scipy-make_interp_spline-natural W4/n1000000/scipy-CubicSpline-periodic" \
  --filter "$filter"
run_python_rows w5_scipy.py "W5/grid/scipy-bisplev"
# W10: python3-svgelements and ezdxf read the files w10_drawing_readers wrote.
run_python_rows w10_readers.py "W10/svg-10MB/svgelements-SVG.parse W10/dxf-10MB/ezdxf-readfile" \
  --filter "$filter" --data "$CASTELJAU_BENCH_DATA"

seconds=$(( $(date +%s) - started ))
echo "== report -> $out_dir/results.json, $out_dir/RESULTS.md ($seconds s of benchmarks)"
/usr/bin/python3 bench/report.py collect --dir "$out_dir" --seconds "$seconds" \
  --build "$(dirname "$bench_dir")" --cpu "$cpu" --load "$load_at_start" \
  --build-seconds "${CASTELJAU_BENCH_BUILD_SECONDS:-}" || status=1
exit $status
