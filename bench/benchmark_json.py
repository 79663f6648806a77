"""Writing the scipy rows of the benchmarks in Google Benchmark's JSON shape,
so that bench/run.sh summarizes them with the C++ rows. Shared by
w1_scipy.py and w4_scipy.py (run as scripts: their folder is on sys.path)."""

import json
import sys


def write_benchmark_json(rows, out):
    """Writes {"context", "benchmarks": rows} to the file `out`, or to standard output for "-"."""
    document = {"context": {"library": "scipy", "executable": sys.argv[0]}, "benchmarks": rows}
    text = json.dumps(document, indent=1)
    if out == "-":
        print(text)
    else:
        with open(out, "w") as f:
            f.write(text)
