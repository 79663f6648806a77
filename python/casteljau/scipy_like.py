"""scipy.interpolate-like classes on casteljau's compiled B-splines.

``BSpline``, ``make_interp_spline``, ``make_lsq_spline``,
``make_smoothing_spline`` and ``CubicSpline`` take the arguments of their
scipy.interpolate namesakes (scipy 1.10) and give the same values (to
rounding), so code written for scipy runs on casteljau's C++ kernels. All
evaluation goes through the compiled batch functions (``points_at``,
``derivatives_at`` with ``extrapolate=True``, writing into the result array):
no per-point Python work. Construction goes through the C++ interpolation and
fitting functions (``interpolate_cubic``, ``interpolate_on_knots``,
``interpolate_bspline``, ``fit_least_squares_on_knots``, ``fit_smoothing``) on
scipy's own knots, and the derivative / antiderivative curves
(``derivative_curve``, ``antiderivative_curve``, ``integral``).

What differs from scipy, everywhere:

- only ``axis=0`` (the interpolation axis first); any other axis raises
  ValueError;
- real data only: complex arrays raise TypeError; NaN or infinite knots,
  coefficients or data raise ValueError (scipy accepts NaN coefficients);
- knots of multiplicity above k+1 raise ValueError (casteljau's B-splines
  require multiplicity <= k+1), except k = 0 with the last knot repeated,
  as make_interp_spline(k=0) makes it (the empty last span holds the value at
  and beyond t[n], as in scipy);
- a spline's ``c`` holds exactly ``len(t) - k - 1`` coefficients (scipy's
  derivative/antiderivative pad ``c`` with zeros up to ``len(t)``);
- evaluation at NaN or infinite x gives NaN;
- a negative derivative order in ``__call__`` raises ValueError (scipy:
  NotImplementedError).

Each class and function says what else differs.
"""

from __future__ import annotations

import operator

import numpy as np

from . import _casteljau as _c

__all__ = ["BSpline", "make_interp_spline", "make_lsq_spline", "make_smoothing_spline", "CubicSpline"]


def _check_axis(axis, ndim):
    """Only the first axis: axis 0 (or -ndim) is accepted."""
    try:
        axis = operator.index(axis)
    except TypeError as error:
        raise TypeError(f"axis must be an integer, got {axis!r}") from error
    if axis == 0 or (ndim >= 1 and axis == -ndim):
        return 0
    raise ValueError(f"axis={axis} is not supported: casteljau's scipy-like splines interpolate along axis 0 only "
                     f"(move the axis first with numpy.moveaxis)")


def _real_array(values, what):
    """values as a float64 array; TypeError for complex, bool, object, string dtypes."""
    array = np.asarray(values)
    if array.dtype.kind not in "fiu":
        raise TypeError(f"{what} has dtype {array.dtype}, expected real numbers (float or integer)")
    return np.asarray(array, dtype=np.float64)


def _as_points(y, what="y"):
    """(n,) or (n, ...) data as an (n, d) C-ordered float64 array and the trailing shape."""
    y = _real_array(y, what)
    if y.ndim == 0:
        raise ValueError(f"{what} must have at least one dimension, got a scalar")
    trailing = y.shape[1:]
    columns = int(np.prod(trailing)) if trailing else 1
    if columns == 0:
        raise ValueError(f"{what} has an empty trailing shape {trailing}")
    return np.ascontiguousarray(y.reshape(y.shape[0], columns)), trailing


def _check_x(x, count=None, what="x"):
    """x as a 1-D strictly increasing finite float64 array (of `count` values when given)."""
    x = _real_array(x, what)
    if x.ndim != 1:
        raise ValueError(f"{what} must be a 1-D array, got shape {x.shape}")
    if x.size == 0:
        raise ValueError(f"{what} is empty")
    if not np.all(np.isfinite(x)):
        raise ValueError(f"{what} has NaN or infinite values")
    if x.size > 1 and not np.all(np.diff(x) > 0):
        raise ValueError(f"{what} must increase strictly (no duplicates)")
    if count is not None and x.size != count:
        raise ValueError(f"shapes of {what} {x.shape} and y ({count}, ...) are incompatible")
    return np.ascontiguousarray(x)


