"""The interpolation layer's bindings (python/src/interpolation.cpp) against scipy and closed forms.

References: scipy.interpolate (make_interp_spline, CubicSpline, CubicHermiteSpline,
BarycentricInterpolator, make_lsq_spline, make_smoothing_spline, splder,
splantider, splint), the formulas of the headers recomputed here in numpy
(parameter steps |P_{i+1} - P_i|^e, Barry–Goldman tangents, Chebyshev points,
Ferguson's control points), and exact fractions for a polyline's integral.
Tolerances are relative to the data's scale. Error types for bad input.
"""

import pickle
from fractions import Fraction

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st
from scipy import interpolate as si

import casteljau as cj

RTOL = 1e-12


def close(a, b, rtol=RTOL):
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    assert a.shape == b.shape, (a.shape, b.shape)
    scale = max(1.0, float(np.abs(b).max())) if b.size else 1.0
    return float(np.abs(a - b).max()) / scale <= rtol if a.size else True


def random_points(seed, count, dimension=2):
    return np.random.default_rng(seed).normal(size=(count, dimension)) * 10


def values(curve, us, order=0):
    us = np.asarray(us, dtype=float)
    if order == 0:
        return cj.points_at(curve, us, extrapolate=True)
    return cj.derivatives_at(curve, us, order, extrapolate=True)


# --- parameterization ------------------------------------------------------------------


@pytest.mark.parametrize("kind,exponent", [("uniform", 0.0), ("chord", 1.0), ("chord-length", 1.0),
                                           ("centripetal", 0.5)])
def test_parameter_values_follow_the_step_formula(kind, exponent):
    points = random_points(1, 9, 3)
    steps = np.linalg.norm(np.diff(points, axis=0), axis=1) ** exponent
    expected = np.concatenate([[0.0], np.cumsum(steps)]) / steps.sum()
    assert close(cj.parameter_values(points, kind), expected)
    closed = cj.parameter_values(points, kind, closed=True)
    assert closed.shape == (10,) and closed[0] == 0.0 and closed[-1] == 1.0
    assert cj.parameterization_from_name(kind) in ("uniform", "chord", "centripetal")


def test_parameterization_names_and_function_parameters():
    with pytest.raises(ValueError, match="uniform"):
        cj.parameter_values(random_points(2, 4), "arc")
    assert cj.end_condition_from_name("not_a_knot") == "not-a-knot"
    with pytest.raises(ValueError, match="natural"):
        cj.end_condition_from_name("free")
    points = np.array([[0.0, 1.0], [1.0, 3.0], [2.5, 0.0]])
    np.testing.assert_array_equal(cj.function_parameters(points), [0.0, 1.0, 2.5])
    with pytest.raises(ValueError, match="increase strictly"):
        cj.function_parameters(points[::-1])
    square = np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 0.0]])
    np.testing.assert_array_equal(cj.without_closing_duplicate(square), square[:3])
    np.testing.assert_array_equal(cj.without_closing_duplicate(square[:3]), square[:3])


# --- Catmull-Rom, c1-bezier, Hermite, Ferguson ------------------------------------------------


def barry_goldman_tangents(points, t):
    h = np.diff(t)
    d = np.diff(points, axis=0) / h[:, None]
    tangents = np.empty_like(points)
    tangents[0], tangents[-1] = d[0], d[-1]
    tangents[1:-1] = (h[1:, None] * d[:-1] + h[:-1, None] * d[1:]) / (h[:-1] + h[1:])[:, None]
    return tangents


@pytest.mark.parametrize("kind", ["uniform", "chord", "centripetal"])
def test_catmull_rom_is_scipys_hermite_spline_with_barry_goldman_tangents(kind):
    points = random_points(3, 8)
    t = cj.parameter_values(points, kind)
    curve = cj.interpolate_catmull_rom(points, t)
    reference = si.CubicHermiteSpline(t, points, barry_goldman_tangents(points, t))
    us = np.linspace(0, 1, 157)
    assert close(values(curve, us), reference(us))
    assert close(values(curve, us, 1), reference(us, 1), 1e-11)


