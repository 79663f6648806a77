"""`casteljau interpolate` against scipy.interpolate, through the CLI.

The references are scipy's own interpolants, built by other people with other
algorithms (FITPACK-style collocation in make_interp_spline, the tridiagonal
solver of CubicSpline, the barycentric formula of BarycentricInterpolator, the
Hermite form of CubicHermiteSpline). The parameter values handed to scipy are
computed here from the points (uniform, chord length, centripetal: steps
|P_{i+1} - P_i|^e, e = 0, 1, 1/2, normalized to [0, 1]), never read back from
casteljau's output.

Compared, to 1e-12 relative to the data's scale:
- cubic, every end condition x every parameterization, on seeded random 2D and
  3D points and on the seeds' head and car, and in --function mode: the knots
  and control points against make_interp_spline(t, P, k=3, bc_type=...), and
  the values at many parameters (the data sites, random ones, the knots)
  against CubicSpline(t, P, bc_type=...);
- natural --order 2 against CubicSpline(bc_type='natural');
- bspline of degrees 1..7 (averaged knots, The NURBS Book eq. 9.8) against
  make_interp_spline(k=p): scipy's default knots coincide with the averaged
  knots for p = 1 and p = 2 (any parameters) and for odd p with uniform
  parameters; elsewhere (odd p >= 3 with chord or centripetal parameters, and
  even p >= 4, which scipy's default refuses) the knots differ, and scipy is
  given ours (t=...), the same collocation problem solved independently;
- lagrange against BarycentricInterpolator; hermite against CubicHermiteSpline.

Run with /usr/bin/python3 -m pytest; the CLI comes from the environment variable
CASTELJAU_CLI (ctest sets it), else build/casteljau.
"""

import json
import subprocess

import numpy as np
import pytest
from scipy.interpolate import (BarycentricInterpolator, BSpline, CubicHermiteSpline, CubicSpline,
                               make_interp_spline)

from cli_support import REPOSITORY, casteljau_cli
EXAMPLES = REPOSITORY / "examples"
RELATIVE_TOLERANCE = 1e-12
PARAMS = ("uniform", "chord", "centripetal")
ENDS = ("natural", "clamped", "not-a-knot", "periodic")
WORST = {}



def record(method, error):
    """Keeps the largest relative difference per method (printed at the end)."""
    WORST[method] = max(WORST.get(method, 0.0), error)
    return error


# --- data ----------------------------------------------------------------------------


def read_example(name):
    return np.loadtxt(EXAMPLES / name, delimiter=",", comments="#", skiprows=2)


def random_points(seed, count, dimension):
    """A seeded random walk (no two consecutive points equal), scale about 10^k."""
    rng = np.random.default_rng(seed)
    scale = float(10 ** rng.uniform(-1, 2))
    steps = rng.normal(size=(count, dimension))
    return scale * np.cumsum(steps, axis=0)


DATASETS = {
    "random2d": lambda: random_points(11, 12, 2),
    "random3d": lambda: random_points(12, 15, 3),
    "head": lambda: read_example("head.csv"),
    "car": lambda: read_example("car.csv"),
}


def python_parameters(points, kind, closed=False):
    """t_0 = 0 < ... < t_m = 1 (t_{m+1} = 1 when closed, for the closing step back
    to P_0): steps |P_{i+1} - P_i|^e, e = 0 (uniform), 1 (chord), 1/2 (centripetal),
    Lee 1989 / The NURBS Book eq. 9.4-9.6. Written independently of casteljau."""
    path = np.vstack([points, points[:1]]) if closed else points
    lengths = np.linalg.norm(np.diff(path, axis=0), axis=1)
    exponent = {"uniform": 0.0, "chord": 1.0, "centripetal": 0.5}[kind]
    steps = lengths ** exponent
    t = np.concatenate([[0.0], np.cumsum(steps)])
    t /= t[-1]
    return t