def _compiled_knots(t, k):
    """The knots of the compiled curve for scipy's knots t: t itself, except for k = 0 with the last knot
    repeated (make_interp_spline's k = 0 knots x, x[-1]). There scipy's last coefficient belongs to the empty
    span [t[n-1], t[n]], which its evaluation uses from t[n] on; casteljau's curves have no empty spans of degree
    0 (multiplicity <= k + 1), so that span is widened to the right, to t[n] plus the previous step (or the next
    double up where that overflows): the same value at and beyond t[n], the base interval still [t[0], t[n]]."""
    if k != 0 or len(t) < 2 or t[-1] != t[-2]:
        return t
    end = float(t[-1])
    step = end - float(t[-3]) if len(t) >= 3 else 0.0
    if not (np.isfinite(step) and step > 0.0):
        step = max(abs(end), 1.0)
    beyond = end + step
    if not np.isfinite(beyond) or beyond <= end:
        beyond = float(np.nextafter(end, np.inf))
    return np.r_[t[:-1], beyond]


class BSpline:
    """A B-spline function of one variable, like scipy.interpolate.BSpline.

    ``BSpline(t, c, k, extrapolate=True, axis=0)``: knots ``t`` (n + k + 1
    values), coefficients ``c`` of shape (n,) or (n, ...), degree ``k``. It is
    a casteljau ``BSplineCurve`` of degree k on t with the rows of c as its
    control points (``curve``), evaluated by the compiled de Boor kernels.

    Differs from scipy: only axis=0; ``c`` keeps its first n rows (scipy keeps
    extra rows); knots of multiplicity above k+1, and NaN/inf in ``t`` or
    ``c``, raise ValueError (at construction, or at first use for
    ``construct_fast``); extrapolating beyond an empty end span (t[k] == t[k+1] or
    t[n-1] == t[n]) continues the first / last non-empty span (scipy's kernel gives 0 there);
    ``integrate`` with extrapolate=False over an interval outside [t[k], t[n]] gives 0 (scipy gives NaN
    for 2-D c); ``derivative(nu)`` on a spline with a knot of
    multiplicity k+1 inside returns the piecewise derivative (scipy raises);
    no ``design_matrix`` or ``from_power_basis``.
    """

    def __init__(self, t, c, k, extrapolate=True, axis=0):
        self.k = operator.index(k)
        if self.k < 0:
            raise ValueError("Spline order cannot be negative.")
        t = _real_array(t, "t")
        c = _real_array(c, "c")
        if t.ndim != 1:
            raise ValueError("Knot vector must be one-dimensional.")
        if c.ndim < 1:
            raise ValueError("Coefficients must be at least 1-dimensional.")
        self.axis = _check_axis(axis, c.ndim)
        n = t.shape[0] - self.k - 1
        if n < self.k + 1:
            raise ValueError(f"Need at least {2 * self.k + 2} knots for degree {self.k}")
        if c.shape[0] < n:
            raise ValueError("Knots, coefficients and degree are inconsistent.")
        self.t = np.ascontiguousarray(t)
        self.c = np.ascontiguousarray(c[:n])
        self.extrapolate = extrapolate if extrapolate == "periodic" else bool(extrapolate)
        self._curve_cache = None
        _ = self.curve  # validates now (ValueError with the C++ message)

    @classmethod
    def construct_fast(cls, t, c, k, extrapolate=True, axis=0):
        """A spline without checks (as scipy's); t and c must be float64 arrays of consistent shapes.

        Differs from scipy: the compiled curve is built, and checked, at the first evaluation.
        """
        self = object.__new__(cls)
        self.t, self.c, self.k = t, c, k
        self.extrapolate = extrapolate
        self.axis = axis
        self._curve_cache = None
        return self

    @classmethod
    def basis_element(cls, t, extrapolate=True):
        """The B-spline basis element B(x | t[0], ..., t[k+1]), k = len(t) - 2 (as scipy's: the knots are
        extended by k copies of t[0] - 1 and t[-1] + 1, the coefficient of the element is 1)."""
        t = _real_array(t, "t")
        k = len(t) - 2
        if k < 0:
            raise ValueError("basis_element needs at least 2 knots")
        t = np.r_[(t[0] - 1,) * k, t, (t[-1] + 1,) * k]
        c = np.zeros(t.size - k - 1)
        c[k] = 1.0
        return cls(t, c, k, extrapolate)

    # --- the compiled curve --------------------------------------------------------------

    @property
    def curve(self):
        """The casteljau BSplineCurve (degree k, knots t, control points c as an (n, d) array), built on first use."""
        t, c, k = self.t, self.c, self.k
        cache = self._curve_cache
        if cache is not None and cache[0] is t and cache[1] is c and cache[2] == k:
            return cache[3]
        n = len(t) - k - 1
        points = np.ascontiguousarray(np.asarray(c, dtype=np.float64)[:n].reshape(n, -1))
        curve = _c.BSplineCurve(k, _compiled_knots(t, k), points)
        self._curve_cache = (t, c, k, curve)
        return curve

    @classmethod
    def _from_curve(cls, curve, trailing, extrapolate, axis=0):
        """A BSpline from a compiled curve whose control points are rows of `trailing`-shaped coefficients."""
        points = curve.control_points
        c = points.reshape((points.shape[0],) + tuple(trailing))
        self = cls.construct_fast(curve.knots, c, curve.degree, extrapolate, axis)
        self._curve_cache = (self.t, self.c, self.k, curve)
        return self

    @property
    def tck(self):
        """(t, c, k), as scipy's (read-only)."""
        return self.t, self.c, self.k

    def _base_interval(self):
        n = len(self.t) - self.k - 1
        return self.t[self.k], self.t[n]

    # --- evaluation ------------------------------------------------------------------------

    def __call__(self, x, nu=0, extrapolate=None):
        """The spline (or its nu-th derivative) at x of any shape: an array of shape x.shape + c.shape[1:].

        extrapolate: True (the end pieces continued), False (NaN outside [t[k], t[n]]) or 'periodic'
        (x wrapped into [t[k], t[n]]); None: self.extrapolate. Evaluated by the compiled batch kernels
        (points_at for nu = 0, derivatives_at otherwise). Differs from scipy: NaN/inf x gives NaN;
        nu < 0 raises ValueError.
        """
        nu = operator.index(nu)
        if nu < 0:
            raise ValueError(f"derivative order nu={nu} is negative")
        if extrapolate is None:
            extrapolate = self.extrapolate
        curve = self.curve
        x = _real_array(x, "x")
        shape = x.shape
        xs = np.ascontiguousarray(x.reshape(-1))
        out = np.empty((xs.size, curve.dimension))
        if extrapolate != "periodic" and (extrapolate or curve.domain == self._base_interval()):
            # One compiled call when every x is finite (and inside, without
            # extrapolation): the kernel checks them as it evaluates. (A k = 0
            # spline's compiled domain can be wider than [t[k], t[n]].)
            try:
                self._evaluate(curve, xs, nu, out, bool(extrapolate))
                return out.reshape(shape + self.c.shape[1:])
            except ValueError:
                pass  # NaN, infinite or outside x: scipy's NaN rows, below
        lower, upper = self._base_interval()
        if extrapolate == "periodic":
            xs = lower + (xs - lower) % (upper - lower)
            extrapolate = False
        outside = None
        finite = np.isfinite(xs)
        if not finite.all():
            outside = ~finite
        if not extrapolate:
            beyond = (xs < lower) | (xs > upper)
            outside = beyond if outside is None else (outside | beyond)
        if outside is not None and outside.any():
            xs = np.where(outside, lower, xs)
        else:
            outside = None
        self._evaluate(curve, xs, nu, out, True)
        if outside is not None:
            out[outside] = np.nan
        return out.reshape(shape + self.c.shape[1:])

    @staticmethod
    def _evaluate(curve, xs, nu, out, extrapolate):
        """C^(nu) at the (k,) array xs into out, by the compiled batch kernels."""
        if nu == 0:
            _c.points_at(curve, xs, out=out, extrapolate=extrapolate)
        else:
            _c.derivatives_at(curve, xs, nu, out=out, extrapolate=extrapolate)

    # --- calculus --------------------------------------------------------------------------

    def derivative(self, nu=1):
        """The nu-th derivative as a BSpline of degree k - nu on t[nu:-nu] (derivative_curve: The NURBS Book
        A3.3, as scipy's splder). ValueError for nu > k, as scipy. Differs from scipy: c is not zero-padded; at a
        knot of multiplicity k+1 (a jump) the piecewise derivative is returned, without that knot's extra copy."""
        nu = operator.index(nu)
        if nu < 0:
            return self.antiderivative(-nu)
        if nu > self.k:
            raise ValueError(f"Order of derivative (n = {nu}) must be <= order of spline (k = {self.k})")
        curve = _c.derivative_curve(self.curve, nu)
        return BSpline._from_curve(curve, self.c.shape[1:], self.extrapolate, self.axis)

    def antiderivative(self, nu=1):
        """The nu-th antiderivative as a BSpline of degree k + nu (antiderivative_curve: cumulative sums as
        scipy's splantider; the integral from t[0] of the B-spline sum). extrapolate='periodic' becomes False
        (as scipy). Differs from scipy: c is not zero-padded."""
        nu = operator.index(nu)
        if nu < 0:
            return self.derivative(-nu)
        curve = _c.antiderivative_curve(self.curve, nu)
        extrapolate = False if self.extrapolate == "periodic" else self.extrapolate
        return BSpline._from_curve(curve, self.c.shape[1:], extrapolate, self.axis)

    def integrate(self, a, b, extrapolate=None):
        """The integral from a to b, an array of shape c.shape[1:] (integral: A(b) - A(a) with the
        antiderivative A). extrapolate: True (the end pieces continued), False (zero outside [t[k], t[n]]),
        'periodic' (whole periods plus the rest); None: self.extrapolate. As scipy's."""
        if extrapolate is None:
            extrapolate = self.extrapolate
        curve = self.curve
        a, b = float(a), float(b)
        sign = 1.0
        if b < a:
            a, b = b, a
            sign = -1.0
        lower, upper = self._base_interval()
        if extrapolate == "periodic":
            period = upper - lower
            periods, left = divmod(b - a, period)
            total = np.zeros(curve.dimension)
            if periods > 0:
                total += periods * _c.integral(curve, lower, upper)
            a = lower + (a - lower) % period
            b = a + left
            if b <= upper:
                total += _c.integral(curve, a, b)
            else:
                total += _c.integral(curve, a, upper)
                total += _c.integral(curve, lower, lower + b - upper)
        elif not extrapolate:
            a, b = max(a, lower), min(b, upper)
            total = _c.integral(curve, a, b) if a < b else np.zeros(curve.dimension)
        else:
            total = _c.integral(curve, a, b)
        return (sign * total).reshape(self.c.shape[1:])

    def __repr__(self):
        return (f"casteljau.BSpline(k={self.k}, {len(self.t)} knots, c.shape={self.c.shape}, "
                f"extrapolate={self.extrapolate!r})")


