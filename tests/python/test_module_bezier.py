"""The bezier layer through the Python module (python/src/bezier.cpp).

References: exact rational arithmetic (fractions.Fraction) for de Casteljau,
the Bernstein basis and its derivatives; math.comb for binomials; the seeds'
worked example (control points (0,0),(1,2),(2,2),(4,1),(4,0) give
B(0.5) = (2.25, 1.5)); the closed-form curvature of the parabola y = x^2.
Invariants (partition of unity, splitting, elevation, affine invariance,
subdivision) are hypothesis properties with derandomize=True (seeded runs).
"""

import math
import pickle
from fractions import Fraction

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

import casteljau as c

SEED_POINTS = [[0, 0], [1, 2], [2, 2], [4, 1], [4, 0]]
SETTINGS = settings(derandomize=True, max_examples=60, deadline=None)


# --- exact references --------------------------------------------------------------------


def exact_casteljau(points, t, weights=None):
    """C(t) by de Casteljau in Fractions (homogeneous for rational curves)."""
    t = Fraction(t)
    w = [Fraction(1)] * len(points) if weights is None else [Fraction(x) for x in weights]
    rows = [[Fraction(x) * wi for x in p] + [wi] for p, wi in zip(points, w)]
    while len(rows) > 1:
        rows = [[(1 - t) * a + t * b for a, b in zip(r0, r1)] for r0, r1 in zip(rows, rows[1:])]
    return [x / rows[0][-1] for x in rows[0][:-1]]


def exact_bernstein(n, k, t):
    t = Fraction(t)
    return math.comb(n, k) * t**k * (1 - t) ** (n - k) if 0 <= k <= n else Fraction(0)


def exact_bernstein_derivative(n, k, t, r):
    """d^r/dt^r B_{n,k} by B' = n (B_{n-1,k-1} - B_{n-1,k}), in Fractions."""
    if r == 0:
        return exact_bernstein(n, k, t)
    if n == 0:
        return Fraction(0)
    return n * (exact_bernstein_derivative(n - 1, k - 1, t, r - 1) - exact_bernstein_derivative(n - 1, k, t, r - 1))


def close(a, b, scale, rel=1e-13):
    np.testing.assert_allclose(np.asarray(a, float), np.asarray([float(x) for x in np.ravel(b)]).reshape(np.shape(a)),
                               rtol=0, atol=rel * max(scale, 1e-300))


# --- strategies -----------------------------------------------------------------------------

dyadic = st.integers(-64, 64).map(lambda i: i / 16)
unit_t = st.integers(0, 256).map(lambda i: i / 256)


@st.composite
def polygons(draw, max_degree=7, dims=(1, 2, 3)):
    d = draw(st.sampled_from(dims))
    n = draw(st.integers(0, max_degree))
    return [[draw(dyadic) for _ in range(d)] for _ in range(n + 1)]


@st.composite
def rational_curves(draw):
    points = draw(polygons())
    weights = [draw(st.integers(1, 16)) / 4 for _ in points]
    return points, weights


def scale_of(points):
    return max(1.0, float(np.max(np.abs(points))))


# --- the seed's worked example and exact evaluation ------------------------------------------


def test_seed_worked_example():
    curve = c.BezierCurve(SEED_POINTS)
    assert curve.degree == 4 and curve.dimension == 2 and not curve.is_rational
    assert curve.domain == (0.0, 1.0)
    np.testing.assert_array_equal(c.point_at(curve, 0.5), [2.25, 1.5])
    assert [float(x) for x in exact_casteljau(SEED_POINTS, Fraction(1, 2))] == [2.25, 1.5]


@SETTINGS
@given(polygons(), unit_t)
def test_point_at_matches_exact_de_casteljau(points, t):
    curve = c.BezierCurve(points)
    close(c.point_at(curve, t), exact_casteljau(points, t), scale_of(points))


@SETTINGS
@given(rational_curves(), unit_t)
def test_rational_point_at_matches_exact(curve_data, t):
    points, weights = curve_data
    curve = c.BezierCurve(points, weights)
    assert curve.is_rational
    close(c.point_at(curve, t), exact_casteljau(points, t, weights), scale_of(points))