def sample_parameters(t, rng, count=64):
    """The data sites, the midpoints, random parameters of [t_0, t_last], both ends."""
    mids = (t[1:] + t[:-1]) / 2
    values = np.concatenate([t, mids, rng.uniform(t[0], t[-1], size=count), [t[0], t[-1]]])
    return np.clip(values, t[0], t[-1])


# --- running casteljau ----------------------------------------------------------------


def write_points(path, points, header=None):
    d = points.shape[1]
    if header is None:
        header = ["x", "y", "z"][:d] if d <= 3 else [f"c{k}" for k in range(d)]
    names = header
    lines = ["# written by test_interpolate_scipy.py", ",".join(names)]
    lines += [",".join(repr(float(x)) for x in row) for row in points]  # repr: shortest round trip
    path.write_text("\n".join(lines) + "\n")


def interpolate(tmp_path, points, *options, header=None):
    """casteljau interpolate POINTS.csv OPTIONS -o model.json; the parsed model."""
    points_path = tmp_path / "points.csv"
    model_path = tmp_path / "model.json"
    write_points(points_path, points, header)
    run = subprocess.run([casteljau_cli(), "interpolate", str(points_path), *options, "-o", str(model_path)],
                         capture_output=True, text=True, check=False)
    assert run.returncode == 0, f"{options}: {run.stderr}"
    assert run.stderr == ""
    return json.loads(model_path.read_text())


def evaluate(tmp_path, model, us):
    """casteljau eval of a model at the parameters us."""
    model_path = tmp_path / "eval_model.json"
    params_path = tmp_path / "params.csv"
    model_path.write_text(json.dumps(model))
    params_path.write_text("u\n" + "".join(repr(float(u)) + "\n" for u in us))
    run = subprocess.run([casteljau_cli(), "eval", str(model_path), "--params", str(params_path)],
                         capture_output=True, text=True, check=False)
    assert run.returncode == 0, run.stderr
    return np.array([[float(x) for x in line.split(",")] for line in run.stdout.splitlines()])


def relative(a, b, scale):
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    assert a.shape == b.shape, f"shapes {a.shape} and {b.shape}"
    return float(np.max(np.abs(a - b))) / scale


def data_scale(points):
    return float(np.max(np.abs(points)))


# --- cubic: every end condition x every parameterization --------------------------------


def end_tangents(points, t):
    """Seeded end derivatives of the data's size (dP/dt with t in [0, 1])."""
    rng = np.random.default_rng(len(points))
    spread = data_scale(points)
    return rng.uniform(-spread, spread, size=points.shape[1]), rng.uniform(-spread, spread, size=points.shape[1])


def scipy_cubic(t, points, end, tangents):
    """make_interp_spline and CubicSpline with the same end condition."""
    if end == "natural":
        bc = "natural"
        return make_interp_spline(t, points, k=3, bc_type=bc), CubicSpline(t, points, bc_type=bc)
    if end == "clamped":
        start, finish = tangents
        return (make_interp_spline(t, points, k=3, bc_type=([(1, start)], [(1, finish)])),
                CubicSpline(t, points, bc_type=((1, start), (1, finish))))
    if end == "not-a-knot":
        return make_interp_spline(t, points, k=3), CubicSpline(t, points, bc_type="not-a-knot")
    closed = np.vstack([points, points[:1]])
    return (make_interp_spline(t, closed, k=3, bc_type="periodic"), CubicSpline(t, closed, bc_type="periodic"))


