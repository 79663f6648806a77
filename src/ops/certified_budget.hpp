#pragma once
// The distance a certified approximation of a Bézier piece (flatten's
// segments, approximate_by_cubics' cubics) may use: the tolerance minus what
// rounding can add to the points and to the bound that certifies them.

#include <algorithm>
#include <cmath>
#include <string>
#include <string_view>

#include "casteljau/bezier/bezier_curve.hpp"
#include "casteljau/core/expected.hpp"
#include "casteljau/core/point_array.hpp"
#include "casteljau/core/tolerance.hpp"
#include "casteljau/ops/tolerance.hpp"
#include "../core/number_text.hpp"

namespace casteljau::ops_detail {

/// tolerance minus tolerances::kFlattenRoundingAllowance x scale x
/// max(1, n/4) x (max w / min w); an error for a tolerance that is not finite
/// and > 0, or below kFlattenSmallestToleranceFactor times that allowance
/// (what double precision can certify). `what` names the operation in errors
/// ("the flattening tolerance ...").
inline Expected<double> certified_budget(const BezierCurve& curve, Tolerance tolerance, std::string_view what) {
  const std::string name(what);
  if (!(std::isfinite(tolerance.distance) && tolerance.distance > 0.0))
    return Error{"the " + name + " tolerance must be a finite distance > 0, got " + detail::number_text(tolerance.distance)};
  double weight_ratio = 1.0;
  if (curve.is_rational()) {
    const auto [lightest, heaviest] = std::minmax_element(curve.weights().begin(), curve.weights().end());
    weight_ratio = *heaviest / *lightest;
  }
  const double allowance = tolerances::kFlattenRoundingAllowance * scale_of(curve.control_points()) *
                           std::max(1.0, curve.degree() / 4.0) * weight_ratio;
  if (tolerance.distance < tolerances::kFlattenSmallestToleranceFactor * allowance)
    return Error{"the " + name + " tolerance " + detail::number_text(tolerance.distance) +
                 " is below what double precision can certify for this curve (" +
                 detail::number_text(tolerances::kFlattenSmallestToleranceFactor * allowance) + ")"};
  return tolerance.distance - allowance;
}

}  // namespace casteljau::ops_detail
