"""Intersections from Python: crossings of two curves against numpy's
polynomial roots (numpy.roots on the implicit line equation substituted into
the cubic: an independent solver), the dict shapes of each kind, every pair of
curve kinds, self-intersections, and the errors."""
import math

import numpy as np
import pytest

import casteljau as cj


def test_cubic_and_line_against_numpy_roots():
    rng = np.random.default_rng(20261202)
    for _ in range(200):
        control = rng.uniform(-1, 1, size=(4, 2))
        cubic = cj.BezierCurve(control)
        p, q = rng.uniform(-1, 1, size=(2, 2))
        line = cj.BezierCurve([p, q])
        # n . (C(t) - p) = 0 with n normal to the line, C in power form.
        n = np.array([q[1] - p[1], p[0] - q[0]])
        b = control @ n - p @ n
        power = [-b[0] + 3 * b[1] - 3 * b[2] + b[3], 3 * b[0] - 6 * b[1] + 3 * b[2], -3 * b[0] + 3 * b[1], b[0]]
        expected = []
        for root in np.roots(power):
            if abs(root.imag) > 1e-9 or not -1e-12 <= root.real <= 1 + 1e-12:
                continue
            point = cj.point_at(cubic, min(max(root.real, 0.0), 1.0))
            s = np.dot(point - p, q - p) / np.dot(q - p, q - p)
            if -1e-12 <= s <= 1 + 1e-12:
                expected.append(root.real)
        found = [x["a"] for x in cj.intersections(cubic, line) if x["kind"] == "transversal"]
        assert len(found) == len(expected), (control, p, q, found, expected)
        for a, e in zip(sorted(found), sorted(expected)):
            assert a == pytest.approx(e, abs=1e-9)


def test_shapes_of_each_kind():
    axis = cj.BezierCurve([[-2, 0], [2, 0]])
    (touch,) = cj.intersections(cj.BezierCurve([[-1, 1], [0, -1], [1, 1]]), axis)
    assert touch["kind"] == "tangent" and touch["multiplicity"] == 2 and touch["point"].shape == (2,)
    cubic = cj.BezierCurve([[0, 0], [1, 3], [2, -3], [3, 0]])
    middle = cj.BezierCurve([[0.75, 0.84375], [1.25, 0.65625], [1.75, -0.65625], [2.25, -0.84375]])
    assert cj.intersections(cubic, middle) == [{"kind": "overlap", "a": (0.25, 0.75), "b": (0.0, 1.0)}]


@pytest.mark.parametrize("a", [
    cj.BezierCurve([[0, 0], [2, 2]]),
    cj.PiecewiseBezierCurve([cj.BezierCurve([[0, 0], [1, 1]]), cj.BezierCurve([[1, 1], [2, 2]])]),
    cj.BSplineCurve(1, [0, 0, 1, 1], [[0, 0], [2, 2]]),
])
def test_every_kind(a):
    b = cj.BSplineCurve(2, [0, 0, 0, 1, 1, 1], [[0, 2], [1, 1], [2, 0]])
    (x,) = cj.intersections(a, b)
    assert x["kind"] == "transversal"
    assert np.allclose(x["point"], [1, 1], atol=1e-14)


def test_self_intersection_of_a_loop():
    (x,) = cj.self_intersections(cj.BezierCurve([[0, 0], [2, 2], [-1, 2], [1, 0]]))
    s = (5 - math.sqrt(15)) / 10
    assert x["a"] == pytest.approx(s, abs=1e-15) and x["b"] == pytest.approx(1 - s, abs=1e-15)


def test_errors():
    plane = cj.BezierCurve([[0, 0], [1, 1]])
    with pytest.raises(ValueError, match="the first lives in R\\^2, the second in R\\^3"):
        cj.intersections(plane, cj.BezierCurve([[0, 0, 0], [1, 1, 1]]))
    with pytest.raises(TypeError, match="b is a int"):
        cj.intersections(plane, 3)
    with pytest.raises(ValueError, match="tolerance"):
        cj.intersections(plane, plane, -1.0)


def test_space_curves_meet_within_the_tolerance():
    # Two segments of R^3 crossing at (1/2, 1/2, 1/2), and one moved off by 1e-6.
    a = cj.BezierCurve([[0, 0, 0], [1, 1, 1]])
    (x,) = cj.intersections(a, cj.BezierCurve([[0, 1, 0], [1, 0, 1]]))
    assert x["kind"] == "transversal" and x["a"] == pytest.approx(0.5, abs=1e-15)
    np.testing.assert_allclose(x["point"], [0.5, 0.5, 0.5], atol=1e-15)
    assert cj.intersections(a, cj.BezierCurve([[0, 1, 1e-6], [1, 0, 1 + 1e-6]])) == []
