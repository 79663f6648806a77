"""casteljau.plot: the artists hold the right data.

References: exact rational arithmetic (fractions.Fraction) for Bézier curves,
their de Casteljau levels, blossoms (the control polygons of pieces) and the
Bernstein polynomials; scipy.interpolate.BSpline for B-spline curves,
basis functions (basis_element, design_matrix) and tensor-product surfaces;
seed 004's worked value B(0.5) = (2.25, 1.5) for (0,0),(1,2),(2,2),(4,1),(4,0).
"""

from __future__ import annotations

import math
import os
import pathlib
import subprocess
import sys
from fractions import Fraction

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402
from hypothesis import given, settings  # noqa: E402
from hypothesis import strategies as st  # noqa: E402
from scipy.interpolate import BSpline  # noqa: E402

import casteljau as cj  # noqa: E402
from casteljau import plot  # noqa: E402

REPOSITORY = pathlib.Path(__file__).resolve().parents[2]
SEED_POLYGON = [(0, 0), (1, 2), (2, 2), (4, 1), (4, 0)]


def require(*names):
    """Skip while another part of the module has not bound these names yet."""
    missing = [name for name in names if not hasattr(cj, name)]
    if missing:
        pytest.skip(f"casteljau lacks {', '.join(missing)}")


@pytest.fixture(autouse=True)
def close_figures():
    yield
    plt.close("all")


def xy(line) -> np.ndarray:
    return np.asarray(line.get_xydata(), dtype=float)


def scale_of(points) -> float:
    return float(np.max(np.abs(np.asarray(points, dtype=float)))) or 1.0


# ---------------------------------------------------------- exact references --


def exact_levels(points, t):
    """The de Casteljau triangle in Fractions: level 0 the points, level n the point C(t)."""
    t = Fraction(t)
    level = [tuple(Fraction(c) for c in p) for p in points]
    levels = [level]
    while len(level) > 1:
        level = [tuple((1 - t) * a + t * b for a, b in zip(p, q)) for p, q in zip(level, level[1:])]
        levels.append(level)
    return levels


def exact_point(points, t):
    return exact_levels(points, t)[-1][0]


def exact_blossom(points, parameters):
    """The polar form b(s_1, ..., s_n) in Fractions (one de Casteljau step per argument)."""
    level = [tuple(Fraction(c) for c in p) for p in points]
    for s in parameters:
        s = Fraction(s)
        level = [tuple((1 - s) * a + s * b for a, b in zip(p, q)) for p, q in zip(level, level[1:])]
    return level[0]


def exact_segment(points, a, b):
    """Control points of C on [a, b]: Q_i = b(a^(n-i), b^i) (Farin, ch. 4)."""
    n = len(points) - 1
    return [exact_blossom(points, [a] * (n - i) + [b] * i) for i in range(n + 1)]


def exact_bernstein(n, k, t):
    t = Fraction(t)
    return math.comb(n, k) * t**k * (1 - t) ** (n - k)


def as_float(points):
    return np.array([[float(c) for c in p] for p in points])


def scipy_curve(curve):
    return BSpline(np.asarray(curve.knots), np.asarray(curve.control_points), curve.degree)


# ---------------------------------------------------------------- import ----


def test_import_casteljau_does_not_import_matplotlib():
    package = pathlib.Path(os.path.abspath(cj.__file__)).parent.parent
    code = "import sys, casteljau; assert 'matplotlib' not in sys.modules; import casteljau.plot; print('ok')"
    env = {**os.environ, "PYTHONPATH": str(package)}
    result = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env, timeout=60)
    assert result.returncode == 0, result.stderr
    assert result.stdout.strip() == "ok"


# ---------------------------------------------------------------- curves ----


