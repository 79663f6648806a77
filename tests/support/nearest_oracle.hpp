#pragma once
// A brute-force reference for the nearest point of a curve, independent of
// ops/closest_point: shared by tests/ops/closest_point_test.cpp and the W7
// benchmark (bench/w7_closest_point.cpp).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "casteljau/curves/curve_view.hpp"

namespace casteljau::test {

/// The brute-force oracle: the curve sampled densely (every piece alike, its
/// ends and breakpoints included), the exact nearest sample by exhaustive
/// search, then golden-section search on the two sample intervals beside it.
class NearestOracle {
 public:
  NearestOracle(CurveView curve, int samples_per_piece) : curve_(curve), d_(curve.dimension()) {
    const std::vector<double> knots = breakpoints(curve);
    for (std::size_t k = 0; k + 1 < knots.size(); ++k)
      for (int i = 0; i < samples_per_piece; ++i)
        us_.push_back(knots[k] + (knots[k + 1] - knots[k]) * i / samples_per_piece);
    us_.push_back(knots.back());
    points_.resize(us_.size() * static_cast<std::size_t>(d_));
    points_at(curve, us_, points_);
    for (std::size_t start = 0; start < us_.size(); start += kChunk) {
      std::vector<double> box(2 * d_, 0.0);
      for (int j = 0; j < d_; ++j) box[j] = INFINITY, box[d_ + j] = -INFINITY;
      for (std::size_t i = start; i < std::min(us_.size(), start + kChunk); ++i)
        for (int j = 0; j < d_; ++j) {
          box[j] = std::min(box[j], points_[i * d_ + j]);
          box[d_ + j] = std::max(box[d_ + j], points_[i * d_ + j]);
        }
      boxes_.insert(boxes_.end(), box.begin(), box.end());
    }
  }

  /// The distance from q (d coordinates) to the curve, from above: the nearest sample, refined.
  double distance(const double* q) const {
    double best = INFINITY;
    std::size_t at = 0;
    for (std::size_t chunk = 0; chunk * kChunk < us_.size(); ++chunk) {
      double bound = 0.0;
      for (int j = 0; j < d_; ++j) {
        const double lower = boxes_[chunk * 2 * d_ + j], upper = boxes_[chunk * 2 * d_ + d_ + j];
        const double gap = q[j] < lower ? lower - q[j] : (q[j] > upper ? q[j] - upper : 0.0);
        bound += gap * gap;
      }
      if (bound > best) continue;
      for (std::size_t i = chunk * kChunk; i < std::min(us_.size(), (chunk + 1) * kChunk); ++i) {
        double g = 0.0;
        for (int j = 0; j < d_; ++j) g += (points_[i * d_ + j] - q[j]) * (points_[i * d_ + j] - q[j]);
        if (g < best) best = g, at = i;
      }
    }
    double result = std::sqrt(best);
    if (at > 0) result = std::min(result, golden(us_[at - 1], us_[at], q));
    if (at + 1 < us_.size()) result = std::min(result, golden(us_[at], us_[at + 1], q));
    return result;
  }

 private:
  static constexpr std::size_t kChunk = 32;

  double at(double u, const double* q) const {
    const Point p = point_at(curve_, u);
    double g = 0.0;
    for (int j = 0; j < d_; ++j) g += (p[j] - q[j]) * (p[j] - q[j]);
    return std::sqrt(g);
  }
  double golden(double a, double b, const double* q) const {
    const double ratio = (std::sqrt(5.0) - 1) / 2;
    double x1 = b - ratio * (b - a), x2 = a + ratio * (b - a);
    double f1 = at(x1, q), f2 = at(x2, q);
    for (int i = 0; i < 60; ++i) {
      if (f1 < f2) b = x2, x2 = x1, f2 = f1, x1 = b - ratio * (b - a), f1 = at(x1, q);
      else a = x1, x1 = x2, f1 = f2, x2 = a + ratio * (b - a), f2 = at(x2, q);
    }
    return std::min({f1, f2, at(a, q), at(b, q)});
  }

  CurveView curve_;
  int d_;
  std::vector<double> us_, points_, boxes_;
};

}  // namespace casteljau::test
