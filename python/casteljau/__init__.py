"""casteljau: Bézier, B-spline and NURBS curves and surfaces on numpy arrays.

The compiled module (casteljau._casteljau) holds the C++ library's classes and
functions under the same names (point_at, points_at, insert_knot, ...); this
package re-exports them and adds the scipy-like classes (BSpline,
make_interp_spline, CubicSpline) and the matplotlib helpers (casteljau.plot,
imported on demand). docs/python.md describes the conventions.
"""

from ._casteljau import *  # noqa: F401,F403  (the C++ API, names as in C++)
from ._casteljau import __version__, tolerances  # noqa: F401
from .scipy_like import BSpline, CubicSpline, make_interp_spline, make_lsq_spline, make_smoothing_spline  # noqa: F401
