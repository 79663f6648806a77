"""casteljau.fit_arcs: a plane curve as arcs and line segments within a tolerance.

The references are geometry written here, not the code under test: each arc's
centre and radius from its ends and bulge (the bulge is tan(sweep / 4)), points
along it by rotation about that centre, the distance from a point to an arc
(to its circle where the point's angle lies within the sweep, else to the
nearer end), and casteljau's closest points on the curve (checked on their own
in test_module_closest_point.py). Both ways within the tolerance: every arc
near the curve and the curve near the chain, on seeded random cubics
(hypothesis) and on the exact half circle, which is one arc.
"""

import math

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

import casteljau as c


def arc_geometry(x0, y0, x1, y1, bulge):
    """Centre, radius and signed sweep of a segment with a non-zero bulge."""
    sweep = 4.0 * math.atan(bulge)
    chord = math.hypot(x1 - x0, y1 - y0)
    radius = chord / (2.0 * abs(math.sin(sweep / 2.0)))
    # The centre lies on the chord's perpendicular bisector, on the left of the chord for a counterclockwise arc.
    mx, my = (x0 + x1) / 2.0, (y0 + y1) / 2.0
    offset = (chord / 2.0) / math.tan(sweep / 2.0)  # signed: negative beyond a half turn the other way
    nx, ny = -(y1 - y0) / chord, (x1 - x0) / chord
    return (mx + offset * nx, my + offset * ny), radius, sweep


def points_along(segment, count):
    x0, y0, x1, y1, bulge = segment
    s = np.linspace(0.0, 1.0, count)
    if bulge == 0.0:
        return np.column_stack([x0 + s * (x1 - x0), y0 + s * (y1 - y0)])
    (cx, cy), _, sweep = arc_geometry(*segment)
    angle = s * sweep
    dx, dy = x0 - cx, y0 - cy
    return np.column_stack([cx + dx * np.cos(angle) - dy * np.sin(angle), cy + dx * np.sin(angle) + dy * np.cos(angle)])


def distance_to_segment(point, segment):
    x0, y0, x1, y1, bulge = segment
    px, py = point
    ends = min(math.hypot(px - x0, py - y0), math.hypot(px - x1, py - y1))
    if bulge == 0.0:
        ux, uy = x1 - x0, y1 - y0
        t = ((px - x0) * ux + (py - y0) * uy) / (ux * ux + uy * uy)
        if 0.0 <= t <= 1.0:
            return abs((px - x0) * uy - (py - y0) * ux) / math.hypot(ux, uy)
        return ends
    (cx, cy), radius, sweep = arc_geometry(*segment)
    start = math.atan2(y0 - cy, x0 - cx)
    turn = math.atan2(py - cy, px - cx) - start
    turn = math.fmod(turn if sweep > 0 else -turn, 2.0 * math.pi)
    if turn < 0.0:
        turn += 2.0 * math.pi
    if turn <= abs(sweep):
        return abs(math.hypot(px - cx, py - cy) - radius)
    return ends


def check_within(curve, tolerance, fitted):
    segments = fitted["segments"]
    assert segments.ndim == 2 and segments.shape[1] == 5 and len(segments) >= 1
    parameters = fitted["parameters"]
    assert parameters.shape == (len(segments) + 1,)
    assert np.all(np.diff(parameters) > 0.0)
    assert 0.0 <= fitted["deviation_bound"] <= tolerance
    # A chain: each segment starts where the one before ends, from the curve's start to its end.
    assert np.array_equal(segments[1:, 0:2], segments[:-1, 2:4])
    start, end = np.asarray(c.point_at(curve, parameters[0])), np.asarray(c.point_at(curve, parameters[-1]))
    assert np.allclose(segments[0, 0:2], start, rtol=0, atol=1e-12 * (1 + np.abs(start).max()))
    assert np.array_equal(segments[-1, 2:4], end)
    slack = 1e-9 * (1.0 + tolerance)
    # Every arc near the curve.
    along = np.vstack([points_along(s, 25) for s in segments])
    _, distances = c.closest_points(curve, along)
    assert distances.max() <= tolerance + slack, distances.max()
    # The curve near the chain, each stretch near its own segment.
    for k, segment in enumerate(segments):
        for t in np.linspace(parameters[k], parameters[k + 1], 25):
            point = np.asarray(c.point_at(curve, t))
            assert distance_to_segment(point, segment) <= tolerance + slack


