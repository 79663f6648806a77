"""matplotlib helpers: the seed notebook's figures (seed 004) in a few lines.

Every function draws on `ax` (the current axes, ``plt.gca()``, when None;
an empty figure gets a 3D axes for a curve or surface in R^3), returns the
list of artists it made, and passes its other keyword arguments to
matplotlib (``color='k'``, ``linestyle='--'``, ...). The axes may also be
given first, ``curve(ax, c)``, as matplotlib's own helpers take it.

All evaluation goes through the compiled batch functions (``points_at``,
``bernstein_all``, ``basis_function``, ``grid_points_at``,
``casteljau_construction``, ``de_boor_net``, ``subdivide_recursive``): no
per-point Python loop. This module imports matplotlib; ``import casteljau``
alone never does.

    from casteljau import plot
    plot.curve(c, polygon=True)             # seed 004's plot_bezier1
    plot.bernstein_basis(20, range(1, 20))  # plot_bernstein(20, range(1, 20))
    plot.de_casteljau(c, 0.5)               # demo_casteljau(Ps, 0.5)
"""

from __future__ import annotations

import functools
import math

import matplotlib.cbook
import matplotlib.lines
import matplotlib.pyplot as plt
import numpy as np
from matplotlib.axes import Axes
from matplotlib.patches import FancyArrowPatch

from . import _casteljau as _cj

__all__ = [
    "curve",
    "control_polygon",
    "basis",
    "bernstein_basis",
    "de_casteljau",
    "de_boor",
    "tangents",
    "subdivision",
    "surface_wireframe",
    "control_net",
]

#: Points per curve when `samples` is an int left at its default: the
#: notebook's subdi(0, 1, 500) (500 intervals).
DEFAULT_SAMPLES = 501

# Default looks, close to the notebook's: curves in black, control points as
# red dots on a dashed polygon, construction levels dashed black, tangents blue.
_POLYGON_STYLE = {"color": "tab:red", "linestyle": "--", "linewidth": 0.8, "marker": "o", "markersize": 4}
_LEVEL_STYLE = {"color": "k", "linestyle": "--", "linewidth": 0.8, "marker": "o", "markersize": 3}
_POINT_STYLE = {"color": "r", "linestyle": "none", "marker": "o", "markersize": 6, "zorder": 3}
_TANGENT_STYLE = {"color": "tab:blue", "linewidth": 1.5}
_NET_STYLE = {"color": "tab:red", "linestyle": "--", "linewidth": 0.6, "marker": "o", "markersize": 2}


# ---------------------------------------------------------------- plumbing --


def _kinds(*names: str) -> tuple[type, ...]:
    """The compiled classes of these names that exist (all of them once the module is complete)."""
    return tuple(getattr(_cj, name) for name in names if hasattr(_cj, name))


def _curve_kinds() -> tuple[type, ...]:
    return _kinds("BezierCurve", "BSplineCurve", "PiecewiseBezierCurve")


def _surface_kinds() -> tuple[type, ...]:
    return _kinds("BSplineSurface", "BezierSurface", "CoonsPatch")


def _is(obj: object, name: str) -> bool:
    kind = getattr(_cj, name, None)
    return kind is not None and isinstance(obj, kind)


def _check_curve(obj: object, allowed: tuple[str, ...] = ("BezierCurve", "BSplineCurve", "PiecewiseBezierCurve")) -> None:
    kinds = _kinds(*allowed)
    if not isinstance(obj, kinds):
        raise TypeError(f"expected a {' or '.join(allowed)}, got {type(obj).__name__}")


def _axes_first(function):
    """Lets `function(ax, obj, ...)` mean `function(obj, ..., ax=ax)`."""

    @functools.wraps(function)
    def wrapper(*args, **kwargs):
        if args and isinstance(args[0], Axes):
            if kwargs.get("ax") is not None:
                raise TypeError(f"{function.__name__}() got the axes twice (first argument and ax=)")
            kwargs["ax"] = args[0]
            args = args[1:]
        return function(*args, **kwargs)

    return wrapper