@SETTINGS
@given(polygons())
def test_points_at_is_point_at_bit_for_bit(points):
    curve = c.BezierCurve(points)
    ts = np.linspace(0, 1, 37)
    batch = c.points_at(curve, ts)
    assert batch.shape == (37, len(points[0]))
    for t, row in zip(ts, batch):
        np.testing.assert_array_equal(row, c.point_at(curve, t))


def test_points_at_out_and_errors():
    curve = c.BezierCurve(SEED_POINTS)
    out = np.empty((3, 2))
    result = c.points_at(curve, [0, 0.5, 1], out=out)
    assert result is out
    np.testing.assert_array_equal(out[1], [2.25, 1.5])
    with pytest.raises(ValueError, match="out has shape"):
        c.points_at(curve, [0, 0.5], out=np.empty((3, 2)))
    with pytest.raises(ValueError, match="outside the domain"):
        c.points_at(curve, [0.5, 1.5])
    with pytest.raises(ValueError, match="NaN"):
        c.points_at(curve, [np.nan])
    assert c.points_at(curve, np.empty(0)).shape == (0, 2)
    np.testing.assert_allclose(c.points_at(curve, [1.5], extrapolate=True)[0],
                               [float(x) for x in exact_casteljau(SEED_POINTS, Fraction(3, 2))], rtol=1e-14)


def test_point_at_bernstein_sum_and_vector_form_agree_with_exact():
    curve = c.BezierCurve(SEED_POINTS)
    for t in (0.0, 0.25, 0.5, 0.8125, 1.0):
        expected = exact_casteljau(SEED_POINTS, t)
        close(c.point_at_bernstein_sum(curve, t), expected, 4)
        close(c.point_at_vector_form(c.to_vector_form(SEED_POINTS), t), expected, 4)


# --- the Bernstein basis ------------------------------------------------------------------------


@SETTINGS
@given(st.integers(0, 40), unit_t)
def test_bernstein_partition_of_unity_and_exact_values(n, t):
    values = c.bernstein_all(n, t)
    assert values.shape == (n + 1,)
    assert abs(values.sum() - 1.0) <= 4 * (n + 1) * 2.2e-16
    assert (values >= 0).all()
    for k in range(n + 1):
        exact = exact_bernstein(n, k, t)
        assert abs(c.bernstein(n, k, t) - float(exact)) <= 1e-14 * (n + 1)
        assert abs(values[k] - float(exact)) <= 1e-14 * (n + 1)


def test_bernstein_vectorized_shapes():
    ts = np.linspace(0, 1, 11)
    values = c.bernstein(5, 2, ts)
    assert isinstance(values, np.ndarray) and values.shape == (11,)
    np.testing.assert_array_equal(values, [c.bernstein(5, 2, t) for t in ts])
    assert isinstance(c.bernstein(5, 2, 0.3), float)
    assert isinstance(c.bernstein(5, 2, 0), float)  # an integer t is a scalar too
    assert c.bernstein(5, 7, 0.3) == 0.0 and c.bernstein(5, -1, 0.3) == 0.0
    table = c.bernstein_all(5, ts)
    assert table.shape == (11, 6)
    np.testing.assert_allclose(table.sum(axis=1), 1.0, rtol=0, atol=1e-15)
    assert c.bernstein_derivatives(4, ts, 2).shape == (11, 5)
    np.testing.assert_array_equal(c.bernstein_derivatives(4, 0.3, 5), np.zeros(5))
    with pytest.raises(ValueError, match="NaN"):
        c.bernstein(3, 1, [0.5, np.nan])
    with pytest.raises(ValueError):
        c.bernstein(-1, 0, 0.5)
    with pytest.raises(ValueError):
        c.bernstein_all(3, np.zeros((2, 2)))
    with pytest.raises(TypeError):
        c.bernstein(3, 1, np.array([0.5j]))