def test_c1_bezier_with_alpha_2_is_the_uniform_catmull_rom():
    points = random_points(4, 7)
    piecewise = cj.interpolate_c1_bezier(points, 2.0)
    spline = cj.interpolate_catmull_rom(points, np.arange(7.0))
    us = np.linspace(0, 6, 61)
    assert close(cj.points_at(piecewise, us), values(spline, us))
    with pytest.raises(ValueError, match="alpha"):
        cj.interpolate_c1_bezier(points, 0.0)


def test_hermite_matches_scipy_and_ferguson_has_the_book_control_points():
    points, tangents = random_points(5, 6, 3), random_points(6, 6, 3)
    t = np.cumsum(np.random.default_rng(7).uniform(0.5, 2, 6))
    curve = cj.interpolate_hermite(points, tangents, t)
    reference = si.CubicHermiteSpline(t, points, tangents)
    us = np.linspace(t[0], t[-1], 99)
    assert close(values(curve, us), reference(us))
    assert close(values(curve, us, 1), reference(us, 1), 1e-11)
    p0, t0, p1, t1 = np.array([0.0, 1.0]), np.array([3.0, 0.0]), np.array([2.0, 2.0]), np.array([0.0, -3.0])
    ferguson = cj.ferguson_curve(p0, t0, p1, t1)
    np.testing.assert_array_equal(ferguson.control_points, [p0, p0 + t0 / 3, p1 - t1 / 3, p1])
    with pytest.raises(ValueError):
        cj.interpolate_hermite(points, tangents[:-1], t)


# --- Lagrange ------------------------------------------------------------------------------


def test_lagrange_matches_scipy_barycentric_interpolator():
    t = cj.chebyshev_parameters(15, (-1.0, 2.0))
    n = 14
    j = np.arange(15)
    expected = 0.5 + 1.5 * np.sin(np.pi * (2 * j - n) / (2 * n))
    assert close(t, expected, 1e-15) and t[0] == -1.0 and t[-1] == 2.0
    points = np.c_[np.cos(3 * t), 1 / (1 + t * t)]
    interpolant = cj.interpolate_lagrange(points, t)
    reference = si.BarycentricInterpolator(t, points)
    ts = np.linspace(-1, 2, 301)
    assert close(cj.points_at(interpolant, ts), reference(ts), 1e-13)
    assert close(cj.point_at(interpolant, 0.3), reference(0.3), 1e-13)
    out = np.empty((301, 2))
    assert cj.points_at(interpolant, ts, out=out) is out
    assert cj.domain_of(interpolant) == (-1.0, 2.0) == interpolant.domain
    with pytest.raises(ValueError, match="outside the domain"):
        cj.points_at(interpolant, np.array([2.5]))
    assert close(cj.points_at(interpolant, np.array([2.5]), extrapolate=True), reference([2.5]), 1e-10)
    bezier = cj.to_bezier(interpolant)
    assert close(cj.points_at(bezier, (ts + 1) / 3), reference(ts), 1e-12)
    copy = pickle.loads(pickle.dumps(interpolant))
    assert copy == interpolant and interpolant.degree == 14 and interpolant.dimension == 2
    np.testing.assert_array_equal(copy.weights, interpolant.weights)


# --- natural splines, cubic and B-spline interpolation ---------------------------------------------


def test_natural_splines_of_order_1_and_2():
    x = np.cumsum(np.random.default_rng(8).uniform(0.3, 1.0, 9))
    points = random_points(9, 9)
    us = np.linspace(x[0], x[-1], 77)
    assert close(values(cj.interpolate_natural(points, x, 2), us), si.CubicSpline(x, points, bc_type="natural")(us))
    polyline = cj.interpolate_natural(points, x, 1)
    assert close(values(polyline, us)[:, 0], np.interp(us, x, points[:, 0]))