def check_cubic(tmp_path, points, t, options, end, tangents, method="cubic"):
    """Knots, control points (when the representations coincide) and values."""
    model = interpolate(tmp_path, points, *options)
    assert model["type"] == "bspline" and model["degree"] == 3
    spline, cubic = scipy_cubic(t, points, end, tangents)
    scale = data_scale(points)
    knots = np.array(model["knots"])
    control = np.array(model["control_points"])
    # Every end condition, periodic included (casteljau extends the knots by
    # the parameter steps taken cyclically, as scipy does): the same B-spline.
    assert len(knots) == len(spline.t), f"{end}: {len(knots)} knots, scipy {len(spline.t)}"
    record(f"{method} knots", relative(knots, spline.t, float(np.max(np.abs(t)))))
    assert relative(knots, spline.t, float(np.max(np.abs(t)))) <= RELATIVE_TOLERANCE
    record(f"{method} control points", relative(control, spline.c, scale))
    assert relative(control, spline.c, scale) <= RELATIVE_TOLERANCE, f"{end}: control points"
    rng = np.random.default_rng(99)
    us = sample_parameters(t, rng)
    ours = evaluate(tmp_path, model, us)
    record(f"{method} values", relative(ours, cubic(us), scale))
    assert relative(ours, cubic(us), scale) <= RELATIVE_TOLERANCE, f"{end}: values against CubicSpline"
    assert relative(ours, spline(us), scale) <= RELATIVE_TOLERANCE, f"{end}: values against make_interp_spline"
    return model


@pytest.mark.parametrize("dataset", list(DATASETS))
@pytest.mark.parametrize("param", PARAMS)
@pytest.mark.parametrize("end", ENDS)
def test_cubic_equals_scipy(tmp_path, dataset, param, end):
    points = DATASETS[dataset]()
    closed = end == "periodic"
    t = python_parameters(points, param, closed)
    options = ["--method", "cubic", "--end", end, "--param", param]
    tangents = None
    if closed:
        options.append("--closed")
    if end == "clamped":
        tangents = end_tangents(points, t)
        options += ["--start-tangent", ",".join(repr(float(x)) for x in tangents[0]),
                    "--end-tangent", ",".join(repr(float(x)) for x in tangents[1])]
    model = check_cubic(tmp_path, points, t, options, end, tangents)
    if closed:
        # Closed with C² continuity at the seam: value, first and second derivative.
        knots, control = np.array(model["knots"]), np.array(model["control_points"])
        spline = BSpline(knots, control, 3)
        lo, hi = knots[3], knots[-4]
        scale = data_scale(points)
        for order in range(3):
            a, b = spline(lo, nu=order), spline(hi, nu=order)
            derivative_scale = max(float(np.max(np.abs(spline(np.linspace(lo, hi, 200), nu=order)))), scale)
            assert relative(a, b, derivative_scale) <= 1e-10, f"seam, derivative {order}"


def test_periodic_accepts_a_closing_duplicate(tmp_path):
    """A closed point set whose last point repeats the first gives the same curve."""
    points = read_example("car.csv")
    without = interpolate(tmp_path, points, "--method", "cubic", "--closed", "--param", "chord")
    with_duplicate = interpolate(tmp_path, np.vstack([points, points[:1]]), "--method", "cubic", "--closed",
                                 "--param", "chord")
    assert without == with_duplicate


def function_data(seed, count):
    rng = np.random.default_rng(seed)
    x = np.cumsum(rng.uniform(0.1, 2.0, size=count)) - 3.0
    y = rng.normal(size=count) * 5.0
    return x, y


@pytest.mark.parametrize("end", ["natural", "clamped", "not-a-knot"])
def test_cubic_function_mode_equals_scipy(tmp_path, end):
    """--function: the curve (x, s(x)) over [x_0, x_n]; s equals scipy with x as the sites."""
    for seed in range(3):
        x, y = function_data(50 + seed, 9 + 4 * seed)
        points = np.column_stack([x, y])
        options = ["--method", "cubic", "--end", end, "--function"]
        slopes = None
        if end == "clamped":
            slopes = (1.5, -0.25)
            options += ["--start-tangent", "1.5", "--end-tangent", "-0.25"]
        model = interpolate(tmp_path, points, *options)
        if end == "clamped":
            spline = make_interp_spline(x, y, k=3, bc_type=([(1, slopes[0])], [(1, slopes[1])]))
            cubic = CubicSpline(x, y, bc_type=((1, slopes[0]), (1, slopes[1])))
        else:
            spline = make_interp_spline(x, y, k=3, bc_type="natural" if end == "natural" else None)
            cubic = CubicSpline(x, y, bc_type=end)
        knots, control = np.array(model["knots"]), np.array(model["control_points"])
        scale = float(np.max(np.abs(points)))
        assert relative(knots, spline.t, float(np.max(np.abs(x)))) <= RELATIVE_TOLERANCE
        record("cubic --function control points", relative(control[:, 1], spline.c, scale))
        assert relative(control[:, 1], spline.c, scale) <= RELATIVE_TOLERANCE
        us = sample_parameters(x, np.random.default_rng(seed))
        ours = evaluate(tmp_path, model, us)
        # The first coordinate is x itself (the spline reproduces linear data) ...
        assert relative(ours[:, 0], us, scale) <= RELATIVE_TOLERANCE
        # ... and the second is s(x).
        record("cubic --function values", relative(ours[:, 1], cubic(us), scale))
        assert relative(ours[:, 1], cubic(us), scale) <= RELATIVE_TOLERANCE


