"""The bspline layer through the Python module (python/src/bspline.cpp and the
BSplineCurve class of bspline_curve.cpp).

References: scipy.interpolate.BSpline (basis_element, design_matrix, curve
values and derivatives: FITPACK-style de Boor written by other people) and
the definitions of the knot builders. The exact algorithms (knot insertion,
refinement, degree elevation, splitting, joining, Bézier pieces,
reparameterization) must keep the curve: hypothesis properties, seeded
(derandomize=True), compared with scipy's evaluation of the original curve.
"""

import pickle

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st
from scipy.interpolate import BSpline

import casteljau as c

SETTINGS = settings(derandomize=True, max_examples=40, deadline=None)
KNOTS = [0, 0, 0, 0.25, 0.5, 0.5, 0.75, 1, 1, 1]  # degree 2, 7 control points, a double knot
POINTS = [[0, 0], [1, 2], [2, 2], [3, 0], [4, -1], [5, 1], [6, 0]]


def scipy_points(curve, us, nu=0):
    """Reference values of a polynomial BSplineCurve by scipy."""
    spline = BSpline(curve.knots, curve.control_points, curve.degree, extrapolate=True)
    return spline.derivative(nu)(us) if nu else spline(us)


def scale_of(points):
    return max(1.0, float(np.max(np.abs(points))))


@st.composite
def curves(draw, clamped=None, max_degree=5):
    """Random polynomial B-splines: degree 1..5, 2D/3D, repeated interior knots, clamped or not."""
    p = draw(st.integers(1, max_degree))
    d = draw(st.sampled_from([2, 3]))
    interior = sorted(draw(st.lists(st.integers(1, 15), min_size=0, max_size=6)))
    # multiplicity at most p
    kept = [u for i, u in enumerate(interior) if interior[:i].count(u) < p]
    is_clamped = draw(st.booleans()) if clamped is None else clamped
    if is_clamped:
        knots = [0.0] * (p + 1) + [u / 16 for u in kept] + [1.0] * (p + 1)
    else:
        knots = [-(p - i) / 8 for i in range(p)] + [0.0] + [u / 16 for u in kept] + [1.0] + \
                [1 + (i + 1) / 8 for i in range(p)]
    n = len(knots) - p - 1
    points = [[draw(st.integers(-32, 32)) / 8 for _ in range(d)] for _ in range(n)]
    return c.BSplineCurve(p, knots, points)


def same_curve(a, b, us, scale, rel=1e-12):
    np.testing.assert_allclose(c.points_at(a, us), c.points_at(b, us), rtol=0, atol=rel * scale)


# --- the basis against scipy ---------------------------------------------------------------------------


@pytest.mark.parametrize("degree,knots", [
    (2, KNOTS),
    (3, [0, 0, 0, 0, 1, 2, 2, 3, 4, 4, 4, 4]),
    (1, [0, 1, 2, 3, 4, 5]),
    (3, [-3, -2, -1, 0, 1, 2, 3, 4, 5, 6]),
])
def test_basis_function_matches_scipy_basis_element(degree, knots):
    knots = np.asarray(knots, float)
    n = len(knots) - degree - 2
    us = np.linspace(knots[0], knots[-1], 97)
    for i in range(n + 1):
        element = BSpline.basis_element(knots[i:i + degree + 2], extrapolate=False)
        expected = np.nan_to_num(element(us))
        values = c.basis_function(knots, degree, i, us)
        # scipy's basis_element is half-open at its last knot; ours closes the end of the domain
        inside = us < knots[i + degree + 1]
        np.testing.assert_allclose(values[inside], expected[inside], rtol=0, atol=1e-14)
        for u, v in zip(us[::12], values[::12]):
            assert c.basis_function(knots, degree, i, float(u)) == v