# --- constructions ---------------------------------------------------------------------


def _parse_bc(bc_type, trailing):
    """scipy's bc_type as (left, right): each None or a list of (order, value array) pairs, or 'periodic'."""
    if bc_type is None or (isinstance(bc_type, str) and bc_type in ("not-a-knot", "periodic")):
        return ("periodic", "periodic") if bc_type == "periodic" else (None, None)
    if isinstance(bc_type, str):
        sides = (bc_type, bc_type)
    else:
        try:
            sides = tuple(bc_type)
        except TypeError as error:
            raise ValueError(f"Unknown boundary condition: {bc_type!r}") from error
        if len(sides) != 2:
            raise ValueError(f"bc_type must be a string or a pair (left, right), got {bc_type!r}")

    def side(spec):
        if spec is None or (isinstance(spec, str) and spec == "not-a-knot"):
            return None
        if isinstance(spec, str):
            if spec == "clamped":
                return [(1, np.zeros(trailing))]
            if spec == "natural":
                return [(2, np.zeros(trailing))]
            raise ValueError(f"Unknown boundary condition: {spec!r}")
        try:
            pairs = [(operator.index(order), _real_array(value, "bc_type value")) for order, value in spec]
        except (TypeError, ValueError) as error:
            raise ValueError("Derivatives, `bc_type`, should be specified as a pair of iterables of pairs of "
                             "(order, value).") from error
        return pairs

    return side(sides[0]), side(sides[1])


