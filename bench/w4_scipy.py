"""W4 with scipy.interpolate (shared/docs/performance.md): C² cubic
interpolation of n = 10^4 and 10^6 points in 3D, chord-length parameters.

The same data as bench/w4_interpolation.cpp (splitmix64 stream seeded
0x57344 + n, the same operations in the same order, so the same doubles): a
random walk with drift P_{i+1} = P_i + (0.1, 0.05, -0.02) + U, U uniform in
[-1,1)^3; the closed variant (periodic rows) is the walk minus its linear
trend, without its last point. Clamped rows take the end derivatives
(P_1 - P_0)/(t_1 - t_0) and (P_m - P_{m-1})/(t_m - t_{m-1}).

One timed fit = chord-length parameters + the scipy constructor:
make_interp_spline(t, P, k=3, bc_type=...) and CubicSpline(t, P, bc_type=...),
for natural, clamped, not-a-knot and periodic (closed chain with the first
point repeated, as scipy requires). Each repetition times enough fits to
last about 0.3 s and reports the time per fit; the rows run in a random order
within each of the repetitions.

Checks (every row, on the first and last 32 parameter intervals and every
(n/2000)-th): the curve reproduces the data points (data_error_rel); at the
interval midpoints it equals the other scipy constructor with the same end
condition, make_interp_spline (B-spline collocation) against CubicSpline
(a slope system), two independent code paths (mid_error_rel); and the end
condition itself holds (end_error_rel: S'' = 0 at the ends, S' = the given
tangents, S''' continuous at t_1 and t_{m-1}, S' and S'' equal at both ends
of a periodic curve; each relative to the largest value of that derivative
at the data parameters). Errors are relative to the scale (largest absolute
coordinate); above 1e-9 the row fails. Prints Google Benchmark's JSON shape
(real_time in ms per fit) to stdout or --out, for bench/run.sh.

Run with /usr/bin/python3 (Debian's numpy and scipy).
"""
import argparse
import math
import random
import re
import statistics
import sys
import time

import numpy as np
from scipy.interpolate import CubicSpline, make_interp_spline

from benchmark_json import write_benchmark_json
from seeded_data import splitmix_units

SIZES = (10_000, 1_000_000)
DRIFT = np.array([0.1, 0.05, -0.02])
END_INTERVALS = 32
SAMPLES = 2000
BOUND = 1e-9
MIN_SECONDS = 0.3
CONDITIONS = ("natural", "clamped", "not-a-knot", "periodic")


def make_case(n):
    units = splitmix_units(0x57344 + n, 3 * (n - 1)).reshape(n - 1, 3)
    points = np.zeros((n, 3))
    points[1:] = np.cumsum(DRIFT + (2 * units - 1), axis=0)
    w = (np.arange(n) / (n - 1))[:, None]
    bridge = points - w * (points[-1] - points[0])
    closed = bridge[:-1]
    chain = np.vstack([closed, closed[:1]])  # scipy's periodic input: last = first
    for set_ in (points, chain):
        if np.any(np.all(np.diff(set_, axis=0) == 0, axis=1)):
            raise SystemExit("consecutive points coincide")
    t = chord_parameters(points)
    start = (points[1] - points[0]) / (t[1] - t[0])
    end = (points[-1] - points[-2]) / (t[-1] - t[-2])
    scale = max(np.max(np.abs(points)), np.max(np.abs(closed)))
    return {"open": points, "chain": chain, "start": start, "end": end, "scale": scale}


def chord_parameters(points):
    d = np.diff(points, axis=0)
    t = np.empty(len(points))
    t[0] = 0.0
    np.cumsum(np.sqrt((d * d).sum(axis=1)), out=t[1:])
    t /= t[-1]
    return t


def fitter(kind, condition, case):
    """A function doing one whole fit, returning the curve (callable, derivative via nu / .derivative)."""
    points = case["chain"] if condition == "periodic" else case["open"]
    if kind == "make_interp_spline":
        bc = {"natural": "natural", "not-a-knot": None, "periodic": "periodic",
              "clamped": ([(1, case["start"])], [(1, case["end"])])}[condition]
        return lambda: make_interp_spline(chord_parameters(points), points, k=3, bc_type=bc)
    bc = {"natural": "natural", "not-a-knot": "not-a-knot", "periodic": "periodic",
          "clamped": ((1, case["start"]), (1, case["end"]))}[condition]
    return lambda: CubicSpline(chord_parameters(points), points, bc_type=bc)


