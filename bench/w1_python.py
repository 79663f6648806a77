"""W1 through the Python module: casteljau.points_at on numpy arrays.

The same data as bench/w1_w2_bspline.cpp and bench/w1_scipy.py (splitmix64
streams with the same seeds): a cubic B-spline in 3D, 1000 control points in
[0,100)^3, clamped uniform knots on [0,1], 10^6 parameters sorted and in
drawn order. Two rows per order:
  W1/<order>/casteljau-python        points_at(curve, us, out=buffer): into a
                                     preallocated array, as the C++ rows do;
  W1/<order>/casteljau-python-alloc  points_at(curve, us): a new array per call.
Issue 6 asks the first to reach 90 % of the C++ row W1/<order>/casteljau of the
same run, and to be 10x scipy's W1/<order>/scipy-BSpline (bench/w1_scipy.py).
Like Google Benchmark, each repetition runs the call for at least 0.5 s and
reports the mean time per call; the variants are interleaved in a seeded
random order per repetition.

Each row checks every 1000th point against w1_scipy.de_boor (an independent
de Boor written in numpy) and fails the run beyond 1e-9 of the scale.
The module is imported from CASTELJAU_PYTHONPATH (default build-bench/python).
Run with /usr/bin/python3.
"""
import os
import pathlib
import random
import re
import sys
import time

import numpy as np

from benchmark_json import benchmark_arguments, timed_rows, write_benchmark_json
from seeded_data import clamped_uniform_knots, splitmix_units
from w1_scipy import BOUND, CONTROL_POINTS, DEGREE, PARAMETERS, SCALE, de_boor

sys.path.insert(0, os.environ.get("CASTELJAU_PYTHONPATH",
                                  str(pathlib.Path(__file__).resolve().parents[1] / "build-bench" / "python")))
import casteljau  # noqa: E402

MINIMUM_SECONDS = 0.5


def seconds_per_call(call):
    """Mean wall time of `call` over at least MINIMUM_SECONDS (one warm-up call first)."""
    call()
    calls, start = 0, time.perf_counter()
    while True:
        call()
        calls += 1
        elapsed = time.perf_counter() - start
        if elapsed >= MINIMUM_SECONDS:
            return elapsed / calls


def main():
    args = benchmark_arguments()

    control = (SCALE * splitmix_units(20261122, CONTROL_POINTS * 3)).reshape(CONTROL_POINTS, 3)
    knots = clamped_uniform_knots(DEGREE, CONTROL_POINTS)
    random_order = splitmix_units(4242, PARAMETERS)
    orders = {"sorted": np.sort(random_order), "random": random_order}
    curve = casteljau.BSplineCurve(DEGREE, knots, control)
    buffer = np.empty((PARAMETERS, 3))

    variants = {}
    for order_name, us in orders.items():
        variants[f"W1/{order_name}/casteljau-python"] = (us, lambda us=us: casteljau.points_at(curve, us, out=buffer))
        variants[f"W1/{order_name}/casteljau-python-alloc"] = (us, lambda us=us: casteljau.points_at(curve, us))
    names = [name for name in variants if re.search(args.filter or ".", name)]  # a regex, as bench/run.sh passes

    times = {name: [] for name in names}
    shuffle = random.Random(6)
    for _ in range(args.repetitions):
        shuffle.shuffle(names)
        for name in names:
            times[name].append(seconds_per_call(variants[name][1]))

    rows, failed = [], False
    for name in sorted(times):
        us, call = variants[name]
        points = call()
        error = max(float(np.max(np.abs(points[i] - de_boor(knots, control, DEGREE, us[i])[0]))) / SCALE
                    for i in range(0, PARAMETERS, 1000))
        new_rows = timed_rows(name, times[name], PARAMETERS, error, BOUND, 1100)
        failed |= "error_occurred" in new_rows[0]
        rows += new_rows
    write_benchmark_json(rows, args.out, library="casteljau Python module")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
