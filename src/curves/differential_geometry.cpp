// Differential geometry from the derivatives at one parameter.
#include "casteljau/curves/differential_geometry.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <span>

#include "casteljau/core/precondition.hpp"
#include "casteljau/core/tolerance.hpp"

namespace casteljau {
namespace {

/// Euclidean norm of a span, overflow-safe.
double norm(std::span<const double> v) {
  double largest = 0.0;
  for (double c : v) largest = std::max(largest, std::abs(c));
  if (largest == 0.0 || !std::isfinite(largest)) return largest;
  double sum = 0.0;
  for (double c : v) sum += (c / largest) * (c / largest);
  return largest * std::sqrt(sum);
}

double dot(std::span<const double> a, std::span<const double> b) {
  double s = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) s += a[i] * b[i];
  return s;
}

/// |a ^ b| = sqrt(sum_{i<j} (a_i b_j - a_j b_i)^2): no cancellation, any dimension.
double wedge_norm(std::span<const double> a, std::span<const double> b) {
  double wedge = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = i + 1; j < a.size(); ++j) {
      const double m = a[i] * b[j] - a[j] * b[i];
      wedge += m * m;
    }
  return std::sqrt(wedge);
}

Point cross(std::span<const double> a, std::span<const double> b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

double curvature_of(const Point& first, const Point& second) {
  const double speed = norm(first);
  if (speed == 0.0) return norm(second) == 0.0 ? 0.0 : INFINITY;
  return wedge_norm(first, second) / (speed * speed * speed);
}

/// The normal from the unit tangent and C'' (see unit_normal_at).
Point normal_of(CurveView curve, const Point& tangent, const Point& second) {
  const int d = curve.dimension();
  Point normal(d, 0.0);
  if (d < 2) return normal;
  const double along = dot(second, tangent);
  for (int i = 0; i < d; ++i) normal[i] = second[i] - along * tangent[i];
  const double length = norm(normal);
  const double scale = scale_of(curve);
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

double torsion_of(const Point& first, const Point& second, const Point& third) {
  const Point b = cross(first, second);
  const double area = norm(b);
  if (area == 0.0) return 0.0;
  return dot(b, third) / (area * area);
}

}  // namespace

Point unit_tangent_at(CurveView curve, double u) {
  const int n = curve.degree(), d = curve.dimension();
  const double scale = scale_of(curve);
  const bool at_end = u >= curve.domain().upper;
  for (int k = 1; k <= std::max(n, 1) && scale > 0.0; ++k) {
    Point v = derivative_at(curve, u, k);
    const double length = norm(v);
    if (length > tolerances::kVanishingDerivative * scale) {
      // C'(u + h) ~ h^(k-1)/(k-1)! C^(k)(u): from the right the sign is +, from
      // the left (-1)^(k-1). The limit is taken from inside the domain.
      const double sign = (at_end && k % 2 == 0) ? -1.0 : 1.0;
      for (double& c : v) c *= sign / length;
      return v;
    }
    if (curve.is_rational() && k >= n) break;
  }
  return Point(d, 0.0);
}

Point unit_normal_at(CurveView curve, double u) {
  return normal_of(curve, unit_tangent_at(curve, u), derivative_at(curve, u, 2));
}

Point binormal_at(CurveView curve, double u) {
  detail::require(curve.dimension() == 3, "binormal_at", "the curve must lie in 3D (dimension() == 3)");
  const Point normal = unit_normal_at(curve, u);
  if (norm(normal) == 0.0) return Point(3, 0.0);
  return cross(unit_tangent_at(curve, u), normal);
}

double curvature_at(CurveView curve, double u) {
  const auto ders = derivatives_up_to(curve, u, 2);
  return curvature_of(ders[1], ders[2]);
}

double signed_curvature_at(CurveView curve, double u) {
  detail::require(curve.dimension() == 2, "signed_curvature_at", "the curve must be planar (dimension() == 2)");
  const auto ders = derivatives_up_to(curve, u, 2);
  const double speed = norm(ders[1]);
  const double cross = ders[1][0] * ders[2][1] - ders[1][1] * ders[2][0];
  if (speed == 0.0) return cross == 0.0 ? 0.0 : std::copysign(INFINITY, cross);
  return cross / (speed * speed * speed);
}

double torsion_at(CurveView curve, double u) {
  detail::require(curve.dimension() == 3, "torsion_at", "the curve must lie in 3D (dimension() == 3)");
  const auto ders = derivatives_up_to(curve, u, 3);
  return torsion_of(ders[1], ders[2], ders[3]);
}

FrenetFrame frenet_frame_at(CurveView curve, double u) {
  const auto ders = derivatives_up_to(curve, u, 3);
  FrenetFrame frame;
  frame.tangent = unit_tangent_at(curve, u);
  frame.normal = normal_of(curve, frame.tangent, ders[2]);
  frame.curvature = curvature_of(ders[1], ders[2]);
  frame.binormal = Point(curve.dimension() == 3 ? 3 : 0, 0.0);
  if (curve.dimension() == 3) {
    if (norm(frame.normal) > 0.0) frame.binormal = cross(frame.tangent, frame.normal);
    frame.torsion = torsion_of(ders[1], ders[2], ders[3]);
  }
  return frame;
}

}  // namespace casteljau