@pytest.mark.parametrize("n,order", [(3, 1), (5, 2), (6, 3), (7, 7)])
def test_bernstein_derivatives_exact(n, order):
    for t in (0, 0.125, 0.5, 0.9375, 1):
        values = c.bernstein_derivatives(n, t, order)
        for k in range(n + 1):
            exact = exact_bernstein_derivative(n, k, t, order)
            assert abs(values[k] - float(exact)) <= 1e-12 * max(1, abs(float(exact)))


def test_binomial_matches_math_comb():
    for n in range(0, 60):
        for k in range(-1, n + 2):
            expected = math.comb(n, k) if 0 <= k <= n else 0
            assert c.binomial(n, k) == float(expected)
    assert c.binomial(2000, 1000) == math.inf


def test_bezier_basis_polynomial_degree_3():
    # seed 001 (with f_1 corrected): f_1 = t^3 - 3t^2 + 3t, f_2 = 3t^2 - 2t^3, f_3 = t^3.
    for t in (0.0, 0.25, 0.5, 0.75, 1.0):
        assert c.bezier_basis_polynomial(3, 0, t) == 1.0
        assert c.bezier_basis_polynomial(3, 1, t) == pytest.approx(t**3 - 3 * t**2 + 3 * t, abs=1e-15)
        assert c.bezier_basis_polynomial(3, 2, t) == pytest.approx(3 * t**2 - 2 * t**3, abs=1e-15)
        assert c.bezier_basis_polynomial(3, 3, t) == pytest.approx(t**3, abs=1e-15)
    assert c.bezier_basis_polynomial(3, 2, np.array([0.0, 1.0])).tolist() == [0.0, 1.0]


# --- derivatives and differential geometry -------------------------------------------------------


@SETTINGS
@given(polygons(), st.integers(0, 4), unit_t)
def test_derivative_matches_exact_derivative_curve(points, order, t):
    n = len(points) - 1
    curve = c.BezierCurve(points)
    # k-th hodograph: n!/(n-k)! Delta^k P in Fractions, then de Casteljau.
    if order > n:
        expected = [0] * len(points[0])
    else:
        rows = [[Fraction(x) for x in p] for p in points]
        for _ in range(order):
            rows = [[b - a for a, b in zip(r0, r1)] for r0, r1 in zip(rows, rows[1:])]
        factor = math.perm(n, order)
        expected = [factor * x for x in exact_casteljau(rows, t)]
    derivative = c.derivative_at(curve, t, order)
    close(derivative, expected, scale_of(points) * max(1, math.perm(n, min(order, n))) * 2**order)
    hodo = c.derivative_curve(curve, order)
    close(c.point_at(hodo, t), expected, scale_of(points) * max(1, math.perm(n, min(order, n))) * 2**order)


def test_derivatives_up_to_and_the_batch_derivatives_at():
    curve = c.BezierCurve(SEED_POINTS)
    table = c.derivatives_up_to(curve, 0.5, 3)
    assert table.shape == (4, 2)
    for k in range(4):
        np.testing.assert_array_equal(table[k], c.derivative_at(curve, 0.5, k))
    np.testing.assert_array_equal(c.derivatives_up_to(curve, 1, 2), c.derivatives_up_to(curve, 1.0, 2))
    ts = np.linspace(0, 1, 9)
    batch = c.derivatives_at(curve, ts, 1)
    for t, row in zip(ts, batch):
        np.testing.assert_allclose(row, c.derivative_at(curve, t, 1), rtol=0, atol=1e-13)
    rational = c.BezierCurve(SEED_POINTS, [1, 2, 3, 2, 1])
    batch = c.derivatives_at(rational, ts, 2)
    for t, row in zip(ts, batch):
        np.testing.assert_array_equal(row, c.derivative_at(rational, t, 2))
    # the rational derivative against central differences
    h = 1e-5
    for t in (0.25, 0.5, 0.75):
        fd = (c.point_at(rational, t + h) - c.point_at(rational, t - h)) / (2 * h)
        np.testing.assert_allclose(c.derivative_at(rational, t), fd, rtol=1e-7, atol=1e-7)
    with pytest.raises(ValueError, match="derivative order"):
        c.derivative_at(curve, 0.5, -1)
    with pytest.raises(ValueError, match="derivative order"):
        c.derivatives_at(curve, ts, 10**6)


