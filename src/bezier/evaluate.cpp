#include "casteljau/bezier/evaluate.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

#include "casteljau/bezier/bernstein.hpp"
#include "casteljau/core/precondition.hpp"
#include "../core/workspace.hpp"
#include "de_casteljau.hpp"

namespace casteljau {
namespace {

/// Copies the control points (homogeneous if rational) into rows of `width`.
void load_rows(const BezierCurve& curve, std::span<double> rows, int width) {
  const auto& p = curve.control_points();
  const int d = curve.dimension();
  for (std::size_t i = 0; i < p.size(); ++i) {
    double* row = rows.data() + i * width;
    if (curve.is_rational()) {
      const double w = curve.weights()[i];
      for (int j = 0; j < d; ++j) row[j] = w * p[i][j];
      row[d] = w;
    } else {
      for (int j = 0; j < d; ++j) row[j] = p[i][j];
    }
  }
}

/// n!/(n-k)! as a double.
double falling_factorial(int n, int k) {
  double f = 1.0;
  for (int i = 0; i < k; ++i) f *= n - i;
  return f;
}

/// Derivative of order k of the (homogeneous, if rational) polynomial curve:
/// k forward differences, de Casteljau on the rest, times n!/(n-k)!.
void polynomial_derivative(const BezierCurve& curve, double t, int k, std::span<double> out, int width) {
  const int n = curve.degree();
  if (k > n) {
    std::fill(out.begin(), out.begin() + width, 0.0);
    return;
  }
  detail::Workspace<> work;
  auto rows = work.take(static_cast<std::size_t>(n + 1) * width);
  load_rows(curve, rows, width);
  for (int r = 1; r <= k; ++r)
    for (int i = 0; i <= n - r; ++i)
      for (int j = 0; j < width; ++j) rows[i * width + j] = rows[(i + 1) * width + j] - rows[i * width + j];
  detail::de_casteljau_in_place(rows.data(), n - k, width, t);
  const double f = falling_factorial(n, k);
  for (int j = 0; j < width; ++j) out[j] = f * rows[j];
}

}  // namespace

void point_at(const BezierCurve& curve, double t, std::span<double> out) {
  const int d = curve.dimension(), n = curve.degree();
  detail::require(out.size() == static_cast<std::size_t>(d), "point_at", "out must hold dimension() values");
  const int width = curve.is_rational() ? d + 1 : d;
  detail::Workspace<> work;
  auto rows = work.take(static_cast<std::size_t>(n + 1) * width);
  load_rows(curve, rows, width);
  detail::de_casteljau_in_place(rows.data(), n, width, t);
  std::copy(rows.begin(), rows.begin() + d, out.begin());
  if (curve.is_rational())
    for (double& c : out) c /= rows[d];
}

Point point_at(const BezierCurve& curve, double t) {
  Point point(static_cast<std::size_t>(curve.dimension()));
  point_at(curve, t, point);
  return point;
}

Point point_at_bernstein_sum(const BezierCurve& curve, double t) {
  const int d = curve.dimension(), n = curve.degree();
  Point sum(d, 0.0);
  double weight_sum = 0.0;
  for (int k = 0; k <= n; ++k) {
    // The seed's bernstein(n, k, t) = binom(n, k) * t**k * (1-t)**(n-k).
    double b = binomial(n, k) * std::pow(t, k) * std::pow(1.0 - t, n - k);
    if (curve.is_rational()) b *= curve.weights()[k];
    for (int j = 0; j < d; ++j) sum[j] += b * curve.control_points()[k][j];
    weight_sum += b;
  }
  if (curve.is_rational())
    for (double& c : sum) c /= weight_sum;
  return sum;
}

namespace {

/// C^(0..k)(t) of a rational curve into result ((k+1) rows of d), with
/// `homogeneous` ((k+1) rows of d+1) as scratch: the homogeneous derivatives
/// A^(j), w^(j), then C^(j) = (A^(j) - sum_{i=1..j} C(j,i) w^(i) C^(j-i)) / w
/// (The NURBS Book A4.2).
void rational_derivatives(const BezierCurve& curve, double t, int max_order, std::span<double> homogeneous,
                          std::span<double> result) {
  const int d = curve.dimension(), width = d + 1;
  for (int k = 0; k <= max_order; ++k) polynomial_derivative(curve, t, k, homogeneous.subspan(k * width), width);
  const double w = homogeneous[d];
  for (int k = 0; k <= max_order; ++k) {
    double* c = result.data() + k * d;
    for (int i = 0; i < d; ++i) c[i] = homogeneous[k * width + i];
    for (int j = 1; j <= k; ++j) {
      const double f = binomial(k, j) * homogeneous[j * width + d];
      for (int i = 0; i < d; ++i) c[i] -= f * result[(k - j) * d + i];
    }
    for (int i = 0; i < d; ++i) c[i] /= w;
  }
}

/// The k-th derivative at t into out (d values), no heap up to kMaxStackDegree.
void derivative_into(const BezierCurve& curve, double t, int order, std::span<double> out) {
  const int d = curve.dimension();
  if (!curve.is_rational()) {
    polynomial_derivative(curve, t, order, out, d);
    return;
  }
  detail::Workspace<> work;
  const std::span<double> rows = work.take(static_cast<std::size_t>(order + 1) * (2 * d + 1));
  const std::span<double> result = rows.subspan(static_cast<std::size_t>(order + 1) * (d + 1));
  rational_derivatives(curve, t, order, rows, result);
  std::copy(result.begin() + order * d, result.begin() + (order + 1) * d, out.begin());
}

}  // namespace

std::vector<Point> derivatives_up_to(const BezierCurve& curve, double t, int max_order) {
  detail::require(max_order >= 0, "derivatives_up_to", "max_order must be >= 0");
  const int d = curve.dimension();
  std::vector<Point> result;
  result.reserve(max_order + 1);
  if (!curve.is_rational()) {
    for (int k = 0; k <= max_order; ++k) {
      Point p(d);
      polynomial_derivative(curve, t, k, p, d);
      result.push_back(std::move(p));
    }
    return result;
  }
  std::vector<double> homogeneous(static_cast<std::size_t>(max_order + 1) * (d + 1));
  std::vector<double> flat(static_cast<std::size_t>(max_order + 1) * d);
  rational_derivatives(curve, t, max_order, homogeneous, flat);
  for (int k = 0; k <= max_order; ++k) result.emplace_back(flat.begin() + k * d, flat.begin() + (k + 1) * d);
  return result;
}

Point derivative_at(const BezierCurve& curve, double t, int order) {
  detail::require(order >= 0, "derivative_at", "the derivative order must be >= 0");
  if (!curve.is_rational()) {
    Point p(curve.dimension());
    polynomial_derivative(curve, t, order, p, curve.dimension());
    return p;
  }
  Point p(curve.dimension());
  derivative_into(curve, t, order, p);
  return p;
}

void derivatives_at(const BezierCurve& curve, std::span<const double> ts, int order, std::span<double> out) {
  const std::size_t d = static_cast<std::size_t>(curve.dimension());
  detail::require(order >= 0, "derivatives_at", "the derivative order must be >= 0");
  detail::require(out.size() == ts.size() * d, "derivatives_at", "out must hold ts.size() * dimension() values");
  if (order == 0) {
    points_at(curve, ts, out);
    return;
  }
  if (!curve.is_rational()) {
    // The k-th derivative curve once, then the batch kernel on it.
    points_at(derivative_curve(curve, order).value(), ts, out);
    return;
  }
  for (std::size_t i = 0; i < ts.size(); ++i) derivative_into(curve, ts[i], order, out.subspan(i * d, d));
}

void points_and_derivatives_at(const BezierCurve& curve, std::span<const double> ts, std::span<double> points,
                               std::span<double> derivatives) {
  points_at(curve, ts, points);
  derivatives_at(curve, ts, 1, derivatives);
}

std::vector<double> breakpoints(const BezierCurve&) { return {0.0, 1.0}; }

Expected<BezierCurve> derivative_curve(const BezierCurve& curve, int order) {
  if (curve.is_rational())
    return Error{"the derivative of a rational Bézier curve is not a Bézier curve of that form; use derivative_at"};
  if (order < 0) return Error{"derivative order " + std::to_string(order) + " is negative"};
  const int n = curve.degree(), d = curve.dimension();
  if (order > n) return BezierCurve::from_trusted(PointArray::zeros(d, 1));
  std::vector<double> rows(curve.control_points().coordinates().begin(), curve.control_points().coordinates().end());
  for (int r = 1; r <= order; ++r)
    for (int i = 0; i <= n - r; ++i)
      for (int j = 0; j < d; ++j) rows[i * d + j] = rows[(i + 1) * d + j] - rows[i * d + j];
  rows.resize(static_cast<std::size_t>(n - order + 1) * d);
  const double f = falling_factorial(n, order);
  for (double& c : rows) c *= f;
  return BezierCurve::from_trusted(PointArray::from_trusted(d, std::move(rows)));
}

}  // namespace casteljau
