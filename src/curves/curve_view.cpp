// CurveView: each operation forwards to the kind's own function.
#include "casteljau/curves/curve_view.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "casteljau/curves/curve.hpp"

namespace casteljau {

static_assert(Curve<CurveView>);

Interval CurveView::domain() const noexcept {
  return visit([](const auto& c) { return c.domain(); });
}
int CurveView::dimension() const noexcept {
  return visit([](const auto& c) { return c.dimension(); });
}
int CurveView::degree() const noexcept {
  return visit([](const auto& c) { return c.degree(); });
}
bool CurveView::is_rational() const noexcept {
  return visit([](const auto& c) { return c.is_rational(); });
}

Point point_at(CurveView curve, double u) {
  return curve.visit([u](const auto& c) { return point_at(c, u); });
}
void point_at(CurveView curve, double u, std::span<double> out) {
  curve.visit([u, out](const auto& c) { point_at(c, u, out); });
}
Point derivative_at(CurveView curve, double u, int order) {
  return curve.visit([=](const auto& c) { return derivative_at(c, u, order); });
}
std::vector<Point> derivatives_up_to(CurveView curve, double u, int max_order) {
  return curve.visit([=](const auto& c) { return derivatives_up_to(c, u, max_order); });
}
void points_at(CurveView curve, std::span<const double> us, std::span<double> out) {
  curve.visit([=](const auto& c) { points_at(c, us, out); });
}
std::size_t points_at_within(CurveView curve, std::span<const double> us, Interval allowed, std::span<double> out) {
  return curve.visit([=](const auto& c) { return points_at_within(c, us, allowed, out); });
}
void derivatives_at(CurveView curve, std::span<const double> us, int order, std::span<double> out) {
  curve.visit([=](const auto& c) { derivatives_at(c, us, order, out); });
}
void points_and_derivatives_at(CurveView curve, std::span<const double> us, std::span<double> points,
                               std::span<double> derivatives) {
  curve.visit([=](const auto& c) { points_and_derivatives_at(c, us, points, derivatives); });
}
std::vector<double> breakpoints(CurveView curve) {
  return curve.visit([](const auto& c) { return breakpoints(c); });
}
BezierPieces to_bezier_pieces(CurveView curve) {
  return curve.visit([](const auto& c) { return to_bezier_pieces(c); });
}

namespace {

/// f(points) for each control polygon of the curve: one for a Bézier curve or
/// a B-spline, one per piece of a piecewise curve.
template <class F>
void for_each_control_polygon(CurveView curve, F&& f) {
  struct Visit {
    F& f;
    void operator()(const BezierCurve& c) const { f(c.control_points()); }
    void operator()(const BSplineCurve& c) const { f(c.control_points()); }
    void operator()(const PiecewiseBezierCurve& c) const {
      for (const BezierCurve& piece : c.pieces()) f(piece.control_points());
    }
  };
  curve.visit(Visit{f});
}

}  // namespace

double scale_of(CurveView curve) {
  double scale = 0.0;
  for_each_control_polygon(curve, [&](const PointArray& points) { scale = std::max(scale, scale_of(points)); });
  return scale;
}

double size_of(CurveView curve) {
  const int d = curve.dimension();
  std::vector<double> lower(d, INFINITY), upper(d, -INFINITY);
  for_each_control_polygon(curve, [&](const PointArray& points) {
    for (std::size_t i = 0; i < points.size(); ++i)
      for (int j = 0; j < d; ++j) lower[j] = std::min(lower[j], points[i][j]), upper[j] = std::max(upper[j], points[i][j]);
  });
  double sum = 0.0;
  for (int j = 0; j < d; ++j) sum += (upper[j] - lower[j]) * (upper[j] - lower[j]);
  return std::sqrt(sum);
}

}  // namespace casteljau
