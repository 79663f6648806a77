#include "segment_distance.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace casteljau::detail {

double distance_to_segment(std::span<const double> p, std::span<const double> a, std::span<const double> b) {
  double ab2 = 0.0, apab = 0.0;
  for (std::size_t j = 0; j < p.size(); ++j) {
    ab2 += (b[j] - a[j]) * (b[j] - a[j]);
    apab += (p[j] - a[j]) * (b[j] - a[j]);
  }
  const double u = ab2 > 0.0 ? std::clamp(apab / ab2, 0.0, 1.0) : 0.0;
  double sum = 0.0;
  for (std::size_t j = 0; j < p.size(); ++j) {
    const double e = p[j] - (a[j] + u * (b[j] - a[j]));
    sum += e * e;
  }
  return std::sqrt(sum);
}

double distance_between_segments(std::span<const double> p0, std::span<const double> p1, std::span<const double> q0,
                                  std::span<const double> q1) {
  const std::size_t n = p0.size();
  double scale = 0.0;
  for (std::size_t j = 0; j < n; ++j)
    scale = std::max({scale, std::abs(p1[j] - p0[j]), std::abs(q0[j] - p0[j]), std::abs(q1[j] - p0[j])});
  if (!std::isfinite(scale)) return NAN;
  if (scale == 0.0) return 0.0;
  // d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0, all divided by the scale.
  double a = 0.0, e = 0.0, f = 0.0, c = 0.0, b = 0.0;
  for (std::size_t j = 0; j < n; ++j) {
    const double d1 = (p1[j] - p0[j]) / scale, d2 = (q1[j] - q0[j]) / scale, r = (p0[j] - q0[j]) / scale;
    a += d1 * d1, e += d2 * d2, f += d2 * r, c += d1 * r, b += d1 * d2;
  }
  double s = 0.0, t = 0.0;
  if (a > 0.0 && e > 0.0) {
    const double denominator = a * e - b * b;  // >= 0; zero for parallel segments
    s = denominator > 0.0 ? std::clamp((b * f - c * e) / denominator, 0.0, 1.0) : 0.0;
    t = (b * s + f) / e;
    if (t < 0.0) t = 0.0, s = std::clamp(-c / a, 0.0, 1.0);
    else if (t > 1.0) t = 1.0, s = std::clamp((b - c) / a, 0.0, 1.0);
  } else if (a > 0.0) {
    s = std::clamp(-c / a, 0.0, 1.0);
  } else if (e > 0.0) {
    t = std::clamp(f / e, 0.0, 1.0);
  }
  double sum = 0.0;
  for (std::size_t j = 0; j < n; ++j) {
    const double d1 = (p1[j] - p0[j]) / scale, d2 = (q1[j] - q0[j]) / scale, r = (p0[j] - q0[j]) / scale;
    const double gap = r + s * d1 - t * d2;
    sum += gap * gap;
  }
  return std::sqrt(sum) * scale;
}

}  // namespace casteljau::detail