def test_basis_functions_match_scipy_design_matrix():
    knots = np.array(KNOTS, float)
    p = 2
    us = np.linspace(0, 1, 41)
    matrix = BSpline.design_matrix(us, knots, p).toarray()
    for row, u in zip(matrix, us):
        span = c.find_span(knots, p, u)
        assert p <= span <= len(knots) - p - 2 and knots[span] < knots[span + 1]
        assert knots[span] <= u and (u < knots[span + 1] or u == knots[-1])
        values = c.basis_functions(knots, p, span, u)
        assert values.shape == (p + 1,)
        np.testing.assert_allclose(values, row[span - p:span + 1], rtol=0, atol=1e-15)
        assert abs(values.sum() - 1) <= 4e-16


def test_basis_function_derivatives_match_scipy():
    knots = np.array([0, 0, 0, 0, 0.3, 0.5, 0.8, 1, 1, 1, 1], float)
    p = 3
    n = len(knots) - p - 2
    for u in (0.0, 0.1, 0.3, 0.4, 0.5, 0.65, 1.0):
        span = c.find_span(knots, p, u)
        table = c.basis_function_derivatives(knots, p, span, u, 5)
        assert table.shape == (6, p + 1)
        np.testing.assert_array_equal(table[4:], 0.0)
        for r in range(p + 1):
            i = span - p + r
            coefficients = np.zeros(n + 1)
            coefficients[i] = 1.0
            spline = BSpline(knots, coefficients, p)
            for j in range(p + 1):
                expected = spline.derivative(j)(u) if j else spline(u)
                assert table[j, r] == pytest.approx(expected, abs=1e-11 * 10**j)


@SETTINGS
@given(curves(), st.integers(0, 64).map(lambda i: i / 64))
def test_partition_of_unity(curve, f):
    knots = curve.knots
    lower, upper = curve.domain
    u = lower + f * (upper - lower)
    span = c.find_span(knots, curve.degree, u)
    assert abs(c.basis_functions(knots, curve.degree, span, u).sum() - 1) <= 1e-14


def test_basis_errors():
    with pytest.raises(ValueError, match="smaller than knot"):
        c.find_span([0, 0, 1, 0.5, 1, 1], 1, 0.5)
    with pytest.raises(ValueError, match="at least"):
        c.find_span([0, 1], 1, 0.5)
    with pytest.raises(ValueError, match="degree"):
        c.find_span(KNOTS, -1, 0.5)
    with pytest.raises(ValueError, match="span"):
        c.basis_functions(KNOTS, 2, 1, 0.5)
    with pytest.raises(ValueError, match="empty"):
        c.basis_functions(KNOTS, 2, 4, 0.5)  # t_4 = t_5 = 0.5
    with pytest.raises(ValueError, match="span"):
        c.basis_function_derivatives(KNOTS, 2, 9, 0.5, 1)
    with pytest.raises(ValueError, match="order"):
        c.basis_function_derivatives(KNOTS, 2, 3, 0.5, -1)
    with pytest.raises(ValueError, match="index"):
        c.basis_function(KNOTS, 2, 7, 0.5)
    with pytest.raises(ValueError, match="NaN"):
        c.basis_function(KNOTS, 2, 1, [0.5, np.nan])
    with pytest.raises(ValueError, match="NaN"):
        c.find_span(KNOTS, 2, np.nan)
    with pytest.raises(ValueError, match="empty"):
        c.find_span([0, 1, 1, 1, 2, 3], 2, 1.0)
    with pytest.raises(TypeError):
        c.find_span(np.array(KNOTS, complex), 2, 0.5)


# --- knot vectors ----------------------------------------------------------------------------------------


