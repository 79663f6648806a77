"""casteljau's surfaces in Python (python/src/surfaces.cpp).

References: scipy.interpolate.bisplev (FITPACK's fpbisp, written by other
people) for polynomial B-spline surfaces of degrees 1..5; the sphere's
equation |S - c| = r for make_sphere (The NURBS Book §8.5: exact as NURBS);
the torus's equation for make_torus; the four boundary curves for Coons
patches (Coons 1967: a Coons patch reproduces its boundaries); the input
curves for ruled surfaces, skinning and revolution; exact dyadic values for
a bilinear patch. Invariants (knot insertion, degree elevation and splitting
keep the surface; grid and scattered batches agree; derivatives against
finite differences) are hypothesis properties with derandomize=True.
"""

import math
import pickle

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st
from scipy.interpolate import bisplev

import casteljau as c

SEEDED = settings(derandomize=True, max_examples=25, deadline=None)
DEGREES = range(1, 6)


# --- generators ------------------------------------------------------------------------


def random_knots(rng, degree, count, clamped=True):
    """count + degree + 1 knots for `count` control points, distinct interior knots."""
    lower = float(rng.uniform(-3, 3))
    upper = lower + float(10 ** rng.uniform(-0.5, 0.5))
    interior = sorted(rng.uniform(lower, upper, count - degree - 1).tolist())
    if clamped:
        return np.array([lower] * (degree + 1) + interior + [upper] * (degree + 1))
    width = upper - lower
    below = sorted((lower - rng.uniform(0.01, width, degree)).tolist())
    above = sorted((upper + rng.uniform(0.01, width, degree)).tolist())
    return np.array(below + [lower] + interior + [upper] + above)


def random_bspline_surface(rng, p=None, q=None, d=3, rational=None, clamped=True):
    p = int(rng.integers(1, 4)) if p is None else p
    q = int(rng.integers(1, 4)) if q is None else q
    rows = p + 1 + int(rng.integers(0, 4))
    columns = q + 1 + int(rng.integers(0, 4))
    net = rng.uniform(-2, 2, (rows, columns, d))
    rational = bool(rng.integers(0, 2)) if rational is None else rational
    weights = rng.uniform(0.5, 2.0, (rows, columns)) if rational else None
    return c.BSplineSurface(p, q, random_knots(rng, p, rows, clamped), random_knots(rng, q, columns, clamped), net,
                            weights)


def random_bezier_surface(rng, d=3, rational=None):
    rows, columns = int(rng.integers(1, 6)), int(rng.integers(1, 6))
    rational = bool(rng.integers(0, 2)) if rational is None else rational
    weights = rng.uniform(0.5, 2.0, (rows, columns)) if rational else None
    return c.BezierSurface(rng.uniform(-2, 2, (rows, columns, d)), weights)


def curve_between(rng, start, end, degree=3, count=5):
    """A clamped B-spline curve on [0, 1] from start to end."""
    points = rng.uniform(-2, 2, (count, len(start)))
    points[0], points[-1] = start, end
    interior = sorted(rng.uniform(0.05, 0.95, count - degree - 1).tolist())
    knots = [0.0] * (degree + 1) + interior + [1.0] * (degree + 1)
    return c.BSplineCurve(degree, knots, points)


def random_coons_patch(rng, d=3, blending="linear"):
    corners = rng.uniform(-2, 2, (2, 2, d))  # corners[i, j] = P(i, j)
    u0 = curve_between(rng, corners[0, 0], corners[0, 1])
    u1 = curve_between(rng, corners[1, 0], corners[1, 1])
    v0 = curve_between(rng, corners[0, 0], corners[1, 0])
    v1 = curve_between(rng, corners[0, 1], corners[1, 1])
    return c.CoonsPatch(u0, u1, v0, v1, blending)


def random_surface(rng, kind):
    if kind == "bspline":
        return random_bspline_surface(rng)
    if kind == "bezier":
        return random_bezier_surface(rng)
    return random_coons_patch(rng, blending=str(rng.choice(["linear", "cubic"])))


def scale_of(surface):
    if isinstance(surface, c.CoonsPatch):
        return max(float(np.abs(b.control_points).max()) for b in (surface.u0, surface.u1, surface.v0, surface.v1))
    return float(np.abs(surface.control_net).max())


def random_pairs(rng, surface, count):
    (a, b), (e, f) = surface.domain_u, surface.domain_v
    return np.column_stack([rng.uniform(a, b, count), rng.uniform(e, f, count)])


seeds = st.integers(0, 2**32 - 1)
kinds = st.sampled_from(["bspline", "bezier", "coons"])


# --- scipy.interpolate.bisplev -----------------------------------------------------------


