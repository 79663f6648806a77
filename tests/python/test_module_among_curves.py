"""casteljau.closest_among_curves and intersections_among_curves: queries
over a drawing's curves. The references: closest_point on every curve and
intersections() on every pair (with self_intersections() on each), which are
tested on their own; the pruning and the sweep must not change an answer."""

import itertools
import math
import pathlib

import numpy as np
import pytest

import casteljau as c

SAILBOAT = pathlib.Path(__file__).resolve().parents[2] / "examples" / "sailboat.svg"


def test_closest_among_the_sailboats_curves_is_the_nearest_of_each_asked():
    curves = c.read_models(SAILBOAT)
    points = np.random.default_rng(20261206).uniform([0, 0], [240, 160], size=(200, 2))
    which, parameters, distances = c.closest_among_curves(curves, points)
    assert which.dtype == np.int64 and which.shape == (200,)
    for i, point in enumerate(points):
        each = [c.closest_point(curve, point)[1] for curve in curves]
        best = int(np.argmin(each))
        assert which[i] == best and distances[i] == each[best]
        assert parameters[i] == c.closest_point(curves[best], point)[0]


def test_intersections_among_the_sailboats_curves_are_every_pair_asked():
    curves = c.read_models(SAILBOAT)
    found = c.intersections_among_curves(curves)
    reference = []
    for a, b in itertools.combinations_with_replacement(range(len(curves)), 2):
        pairs = c.self_intersections(curves[a]) if a == b else c.intersections(curves[a], curves[b])
        reference += [(a, b, x["kind"], x["a"]) for x in pairs]
    assert [(x["curve_a"], x["curve_b"], x["kind"], x["a"]) for x in found] == reference
    assert len(found) == 10


def test_worked_by_hand_and_bad_input():
    up, down = c.BezierCurve([[0, 0], [2, 2]]), c.BezierCurve([[0, 2], [2, 0]])
    [x] = c.intersections_among_curves([up, down])
    assert (x["curve_a"], x["curve_b"], x["a"], x["b"]) == (0, 1, 0.5, 0.5)
    which, parameters, distances = c.closest_among_curves([up, down], [[2, 1]])
    assert which.tolist() == [0] and distances[0] == pytest.approx(math.sqrt(0.5), abs=1e-15)
    with pytest.raises(ValueError, match="curve 1 lives in R\\^3"):
        c.closest_among_curves([up, c.BezierCurve([[0, 0, 0], [1, 1, 1]])], [[0, 0]])
    with pytest.raises(ValueError, match="at least one curve"):
        c.closest_among_curves([], [[0, 0]])
    with pytest.raises(TypeError, match="curves\\[1\\]"):
        c.intersections_among_curves([up, [[0, 0], [1, 1]]])
    with pytest.raises(ValueError, match="tolerance"):
        c.intersections_among_curves([up, down], tolerance=-1.0)
