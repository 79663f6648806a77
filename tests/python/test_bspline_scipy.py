"""casteljau's B-spline evaluation against independent references, through the CLI.

Polynomial curves: ``scipy.interpolate.BSpline(t, c, k)`` and its ``.derivative(nu)``
(FITPACK-style de Boor, written by other people) must agree with
``casteljau eval MODEL --params FILE.csv --derivative K`` for K = 0..3, to 1e-12
relative to the scale of the (derivative's) control points.

Rational curves (NURBS): an exact reference in rational arithmetic
(``fractions.Fraction``): the Cox-de Boor recursion and the quotient rule for the
derivatives, computed without rounding from the very doubles that were written
to the model file.

Random curves are seeded: degrees 1..7, 2D and 3D, clamped and unclamped knots
with repeated interior knots; the parameters include every knot of the domain
and both ends. Run with /usr/bin/python3 -m pytest; the CLI comes from the
environment variable CASTELJAU_CLI (ctest sets it), else build/casteljau.
"""

import json
import math
import subprocess
from fractions import Fraction

import numpy as np
import pytest
from scipy.interpolate import BSpline

from cli_support import casteljau_cli
RELATIVE_TOLERANCE = 1e-12
DEGREES = range(1, 8)
DIMENSIONS = (2, 3)
CURVES_PER_CASE = 2



# --- random curves -------------------------------------------------------------------


def knot_multiset(rng, total, max_multiplicity, low, high):
    """`total` sorted knots in (low, high): distinct values, each repeated 1..max times
    (half of them simple), so that repeated interior knots are common."""
    knots = []
    while len(knots) < total:
        value = float(rng.uniform(low, high))
        if value in knots or not low < value < high:
            continue
        multiplicity = 1 if rng.random() < 0.5 else int(rng.integers(1, max_multiplicity + 1))
        knots.extend([value] * min(multiplicity, total - len(knots)))
    return sorted(knots)


def random_curve(rng, degree, dimension, clamped, rational):
    """(knots, control points (count, d), weights or None) of a valid random curve."""
    p = degree
    count = p + 1 + int(rng.integers(0, 9))
    lower = float(rng.uniform(-5, 5))
    upper = lower + float(10 ** rng.uniform(-1, 1))
    if clamped:
        interior = knot_multiset(rng, count - p - 1, p, lower, upper)
        knots = [lower] * (p + 1) + interior + [upper] * (p + 1)
    else:
        # Unclamped: every knot free (repeats up to p), the domain [t_p, t_{n+1}]
        # wherever it falls; redrawn until it is not empty.
        while True:
            knots = knot_multiset(rng, count + p + 1, p, lower, upper)
            if knots[p] < knots[count]:
                break
    scale = float(10 ** rng.uniform(-2, 3))
    points = rng.uniform(-scale, scale, size=(count, dimension))
    weights = None
    if rational:
        weights = [float(w) for w in 10 ** rng.uniform(-1, 1, size=count)]
    return knots, points, weights


def parameters(rng, knots, degree, count):
    """Random parameters of the domain, every knot inside it, and both ends."""
    lower, upper = knots[degree], knots[count]
    values = [float(u) for u in rng.uniform(lower, upper, size=24)]
    values += [k for k in knots if lower <= k <= upper]
    values += [lower, upper, lower, upper]
    return values


# --- running casteljau ------------------------------------------------------------------


def evaluate(tmp_path, knots, points, weights, degree, us, order):
    """casteljau eval of the model at `us` (via --params) for the order-th derivative."""
    model = {"type": "bspline", "degree": degree, "knots": knots, "control_points": points.tolist()}
    if weights is not None:
        model["weights"] = weights
    model_path = tmp_path / "model.json"
    params_path = tmp_path / "params.csv"
    model_path.write_text(json.dumps(model))  # json writes repr(float): shortest round trip
    params_path.write_text("u\n" + "".join(repr(u) + "\n" for u in us))
    run = subprocess.run(
        [casteljau_cli(), "eval", str(model_path), "--params", str(params_path), "--derivative", str(order)],
        capture_output=True, text=True, check=False)
    assert run.returncode == 0, run.stderr
    assert run.stderr == ""
    rows = [[float(x) for x in line.split(",")] for line in run.stdout.splitlines()]
    return np.array(rows)