def _axes(ax: Axes | None, dimension: int) -> Axes:
    """`ax`, or the current axes; a 3D one for points of R^3 (made on an empty figure)."""
    if dimension not in (1, 2, 3):
        raise ValueError(f"can only draw points of R^1, R^2 or R^3, got dimension {dimension}")
    if ax is None:
        figure = plt.gcf()
        if dimension == 3 and not figure.axes:
            ax = figure.add_subplot(projection="3d")
        else:
            ax = plt.gca()
    elif not isinstance(ax, Axes):
        raise TypeError(f"ax must be a matplotlib Axes or None, got {type(ax).__name__}")
    if dimension == 3 and ax.name != "3d":
        raise ValueError("points of R^3 need a 3D axes (e.g. plt.figure().add_subplot(projection='3d'))")
    return ax


def _merged(style: dict, kw: dict | None) -> dict:
    """The caller's line options over the default `style`, matplotlib's short aliases
    (``ls``, ``lw``, ``c``, ``ms``...) first written in full, so that ``ls='-'`` replaces the
    default ``linestyle`` rather than meeting it ("Got both 'linestyle' and 'ls'")."""
    return {**style, **matplotlib.cbook.normalize_kwargs(kw or {}, matplotlib.lines.Line2D)}


def _plot(ax: Axes, points: np.ndarray, style: dict, kw: dict) -> list:
    """ax.plot of an (k, 2) or (k, 3) array, default `style` under the caller's `kw`."""
    options = _merged(style, kw)
    points = np.asarray(points, dtype=float)
    if points.shape[1] == 3:
        return list(ax.plot(points[:, 0], points[:, 1], points[:, 2], **options))
    return list(ax.plot(points[:, 0], points[:, 1], **options))


def _breakpoints(obj) -> np.ndarray:
    """The parameters where a curve may lose smoothness (knots inside the domain, piece joints)."""
    lower, upper = obj.domain
    if _is(obj, "BSplineCurve"):
        knots = np.asarray(obj.knots, dtype=float)
        return np.unique(knots[(knots >= lower) & (knots <= upper)])
    if _is(obj, "PiecewiseBezierCurve"):
        return np.arange(0.0, upper + 1.0)
    return np.array([lower, upper])


def _parameters(obj, samples) -> np.ndarray:
    """`samples` points over the domain (breakpoints included, so joints and kinks are exact), or the given array."""
    if isinstance(samples, (int, np.integer)) and not isinstance(samples, bool):
        if samples < 2:
            raise ValueError(f"samples must be at least 2, got {samples}")
        lower, upper = obj.domain
        return np.union1d(np.linspace(lower, upper, int(samples)), _breakpoints(obj))
    values = np.asarray(samples)
    if values.dtype.kind not in "fiu":
        raise TypeError(f"samples must be an int or an array of real parameters, got dtype {values.dtype}")
    return np.ascontiguousarray(values, dtype=float)


def _greville(obj) -> np.ndarray:
    """Abscissae of the control points of a curve in R^1 drawn as a graph (Greville abscissae; k/n for Bézier)."""
    if _is(obj, "BSplineCurve"):
        knots, p = np.asarray(obj.knots, dtype=float), obj.degree
        n = len(knots) - p - 1
        if p == 0:
            return knots[:n]
        return np.array([knots[i + 1 : i + p + 1].mean() for i in range(n)])
    if _is(obj, "PiecewiseBezierCurve"):
        return np.concatenate([i + np.linspace(0.0, 1.0, piece.degree + 1) for i, piece in enumerate(obj.pieces)])
    return np.linspace(0.0, 1.0, obj.degree + 1) if obj.degree > 0 else np.zeros(1)


def _graph(parameters: np.ndarray, values: np.ndarray) -> np.ndarray:
    """(u, x(u)): how a curve in R^1 is drawn."""
    return np.column_stack([parameters, np.asarray(values, dtype=float).reshape(-1)])


def _degree_at(obj, u: float) -> int:
    """The degree of the curve (of the piece holding u, for a PiecewiseBezierCurve: locate's rule)."""
    if _is(obj, "PiecewiseBezierCurve"):
        pieces = obj.pieces
        return int(pieces[min(max(int(math.floor(u)), 0), len(pieces) - 1)].degree)
    return int(obj.degree)