@pytest.mark.parametrize("ends", ["natural", "clamped", "not-a-knot", "periodic"])
def test_interpolate_cubic_matches_scipy(ends):
    rng = np.random.default_rng(10)
    x = np.cumsum(rng.uniform(0.2, 1.5, 12))
    points = random_points(11, 12, 3)
    kwargs, bc_type = {}, ends
    if ends == "clamped":
        start, end = np.array([1.0, -2.0, 0.5]), np.array([0.0, 3.0, -1.0])
        kwargs = dict(start_tangent=start, end_tangent=end)
        bc_type = ([(1, start)], [(1, end)])
    if ends == "periodic":
        curve = cj.interpolate_cubic(points[:-1], x, "periodic")
        points[-1] = points[0]
    else:
        curve = cj.interpolate_cubic(points, x, ends, **kwargs)
    reference = si.make_interp_spline(x, points, k=3, bc_type=bc_type)
    np.testing.assert_allclose(curve.knots, reference.t, rtol=0, atol=1e-14 * x[-1])
    n = len(curve.knots) - 4
    assert close(curve.control_points, reference.c[:n], 1e-11)
    with pytest.raises(ValueError, match="clamped"):
        cj.interpolate_cubic(points, x, "natural", start_tangent=np.zeros(3))


def test_interpolate_bspline_degree_2_is_scipys_and_derivatives_hold():
    x = np.cumsum(np.random.default_rng(12).uniform(0.2, 1.5, 10))
    points = random_points(13, 10)
    curve = cj.interpolate_bspline(points, x, 2)
    reference = si.make_interp_spline(x, points, k=2)
    np.testing.assert_allclose(curve.knots, reference.t, rtol=0, atol=1e-14 * x[-1])
    assert close(curve.control_points, reference.c, 1e-11)
    start, second = np.array([1.0, 2.0]), np.array([-3.0, 0.0])
    curve = cj.interpolate_bspline(points, x, 4, [("start", 1, start), (True, 2, second)])
    assert close(cj.derivative_at(curve, x[0], 1), start, 1e-10)
    assert close(cj.derivative_at(curve, x[-1], 2), second, 1e-10)
    assert close(values(curve, x), points, 1e-11)
    with pytest.raises(ValueError, match="order"):
        cj.interpolate_bspline(points, x, 3, [("start", 5, start)])
    with pytest.raises(TypeError):
        cj.interpolate_bspline(points, x, 3, [("start", 1)])


@pytest.mark.parametrize("k", [1, 2, 3, 4, 5, 7])
def test_interpolate_on_knots_is_scipys_make_interp_spline_with_t(k):
    rng = np.random.default_rng(30 + k)
    x = np.cumsum(rng.uniform(0.2, 2.0, 14))
    points = random_points(30 + k, 14, 3)
    # scipy's not-a-knot knots (odd k) or clamped averaged ones (even k): any valid t
    half = (k + 1) // 2
    interior = x[half:-half] if k % 2 else np.convolve(x[1:-1], np.ones(k) / k, "valid")
    knots = np.r_[(x[0],) * (k + 1), interior, (x[-1],) * (k + 1)]
    curve = cj.interpolate_on_knots(points, x, k, knots)
    reference = si.make_interp_spline(x, points, k=k, t=knots)
    np.testing.assert_array_equal(curve.knots, knots)
    assert curve.degree == k and close(curve.control_points, reference.c, 1e-10)
    assert close(values(curve, x), points, 1e-10)
    if k >= 2:  # one derivative at each end, on knots averaging k of the sites x[0], x[0], x[1], ..., x[-1], x[-1]
        sites = np.r_[x[0], x, x[-1]]
        knots = np.r_[(x[0],) * (k + 1), np.convolve(sites[1:-1], np.ones(k) / k, "valid"), (x[-1],) * (k + 1)]
        start, end = rng.normal(size=3), rng.normal(size=3)
        order = 2
        curve = cj.interpolate_on_knots(points, x, k, knots, [("start", 1, start), (True, order, end)])
        reference = si.make_interp_spline(x, points, k=k, t=knots, bc_type=([(1, start)], [(order, end)]))
        assert close(curve.control_points, reference.c, 1e-10)
        assert close(values(curve, x[:1], 1)[0], start, 1e-9) and close(values(curve, x[-1:], order)[0], end, 1e-9)