def _cubic_ends(left, right, trailing):
    """The C++ cubic end condition (name, start tangent, end tangent) for scipy's (left, right) derivative lists
    when both ends take the same one of interpolate_cubic's conditions, else None."""
    def kind(spec):
        if spec is None:
            return "not-a-knot", None
        if len(spec) == 1 and spec[0][0] == 1:
            return "clamped", np.broadcast_to(spec[0][1], trailing).reshape(-1)
        if len(spec) == 1 and spec[0][0] == 2 and not np.any(spec[0][1]):
            return "natural", None
        return "other", None

    (left_kind, left_value), (right_kind, right_value) = kind(left), kind(right)
    if left_kind == right_kind and left_kind != "other":
        return left_kind, left_value, right_value
    return None


def _end_derivatives(left, right, trailing):
    """scipy's (left, right) derivative lists as interpolate_on_knots' (at_end, order, value) tuples."""
    columns = int(np.prod(trailing)) if trailing else 1
    derivatives = []
    for at_end, spec in ((False, left), (True, right)):
        for order, value in spec or ():
            value = np.asarray(value, dtype=np.float64)
            if value.size != columns and value.size != 1:
                raise ValueError(f"bc_type value {value!r} does not have the shape {trailing} of y[0]")
            derivatives.append((at_end, order, np.broadcast_to(value.reshape(-1), (columns,)).copy()))
    return derivatives