@pytest.mark.parametrize("p", DEGREES)
@pytest.mark.parametrize("q", DEGREES)
def test_bspline_surface_matches_scipy_bisplev(p, q):
    rng = np.random.default_rng(1000 * p + q)
    for clamped in (True, False):
        surface = random_bspline_surface(rng, p, q, d=2, rational=False, clamped=clamped)
        (a, b), (e, f) = surface.domain_u, surface.domain_v
        interior_u = np.unique(surface.knots_u[p:len(surface.knots_u) - p])
        interior_v = np.unique(surface.knots_v[q:len(surface.knots_v) - q])
        us = np.unique(np.concatenate([rng.uniform(a, b, 9), interior_u, [a, b]]))
        vs = np.unique(np.concatenate([rng.uniform(e, f, 9), interior_v, [e, f]]))
        grid = c.grid_points_at(surface, us, vs)
        assert grid.shape == (len(us), len(vs), 2)
        net = surface.control_net
        scale = np.abs(net).max()
        for coordinate in range(2):
            tck = [surface.knots_u, surface.knots_v, net[:, :, coordinate].ravel(), p, q]
            expected = bisplev(us, vs, tck)
            np.testing.assert_allclose(grid[:, :, coordinate], expected, rtol=0, atol=1e-12 * scale)
        # The scattered batch and the single-point call on the same pairs.
        uu, vv = np.meshgrid(us, vs, indexing="ij")
        pairs = np.column_stack([uu.ravel(), vv.ravel()])
        scattered = c.points_at(surface, pairs)
        np.testing.assert_allclose(scattered.reshape(grid.shape), grid, rtol=0, atol=1e-13 * scale)
        for k in range(0, len(pairs), 7):
            np.testing.assert_allclose(c.point_at(surface, *pairs[k]), scattered[k], rtol=0, atol=1e-13 * scale)


# --- batches agree -----------------------------------------------------------------------


@SEEDED
@given(seeds, kinds)
def test_grid_points_at_equals_points_at_on_the_same_pairs(seed, kind):
    rng = np.random.default_rng(seed)
    surface = random_surface(rng, kind)
    (a, b), (e, f) = surface.domain_u, surface.domain_v
    us = np.concatenate([rng.uniform(a, b, 6), [a, b]])  # any order
    vs = np.concatenate([[f], rng.uniform(e, f, 5), [e]])
    grid = c.grid_points_at(surface, us, vs)
    uu, vv = np.meshgrid(us, vs, indexing="ij")
    scattered = c.points_at(surface, np.column_stack([uu.ravel(), vv.ravel()]))
    np.testing.assert_allclose(scattered.reshape(grid.shape), grid, rtol=0, atol=1e-13 * scale_of(surface))
    for a_index in (0, 3, 7):
        for b_index in (0, 4):
            np.testing.assert_allclose(c.point_at(surface, us[a_index], vs[b_index]), grid[a_index, b_index],
                                       rtol=0, atol=1e-13 * scale_of(surface))


def test_batches_fill_out_and_cover_several_chunks():
    rng = np.random.default_rng(7)
    surface = random_bspline_surface(rng, 3, 2, rational=True)
    count = 300_000  # more than one chunk of 2^18 (python/src/arrays.hpp)
    pairs = random_pairs(rng, surface, count)
    out = np.empty((count, 3))
    result = c.points_at(surface, pairs, out=out)
    assert result is out
    expected = np.array([c.point_at(surface, u, v) for u, v in pairs[::997]])
    np.testing.assert_allclose(out[::997], expected, rtol=0, atol=1e-13 * scale_of(surface))
    pairs[count - 5, 1] = np.nan  # in the second chunk: the message names its row
    with pytest.raises(ValueError, match=f"\\[{count - 5}, 1\\].*NaN"):
        c.points_at(surface, pairs)
    us = np.linspace(*surface.domain_u, 4100)
    vs = np.linspace(*surface.domain_v, 3)
    grid_out = np.empty((4100, 3, 3))
    assert c.grid_points_at(surface, us, vs, out=grid_out) is grid_out
    np.testing.assert_allclose(grid_out[4099, 2], c.point_at(surface, us[-1], vs[-1]), rtol=0, atol=1e-13)
    with pytest.raises(ValueError, match="shape"):
        c.grid_points_at(surface, us, vs, out=np.empty((4100, 3, 2)))
    with pytest.raises(ValueError, match="float64"):
        c.points_at(surface, pairs, out=np.empty((count, 3), dtype=np.float32))


def test_empty_batches():
    surface = c.make_sphere([0, 0, 0], 1)
    assert c.points_at(surface, np.empty((0, 2))).shape == (0, 3)
    assert c.grid_points_at(surface, [], [0.5]).shape == (0, 1, 3)
    assert c.grid_points_at(surface, [0.5], []).shape == (1, 0, 3)
    assert c.normals_at(surface, np.empty((0, 2))).shape == (0, 3)


def test_other_dtypes_and_layouts_give_the_same_points():
    rng = np.random.default_rng(3)
    surface = random_bspline_surface(rng, 2, 2, rational=False)
    pairs = random_pairs(rng, surface, 40)
    reference = c.points_at(surface, pairs)
    fortran = np.asfortranarray(pairs)
    strided = np.zeros((40, 4))
    strided[:, ::2] = pairs
    for variant in (fortran, strided[:, ::2], pairs.tolist()):
        np.testing.assert_array_equal(c.points_at(surface, variant), reference)
    # float32 and integer parameters: converted once to float64.
    sphere = c.make_sphere([0, 0, 0], 1)
    dyadic = rng.integers(0, 65, (20, 2)) / 64
    np.testing.assert_array_equal(c.points_at(sphere, dyadic.astype(np.float32)), c.points_at(sphere, dyadic))
    np.testing.assert_array_equal(c.grid_points_at(sphere, np.array([0, 1]), np.array([0, 1], dtype=np.uint8)),
                                  c.grid_points_at(sphere, [0.0, 1.0], [0.0, 1.0]))
    # Integer parameters and nets.
    integer_net = c.BezierSurface(np.arange(12).reshape(2, 2, 3))
    float_net = c.BezierSurface(np.arange(12, dtype=float).reshape(2, 2, 3))
    assert integer_net == float_net
    np.testing.assert_array_equal(c.grid_points_at(float_net, np.array([0, 1]), [0, 1]),
                                  float_net.control_net)
    # A net given in Fortran order or as float32 is the same net.
    net = rng.uniform(-1, 1, (3, 4, 2))
    assert c.BezierSurface(np.asfortranarray(net)) == c.BezierSurface(net)
    assert c.BezierSurface(net.astype(np.float32)) == c.BezierSurface(net.astype(np.float32).astype(float))