def test_knot_builders():
    np.testing.assert_array_equal(c.clamped_uniform_knots(2, 5), [0, 0, 0, 1 / 3, 2 / 3, 1, 1, 1])
    np.testing.assert_array_equal(c.clamped_uniform_knots(1, 3, (2.0, 4.0)), [2, 2, 3, 4, 4])
    np.testing.assert_allclose(c.uniform_knots(2, 4), [-1, -0.5, 0, 0.5, 1, 1.5, 2], rtol=0, atol=1e-15)
    periodic = c.periodic_knots(3, 5)
    assert len(periodic) == 5 + 2 * 3 + 1
    assert periodic[3] == 0 and periodic[3 + 5] == 1
    np.testing.assert_allclose(np.diff(periodic), 0.2, rtol=1e-12)
    np.testing.assert_array_equal(c.knots_from_rhino([0, 0, 0.5, 1, 1], 2, 4), [0, 0, 0, 0.5, 1, 1, 1])
    assert c.knot_multiplicities(KNOTS) == [(0.0, 3), (0.25, 1), (0.5, 2), (0.75, 1), (1.0, 3)]
    assert c.multiplicity_of(KNOTS, 0.5) == 2 and c.multiplicity_of(KNOTS, 0.3) == 0
    assert c.validate_knots(KNOTS, 2, 7) is None
    for args in [(1, 1), (-1, 5), (2, 2)]:
        with pytest.raises(ValueError):
            c.clamped_uniform_knots(*args)
    with pytest.raises(ValueError, match="domain"):
        c.uniform_knots(2, 4, (1.0, 1.0))
    with pytest.raises(ValueError):
        c.periodic_knots(2, 0)
    with pytest.raises(ValueError, match="Rhino"):
        c.knots_from_rhino([0, 1], 2, 4)


def test_validate_knots_errors():
    with pytest.raises(ValueError, match="knot 4 \\(0.2\\) is smaller than knot 3 \\(0.25\\)"):
        c.validate_knots([0, 0, 0, 0.25, 0.2, 0.5, 0.75, 1, 1, 1], 2, 7)
    with pytest.raises(ValueError, match="9 knots given"):
        c.validate_knots(KNOTS[:-1], 2, 7)
    with pytest.raises(ValueError, match="multiplicity 4"):
        c.validate_knots([0, 0, 0, 0, 1, 1, 1], 2, 4)
    with pytest.raises(ValueError):
        c.validate_knots(KNOTS, 2, 2)  # fewer control points than degree + 1
    with pytest.raises(ValueError, match="NaN"):
        c.validate_knots([0, 0, 0, np.nan, 1, 1, 1], 2, 4)


# --- curves against scipy ------------------------------------------------------------------------------------


@SETTINGS
@given(curves())
def test_curve_points_and_derivatives_match_scipy(curve):
    lower, upper = curve.domain
    us = np.linspace(lower, upper, 33)
    scale = scale_of(curve.control_points)
    np.testing.assert_allclose(c.points_at(curve, us), scipy_points(curve, us), rtol=0, atol=1e-12 * scale)
    for u in us[::8]:
        np.testing.assert_allclose(c.point_at(curve, u), scipy_points(curve, u), rtol=0, atol=1e-12 * scale)
    derivative_scale = scale * curve.degree / min(np.diff(np.unique(curve.knots)))
    np.testing.assert_allclose(c.derivatives_at(curve, us[:-1], 1), scipy_points(curve, us[:-1], 1),
                               rtol=0, atol=1e-11 * derivative_scale)


# --- exact algorithms keep the curve ------------------------------------------------------------------------


@SETTINGS
@given(curves(), st.integers(1, 63).map(lambda i: i / 64), st.integers(1, 3))
def test_insert_refine_elevate_split_keep_the_curve(curve, u, times):
    us = np.linspace(0, 1, 29)
    scale = scale_of(curve.control_points)
    reference = scipy_points(curve, us)
    multiplicity = c.multiplicity_of(curve.knots, u)
    allowed = min(times, curve.degree + 1 - multiplicity)
    inserted = c.insert_knot(curve, u, allowed)
    assert c.multiplicity_of(inserted.knots, u) == multiplicity + allowed
    np.testing.assert_allclose(c.points_at(inserted, us), reference, rtol=0, atol=1e-12 * scale)
    refined = c.refine_knots(curve, [0.125, 0.375, u])
    np.testing.assert_allclose(c.points_at(refined, us), reference, rtol=0, atol=1e-12 * scale)
    elevated = c.elevate_degree(curve, times)
    assert elevated.degree == curve.degree + times
    np.testing.assert_allclose(c.points_at(elevated, us), reference, rtol=0, atol=1e-11 * scale)
    first, second = c.split_at(curve, u)
    assert first.domain == (0.0, u) and second.domain == (u, 1.0)
    left = us[us <= u]
    right = us[us >= u]
    np.testing.assert_allclose(c.points_at(first, left), scipy_points(curve, left), rtol=0, atol=1e-12 * scale)
    np.testing.assert_allclose(c.points_at(second, right), scipy_points(curve, right), rtol=0, atol=1e-12 * scale)
    joined = c.join(first, second)
    assert joined.gap <= 1e-12 * scale and joined.joint == u
    np.testing.assert_allclose(c.points_at(joined.curve, us), reference, rtol=0, atol=1e-11 * scale)


