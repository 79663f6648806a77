"""W5 with scipy.interpolate.bisplev (shared/docs/performance.md).

The same data as bench/w5_surface.cpp (a splitmix64 stream with the same
seed, drawn in the same order): a bicubic B-spline surface with the 100 x 100
control net P_ij = (i, j, 10 r), clamped uniform knots on [0,1] in both
directions, evaluated on the 1000 x 1000 grid u_a = a/999, v_b = b/999.
bisplev evaluates one scalar tensor-product spline on a grid, so one
iteration is three calls (x, y and z coefficients, tck = [tu, tv, c, 3, 3]
with c the net's coordinate row by row); scipy allocates its outputs (no
output argument), which the row includes.

The row checks every 997th grid point against a tensor-product evaluation by
another scipy code path (scipy.interpolate.BSpline along u on the whole net,
then along v on the resulting row) and fails if a coordinate differs by more
than 1e-9 of the scale (99). Prints Google Benchmark's JSON to stdout or to
--out, so bench/run.sh summarizes it like the C++ rows.

Run with /usr/bin/python3 (Debian's numpy and scipy).
"""
import statistics
import sys
import time

import numpy as np
from scipy.interpolate import BSpline, bisplev

from benchmark_json import benchmark_arguments, write_benchmark_json
from seeded_data import splitmix_units, clamped_uniform_knots

DEGREE = 3
NET = 100
GRID = 1000
CHECK_STRIDE = 997
SCALE = 99.0
BOUND = 1e-9
NAME = "W5/grid/scipy-bisplev"


def main():
    args = benchmark_arguments()

    net = np.zeros((NET, NET, 3))
    net[:, :, 0] = np.arange(NET)[:, None]
    net[:, :, 1] = np.arange(NET)[None, :]
    net[:, :, 2] = 10.0 * splitmix_units(20261122, NET * NET).reshape(NET, NET)
    knots = clamped_uniform_knots(DEGREE, NET)
    ts = np.arange(GRID) / (GRID - 1)
    tcks = [[knots, knots, net[:, :, c].ravel(), DEGREE, DEGREE] for c in range(3)]

    times = []
    for _ in range(args.repetitions):
        start, start_cpu = time.perf_counter(), time.process_time()
        coordinates = [bisplev(ts, ts, tck) for tck in tcks]
        times.append((time.perf_counter() - start, time.process_time() - start_cpu))
    points = np.stack(coordinates, axis=-1).reshape(GRID * GRID, 3)

    # The check: BSpline along u on the whole net (values are rows of 100 x 3), then along v.
    along_u = BSpline(knots, net, DEGREE)
    error = 0.0
    for k in range(0, GRID * GRID, CHECK_STRIDE):
        row = along_u(ts[k // GRID])
        point = BSpline(knots, row, DEGREE)(ts[k % GRID])
        error = max(error, float(np.max(np.abs(points[k] - point))) / SCALE)

    base = {"name": NAME + "/real_time", "run_name": NAME + "/real_time", "family_index": 1000,
            "per_family_instance_index": 0, "repetitions": args.repetitions, "threads": 1,
            "time_unit": "ms", "max_error_rel": error}
    rows = []
    failed = not error <= BOUND
    if failed:
        rows.append(dict(base, run_type="iteration", repetition_index=0, error_occurred=True,
                         error_message=f"relative error {error:g} exceeds the bound"))
    else:
        for index, (seconds, cpu) in enumerate(times):
            rows.append(dict(base, run_type="iteration", repetition_index=index, iterations=1,
                             real_time=seconds * 1e3, cpu_time=cpu * 1e3, items_per_second=GRID * GRID / seconds))
        median = statistics.median(seconds for seconds, _ in times)
        median_cpu = statistics.median(cpu for _, cpu in times)
        rows.append(dict(base, name=NAME + "/real_time_median", run_type="aggregate", aggregate_name="median",
                         iterations=args.repetitions, real_time=median * 1e3, cpu_time=median_cpu * 1e3,
                         items_per_second=GRID * GRID / median))
    write_benchmark_json(rows, args.out)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