# --- exact values ------------------------------------------------------------------------


def test_bilinear_patch_exact_dyadic_values():
    # S(u, v) = (1-u)(1-v) P00 + (1-u) v P01 + u (1-v) P10 + u v P11, exact for dyadic u, v.
    net = np.array([[[0.0, 0.0, 0.0], [0.0, 4.0, 1.0]], [[4.0, 0.0, 2.0], [4.0, 4.0, 8.0]]])
    patch = c.BezierSurface(net)
    for u in (0.0, 0.25, 0.5, 0.75, 1.0):
        for v in (0.0, 0.125, 0.5, 1.0):
            expected = ((1 - u) * (1 - v) * net[0, 0] + (1 - u) * v * net[0, 1] + u * (1 - v) * net[1, 0]
                        + u * v * net[1, 1])
            np.testing.assert_array_equal(c.point_at(patch, u, v), expected)
    spline = c.to_bspline_surface(patch)
    np.testing.assert_array_equal(spline.knots_u, [0, 0, 1, 1])
    np.testing.assert_array_equal(c.point_at(spline, 0.5, 0.5), [2.0, 2.0, 2.75])
    # d^2 S / du dv = P11 - P10 - P01 + P00.
    np.testing.assert_array_equal(c.partial_derivative_at(patch, 0.3, 0.6, 1, 1), net[1, 1] - net[1, 0] - net[0, 1]
                                  + net[0, 0])


@SEEDED
@given(seeds)
def test_nurbs_sphere_points_lie_at_the_radius(seed):
    rng = np.random.default_rng(seed)
    radius = float(10 ** rng.uniform(-3, 3))
    center = rng.uniform(-radius, radius, 3)
    sphere = c.make_sphere(center, radius)
    assert sphere.degree_u == 2 and sphere.degree_v == 2 and sphere.is_rational
    assert sphere.control_net.shape == (9, 5, 3)
    pairs = np.vstack([rng.uniform(0, 1, (200, 2)), [[0, 0], [1, 1], [0.5, 0.5], [0.25, 0.75]]])
    points = c.points_at(sphere, pairs)
    distances = np.linalg.norm(points - center, axis=1)
    assert np.abs(distances - radius).max() <= 1e-14 * radius
    grid = c.grid_points_at(sphere, np.linspace(0, 1, 9), np.linspace(0, 1, 7))
    assert np.abs(np.linalg.norm(grid - center, axis=2) - radius).max() <= 1e-14 * radius
    # Outward unit normals: (S - c) / r, also at the poles (the limit).
    normals = c.normals_at(sphere, pairs)
    np.testing.assert_allclose(normals, (points - center) / radius, rtol=0, atol=1e-9)
    np.testing.assert_allclose(c.normal_at(sphere, 0.3, 0.0), [0, 0, -1], atol=1e-12)
    np.testing.assert_allclose(c.normal_at(sphere, 0.3, 1.0), [0, 0, 1], atol=1e-12)


@SEEDED
@given(seeds)
def test_torus_points_satisfy_the_torus_equation(seed):
    rng = np.random.default_rng(seed)
    major = float(rng.uniform(1, 3))
    minor = float(rng.uniform(0.1, 0.9)) * major
    center = rng.uniform(-1, 1, 3)
    axis = rng.normal(size=3)
    torus = c.make_torus(center, axis, major, minor)
    assert torus.control_net.shape == (9, 9, 3)
    points = c.points_at(torus, rng.uniform(0, 1, (100, 2)))
    z_axis = axis / np.linalg.norm(axis)
    relative = points - center
    height = relative @ z_axis
    radial = np.linalg.norm(relative - np.outer(height, z_axis), axis=1)
    np.testing.assert_allclose((radial - major) ** 2 + height ** 2, minor ** 2, rtol=0, atol=1e-12 * major ** 2)


# --- Coons patches ------------------------------------------------------------------------


@SEEDED
@given(seeds, st.sampled_from(["linear", "cubic"]))
def test_coons_patch_reproduces_its_boundaries(seed, blending):
    rng = np.random.default_rng(seed)
    patch = random_coons_patch(rng, blending=blending)
    assert patch.blending == blending
    t = np.concatenate([[0.0, 1.0], rng.uniform(0, 1, 20)])
    scale = scale_of(patch)
    zeros, ones = np.zeros_like(t), np.ones_like(t)
    for fixed, values, curve in ((0, zeros, patch.u0), (0, ones, patch.u1), (1, zeros, patch.v0), (1, ones, patch.v1)):
        pairs = np.column_stack([values, t]) if fixed == 0 else np.column_stack([t, values])
        np.testing.assert_allclose(c.points_at(patch, pairs), c.points_at(curve, t), rtol=0, atol=1e-13 * scale)
    grid = c.grid_points_at(patch, t, [0.0, 1.0])
    np.testing.assert_allclose(grid[:, 0], c.points_at(patch.v0, t), rtol=0, atol=1e-13 * scale)
    # Its exact B-spline form is the same surface.
    spline = c.to_bspline_surface(patch)
    pairs = rng.uniform(0, 1, (30, 2))
    np.testing.assert_allclose(c.points_at(spline, pairs), c.points_at(patch, pairs), rtol=0, atol=1e-12 * scale)