def test_bezier_curve_line_lies_on_the_exact_curve_and_polygon_holds_control_points():
    require("BezierCurve", "points_at")
    curve = cj.BezierCurve(SEED_POLYGON)
    fig, ax = plt.subplots()
    artists = plot.curve(curve, 33, ax=ax, polygon=True)
    line, polygon = artists[0], artists[1]
    points = xy(line)
    ts = np.linspace(0, 1, 33)
    assert points.shape == (33, 2)
    exact = as_float([exact_point(SEED_POLYGON, t) for t in ts])
    np.testing.assert_allclose(points, exact, rtol=0, atol=1e-14 * scale_of(SEED_POLYGON))
    np.testing.assert_array_equal(xy(polygon), np.array(SEED_POLYGON, dtype=float))
    np.testing.assert_array_equal(points[16], [2.25, 1.5])  # the seed's worked value, exact in binary


def test_curve_with_explicit_parameters_and_styling_passes_through():
    require("BezierCurve", "points_at")
    curve = cj.BezierCurve(SEED_POLYGON)
    ts = np.array([0.0, 0.5, 0.25, 1.0])
    (line,) = plot.curve(curve, ts, color="m", linewidth=3)
    np.testing.assert_array_equal(xy(line), as_float([exact_point(SEED_POLYGON, t) for t in ts]))
    assert line.get_color() == "m" and line.get_linewidth() == 3


def test_matplotlib_short_aliases_replace_the_default_style():
    # ls, lw, c, ms are matplotlib's own aliases: they override the helpers' defaults
    # (written in full) instead of meeting them ("Got both 'linestyle' and 'ls'").
    require("BezierCurve", "points_at")
    curve = cj.BezierCurve(SEED_POLYGON)
    (polygon,) = plot.control_polygon(curve, ls=":", c="g", ms=9)
    assert polygon.get_linestyle() == ":" and polygon.get_color() == "g" and polygon.get_markersize() == 9
    lines = plot.bernstein_basis(3, lw=2.5)
    assert all(line.get_linewidth() == 2.5 for line in lines)
    (line, *_) = plot.curve(curve, polygon=True, polygon_kw={"lw": 4})
    assert line.get_linewidth() != 4
    plt.close("all")


def test_axes_may_come_first_and_none_means_current_axes():
    require("BezierCurve", "points_at")
    curve = cj.BezierCurve(SEED_POLYGON)
    fig, (first, second) = plt.subplots(1, 2)
    plt.sca(first)
    assert all(a.axes is first for a in plot.curve(curve))
    assert all(a.axes is second for a in plot.curve(second, curve, polygon=True))
    plt.sca(second)
    assert plot.bernstein_basis(3)[0].axes is second
    assert plot.control_polygon(curve)[0].axes is second
    with pytest.raises(TypeError):
        plot.curve(first, curve, ax=second)


def test_bspline_curve_matches_scipy_and_keeps_its_knots():
    curve = cj.BSplineCurve(3, [0, 0, 0, 0, 0.3, 0.5, 0.5, 1, 1, 1, 1],
                            [(0, 0), (1, 3), (2, -1), (3, 2), (4, 0), (5, 4), (6, 1)])
    reference = scipy_curve(curve)
    (line,) = plot.curve(curve, 50)
    points = xy(line)
    # 50 spread parameters plus the interior knots 0.3 and 0.5, in order.
    assert points.shape == (52, 2)
    for knot in (0.3, 0.5):
        assert np.min(np.linalg.norm(points - reference(knot), axis=1)) < 1e-13 * 6
    us = np.linspace(0, 1, 17)
    (line,) = plot.curve(curve, us)
    np.testing.assert_allclose(xy(line), reference(us), rtol=0, atol=1e-13 * 6)