def test_curvature_of_the_parabola():
    # (0,0), (1/2,0), (1,1): x = t, y = t^2, kappa = 2 / (1 + 4x^2)^(3/2), turning left.
    parabola = c.BezierCurve([[0, 0], [0.5, 0], [1, 1]])
    for t in (0.0, 0.3, 0.5, 1.0):
        expected = 2 / (1 + 4 * t * t) ** 1.5
        assert c.curvature_at(parabola, t) == pytest.approx(expected, rel=1e-14)
        assert c.signed_curvature_at(parabola, t) == pytest.approx(expected, rel=1e-14)
        assert c.signed_curvature_at(c.reversed(parabola), 1 - t) == pytest.approx(-expected, rel=1e-14)
    np.testing.assert_allclose(c.unit_tangent_at(parabola, 0.0), [1, 0], atol=1e-15)
    np.testing.assert_allclose(c.unit_normal_at(parabola, 0.0), [0, 1], atol=1e-15)
    with pytest.raises(ValueError, match="plane curve"):
        c.signed_curvature_at(c.BezierCurve([[0, 0, 0], [1, 1, 1]]), 0.5)


# --- subdivision, construction, degree ------------------------------------------------------------


@SETTINGS
@given(polygons(), st.integers(1, 255).map(lambda i: i / 256), unit_t)
def test_split_keeps_the_curve(points, t, s):
    curve = c.BezierCurve(points)
    left, right = c.split_at(curve, t)
    scale = scale_of(points)
    close(c.point_at(left, s), exact_casteljau(points, Fraction(s) * Fraction(t)), scale, 1e-12)
    close(c.point_at(right, s), exact_casteljau(points, Fraction(t) + Fraction(s) * (1 - Fraction(t))), scale, 1e-12)
    np.testing.assert_array_equal(left.control_points[-1], c.point_at(curve, t))
    piece = c.segment(curve, 0.25, 0.75)
    close(c.point_at(piece, s), exact_casteljau(points, Fraction(1, 4) + Fraction(s) / 2), scale, 1e-12)
    close(c.point_at(c.reversed(curve), s), exact_casteljau(points, 1 - Fraction(s)), scale, 1e-12)


def test_rational_split_outside_refuses_non_positive_weights():
    curve = c.BezierCurve([[0, 0], [1, 1], [2, 0]], [1, 10, 1])
    left, right = c.split_at(curve, 0.5)
    assert left.is_rational and right.is_rational
    with pytest.raises(ValueError, match="not strictly inside the domain"):
        c.split_at(curve, -3.0)
    with pytest.raises(ValueError, match="weight"):
        c.split_at(curve, -3.0, extrapolate=True)
    with pytest.raises(ValueError, match="weight"):
        c.segment(curve, -3.0, 0.5, extrapolate=True)
    polynomial = c.BezierCurve(SEED_POINTS)
    left, _ = c.split_at(polynomial, 2.0, extrapolate=True)
    np.testing.assert_allclose(left.control_points[-1], [float(x) for x in exact_casteljau(SEED_POINTS, 2)])


@pytest.mark.parametrize("depth", [0, 1, 3, 6])
def test_subdivide_recursive_gives_the_dyadic_points(depth):
    curve = c.BezierCurve(SEED_POINTS)
    points = c.subdivide_recursive(curve, depth)
    assert points.shape == (2**depth + 1, 2)
    for i, p in enumerate(points):
        close(p, exact_casteljau(SEED_POINTS, Fraction(i, 2**depth)), 4)
    with pytest.raises(ValueError):
        c.subdivide_recursive(curve, -1)
    with pytest.raises(ValueError):
        c.subdivide_recursive(curve, 25)
    with pytest.raises(ValueError):
        c.subdivide_recursive(curve, 2, 1.0)