def test_coons_patch_takes_any_curve_kind_and_checks_corners():
    square = [c.BezierCurve([[0, 0, 0], [0, 1, 0]]), c.BezierCurve([[1, 0, 0], [1, 1, 0]]),
              c.BSplineCurve(1, [0, 0, 1, 1], [[0, 0, 0], [1, 0, 0]]),
              c.PiecewiseBezierCurve([c.BezierCurve([[0, 1, 0], [0.5, 1, 0]]),
                                      c.BezierCurve([[0.5, 1, 0], [1, 1, 0]])])]
    patch = c.CoonsPatch(*square)
    np.testing.assert_allclose(c.point_at(patch, 0.25, 0.5), [0.25, 0.5, 0], atol=1e-15)
    np.testing.assert_allclose(c.normal_at(patch, 0.5, 0.5), [0, 0, 1], atol=1e-15)
    assert c.breakpoints_u(patch).tolist() == [0.0, 0.5, 1.0]
    with pytest.raises(ValueError, match="corner"):
        c.CoonsPatch(square[0], square[1], square[2], c.BezierCurve([[0, 2, 0], [1, 1, 0]]))
    with pytest.raises(ValueError, match="blending"):
        c.CoonsPatch(*square, blending="quintic")
    with pytest.raises(TypeError):
        c.CoonsPatch(square[0], square[1], square[2], "v1")
    with pytest.raises(ValueError, match="extrapolate"):
        c.point_at(patch, 0.5, 0.5, extrapolate=True)
    assert c.blending_functions("cubic", 0.5) == (0.5, 0.5)
    assert c.blending_functions("linear", 0.25, 1) == (-1.0, 1.0)
    with pytest.raises(ValueError):
        c.blending_functions("linear", 0.25, -1)


# --- derivatives and normals --------------------------------------------------------------


@SEEDED
@given(seeds, kinds)
def test_partial_derivatives_match_finite_differences(seed, kind):
    rng = np.random.default_rng(seed)
    surface = random_surface(rng, kind)
    (a, b), (e, f) = surface.domain_u, surface.domain_v
    u = float(rng.uniform(a + 0.2 * (b - a), b - 0.2 * (b - a)))
    v = float(rng.uniform(e + 0.2 * (f - e), f - 0.2 * (f - e)))
    h = 1e-6 * min(b - a, f - e)
    su = c.partial_derivative_at(surface, u, v, 1, 0)
    sv = c.partial_derivative_at(surface, u, v, 0, 1)
    if isinstance(surface, c.BSplineSurface):
        # Finite differences only inside one knot span.
        knots_u, knots_v = surface.knots_u, surface.knots_v
        if np.any(np.abs(knots_u - u) < 2 * h) or np.any(np.abs(knots_v - v) < 2 * h):
            return
    fd_u = (c.point_at(surface, u + h, v) - c.point_at(surface, u - h, v)) / (2 * h)
    fd_v = (c.point_at(surface, u, v + h) - c.point_at(surface, u, v - h)) / (2 * h)
    size = max(np.abs(su).max(), np.abs(sv).max(), scale_of(surface))
    np.testing.assert_allclose(su, fd_u, rtol=0, atol=1e-5 * size)
    np.testing.assert_allclose(sv, fd_v, rtol=0, atol=1e-5 * size)
    table = c.partial_derivatives_up_to(surface, u, v, 2)
    assert table.shape == (3, 3, 3)
    np.testing.assert_allclose(table[0, 0], c.point_at(surface, u, v), rtol=0, atol=1e-13 * size)
    np.testing.assert_allclose(table[1, 0], su, rtol=0, atol=1e-12 * size)
    np.testing.assert_allclose(table[0, 1], sv, rtol=0, atol=1e-12 * size)
    np.testing.assert_allclose(table[1, 1], c.partial_derivative_at(surface, u, v, 1, 1), rtol=0, atol=1e-11 * size)
    assert np.isnan(table[2, 1]).all() and np.isnan(table[2, 2]).all()
    normal = c.normal_at(surface, u, v)
    cross = np.cross(su, sv)
    if np.linalg.norm(cross) > 1e-6 * size ** 2:
        np.testing.assert_allclose(normal, cross / np.linalg.norm(cross), rtol=0, atol=1e-9)
    np.testing.assert_array_equal(c.normals_at(surface, [[u, v]])[0], normal)


# --- exact operations keep the surface ------------------------------------------------------