def test_piecewise_curve_and_its_polygons():
    require("BezierCurve", "PiecewiseBezierCurve", "points_at")
    a = [(0, 0), (1, 1), (2, 0)]
    b = [(2, 0), (3, -1), (4, 1), (5, 0)]
    curve = cj.PiecewiseBezierCurve([cj.BezierCurve(a), cj.BezierCurve(b)])
    artists = plot.curve(curve, np.array([0, 0.5, 1, 1.25, 2]), polygon=True)
    expected = [exact_point(a, 0), exact_point(a, 0.5), exact_point(b, 0), exact_point(b, 0.25), exact_point(b, 1)]
    np.testing.assert_allclose(xy(artists[0]), as_float(expected), rtol=0, atol=1e-14 * 5)
    assert len(artists) == 3
    np.testing.assert_array_equal(xy(artists[1]), np.array(a, dtype=float))
    np.testing.assert_array_equal(xy(artists[2]), np.array(b, dtype=float))


def test_curve_in_3d_on_a_3d_axes():
    require("BezierCurve", "points_at")
    control = [(0, 0, 0), (1, 2, 1), (3, 1, 2), (4, 0, 0)]
    curve = cj.BezierCurve(control)
    (line,) = plot.curve(curve, 9)  # empty figure: a 3D axes is made
    assert line.axes.name == "3d"
    xs, ys, zs = line.get_data_3d()
    exact = as_float([exact_point(control, t) for t in np.linspace(0, 1, 9)])
    np.testing.assert_allclose(np.column_stack([xs, ys, zs]), exact, rtol=0, atol=1e-14 * 4)
    fig, ax = plt.subplots()
    with pytest.raises(ValueError, match="3D"):
        plot.curve(curve, ax=ax)


def test_curve_in_1d_is_drawn_as_a_graph():
    require("BezierCurve", "points_at")
    curve = cj.BezierCurve([[0.0], [3.0], [1.0]])
    line, polygon = plot.curve(curve, 5, polygon=True)
    ts = np.linspace(0, 1, 5)
    np.testing.assert_allclose(xy(line)[:, 0], ts)
    np.testing.assert_allclose(xy(line)[:, 1], [float(exact_point([[0], [3], [1]], t)[0]) for t in ts], atol=1e-14)
    np.testing.assert_array_equal(xy(polygon), [[0, 0], [0.5, 3], [1, 1]])


def test_bad_input_raises():
    require("BezierCurve")
    curve = cj.BezierCurve(SEED_POLYGON)
    with pytest.raises(TypeError):
        plot.curve([(0, 0), (1, 1)])
    with pytest.raises(TypeError):
        plot.curve("curve")
    with pytest.raises(TypeError):
        plot.tangents(None)
    with pytest.raises(TypeError):
        plot.de_casteljau(cj.BSplineCurve(1, [0, 0, 1, 1], [(0, 0), (1, 1)]), 0.5)
    with pytest.raises(TypeError):
        plot.de_boor(curve, 0.5)
    with pytest.raises(TypeError):
        plot.subdivision(curve, 2.5)
    with pytest.raises(TypeError):
        plot.surface_wireframe(curve)
    with pytest.raises(TypeError):
        plot.bernstein_basis(2.5)
    with pytest.raises(TypeError):
        plot.control_polygon(np.array([[1 + 1j, 0], [0, 1]]))
    with pytest.raises(TypeError):
        plot.curve(curve, ax="not an axes")
    with pytest.raises(ValueError):
        plot.control_polygon(np.array([1.0, 2.0, 3.0]))
    with pytest.raises(ValueError):
        plot.curve(curve, 1)
    with pytest.raises(ValueError):
        plot.curve(curve, np.array([0.0, 1.5]))  # outside the domain: the batch function refuses it
    with pytest.raises(ValueError):
        plot.curve(curve, np.array([0.0, np.nan]))
    with pytest.raises(ValueError):
        plot.bernstein_basis(4, [5])
    with pytest.raises(ValueError):
        plot.curve(cj.BezierCurve(np.zeros((3, 4))))


def test_control_polygon_of_an_array_in_any_real_dtype():
    points = np.array(SEED_POLYGON)
    reference = xy(plot.control_polygon(points.astype(np.float64))[0])
    for variant in (points.astype(np.float32), points.astype(np.int64), np.asfortranarray(points), points[::1]):
        np.testing.assert_array_equal(xy(plot.control_polygon(variant)[0]), reference)


