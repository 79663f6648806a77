"""casteljau's B-spline fitting against scipy and dense numpy references, through the CLI.

- Least squares, free ends: ``casteljau fit --control-points N --free-ends`` must give
  the control points of ``scipy.interpolate.make_lsq_spline(t, P, knots, k)`` on the
  knots it wrote (The NURBS Book eq. 9.68-9.69) and the parameters it used (x with
  ``--function``; chord-length parameters recomputed here for parametric curves).
- Least squares, interpolated ends (the default): the constrained problem solved
  densely with numpy (``numpy.linalg.lstsq`` on scipy's design matrix), an
  independent reference since scipy has no end constraints.
- Smoothing with a given lambda: ``scipy.interpolate.make_smoothing_spline(x, y,
  lam=lambda)`` (scipy 1.10, Woltring's algorithm in the natural-spline basis) for a
  function y(x) with ``--function --free-ends --degree 3``: same knots, same control
  points.
- Smoothing with lambda chosen by GCV: scipy's own GCV choice (its Brent search over
  [0, n]) is recorded by wrapping its private helper; our lambda must minimize the
  GCV score, computed here densely from the hat matrix, at least as well as
  scipy's: the same lambda to 1e-6, or a lower score (20 seeded samples and the
  data of scipy's gcvspl test). Our reported GCV score and effective degrees of
  freedom must equal the dense ones.

Tolerances are relative to the data's scale. Data are seeded. Run with
/usr/bin/python3 -m pytest; the CLI comes from CASTELJAU_CLI (ctest sets it), else
build/casteljau.
"""

import json
import re
import subprocess

import numpy as np
import pytest
from scipy.interpolate import BSpline, make_lsq_spline, make_smoothing_spline
from scipy.interpolate import _bsplines

from cli_support import casteljau_cli



def write_points(path, points):
    with open(path, "w", encoding="utf-8") as out:
        for row in points:
            out.write(",".join(repr(float(v)) for v in row) + "\n")


SUMMARY = re.compile(
    r"^fit: (\d+) control points, max error (\S+) at point (\d+), rms error (\S+), "
    r"lambda (\S+?)( \(gcv\))?, gcv (\S+), effective degrees of freedom (\S+)$"
)


def run_fit(tmp_path, points, *options):
    """Runs `casteljau fit` on the points; returns (model dict, summary dict)."""
    source = tmp_path / "points.csv"
    target = tmp_path / "fit.json"
    write_points(source, points)
    result = subprocess.run(
        [casteljau_cli(), "fit", str(source), *options, "-o", str(target)],
        capture_output=True, text=True, check=False,
    )
    assert result.returncode == 0, result.stderr
    assert result.stderr == ""
    match = SUMMARY.match(result.stdout.strip())
    assert match, f"unexpected summary line: {result.stdout!r}"
    summary = {
        "control_points": int(match.group(1)),
        "max_error": float(match.group(2)),
        "rms_error": float(match.group(4)),
        "lambda": float(match.group(5)),
        "from_gcv": match.group(6) is not None,
        "gcv": float(match.group(7)),
        "edf": float(match.group(8)),
    }
    with open(target, encoding="utf-8") as model_file:
        model = json.load(model_file)
    assert model["type"] == "bspline"
    return model, summary


def chord_parameters(points):
    steps = np.linalg.norm(np.diff(points, axis=0), axis=1)
    t = np.concatenate([[0.0], np.cumsum(steps)])
    return t / t[-1]


def noisy_function(seed, count, noise):
    rng = np.random.default_rng(seed)
    x = np.sort(rng.uniform(-2.0, 3.0, count))
    y = x**3 / 4 + x**2 * np.sin(3 * x) + rng.normal(0.0, noise, count)
    return x, y


def noisy_curve(seed, count, dimension):
    rng = np.random.default_rng(seed)
    s = np.linspace(0.0, 2 * np.pi, count)
    columns = [3 * np.cos(s) + 0.5 * np.cos(5 * s), 2 * np.sin(s), 0.3 * s][:dimension]
    return np.stack(columns, axis=1) + rng.normal(0.0, 0.05, (count, dimension))