# --- scipy: polynomial curves -------------------------------------------------------------

def derivative_scale(knots, points, degree, order):
    """The largest coefficient of the order-th derivative's control net
    (c'_i = q (c_{i+1} - c_i) / (t_{i+q+1} - t_{i+1}), The NURBS Book eq. 3.4; a zero
    denominator belongs to a basis function that vanishes, its coefficient is 0).
    The values of that derivative are convex combinations of these coefficients:
    the scale its rounding is measured against."""
    t = list(knots)
    c = np.array(points, dtype=float)
    q = degree
    for _ in range(order):
        rows = []
        for i in range(len(c) - 1):
            gap = t[i + q + 1] - t[i + 1]
            rows.append(q * (c[i + 1] - c[i]) / gap if gap != 0 else np.zeros_like(c[0]))
        c = np.array(rows)
        t = t[1:-1]
        q -= 1
    return float(np.max(np.abs(c)))


def scipy_values(spline, knots, points, degree, us, order):
    """scipy's C^(order)(u) at every u, except where scipy is known to be wrong:
    at the end of a domain whose end knot t_{n+1} is repeated in an unclamped vector
    (t_n == t_{n+1}), scipy's interval search picks the empty span [t_n, t_{n+1}]
    and returns 0 (the last-knot bug issue 4 names). There the reference is the
    exact rational evaluation below (weights 1), which takes the last non-empty span."""
    count = len(points)
    expected = spline(np.array(us), nu=order)
    if knots[count - 1] == knots[count]:
        for i, u in enumerate(us):
            if u == knots[count]:
                exact = exact_nurbs_derivatives(knots, points.tolist(), [1.0] * count, degree, u, order)
                expected[i] = [float(x) for x in exact[order]]
    return expected


CASES = [(p, d, clamped) for p in DEGREES for d in DIMENSIONS for clamped in (True, False)]
WORST = {}


@pytest.mark.parametrize("degree,dimension,clamped", CASES)
def test_points_and_derivatives_equal_scipy(tmp_path, degree, dimension, clamped):
    rng = np.random.default_rng(4000 + 100 * degree + 10 * dimension + int(clamped))
    for _ in range(CURVES_PER_CASE):
        knots, points, _ = random_curve(rng, degree, dimension, clamped, rational=False)
        us = parameters(rng, knots, degree, len(points))
        spline = BSpline(np.array(knots), points, degree)
        for order in range(4):
            ours = evaluate(tmp_path, knots, points, None, degree, us, order)
            assert ours.shape == (len(us), dimension)
            if order > degree:
                expected, scale = np.zeros_like(ours), 1.0
            else:
                # spline(x, nu) evaluates derivatives directly (de Boor on the
                # span), also where .derivative() refuses (repeated interior knots).
                expected = scipy_values(spline, knots, points, degree, us, order)
                scale = derivative_scale(knots, points, degree, order)
            error = float(np.max(np.abs(ours - expected))) / scale
            WORST[order] = max(WORST.get(order, 0.0), error)
            assert error <= RELATIVE_TOLERANCE, (
                f"degree {degree}, order {order}, clamped {clamped}: error {error:.3g} x scale; knots {knots}")