@SEEDED
@given(seeds, st.sampled_from(["u", "v"]))
def test_insertion_refinement_elevation_split_keep_the_surface(seed, direction):
    rng = np.random.default_rng(seed)
    surface = random_bspline_surface(rng)
    scale = scale_of(surface)
    pairs = random_pairs(rng, surface, 40)
    reference = c.points_at(surface, pairs)
    low, high = surface.domain(direction)
    value = float(rng.uniform(low, high))
    inserted = c.insert_knot(surface, direction, value, 2)
    assert len(inserted.knots(direction)) == len(surface.knots(direction)) + 2
    np.testing.assert_allclose(c.points_at(inserted, pairs), reference, rtol=0, atol=1e-12 * scale)
    refined = c.refine_knots(surface, direction, rng.uniform(low, high, 3))
    np.testing.assert_allclose(c.points_at(refined, pairs), reference, rtol=0, atol=1e-12 * scale)
    elevated = c.elevate_degree(surface, direction, 2)
    assert elevated.degree(direction) == surface.degree(direction) + 2
    np.testing.assert_allclose(c.points_at(elevated, pairs), reference, rtol=0, atol=1e-11 * scale)
    first, second = c.split_at(surface, direction, value)
    index = 0 if direction == "u" else 1
    for part, mask in ((first, pairs[:, index] <= value), (second, pairs[:, index] >= value)):
        if mask.any():
            np.testing.assert_allclose(c.points_at(part, pairs[mask]), reference[mask], rtol=0, atol=1e-12 * scale)
    # Iso-curves: the surface with one parameter fixed.
    curve = c.iso_curve(surface, direction, value)
    ts = rng.uniform(*surface.domain("v" if direction == "u" else "u"), 10)
    expected = c.points_at(surface, np.column_stack([np.full(10, value), ts] if direction == "u"
                                                    else [ts, np.full(10, value)]))
    np.testing.assert_allclose(c.points_at(curve, ts), expected, rtol=0, atol=1e-12 * scale)


@SEEDED
@given(seeds, st.sampled_from(["u", "v"]))
def test_bezier_patch_operations_keep_the_surface(seed, direction):
    rng = np.random.default_rng(seed)
    patch = random_bezier_surface(rng)
    pairs = rng.uniform(0, 1, (30, 2))
    reference = c.points_at(patch, pairs)
    scale = scale_of(patch)
    elevated = c.elevate_degree(patch, direction, 1)
    np.testing.assert_allclose(c.points_at(elevated, pairs), reference, rtol=0, atol=1e-12 * scale)
    np.testing.assert_allclose(c.points_at(c.to_bspline_surface(patch), pairs), reference, rtol=0, atol=1e-12 * scale)
    first, second = c.split_at(patch, direction, 0.5)
    index = 0 if direction == "u" else 1
    local = pairs.copy()
    mask = pairs[:, index] <= 0.5
    local[mask, index] = pairs[mask, index] * 2
    local[~mask, index] = pairs[~mask, index] * 2 - 1
    if mask.any():
        np.testing.assert_allclose(c.points_at(first, local[mask]), reference[mask], rtol=0, atol=1e-12 * scale)
    if (~mask).any():
        np.testing.assert_allclose(c.points_at(second, local[~mask]), reference[~mask], rtol=0, atol=1e-12 * scale)
    curve = c.iso_curve(patch, direction, 0.25)
    assert isinstance(curve, c.BezierCurve)
    ts = rng.uniform(0, 1, 5)
    expected = c.points_at(patch, np.column_stack([np.full(5, 0.25), ts] if direction == "u"
                                                  else [ts, np.full(5, 0.25)]))
    np.testing.assert_allclose(c.points_at(curve, ts), expected, rtol=0, atol=1e-12 * scale)


def test_transposed_homogeneous_net_and_from_homogeneous():
    rng = np.random.default_rng(11)
    surface = random_bspline_surface(rng, 2, 3, rational=True)
    swapped = c.transposed(surface)
    assert swapped.degree_u == 3 and swapped.degree_v == 2
    pairs = random_pairs(rng, surface, 10)
    np.testing.assert_allclose(c.points_at(swapped, pairs[:, ::-1]), c.points_at(surface, pairs), rtol=0, atol=1e-13)
    net = c.homogeneous_net(surface)
    assert net.shape == surface.control_net.shape[:2] + (4,)
    np.testing.assert_array_equal(net[:, :, 3], surface.weights)
    back = c.from_homogeneous(2, 3, surface.knots_u, surface.knots_v, net)
    np.testing.assert_allclose(back.control_net, surface.control_net, rtol=1e-15, atol=1e-15)
    bad = net.copy()
    bad[1, 1, 3] = -1
    with pytest.raises(ValueError, match="weight"):
        c.from_homogeneous(2, 3, surface.knots_u, surface.knots_v, bad)
    with pytest.raises(ValueError, match="knots_u"):
        c.from_homogeneous(2, 3, surface.knots_u[::-1], surface.knots_v, net)


# --- constructions ---------------------------------------------------------------------------