# ----------------------------------------------------------------- bases ----


def test_bernstein_basis_n20_is_a_partition_of_unity_and_matches_the_formula():
    require("bernstein_all")
    lines = plot.bernstein_basis(20, samples=41)
    assert len(lines) == 21
    ts = xy(lines[0])[:, 0]
    np.testing.assert_allclose(ts, np.linspace(0, 1, 41))
    values = np.array([xy(line)[:, 1] for line in lines])
    np.testing.assert_allclose(values.sum(axis=0), 1.0, rtol=0, atol=1e-14)
    for k in (0, 3, 10, 20):
        exact = [float(exact_bernstein(20, k, t)) for t in ts]
        np.testing.assert_allclose(values[k], exact, rtol=1e-13, atol=1e-300)


def test_bernstein_basis_without_the_ends_is_the_notebooks_second_figure():
    require("bernstein_all")
    lines = plot.bernstein_basis(20, range(1, 20), samples=11, color="r")
    assert len(lines) == 19
    ts = np.linspace(0, 1, 11)
    for k, line in zip(range(1, 20), lines):
        np.testing.assert_allclose(xy(line)[:, 1], [float(exact_bernstein(20, k, t)) for t in ts], rtol=1e-13, atol=1e-300)
        assert line.get_color() == "r"


def scipy_basis(knots, degree, i, us):
    element = BSpline.basis_element(knots[i : i + degree + 2], extrapolate=False)
    return np.nan_to_num(element(us), nan=0.0)


def test_basis_sums_to_one_in_the_domain_and_matches_scipy():
    require("basis_function")
    knots = np.array([0, 0, 0, 1, 2, 2, 3, 4, 4, 4], dtype=float)
    degree = 2
    lines = plot.basis(knots, degree)
    assert len(lines) == len(knots) - degree - 1
    us = xy(lines[0])[:, 0]
    assert set(knots) <= set(us)
    values = np.array([xy(line)[:, 1] for line in lines])
    np.testing.assert_allclose(values.sum(axis=0), 1.0, rtol=0, atol=1e-14)
    # Away from the knots (where half-open intervals and the closed end differ by convention).
    inside = np.all(np.abs(us[:, None] - knots[None, :]) > 1e-9, axis=1)
    for i, line in enumerate(lines):
        np.testing.assert_allclose(values[i][inside], scipy_basis(knots, degree, i, us[inside]), rtol=0, atol=1e-14)


@settings(derandomize=True, max_examples=25, deadline=None)
@given(degree=st.integers(0, 4), gaps=st.lists(st.sampled_from([0.0, 0.25, 0.5, 1.0, 2.0]), min_size=6, max_size=10))
def test_basis_property_partition_of_unity_on_the_domain(degree, gaps):
    require("basis_function")
    knots = np.concatenate([[0.0], np.cumsum(gaps)])
    count = len(knots) - degree - 1
    lower, upper = knots[degree], knots[count]
    if count < 1 or not upper > lower:
        return
    # Multiplicity above degree + 1 is not a valid knot vector.
    if max(np.unique(knots, return_counts=True)[1]) > degree + 1:
        return
    lines = plot.basis(knots, degree, samples=40)
    us = xy(lines[0])[:, 0]
    values = np.array([xy(line)[:, 1] for line in lines])
    domain = (us >= lower) & (us <= upper)
    np.testing.assert_allclose(values.sum(axis=0)[domain], 1.0, rtol=0, atol=1e-13)
    assert np.all(values >= -1e-15)
    inside = np.all(np.abs(us[:, None] - knots[None, :]) > 1e-9, axis=1)
    for i in range(count):
        np.testing.assert_allclose(values[i][inside], scipy_basis(knots, degree, i, us[inside]), rtol=0, atol=1e-13)
    plt.close("all")


