"""The cubic smoothing spline of casteljau and of scipy against the exact solve (issue 43).

The reference is exact rational arithmetic (fractions.Fraction): the B-spline basis by the
Cox-de Boor recursion and its second derivatives in rationals, the penalty
Omega_jk = integral of N_j'' N_k'' by Milne's rule (exact for the quadratic integrands of
a cubic spline), the penalized normal equations (B^T B + lam Omega) c = B^T y solved by
exact Gaussian elimination. Every double input (parameters, coordinates, lam) is taken as
the rational it is. The data: the seed's head (19 points), each coordinate a function of
the parameters k / 32 (dyadic: Milne's nodes are exact), knots at every parameter, free
ends: scipy 1.10's make_smoothing_spline(t, y, lam) solves the same problem. lam runs over
1e-6 .. 1e6 of the data's scale (the head spans 19 units, its parameters 0.56).

Printed with pytest -s, the table docs/interpolation.md quotes; held: casteljau within
1e-12 of the scale at every lam.
"""

from fractions import Fraction

import numpy as np
import pytest
from scipy.interpolate import make_smoothing_spline

import casteljau as cj

HEAD = [(9.5, 5), (5.5, 5), (1, 7), (-3.5, 9.5), (-9.5, 8), (-9.5, -2.5), (-8.5, -4.5), (-5, -5),
        (-4.5, -2.5), (-0.5, -9), (0, -7), (-1, -4.5), (2, -5), (3, -1.5), (2.5, -5), (5, -4.5),
        (7.5, -5), (6.5, -0.5), (9.5, -0.5)]
DEGREE = 3


def basis(knots, i, p, u, last):
    """N_{i,p}(u) in rationals (the last non-empty span closed at its right end)."""
    if p == 0:
        inside = knots[i] <= u < knots[i + 1] or (i == last and u == knots[i + 1])
        return Fraction(1 if inside else 0)
    value = Fraction(0)
    if knots[i + p] != knots[i]:
        value += (u - knots[i]) / (knots[i + p] - knots[i]) * basis(knots, i, p - 1, u, last)
    if knots[i + p + 1] != knots[i + 1]:
        value += (knots[i + p + 1] - u) / (knots[i + p + 1] - knots[i + 1]) * basis(knots, i + 1, p - 1, u, last)
    return value


def basis_derivative(knots, i, p, k, u, last):
    """The k-th derivative of N_{i,p} at u, in rationals (The NURBS Book eq. 2.9)."""
    if k == 0:
        return basis(knots, i, p, u, last)
    value = Fraction(0)
    if knots[i + p] != knots[i]:
        value += Fraction(p) / (knots[i + p] - knots[i]) * basis_derivative(knots, i, p - 1, k - 1, u, last)
    if knots[i + p + 1] != knots[i + 1]:
        value -= Fraction(p) / (knots[i + p + 1] - knots[i + 1]) * basis_derivative(knots, i + 1, p - 1, k - 1, u,
                                                                                     last)
    return value


def solve(matrix, rhs):
    """Exact Gaussian elimination with row pivoting on nonzero entries."""
    n = len(matrix)
    a = [row[:] + rhs_row[:] for row, rhs_row in zip(matrix, rhs)]
    for c in range(n):
        pivot = next(r for r in range(c, n) if a[r][c] != 0)
        a[c], a[pivot] = a[pivot], a[c]
        for r in range(n):
            if r != c and a[r][c] != 0:
                factor = a[r][c] / a[c][c]
                a[r] = [x - factor * y for x, y in zip(a[r], a[c])]
    return [[x / a[r][r] for x in a[r][n:]] for r in range(n)]


@pytest.fixture(scope="module")
def exact_system():
    t = [Fraction(k, 32) for k in range(len(HEAD))]
    knots = [t[0]] * DEGREE + t + [t[-1]] * DEGREE
    count = len(knots) - DEGREE - 1
    last = len(knots) - DEGREE - 2  # the last non-empty span's index
    b = [[basis(knots, j, DEGREE, u, last) for j in range(count)] for u in t]
    omega = [[Fraction(0)] * count for _ in range(count)]
    for s in range(len(knots) - 1):
        lo, hi = knots[s], knots[s + 1]
        if lo == hi:
            continue
        h = hi - lo
        for node, weight in ((lo + h / 4, 2), (lo + h / 2, -1), (lo + 3 * h / 4, 2)):
            second = [basis_derivative(knots, j, DEGREE, 2, node, last) for j in range(count)]
            for j in range(count):
                if second[j] == 0:
                    continue
                for k in range(count):
                    omega[j][k] += h / 3 * weight * second[j] * second[k]
    gram = [[sum(b[r][j] * b[r][k] for r in range(len(t))) for k in range(count)] for j in range(count)]
    right = [[sum(b[r][j] * Fraction(HEAD[r][c]) for r in range(len(t))) for c in range(2)] for j in range(count)]
    return t, gram, omega, right


def test_smoothing_spline_against_the_exact_solve(exact_system):
    t, gram, omega, right = exact_system
    parameters = np.array([float(u) for u in t])
    points = np.array(HEAD, dtype=float)
    scale = np.max(np.abs(points))
    worst_ours = 0.0
    print("\nlam      casteljau  scipy   (largest control point error / scale, both coordinates)")
    for k in range(-6, 7):
        lam = 10.0 ** k
        exact_lam = Fraction(lam)
        system = [[g + exact_lam * w for g, w in zip(gram_row, omega_row)] for gram_row, omega_row in zip(gram, omega)]
        exact = np.array([[float(x) for x in row] for row in solve(system, right)])
        fit = cj.fit_smoothing(points, parameters, degree=DEGREE, ends="free", smoothing=lam)
        ours = np.asarray(fit.curve.control_points)
        theirs = np.stack([make_smoothing_spline(parameters, points[:, c], lam=lam).c for c in range(2)], axis=1)
        error_ours = np.max(np.abs(ours - exact)) / scale
        error_theirs = np.max(np.abs(theirs - exact)) / scale
        print(f"1e{k:+d}   {error_ours:.1e}   {error_theirs:.1e}")
        worst_ours = max(worst_ours, error_ours)
    assert worst_ours <= 1e-12