def test_casteljau_construction_levels():
    curve = c.BezierCurve(SEED_POINTS)
    levels = c.casteljau_construction(curve, 0.5)
    assert [level.shape for level in levels] == [(5 - r, 2) for r in range(5)]
    np.testing.assert_array_equal(levels[0], SEED_POINTS)
    np.testing.assert_array_equal(levels[-1][0], [2.25, 1.5])
    left, right = c.split_at(curve, 0.5)
    np.testing.assert_array_equal([level[0] for level in levels], left.control_points)
    with pytest.raises(ValueError):
        c.casteljau_construction(curve, 1.5)


@SETTINGS
@given(polygons(max_degree=6), st.integers(0, 3))
def test_elevation_keeps_the_curve_and_reduction_undoes_it(points, times):
    curve = c.BezierCurve(points)
    higher = c.elevate_degree(curve, times)
    assert higher.degree == curve.degree + times
    ts = np.linspace(0, 1, 17)
    scale = scale_of(points)
    np.testing.assert_allclose(c.points_at(higher, ts), c.points_at(curve, ts), rtol=0, atol=1e-13 * scale)
    if times >= 1:
        reduction = c.reduce_degree(higher)
        assert reduction.curve.degree == higher.degree - 1
        assert reduction.sampled_error <= reduction.error_bound + 1e-15 * scale
        assert reduction.error_bound <= 1e-10 * scale  # the elevated curve is exactly reducible


def test_reduce_degree_result_and_errors():
    curve = c.BezierCurve(SEED_POINTS)
    reduction = c.reduce_degree(curve)
    np.testing.assert_array_equal(c.point_at(reduction.curve, 0.0), [0, 0])
    np.testing.assert_array_equal(c.point_at(reduction.curve, 1.0), [4, 0])
    free = c.reduce_degree(curve, keep_end_points=False)
    assert free.sampled_error <= free.error_bound
    with pytest.raises(ValueError, match="degree 0"):
        c.reduce_degree(c.BezierCurve([[1, 2]]))
    with pytest.raises(ValueError, match="rational"):
        c.reduce_degree(c.BezierCurve(SEED_POINTS, [1, 1, 2, 1, 1]))
    with pytest.raises(ValueError):
        c.elevate_degree(curve, -1)
    with pytest.raises(ValueError):
        c.elevate_degree(curve, 10**6)
    assert pickle.loads(pickle.dumps(reduction)).curve == reduction.curve


def test_repeat_control_point():
    curve = c.BezierCurve(SEED_POINTS)
    pulled = c.repeat_control_point(curve, 2, 3)
    assert pulled.degree == 7
    np.testing.assert_array_equal(pulled.control_points[2:6], [[2, 2]] * 4)
    for index, extra in [(-1, 1), (5, 1), (0, -1), (0, 10**6)]:
        with pytest.raises(ValueError):
            c.repeat_control_point(curve, index, extra)


def test_vector_form_round_trip():
    vectors = c.to_vector_form(SEED_POINTS)
    np.testing.assert_array_equal(vectors, [[0, 0], [1, 2], [1, 0], [2, -1], [0, -1]])
    np.testing.assert_array_equal(c.from_vector_form(vectors), SEED_POINTS)


# --- affine maps and the homogeneous form -----------------------------------------------------------


@SETTINGS
@given(polygons(dims=(2,)), st.floats(-3, 3), dyadic, dyadic, unit_t)
def test_affine_invariance(points, angle, bx, by, t):
    curve = c.BezierCurve(points, [1 + i % 3 for i in range(len(points))])
    rotation = c.AffineMap.rotate_2d(angle)
    shift = c.AffineMap.translate([bx, by])
    both = shift.after(rotation)
    np.testing.assert_allclose(both.linear, rotation.linear)
    image = c.transformed(curve, both)
    scale = scale_of(points) + abs(bx) + abs(by)
    np.testing.assert_allclose(c.point_at(image, t), c.transformed_point(both, c.point_at(curve, t)),
                               rtol=0, atol=1e-13 * scale)


