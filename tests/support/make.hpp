#pragma once
// Test values made from literal data, and a result's error as text. The data
// of a test is known to be valid: .value() aborts with the library's message
// when it is not (a mistake in the test, not a failure of the library).

#include <string>
#include <utility>
#include <vector>

#include "casteljau/bezier/bezier_curve.hpp"
#include "casteljau/core/expected.hpp"
#include "casteljau/core/point_array.hpp"

namespace casteljau::test {

/// The points of dimension `dimension` whose coordinates follow point after point.
inline PointArray points_of(int dimension, std::vector<double> coordinates) {
  return PointArray::make(dimension, std::move(coordinates)).value();
}

/// The Bézier curve of the control points given as rows {x, y[, z...]}, rational with weights.
inline BezierCurve bezier(const std::vector<std::vector<double>>& rows, std::vector<double> weights = {}) {
  return BezierCurve::make(PointArray::make(rows).value(), std::move(weights)).value();
}

/// The Bézier curve of dimension `dimension` whose coordinates follow point after point.
inline BezierCurve bezier_of(int dimension, std::vector<double> coordinates, std::vector<double> weights = {}) {
  return BezierCurve::make(points_of(dimension, std::move(coordinates)), std::move(weights)).value();
}

/// The error's message, or "(accepted)" when there is none (what a failed
/// EXPECT_THAT(message_of(r), HasSubstr(...)) then shows).
template <class T>
std::string message_of(const Expected<T>& result) {
  return result ? std::string("(accepted)") : result.error().message;
}
inline std::string message_of(const Status& status) {
  return status ? std::string("(accepted)") : status.error().message;
}

}  // namespace casteljau::test
