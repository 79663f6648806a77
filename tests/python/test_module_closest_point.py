"""Closest points from Python against an independent reference: the nearest
point of an ellipse found by scipy.optimize.minimize_scalar on the ellipse's
own angle parameterization (a cos s, b sin s), started from the best of 720
samples; the batch against single queries; local minima from inside the
ellipse (the two ends of the minor axis); every curve kind; the errors."""
import math

import numpy as np
import pytest
import scipy.optimize

import casteljau as cj


def scipy_ellipse_distance(a, b, q):
    s = np.linspace(0, 2 * math.pi, 721)
    d = np.hypot(a * np.cos(s) - q[0], b * np.sin(s) - q[1])
    k = int(np.argmin(d))
    step = 2 * math.pi / 720
    result = scipy.optimize.minimize_scalar(
        lambda t: math.hypot(a * math.cos(t) - q[0], b * math.sin(t) - q[1]),
        bounds=(s[k] - step, s[k] + step), method="bounded", options={"xatol": 1e-13})
    return min(result.fun, d[k])


def test_ellipse_against_scipy():
    a, b = 3.0, 1.0
    ellipse = cj.make_ellipse((0.0, 0.0), a, b)
    rng = np.random.default_rng(20261202)
    queries = rng.uniform(-5, 5, size=(2000, 2))
    parameters, distances = cj.closest_points(ellipse, queries)
    worst = 0.0
    for q, t, d in zip(queries, parameters, distances):
        reference = scipy_ellipse_distance(a, b, q)
        assert d <= reference + 1e-12, (q, d, reference)
        worst = max(worst, reference - d)
        assert np.linalg.norm(cj.point_at(ellipse, t) - q) == pytest.approx(d, abs=1e-12)
    print(f"ellipse: scipy's distance exceeds ours by at most {worst:.2g}")
    assert worst < 1e-9


def test_single_query_matches_the_batch_and_local_minima():
    ellipse = cj.make_ellipse((0.0, 0.0), 3.0, 1.0)
    t, d, p = cj.closest_point(ellipse, [0.5, 0.0])
    assert d == pytest.approx(scipy_ellipse_distance(3.0, 1.0, [0.5, 0.0]), abs=1e-12)
    parameters, distances = cj.closest_points(ellipse, [[0.5, 0.0]])
    assert distances[0] == pytest.approx(d, abs=1e-14)
    assert p.shape == (2,)
    # From the centre the nearest points are the minor axis' ends (0, +-1).
    ts, ds, ps = cj.local_closest_points(ellipse, [0.0, 0.0])
    assert ps.shape == (len(ts), 2)
    minor = sorted(tuple(np.round(x, 12)) for x in ps if abs(abs(x[1]) - 1) < 1e-9)
    assert minor == [(0.0, -1.0), (0.0, 1.0)], ps
    assert ds[0] == pytest.approx(1.0, abs=1e-14)
    assert all(ds >= ds[0])


@pytest.mark.parametrize("curve", [
    cj.BezierCurve([[0, 0], [1, 2], [3, 2], [4, 0]]),
    cj.PiecewiseBezierCurve([cj.BezierCurve([[0, 0], [1, 2], [2, 0]]), cj.BezierCurve([[2, 0], [4, 0]])]),
    cj.BSplineCurve(2, [0, 0, 0, 1, 2, 2, 2], [[0, 0], [1, 2], [3, 2], [4, 0]]),
])
def test_every_kind(curve):
    t, d, p = cj.closest_point(curve, [2.0, 3.0])
    samples = cj.points_at(curve, np.linspace(*curve.domain, 20001))
    assert d <= np.min(np.hypot(samples[:, 0] - 2, samples[:, 1] - 3)) + 1e-12


def test_errors():
    curve = cj.BezierCurve([[0, 0], [4, 2]])
    with pytest.raises(ValueError, match="the query point has 3 coordinates, the curve lives in R\\^2"):
        cj.closest_point(curve, [1, 2, 3])
    with pytest.raises(ValueError, match="NaN"):
        cj.closest_point(curve, [1, float("nan")])
    with pytest.raises(ValueError, match="points has 3 columns, the curve lives in R\\^2"):
        cj.closest_points(curve, [[1, 2, 3]])


def test_point_inversion_on_the_sphere():
    sphere = cj.make_sphere((0.0, 0.0, 0.0), 2.0)
    rng = np.random.default_rng(7)
    for q in rng.uniform(-5, 5, size=(200, 3)):
        u, v, d, p = cj.closest_point(sphere, q)
        assert d == pytest.approx(abs(np.linalg.norm(q) - 2.0), abs=1e-12)
        assert np.allclose(cj.point_at(sphere, u, v), p, atol=1e-14)
    with pytest.raises(ValueError, match="the surface lives in R\\^3"):
        cj.closest_point(sphere, [1.0, 2.0])
