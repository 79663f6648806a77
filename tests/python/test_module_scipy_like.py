"""casteljau.scipy_like against scipy.interpolate (scipy 1.10, the independent reference).

BSpline (call with nu and every extrapolate mode, derivative, antiderivative,
integrate) on seeded random knots for degrees 0..5 with 1-D and 2-D
coefficients; make_interp_spline for k = 0..7 (scipy's default knots, even
and uneven x), given knots t, derivative bc_type for k = 2..6 (mixed orders,
non-zero values); CubicSpline for every bc_type, mixed ones included;
make_lsq_spline on random valid knots with random weights; make_smoothing_spline
with a fixed lam. Differences are
measured relative to the size of scipy's values. hypothesis properties:
interpolants pass through their points, the derivative of the antiderivative
is the spline, integrals add up. Error types for bad arrays.
"""

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st
from scipy import interpolate as si

import casteljau
from casteljau import scipy_like as sl

RTOL = 1e-12


def relative(a, b):
    """max |a - b| / max(1, max |b|), NaN where both are NaN counting as equal."""
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    assert a.shape == b.shape
    both_nan = np.isnan(a) & np.isnan(b)
    assert not np.any(np.isnan(a) ^ np.isnan(b)), "NaN in one result only"
    diff = np.where(both_nan, 0.0, np.abs(a - b))
    scale = max(1.0, float(np.nanmax(np.abs(b))) if b.size and not np.all(np.isnan(b)) else 1.0)
    return float(diff.max() / scale) if diff.size else 0.0


def random_knots(rng, count, k):
    """Increasing knots with steps in [0.25, 1.25] (no tiny spans), some repeated strictly inside the base
    interval [t_k, t_n] only: scipy extrapolates from the span [t_k, t_{k+1}] even when it is empty (and gives
    0 there), casteljau from the first non-empty span; the two agree when the end spans are not empty."""
    steps = rng.uniform(0.25, 1.25, count - 1)
    n = count - k - 1
    inside = np.arange(count - 1)
    steps[(rng.random(count - 1) < 0.2) & (inside >= k + 1) & (inside <= n - 2)] = 0.0
    return np.concatenate([[0.0], np.cumsum(steps)]) - 1.5


def random_spline(rng, k, columns):
    n = k + 1 + int(rng.integers(0, 6))
    while True:
        t = random_knots(rng, n + k + 1, k)
        # casteljau's multiplicity <= k+1
        values, counts = np.unique(t, return_counts=True)
        if counts.max() <= k + 1:
            break
    c = rng.normal(size=(n,) if columns == 0 else (n, columns)) * 10
    return t, c


# --- BSpline --------------------------------------------------------------------------


