#pragma once
// CurveView: a non-owning reference to a curve of any kind, the curve
// counterpart of SurfaceView. It meets the Curve concept (curves/curve.hpp),
// so the algorithms written once take a CurveView and run on every kind; a
// BezierCurve, PiecewiseBezierCurve or BSplineCurve converts to it
// implicitly, as a vector does to a span. Like a span it does not own what it
// shows: the curve must outlive the view. It is the one place below io/ that
// dispatches on the curve kind (Model reaches curves through curve_view()).

#include <cstddef>
#include <span>
#include <variant>
#include <vector>

#include "casteljau/bezier/bezier_curve.hpp"
#include "casteljau/bezier/piecewise_bezier.hpp"
#include "casteljau/bspline/bezier_pieces.hpp"
#include "casteljau/bspline/bspline_curve.hpp"
#include "casteljau/core/interval.hpp"
#include "casteljau/core/point_array.hpp"
#include "casteljau/core/precondition.hpp"
#include "casteljau/core/vec.hpp"

namespace casteljau {

/// A view of a Bézier (polynomial or rational), piecewise Bézier or
/// B-spline/NURBS curve.
class CurveView {
 public:
  /// Views of the curve kinds (implicit, like span from a vector).
  CurveView(const BezierCurve& curve) noexcept : curve_(&curve) {}           // NOLINT: implicit by design
  CurveView(const PiecewiseBezierCurve& curve) noexcept : curve_(&curve) {}  // NOLINT
  CurveView(const BSplineCurve& curve) noexcept : curve_(&curve) {}          // NOLINT
  /// Never of a temporary: the view would outlive it. Name the curve first
  /// (`auto c = *BezierCurve::make(...); arc_length(c, ...)`); docs/cpp.md,
  /// "Lifetimes", says why even the safe call on a temporary is refused.
  CurveView(const BezierCurve&&) = delete;  // a view of a temporary dangles: name it first
  CurveView(const PiecewiseBezierCurve&&) = delete;  // a view of a temporary dangles: name it first
  CurveView(const BSplineCurve&&) = delete;  // a view of a temporary dangles: name it first

  /// The parameter domain ([0,1] Bézier, [0,m] piecewise, [t_p, t_{n+1}] B-spline).
  Interval domain() const noexcept;
  /// d.
  int dimension() const noexcept;
  /// The degree (the highest of the pieces for a piecewise curve).
  int degree() const noexcept;
  /// True for a rational curve (some rational piece).
  bool is_rational() const noexcept;

  /// Calls f(const Kind&) with the curve itself: the static dispatch an
  /// algorithm uses when it wants the kind's own kernel in a loop.
  template <class F>
  decltype(auto) visit(F&& f) const {
    return std::visit([&f](const auto* curve) -> decltype(auto) { return f(*curve); }, curve_);
  }

 private:
  /// The curve kinds: adding one is adding it here (and a constructor).
  std::variant<const BezierCurve*, const PiecewiseBezierCurve*, const BSplineCurve*> curve_;
};

/// The kind's point_at, derivative_at, derivatives_up_to (same values, bit for bit).
Point point_at(CurveView curve, double u);
/// The kind's point_at into `out` (dimension() values), without allocating.
void point_at(CurveView curve, double u, std::span<double> out);
Point derivative_at(CurveView curve, double u, int order);
std::vector<Point> derivatives_up_to(CurveView curve, double u, int max_order);
/// The kind's batch kernels (same contracts: out has us.size() * d values).
void points_at(CurveView curve, std::span<const double> us, std::span<double> out);
/// P(u) and its derivative of order k as a fixed-size Vec<D>: the scalar call
/// without the heap allocation of a Point, for code that knows the dimension
/// (requires dimension() == D, checked in every build: it sizes the result).
/// The point is the scalar kernel into the Vec (point_at above), the
/// derivative the batch kernel on one parameter: the same values as
/// point_at and derivative_at.
template <int D>
Vec<D> point_at(CurveView curve, double u);
template <int D>
Vec<D> derivative_at(CurveView curve, double u, int order);
std::size_t points_at_within(CurveView curve, std::span<const double> us, Interval allowed, std::span<double> out);
void derivatives_at(CurveView curve, std::span<const double> us, int order, std::span<double> out);
void points_and_derivatives_at(CurveView curve, std::span<const double> us, std::span<double> points,
                               std::span<double> derivatives);
/// The kind's breakpoints and Bézier pieces.
std::vector<double> breakpoints(CurveView curve);
BezierPieces to_bezier_pieces(CurveView curve);
/// The largest |coordinate| of the control points (scale_of of all of them):
/// the scale that relative tolerances on the curve are measured against.
double scale_of(CurveView curve);
/// The diagonal of the box of all control points: the curve's size, which
/// relative accuracies (arc length, the CLI's defaults) are fractions of.
/// The curve lies in the box (convex hull property, weights > 0).
double size_of(CurveView curve);

template <int D>
Vec<D> point_at(CurveView curve, double u) {
  detail::require(curve.dimension() == D, "point_at<D>", "D must be the curve's dimension()");
  Vec<D> point;
  point_at(curve, u, std::span<double>(point.coordinates));
  return point;
}

template <int D>
Vec<D> derivative_at(CurveView curve, double u, int order) {
  detail::require(curve.dimension() == D, "derivative_at<D>", "D must be the curve's dimension()");
  Vec<D> derivative;
  derivatives_at(curve, std::span<const double>(&u, 1), order, std::span<double>(derivative.coordinates));
  return derivative;
}

}  // namespace casteljau