def test_interpolate_on_knots_errors_name_the_problem():
    x = np.arange(8.0)
    points = np.c_[x, np.sin(x)]
    knots = np.r_[[0.0] * 4, x[2:-2], [7.0] * 4]
    assert close(values(cj.interpolate_on_knots(points, x, 3, knots), x), points)
    with pytest.raises(ValueError, match="11 knots given, 8 points and 0 end derivatives determine 8 control points "
                                         "of degree 3, which need 12 knots"):
        cj.interpolate_on_knots(points, x, 3, knots[1:])
    # four interior knots inside (2, 3): basis function 3's support [0, 2.8) misses parameter 3
    crowded = np.r_[[0.0] * 4, 2.2, 2.4, 2.6, 2.8, [7.0] * 4]
    with pytest.raises(ValueError, match=r"parameter 3 \(3\) is not inside the support \[0, 2.8\) of basis "
                                         r"function 3.*Schoenberg"):
        cj.interpolate_on_knots(points, x, 3, crowded)
    with pytest.raises(ValueError, match="knot 5 .* is smaller than knot 4"):
        cj.interpolate_on_knots(points, x, 3, np.r_[[0.0] * 4, 3.0, 2.0, 4.0, 5.0, [7.0] * 4])
    with pytest.raises(ValueError, match="5.* is NaN"):
        cj.interpolate_on_knots(points, x, 3, np.r_[[0.0] * 4, 3.0, np.nan, 4.0, 5.0, [7.0] * 4])
    with pytest.raises(ValueError, match="parameter 0 .* is not knot 3"):
        cj.interpolate_on_knots(points, x, 3, np.r_[[-1.0] * 4, 2.0, 3.0, 4.0, 5.0, [7.0] * 4])
    with pytest.raises(ValueError, match="order 4"):
        cj.interpolate_on_knots(points, x, 3, np.r_[[0.0] * 4, x[1:-1], [7.0] * 4], [(False, 4, [0, 0]), (True, 1, [0, 0])])
    with pytest.raises(ValueError, match="coordinates"):
        cj.interpolate_on_knots(points, x, 3, np.r_[[0.0] * 4, x[1:-1], [7.0] * 4], [(False, 1, [0]), (True, 1, [0, 0])])
    with pytest.raises(ValueError, match="degree 0"):
        cj.interpolate_on_knots(points, x, 0, np.r_[x, 8.0])
    with pytest.raises(TypeError):
        cj.interpolate_on_knots(points, x, 3, knots + 0j)


# --- fits ----------------------------------------------------------------------------------


def test_fit_least_squares_free_ends_is_scipys_make_lsq_spline():
    rng = np.random.default_rng(14)
    x = np.sort(rng.uniform(0, 10, 80))
    points = np.c_[np.sin(x), np.cos(0.5 * x)] + rng.normal(scale=0.05, size=(80, 2))
    fit = cj.fit_least_squares(points, x, 3, 14, "free")
    knots = cj.approximation_knots(x, 3, 14)
    np.testing.assert_array_equal(fit.curve.knots, knots)
    reference = si.make_lsq_spline(x, points, knots, 3)
    assert close(fit.curve.control_points, reference.c, 1e-10)
    errors = np.linalg.norm(values(fit.curve, x) - points, axis=1)
    assert close(fit.errors, errors, 1e-10) and fit.max_error == fit.errors.max()
    assert fit.worst_point == int(np.argmax(fit.errors)) and fit.smoothing == 0.0
    interpolated = cj.fit_least_squares(points, x, 3, 14)
    assert close(values(interpolated.curve, x[[0, -1]]), points[[0, -1]], 1e-13)
    assert pickle.loads(pickle.dumps(fit)) == fit
    with pytest.raises(ValueError, match="interpolated or free"):
        cj.fit_least_squares(points, x, 3, 14, "loose")
    with pytest.raises(ValueError, match="control_point_count"):
        cj.approximation_knots(x, 3, 200)


