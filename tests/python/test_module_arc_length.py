"""Arc length from Python against independent references: the ellipse's
perimeter 4 a E(e^2) with scipy.special.ellipe (the complete elliptic integral
of the second kind), at every accuracy from 1e-1 to 1e-13 of the size; the
circle's equal-arc-length samples at exact angles; the three curve kinds; and
the errors (ValueError naming the problem)."""
import math

import numpy as np
import pytest
import scipy.special

import casteljau as cj


@pytest.mark.parametrize("a, b", [(3.0, 1.0), (2.0, 1.9), (5.0, 0.2)])
def test_ellipse_perimeter_meets_every_requested_accuracy(a, b):
    ellipse = cj.make_ellipse((0.5, -1.0), a, b)
    exact = 4 * a * scipy.special.ellipe(1 - (b / a) ** 2)
    size = 2 * math.hypot(a, b)  # the control points' box is the ellipse's bounding box
    worst = 0.0
    for k in range(1, 14):
        tolerance = 10.0 ** -k * size
        error = abs(cj.arc_length(ellipse, tolerance) - exact)
        assert error <= tolerance, (k, error)
        worst = max(worst, error / tolerance)
    print(f"ellipse {a} x {b}: largest error / requested accuracy {worst:.2g}")


def test_quarter_ellipse_by_range_and_inverse():
    a, b = 3.0, 1.0
    ellipse = cj.make_ellipse((0, 0), a, b)
    lower, upper = ellipse.domain
    quarter = cj.arc_length(ellipse, 1e-12, start=lower, end=lower + (upper - lower) / 4)
    assert quarter == pytest.approx(a * scipy.special.ellipe(1 - (b / a) ** 2), abs=1e-12)
    u = cj.parameter_at_length(ellipse, quarter, 1e-12)
    assert u == pytest.approx(lower + (upper - lower) / 4, abs=1e-9)


def test_equal_arc_length_samples_of_the_circle():
    circle = cj.make_circle((0, 0), 2.0)
    us = cj.equal_arc_length_parameters(circle, 9, 1e-12)
    points = cj.points_at(circle, us)
    angles = np.unwrap(np.arctan2(points[:, 1], points[:, 0]))
    np.testing.assert_allclose(np.diff(angles), 2 * np.pi / 8, atol=1e-11)


def test_every_kind_and_the_default_tolerance():
    parabola = cj.BezierCurve([[0, 0], [1, 0], [2, 4]])
    exact = math.sqrt(17) + math.asinh(4) / 4
    left, right = cj.split_at(parabola, 0.5)
    for curve in (parabola, cj.to_bspline(parabola), cj.PiecewiseBezierCurve([left, right])):
        assert cj.arc_length(curve) == pytest.approx(exact, abs=1e-11)


def test_errors_are_value_errors_that_say_what():
    line = cj.BezierCurve([[0, 0], [3, 4]])
    with pytest.raises(ValueError, match="must be finite and > 0"):
        cj.arc_length(line, 0.0)
    with pytest.raises(ValueError, match="below 1e-14 of the curve's size 5"):
        cj.arc_length(line, 1e-20)
    with pytest.raises(ValueError, match="outside the domain"):
        cj.arc_length(line, start=-1.0)
    with pytest.raises(ValueError, match="runs backwards"):
        cj.arc_length(line, start=0.8, end=0.2)
    with pytest.raises(ValueError, match=r"the length 6 is outside \[0, 5\]"):
        cj.parameter_at_length(line, 6.0)
    with pytest.raises(ValueError, match="at least 2"):
        cj.equal_arc_length_parameters(line, 1)


def test_bounding_box_of_the_circle_and_a_parabola():
    lower, upper = cj.bounding_box(cj.make_circle((1.0, -2.0), 3.0))
    np.testing.assert_allclose(lower, [-2.0, -5.0], atol=1e-14)
    np.testing.assert_allclose(upper, [4.0, 1.0], atol=1e-14)
    lower, upper = cj.bounding_box(cj.BezierCurve([[0, 0], [1, 2], [2, 0]]))  # the polygon reaches y = 2
    np.testing.assert_allclose(upper, [2.0, 1.0], atol=1e-15)


def test_inflections_of_a_cubic_graph_and_errors():
    # x = t, y = (t - 1/2)^3 in Bernstein form: the inflection is at t = 1/2.
    s_curve = cj.BezierCurve([[0, -0.125], [1 / 3, 0.125], [2 / 3, -0.125], [1, 0.125]])
    np.testing.assert_allclose(cj.inflection_parameters(s_curve), [0.5], atol=1e-15)
    assert cj.inflection_parameters(cj.make_circle((0, 0), 1.0)).size == 0
    with pytest.raises(ValueError, match="plane curve"):
        cj.inflection_parameters(cj.BezierCurve([[0, 0, 0], [1, 1, 1], [2, 0, 1]]))


def test_curvature_extrema_and_cusps():
    # The same S-curve: y = s^3 (s = t - 1/2) has its sharpest points where
    # d/ds [6 s / (1 + 9 s^4)^(3/2)] = 0, s = +-45^(-1/4).
    s_curve = cj.BezierCurve([[0, -0.125], [1 / 3, 0.125], [2 / 3, -0.125], [1, 0.125]])
    parameters, curvatures, maxima = cj.curvature_extrema(s_curve)
    s = 45.0 ** -0.25
    np.testing.assert_allclose(parameters, [0.5 - s, 0.5 + s], atol=1e-14)
    kappa = 6 * s / (1 + 9 * s**4) ** 1.5
    np.testing.assert_allclose(curvatures, [-kappa, kappa], rtol=1e-13)
    assert maxima.dtype == np.bool_ and maxima.tolist() == [True, True]
    # The ellipse x^2/9 + y^2 = 1 from (3, 0): (0, 1) flattest, (-3, 0) sharpest, (0, -1).
    parameters, curvatures, maxima = cj.curvature_extrema(cj.make_ellipse((0, 0), 3.0, 1.0))
    np.testing.assert_allclose(curvatures, [1 / 9, 3.0, 1 / 9], rtol=1e-13)
    assert maxima.tolist() == [False, True, False]
    # The cusp of (0,0) (1,1) (0,1) (1,0) at t = 1/2, none on a circle.
    cusp = cj.BezierCurve([[0, 0], [1, 1], [0, 1], [1, 0]])
    np.testing.assert_allclose(cj.cusp_parameters(cusp), [0.5], atol=1e-15)
    assert cj.cusp_parameters(cj.make_circle((0, 0), 1.0)).size == 0
    for function in (cj.curvature_extrema, cj.cusp_parameters):
        with pytest.raises(ValueError, match="R\\^2 or more"):
            function(cj.BezierCurve([[0], [1], [3]]))