# --- natural splines of order 2 ------------------------------------------------------------


@pytest.mark.parametrize("dataset", list(DATASETS))
@pytest.mark.parametrize("param", PARAMS)
def test_natural_order_2_equals_the_natural_cubic_spline(tmp_path, dataset, param):
    points = DATASETS[dataset]()
    t = python_parameters(points, param)
    check_cubic(tmp_path, points, t, ["--method", "natural", "--order", "2", "--param", param], "natural", None,
                method="natural q=2")


def test_natural_order_2_function_mode(tmp_path):
    x, y = function_data(77, 11)
    model = interpolate(tmp_path, np.column_stack([x, y]), "--method", "natural", "--order", "2", "--function")
    us = sample_parameters(x, np.random.default_rng(1))
    ours = evaluate(tmp_path, model, us)
    scale = float(max(np.max(np.abs(x)), np.max(np.abs(y))))
    record("natural q=2 --function values", relative(ours[:, 1], CubicSpline(x, y, bc_type="natural")(us), scale))
    assert relative(ours[:, 1], CubicSpline(x, y, bc_type="natural")(us), scale) <= RELATIVE_TOLERANCE


# --- B-splines of any degree ----------------------------------------------------------------


def averaged_knots(t, p):
    """The NURBS Book eq. 9.8: p+1 copies of t_0 and t_m, interior knots the
    averages of p consecutive parameters, u_{j+p} = (t_j + ... + t_{j+p-1}) / p."""
    m = len(t) - 1
    interior = [sum(t[j:j + p]) / p for j in range(1, m - p + 1)]
    return np.array([t[0]] * (p + 1) + interior + [t[-1]] * (p + 1))


def scipy_default_knots(t, p):
    """The knots make_interp_spline chooses by itself (None for even p >= 4, which it refuses)."""
    if p == 2 or p % 2 == 1:
        return make_interp_spline(t, np.zeros_like(t), k=p).t
    return None


@pytest.mark.parametrize("dataset", list(DATASETS))
@pytest.mark.parametrize("param", PARAMS)
def test_bspline_any_degree_equals_scipy(tmp_path, dataset, param):
    points = DATASETS[dataset]()
    t = python_parameters(points, param)
    scale = data_scale(points)
    rng = np.random.default_rng(5)
    us = sample_parameters(t, rng)
    for p in range(1, 8):
        model = interpolate(tmp_path, points, "--method", "bspline", "--degree", str(p), "--param", param)
        knots, control = np.array(model["knots"]), np.array(model["control_points"])
        assert model["degree"] == p
        assert relative(knots, averaged_knots(t, p), 1.0) <= RELATIVE_TOLERANCE, f"p = {p}: knots"
        default = scipy_default_knots(t, p)
        same_as_default = default is not None and len(default) == len(knots) and relative(knots, default, 1.0) <= 1e-12
        if p <= 2 or (p % 2 == 1 and param == "uniform"):
            # Where scipy's own choice and knot averaging coincide.
            assert same_as_default, f"p = {p}, {param}: scipy's default knots differ"
        spline = make_interp_spline(t, points, k=p, t=knots)
        # High degrees on uneven parameters give control points far larger than
        # the data (80 times at p = 7 on random2d with chord parameters): both
        # solvers' rounding is relative to the solution, so the control points
        # are compared at the scale of the control points themselves.
        control_scale = max(scale, float(np.max(np.abs(spline.c))))
        record("bspline control points", relative(control, spline.c, control_scale))
        assert relative(control, spline.c, control_scale) <= RELATIVE_TOLERANCE, f"p = {p}: control points"
        ours = evaluate(tmp_path, model, us)
        record("bspline values", relative(ours, spline(us), scale))
        assert relative(ours, spline(us), scale) <= RELATIVE_TOLERANCE, f"p = {p}: values"
        assert relative(evaluate(tmp_path, model, t), points, scale) <= RELATIVE_TOLERANCE, f"p = {p}: data"