def test_scipy_is_wrong_at_a_repeated_unclamped_end_knot_and_casteljau_is_not(tmp_path):
    """Why scipy_values replaces scipy at one kind of point, on a case worked by hand:
    degree 2, knots 0, 1, 2, 3, 3, 4, 5 (t_3 = t_4 = 3), P = (1,5) (3,7) (4,4) (6,0).
    The domain is [t_2, t_4] = [2, 3]; on its one span [2, 3) the Cox-de Boor basis is
    N_0 = (3-u)^2/2, N_2 = (u-2)^2, N_1 = 1 - N_0 - N_2, so C(2) = (P_0 + P_1)/2 = (2,6),
    C(2.5) = P_0/8 + 5 P_1/8 + P_2/4 = (3,6) and C(3) = P_2 = (4,4), the double knot
    making the curve pass through P_2. scipy returns 0 at u = 3."""
    knots, points = [0.0, 1.0, 2.0, 3.0, 3.0, 4.0, 5.0], np.array([[1.0, 5.0], [3.0, 7.0], [4.0, 4.0], [6.0, 0.0]])
    spline = BSpline(np.array(knots), points, 2)
    assert list(spline(3.0)) == [0.0, 0.0]
    assert list(spline(2.5)) == [3.0, 6.0]
    ours = evaluate(tmp_path, knots, points, None, 2, [2.0, 2.5, 3.0], 0)
    assert ours.tolist() == [[2.0, 6.0], [3.0, 6.0], [4.0, 4.0]]


# --- exact rational reference: NURBS ------------------------------------------------------


def span_of(knots, degree, count, u):
    """The span s, p <= s <= n, with t_s <= u < t_{s+1}; at the end of the domain
    the last non-empty span (the convention casteljau and The NURBS Book use)."""
    n = count - 1
    if u == knots[n + 1]:
        s = n
        while knots[s] == knots[s + 1]:
            s -= 1
        return s
    for s in range(degree, n + 1):
        if knots[s] <= u < knots[s + 1]:
            return s
    raise ValueError("parameter outside the domain")


def exact_basis_derivatives(knots, degree, span, u, order):
    """{(i, k): d^k/du^k N_{i,p}(u)} for the polynomial piece of `span`, in Fractions:
    Cox-de Boor with N_{i,0} = [i == span] and the derivative recursion
    N^(k)_{i,j} = j (N^(k-1)_{i,j-1} / (t_{i+j} - t_i) - N^(k-1)_{i+1,j-1} / (t_{i+j+1} - t_{i+1})),
    0/0 := 0 (The NURBS Book eq. 2.5 and 2.9)."""
    t = knots
    memo = {}

    def basis(i, j, k):
        key = (i, j, k)
        if key in memo:
            return memo[key]
        if j == 0:
            value = Fraction(1 if (i == span and k == 0) else 0)
        elif k == 0:
            value = Fraction(0)
            if t[i + j] != t[i]:
                value += (u - t[i]) / (t[i + j] - t[i]) * basis(i, j - 1, 0)
            if t[i + j + 1] != t[i + 1]:
                value += (t[i + j + 1] - u) / (t[i + j + 1] - t[i + 1]) * basis(i + 1, j - 1, 0)
        else:
            value = Fraction(0)
            if t[i + j] != t[i]:
                value += j * basis(i, j - 1, k - 1) / (t[i + j] - t[i])
            if t[i + j + 1] != t[i + 1]:
                value -= j * basis(i + 1, j - 1, k - 1) / (t[i + j + 1] - t[i + 1])
        memo[key] = value
        return value

    return {(i, k): basis(i, degree, k) for i in range(span - degree, span + 1) for k in range(order + 1)}


def exact_nurbs_derivatives(knots, points, weights, degree, u, order):
    """C(u), C'(u), ..., C^(order)(u) exactly: A^(k) = sum N_i^(k) w_i P_i,
    w^(k) = sum N_i^(k) w_i, C^(k) = (A^(k) - sum_{j=1..k} binom(k,j) w^(j) C^(k-j)) / w
    (The NURBS Book eq. 4.8)."""
    t = [Fraction(k) for k in knots]
    uu = Fraction(u)
    count, d = len(points), len(points[0])
    span = span_of(t, degree, count, uu)
    n = exact_basis_derivatives(t, degree, span, uu, order)
    w = [Fraction(x) for x in weights]
    p = [[Fraction(x) for x in row] for row in points]
    a_derivs, w_derivs = [], []
    for k in range(order + 1):
        a_derivs.append([sum(n[(i, k)] * w[i] * p[i][j] for i in range(span - degree, span + 1)) for j in range(d)])
        w_derivs.append(sum(n[(i, k)] * w[i] for i in range(span - degree, span + 1)))
    c = []
    for k in range(order + 1):
        value = list(a_derivs[k])
        for j in range(1, k + 1):
            for m in range(d):
                value[m] -= math.comb(k, j) * w_derivs[j] * c[k - j][m]
        c.append([x / w_derivs[0] for x in value])
    return c