@SEEDED
@given(seeds)
def test_ruled_surface_skin_and_make_compatible_hold_their_curves(seed):
    rng = np.random.default_rng(seed)
    first = curve_between(rng, rng.uniform(-1, 1, 3), rng.uniform(-1, 1, 3), degree=2, count=4)
    second = c.BezierCurve(rng.uniform(-1, 1, (4, 3)) + [0, 0, 3])
    ruled = c.ruled_surface(first, second)
    assert ruled.degree_v == 1
    t = rng.uniform(0, 1, 12)
    np.testing.assert_allclose(c.points_at(ruled, np.column_stack([t, np.zeros(12)])), c.points_at(first, t),
                               rtol=0, atol=1e-13)
    np.testing.assert_allclose(c.points_at(ruled, np.column_stack([t, np.ones(12)])), c.points_at(second, t),
                               rtol=0, atol=1e-13)
    third = curve_between(rng, rng.uniform(-1, 1, 3) + [0, 0, 6], rng.uniform(-1, 1, 3) + [0, 0, 6])
    sections = [first, second, third]
    compatible = c.make_compatible(sections)
    assert len({(curve.degree, len(curve.knots)) for curve in compatible}) == 1
    for original, made in zip(sections, compatible):
        np.testing.assert_allclose(c.points_at(made, t), c.points_at(original, t), rtol=0, atol=1e-13)
    parameters = c.section_parameters(sections)
    assert parameters[0] == 0 and parameters[-1] == 1 and np.all(np.diff(parameters) > 0)
    skinned = c.skin(sections, 2)
    for section, v in zip(sections, parameters):
        np.testing.assert_allclose(c.points_at(skinned, np.column_stack([t, np.full(12, v)])), c.points_at(section, t),
                                   rtol=0, atol=1e-12)
    uniform = c.section_parameters(sections, "uniform")
    np.testing.assert_allclose(uniform, [0, 0.5, 1])
    with pytest.raises(ValueError):
        c.skin(sections, 3)
    with pytest.raises(ValueError):
        c.skin(sections[:1], 1)
    with pytest.raises(ValueError):
        c.make_compatible([])
    with pytest.raises(ValueError, match="parameterization|uniform"):
        c.skin(sections, 2, "random")


def test_revolve_keeps_the_profile_and_the_distance_to_the_axis():
    rng = np.random.default_rng(5)
    profile = curve_between(rng, np.array([1.0, 0, 0]), np.array([2.0, 0, 3]), degree=2, count=4)
    profile = c.BSplineCurve(profile.degree, profile.knots, np.abs(profile.control_points) + [0.5, 0, 0])
    surface = c.revolve(profile, [0, 0, 0], [0, 0, 1], math.pi)
    assert surface.degree_u == 2
    v = np.linspace(0, 1, 9)
    np.testing.assert_allclose(c.points_at(surface, np.column_stack([np.zeros(9), v])), c.points_at(profile, v),
                               rtol=0, atol=1e-14)
    for u in (0.25, 0.5, 1.0):
        points = c.points_at(surface, np.column_stack([np.full(9, u), v]))
        original = c.points_at(profile, v)
        np.testing.assert_allclose(np.hypot(points[:, 0], points[:, 1]), np.hypot(original[:, 0], original[:, 1]),
                                   rtol=1e-14)
        np.testing.assert_allclose(points[:, 2], original[:, 2], rtol=0, atol=1e-14)
    with pytest.raises(ValueError):
        c.revolve(profile, [0, 0, 0], [0, 0, 0], math.pi)
    with pytest.raises(ValueError):
        c.revolve(profile, [0, 0, 0], [0, 0, 1], 7.0)
    with pytest.raises(ValueError):
        c.revolve(profile, [0, 0], [0, 0, 1], 1.0)


@SEEDED
@given(seeds)
def test_interpolate_grid_passes_through_its_points(seed):
    rng = np.random.default_rng(seed)
    rows, columns = int(rng.integers(4, 8)), int(rng.integers(4, 8))
    x, y = np.meshgrid(np.cumsum(rng.uniform(0.2, 1, rows)), np.cumsum(rng.uniform(0.2, 1, columns)), indexing="ij")
    points = np.stack([x, y, np.sin(x) * np.cos(y)], axis=2)
    us, vs = c.grid_parameters(points)
    assert us[0] == 0 and us[-1] == 1 and len(us) == rows and len(vs) == columns
    surface = c.interpolate_grid(points, 3, 2)
    np.testing.assert_allclose(c.grid_points_at(surface, us, vs), points, rtol=0, atol=1e-12 * np.abs(points).max())
    centripetal = c.interpolate_grid(points, parameterization="centripetal")
    us, vs = c.grid_parameters(points, "centripetal")
    np.testing.assert_allclose(c.grid_points_at(centripetal, us, vs), points, rtol=0,
                               atol=1e-12 * np.abs(points).max())
    with pytest.raises(ValueError, match="degree_u"):
        c.interpolate_grid(points[:3], 3, 3)
    with pytest.raises(ValueError):
        c.interpolate_grid(points, 0, 3)
    with pytest.raises(ValueError):
        c.grid_parameters(points[:1])


# --- classes: properties, equality, pickling ------------------------------------------------