def _derivatives(obj, parameters: np.ndarray, order: int) -> np.ndarray:
    """C^(order) at every parameter: the batch derivatives_at where the curve kind has one."""
    try:
        return np.asarray(_cj.derivatives_at(obj, parameters, order))
    except TypeError:
        # A curve kind with only the single-parameter derivative (a handful of parameters here).
        return np.array([_cj.derivative_at(obj, float(u), order) for u in parameters])


# ------------------------------------------------------------------ curves --


@_axes_first
def curve(curve, samples=DEFAULT_SAMPLES, *, ax=None, polygon=False, polygon_kw=None, **kw) -> list:
    """Draw a BezierCurve, BSplineCurve or PiecewiseBezierCurve (seed 004's plot_bezier1).

    samples: the number of parameters spread over the domain (the knots or
    joints are added so kinks are exact) or an array of parameters. A curve
    in R^3 needs a 3D axes; a curve in R^1 is drawn as the graph (u, x(u)).
    polygon=True also draws the control polygon (styled by polygon_kw).
    Returns [curve line] (+ the polygon's artists).
    """
    _check_curve(curve)
    ax = _axes(ax, curve.dimension)
    parameters = _parameters(curve, samples)
    points = _cj.points_at(curve, parameters)
    if curve.dimension == 1:
        points = _graph(parameters, points)
    artists = _plot(ax, points, {}, kw)
    if polygon:
        artists += control_polygon(curve, ax=ax, **(polygon_kw or {}))
    return artists


_draw_curve = curve  # the function: the name `curve` is shadowed by the parameters of the others


@_axes_first
def control_polygon(curve, *, ax=None, **kw) -> list:
    """Draw the control polygon of a curve (or of an (n, d) array of points): a dashed line through red dots.

    PiecewiseBezierCurve: one line per piece. Rational curves: the Euclidean
    control points. A curve in R^1: the points (Greville abscissa, c_i).
    Returns the lines.
    """
    if isinstance(curve, _curve_kinds()):
        dimension = curve.dimension
        if _is(curve, "PiecewiseBezierCurve"):
            polygons = [np.asarray(piece.control_points, dtype=float) for piece in curve.pieces]
        else:
            polygons = [np.asarray(curve.control_points, dtype=float)]
        if dimension == 1:
            abscissae = _greville(curve)
            sizes = np.cumsum([0] + [len(p) for p in polygons])
            polygons = [_graph(abscissae[a:b], p) for p, a, b in zip(polygons, sizes[:-1], sizes[1:])]
    else:
        if isinstance(curve, (str, bytes)) or curve is None or isinstance(curve, _surface_kinds()):
            raise TypeError(f"expected a curve or an (n, d) array of points, got {type(curve).__name__}")
        points = np.asarray(curve)
        if points.dtype.kind not in "fiu":
            raise TypeError(f"expected a curve or an (n, d) array of real points, got dtype {points.dtype}")
        if points.ndim != 2 or points.shape[0] == 0 or points.shape[1] not in (2, 3):
            raise ValueError(f"points must be an (n, 2) or (n, 3) array, got shape {points.shape}")
        dimension, polygons = points.shape[1], [points.astype(float)]
    ax = _axes(ax, dimension)
    artists = []
    for points in polygons:
        artists += _plot(ax, points, _POLYGON_STYLE, kw)
    return artists


@_axes_first
def bernstein_basis(n, ks=None, samples=DEFAULT_SAMPLES, *, ax=None, **kw) -> list:
    """Draw the Bernstein polynomials B_{n,k} on [0, 1] for k in ks (all k = 0..n when None).

    Seed 004's plot_bernstein(n, rng), values by bernstein_all (The NURBS
    Book A1.3). Returns one line per k, in the order of ks.
    """
    if isinstance(n, bool) or not isinstance(n, (int, np.integer)):
        raise TypeError(f"n must be an int, got {type(n).__name__}")
    indices = list(range(n + 1)) if ks is None else [int(k) for k in ks]
    for k in indices:
        if not 0 <= k <= n:
            raise ValueError(f"k = {k} is outside 0..{n}")
    ax = _axes(ax, 2)
    ts = np.linspace(0.0, 1.0, int(samples))
    values = np.asarray(_cj.bernstein_all(int(n), ts))
    options = _merged({"color": "k", "linewidth": 1.0}, kw)
    artists = []
    for k in indices:
        artists += ax.plot(ts, values[:, k], **options)
    return artists


