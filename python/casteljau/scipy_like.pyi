"""Type stubs of casteljau.scipy_like (scipy.interpolate-like classes on casteljau's B-splines)."""

from __future__ import annotations

from typing import Any, Literal, Optional, Sequence, Tuple, Union

import numpy
from numpy.typing import ArrayLike, NDArray

from . import BSplineCurve

Extrapolate = Union[bool, Literal["periodic"]]
BoundaryDerivatives = Optional[Sequence[Tuple[int, ArrayLike]]]
InterpBC = Union[
    None,
    Literal["not-a-knot", "natural", "clamped", "periodic"],
    Tuple[Union[None, str, BoundaryDerivatives], Union[None, str, BoundaryDerivatives]],
]
CubicBC = Union[
    Literal["not-a-knot", "natural", "clamped", "periodic"],
    Tuple[Union[str, Tuple[int, ArrayLike]], Union[str, Tuple[int, ArrayLike]]],
]

__all__: list[str]

class BSpline:
    """A B-spline function of one variable, like scipy.interpolate.BSpline (axis=0 only)."""
    t: NDArray[numpy.float64]
    c: NDArray[numpy.float64]
    k: int
    extrapolate: Extrapolate
    axis: int
    def __init__(self, t: ArrayLike, c: ArrayLike, k: int, extrapolate: Extrapolate = True, axis: int = 0) -> None: ...
    @classmethod
    def construct_fast(
        cls, t: NDArray[numpy.float64], c: NDArray[numpy.float64], k: int, extrapolate: Extrapolate = True,
        axis: int = 0,
    ) -> BSpline: ...
    @classmethod
    def basis_element(cls, t: ArrayLike, extrapolate: Extrapolate = True) -> BSpline: ...
    @property
    def curve(self) -> BSplineCurve: ...
    @property
    def tck(self) -> Tuple[NDArray[numpy.float64], NDArray[numpy.float64], int]: ...
    def __call__(self, x: ArrayLike, nu: int = 0, extrapolate: Optional[Extrapolate] = None) -> NDArray[numpy.float64]: ...
    def derivative(self, nu: int = 1) -> BSpline: ...
    def antiderivative(self, nu: int = 1) -> BSpline: ...
    def integrate(self, a: float, b: float, extrapolate: Optional[Extrapolate] = None) -> NDArray[numpy.float64]: ...

def make_interp_spline(
    x: ArrayLike, y: ArrayLike, k: int = 3, t: Optional[ArrayLike] = None, bc_type: InterpBC = None, axis: int = 0
) -> BSpline: ...
def make_lsq_spline(
    x: ArrayLike, y: ArrayLike, t: ArrayLike, k: int = 3, w: Optional[ArrayLike] = None, axis: int = 0
) -> BSpline: ...
def make_smoothing_spline(
    x: ArrayLike, y: ArrayLike, w: Optional[ArrayLike] = None, lam: Optional[float] = None
) -> BSpline: ...

class CubicSpline:
    """The C2 cubic spline through (x, y), like scipy.interpolate.CubicSpline (a BSpline inside, not a PPoly)."""
    x: NDArray[numpy.float64]
    axis: int
    extrapolate: Extrapolate
    bc_type: CubicBC
    bspline: BSpline
    def __init__(
        self, x: ArrayLike, y: ArrayLike, axis: int = 0, bc_type: CubicBC = "not-a-knot",
        extrapolate: Optional[Extrapolate] = None,
    ) -> None: ...
    def __call__(self, x: ArrayLike, nu: int = 0, extrapolate: Optional[Extrapolate] = None) -> NDArray[numpy.float64]: ...
    def derivative(self, nu: int = 1) -> BSpline: ...
    def antiderivative(self, nu: int = 1) -> BSpline: ...
    def integrate(self, a: float, b: float, extrapolate: Optional[Extrapolate] = None) -> NDArray[numpy.float64]: ...