def test_bspline_knots_differ_from_scipy_for_odd_degrees_and_chord_parameters(tmp_path):
    """Where the two knot choices differ (documented in docs/interpolation.md):
    scipy takes every other parameter (not-a-knot, t_2..t_{m-2} for p = 3),
    casteljau the averages (t_1 + t_2 + t_3)/3, ... (The NURBS Book eq. 9.8).
    Both interpolate the data; they are different curves."""
    points = read_example("head.csv")
    t = python_parameters(points, "chord")
    model = interpolate(tmp_path, points, "--method", "bspline", "--degree", "3", "--param", "chord")
    knots = np.array(model["knots"])
    default = scipy_default_knots(t, 3)
    assert len(knots) == len(default)
    assert np.max(np.abs(knots - default)) > 1e-3
    ours = evaluate(tmp_path, model, t)
    assert relative(ours, points, data_scale(points)) <= RELATIVE_TOLERANCE


def test_bspline_end_derivatives_equal_scipy_on_the_same_knots(tmp_path):
    """--start-tangent/--end-tangent add C'(t_0), C'(t_m) (The NURBS Book §9.2.2);
    scipy solves the same problem on casteljau's knots with bc_type=([(1, d0)], [(1, d1)])."""
    points = read_example("car.csv")
    t = python_parameters(points, "centripetal")
    start, finish = np.array([3.0, -40.0]), np.array([-25.0, 1.0])
    for p in (2, 3, 5):
        model = interpolate(tmp_path, points, "--method", "bspline", "--degree", str(p), "--param", "centripetal",
                            "--start-tangent", "3,-40", "--end-tangent", "-25,1")
        knots, control = np.array(model["knots"]), np.array(model["control_points"])
        assert len(control) == len(points) + 2
        spline = make_interp_spline(t, points, k=p, t=knots, bc_type=([(1, start)], [(1, finish)]))
        scale = data_scale(points)
        record("bspline+derivatives control points", relative(control, spline.c, scale))
        assert relative(control, spline.c, scale) <= RELATIVE_TOLERANCE
        derivative = BSpline(knots, control, p).derivative()
        assert relative(derivative(0.0), start, 40.0) <= RELATIVE_TOLERANCE
        assert relative(derivative(1.0), finish, 40.0) <= RELATIVE_TOLERANCE


# --- Lagrange ---------------------------------------------------------------------------------


def chebyshev_nodes(count):
    """Chebyshev points of the second kind on [0, 1]: (1 - cos(j pi / n)) / 2, j = 0..n."""
    n = count - 1
    return (1.0 - np.cos(np.arange(count) * np.pi / n)) / 2.0


# Lagrange's result is a Bézier curve (to_bezier): its control points solve a
# Bernstein-Vandermonde system whose conditioning grows like 2^n (Farouki 1991),
# so the values are compared relative to the polynomial's own size on [0, 1]
# (max |p|), and the degrees stay where that conditioning allows 1e-12.
LAGRANGE_CASES = [("random2d", 8), ("random3d", 10), ("head", 12), ("car", 12)]


