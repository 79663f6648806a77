"""Extreme numbers through the Python module (issue 15).

A B-spline whose knot span has a subnormal width (5e-324) killed the
interpreter in points_at: the span search divided by the width and cast the
NaN to an index. Every make() now refuses knots, coordinates and weights
outside the ranges in which a valid object evaluates (core/tolerance.hpp,
"Valid model numbers"), so the module raises ValueError naming them. The
crash case runs in a child interpreter, so that a regression shows as a
failed test rather than a dead pytest.
"""

import os
import subprocess
import sys

import numpy as np
import pytest

import casteljau as cj

SUBNORMAL_SPAN = "knots 1 and 2 (0 and 5e-324) are 5e-324 apart"


def run_child(code):
    """Runs `code` in a fresh interpreter that imports this casteljau."""
    folder = os.path.dirname(os.path.dirname(cj.__file__))
    env = dict(os.environ, PYTHONPATH=os.pathsep.join([folder, os.environ.get("PYTHONPATH", "")]))
    return subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env, timeout=120)


def test_the_issues_command_raises_value_error_and_the_interpreter_lives():
    code = (
        "import numpy as np, casteljau as cj\n"
        "try:\n"
        "    cj.points_at(cj.BSplineCurve(1, [0, 0, 5e-324, 5e-324], [(0, 0), (1, 1)]), np.array([0.0]))\n"
        "except ValueError as error:\n"
        "    print('ValueError:', error)\n"
    )
    child = run_child(code)
    assert child.returncode == 0, f"exit {child.returncode}: {child.stderr}"
    assert SUBNORMAL_SPAN in child.stdout


@pytest.mark.parametrize(
    "knots, message",
    [
        ([0, 0, 5e-324, 5e-324], SUBNORMAL_SPAN),
        ([0, 0, 1e-310, 1e-310], "knots 1 and 2 (0 and 1e-310) are 1e-310 apart"),
        ([-1e308, -1e308, 1e308, 1e308], "knot 0 is -1e+308, outside [-1e+100, 1e+100], the range of knots"),
        ([0, 0, np.nextafter(1e-100, 0), 1], "less than the narrowest knot span 1e-100"),
    ],
)
def test_bspline_curves_refuse_knots_outside_the_ranges(knots, message):
    with pytest.raises(ValueError) as error:
        cj.BSplineCurve(1, knots, [(0, 0), (1, 1)] if len(knots) == 4 else [(0, 0), (1, 1), (2, 0)])
    assert message in str(error.value)


def test_the_scipy_like_bspline_refuses_them_too():
    with pytest.raises(ValueError, match="narrowest knot span"):
        cj.BSpline([0, 0, 5e-324, 5e-324], [0.0, 1.0], 1)


def test_spans_of_one_ulp_and_the_edges_of_the_ranges_evaluate():
    one = np.nextafter(1.0, 2.0)
    curve = cj.BSplineCurve(1, [1, 1, one, one], [(0, 0), (1, 1)])
    np.testing.assert_array_equal(cj.points_at(curve, np.array([1.0, one])), [[0, 0], [1, 1]])
    edges = cj.BSplineCurve(1, [0, 0, 1e-100, 1e-100], [(-1e100, 0), (1e100, 0)], weights=[1e-50, 1e50])
    values = cj.points_at(edges, np.array([0.0, 5e-101, 1e-100]))
    assert np.all(np.isfinite(values))
    slope = cj.derivative_at(edges, 0.0)
    assert np.all(np.isfinite(slope)) and slope[0] > 1e299


@pytest.mark.parametrize(
    "make, message",
    [
        (lambda: cj.BezierCurve([(-1e308, 0), (1e308, 0)]), "coordinate 0 of control point 0 is -1e+308"),
        (lambda: cj.BezierCurve([(0, 0), (1, 1)], weights=[1, 1e-320]), "the range of weights"),
        (lambda: cj.BezierCurve([(0, 0), (1, 1)], weights=[1, 1e51]), "weight 1 is 1e+51, outside [1e-50, 1e+50]"),
        (lambda: cj.BSplineCurve(1, [0, 0, 1, 1], [(0, 0), (1, 1e101)]), "the range of coordinates"),
        (lambda: cj.make_circle([0, 0], 1e300), "the radius is 1e+300, outside (0, 1e+100]"),
    ],
)
def test_coordinates_and_weights_outside_the_ranges_raise(make, message):
    with pytest.raises(ValueError) as error:
        make()
    assert message in str(error.value)


def surface_net():
    return np.array([[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]], dtype=float)


def test_surfaces_refuse_subnormal_spans_in_either_direction():
    with pytest.raises(ValueError, match=r"knots_u: knots 1 and 2 \(0 and 5e-324\)"):
        cj.BSplineSurface(1, 1, [0, 0, 5e-324, 5e-324], [0, 0, 1, 1], surface_net())
    with pytest.raises(ValueError, match=r"knots_v: knots 1 and 2 \(0 and 1e-310\)"):
        cj.BSplineSurface(1, 1, [0, 0, 1, 1], [0, 0, 1e-310, 1e-310], surface_net())
    far = surface_net()
    far[1, 1, 2] = 1e308
    with pytest.raises(ValueError, match=r"coordinate 2 of control point \[1\]\[1\] is 1e\+308"):
        cj.BezierSurface(far)


def test_interpolation_inputs_outside_the_ranges_raise():
    with pytest.raises(ValueError, match="the range of coordinates"):
        cj.interpolate_c1_bezier(np.array([[0, 0], [1e308, 1], [2, 0]], dtype=float))


def test_a_knot_inserted_beside_another_is_refused_not_a_nan_derivative():
    # insert_knot(c, 5e-324) gave a curve whose derivative was NaN: the new
    # span is held to the rule make() applies to a model's knots.
    line = cj.BSplineCurve(1, [0, 0, 1, 1], [(0, 0), (1, 1)])
    with pytest.raises(ValueError, match=r"knot 1 and the knot to insert \(0 and 5e-324\) are 5e-324 apart"):
        cj.insert_knot(line, 5e-324)
    with pytest.raises(ValueError, match=r"knot 1 and the split parameter \(0 and 1e-200\)"):
        cj.split_at(line, 1e-200)
    beside = cj.insert_knot(line, 1e-100)
    assert np.all(np.isfinite(cj.derivative_at(beside, 0.0, 1)))
