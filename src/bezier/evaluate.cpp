#include "casteljau/bezier/evaluate.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

#include "casteljau/bezier/bernstein.hpp"
#include "casteljau/core/tolerance.hpp"
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

/// Euclidean norm of a span, overflow-safe.
double span_norm(std::span<const double> v) {
  double largest = 0.0;
  for (double c : v) largest = std::max(largest, std::abs(c));
  if (largest == 0.0 || !std::isfinite(largest)) return largest;
  double sum = 0.0;
  for (double c : v) sum += (c / largest) * (c / largest);
  return largest * std::sqrt(sum);
}

}  // namespace

Point point_at(const BezierCurve& curve, double t) {
  const int d = curve.dimension(), n = curve.degree();
  const int width = curve.is_rational() ? d + 1 : d;
  detail::Workspace<> work;
  auto rows = work.take(static_cast<std::size_t>(n + 1) * width);
  load_rows(curve, rows, width);
  detail::de_casteljau_in_place(rows.data(), n, width, t);
  Point point(rows.begin(), rows.begin() + d);
  if (curve.is_rational())
    for (double& c : point) c /= rows[d];
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

std::vector<Point> derivatives_at(const BezierCurve& curve, double t, int max_order) {
  assert(max_order >= 0);
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
  // Rational: homogeneous derivatives A^(k) (first d) and w^(k) (last), then
  // C^(k) = (A^(k) - sum_{j=1..k} C(k,j) w^(j) C^(k-j)) / w  (NURBS Book A4.2).
  std::vector<Point> homogeneous;
  for (int k = 0; k <= max_order; ++k) {
    Point h(d + 1);
    polynomial_derivative(curve, t, k, h, d + 1);
    homogeneous.push_back(std::move(h));
  }
  const double w = homogeneous[0][d];
  for (int k = 0; k <= max_order; ++k) {
    Point c(homogeneous[k].begin(), homogeneous[k].begin() + d);
    for (int j = 1; j <= k; ++j) {
      const double f = binomial(k, j) * homogeneous[j][d];
      for (int i = 0; i < d; ++i) c[i] -= f * result[k - j][i];
    }
    for (double& v : c) v /= w;
    result.push_back(std::move(c));
  }
  return result;
}

Point derivative_at(const BezierCurve& curve, double t, int order) {
  assert(order >= 0);
  if (!curve.is_rational()) {
    Point p(curve.dimension());
    polynomial_derivative(curve, t, order, p, curve.dimension());
    return p;
  }
  return std::move(derivatives_at(curve, t, order).back());
}

Expected<BezierCurve> hodograph(const BezierCurve& curve, int order) {
  if (curve.is_rational()) return Error{"the hodograph of a rational Bézier curve is not a Bézier curve of that form; use derivative_at"};
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

Point unit_tangent_at(const BezierCurve& curve, double t) {
  const int n = curve.degree(), d = curve.dimension();
  const double scale = scale_of(curve.control_points());
  for (int k = 1; k <= std::max(n, 1) && scale > 0.0; ++k) {
    Point v = derivative_at(curve, t, k);
    const double length = span_norm(v);
    if (length > tolerances::kVanishingDerivative * scale) {
      // C'(t + h) ~ h^(k-1)/(k-1)! C^(k)(t): from the right the sign is +, from the
      // left (-1)^(k-1). We take the limit from inside the domain.
      const double sign = (t >= 1.0 && k % 2 == 0) ? -1.0 : 1.0;
      for (double& c : v) c *= sign / length;
      return v;
    }
    if (curve.is_rational() && k >= n) break;
  }
  return Point(d, 0.0);
}

double curvature_at(const BezierCurve& curve, double t) {
  const auto ders = derivatives_at(curve, t, 2);
  const Point& a = ders[1];
  const Point& b = ders[2];
  // |a ^ b|^2 = sum_{i<j} (a_i b_j - a_j b_i)^2: no cancellation, any dimension.
  double wedge = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = i + 1; j < a.size(); ++j) {
      const double m = a[i] * b[j] - a[j] * b[i];
      wedge += m * m;
    }
  const double speed = span_norm(a);
  if (speed == 0.0) return span_norm(b) == 0.0 ? 0.0 : INFINITY;
  return std::sqrt(wedge) / (speed * speed * speed);
}

double signed_curvature_at(const BezierCurve& curve, double t) {
  assert(curve.dimension() == 2);
  const auto ders = derivatives_at(curve, t, 2);
  const double speed = span_norm(ders[1]);
  const double cross = ders[1][0] * ders[2][1] - ders[1][1] * ders[2][0];
  if (speed == 0.0) return cross == 0.0 ? 0.0 : std::copysign(INFINITY, cross);
  return cross / (speed * speed * speed);
}

Point unit_normal_at(const BezierCurve& curve, double t) {
  const int d = curve.dimension();
  Point normal(d, 0.0);
  if (d < 2) return normal;
  const Point tangent = unit_tangent_at(curve, t);
  const Point second = derivative_at(curve, t, 2);
  const double along = [&] {
    double s = 0.0;
    for (int i = 0; i < d; ++i) s += second[i] * tangent[i];
    return s;
  }();
  for (int i = 0; i < d; ++i) normal[i] = second[i] - along * tangent[i];
  const double length = span_norm(normal);
  const double scale = scale_of(curve.control_points());
  if (length > tolerances::kVanishingDerivative * scale && scale > 0.0) {
    for (double& c : normal) c /= length;
    return normal;
  }
  std::fill(normal.begin(), normal.end(), 0.0);
  if (d == 2) {
    normal[0] = -tangent[1];
    normal[1] = tangent[0];
  }
  return normal;
}

}  // namespace casteljau