def test_properties_equality_repr_and_pickle():
    rng = np.random.default_rng(9)
    for surface in (random_bspline_surface(rng, rational=True), random_bspline_surface(rng, rational=False),
                    random_bezier_surface(rng, rational=True), random_bezier_surface(rng, rational=False),
                    random_coons_patch(rng, blending="cubic")):
        copy = pickle.loads(pickle.dumps(surface))
        assert copy == surface and type(copy) is type(surface)
        assert repr(surface).startswith(type(surface).__name__ + "(")
        assert surface.dimension == 3
    surface = random_bspline_surface(rng, 2, 1, rational=False)
    assert surface.weights.shape == (0, 0) and not surface.is_rational
    assert surface.control_net.dtype == np.float64 and surface.control_net.ndim == 3
    assert surface.domain_u == (surface.knots_u[2], surface.knots_u[-3])
    assert surface.domain("v") == surface.domain_v and surface.degree("u") == 2
    np.testing.assert_array_equal(surface.knots("v"), surface.knots_v)
    other = c.BSplineSurface(2, 1, surface.knots_u, surface.knots_v, surface.control_net + 1)
    assert other != surface
    # A rational surface with all weights 1 is not the polynomial one (as in C++).
    weighted = c.BSplineSurface(2, 1, surface.knots_u, surface.knots_v, surface.control_net,
                                np.ones(surface.control_net.shape[:2]))
    assert weighted != surface and weighted.is_rational
    patch = c.BezierSurface(np.zeros((2, 3, 2)))
    assert (patch.degree_u, patch.degree_v) == (1, 2) and patch.domain_u == (0.0, 1.0)
    assert c.breakpoints(patch)[0].tolist() == [0.0, 1.0]
    spline_u, spline_v = c.breakpoints(surface)
    np.testing.assert_array_equal(spline_u, np.unique(surface.knots_u[2:-2]))
    np.testing.assert_array_equal(c.breakpoints_v(surface), spline_v)


# --- errors ----------------------------------------------------------------------------------


def bilinear():
    return c.BSplineSurface(1, 1, [0, 0, 1, 1], [0, 0, 2, 2], np.arange(12, dtype=float).reshape(2, 2, 3))


def test_bad_nets_and_weights():
    knots = [0, 0, 1, 1]
    net = np.zeros((2, 2, 3))
    nan_net = net.copy()
    nan_net[1, 0, 2] = np.nan
    with pytest.raises(ValueError, match=r"control_net\[1, 0, 2\] is NaN"):
        c.BSplineSurface(1, 1, knots, knots, nan_net)
    inf_net = net.copy()
    inf_net[0, 1, 0] = np.inf
    with pytest.raises(ValueError, match="infinite"):
        c.BezierSurface(inf_net)
    with pytest.raises(ValueError, match="ragged"):
        c.BezierSurface([[[0, 0], [1, 0]], [[0, 1]]])
    with pytest.raises(ValueError, match="ragged"):
        c.BezierSurface([[[0, 0], [1, 0]], [[0, 1], [1]]])
    for wrong in (np.zeros((4, 3)), np.zeros((2, 2, 2, 3)), np.zeros(3), np.zeros((0, 2, 3)), np.zeros((2, 2, 0))):
        with pytest.raises(ValueError, match="shape"):
            c.BezierSurface(wrong)
    with pytest.raises(TypeError):
        c.BezierSurface(net.astype(complex))
    with pytest.raises(TypeError):
        c.BezierSurface(None)
    with pytest.raises(TypeError):
        c.BezierSurface(net.astype(bool))
    for weights, message in ((np.array([[1, 1], [1, 0.0]]), "weight \\[1\\]\\[1\\]"),
                             (np.array([[1, 1], [-2, 1.0]]), "must be > 0"),
                             (np.array([[1, 1], [np.nan, 1.0]]), "NaN"),
                             (np.ones((2, 3)), "shape"), (np.ones(4), "shape")):
        with pytest.raises(ValueError, match=message):
            c.BSplineSurface(1, 1, knots, knots, net, weights)
        with pytest.raises(ValueError):
            c.BezierSurface(net, weights)
    with pytest.raises(TypeError):
        c.BezierSurface(net, np.ones((2, 2), dtype=complex))
    with pytest.raises(ValueError, match="knots_v"):
        c.BSplineSurface(1, 1, knots, [0, 1, 0, 1], net)
    with pytest.raises(ValueError, match="degree_u"):
        c.BSplineSurface(-1, 1, knots, knots, net)
    with pytest.raises(ValueError, match="rows"):
        c.BSplineSurface(2, 1, [0, 0, 0, 1, 1, 1], knots, net)
    with pytest.raises(ValueError, match="knots_u"):
        c.BSplineSurface(1, 1, [0, 0, np.nan, 1], knots, net)