@SETTINGS
@given(curves())
def test_reverse_reparameterize_clamp_pieces_keep_the_curve(curve):
    us = np.linspace(0, 1, 23)
    scale = scale_of(curve.control_points)
    reference = scipy_points(curve, us)
    np.testing.assert_allclose(c.points_at(c.reversed(curve), 1 - us), reference, rtol=0, atol=1e-12 * scale)
    moved = c.reparameterized(curve, (2.0, 6.0))
    assert moved.domain == (2.0, 6.0)
    np.testing.assert_allclose(c.points_at(moved, 2 + 4 * us), reference, rtol=0, atol=1e-12 * scale)
    clamped = c.clamped(curve)
    np.testing.assert_allclose(clamped.control_points[0], reference[0], rtol=0, atol=1e-12 * scale)
    np.testing.assert_allclose(c.points_at(clamped, us), reference, rtol=0, atol=1e-12 * scale)
    pieces = c.to_bezier_pieces(curve)
    breaks = pieces.breakpoints
    assert len(pieces) == len(breaks) - 1 and breaks[0] == 0 and breaks[-1] == 1
    for a, b, piece in zip(breaks, breaks[1:], pieces.pieces):
        assert piece.degree == curve.degree
        local = np.linspace(0, 1, 5)
        np.testing.assert_allclose(c.points_at(piece, local), scipy_points(curve, a + local * (b - a)),
                                   rtol=0, atol=1e-12 * scale)
    back = c.from_bezier_pieces(pieces)
    np.testing.assert_allclose(c.points_at(back, us), reference, rtol=0, atol=1e-12 * scale)
    smooth = c.remove_knots(back, 1e-9 * scale)
    assert smooth.error_bound <= 1e-9 * scale
    np.testing.assert_allclose(c.points_at(smooth.curve, us), reference, rtol=0, atol=1e-9 * scale)


def test_remove_knot_undoes_insertion():
    curve = c.BSplineCurve(2, KNOTS, POINTS)
    inserted = c.insert_knot(curve, 0.6, 2)
    removal = c.remove_knot(inserted, 0.6, 2, 1e-12)
    assert removal.removed == 2 and removal.error_bound <= 1e-12
    np.testing.assert_allclose(removal.curve.knots, KNOTS)
    np.testing.assert_allclose(removal.curve.control_points, POINTS, atol=1e-13)
    assert "removed=2" in repr(removal)
    assert pickle.loads(pickle.dumps(removal)).curve == removal.curve
    with pytest.raises(ValueError, match="not a knot"):
        c.remove_knot(curve, 0.3, 1, 1e-6)
    with pytest.raises(ValueError, match="tolerance"):
        c.remove_knot(inserted, 0.6, 1, 0.0)
    with pytest.raises(ValueError, match="tolerance"):
        c.remove_knots(inserted, np.nan)


