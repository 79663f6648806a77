"""W1 and W2 with scipy.interpolate.BSpline (shared/docs/performance.md).

The same data as bench/w1_w2_bspline.cpp (splitmix64 streams with the same
seeds): a cubic B-spline in 3D, 1000 control points in [0,100)^3, clamped
uniform knots on [0,1], 10^6 parameters sorted and in drawn order. W1 calls
spl(x), W2 spl(x) and spl(x, 1); scipy allocates its outputs (its public API
has no output argument), which these rows include.

Each row checks its result on every 1000th parameter against a plain de Boor
evaluation written here (The NURBS Book A3.1 via de Boor's algorithm, and the
derivative from the control points' differences) and fails if a coordinate
differs by more than 1e-9 of the scale. Prints Google Benchmark's JSON
(name, run_name, run_type, real_time in ms, items_per_second, aggregates) to
stdout or to --out, so bench/run.sh summarizes it like the C++ rows.

Run with /usr/bin/python3 (Debian's numpy and scipy).
"""
import sys
import time

import numpy as np
from scipy.interpolate import BSpline

from benchmark_json import benchmark_arguments, timed_rows, write_benchmark_json
from seeded_data import splitmix_units, clamped_uniform_knots

DEGREE = 3
CONTROL_POINTS = 1000
PARAMETERS = 1_000_000
SCALE = 100.0
BOUND = 1e-9


def de_boor(t, c, p, u):
    """Point and first derivative at u by de Boor's algorithm (independent reference)."""
    n = len(c) - 1
    k = min(max(np.searchsorted(t, u, side="right") - 1, p), n)
    d = [c[j + k - p].copy() for j in range(p + 1)]
    for r in range(1, p + 1):
        if r == p:
            slope = p * (d[p] - d[p - 1]) / (t[k + 1] - t[k])
        for j in range(p, r - 1, -1):
            a = (u - t[j + k - p]) / (t[j + 1 + k - r] - t[j + k - p])
            d[j] = (1.0 - a) * d[j - 1] + a * d[j]
    return d[p], slope


def main():
    args = benchmark_arguments()

    control = (SCALE * splitmix_units(20261122, CONTROL_POINTS * 3)).reshape(CONTROL_POINTS, 3)
    knots = clamped_uniform_knots(DEGREE, CONTROL_POINTS)
    random_order = splitmix_units(4242, PARAMETERS)
    sorted_order = np.sort(random_order)
    spline = BSpline(knots, control, DEGREE)

    rows = []
    failed = False
    for workload in ("W1", "W2"):
        for order_name, us in (("sorted", sorted_order), ("random", random_order)):
            name = f"{workload}/{order_name}/scipy-BSpline"
            if args.filter and args.filter not in name and args.filter != ".":
                continue
            times = []
            for repetition in range(args.repetitions):
                start = time.perf_counter()
                points = spline(us)
                derivatives = spline(us, 1) if workload == "W2" else None
                times.append(time.perf_counter() - start)
            # Check every 1000th parameter against de Boor.
            error = 0.0
            derivative_scale = 0.0
            samples = []
            for i in range(0, PARAMETERS, 1000):
                point, slope = de_boor(knots, control, DEGREE, us[i])
                samples.append((i, point, slope))
                derivative_scale = max(derivative_scale, float(np.max(np.abs(slope))))
            for i, point, slope in samples:
                error = max(error, float(np.max(np.abs(points[i] - point))) / SCALE)
                if derivatives is not None:
                    error = max(error, float(np.max(np.abs(derivatives[i] - slope))) / derivative_scale)
            new_rows = timed_rows(name, times, PARAMETERS, error, BOUND, 1000)
            failed |= "error_occurred" in new_rows[0]
            rows += new_rows
    write_benchmark_json(rows, args.out)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