def _scipy_knots(x, k, with_derivatives):
    """The knots scipy's make_interp_spline takes when t is None (scipy 1.10): x[0]*k, x, x[-1]*k with end
    derivatives (_augknt); without them, for k = 2 the midpoints of x without the first and last, for odd k the
    not-a-knot knots x[(k+1)//2 : -(k+1)//2] (de Boor XIII (12)), each with k+1 copies of x[0] and x[-1]; None for
    even k >= 4 (scipy refuses those)."""
    if with_derivatives:
        return np.r_[(x[0],) * k, x, (x[-1],) * k]
    if k == 2:
        middles = (x[1:] + x[:-1]) / 2.0
        return np.r_[(x[0],) * 3, middles[1:-1], (x[-1],) * 3]
    if k % 2 == 1:
        half = (k + 1) // 2
        return np.r_[(x[0],) * (k + 1), x[half:-half], (x[-1],) * (k + 1)]
    return None


def _knot_array(t, what="t"):
    t = _real_array(t, what)
    if t.ndim != 1:
        raise ValueError(f"{what} must be a 1-D array of knots, got shape {t.shape}")
    if not np.all(np.isfinite(t)):
        raise ValueError(f"{what} has NaN or infinite values")
    if t.size > 1 and np.any(t[1:] < t[:-1]):
        raise ValueError("Expect t to be a 1-D sorted array_like.")
    return np.ascontiguousarray(t)