# ---------------------------------------------------------- constructions ----


def test_de_casteljau_construction_ends_at_the_seeds_value():
    require("BezierCurve", "casteljau_construction")
    curve = cj.BezierCurve(SEED_POLYGON)
    artists = plot.de_casteljau(curve, 0.5)
    # [curve, level 0 .. level 3, point]
    assert len(artists) == 1 + 4 + 1
    np.testing.assert_array_equal(xy(artists[-1]), [[2.25, 1.5]])
    exact = exact_levels(SEED_POLYGON, Fraction(1, 2))
    for r in range(4):
        np.testing.assert_array_equal(xy(artists[1 + r]), as_float(exact[r]))  # dyadic: exact in binary
    np.testing.assert_array_equal(xy(artists[1]), np.array(SEED_POLYGON, dtype=float))


def test_de_casteljau_on_the_spiral_without_the_curve():
    require("BezierCurve", "casteljau_construction")
    points = np.loadtxt(REPOSITORY / "examples" / "spiral_5.csv", delimiter=",", comments="#", skiprows=2)
    curve = cj.BezierCurve(points)
    artists = plot.de_casteljau(curve, 0.6, show_curve=False, color="g")
    assert len(artists) == 5 + 1
    exact = exact_levels(points, 0.6)
    for r in range(5):
        np.testing.assert_allclose(xy(artists[r]), as_float(exact[r]), rtol=0, atol=1e-15)
        assert artists[r].get_color() == "g"
    np.testing.assert_allclose(xy(artists[-1]), as_float(exact[5]), rtol=0, atol=1e-15)


def test_de_boor_levels_and_point_match_scipy():
    curve = cj.BSplineCurve(3, [0, 0, 0, 0, 0.25, 0.5, 0.75, 1, 1, 1, 1],
                            [(0, 0), (1, 2), (2, 3), (4, 1), (5, 3), (6, 0), (7, 2)])
    reference = scipy_curve(curve)
    artists = plot.de_boor(curve, 0.6)
    # [curve, full polygon, level 0 .. level 2, point]
    assert len(artists) == 1 + 1 + 3 + 1
    np.testing.assert_array_equal(xy(artists[1]), np.asarray(curve.control_points))
    span = 5  # 0.5 <= 0.6 < 0.75 is knots[5] .. knots[6]
    np.testing.assert_array_equal(xy(artists[2]), np.asarray(curve.control_points)[span - 3 : span + 1])
    np.testing.assert_allclose(xy(artists[-1])[0], reference(0.6), rtol=0, atol=1e-14 * 7)


def test_tangents_at_the_ends_are_the_end_legs_of_the_polygon():
    require("BezierCurve", "points_at", "derivatives_at")
    curve = cj.BezierCurve(SEED_POLYGON)
    first, last = plot.tangents(curve)
    np.testing.assert_allclose(xy(first), [SEED_POLYGON[0], SEED_POLYGON[1]], rtol=0, atol=1e-14)
    np.testing.assert_allclose(xy(last), [SEED_POLYGON[3], SEED_POLYGON[4]], rtol=0, atol=1e-14)


def test_tangent_vectors_at_parameters_are_the_exact_derivative():
    require("BezierCurve", "points_at", "derivatives_at")
    curve = cj.BezierCurve(SEED_POLYGON)
    artists = plot.tangents(curve, [0.25, 0.5], scale=1.0)
    lines = artists[:2]
    assert len(artists) == 4  # two segments, two arrow heads
    n = len(SEED_POLYGON) - 1
    hodograph = [(n * (q[0] - p[0]), n * (q[1] - p[1])) for p, q in zip(SEED_POLYGON, SEED_POLYGON[1:])]
    for t, line in zip((0.25, 0.5), lines):
        base, derivative = as_float([exact_point(SEED_POLYGON, t), exact_point(hodograph, t)])
        np.testing.assert_allclose(xy(line), [base, base + derivative], rtol=0, atol=1e-13)