def penalty_matrix(knots, degree):
    """Omega_jk = integral of N_j'' N_k'' over the domain, by 8-point Gauss-Legendre per span
    (exact for the degrees used here) with scipy's BSpline derivatives."""
    count = len(knots) - degree - 1
    nodes, weights = np.polynomial.legendre.leggauss(8)
    omega = np.zeros((count, count))
    second = [BSpline(knots, np.eye(count)[j], degree).derivative(2) for j in range(count)]
    for a, b in zip(knots[:-1], knots[1:]):
        if b <= a:
            continue
        u = (a + b) / 2 + (b - a) / 2 * nodes
        values = np.array([f(u) for f in second])
        omega += (values * ((b - a) / 2 * weights)) @ values.T
    return omega


def dense_gcv(x, y, knots, degree, lam):
    """(GCV score, trace of the hat matrix) for the smoothing fit at lambda, densely."""
    design = BSpline.design_matrix(x, knots, degree).toarray()
    omega = penalty_matrix(knots, degree)
    hat = design @ np.linalg.solve(design.T @ design + lam * omega, design.T)
    residual = y - hat @ y
    n = len(x)
    trace = np.trace(hat)
    return float(residual @ residual / n / (1 - trace / n) ** 2), float(trace)


# --- least squares -----------------------------------------------------------------


@pytest.mark.parametrize("degree", [1, 2, 3, 5])
@pytest.mark.parametrize("control_points", [6, 11, 25])
def test_least_squares_function_equals_make_lsq_spline(tmp_path, degree, control_points):
    x, y = noisy_function(10 * degree + control_points, 40, 0.3)
    model, summary = run_fit(tmp_path, np.stack([x, y], axis=1), "--function", "--free-ends",
                             "--degree", str(degree), "--control-points", str(control_points))
    knots = np.array(model["knots"])
    ours = np.array(model["control_points"])
    assert model["degree"] == degree and len(ours) == control_points == summary["control_points"]
    reference = make_lsq_spline(x, y, knots, k=degree)
    scale = np.max(np.abs(y))
    assert np.max(np.abs(ours[:, 1] - reference.c)) <= 1e-10 * scale
    # x(t) = t is reproduced exactly by least squares (degree >= 1 contains lines).
    assert np.max(np.abs(BSpline(knots, ours[:, 0], degree)(x) - x)) <= 1e-12 * np.max(np.abs(x))
    residuals = np.abs(reference(x) - y)
    assert abs(summary["max_error"] - residuals.max()) <= 1e-5 * residuals.max()
    assert abs(summary["rms_error"] - np.sqrt(np.mean(residuals**2))) <= 1e-5 * summary["rms_error"]


@pytest.mark.parametrize("dimension", [2, 3])
def test_least_squares_curve_equals_make_lsq_spline(tmp_path, dimension):
    points = noisy_curve(dimension, 60, dimension)
    model, _ = run_fit(tmp_path, points, "--param", "chord", "--free-ends", "--degree", "3",
                       "--control-points", "14")
    knots = np.array(model["knots"])
    t = chord_parameters(points)
    reference = make_lsq_spline(t, points, knots, k=3)
    scale = np.max(np.abs(points))
    assert np.max(np.abs(np.array(model["control_points"]) - reference.c)) <= 1e-10 * scale


@pytest.mark.parametrize("degree", [2, 3, 4])
def test_least_squares_with_interpolated_ends(tmp_path, degree):
    """Q_0 = P_0, Q_n = P_m and the interior control points minimizing the squared
    distances of the other points: a dense reference by numpy.linalg.lstsq."""
    points = noisy_curve(7 + degree, 50, 2)
    model, summary = run_fit(tmp_path, points, "--param", "chord", "--degree", str(degree),
                             "--control-points", "12")
    knots = np.array(model["knots"])
    ours = np.array(model["control_points"])
    t = chord_parameters(points)
    design = BSpline.design_matrix(t, knots, degree).toarray()
    target = points[1:-1] - np.outer(design[1:-1, 0], points[0]) - np.outer(design[1:-1, -1], points[-1])
    interior, *_ = np.linalg.lstsq(design[1:-1, 1:-1], target, rcond=None)
    reference = np.vstack([points[0], interior, points[-1]])
    scale = np.max(np.abs(points))
    assert np.max(np.abs(ours - reference)) <= 1e-10 * scale
    assert np.array_equal(ours[0], points[0]) and np.array_equal(ours[-1], points[-1])
    assert summary["max_error"] == pytest.approx(np.max(np.linalg.norm(design @ reference - points, axis=1)),
                                                 rel=1e-5)