def make_interp_spline(x, y, k=3, t=None, bc_type=None, axis=0):
    """The interpolating B-spline of degree k through (x[i], y[i]), like scipy.interpolate.make_interp_spline.

    On scipy's knots for every k (same knots, same coefficients to rounding): without end derivatives the
    not-a-knot knots x[0]*(k+1), x[(k+1)//2 : -(k+1)//2], x[-1]*(k+1) for odd k, the inner midpoints of x for
    k = 2, x[0], x, x[-1] for k = 1; with end derivatives x[0]*k, x, x[-1]*k (then the left and right lists must
    hold k-1 derivatives in all, as in scipy); or the knots t given. The cubic's own conditions (not-a-knot, both
    ends natural or both clamped, periodic) are built by interpolate_cubic (de Boor, A Practical Guide to Splines,
    ch. IV), everything else by interpolate_on_knots (collocation: The NURBS Book §9.2.1-9.2.2, de Boor ch. XIII).
    bc_type: None, 'not-a-knot', 'natural', 'clamped', 'periodic' (k = 3), or a pair (left, right), each None or a
    list of (order, value) pairs with orders 1..k. k = 0 is scipy's piecewise constant: knots x, x[-1],
    coefficients y, the value y[i] on [x[i], x[i+1]) and y[-1] from x[-1] on (and y[0] before x[0]).

    Differs from scipy: even k >= 4 without t and bc_type (scipy refuses) gives the spline on The NURBS Book's
    averaged knots (eq. 9.8, interpolate_bspline); a t whose domain [t[k], t[n]] is wider than [x[0], x[-1]]
    raises ValueError (casteljau needs x[0] = t[k] and x[-1] = t[n]; scipy accepts x inside); a singular system
    (knots against the Schoenberg-Whitney condition, impossible derivative orders) raises ValueError naming the
    cause (scipy: LinAlgError); a scalar derivative value is broadcast over the shape of y[0] (scipy wants that
    shape); 'periodic' only with k = 3 (scipy: any k); axis != 0; for k = 0, integrate and antiderivative are
    those of the step function (scipy 1.10's antiderivative drops to 0 at x[-1], its empty last span, so its
    integrate(x[0], x[-1]) is 0) and the antiderivative's last knot lies one step past x[-1].
    """
    k = operator.index(k)
    if k < 0:
        raise ValueError("Expect non-negative k.")
    y_array = _real_array(y, "y")
    _check_axis(axis, y_array.ndim)
    points, trailing = _as_points(y_array)
    x = _check_x(x, points.shape[0])
    left, right = _parse_bc(bc_type, trailing)
    periodic = left == "periodic"
    if k == 0 or (k == 1 and t is None):
        if left is not None or right is not None:
            raise ValueError(f"Too much info for k={k}: bc_type can only be None.")
        if t is not None:
            raise ValueError("Too much info for k=0: t and bc_type can only be None.")
        knots = np.r_[x, x[-1]] if k == 0 else np.r_[x[0], x, x[-1]]
        return BSpline(knots, y_array, k)
    if periodic:
        if t is not None:
            raise ValueError("For periodic case t is constructed automatically and can not be passed manually")
        if k != 3:
            raise ValueError(f"bc_type='periodic' is supported for k=3 only, got k={k}")
        if not np.allclose(points[0], points[-1], atol=1e-15):
            raise ValueError("First and last points does not match while periodic case expected")
        curve = _c.interpolate_cubic(points[:-1], x, "periodic")
        return BSpline._from_curve(curve, trailing, "periodic")
    derivatives = _end_derivatives(left, right, trailing)
    cubic = _cubic_ends(left, right, trailing) if k == 3 and t is None else None
    if cubic is not None:
        ends, start_tangent, end_tangent = cubic
        curve = _c.interpolate_cubic(points, x, ends, start_tangent=start_tangent, end_tangent=end_tangent)
    else:
        knots = _scipy_knots(x, k, bool(derivatives)) if t is None else _knot_array(t)
        if knots is None:
            curve = _c.interpolate_bspline(points, x, k)
        else:
            expected = knots.size - k - 1 - x.size
            if t is None and len(derivatives) != expected:
                left_count = len(left or ())
                raise ValueError(f"The number of derivatives at boundaries does not match: expected {expected}, "
                                 f"got {left_count}+{len(derivatives) - left_count}")
            curve = _c.interpolate_on_knots(points, x, k, knots, derivatives)
    return BSpline._from_curve(curve, trailing, True)


def make_lsq_spline(x, y, t, k=3, w=None, axis=0):
    """The least-squares B-spline of degree k on the knots t, like scipy.interpolate.make_lsq_spline: minimizes
    sum (w[i] (S(x[i]) - y[i]))^2 (fit_least_squares_on_knots with free ends and weights w**2: The NURBS Book
    §9.4.1 and §9.4.4, de Boor, A Practical Guide to Splines, ch. XIV). Any t whose domain [t[k], t[n]] holds every
    x and that satisfies the Schoenberg-Whitney condition; w None (all 1) or one weight >= 0 per point (a zero
    weight leaves its point out).

    Differs from scipy: k >= 1 (k = 0 raises ValueError); knots and data against the Schoenberg-Whitney condition
    raise ValueError naming the basis function left without data (scipy may return a spline from a singular
    system or raise LinAlgError); negative or NaN weights raise ValueError.
    """
    k = operator.index(k)
    if k < 1:
        raise ValueError(f"k={k} is not supported: casteljau's least squares needs k >= 1")
    y_array = _real_array(y, "y")
    _check_axis(axis, y_array.ndim)
    points, trailing = _as_points(y_array)
    x = _check_x(x, points.shape[0])
    t = _knot_array(t)
    weights = None
    if w is not None:
        w = _real_array(w, "w")
        if w.shape != x.shape:
            raise ValueError(f"Shapes of x {x.shape} and w {w.shape} are incompatible")
        if not np.all(np.isfinite(w)) or np.any(w < 0):
            raise ValueError("w must hold finite weights >= 0")
        weights = np.ascontiguousarray(w * w)
    fit = _c.fit_least_squares_on_knots(points, x, k, t, weights, "free")
    return BSpline._from_curve(fit.curve, trailing, True)