@pytest.mark.parametrize("k", [1, 2, 3, 5])
def test_fit_least_squares_on_knots_is_scipys_weighted_make_lsq_spline(k):
    rng = np.random.default_rng(40 + k)
    x = np.sort(rng.uniform(0, 10, 70))
    points = np.c_[np.sin(x), np.cos(0.5 * x)] + rng.normal(scale=0.05, size=(70, 2))
    # unclamped knots reaching past the data (scipy allows any valid t) and random interior knots
    interior = np.sort(rng.choice(x[k + 2:-k - 2], size=6, replace=False))
    knots = np.r_[x[0] - np.arange(k, 0, -1) * 0.3, x[0], interior, x[-1], x[-1] + np.arange(1, k + 1) * 0.3]
    w = rng.uniform(0.2, 3.0, 70)
    fit = cj.fit_least_squares_on_knots(points, x, k, knots, w ** 2)
    reference = si.make_lsq_spline(x, points, knots, k, w=w)
    np.testing.assert_array_equal(fit.curve.knots, knots)
    assert close(fit.curve.control_points, reference.c, 1e-10)
    assert close(fit.errors, np.linalg.norm(values(fit.curve, x) - points, axis=1), 1e-10)
    unweighted = cj.fit_least_squares_on_knots(points, x, k, knots)
    assert close(unweighted.curve.control_points, si.make_lsq_spline(x, points, knots, k).c, 1e-10)
    # on approximation_knots with unit weights it is fit_least_squares
    clamped = cj.approximation_knots(x, k, 12)
    for ends in ("free", "interpolated"):
        same = cj.fit_least_squares_on_knots(points, x, k, clamped, np.ones(70), ends)
        assert close(same.curve.control_points, cj.fit_least_squares(points, x, k, 12, ends).curve.control_points, 1e-12)


def test_fit_least_squares_on_knots_errors_name_the_problem():
    x = np.linspace(0, 10, 30)
    points = np.c_[x, np.sin(x)]
    knots = np.r_[[0.0] * 4, 5.0, [10.0] * 4]
    with pytest.raises(ValueError, match=r"basis function 4 \(support \[5.2, 5.4\)\).*Schoenberg"):
        cj.fit_least_squares_on_knots(points, x, 3, np.r_[[0.0] * 4, 5.2, 5.25, 5.3, 5.35, 5.4, [10.0] * 4])
    with pytest.raises(ValueError, match="29 weights for 30 points"):
        cj.fit_least_squares_on_knots(points, x, 3, knots, np.ones(29))
    with pytest.raises(ValueError, match="weight 3 is -1"):
        cj.fit_least_squares_on_knots(points, x, 3, knots, np.r_[1, 1, 1, -1, np.ones(26)])
    with pytest.raises(ValueError, match="2.* is NaN"):
        cj.fit_least_squares_on_knots(points, x, 3, knots, np.r_[1, 1, np.nan, np.ones(27)])
    with pytest.raises(ValueError, match="outside the knots' domain"):
        cj.fit_least_squares_on_knots(points, x, 3, np.r_[[1.0] * 4, 5.0, [10.0] * 4])
    with pytest.raises(ValueError, match="clamped"):
        cj.fit_least_squares_on_knots(points, x, 3, np.r_[-1.0, [0.0] * 3, 5.0, [10.0] * 4], None, "interpolated")
    with pytest.raises(ValueError, match="knot 5 .* is smaller"):
        cj.fit_least_squares_on_knots(points, x, 3, np.r_[[0.0] * 4, 6.0, 5.0, [10.0] * 4])
    with pytest.raises(ValueError, match="at least 8"):
        cj.fit_least_squares_on_knots(points, x, 3, np.r_[0.0, 10.0])
    with pytest.raises(ValueError, match="interpolated or free"):
        cj.fit_least_squares_on_knots(points, x, 3, knots, None, "loose")