NURBS_CASES = [(p, d) for p in DEGREES for d in DIMENSIONS]


@pytest.mark.parametrize("degree,dimension", NURBS_CASES)
def test_rational_points_and_derivatives_equal_an_exact_reference(tmp_path, degree, dimension):
    rng = np.random.default_rng(7000 + 10 * degree + dimension)
    for clamped in (True, False):
        knots, points, weights = random_curve(rng, degree, dimension, clamped, rational=True)
        count = len(points)
        us = parameters(rng, knots, degree, count)[:16] + [knots[degree], knots[count]]
        us += [k for k in knots if knots[degree] < k < knots[count]][:4]
        exact = [exact_nurbs_derivatives(knots, points.tolist(), weights, degree, u, 3) for u in us]
        for order in range(4):
            ours = evaluate(tmp_path, knots, points, weights, degree, us, order)
            # Scale: the largest exact value of this order over the parameters and the
            # control points' scale (for order 0); a rational derivative has no
            # control net of its own to measure against.
            values = np.array([[float(x) for x in e[order]] for e in exact])
            scale = max(float(np.max(np.abs(values))), float(np.max(np.abs(points))) if order == 0 else 0.0)
            worst = 0.0
            for i, u in enumerate(us):
                for j in range(dimension):
                    error = abs(Fraction(float(ours[i][j])) - exact[i][order][j])
                    worst = max(worst, float(error) / scale)
            WORST[("rational", order)] = max(WORST.get(("rational", order), 0.0), worst)
            assert worst <= RELATIVE_TOLERANCE, (
                f"degree {degree}, order {order}, clamped {clamped}: error {worst:.3g} x scale")


def test_the_exact_reference_is_right_on_a_known_curve():
    """The Fraction reference itself, on a case worked by hand: P = (1,0) (1,1) (0,1),
    w = 1, 1/2, 1 on knots 0,0,0,1,1,1 (one rational quadratic Bezier piece). At u = 1/2
    the Bernstein values are 1/4, 1/2, 1/4, so w B = 1/4, 1/4, 1/4, the denominator
    is 3/4, the numerator (1/4)(1,0) + (1/4)(1,1) + (1/4)(0,1) = (1/2, 1/2), and
    C(1/2) = (2/3, 2/3)."""
    c = exact_nurbs_derivatives([0, 0, 0, 1, 1, 1], [[1, 0], [1, 1], [0, 1]], [1, 0.5, 1], 2, 0.5, 1)
    assert c[0] == [Fraction(2, 3), Fraction(2, 3)]
    # Derivative at 1/2 by symmetry points along (-1, 1).
    assert c[1][0] == -c[1][1] and c[1][0] < 0
    # And a polynomial check against scipy (weights all 1).
    knots, points = [0, 0, 0, 0.5, 1, 1, 1], np.array([[0.0, 1.0], [1.0, 3.0], [2.0, -1.0], [4.0, 0.5]])
    spline = BSpline(np.array(knots, dtype=float), points, 2)
    for u in (0.0, 0.25, 0.5, 0.75, 1.0):
        ours = exact_nurbs_derivatives(knots, points.tolist(), [1.0] * 4, 2, u, 2)
        for order in range(3):
            expected = (spline.derivative(order) if order else spline)(u)
            assert np.allclose([float(x) for x in ours[order]], expected, rtol=0, atol=1e-13)


def test_report_worst_errors(capsys):
    """Prints the worst relative errors met above (pytest -s shows them)."""
    with capsys.disabled():
        for key in sorted(WORST, key=str):
            print(f"\nworst relative error {key}: {WORST[key]:.3g}", end="")