def sampled_intervals(intervals):
    stride = max(1, intervals // SAMPLES)
    i = np.arange(intervals)
    return i[(i < END_INTERVALS) | (i + END_INTERVALS >= intervals) | (i % stride == 0)]


def check(curve, other, condition, case):
    points = case["chain"] if condition == "periodic" else case["open"]
    t = chord_parameters(points)
    scale = case["scale"]
    i = sampled_intervals(len(t) - 1)
    knots = np.unique(np.concatenate([i, i + 1]))
    data = float(np.max(np.abs(curve(t[knots]) - points[knots]))) / scale
    middle = 0.5 * (t[i] + t[i + 1])
    mid = float(np.max(np.abs(curve(middle) - other(middle)))) / scale

    def derivative(order, at):
        return curve(at, order) if not isinstance(curve, CubicSpline) else curve(at, nu=order)

    def relative(value, order):
        size = float(np.max(np.abs(derivative(order, t[knots]))))
        return float(np.max(np.abs(value))) / size

    ends = np.array([t[0], t[-1]])
    if condition == "natural":
        end = relative(derivative(2, ends), 2)
    elif condition == "clamped":
        d1 = derivative(1, ends)
        end = relative(np.concatenate([d1[0] - case["start"], d1[1] - case["end"]]), 1)
    elif condition == "not-a-knot":
        # The third derivative on both sides of t_1 and t_{m-1}: its value at
        # the middle of the neighbouring intervals (it is constant on each).
        at = np.array([0.5 * (t[0] + t[1]), 0.5 * (t[1] + t[2]), 0.5 * (t[-3] + t[-2]), 0.5 * (t[-2] + t[-1])])
        d3 = derivative(3, at)
        end = relative(np.concatenate([d3[0] - d3[1], d3[2] - d3[3]]), 3)
    else:
        end = max(relative(np.diff(derivative(order, ends), axis=0), order) for order in (1, 2))
    return data, mid, end


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--repetitions", type=int, default=3)
    parser.add_argument("--out", default="-")
    parser.add_argument("--filter", default="", help="a regex on the row names (as --benchmark_filter)")
    args = parser.parse_args()

    cases = {n: make_case(n) for n in SIZES}
    rows = []
    for n in SIZES:
        for kind in ("make_interp_spline", "CubicSpline"):
            for condition in CONDITIONS:
                name = f"W4/n{n}/scipy-{kind}-{condition}"
                if args.filter and not re.search(args.filter, name):
                    continue
                rows.append((name, n, kind, condition))

    times = {name: [] for name, *_ in rows}
    curves = {}
    order = random.Random(20261122)
    for repetition in range(args.repetitions):
        shuffled = rows[:]
        order.shuffle(shuffled)
        for name, n, kind, condition in shuffled:
            fit = fitter(kind, condition, cases[n])
            start, start_cpu = time.perf_counter(), time.process_time()
            curve = fit()
            seconds, cpu = time.perf_counter() - start, time.process_time() - start_cpu
            count = max(1, math.ceil(MIN_SECONDS / seconds)) if seconds < MIN_SECONDS else 1
            if count > 1:
                start, start_cpu = time.perf_counter(), time.process_time()
                for _ in range(count):
                    curve = fit()
                seconds = (time.perf_counter() - start) / count
                cpu = (time.process_time() - start_cpu) / count
            times[name].append((seconds, cpu, count))
            curves[name] = curve

    results = []
    failed = False
    for family, (name, n, kind, condition) in enumerate(rows):
        other_kind = "CubicSpline" if kind == "make_interp_spline" else "make_interp_spline"
        other = curves.get(f"W4/n{n}/scipy-{other_kind}-{condition}")
        if other is None:
            other = fitter(other_kind, condition, cases[n])()
        data, mid, end = check(curves[name], other, condition, cases[n])
        points = len(cases[n]["chain"]) - 1 if condition == "periodic" else n
        base = {"name": name + "/real_time", "run_name": name + "/real_time", "family_index": 1000 + family,
                "per_family_instance_index": 0, "repetitions": args.repetitions, "threads": 1,
                "time_unit": "ms", "data_error_rel": data, "mid_error_rel": mid, "end_error_rel": end,
                "points": points}
        worst = max(data, mid, end)
        if not worst <= BOUND:
            failed = True
            results.append(dict(base, run_type="iteration", repetition_index=0, error_occurred=True,
                                error_message=f"check failed: data {data:g}, midpoints {mid:g}, end {end:g}"))
            continue
        for index, (seconds, cpu, count) in enumerate(times[name]):
            results.append(dict(base, run_type="iteration", repetition_index=index, iterations=count,
                                real_time=seconds * 1e3, cpu_time=cpu * 1e3))
        median = statistics.median(seconds for seconds, _, _ in times[name])
        median_cpu = statistics.median(cpu for _, cpu, _ in times[name])
        results.append(dict(base, name=name + "/real_time_median", run_type="aggregate", aggregate_name="median",
                            iterations=args.repetitions, real_time=median * 1e3, cpu_time=median_cpu * 1e3))
    write_benchmark_json(results, args.out)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