def test_affine_map_construction_and_errors():
    m = c.AffineMap([[2, 0], [0, 3]], [1, 1])
    assert m.dimension == 2
    np.testing.assert_array_equal(c.transformed_point(m, [1, 1]), [3, 4])
    assert pickle.loads(pickle.dumps(m)) == m
    assert c.AffineMap.identity(3) == c.AffineMap.scale(3, 1.0)
    with pytest.raises(ValueError, match="matrix"):
        c.AffineMap([[1, 2, 3]], [0])
    with pytest.raises(ValueError, match="translation"):
        c.AffineMap(np.eye(2), [0, 0, 0])
    with pytest.raises(ValueError, match="NaN"):
        c.AffineMap([[1, np.nan], [0, 1]], [0, 0])
    with pytest.raises(ValueError):
        c.AffineMap.identity(0)
    with pytest.raises(ValueError):
        c.AffineMap.translate([])
    with pytest.raises(ValueError):
        c.AffineMap.rotate_2d(math.inf)
    with pytest.raises(ValueError):
        c.AffineMap.identity(2).after(c.AffineMap.identity(3))
    with pytest.raises(ValueError):
        c.transformed_point(m, [1, 2, 3])
    with pytest.raises(ValueError, match="R\\^3"):
        c.transformed(c.BezierCurve([[0, 0, 0]]), m)


def test_homogeneous_round_trip():
    curve = c.BezierCurve(SEED_POINTS, [1, 2, 4, 2, 1])
    rows = c.homogeneous_points(curve)
    assert rows.shape == (5, 3)
    np.testing.assert_array_equal(rows[:, 2], [1, 2, 4, 2, 1])
    assert c.from_homogeneous(rows) == curve
    with pytest.raises(ValueError, match="weight 1"):
        c.from_homogeneous([[0, 0, 1], [1, 1, 0]])
    with pytest.raises(ValueError, match="columns"):
        c.from_homogeneous([[1], [2]])
    with pytest.raises(ValueError, match="infinite"):
        c.from_homogeneous([[1e300, 1e-300]])


# --- piecewise Bézier curves ---------------------------------------------------------------------------


def test_piecewise_bezier_curve():
    first = c.BezierCurve([[0, 0], [1, 1], [2, 0]])
    second = c.BezierCurve([[2, 0], [3, -1], [4, 0], [5, 1]])
    curve = c.PiecewiseBezierCurve([first, second])
    assert curve.size == 2 and len(curve) == 2 and curve.domain == (0.0, 2.0) and curve.dimension == 2
    assert curve.pieces == [first, second]
    assert c.locate(curve, 1.25) == (1, 0.25)
    assert c.locate(curve, 2.0) == (1, 1.0)
    np.testing.assert_array_equal(c.point_at(curve, 1.25), c.point_at(second, 0.25))
    np.testing.assert_array_equal(c.derivative_at(curve, 0.5, 1), c.derivative_at(first, 0.5, 1))
    us = np.linspace(0, 2, 9)
    np.testing.assert_array_equal(c.points_at(curve, us), [c.point_at(curve, u) for u in us])
    assert pickle.loads(pickle.dumps(curve)) == curve
    with pytest.raises(ValueError, match="outside the domain"):
        c.point_at(curve, 2.5)
    with pytest.raises(ValueError):
        c.points_at(curve, [-0.5])
    with pytest.raises(ValueError, match="at least one piece"):
        c.PiecewiseBezierCurve([])
    with pytest.raises(ValueError, match="dimension"):
        c.PiecewiseBezierCurve([first, c.BezierCurve([[0, 0, 0]])])


def test_piecewise_bezier_curve_from_model_json_lists():
    # Issue 39: the nested lists of model JSON's "pieces" were refused.
    pieces = [[[0, 0], [1, 1], [2, 0]], [[2, 0], [3, -1], [4, 0], [5, 1]]]
    curve = c.PiecewiseBezierCurve(pieces)
    assert curve == c.PiecewiseBezierCurve([c.BezierCurve(p) for p in pieces])
    assert curve == c.parse_models_json('{"type": "piecewise_bezier", "pieces": %s}' % pieces)[0]
    # Mixed with BezierCurve objects, and as one (m, n, d) numpy array.
    assert c.PiecewiseBezierCurve([c.BezierCurve(pieces[0]), np.array(pieces[1])]) == curve
    lines = c.PiecewiseBezierCurve(np.array([[[0, 0], [1, 0]], [[1, 0], [1, 1]]]))
    assert lines.size == 2 and c.point_at(lines, 1.5).tolist() == [1.0, 0.5]
    with pytest.raises(ValueError, match=r"coordinate 0 of pieces\[1\] 0 is NaN"):
        c.PiecewiseBezierCurve([pieces[0], [[np.nan, 0], [1, 1]]])
    with pytest.raises(ValueError, match=r"pieces\[0\] must be an \(n, d\) array"):
        c.PiecewiseBezierCurve([[1, 2, 3]])
    with pytest.raises(ValueError, match="got a string"):
        c.PiecewiseBezierCurve("abc")


