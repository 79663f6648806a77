"""Writing the scipy rows of the benchmarks in Google Benchmark's JSON shape,
so that bench/run.sh summarizes them with the C++ rows. Shared by
w1_scipy.py, w1_python.py and w4_scipy.py (run as scripts: their folder is on sys.path)."""

import argparse
import json
import statistics
import sys


def write_benchmark_json(rows, out, library="scipy"):
    """Writes {"context", "benchmarks": rows} to the file `out`, or to standard output for "-"."""
    document = {"context": {"library": library, "executable": sys.argv[0]}, "benchmarks": rows}
    text = json.dumps(document, indent=1)
    if out == "-":
        print(text)
    else:
        with open(out, "w") as f:
            f.write(text)


def timed_rows(name, times, items, error, bound, family_index, counter="max_error_rel"):
    """The rows of one benchmark in Google Benchmark's shape: one per repetition
    (`times` in seconds per batch of `items`) and their median, or a single
    error row when `error` (the row's measured deviation from its reference)
    is not within `bound`, so that a fast wrong answer fails the run."""
    base = {"name": name + "/real_time", "run_name": name + "/real_time", "family_index": family_index,
            "per_family_instance_index": 0, "repetitions": len(times), "threads": 1,
            "time_unit": "ms", counter: error}
    if not error <= bound:
        return [dict(base, run_type="iteration", repetition_index=0, error_occurred=True,
                     error_message=f"relative error {error:g} exceeds the bound {bound:g}")]
    rows = [dict(base, run_type="iteration", repetition_index=index, iterations=1,
                 real_time=seconds * 1e3, cpu_time=seconds * 1e3, items_per_second=items / seconds)
            for index, seconds in enumerate(times)]
    median = statistics.median(times)
    rows.append(dict(base, name=name + "/real_time_median", run_type="aggregate", aggregate_name="median",
                     iterations=len(times), real_time=median * 1e3, cpu_time=median * 1e3,
                     items_per_second=items / median))
    return rows


def benchmark_arguments():
    """The options every Python bench script takes, as bench/run.sh passes them:
    --repetitions N, --out FILE ("-": standard output), --filter TEXT."""
    parser = argparse.ArgumentParser()
    parser.add_argument("--repetitions", type=int, default=3)
    parser.add_argument("--out", default="-")
    parser.add_argument("--filter", default="")
    return parser.parse_args()