def make_smoothing_spline(x, y, w=None, lam=None):
    """The cubic smoothing spline minimizing sum (y_i - g(x_i))^2 + lam * integral g''^2, like
    scipy.interpolate.make_smoothing_spline (fit_smoothing with degree 3, a knot at every x, free ends).

    w: None (all 1) or one positive weight per point multiplying its squared residual (not squared), as
    scipy's. Differs from scipy: lam=None chooses lam by casteljau's GCV search (a grid then Brent's method,
    Craven & Wahba 1979), which may pick a slightly different lam than scipy's (with weights, casteljau's GCV
    weighs the residuals as the fit does, scipy 1.10's leaves them unweighted); y may also be (n, d) (one lam
    for all columns).
    """
    y_array = _real_array(y, "y")
    points, trailing = _as_points(y_array)
    x = _check_x(x, points.shape[0])
    weights = None
    if w is not None:
        weights = np.ascontiguousarray(w, dtype=float)
        if weights.shape != (points.shape[0],) or not np.all(weights > 0):
            raise ValueError("Invalid vector of weights")  # scipy's words
    if lam is not None:
        lam = float(lam)
    fit = _c.fit_smoothing(points, x, degree=3, control_point_count=0, smoothing=lam, ends="free", weights=weights)
    return BSpline._from_curve(fit.curve, trailing, True)