def test_degree_reduction_and_continuity():
    curve = c.BSplineCurve(2, KNOTS, POINTS)
    elevated = c.elevate_degree(curve)
    reduction = c.reduce_degree(elevated, 1e-9)
    assert reduction.curve.degree == 2 and reduction.error_bound <= 1e-9
    same_curve(reduction.curve, curve, np.linspace(0, 1, 31), 6, 1e-9)
    with pytest.raises(ValueError, match="degree"):
        c.reduce_degree(c.BSplineCurve(1, [0, 0, 1, 1], [[0, 0], [1, 1]]), 1.0)
    with pytest.raises(ValueError, match="tolerance"):
        c.reduce_degree(elevated, -1.0)
    knots = c.continuity_at_knots(curve)
    assert [(k.value, k.multiplicity, k.predicted) for k in knots] == [(0.25, 1, 1), (0.5, 2, 0), (0.75, 1, 1)]
    assert all(k.measured.parametric >= k.predicted for k in knots)
    assert c.continuity_at(curve, 0.3).parametric == 2
    for u in (0.0, 1.0, np.nan, 2.0):
        with pytest.raises(ValueError):
            c.continuity_at(curve, u)


def test_join_and_bezier_bridges():
    bezier = c.BezierCurve([[0, 0], [1, 2], [2, 2], [4, 1], [4, 0]])
    spline = c.to_bspline(bezier)
    assert spline.degree == 4 and spline.knots.tolist() == [0] * 5 + [1] * 5
    us = np.linspace(0, 1, 11)
    np.testing.assert_allclose(c.points_at(spline, us), c.points_at(bezier, us), rtol=0, atol=1e-14)
    piecewise = c.PiecewiseBezierCurve([bezier, c.BezierCurve([[4, 0], [5, -1], [6, 0]])])
    pieces = c.to_bezier_pieces(piecewise)
    assert pieces.breakpoints.tolist() == [0, 1, 2]
    assert c.to_piecewise_bezier(pieces) == piecewise
    joined = c.from_bezier_pieces(pieces)
    np.testing.assert_allclose(c.point_at(joined, 1.5), c.point_at(piecewise, 1.5), atol=1e-14)
    with pytest.raises(ValueError, match="breakpoint"):
        c.from_bezier_pieces(c.BezierPieces([0, 1], pieces.pieces))
    with pytest.raises(ValueError):
        c.to_piecewise_bezier(c.BezierPieces([0], []))
    with pytest.raises(ValueError, match="do not meet"):
        c.join(spline, c.to_bspline(c.BezierCurve([[9, 9], [10, 10]])))
    with pytest.raises(ValueError, match="dimension"):
        c.join(spline, c.to_bspline(c.BezierCurve([[4, 0, 0], [10, 10, 0]])))
    assert pickle.loads(pickle.dumps(pieces)) == pieces


def test_make_periodic_is_closed():
    square = [[0, 0], [1, 0], [1, 1], [0, 1]]
    curve = c.make_periodic(3, square)
    assert curve.degree == 3 and len(curve.control_points) == 7
    start, end = c.point_at(curve, 0.0), c.point_at(curve, 1.0)
    np.testing.assert_allclose(start, end, atol=1e-15)
    np.testing.assert_allclose(c.derivative_at(curve, 0.0, 1), c.derivative_at(curve, 1.0, 1), atol=1e-13)
    np.testing.assert_allclose(curve.knots, c.periodic_knots(3, 4))
    with pytest.raises(ValueError):
        c.make_periodic(0, square)
    with pytest.raises(ValueError):
        c.make_periodic(4, square)
    with pytest.raises(ValueError):
        c.make_periodic(2, square, domain=(1.0, 0.0))


def test_homogeneous_round_trip_and_nurbs_insertion():
    weights = [1, 2, 1, 3, 1, 1, 2]
    curve = c.BSplineCurve(2, KNOTS, POINTS, weights)
    rows = c.homogeneous_points(curve)
    assert rows.shape == (7, 3)
    assert c.from_homogeneous(2, KNOTS, rows) == curve
    us = np.linspace(0, 1, 17)
    same_curve(c.insert_knot(curve, 0.3, 2), curve, us, 6)
    same_curve(c.elevate_degree(curve), curve, us, 6, 1e-11)
    with pytest.raises(ValueError, match="weight 1"):
        c.from_homogeneous(2, KNOTS, np.column_stack([POINTS, [1, -1, 1, 1, 1, 1, 1]]))
    with pytest.raises(ValueError, match="knots"):
        c.from_homogeneous(2, KNOTS[:-1], rows)