@pytest.mark.parametrize("dataset,count", LAGRANGE_CASES)
@pytest.mark.parametrize("nodes", ["uniform", "chord", "centripetal", "chebyshev"])
def test_lagrange_equals_barycentric_interpolator(tmp_path, dataset, count, nodes):
    points = DATASETS[dataset]()[:count]
    if nodes == "chebyshev":
        t = chebyshev_nodes(len(points))
        options = ["--method", "lagrange", "--nodes", "chebyshev"]
    else:
        t = python_parameters(points, nodes)
        options = ["--method", "lagrange", "--param", nodes]
    model = interpolate(tmp_path, points, *options)
    assert model["type"] == "bezier" and len(model["control_points"]) == len(points)
    reference = BarycentricInterpolator(t, points)
    us = sample_parameters(t, np.random.default_rng(3), count=200)
    expected = reference(us)
    scale = max(float(np.max(np.abs(expected))), data_scale(points))
    ours = evaluate(tmp_path, model, us)
    record("lagrange values", relative(ours, expected, scale))
    assert relative(ours, expected, scale) <= RELATIVE_TOLERANCE


def test_lagrange_function_mode_runge(tmp_path):
    """--function on Runge's f(x) = 1/(1 + 25x^2) at 11 Chebyshev points of [-1, 1]: the
    curve (x, p(x)); p equals BarycentricInterpolator, and the first coordinate is x."""
    x = -np.cos(np.arange(11) * np.pi / 10)
    x[5] = 0.0
    y = 1.0 / (1.0 + 25.0 * x * x)
    model = interpolate(tmp_path, np.column_stack([x, y]), "--method", "lagrange", "--function")
    s = np.linspace(0.0, 1.0, 301)
    ours = evaluate(tmp_path, model, s)
    assert relative(ours[:, 0], -1.0 + 2.0 * s, 1.0) <= RELATIVE_TOLERANCE
    expected = BarycentricInterpolator(x, y)(ours[:, 0])
    record("lagrange --function values", relative(ours[:, 1], expected, 1.0))
    assert relative(ours[:, 1], expected, 1.0) <= RELATIVE_TOLERANCE


# --- Hermite ----------------------------------------------------------------------------------


@pytest.mark.parametrize("dataset", list(DATASETS))
@pytest.mark.parametrize("param", PARAMS)
@pytest.mark.parametrize("closed", [False, True])
def test_hermite_equals_cubic_hermite_spline(tmp_path, dataset, param, closed):
    points = DATASETS[dataset]()
    rng = np.random.default_rng(len(points) + 7)
    spread = data_scale(points)
    tangents = rng.uniform(-spread, spread, size=points.shape)
    d = points.shape[1]
    header = ["x", "y", "z"][:d] + ["dx", "dy", "dz"][:d]
    options = ["--method", "hermite", "--param", param] + (["--closed"] if closed else [])
    model = interpolate(tmp_path, np.hstack([points, tangents]), *options, header=header)
    assert model["type"] == "bspline" and model["degree"] == 3
    t = python_parameters(points, param, closed)
    if closed:
        reference = CubicHermiteSpline(t, np.vstack([points, points[:1]]), np.vstack([tangents, tangents[:1]]))
    else:
        reference = CubicHermiteSpline(t, points, tangents)
    us = sample_parameters(t, np.random.default_rng(8))
    ours = evaluate(tmp_path, model, us)
    record("hermite values", relative(ours, reference(us), spread))
    assert relative(ours, reference(us), spread) <= RELATIVE_TOLERANCE
    # The tangents: the model's derivative at the data sites (right-hand spans).
    knots, control = np.array(model["knots"]), np.array(model["control_points"])
    derivative = BSpline(knots, control, 3).derivative()
    inner = t[:-1]
    scale = float(np.max(np.abs(tangents)))
    assert relative(derivative(inner), (reference.derivative())(inner), scale) <= RELATIVE_TOLERANCE


def test_report_largest_relative_differences(capsys):
    """Prints the largest relative difference per method (pytest -s shows them)."""
    with capsys.disabled():
        for key in sorted(WORST):
            print(f"\nlargest relative difference, {key}: {WORST[key]:.3g}", end="")