@_axes_first
def basis(knots, degree, indices=None, samples=DEFAULT_SAMPLES, *, ax=None, **kw) -> list:
    """Draw the B-spline basis functions N_{i,p} over the whole knot range [t_0, t_last].

    By the Cox–de Boor definition (basis_function, The NURBS Book A2.4), so
    the partial functions near the ends show too; the knots are among the
    sample points. indices: which i (all 0..n when None). Returns one line
    per function.
    """
    values = np.asarray(knots)
    if values.dtype.kind not in "fiu":
        raise TypeError(f"knots must be an array of real numbers, got dtype {values.dtype}")
    values = values.astype(float)
    if values.ndim != 1 or values.size < 2:
        raise ValueError(f"knots must be a (k,) array of at least 2 values, got shape {values.shape}")
    if not np.all(np.isfinite(values)):
        raise ValueError("knots must be finite")
    if isinstance(degree, bool) or not isinstance(degree, (int, np.integer)):
        raise TypeError(f"degree must be an int, got {type(degree).__name__}")
    count = values.size - int(degree) - 1
    chosen = list(range(count)) if indices is None else [int(i) for i in indices]
    ax = _axes(ax, 2)
    lower, upper = values[0], values[-1]
    if not upper > lower:
        raise ValueError("the knots span an empty range")
    us = np.union1d(np.linspace(lower, upper, int(samples)), values)
    options = _merged({"linewidth": 1.0}, kw)
    artists = []
    for i in chosen:
        artists += ax.plot(us, np.asarray(_cj.basis_function(values, int(degree), i, us)), **options)
    return artists


@_axes_first
def de_casteljau(curve, t, *, ax=None, show_curve=True, samples=DEFAULT_SAMPLES, curve_kw=None, point_kw=None, **kw) -> list:
    """Draw de Casteljau's construction of C(t) (seed 004's demo_casteljau).

    The levels 0..n-1 of casteljau_construction (level 0 the control
    polygon) as dashed polygons styled by kw, the point C(t) in red, and the
    curve in black (show_curve=False leaves it out). Returns [curve line if
    drawn, level 0 line, ..., level n-1 line, point]: the last artist holds C(t).
    """
    _check_curve(curve, ("BezierCurve",))
    ax = _axes(ax, curve.dimension)
    if curve.dimension == 1:
        raise ValueError("the construction is drawn for curves in R^2 or R^3")
    levels = [np.asarray(level, dtype=float) for level in _cj.casteljau_construction(curve, float(t))]
    return _construction(ax, curve, levels, show_curve, samples, curve_kw, point_kw, kw, polygon=False)


@_axes_first
def de_boor(curve, u, *, ax=None, show_curve=True, polygon=True, samples=DEFAULT_SAMPLES, curve_kw=None, point_kw=None,
            **kw) -> list:
    """Draw de Boor's algorithm at u for a BSplineCurve (The NURBS Book §5.3, fig. 5.11).

    The whole control polygon (polygon=True), the levels 0..p-1 of
    de_boor_net (level 0 the p+1 control points of the span) dashed, the
    point C(u) in red and the curve. Returns [curve line if drawn, polygon
    lines if drawn, level 0 line, ..., level p-1 line, point].
    """
    _check_curve(curve, ("BSplineCurve",))
    ax = _axes(ax, curve.dimension)
    if curve.dimension == 1:
        raise ValueError("the construction is drawn for curves in R^2 or R^3")
    _span, levels = _cj.de_boor_net(curve, float(u))
    levels = [np.asarray(level, dtype=float) for level in levels]
    return _construction(ax, curve, levels, show_curve, samples, curve_kw, point_kw, kw, polygon=polygon)