@pytest.mark.parametrize("lam", [1e-2, 1.0])
def test_fit_smoothing_is_scipys_make_smoothing_spline(lam):
    rng = np.random.default_rng(15)
    x = np.sort(rng.uniform(0, 4, 30))
    y = np.exp(-x) * np.sin(3 * x) + rng.normal(scale=0.05, size=30)
    fit = cj.fit_smoothing(y[:, None], x, smoothing=lam)
    reference = si.make_smoothing_spline(x, y, lam=lam)
    us = np.linspace(x[0], x[-1], 91)
    assert close(values(fit.curve, us)[:, 0], reference(us), 1e-9)
    assert fit.smoothing == lam and not fit.smoothing_from_gcv
    by_gcv = cj.fit_smoothing(y[:, None], x)
    assert by_gcv.smoothing_from_gcv and by_gcv.smoothing > 0
    with pytest.raises(ValueError):
        cj.fit_smoothing(y[:, None], x, smoothing=-1.0)


def test_fit_to_tolerance_reaches_it():
    x = np.linspace(0, 6, 200)
    points = np.c_[x, np.sin(x)]
    fit = cj.fit_to_tolerance(points, x, 3, 1e-4)
    assert fit.max_error <= 1e-4
    assert close(fit.errors, np.linalg.norm(values(fit.curve, x) - points, axis=1), 1e-8)
    with pytest.raises(ValueError, match="tolerance"):
        cj.fit_to_tolerance(points, x, 3, 0.0)


# --- derivative and antiderivative curves, integrals ---------------------------------------------


def random_curve(seed, degree, dimension=2):
    rng = np.random.default_rng(seed)
    n = degree + 1 + int(rng.integers(0, 6))
    interior = np.sort(rng.uniform(0.5, 4.5, n - degree - 1))
    knots = np.r_[[0.0] * (degree + 1), interior, [5.0] * (degree + 1)]
    if seed % 2:
        knots = np.sort(rng.uniform(-1, 6, n + degree + 1))  # unclamped
    return cj.BSplineCurve(degree, knots, rng.normal(size=(n, dimension)) * 10)


@pytest.mark.parametrize("degree", range(6))
def test_derivative_and_antiderivative_curves_are_fitpacks(degree):
    for seed in range(6):
        curve = random_curve(seed, degree)
        t, c = curve.knots, curve.control_points
        for order in range(1, degree + 1):
            derivative = cj.derivative_curve(curve, order)
            t2, c2, k2 = si.splder((t, np.r_[c, np.zeros((degree + 1, 2))], degree), order)
            np.testing.assert_array_equal(derivative.knots, t2)
            assert derivative.degree == k2
            assert close(derivative.control_points, c2[:len(t2) - k2 - 1], 1e-11)
        for order in range(1, 4):
            antiderivative = cj.antiderivative_curve(curve, order)
            t2, c2, k2 = si.splantider((t, np.r_[c, np.zeros((degree + 1, 2))], degree), order)
            np.testing.assert_array_equal(antiderivative.knots, t2)
            assert close(antiderivative.control_points, c2[:len(t2) - k2 - 1], RTOL)
        lower, upper = curve.domain
        a, b = lower + 0.3 * (upper - lower), upper - 0.1 * (upper - lower)
        reference = si.BSpline(t, c, degree).integrate(a, b)
        assert close(cj.integral(curve, a, b), reference, 1e-12)


def test_integral_of_a_polyline_is_exact():
    curve = cj.BSplineCurve(1, [0, 0, 1, 3, 3], [[0.0, 1.0], [2.0, -1.0], [6.0, 4.0]])
    exact = [Fraction(0 + 2, 2) * 1 + Fraction(2 + 6, 2) * 2, Fraction(1 - 1, 2) * 1 + Fraction(-1 + 4, 2) * 2]
    np.testing.assert_array_equal(cj.integral(curve, 0.0, 3.0), [float(v) for v in exact])
    np.testing.assert_array_equal(cj.integral(curve, 3.0, 0.0), [-float(v) for v in exact])
    zero = cj.derivative_curve(curve, 2)
    assert zero.degree == 0 and zero.domain == curve.domain
    np.testing.assert_array_equal(zero.control_points, [[0.0, 0.0]])