def test_bspline_tangents_match_scipy_derivative():
    require("derivative_at")
    curve = cj.BSplineCurve(2, [0, 0, 0, 0.5, 1, 1, 1], [(0, 0), (1, 2), (3, 2), (4, 0)])
    reference = scipy_curve(curve)
    lines = plot.tangents(curve, [0.3], scale=0.5, arrows=False)
    assert len(lines) == 1
    np.testing.assert_allclose(xy(lines[0]), [reference(0.3), reference(0.3) + 0.5 * reference.derivative()(0.3)],
                               rtol=0, atol=1e-13)


def test_piecewise_end_tangents_use_each_end_pieces_degree():
    require("BezierCurve", "PiecewiseBezierCurve", "points_at", "derivative_at")
    a, b = [(0, 0), (1, 1), (2, 0)], [(2, 0), (3, -1), (4, 1), (5, 0)]
    curve = cj.PiecewiseBezierCurve([cj.BezierCurve(a), cj.BezierCurve(b)])
    first, last = plot.tangents(curve)
    np.testing.assert_allclose(xy(first), [a[0], a[1]], rtol=0, atol=1e-14)
    np.testing.assert_allclose(xy(last), [b[2], b[3]], rtol=0, atol=1e-14)


def test_rational_construction_ends_on_the_circle():
    require("BezierCurve", "casteljau_construction")
    # The quarter circle as a rational quadratic, weights 1, cos(45°), 1 (The NURBS Book ex. 7.1): C(1/2) = (1, 1)/√2.
    curve = cj.BezierCurve([(1, 0), (1, 1), (0, 1)], weights=[1, math.sqrt(0.5), 1])
    artists = plot.de_casteljau(curve, 0.5, show_curve=False)
    np.testing.assert_allclose(xy(artists[-1])[0], [math.sqrt(0.5)] * 2, rtol=0, atol=1e-15)
    np.testing.assert_array_equal(xy(artists[0]), [(1, 0), (1, 1), (0, 1)])


def test_de_boor_in_3d_matches_scipy():
    curve = cj.BSplineCurve(2, [0, 0, 0, 0.5, 1, 1, 1], [(0, 0, 0), (1, 2, 1), (3, 2, 0), (4, 0, 2)])
    artists = plot.de_boor(curve, 0.3)
    assert artists[0].axes.name == "3d" and len(artists) == 1 + 1 + 2 + 1
    np.testing.assert_allclose(np.column_stack(artists[-1].get_data_3d())[0], scipy_curve(curve)(0.3), rtol=0, atol=1e-14)


def test_surface_in_3d_refuses_a_2d_current_axes():
    require("BezierSurface", "grid_points_at")
    surface = cj.BezierSurface(np.zeros((2, 2, 3)) + np.arange(2)[:, None, None])
    plt.subplots()
    with pytest.raises(ValueError, match="3D"):
        plot.surface_wireframe(surface)


def test_subdivision_points_are_the_curve_at_dyadic_parameters_and_polygons_are_the_pieces():
    require("BezierCurve", "subdivide_recursive", "split_at")
    control = [(0, 0), (1, 2), (2, 3), (4, 1), (5, 3)]  # the notebook's cell [32]/[35]
    curve = cj.BezierCurve(control)
    (line,) = plot.subdivision(curve, 10)
    assert len(xy(line)) == 1025  # the notebook's len(bezier(Ps, 10))
    artists = plot.subdivision(curve, 3, polygons=True)
    points = xy(artists[0])
    exact = as_float([exact_point(control, Fraction(i, 8)) for i in range(9)])
    np.testing.assert_array_equal(points, exact)  # dyadic parameters: exact in binary
    assert len(artists) == 1 + 8
    for j, polygon in enumerate(artists[1:]):
        np.testing.assert_array_equal(xy(polygon), as_float(exact_segment(control, Fraction(j, 8), Fraction(j + 1, 8))))


