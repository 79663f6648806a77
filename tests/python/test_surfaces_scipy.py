"""casteljau's surfaces against independent references, through the CLI.

Non-rational B-spline surfaces: ``scipy.interpolate.bisplev`` (FITPACK's fpbisp,
written by other people) on the same knots and coefficients, one coordinate at a
time, must agree with ``casteljau eval MODEL --params FILE.csv`` (two columns
u,v) to 1e-12 relative to the scale of the control points. Random surfaces are
seeded: degrees p, q in 1..5, clamped and unclamped knot vectors with random
interior knots; the parameters are random points of the domain plus its corners
and every distinct knot pair of the domain.

Coons patches: with four straight edges (written as Bézier, B-spline and
piecewise Bézier curves, each linearly parameterized) the bilinearly blended
patch is the bilinear interpolant of its corners,
(1-u)(1-v) P00 + (1-u) v P01 + u (1-v) P10 + u v P11.

The CLI comes from CASTELJAU_CLI (ctest sets it), else build/casteljau.
"""

import json
import subprocess

import numpy as np
import pytest
from scipy.interpolate import bisplev

from cli_support import casteljau_cli

RELATIVE_TOLERANCE = 1e-12
DEGREES = range(1, 6)


def run_cli(*arguments):
    result = subprocess.run([casteljau_cli(), *map(str, arguments)], capture_output=True, text=True)
    assert result.returncode == 0, result.stderr
    return result.stdout


def read_points(text):
    return np.array([[float(x) for x in line.split(",")] for line in text.splitlines() if line.strip()])


def random_knots(rng, degree, count, clamped):
    """A knot vector of count + degree + 1 knots, strictly increasing in its
    interior, for `count` control points."""
    lower = float(rng.uniform(-3, 3))
    upper = lower + float(10 ** rng.uniform(-1, 1))
    interior = sorted(float(x) for x in rng.uniform(lower, upper, count - degree - 1))
    if clamped:
        return [lower] * (degree + 1) + interior + [upper] * (degree + 1)
    # Unclamped: the outer knots spread beyond the domain [t_p, t_{n+1}].
    width = upper - lower
    below = sorted(float(x) for x in lower - rng.uniform(0, width, degree))
    above = sorted(float(x) for x in upper + rng.uniform(0, width, degree))
    return below + [lower] + interior + [upper] + above


def domain(knots, degree):
    return knots[degree], knots[len(knots) - degree - 1]


def bspline_surface_case(rng, p, q, clamped):
    rows = p + 1 + int(rng.integers(0, 6))
    columns = q + 1 + int(rng.integers(0, 6))
    knots_u = random_knots(rng, p, rows, clamped)
    knots_v = random_knots(rng, q, columns, clamped)
    net = rng.uniform(-10, 10, (rows, columns, 3))
    return knots_u, knots_v, net


@pytest.mark.parametrize("clamped", [True, False], ids=["clamped", "unclamped"])
@pytest.mark.parametrize("q", DEGREES)
@pytest.mark.parametrize("p", DEGREES)
def test_bspline_surfaces_equal_bisplev(tmp_path, p, q, clamped):
    rng = np.random.default_rng(5000 + 100 * p + 10 * q + int(clamped))
    worst = 0.0
    for case in range(2):
        knots_u, knots_v, net = bspline_surface_case(rng, p, q, clamped)
        model = {"type": "bspline_surface", "degree": [p, q], "knots": [knots_u, knots_v],
                 "control_points": net.tolist()}
        (tmp_path / "s.json").write_text(json.dumps(model))
        (u0, u1), (v0, v1) = domain(knots_u, p), domain(knots_v, q)
        us = np.concatenate([rng.uniform(u0, u1, 30), sorted(set(knots_u[p:len(knots_u) - p]))])
        vs = np.concatenate([rng.uniform(v0, v1, 30), sorted(set(knots_v[q:len(knots_v) - q]))])
        # Random pairs, plus every (u knot, v knot) pair of the domain (corners included).
        pairs = [(u, v) for u, v in zip(us[:30], vs[:30])]
        pairs += [(u, v) for u in us[30:] for v in vs[30:]]
        (tmp_path / "uv.csv").write_text("u,v\n" + "".join(f"{u!r},{v!r}\n" for u, v in pairs))
        got = read_points(run_cli("eval", tmp_path / "s.json", "--params", tmp_path / "uv.csv"))
        assert got.shape == (len(pairs), 3)
        scale = np.abs(net).max()
        for c in range(3):
            tck = [np.array(knots_u), np.array(knots_v), net[:, :, c].ravel(), p, q]
            expected = np.array([bisplev(u, v, tck) for u, v in pairs])
            difference = np.abs(got[:, c] - expected).max() / scale
            worst = max(worst, difference)
            assert difference <= RELATIVE_TOLERANCE, (p, q, clamped, case, c, difference)
    print(f"p={p} q={q} {'clamped' if clamped else 'unclamped'}: max relative difference vs bisplev {worst:.3g}")