def test_rational_curves_and_bad_orders_are_refused():
    arc = cj.BSplineCurve(2, [0, 0, 0, 1, 1, 1], [[1.0, 0.0], [1.0, 1.0], [0.0, 1.0]], [1.0, 0.5 ** 0.5, 1.0])
    for function in (cj.derivative_curve, cj.antiderivative_curve):
        with pytest.raises(ValueError, match="rational"):
            function(arc)
    with pytest.raises(ValueError, match="rational"):
        cj.integral(arc, 0.0, 1.0)
    line = cj.BSplineCurve(1, [0, 0, 1, 1], [[0.0], [1.0]])
    with pytest.raises(ValueError, match="negative"):
        cj.derivative_curve(line, -1)
    with pytest.raises(ValueError, match="not finite"):
        cj.integral(line, 0.0, float("nan"))


# --- properties ----------------------------------------------------------------------------


@settings(derandomize=True, max_examples=40, deadline=None)
@given(st.lists(st.floats(0.05, 2.0), min_size=5, max_size=12), st.sampled_from(["natural", "not-a-knot"]),
       st.integers(0, 2**31 - 1))
def test_cubic_interpolants_pass_through_their_points(steps, ends, seed):
    x = np.cumsum(steps)
    points = np.random.default_rng(seed).uniform(-50, 50, size=(x.size, 3))
    curve = cj.interpolate_cubic(points, x, ends)
    assert close(values(curve, x), points, 1e-11)


@settings(derandomize=True, max_examples=40, deadline=None)
@given(st.integers(0, 6), st.integers(0, 10**6), st.floats(0.0, 1.0), st.floats(0.0, 1.0), st.floats(0.0, 1.0))
def test_integral_is_additive_and_the_antiderivative_differentiates_back(degree, seed, fa, fb, fm):
    curve = random_curve(seed, degree, 3)
    lower, upper = curve.domain
    a, b, m = (lower + f * (upper - lower) for f in (fa, fb, fm))
    scale = 10 * max(1.0, float(np.abs(curve.control_points).max())) * (upper - lower)
    total = cj.integral(curve, a, m) + cj.integral(curve, m, b)
    assert np.abs(total - cj.integral(curve, a, b)).max() <= 1e-12 * scale
    back = cj.derivative_curve(cj.antiderivative_curve(curve))
    np.testing.assert_array_equal(back.knots, curve.knots)
    us = np.linspace(lower, upper, 13)
    assert close(values(back, us), values(curve, us), 1e-10)


# --- errors --------------------------------------------------------------------------------


def test_bad_arrays_raise_the_right_errors():
    x = np.arange(6.0)
    points = np.c_[x, x ** 2]
    with pytest.raises(ValueError):
        cj.interpolate_cubic(points[:, 0], x)                    # not (n, d)
    with pytest.raises(ValueError):
        cj.interpolate_cubic(points, x[:-1])                     # one parameter short
    with pytest.raises(ValueError):
        cj.interpolate_cubic(np.r_[points[:-1], [[np.nan, 0]]], x)
    with pytest.raises(ValueError):
        cj.interpolate_cubic(np.empty((0, 2)), np.empty(0))
    with pytest.raises(ValueError):
        cj.interpolate_cubic(points[:3], x[:3], "not-a-knot")    # too few points
    with pytest.raises(ValueError):
        cj.interpolate_cubic(points, x[::-1])                    # not increasing
    with pytest.raises(TypeError):
        cj.interpolate_cubic(points.astype(complex), x)
    with pytest.raises(TypeError):
        cj.interpolate_lagrange(points, x + 0j)
    with pytest.raises(ValueError):
        cj.chebyshev_parameters(-3)
    with pytest.raises(ValueError):
        cj.fit_smoothing(points, x, control_point_count=-1)
    # float32, integers, F order and strides give the float64 results
    reference = cj.interpolate_cubic(points, x, "natural")
    for p, t in ((points.astype(np.float32), x.astype(np.float32)), (points.astype(int), x.astype(int)),
                 (np.asfortranarray(points), x), (np.c_[points, points][:, ::2][:, :2] * 0 + points, x[::1])):
        assert cj.interpolate_cubic(p, t, "natural") == reference
    strided = np.zeros((6, 4))
    strided[:, ::2] = points
    assert cj.interpolate_cubic(strided[:, ::2], np.c_[x, x][:, 0], "natural") == reference