def _construction(ax, obj, levels, show_curve, samples, curve_kw, point_kw, kw, polygon) -> list:
    artists = []
    if show_curve:
        artists += _draw_curve(obj, samples, ax=ax, **{"color": "k", **(curve_kw or {})})
    if polygon:
        artists += control_polygon(obj, ax=ax, **{"color": "0.6", "marker": "none"})
    for level in levels[:-1]:
        artists += _plot(ax, level, _LEVEL_STYLE, kw)
    artists += _plot(ax, levels[-1], _POINT_STYLE, point_kw or {})
    return artists



@_axes_first
def tangents(curve, ts=None, *, order=1, scale=None, ax=None, arrows=None, **kw) -> list:
    """Draw the end tangents of a curve (seed 004's plot_bezier2), or derivative vectors at the parameters ts.

    Each is a segment from C(t) along scale * C^(order)(t); scale defaults to
    (p - order)!/p! (p the degree), so for a Bézier curve the first-order
    segments are Delta P_k: at the ends, ts=None, they are the first and last
    legs of the control polygon, C'(0) = n (P_1 - P_0) and C'(1) = n (P_n -
    P_{n-1}), the last one drawn backward from C(1). arrows (2D, default on
    when ts is given) adds arrow heads. Returns the segments, then the heads.
    """
    _check_curve(curve)
    ax = _axes(ax, curve.dimension)
    if curve.dimension == 1:
        raise ValueError("tangents are drawn for curves in R^2 or R^3")
    if isinstance(order, bool) or not isinstance(order, (int, np.integer)):
        raise TypeError(f"order must be an int, got {type(order).__name__}")
    ends = ts is None
    parameters = np.array(curve.domain, dtype=float) if ends else _parameters(curve, np.atleast_1d(np.asarray(ts)))
    points = np.asarray(_cj.points_at(curve, parameters))
    vectors = _derivatives(curve, parameters, int(order))
    if scale is None:  # per parameter: a piecewise curve's pieces may differ in degree
        degrees = [_degree_at(curve, u) for u in parameters]
        scale = np.array([1.0 / math.perm(p, int(order)) if 0 < order <= p else 1.0 for p in degrees])
    scale = np.broadcast_to(np.asarray(scale, dtype=float).reshape(-1), (len(parameters),))[:, None]
    starts, stops = points.copy(), points + scale * vectors
    if ends:  # the end tangent drawn toward the inside of the curve, on the last leg
        starts[-1], stops[-1] = points[-1] - scale[-1] * vectors[-1], points[-1]
    options = _merged(_TANGENT_STYLE, kw)
    artists = []
    for a, b in zip(starts, stops):
        artists += _plot(ax, np.vstack([a, b]), {}, options)
    if arrows is None:
        arrows = not ends
    if arrows and curve.dimension == 2:
        color = artists[0].get_color() if artists else options.get("color")
        for a, b in zip(starts, stops):
            head = FancyArrowPatch(tuple(a), tuple(b), arrowstyle="-|>", mutation_scale=12, color=color, linewidth=0)
            artists.append(ax.add_patch(head))
    return artists


@_axes_first
def subdivision(curve, depth, t=0.5, *, ax=None, polygons=False, polygon_kw=None, **kw) -> list:
    """Draw recursive subdivision of a BezierCurve `depth` times at t (seed 004's plot_bezier(Ps, r)).

    The polyline through the 2^depth + 1 points of subdivide_recursive (all
    on the curve; depth 9 gives the notebook's 513 points), styled by kw;
    polygons=True also draws the control polygons of the 2^depth pieces
    (split_at applied depth times; depth <= 10 then). Returns [polyline,
    piece polygons...].
    """
    _check_curve(curve, ("BezierCurve",))
    ax = _axes(ax, curve.dimension)
    if curve.dimension == 1:
        raise ValueError("subdivision is drawn for curves in R^2 or R^3")
    if isinstance(depth, bool) or not isinstance(depth, (int, np.integer)):
        raise TypeError(f"depth must be an int, got {type(depth).__name__}")
    points = np.asarray(_cj.subdivide_recursive(curve, int(depth), float(t)))
    artists = _plot(ax, points, {"color": "k"}, kw)
    if polygons:
        if depth > 10:
            raise ValueError(f"polygons=True draws 2^depth polygons; depth {depth} is above 10")
        pieces = [curve]
        for _ in range(int(depth)):  # one split per piece and level: a loop over curves, not points
            pieces = [half for piece in pieces for half in _cj.split_at(piece, float(t))]
        style = _merged(_POLYGON_STYLE, polygon_kw)
        for piece in pieces:
            artists += _plot(ax, np.asarray(piece.control_points, dtype=float), style, {})
    return artists