# --- errors and dtypes ---------------------------------------------------------------------------------------


def test_curve_errors():
    with pytest.raises(ValueError, match="smaller than knot"):
        c.BSplineCurve(2, [0, 0, 0, 0.5, 0.25, 1, 1, 1], POINTS[:5])
    with pytest.raises(ValueError, match="weight 3 is 0"):
        c.BSplineCurve(2, KNOTS, POINTS, [1, 1, 1, 0, 1, 1, 1])
    with pytest.raises(ValueError, match="weight 0 is -2"):
        c.BSplineCurve(2, KNOTS, POINTS, [-2, 1, 1, 1, 1, 1, 1])
    with pytest.raises(ValueError, match="coordinate 0 of control_points 6 is NaN"):
        c.BSplineCurve(2, KNOTS, POINTS[:-1] + [[np.nan, 0]])
    with pytest.raises(TypeError, match="complex"):
        c.BSplineCurve(2, KNOTS, np.array(POINTS, complex))
    with pytest.raises(ValueError, match="shape"):
        c.BSplineCurve(2, KNOTS, np.zeros((7, 2, 1)))
    with pytest.raises(ValueError, match="empty"):
        c.BSplineCurve(0, [0, 1], np.empty((0, 2)))
    curve = c.BSplineCurve(2, KNOTS, POINTS)
    with pytest.raises(ValueError, match="outside the domain"):
        c.insert_knot(curve, 1.5)
    with pytest.raises(ValueError, match="multiplicity"):
        c.insert_knot(curve, 0.5, 2)
    with pytest.raises(ValueError):
        c.insert_knot(curve, 0.5, -1)
    with pytest.raises(ValueError):
        c.refine_knots(curve, [0.5, np.nan])
    with pytest.raises(ValueError, match="strictly inside"):
        c.split_at(curve, 1.0)
    with pytest.raises(ValueError):
        c.elevate_degree(curve, -1)
    with pytest.raises(ValueError):
        c.reparameterized(curve, (1.0, 1.0))


def test_dtypes_and_layouts_give_the_float64_result():
    reference = c.BSplineCurve(2, KNOTS, POINTS)
    variants = [
        c.BSplineCurve(2, np.array(KNOTS, np.float32), np.array(POINTS, np.float32)),
        c.BSplineCurve(2, np.array(KNOTS) * 4, np.array(POINTS, np.int32)),
        c.BSplineCurve(2, np.array(KNOTS)[::-1][::-1], np.asfortranarray(np.array(POINTS, float))),
        c.BSplineCurve(2, np.repeat(KNOTS, 2)[::2], np.array([[x, 7, y] for x, y in POINTS], float)[:, ::2]),
    ]
    assert variants[0] == reference and variants[2] == reference and variants[3] == reference
    np.testing.assert_array_equal(variants[1].control_points, POINTS)
    knots = np.array(KNOTS)
    assert c.find_span(knots.astype(np.float32), 2, 0.6) == c.find_span(knots, 2, 0.6)
    np.testing.assert_array_equal(c.basis_function(knots, 2, 3, np.linspace(0, 1, 10)[::3]),
                                  c.basis_function(knots, 2, 3, np.linspace(0, 1, 10)[::3].copy()))


def test_pickle_round_trip():
    for curve in (c.BSplineCurve(2, KNOTS, POINTS), c.BSplineCurve(2, KNOTS, POINTS, [1, 2, 1, 3, 1, 1, 2])):
        assert pickle.loads(pickle.dumps(curve)) == curve
    curve = c.BSplineCurve(2, KNOTS, POINTS)
    joined = c.join(*c.split_at(curve, 0.6))
    again = pickle.loads(pickle.dumps(joined))
    assert again.curve == joined.curve and again.continuity == joined.continuity
    knot = c.continuity_at_knots(curve)[0]
    assert pickle.loads(pickle.dumps(knot)) == knot