class CubicSpline:
    """The C2 cubic spline through (x[i], y[i]), like scipy.interpolate.CubicSpline (interpolate_cubic).

    bc_type: 'not-a-knot' (default), 'natural', 'clamped', 'periodic', or a pair of ends each 'not-a-knot',
    'natural', 'clamped', (1, value) or (2, value), the two ends of any kinds (as scipy's). The same kind at
    both ends (second derivatives 0) is built by interpolate_cubic; other pairs by interpolate_on_knots on the
    knots scipy's tridiagonal system implies (every x, less x[1] / x[-2] at a not-a-knot end). With 2 points
    and not-a-knot ends it is the line, with 3 the parabola (as scipy's).

    Differs from scipy: the spline is a BSpline (``self.bspline``), not a PPoly: no ``c`` of power
    coefficients, no ``solve``/``roots``; derivative() and antiderivative() return BSplines; only axis=0.
    """

    def __init__(self, x, y, axis=0, bc_type="not-a-knot", extrapolate=None):
        y_array = _real_array(y, "y")
        self.axis = _check_axis(axis, y_array.ndim)
        points, trailing = _as_points(y_array)
        x = _check_x(x, points.shape[0])
        if x.size < 2:
            raise ValueError("`x` must contain at least 2 elements.")
        left, right = self._ends(bc_type, trailing)
        if left == "periodic":
            if not np.allclose(points[0], points[-1], rtol=1e-15, atol=0):
                raise ValueError("The first and last `y` point along axis 0 must be identical (within machine "
                                 "precision) when bc_type='periodic'.")
            curve = _c.interpolate_cubic(points[:-1], x, "periodic")
        else:
            cubic = _cubic_ends(left, right, trailing)
            if cubic is None:
                curve = self._mixed(x, points, left, right, trailing)
            elif cubic[0] == "not-a-knot" and x.size < 4:
                curve = _c.interpolate_bspline(points, x, x.size - 1)
            else:
                ends, start, end = cubic
                curve = _c.interpolate_cubic(points, x, ends, start_tangent=start, end_tangent=end)
        if extrapolate is None:
            extrapolate = "periodic" if left == "periodic" else True
        self.x = x
        self.extrapolate = extrapolate
        self.bc_type = bc_type
        self.bspline = BSpline._from_curve(curve, trailing, extrapolate)

    @staticmethod
    def _mixed(x, points, left, right, trailing):
        """Ends of different kinds (or second derivatives other than 0): the cubic on knots at every x, less x[1]
        (x[-2]) at a not-a-knot start (end), through interpolate_on_knots with the derivative ends (with 2 points a
        not-a-knot end takes the chord's slope, as scipy's)."""
        if x.size == 2:  # as scipy: a not-a-knot end of two points takes the chord's slope
            slope = [(1, (points[1] - points[0]) / (x[1] - x[0]))]
            left, right = left or slope, right or slope
        interior = x[1:-1]
        if left is None:
            interior = interior[1:]
        if right is None:
            interior = interior[:-1]
        knots = np.r_[(x[0],) * 4, interior, (x[-1],) * 4]
        return _c.interpolate_on_knots(points, x, 3, knots, _end_derivatives(left, right, trailing))

    @staticmethod
    def _ends(bc_type, trailing):
        if isinstance(bc_type, str):
            if bc_type == "periodic":
                return "periodic", "periodic"
            bc_type = (bc_type, bc_type)
        try:
            sides = tuple(bc_type)
        except TypeError as error:
            raise ValueError(f"Unknown boundary condition: {bc_type!r}") from error
        if len(sides) != 2:
            raise ValueError("`bc_type` must contain 2 elements to specify start and end conditions.")
        if "periodic" in [s for s in sides if isinstance(s, str)]:
            raise ValueError("'periodic' `bc_type` is defined for both curve ends and cannot be used with other "
                             "boundary conditions.")
        parsed = []
        for spec in sides:
            if isinstance(spec, str):
                parsed.append(_parse_bc((spec, spec), trailing)[0])
            else:
                try:
                    order, value = spec
                    order = operator.index(order)
                except (TypeError, ValueError) as error:
                    raise ValueError(f"bc_type entry {spec!r} must be a string or a pair (order, value)") from error
                if order not in (1, 2):
                    raise ValueError("The specified derivative order must be 1 or 2.")
                value = _real_array(value, "bc_type value")
                if value.size != (int(np.prod(trailing)) if trailing else 1):
                    raise ValueError(f"bc_type value must have shape {trailing}, got {value.shape}")
                parsed.append([(order, value.reshape(trailing))])
        return parsed[0], parsed[1]

    def __call__(self, x, nu=0, extrapolate=None):
        """The spline or its nu-th derivative at x (any shape): BSpline.__call__ of self.bspline."""
        return self.bspline(x, nu, self.extrapolate if extrapolate is None else extrapolate)

    def derivative(self, nu=1):
        """The nu-th derivative as a BSpline (scipy returns a PPoly)."""
        return self.bspline.derivative(nu)

    def antiderivative(self, nu=1):
        """The nu-th antiderivative as a BSpline whose antiderivatives of every order are zero at x[0], as
        scipy's PPoly.antiderivative (scipy returns a PPoly). Each integration is antiderivative_curve with its
        control points shifted by the value at x[0] (the basis sums to one on the domain)."""
        nu = operator.index(nu)
        if nu < 0:
            return self.derivative(-nu)
        spline = self.bspline
        start = np.array([self.x[0]])
        for _ in range(nu):
            spline = spline.antiderivative(1)
            shifted = spline.c - spline(start, extrapolate=True)[0]
            spline = BSpline(spline.t, shifted, spline.k, spline.extrapolate)
        return spline

    def integrate(self, a, b, extrapolate=None):
        """The integral from a to b (BSpline.integrate; extrapolate None: self.extrapolate). As scipy's PPoly,
        extrapolate=False gives NaN when a or b lies outside [x[0], x[-1]]."""
        if extrapolate is None:
            extrapolate = self.extrapolate
        if extrapolate is not True and extrapolate != "periodic" and not extrapolate:
            if min(a, b) < self.x[0] or max(a, b) > self.x[-1]:
                return np.full(self.bspline.c.shape[1:], np.nan)
        return self.bspline.integrate(a, b, extrapolate)

    def __repr__(self):
        return f"casteljau.CubicSpline({self.x.size} points, bc_type={self.bc_type!r})"