def test_parameters_outside_the_domain_nan_and_extrapolation():
    surface = bilinear()
    with pytest.raises(ValueError, match="outside the domain"):
        c.point_at(surface, 1.5, 1.0)
    with pytest.raises(ValueError, match="outside the domain"):
        c.point_at(surface, 0.5, 2.5)
    with pytest.raises(ValueError, match="NaN"):
        c.point_at(surface, np.nan, 1.0)
    with pytest.raises(ValueError, match="infinite"):
        c.point_at(surface, 0.5, np.inf, extrapolate=True)
    np.testing.assert_allclose(c.point_at(surface, 1.5, 1.0, extrapolate=True),
                               [1.5 * 6 + 1.5, 1.5 * 6 + 2.5, 1.5 * 6 + 3.5])
    pairs = np.full((3000, 2), 0.5)
    pairs[2500] = [0.5, 3.0]
    with pytest.raises(ValueError, match=r"uv\[2500, 1\] = 3 is outside the domain \[0, 2\] of v"):
        c.points_at(surface, pairs)
    assert c.points_at(surface, pairs, extrapolate=True).shape == (3000, 3)
    pairs[10] = [np.nan, 0.0]
    with pytest.raises(ValueError, match=r"uv\[10, 0\] \(u\) is NaN"):
        c.points_at(surface, pairs, extrapolate=True)
    with pytest.raises(ValueError, match=r"vs \[1\]"):
        c.grid_points_at(surface, [0.5], [0.5, -1.0])
    with pytest.raises(ValueError, match=r"us \[0\]"):
        c.grid_points_at(surface, [np.nan], [0.5])
    with pytest.raises(ValueError, match="outside"):
        c.partial_derivative_at(surface, 2.0, 0.0, 1, 0)
    with pytest.raises(ValueError, match="outside"):
        c.normal_at(surface, -1.0, 0.0)
    with pytest.raises(ValueError, match="outside"):
        c.normals_at(surface, [[0.5, 5.0]])
    with pytest.raises(ValueError, match="outside"):
        c.partial_derivatives_up_to(surface, 0.5, 5.0, 1)
    for pairs in (np.zeros((3, 3)), np.zeros(2), np.zeros((2, 2, 2))):
        with pytest.raises(ValueError, match=r"\(k, 2\)"):
            c.points_at(surface, pairs)
    with pytest.raises(TypeError):
        c.points_at(surface, np.zeros((3, 2), dtype=complex))
    with pytest.raises(TypeError):
        c.grid_points_at(surface, np.zeros(3, dtype=complex), [0.5])
    with pytest.raises(ValueError):
        c.grid_points_at(surface, np.zeros((3, 1)), [0.5])


def test_preconditions_raise_instead_of_asserting():
    surface = bilinear()
    patch = c.BezierSurface(np.zeros((2, 2, 3)))
    for order_u, order_v in ((-1, 0), (0, -1), (1001, 0), (600, 600), (60, 41)):
        with pytest.raises(ValueError, match="order"):
            c.partial_derivative_at(surface, 0.5, 0.5, order_u, order_v)
        with pytest.raises(ValueError, match="order"):
            c.partial_derivative_at(patch, 0.5, 0.5, order_u, order_v)
    for order in (-1, 101, 1001):
        with pytest.raises(ValueError, match="max_order"):
            c.partial_derivatives_up_to(surface, 0.5, 0.5, order)
    np.testing.assert_array_equal(c.partial_derivative_at(surface, 0.5, 0.5, 5, 0), [0, 0, 0])
    plane = c.BSplineSurface(1, 1, [0, 0, 1, 1], [0, 0, 1, 1], np.zeros((2, 2, 2)))
    with pytest.raises(ValueError, match="R\\^3"):
        c.normal_at(plane, 0.5, 0.5)
    with pytest.raises(ValueError, match="R\\^3"):
        c.normals_at(plane, [[0.5, 0.5]])
    with pytest.raises(ValueError, match="'u' or 'v'"):
        c.insert_knot(surface, "w", 0.5)
    with pytest.raises(ValueError, match="'u' or 'v'"):
        c.iso_curve(surface, "U", 0.5)
    with pytest.raises(ValueError):
        c.insert_knot(surface, "u", 0.5, -1)
    with pytest.raises(ValueError):
        c.insert_knot(surface, "u", 3.0)
    with pytest.raises(ValueError):
        c.insert_knot(surface, "v", np.nan)
    with pytest.raises(ValueError):
        c.insert_knot(surface, "u", 0.5, 5)
    with pytest.raises(ValueError):
        c.refine_knots(surface, "u", [0.5, np.nan])
    with pytest.raises(ValueError):
        c.refine_knots(surface, "u", [[0.5]])
    with pytest.raises(ValueError):
        c.elevate_degree(surface, "u", -1)
    with pytest.raises(ValueError):
        c.elevate_degree(surface, "v", 10**6)
    with pytest.raises(ValueError):
        c.elevate_degree(patch, "u", 10**6)
    for value in (0.0, 1.0, np.nan, 2.0):
        with pytest.raises(ValueError):
            c.split_at(surface, "u", value)
        with pytest.raises(ValueError):
            c.split_at(patch, "v", value)
    for value in (np.nan, -0.5, 1.5):
        with pytest.raises(ValueError):
            c.iso_curve(patch, "u", value)
    with pytest.raises(ValueError):
        c.iso_curve(surface, "v", 2.5)
    with pytest.raises(ValueError):
        c.make_sphere([0, 0], 1)
    with pytest.raises(ValueError):
        c.make_sphere([0, 0, 0], 0)
    with pytest.raises(ValueError):
        c.make_sphere([0, 0, np.nan], 1)
    with pytest.raises(ValueError):
        c.make_torus([0, 0, 0], [0, 0, 1], 1, 1)
    with pytest.raises(ValueError):
        c.make_torus([0, 0, 0], [0, 0, 0], 2, 1)
    with pytest.raises(TypeError):
        c.make_compatible([surface])
    with pytest.raises(TypeError):
        c.make_compatible("curves")
    with pytest.raises(ValueError):
        c.grid_parameters(np.zeros((3, 3, 2)))  # every row coincides
    with pytest.raises(ValueError):
        c.section_parameters([])
    with pytest.raises(ValueError):
        c.ruled_surface(c.BezierCurve([[0, 0], [1, 1]]), c.BezierCurve([[0, 0, 0], [1, 1, 1]]))
    with pytest.raises(ValueError):
        c.from_homogeneous(1, 1, [0, 0, 1, 1], [0, 0, 1, 1], np.ones((2, 2, 1)))