def test_the_half_circle_is_one_arc():
    # The half circle of radius 3 over (0, 3), examples/semicircle.json: two exact quarter circles.
    half = c.parse_models_json(
        '{"type": "bspline", "degree": 2, "knots": [0, 0, 0, 0.5, 0.5, 1, 1, 1], '
        '"control_points": [[-3, 0], [-3, 3], [0, 3], [3, 3], [3, 0]], "weights": [1, 0.7071067811865476, 1, '
        '0.7071067811865476, 1]}', "half")[0]
    fitted = c.fit_arcs(half, 0.01)
    [[x0, y0, x1, y1, bulge]] = fitted["segments"]
    assert (x0, y0, x1, y1) == (-3.0, 0.0, 3.0, 0.0)
    assert bulge == pytest.approx(-1.0, abs=1e-12)  # a half turn, clockwise
    assert fitted["deviation_bound"] < 1e-9
    check_within(half, 0.01, fitted)


def test_a_polyline_is_its_segments():
    square = c.PiecewiseBezierCurve([c.BezierCurve([[0, 0], [2, 0]]), c.BezierCurve([[2, 0], [2, 2]]),
                                     c.BezierCurve([[2, 2], [0, 2]])])
    fitted = c.fit_arcs(square, 0.1)
    assert fitted["segments"].tolist() == [[0, 0, 2, 0, 0], [2, 0, 2, 2, 0], [2, 2, 0, 2, 0]]
    assert fitted["parameters"].tolist() == [0, 1, 2, 3]


@settings(max_examples=40, deadline=None, derandomize=True)
@given(st.integers(0, 2**32 - 1), st.sampled_from([1e-1, 1e-2, 1e-3]))
def test_random_cubics_are_within_the_tolerance_both_ways(seed, relative):
    points = np.random.default_rng(seed).uniform(-10.0, 10.0, size=(4, 2))
    curve = c.BezierCurve(points)
    size = float(np.linalg.norm(points.max(axis=0) - points.min(axis=0)))
    tolerance = relative * size
    check_within(curve, tolerance, c.fit_arcs(curve, tolerance))


def test_bad_input_is_a_value_error():
    plane = c.BezierCurve([[0, 0], [1, 2], [3, 0]])
    with pytest.raises(ValueError, match="plane curve"):
        c.fit_arcs(c.BezierCurve([[0, 0, 0], [1, 2, 3]]), 0.1)
    for bad in (0.0, -1.0, float("nan"), float("inf")):
        with pytest.raises(ValueError, match="tolerance"):
            c.fit_arcs(plane, bad)
    with pytest.raises(TypeError):
        c.fit_arcs([[0, 0], [1, 1]], 0.1)


def test_straight_stretches_are_segments():
    """The sailboat's straight edges, fitted by biarcs, came out as arcs of
    bulge 1e-15 (centres 1e15 away, which ezdxf's bulge_to_arc put 0.49 mm off):
    an arc straight within rounding is now a segment, bulge exactly 0."""
    import pathlib

    drawing = pathlib.Path(__file__).resolve().parents[2] / "examples" / "sailboat.svg"
    straight = 0
    for curve in c.read_models(drawing):
        fitted = c.fit_arcs(curve, 0.01)
        segments = fitted["segments"]
        points = np.vstack([segments[:, 0:2], segments[:, 2:4]])
        size = float(np.linalg.norm(points.max(axis=0) - points.min(axis=0)))
        sagittas = np.abs(segments[:, 4]) * np.hypot(segments[:, 2] - segments[:, 0], segments[:, 3] - segments[:, 1]) / 2
        assert not np.any((segments[:, 4] != 0) & (sagittas <= 1e-9 * size)), segments[:, 4]
        straight += int(np.sum(segments[:, 4] == 0))
        check_within(curve, 0.01, fitted)
    assert straight >= 16
