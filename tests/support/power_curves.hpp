#pragma once
// Test curves given in the power basis, converted exactly to Bézier form:
// a coordinate sum_j a_j t^j on [0, 1] has the Bernstein coefficients
// b_i = sum_{j <= i} C(i, j) / C(n, j) a_j (Farin §5.9). Closed forms of
// curvature, inflections and cusps are written on such curves.
#include <algorithm>
#include <vector>

#include "casteljau/bezier/bernstein.hpp"
#include "casteljau/bezier/bezier_curve.hpp"

namespace casteljau::test {

/// The curve whose coordinate k is sum_j power[k][j] t^j, t in [0, 1], of
/// degree the longest list minus one (shorter lists are zero-padded).
inline BezierCurve power_curve(const std::vector<std::vector<double>>& power) {
  std::size_t size = 1;
  for (const auto& coordinate : power) size = std::max(size, coordinate.size());
  const int n = static_cast<int>(size) - 1;
  std::vector<std::vector<double>> rows(size, std::vector<double>(power.size(), 0.0));
  for (std::size_t k = 0; k < power.size(); ++k)
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= i && j < static_cast<int>(power[k].size()); ++j)
        rows[i][k] += binomial(i, j) / binomial(n, j) * power[k][j];
  return BezierCurve::make(PointArray::make(rows).value()).value();
}

/// The graph (t, y(t)) on [0, 1] of y = sum_j a_j t^j.
inline BezierCurve polynomial_graph(const std::vector<double>& power) { return power_curve({{0.0, 1.0}, power}); }

}  // namespace casteljau::test