# --------------------------------------------------------------- surfaces ----


def test_bezier_surface_wireframe_matches_the_tensor_product():
    require("BezierSurface", "grid_points_at")
    net = np.array([[[0, 0, 0], [0, 1, 1], [0, 2, 0]],
                    [[1, 0, 1], [1, 1, 2], [1, 2, 1]]], dtype=float)  # degrees (1, 2)
    surface = cj.BezierSurface(net)
    artists = plot.surface_wireframe(surface, count=(3, 4), samples=5, net=True)
    assert artists[0].axes.name == "3d"
    assert len(artists) == 3 + 4 + (2 + 3)

    def exact(u, v):
        return sum(float(exact_bernstein(1, i, u) * exact_bernstein(2, j, v)) * net[i, j]
                   for i in range(2) for j in range(3))

    vs = np.linspace(0, 1, 5)
    for line, u in zip(artists[:3], np.linspace(0, 1, 3)):
        data = np.column_stack(line.get_data_3d())
        np.testing.assert_allclose(data, [exact(u, v) for v in vs], rtol=0, atol=1e-14 * 2)
    for line, v in zip(artists[3:7], np.linspace(0, 1, 4)):
        data = np.column_stack(line.get_data_3d())
        np.testing.assert_allclose(data, [exact(u, v) for u in vs], rtol=0, atol=1e-14 * 2)
    np.testing.assert_array_equal(np.column_stack(artists[7].get_data_3d()), net[0])
    np.testing.assert_array_equal(np.column_stack(artists[9].get_data_3d()), net[:, 0])


def test_bspline_surface_wireframe_matches_scipy_design_matrices():
    require("BSplineSurface", "grid_points_at")
    knots_u = np.array([0, 0, 0, 0.5, 1, 1, 1.0])
    knots_v = np.array([0, 0, 1, 2, 2.0])
    rng = np.random.default_rng(4)
    net = rng.random((4, 3, 3))
    surface = cj.BSplineSurface(2, 1, knots_u, knots_v, net)
    fig = plt.figure()
    ax = fig.add_subplot(projection="3d")
    artists = plot.surface_wireframe(surface, count=3, samples=7, ax=ax)
    assert len(artists) == 6
    us, vs = np.linspace(0, 1, 3), np.linspace(0, 2, 7)
    nu = BSpline.design_matrix(us, knots_u, 2).toarray()
    nv = BSpline.design_matrix(vs, knots_v, 1).toarray()
    grid = np.einsum("ai,bj,ijc->abc", nu, nv, net)
    for a, line in enumerate(artists[:3]):
        np.testing.assert_allclose(np.column_stack(line.get_data_3d()), grid[a], rtol=0, atol=1e-14)


def test_coons_patch_wireframe_reproduces_its_boundaries():
    require("CoonsPatch", "BezierCurve", "grid_points_at")
    u0 = [(0, 0, 0), (0, 0.5, 1), (0, 1, 0)]
    u1 = [(1, 0, 0), (1, 1, 0)]
    v0 = [(0, 0, 0), (0.5, 0, -1), (1, 0, 0)]
    v1 = [(0, 1, 0), (1, 1, 0)]
    patch = cj.CoonsPatch(*(cj.BezierCurve(c) for c in (u0, u1, v0, v1)))
    artists = plot.surface_wireframe(patch, count=2, samples=9, net=True)
    assert len(artists) == 2 + 2 + 4
    ts = np.linspace(0, 1, 9)
    np.testing.assert_allclose(np.column_stack(artists[0].get_data_3d()), as_float([exact_point(u0, t) for t in ts]),
                               rtol=0, atol=1e-14)
    np.testing.assert_allclose(np.column_stack(artists[2].get_data_3d()), as_float([exact_point(v0, t) for t in ts]),
                               rtol=0, atol=1e-14)