# --- bad input and dtypes ----------------------------------------------------------------------------------


def test_bad_input_errors():
    with pytest.raises(ValueError, match="coordinate 1 of control_points 2 is NaN"):
        c.BezierCurve([[0, 0], [1, 1], [2, np.nan]])
    with pytest.raises(ValueError, match="infinite"):
        c.BezierCurve([[0, np.inf]])
    with pytest.raises(TypeError, match="complex"):
        c.BezierCurve(np.array([[0, 1j]]))
    with pytest.raises(TypeError):
        c.BezierCurve([["a", "b"]])
    with pytest.raises(ValueError, match="shape"):
        c.BezierCurve([0.0, 1.0, 2.0])
    with pytest.raises(ValueError, match="empty"):
        c.BezierCurve(np.empty((0, 2)))
    with pytest.raises(ValueError, match="weight 1 is 0"):
        c.BezierCurve(SEED_POINTS, [1, 0, 1, 1, 1])
    with pytest.raises(ValueError, match="weight 2 is -1"):
        c.BezierCurve(SEED_POINTS, [1, 1, -1, 1, 1])
    with pytest.raises(ValueError, match="3 weights for 5"):
        c.BezierCurve(SEED_POINTS, [1, 1, 1])
    curve = c.BezierCurve(SEED_POINTS)
    for bad in (1.5, -0.1, math.nan, math.inf):
        with pytest.raises(ValueError):
            c.point_at(curve, bad)
    with pytest.raises(ValueError, match="infinite"):
        c.point_at(curve, math.inf, extrapolate=True)
    with pytest.raises(ValueError):
        c.points_at(curve, 0.5)  # a float: use point_at
    with pytest.raises(ValueError):
        c.points_at(curve, np.zeros((2, 2)))


def test_dtypes_and_layouts_give_the_float64_result():
    reference = c.points_at(c.BezierCurve(np.array(SEED_POINTS, dtype=np.float64)), np.linspace(0, 1, 5))
    for points in (np.array(SEED_POINTS, dtype=np.float32), np.array(SEED_POINTS, dtype=np.int64),
                   np.asfortranarray(np.array(SEED_POINTS, dtype=np.float64)),
                   np.array([[p[0], -1, p[1]] for p in SEED_POINTS], dtype=np.float64)[:, ::2], SEED_POINTS):
        np.testing.assert_array_equal(c.points_at(c.BezierCurve(points), np.linspace(0, 1, 5)), reference)
    ts = np.linspace(0, 1, 10)[::2]
    curve = c.BezierCurve(SEED_POINTS)
    np.testing.assert_array_equal(c.points_at(curve, ts), c.points_at(curve, np.ascontiguousarray(ts)))
    np.testing.assert_array_equal(c.points_at(curve, ts.astype(np.float32)),
                                  c.points_at(curve, ts.astype(np.float32).astype(np.float64)))
    np.testing.assert_array_equal(c.points_at(curve, np.array([0, 1])), c.points_at(curve, [0.0, 1.0]))


def test_pickle_round_trip():
    for curve in (c.BezierCurve(SEED_POINTS), c.BezierCurve(SEED_POINTS, [1, 2, 3, 2, 1])):
        again = pickle.loads(pickle.dumps(curve))
        assert again == curve and again.is_rational == curve.is_rational
        np.testing.assert_array_equal(again.weights, curve.weights)
    assert "degree=4" in repr(c.BezierCurve(SEED_POINTS))
