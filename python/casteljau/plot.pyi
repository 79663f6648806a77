"""Type stubs of casteljau.plot (matplotlib helpers for seed 004's figures).

Every function also accepts the axes as its first positional argument,
`f(ax, obj, ...)`, meaning `f(obj, ..., ax=ax)` (the second overload).
"""

from __future__ import annotations

from typing import Any, Sequence, Union, overload

from matplotlib.artist import Artist
from matplotlib.axes import Axes
from numpy.typing import ArrayLike

from . import BezierCurve, BezierSurface, BSplineCurve, BSplineSurface, CoonsPatch, PiecewiseBezierCurve

Curve = Union[BezierCurve, BSplineCurve, PiecewiseBezierCurve]
Surface = Union[BSplineSurface, BezierSurface, CoonsPatch]
Samples = Union[int, ArrayLike]

DEFAULT_SAMPLES: int

__all__: list[str]

@overload
def curve(curve: Curve, samples: Samples = ..., *, ax: Axes | None = None, polygon: bool = False,
          polygon_kw: dict[str, Any] | None = None, **kw: Any) -> list[Artist]: ...
@overload
def curve(ax: Axes, curve: Curve, samples: Samples = ..., *, polygon: bool = False,
          polygon_kw: dict[str, Any] | None = None, **kw: Any) -> list[Artist]: ...
@overload
def control_polygon(curve: Curve | ArrayLike, *, ax: Axes | None = None, **kw: Any) -> list[Artist]: ...
@overload
def control_polygon(ax: Axes, curve: Curve | ArrayLike, **kw: Any) -> list[Artist]: ...
@overload
def bernstein_basis(n: int, ks: Sequence[int] | None = None, samples: int = ..., *, ax: Axes | None = None,
                    **kw: Any) -> list[Artist]: ...
@overload
def bernstein_basis(ax: Axes, n: int, ks: Sequence[int] | None = None, samples: int = ..., **kw: Any) -> list[Artist]: ...
@overload
def basis(knots: ArrayLike, degree: int, indices: Sequence[int] | None = None, samples: int = ..., *,
          ax: Axes | None = None, **kw: Any) -> list[Artist]: ...
@overload
def basis(ax: Axes, knots: ArrayLike, degree: int, indices: Sequence[int] | None = None, samples: int = ...,
          **kw: Any) -> list[Artist]: ...
@overload
def de_casteljau(curve: BezierCurve, t: float, *, ax: Axes | None = None, show_curve: bool = True,
                 samples: Samples = ..., curve_kw: dict[str, Any] | None = None,
                 point_kw: dict[str, Any] | None = None, **kw: Any) -> list[Artist]: ...
@overload
def de_casteljau(ax: Axes, curve: BezierCurve, t: float, *, show_curve: bool = True, samples: Samples = ...,
                 curve_kw: dict[str, Any] | None = None, point_kw: dict[str, Any] | None = None,
                 **kw: Any) -> list[Artist]: ...
@overload
def de_boor(curve: BSplineCurve, u: float, *, ax: Axes | None = None, show_curve: bool = True, polygon: bool = True,
            samples: Samples = ..., curve_kw: dict[str, Any] | None = None, point_kw: dict[str, Any] | None = None,
            **kw: Any) -> list[Artist]: ...
@overload
def de_boor(ax: Axes, curve: BSplineCurve, u: float, *, show_curve: bool = True, polygon: bool = True,
            samples: Samples = ..., curve_kw: dict[str, Any] | None = None, point_kw: dict[str, Any] | None = None,
            **kw: Any) -> list[Artist]: ...
@overload
def tangents(curve: Curve, ts: ArrayLike | None = None, *, order: int = 1, scale: float | None = None,
             ax: Axes | None = None, arrows: bool | None = None, **kw: Any) -> list[Artist]: ...
@overload
def tangents(ax: Axes, curve: Curve, ts: ArrayLike | None = None, *, order: int = 1, scale: float | None = None,
             arrows: bool | None = None, **kw: Any) -> list[Artist]: ...
@overload
def subdivision(curve: BezierCurve, depth: int, t: float = 0.5, *, ax: Axes | None = None, polygons: bool = False,
                polygon_kw: dict[str, Any] | None = None, **kw: Any) -> list[Artist]: ...
@overload
def subdivision(ax: Axes, curve: BezierCurve, depth: int, t: float = 0.5, *, polygons: bool = False,
                polygon_kw: dict[str, Any] | None = None, **kw: Any) -> list[Artist]: ...
@overload
def control_net(surface: Surface, *, ax: Axes | None = None, **kw: Any) -> list[Artist]: ...
@overload
def control_net(ax: Axes, surface: Surface, **kw: Any) -> list[Artist]: ...
@overload
def surface_wireframe(surface: Surface, count: int | tuple[int, int] = 10, samples: int = 101, *,
                      ax: Axes | None = None, net: bool = False, net_kw: dict[str, Any] | None = None,
                      **kw: Any) -> list[Artist]: ...
@overload
def surface_wireframe(ax: Axes, surface: Surface, count: int | tuple[int, int] = 10, samples: int = 101, *,
                      net: bool = False, net_kw: dict[str, Any] | None = None, **kw: Any) -> list[Artist]: ...