def test_grid_samples_equal_bisplev_on_the_grid(tmp_path):
    """--samples N: the N x N grid over the domain, u the slow index."""
    rng = np.random.default_rng(5999)
    knots_u, knots_v, net = bspline_surface_case(rng, 3, 2, True)
    model = {"type": "bspline_surface", "degree": [3, 2], "knots": [knots_u, knots_v], "control_points": net.tolist()}
    (tmp_path / "s.json").write_text(json.dumps(model))
    n = 7
    got = read_points(run_cli("eval", tmp_path / "s.json", "--samples", n))
    assert got.shape == (n * n, 3)
    us = np.linspace(*domain(knots_u, 3), n)
    vs = np.linspace(*domain(knots_v, 2), n)
    for c in range(3):
        expected = bisplev(us, vs, [np.array(knots_u), np.array(knots_v), net[:, :, c].ravel(), 3, 2])
        assert np.abs(got[:, c] - expected.ravel()).max() <= RELATIVE_TOLERANCE * np.abs(net).max()


def straight(kind, a, b):
    """The segment from a to b, linearly parameterized, as a curve model of `kind`."""
    a, b = np.asarray(a), np.asarray(b)
    if kind == "bezier":
        return {"type": "bezier", "control_points": [a.tolist(), b.tolist()]}
    if kind == "bspline":  # degree 2, evenly spaced collinear points: linear precision
        return {"type": "bspline", "degree": 2, "knots": [0, 0, 0, 1, 2, 2, 2],
                "control_points": [a.tolist(), (0.75 * a + 0.25 * b).tolist(), (0.25 * a + 0.75 * b).tolist(),
                                   b.tolist()]}
    middle = (0.5 * (a + b)).tolist()  # piecewise: two halves, each on [i, i+1]
    return {"type": "piecewise_bezier", "pieces": [[a.tolist(), middle], [middle, b.tolist()]]}


@pytest.mark.parametrize("kinds", [("bezier",) * 4, ("bspline", "piecewise", "bezier", "bspline"),
                                   ("piecewise",) * 4])
def test_coons_with_straight_edges_is_the_bilinear_patch(tmp_path, kinds):
    rng = np.random.default_rng(5100 + len(set(kinds)))
    p00, p01, p10, p11 = rng.uniform(-5, 5, (4, 3))
    boundaries = {"u0": straight(kinds[0], p00, p01), "u1": straight(kinds[1], p10, p11),
                  "v0": straight(kinds[2], p00, p10), "v1": straight(kinds[3], p01, p11)}
    (tmp_path / "c.json").write_text(json.dumps({"type": "coons", "boundaries": boundaries}))
    pairs = rng.uniform(0, 1, (50, 2)).tolist() + [[0, 0], [0, 1], [1, 0], [1, 1], [0.5, 0.5]]
    (tmp_path / "uv.csv").write_text("".join(f"{u!r},{v!r}\n" for u, v in pairs))
    got = read_points(run_cli("eval", tmp_path / "c.json", "--params", tmp_path / "uv.csv"))
    expected = np.array([(1 - u) * (1 - v) * p00 + (1 - u) * v * p01 + u * (1 - v) * p10 + u * v * p11
                         for u, v in pairs])
    scale = np.abs([p00, p01, p10, p11]).max()
    assert np.abs(got - expected).max() <= 1e-14 * 16 * scale