# --- smoothing -----------------------------------------------------------------------


@pytest.mark.parametrize("lam", [1e-4, 0.01, 0.5, 20.0])
def test_smoothing_equals_make_smoothing_spline(tmp_path, lam):
    x, y = noisy_function(3, 45, 0.5)
    model, summary = run_fit(tmp_path, np.stack([x, y], axis=1), "--function", "--free-ends",
                             "--degree", "3", "--smoothing", repr(lam))
    reference = make_smoothing_spline(x, y, lam=lam)
    knots = np.array(model["knots"])
    assert np.array_equal(knots, reference.t)
    ours = np.array(model["control_points"])
    scale = np.max(np.abs(y))
    assert np.max(np.abs(ours[:, 1] - reference.c)) <= 1e-8 * scale
    assert summary["lambda"] == lam and not summary["from_gcv"]
    gcv, trace = dense_gcv(x, y, knots, 3, lam)
    assert summary["gcv"] == pytest.approx(gcv, rel=1e-5)
    assert summary["edf"] == pytest.approx(trace, rel=1e-5)


def scipy_gcv_lambda(x, y):
    """make_smoothing_spline(x, y) and the lambda its GCV search chose (recorded by
    wrapping scipy's private helper, which returns it)."""
    chosen = []
    original = _bsplines._compute_optimal_gcv_parameter

    def recording(*args):
        chosen.append(original(*args))
        return chosen[-1]

    _bsplines._compute_optimal_gcv_parameter = recording
    try:
        spline = make_smoothing_spline(x, y)
    finally:
        _bsplines._compute_optimal_gcv_parameter = original
    return spline, chosen[0]


def gcvspl_data():
    """The data of scipy's TestSmoothingSpline.test_compare_with_GCVSPL, made as its
    docstring says (100 points of sin x + noise of 0.5 on [-2, 2], legacy seed 1234):
    smooth at the scale of the spacing, so that the GCV minimum (lambda 0.39) lies
    ten million times above lambda_0 = tr(B^T B) / tr(Omega), beyond the range
    casteljau's grid first searches (issue 43)."""
    state = np.random.RandomState(1234)
    x = np.sort(state.random_sample(100) * 4 - 2)
    y = np.sin(x) + state.normal(scale=0.5, size=100)
    return x, y


# Twenty data sets of every kind (issue 43 asks for twenty), and scipy's gcvspl case.
GCV_CASES = [(seed, 40 + 13 * seed, [0.05, 0.2, 0.5, 1.5][seed % 4]) for seed in range(1, 21)]


@pytest.mark.parametrize("seed,count,noise", GCV_CASES + [("gcvspl", 100, 0.5)])
def test_gcv_choice_agrees_with_make_smoothing_spline(tmp_path, seed, count, noise):
    x, y = gcvspl_data() if seed == "gcvspl" else noisy_function(seed, count, noise)
    model, summary = run_fit(tmp_path, np.stack([x, y], axis=1), "--function", "--free-ends",
                             "--degree", "3", "--smoothing", "gcv")
    assert summary["from_gcv"]
    spline, scipy_lambda = scipy_gcv_lambda(x, y)
    ours = summary["lambda"]
    knots = np.array(model["knots"])
    our_gcv, our_trace = dense_gcv(x, y, knots, 3, ours)
    scipy_gcv, _ = dense_gcv(x, y, knots, 3, scipy_lambda)
    print(f"seed {seed}: lambda ours {ours:.9g} scipy {scipy_lambda:.9g}, "
          f"GCV ours {our_gcv:.12g} scipy {scipy_gcv:.12g}, edf {our_trace:.6g}")
    # Both minimize the same function; ours at least as well (up to rounding),
    # at the same minimum (1e-6 relative) or a lower score.
    assert our_gcv <= scipy_gcv * (1 + 1e-9)
    assert ours == pytest.approx(scipy_lambda, rel=1e-6) or our_gcv < scipy_gcv * (1 - 1e-12)
    assert summary["gcv"] == pytest.approx(our_gcv, rel=1e-5)
    assert summary["edf"] == pytest.approx(our_trace, rel=1e-5)
    # The curves agree as closely as the two lambdas do.
    scale = np.max(np.abs(y))
    assert np.max(np.abs(np.array(model["control_points"])[:, 1] - spline.c)) <= 1e-2 * scale