# ---------------------------------------------------------------- surfaces --


def _net_lines(net: np.ndarray) -> list[np.ndarray]:
    """The rows and columns of an (rows, columns, d) net as polylines."""
    return [net[i] for i in range(net.shape[0])] + [net[:, j] for j in range(net.shape[1])]


@_axes_first
def control_net(surface, *, ax=None, **kw) -> list:
    """Draw the control net of a BSplineSurface or BezierSurface (rows then columns), or the
    control polygons of a CoonsPatch's four boundaries (u0, u1, v0, v1). Returns the lines."""
    if not isinstance(surface, _surface_kinds()):
        raise TypeError(f"expected a BSplineSurface, BezierSurface or CoonsPatch, got {type(surface).__name__}")
    ax = _axes(ax, surface.dimension)
    if _is(surface, "CoonsPatch"):
        lines = [np.asarray(boundary.control_points, dtype=float)
                 for boundary in (surface.u0, surface.u1, surface.v0, surface.v1)]
    else:
        lines = _net_lines(np.asarray(surface.control_net, dtype=float))
    artists = []
    for line in lines:
        artists += _plot(ax, line, _NET_STYLE, kw)
    return artists


@_axes_first
def surface_wireframe(surface, count=10, samples=101, *, ax=None, net=False, net_kw=None, **kw) -> list:
    """Draw a BSplineSurface, BezierSurface or CoonsPatch as iso-curves (on a 3D axes for a surface in R^3).

    count: iso-curves per direction, an int or (count_u, count_v), evenly
    spaced over the domain (ends included); samples: points per iso-curve.
    Each family is one grid_points_at call. net=True also draws the control
    net (control_net). Returns the u-iso-curves (u fixed), then the
    v-iso-curves, then the net's lines.
    """
    if not isinstance(surface, _surface_kinds()):
        raise TypeError(f"expected a BSplineSurface, BezierSurface or CoonsPatch, got {type(surface).__name__}")
    count_u, count_v = (count, count) if np.ndim(count) == 0 else tuple(count)
    if min(int(count_u), int(count_v)) < 1 or int(samples) < 2:
        raise ValueError("count must be >= 1 and samples >= 2")
    ax = _axes(ax, surface.dimension)
    if surface.dimension == 1:
        raise ValueError("surfaces are drawn in R^2 or R^3")
    (u0, u1), (v0, v1) = surface.domain_u, surface.domain_v
    us_dense, vs_dense = np.linspace(u0, u1, int(samples)), np.linspace(v0, v1, int(samples))
    us_iso = np.linspace(u0, u1, int(count_u)) if int(count_u) > 1 else np.array([0.5 * (u0 + u1)])
    vs_iso = np.linspace(v0, v1, int(count_v)) if int(count_v) > 1 else np.array([0.5 * (v0 + v1)])
    along_v = np.asarray(_cj.grid_points_at(surface, us_iso, vs_dense))  # (count_u, samples, d)
    along_u = np.asarray(_cj.grid_points_at(surface, us_dense, vs_iso))  # (samples, count_v, d)
    options = _merged({"color": "k", "linewidth": 0.7}, kw)
    artists = []
    for a in range(along_v.shape[0]):
        artists += _plot(ax, along_v[a], {}, options)
    for b in range(along_u.shape[1]):
        artists += _plot(ax, along_u[:, b], {}, options)
    if net:
        artists += control_net(surface, ax=ax, **(net_kw or {}))
    return artists
