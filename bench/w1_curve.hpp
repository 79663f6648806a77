#pragma once
// W1's curve (shared/docs/performance.md), shared by the workloads that use
// it (W1/W2 evaluation, W7 closest point, W9 arc length): a cubic B-spline in
// 3D with 1000 control points drawn uniformly in [0,100)^3 from a fixed
// splitmix64 stream, on the clamped uniform knots of [0,1].
#include <cstddef>
#include <vector>

#include "casteljau/bspline/bspline_curve.hpp"
#include "casteljau/bspline/knot_vector.hpp"
#include "support/splitmix.hpp"

namespace casteljau::bench {

inline constexpr int kW1Degree = 3;
inline constexpr std::size_t kW1ControlPoints = 1000;
inline constexpr double kW1Scale = 100.0;

/// The control points, row-major (kW1ControlPoints x 3).
inline std::vector<double> w1_control_points() {
  test::SplitMix random{20261122u};
  std::vector<double> control(kW1ControlPoints * 3);
  for (double& x : control) x = kW1Scale * random.unit();
  return control;
}

/// The curve itself.
inline BSplineCurve w1_curve() {
  return BSplineCurve::from_trusted(kW1Degree, clamped_uniform_knots(kW1Degree, kW1ControlPoints),
                                    PointArray::from_trusted(3, w1_control_points()));
}

}  // namespace casteljau::bench