@pytest.mark.parametrize("k", range(6))
@pytest.mark.parametrize("columns", [0, 3])
def test_bspline_call_matches_scipy(k, columns):
    rng = np.random.default_rng(100 + 10 * k + columns)
    for _ in range(5):
        t, c = random_spline(rng, k, columns)
        ours, theirs = sl.BSpline(t, c, k), si.BSpline(t, c, k)
        x = np.concatenate([rng.uniform(t[k] - 0.5, t[-k - 1] + 0.5, 40), t[k:len(t) - k]])
        x = x[:x.size // 2 * 2].reshape(2, -1)
        for nu in range(k + 2):
            for extrapolate in (True, False, "periodic"):
                got, want = ours(x, nu, extrapolate), theirs(x, nu, extrapolate)
                assert got.shape == want.shape == x.shape + c.shape[1:]
                assert relative(got, want) <= RTOL, (k, nu, extrapolate)


@pytest.mark.parametrize("k", range(6))
def test_bspline_derivative_antiderivative_integrate_match_scipy(k):
    rng = np.random.default_rng(200 + k)
    for trial in range(6):
        t, c = random_spline(rng, k, trial % 2 * 2)
        ours, theirs = sl.BSpline(t, c, k), si.BSpline(t, c, k)
        x = rng.uniform(t[k], t[-k - 1], 50)
        for nu in range(1, k + 1):
            if np.any(np.diff(t)[1:-1] == 0) and nu > 0:
                # scipy's splder raises on a knot of multiplicity k+1 - nu + 1 inside
                try:
                    want = theirs.derivative(nu)(x)
                except ValueError:
                    continue
            else:
                want = theirs.derivative(nu)(x)
            got = ours.derivative(nu)
            assert got.k == k - nu
            assert relative(got(x), want) <= 1e-11
        for nu in range(1, 4):
            got, want = ours.antiderivative(nu), theirs.antiderivative(nu)
            assert got.k == want.k
            np.testing.assert_array_equal(got.t, want.t)
            n = len(got.t) - got.k - 1
            assert relative(got.c, want.c[:n]) <= RTOL
            assert relative(got(x), want(x)) <= RTOL
        for extrapolate in (True, False, "periodic"):
            for _ in range(4):
                a, b = rng.uniform(t[0] - 1, t[-1] + 1, 2)
                if extrapolate is False and (max(a, b) < t[k] or min(a, b) > t[-k - 1]):
                    continue  # outside the base interval: casteljau 0, scipy NaN (2-D c) or splint's value
                got, want = ours.integrate(a, b, extrapolate), theirs.integrate(a, b, extrapolate)
                assert np.shape(got) == np.shape(want)
                if extrapolate is False and not (t[k] == t[0] and t[-1] == t[-k - 1]):
                    continue  # scipy's splint integrates the unclamped basis beyond the base interval
                assert relative(got, want) <= 1e-11, (a, b, extrapolate)


def test_bspline_derivative_order_above_degree_raises_like_scipy():
    spline = sl.BSpline([0, 0, 0, 1, 2, 2, 2], [1.0, 2.0, 0.0, 3.0], 2)
    with pytest.raises(ValueError):
        spline.derivative(3)


def test_basis_element_matches_scipy():
    for knots in ([0, 1, 2, 3, 4], [0, 1, 1, 2], [0, 0.5, 2]):
        x = np.linspace(-1, 5, 31)
        ours, theirs = sl.BSpline.basis_element(knots), si.BSpline.basis_element(knots)
        assert relative(ours(x), theirs(x)) <= RTOL
        assert relative(ours.integrate(0, 1), theirs.integrate(0, 1)) <= RTOL


def test_construct_fast_and_attributes():
    t = np.array([0.0, 0, 0, 1, 2, 2, 2])
    c = np.array([1.0, 2.0, 0.0, 3.0])
    spline = sl.BSpline.construct_fast(t, c, 2)
    assert spline.k == 2 and spline.t is t and spline.c is c and spline.extrapolate is True and spline.axis == 0
    assert relative(spline(np.array([0.5, 1.5])), si.BSpline(t, c, 2)(np.array([0.5, 1.5]))) <= RTOL
    assert isinstance(spline.curve, casteljau.BSplineCurve)


def test_scalar_x_gives_a_zero_d_array():
    spline = sl.BSpline([0, 0, 1, 1], [0.0, 2.0], 1)
    value = spline(0.25)
    assert value.shape == () and float(value) == 0.5


# --- make_interp_spline -------------------------------------------------------------------


def uneven_x(rng, count):
    return np.cumsum(rng.uniform(0.3, 1.5, count))


@pytest.mark.parametrize("k", [1, 2, 3, 4, 5, 6, 7])
def test_make_interp_spline_default_matches_scipy(k):
    rng = np.random.default_rng(300 + k)
    for even in (True, False):
        x = np.linspace(0, 7, 12) if even else uneven_x(rng, 12)
        y = rng.normal(size=(12, 2))
        ours = sl.make_interp_spline(x, y, k=k)
        xs = np.linspace(x[0], x[-1], 101)
        assert relative(ours(x), y) <= RTOL
        if k in (4, 6):
            with pytest.raises(ValueError):
                si.make_interp_spline(x, y, k=k)  # scipy refuses even k >= 4; casteljau averages (documented)
            continue
        theirs = si.make_interp_spline(x, y, k=k)
        np.testing.assert_array_equal(ours.t, theirs.t)
        assert relative(ours.c, theirs.c) <= 1e-10
        assert relative(ours(xs), theirs(xs)) <= 1e-11
        assert relative(ours(xs, 1), theirs(xs, 1)) <= 1e-10


@pytest.mark.parametrize("count", [1, 2, 12])
@pytest.mark.parametrize("columns", [0, 2])
def test_make_interp_spline_k0_matches_scipy(count, columns):
    """Issue 15: k=0 failed with a knot-multiplicity message. scipy's piecewise constant has the knots
    x, x[-1] and takes y[i] on [x[i], x[i+1]), y[-1] at x[-1] and beyond (its empty last span): the same knots,
    coefficients and values in every extrapolate mode, at the data, between them and outside."""
    rng = np.random.default_rng(150 + count)
    x = uneven_x(rng, count)
    y = rng.normal(size=(count, columns) if columns else count)
    ours, theirs = sl.make_interp_spline(x, y, k=0), si.make_interp_spline(x, y, k=0)
    np.testing.assert_array_equal(ours.t, theirs.t)
    np.testing.assert_array_equal(ours.c, theirs.c)
    assert ours.k == theirs.k == 0
    middles = (x[1:] + x[:-1]) / 2 if count > 1 else x
    xs = np.r_[x[0] - 2.0, x[0] - 1e-9, x, middles, x[-1] + 1e-9, x[-1] + 1.0, x[-1] + 100.0, np.nan]
    for extrapolate in (None, True, False, "periodic"):
        if extrapolate == "periodic" and count == 1:
            continue  # a period of length 0
        np.testing.assert_array_equal(ours(xs, extrapolate=extrapolate), theirs(xs, extrapolate=extrapolate))
    # The integral of the step function over the data: Σ y_i (x_{i+1} - x_i). (scipy 1.10 gives 0 from x[-1]
    # on: its antiderivative evaluates the empty last span; casteljau's is the step function's, documented.)
    if count > 1:
        steps = np.diff(x).reshape((-1,) + (1,) * (y.ndim - 1))
        assert relative(ours.integrate(x[0], x[-1]), (y[:-1] * steps).sum(axis=0)) <= RTOL
    with pytest.raises(ValueError, match="Too much info for k=0"):
        sl.make_interp_spline(x, y, k=0, bc_type="natural")


@pytest.mark.parametrize("bc_type", [None, "not-a-knot", "natural", "clamped", "periodic",
                                     ([(1, 0.5)], [(1, -2.0)]), ([(2, 0.0)], [(2, 0.0)])])
def test_make_interp_spline_cubic_bc_types_match_scipy(bc_type):
    rng = np.random.default_rng(400)
    x = uneven_x(rng, 15)
    y = rng.normal(size=15) * 5
    if bc_type == "periodic":
        y[-1] = y[0]
    ours, theirs = sl.make_interp_spline(x, y, k=3, bc_type=bc_type), si.make_interp_spline(x, y, k=3, bc_type=bc_type)
    xs = np.linspace(x[0] - 1, x[-1] + 1, 201)
    np.testing.assert_allclose(ours.t, theirs.t, rtol=0, atol=1e-13 * x[-1])
    n = len(ours.t) - 4
    assert relative(ours.c, theirs.c[:n]) <= 1e-11
    for nu in range(4):
        assert relative(ours(xs, nu), theirs(xs, nu)) <= 1e-10


def random_bc(rng, k, columns):
    """Random end derivatives for scipy's default derivative knots (x[0]*k, x, x[-1]*k): k-1 of them, split
    between the ends as evenly as possible (either way round), at each end `count` distinct orders out of
    1..count+1 (orders far above the count make the system nearly singular, in scipy as in casteljau), values of
    the shape of y[0]."""
    total = k - 1
    left_count = total // 2 if rng.random() < 0.5 else total - total // 2
    def side(count):  # scipy wants None rather than an empty list
        orders = np.sort(rng.choice(np.arange(1, count + 2), size=count, replace=False))
        return [(int(order), rng.normal(size=columns) * 3) for order in orders] or None
    return side(left_count), side(total - left_count)


@pytest.mark.parametrize("k", [2, 3, 4, 5, 6])
def test_make_interp_spline_derivative_bc_matches_scipy(k):
    rng = np.random.default_rng(700 + k)
    for trial in range(6):
        x = uneven_x(rng, 9 + trial)
        y = rng.normal(size=(x.size, 2)) * 4
        bc_type = random_bc(rng, k, 2)
        ours, theirs = sl.make_interp_spline(x, y, k=k, bc_type=bc_type), si.make_interp_spline(x, y, k=k, bc_type=bc_type)
        np.testing.assert_array_equal(ours.t, theirs.t)
        assert relative(ours.c, theirs.c) <= 1e-10
        xs = np.linspace(x[0], x[-1], 101)
        for nu in range(k + 1):
            assert relative(ours(xs, nu), theirs(xs, nu)) <= 1e-9
        # the prescribed derivatives hold (to the rounding of a k-th derivative)
        for at, side in ((x[0], bc_type[0]), (x[-1], bc_type[1])):
            for order, value in side or ():
                assert relative(ours(np.array([at]), order)[0], value) <= 1e-8


@pytest.mark.parametrize("bc_type", [([(1, 0.5)], [(2, -1.0)]), ([(2, 3.0)], [(2, 0.0)]), ("natural", "clamped"),
                                     ([(1, 1.0), (2, 0.5)], None), (None, [(2, 1.0), (1, 0.5)])])
def test_make_interp_spline_cubic_mixed_bc_matches_scipy(bc_type):
    rng = np.random.default_rng(450)
    x = uneven_x(rng, 12)
    y = rng.normal(size=12) * 5
    ours, theirs = sl.make_interp_spline(x, y, k=3, bc_type=bc_type), si.make_interp_spline(x, y, k=3, bc_type=bc_type)
    np.testing.assert_array_equal(ours.t, theirs.t)
    assert relative(ours.c, theirs.c) <= 1e-10


def random_interpolation_knots(rng, x, k, extra):
    """Knots clamped at x[0] and x[-1] with len(x) + extra - k - 1 interior knots, each between the sites that
    Schoenberg-Whitney allows: the j-th interior knot strictly inside (x[j], x[j+k+1]) of the extended sites
    (x[0] repeated for the derivative rows at the start): The NURBS Book's average of k sites (eq. 9.8, well
    conditioned) moved at random by up to a tenth of its window."""
    sites = np.r_[(x[0],) * (extra // 2), x, (x[-1],) * (extra - extra // 2)]
    n = sites.size
    interior = []
    for j in range(1, n - k):
        window = sites[j + k] - sites[j]
        interior.append(np.mean(sites[j:j + k]) + rng.uniform(-0.1, 0.1) * window)
    interior = np.sort(interior)
    return np.r_[(x[0],) * (k + 1), interior, (x[-1],) * (k + 1)]


@pytest.mark.parametrize("k", [1, 2, 3, 4, 5])
def test_make_interp_spline_with_t_matches_scipy(k):
    rng = np.random.default_rng(800 + k)
    for trial in range(5):
        x = uneven_x(rng, 10 + trial)
        y = rng.normal(size=(x.size, 3)) * 2
        t = random_interpolation_knots(rng, x, k, 0)
        ours, theirs = sl.make_interp_spline(x, y, k=k, t=t), si.make_interp_spline(x, y, k=k, t=t)
        np.testing.assert_array_equal(ours.t, t)
        assert relative(ours.c, theirs.c) <= 1e-10
        assert relative(ours(x), y) <= 1e-10
        if k >= 2:  # with end derivatives: one at each end
            t = random_interpolation_knots(rng, x, k, 2)
            bc_type = ([(1, rng.normal(size=3))], [(k - 1 if k > 2 else 1, rng.normal(size=3))])
            ours = sl.make_interp_spline(x, y, k=k, t=t, bc_type=bc_type)
            theirs = si.make_interp_spline(x, y, k=k, t=t, bc_type=bc_type)
            assert relative(ours.c, theirs.c) <= 1e-10


def test_make_interp_spline_bad_requests_raise_value_error():
    x, y = np.arange(8.0), np.sin(np.arange(8.0))
    # a knot count that does not match: scipy raises too
    t = np.r_[[0.0] * 4, 2.5, [7.0] * 4]
    with pytest.raises(ValueError):
        si.make_interp_spline(x, y, k=3, t=t)
    with pytest.raises(ValueError, match="9 knots given.*12 knots"):
        sl.make_interp_spline(x, y, k=3, t=t)
    # Schoenberg-Whitney: four knots between x[4] and x[5] leave basis function 4 without a parameter
    t = np.r_[[0.0] * 4, 4.2, 4.4, 4.6, 4.8, [7.0] * 4]
    with pytest.raises(ValueError, match=r"parameter \d+ \(.*\) is not inside the support .* of basis function "
                                         r"\d+.*Schoenberg"):
        sl.make_interp_spline(x, y, k=3, t=t)
    # knots that decrease or are NaN
    with pytest.raises(ValueError, match="sorted"):
        sl.make_interp_spline(x, y, k=3, t=np.r_[[0.0] * 4, 3.0, 2.0, 4.0, 5.0, [7.0] * 4])
    with pytest.raises(ValueError, match="NaN"):
        sl.make_interp_spline(x, y, k=3, t=np.r_[[0.0] * 4, 3.0, np.nan, 4.0, 5.0, [7.0] * 4])
    # the derivative count must fit scipy's default knots (k - 1 in all)
    with pytest.raises(ValueError, match="expected 4, got 1\\+0"):
        sl.make_interp_spline(x, y, k=5, bc_type="clamped"[:0] or ([(1, 0.0)], None))
    with pytest.raises(ValueError, match="expected 4"):
        sl.make_interp_spline(x, y, k=5, bc_type="clamped")
    # a derivative order above k
    with pytest.raises(ValueError, match="order 4"):
        sl.make_interp_spline(x, y, k=3, bc_type=([(4, 0.0)], [(1, 0.0)]))
    # x strictly inside the knots' domain: scipy accepts, casteljau refuses (documented)
    with pytest.raises(ValueError, match="domain"):
        sl.make_interp_spline(x, y, k=3, t=np.r_[[-1.0] * 4, 1.5, 2.5, 3.5, 4.5, [7.0] * 4])
    with pytest.raises(ValueError, match="axis"):
        sl.make_interp_spline(x, np.c_[y, y].T, axis=1)
    with pytest.raises(ValueError, match="periodic"):
        sl.make_interp_spline(x, np.r_[y[:-1], y[0]], k=5, bc_type="periodic")
    # t equal to the default knots gives the same spline
    spline = sl.make_interp_spline(x, y)
    again = sl.make_interp_spline(x, y, t=spline.t)
    np.testing.assert_array_equal(again.t, spline.t)
    assert relative(again.c, spline.c) <= 1e-13


# --- CubicSpline -----------------------------------------------------------------------


@pytest.mark.parametrize("bc_type", ["not-a-knot", "natural", "clamped", "periodic", ((1, 0.5), (1, -1.0)),
                                     ((2, 0.0), (2, 0.0)), ("natural", (2, 0.0)), ("clamped", (1, 0.0))])
def test_cubic_spline_matches_scipy(bc_type):
    rng = np.random.default_rng(500)
    x = uneven_x(rng, 11)
    y = rng.normal(size=(11, 2))
    if bc_type == "periodic":
        y[-1] = y[0]
    # scipy wants each value of the shape of y[0]
    if bc_type == ((1, 0.5), (1, -1.0)):
        bc_type = ((1, np.array([0.5, 2.0])), (1, np.array([-1.0, 0.0])))
    elif isinstance(bc_type, tuple):
        bc_type = tuple(side if isinstance(side, str) else (side[0], np.zeros(2)) for side in bc_type)
    ours, theirs = sl.CubicSpline(x, y, bc_type=bc_type), si.CubicSpline(x, y, bc_type=bc_type)
    xs = np.linspace(x[0] - 1, x[-1] + 1, 201)
    for nu in range(4):
        assert relative(ours(xs, nu), theirs(xs, nu)) <= 1e-10
    assert relative(ours.derivative()(xs), theirs.derivative()(xs)) <= 1e-10
    inside = np.linspace(x[0], x[-1], 101)
    for nu in (1, 2):
        assert relative(ours.antiderivative(nu)(inside), theirs.antiderivative(nu)(inside)) <= 1e-10
    for a, b in ((x[0], x[-1]), (x[2] + 0.1, x[5]), (x[-1] - 0.3, x[0] - 2.0), (x[0] - 3, x[-1] + 20)):
        for extrapolate in (None, True, False):
            assert relative(ours.integrate(a, b, extrapolate), theirs.integrate(a, b, extrapolate)) <= 1e-10
    np.testing.assert_array_equal(ours.x, x)


@pytest.mark.parametrize("count", [2, 3])
def test_cubic_spline_few_points_not_a_knot(count):
    x = np.array([0.0, 1.0, 3.0])[:count]
    y = np.array([1.0, -1.0, 2.0])[:count]
    xs = np.linspace(-1, 4, 21)
    assert relative(sl.CubicSpline(x, y)(xs), si.CubicSpline(x, y)(xs)) <= RTOL


@pytest.mark.parametrize("count", [2, 3, 4, 9])
@pytest.mark.parametrize("bc_type", [((1, 0.5), (2, 1.0)), ("not-a-knot", (1, 0.0)), ((2, 3.0), "not-a-knot"),
                                     ((2, 3.0), (2, -1.0)), ("natural", "clamped")])
def test_cubic_spline_mixed_conditions_match_scipy(count, bc_type):
    rng = np.random.default_rng(550 + count)
    x = uneven_x(rng, count)
    y = rng.normal(size=count) * 3
    ours, theirs = sl.CubicSpline(x, y, bc_type=bc_type), si.CubicSpline(x, y, bc_type=bc_type)
    xs = np.linspace(x[0] - 1, x[-1] + 1, 101)
    for nu in range(4):
        assert relative(ours(xs, nu), theirs(xs, nu)) <= 1e-10


def test_cubic_spline_bad_periodic_raises_value_error():
    x, y = np.arange(6.0), np.cos(np.arange(6.0))
    with pytest.raises(ValueError):
        sl.CubicSpline(x, y, bc_type="periodic")  # y[0] != y[-1]


# --- fits ------------------------------------------------------------------------------


@pytest.mark.parametrize("k", [1, 2, 3, 5])
def test_make_lsq_spline_on_approximation_knots_matches_scipy(k):
    rng = np.random.default_rng(600 + k)
    x = np.sort(rng.uniform(0, 10, 60))
    y = np.sin(x) + rng.normal(scale=0.1, size=(60,))
    t = casteljau.approximation_knots(x, k, 12)
    ours, theirs = sl.make_lsq_spline(x, y, t, k), si.make_lsq_spline(x, y, t, k)
    np.testing.assert_array_equal(ours.t, t)
    assert relative(ours.c, theirs.c) <= 1e-10
    xs = np.linspace(x[0], x[-1], 101)
    assert relative(ours(xs), theirs(xs)) <= 1e-10


def random_lsq_knots(rng, x, k, count):
    """count interior knots at distinct random data sites' midpoints, at least k+1 data points apart, so that
    Schoenberg-Whitney holds; the ends clamped at x[0] and x[-1], or (unclamped) continued below / above them."""
    picks = np.sort(rng.choice(np.arange(k + 1, x.size - k - 1, k + 1), size=count, replace=False))
    interior = (x[picks] + x[picks - 1]) / 2
    if rng.random() < 0.5:
        return np.r_[(x[0],) * (k + 1), interior, (x[-1],) * (k + 1)]
    below = x[0] - np.cumsum(rng.uniform(0.1, 1.0, k))[::-1]
    above = x[-1] + np.cumsum(rng.uniform(0.1, 1.0, k))
    return np.r_[below, x[0], interior, x[-1], above]


@pytest.mark.parametrize("k", [1, 2, 3, 4, 5])
def test_make_lsq_spline_with_random_knots_and_weights_matches_scipy(k):
    rng = np.random.default_rng(650 + k)
    for trial in range(5):
        x = np.sort(rng.uniform(-5, 20, 80))
        y = np.c_[np.cos(x), x ** 2 / 50] + rng.normal(scale=0.05, size=(80, 2))
        t = random_lsq_knots(rng, x, k, int(rng.integers(1, 8)))
        w = rng.uniform(0.1, 4.0, 80) if trial % 2 == 0 else None
        ours, theirs = sl.make_lsq_spline(x, y, t, k, w=w), si.make_lsq_spline(x, y, t, k, w=w)
        np.testing.assert_array_equal(ours.t, t)
        assert relative(ours.c, theirs.c) <= 1e-10
        xs = np.linspace(x[0], x[-1], 101)
        assert relative(ours(xs), theirs(xs)) <= 1e-10
    # zero weights leave their points out (scipy's NaN workaround)
    x = np.linspace(0, 10, 40)
    y = np.sin(x)
    w = np.ones(40)
    w[::7] = 0.0
    y_bad = np.where(w == 0, 1e6, y)
    t = np.r_[[0.0] * (k + 1), 2.5, 5.0, 7.5, [10.0] * (k + 1)]
    ours, theirs = sl.make_lsq_spline(x, y_bad, t, k, w=w), si.make_lsq_spline(x, y_bad, t, k, w=w)
    assert relative(ours.c, theirs.c) <= 1e-10
    assert relative(ours.c, si.make_lsq_spline(x[w > 0], y[w > 0], t, k).c) <= 1e-10


def test_make_lsq_spline_bad_requests_raise_value_error():
    x = np.linspace(0, 10, 30)
    y = np.sin(x)
    t = np.r_[[0.0] * 4, 5.0, [10.0] * 4]
    with pytest.raises(ValueError, match="basis function 4 .*Schoenberg"):  # 5 knots between two data points
        sl.make_lsq_spline(x, y, np.r_[[0.0] * 4, 5.2, 5.25, 5.3, 5.35, 5.4, [10.0] * 4], 3)
    with pytest.raises(ValueError, match="Schoenberg"):  # every point weighted 0 on the right half
        sl.make_lsq_spline(x, y, t, 3, w=np.r_[np.ones(15), np.zeros(15)])
    with pytest.raises(ValueError, match="outside the knots' domain"):
        sl.make_lsq_spline(x, y, np.r_[[1.0] * 4, 5.0, [10.0] * 4], 3)
    with pytest.raises(ValueError, match="sorted"):
        sl.make_lsq_spline(x, y, np.r_[[0.0] * 4, 6.0, 5.0, [10.0] * 4], 3)
    with pytest.raises(ValueError, match="NaN"):
        sl.make_lsq_spline(x, y, np.r_[[0.0] * 4, np.nan, [10.0] * 4], 3)
    with pytest.raises(ValueError, match="incompatible"):
        sl.make_lsq_spline(x, y, t, 3, w=np.ones(29))
    with pytest.raises(ValueError, match=">= 0"):
        sl.make_lsq_spline(x, y, t, 3, w=-np.ones(30))
    with pytest.raises(ValueError, match="multiplicity"):
        sl.make_lsq_spline(x, y, np.r_[[0.0] * 5, 5.0, [10.0] * 4], 3)


@pytest.mark.parametrize("lam", [1e-3, 0.1, 10.0])
def test_make_smoothing_spline_with_fixed_lam_matches_scipy(lam):
    rng = np.random.default_rng(700)
    x = np.sort(rng.uniform(0, 5, 40))
    y = np.cos(2 * x) + rng.normal(scale=0.2, size=40)
    ours, theirs = sl.make_smoothing_spline(x, y, lam=lam), si.make_smoothing_spline(x, y, lam=lam)
    xs = np.linspace(x[0], x[-1], 151)
    assert relative(ours(xs), theirs(xs)) <= 1e-9
    assert relative(ours(xs, 1), theirs(xs, 1)) <= 1e-8


@pytest.mark.parametrize("lam", [1e-3, 0.1, 10.0])
def test_make_smoothing_spline_with_weights_matches_scipy(lam):
    # scipy weighs each squared residual by w (not squared), as casteljau does.
    rng = np.random.default_rng(702)
    x = np.sort(rng.uniform(0, 5, 40))
    y = np.cos(2 * x) + rng.normal(scale=0.2, size=40)
    w = rng.uniform(0.1, 5.0, 40)
    ours, theirs = sl.make_smoothing_spline(x, y, w=w, lam=lam), si.make_smoothing_spline(x, y, w=w, lam=lam)
    xs = np.linspace(x[0], x[-1], 151)
    assert relative(ours(xs), theirs(xs)) <= 1e-9
    # Weights that all equal c are the unweighted spline at lam / c.
    scaled = sl.make_smoothing_spline(x, y, w=np.full(40, 4.0), lam=4.0 * lam)
    assert relative(scaled(xs), sl.make_smoothing_spline(x, y, lam=lam)(xs)) <= 1e-12
    for bad in (np.r_[np.ones(39), 0.0], -np.ones(40), np.ones(39)):
        with pytest.raises(ValueError, match="Invalid vector of weights"):
            sl.make_smoothing_spline(x, y, w=bad, lam=lam)


def test_make_smoothing_spline_by_gcv_is_close_to_scipy():
    rng = np.random.default_rng(701)
    x = np.sort(rng.uniform(0, 5, 50))
    y = np.sin(x) + rng.normal(scale=0.1, size=50)
    xs = np.linspace(x[0], x[-1], 101)
    # different lambda searches: the curves agree to the noise level, not to rounding
    assert relative(sl.make_smoothing_spline(x, y)(xs), si.make_smoothing_spline(x, y)(xs)) <= 0.05


# --- properties ------------------------------------------------------------------------

steps = st.lists(st.floats(0.1, 3.0), min_size=6, max_size=14)


@settings(derandomize=True, max_examples=40, deadline=None)
@given(steps, st.integers(1, 5), st.sampled_from([None, "natural", "clamped"]), st.integers(0, 2**31 - 1))
def test_interpolants_pass_through_their_points(step_list, k, bc_type, seed):
    x = np.cumsum(step_list)
    y = np.random.default_rng(seed).normal(size=(x.size, 2)) * 10
    if bc_type is not None and k != 3:
        bc_type = None
    spline = sl.make_interp_spline(x, y, k=k, bc_type=bc_type)
    assert relative(spline(x), y) <= 1e-11
    cubic = sl.CubicSpline(x, y, bc_type=bc_type or "not-a-knot")
    assert relative(cubic(x), y) <= 1e-11


@settings(derandomize=True, max_examples=30, deadline=None)
@given(st.integers(1, 5), st.integers(1, 6), st.floats(1e-3, 1e3), st.integers(0, 2**31 - 1))
def test_lsq_splines_reproduce_polynomials_and_ignore_the_weights_scale(k, interior, scale, seed):
    rng = np.random.default_rng(seed)
    x = np.sort(rng.uniform(-3, 9, 60))
    t = random_lsq_knots(rng, x, k, interior)
    w = rng.uniform(0.1, 5.0, 60)
    coefficients = rng.normal(size=k + 1)
    y = np.polynomial.polynomial.polyval((x - 3) / 6, coefficients)
    spline = sl.make_lsq_spline(x, y, t, k, w=w)
    assert relative(spline(x), y) <= 1e-10
    noisy = y + rng.normal(scale=0.1, size=60)
    assert relative(sl.make_lsq_spline(x, noisy, t, k, w=w * scale).c, sl.make_lsq_spline(x, noisy, t, k, w=w).c) <= 1e-10


@settings(derandomize=True, max_examples=30, deadline=None)
@given(st.integers(1, 6), st.integers(0, 2**31 - 1))
def test_splines_on_given_knots_pass_through_their_points(k, seed):
    rng = np.random.default_rng(seed)
    x = uneven_x(rng, int(rng.integers(k + 3, 20)))
    y = rng.normal(size=(x.size, 2)) * 10
    extra = 0 if k == 1 else int(rng.integers(0, 2)) * 2
    t = random_interpolation_knots(rng, x, k, extra)
    bc_type = None if extra == 0 else ([(1, rng.normal(size=2))], [(1, rng.normal(size=2))])
    spline = sl.make_interp_spline(x, y, k=k, t=t, bc_type=bc_type)
    assert relative(spline(x), y) <= 1e-9
    if bc_type is not None:
        assert relative(spline(x[[0, -1]], 1), np.array([bc_type[0][0][1], bc_type[1][0][1]])) <= 1e-8


@settings(derandomize=True, max_examples=40, deadline=None)
@given(st.integers(0, 5), st.integers(0, 2**31 - 1), st.integers(1, 3))
def test_derivative_of_antiderivative_is_the_spline(k, seed, nu):
    rng = np.random.default_rng(seed)
    t, c = random_spline(rng, k, 2)
    spline = sl.BSpline(t, c, k)
    back = spline.antiderivative(nu).derivative(nu)
    x = rng.uniform(t[k], t[-k - 1], 30)
    assert relative(back(x), spline(x)) <= 1e-10


@settings(derandomize=True, max_examples=40, deadline=None)
@given(st.integers(0, 5), st.integers(0, 2**31 - 1))
def test_integrals_add_up(k, seed):
    rng = np.random.default_rng(seed)
    t, c = random_spline(rng, k, 0)
    spline = sl.BSpline(t, c, k)
    a, b, m = rng.uniform(t[0] - 1, t[-1] + 1, 3)
    scale = max(1.0, float(np.abs(spline.integrate(min(a, b, m), max(a, b, m)))))
    for extrapolate in (True, False):
        total = spline.integrate(a, m, extrapolate) + spline.integrate(m, b, extrapolate)
        assert abs(total - spline.integrate(a, b, extrapolate)) <= 1e-11 * scale * (t[-1] - t[0])
    assert spline.integrate(a, b) == -spline.integrate(b, a)


# --- errors ----------------------------------------------------------------------------


def test_bad_arrays_raise_the_right_errors():
    x = np.arange(6.0)
    y = np.sin(x)
    with pytest.raises(ValueError):
        sl.make_interp_spline(x, y[:-1])                     # wrong shape
    with pytest.raises(ValueError):
        sl.make_interp_spline(np.c_[x, x], y)                # x not 1-D
    with pytest.raises(ValueError):
        sl.make_interp_spline(x, np.r_[y[:-1], np.nan])      # NaN in y
    with pytest.raises(ValueError):
        sl.make_interp_spline(np.r_[x[:-1], np.nan], y)      # NaN in x
    with pytest.raises(ValueError):
        sl.make_interp_spline([], [])                        # empty
    with pytest.raises(ValueError):
        sl.make_interp_spline(x[:3], y[:3], k=3)             # too few points for not-a-knot
    with pytest.raises(ValueError):
        sl.make_interp_spline(x[::-1], y)                    # x not increasing
    with pytest.raises(ValueError):
        sl.CubicSpline(x[:1], y[:1])
    with pytest.raises(TypeError):
        sl.make_interp_spline(x, y + 1j)
    with pytest.raises(TypeError):
        sl.CubicSpline(x, y.astype(complex))
    with pytest.raises(TypeError):
        sl.BSpline([0, 0, 1, 1], np.array([1, 2], dtype=complex), 1)
    with pytest.raises(ValueError):
        sl.BSpline([0, 0, 1, 1], [1.0, np.nan], 1)
    with pytest.raises(ValueError):
        sl.BSpline([0, 1, 0.5, 1], [1.0, 2.0], 1)            # knots decrease
    with pytest.raises(ValueError):
        sl.BSpline([0, 0, 1, 1], [1.0], 1)                   # too few coefficients
    with pytest.raises(ValueError, match="axis"):
        sl.BSpline([0, 0, 1, 1], np.ones((2, 3)), 1, axis=1)
    spline = sl.BSpline([0, 0, 1, 1], [1.0, 2.0], 1)
    with pytest.raises(TypeError):
        spline(np.array([0.5j]))
    with pytest.raises(ValueError):
        spline(0.5, nu=-1)


def test_other_dtypes_and_layouts_give_the_same_result():
    rng = np.random.default_rng(800)
    x = np.arange(10)
    y = rng.integers(-5, 5, size=(10, 3))
    reference = sl.make_interp_spline(x.astype(float), y.astype(float))
    xs = np.linspace(0, 9, 17)
    for xx, yy in ((x, y), (x.astype(np.float32), y.astype(np.float32)), (x, np.asfortranarray(y.astype(float))),
                   (x.astype(float)[::-1][::-1], y.astype(float)[:, ::-1][:, ::-1])):
        # float32 and integer data hold exactly representable values here: the same float64 result
        np.testing.assert_array_equal(sl.make_interp_spline(xx, yy)(xs), reference(xs))
    strided = np.linspace(0, 9, 34)[::2]
    np.testing.assert_array_equal(reference(strided), reference(np.ascontiguousarray(strided)))
    np.testing.assert_array_equal(reference(strided.astype(np.float32)), reference(strided.astype(np.float32).astype(float)))
