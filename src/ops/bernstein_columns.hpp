#pragma once
// Internal to src/ops: a piece's coordinates as scalar polynomials in
// Bernstein form, and their derivatives, for the questions that reduce to
// roots of one polynomial (bounds.cpp, inflections.cpp, curvature_extrema.cpp).
#include <cassert>
#include <vector>

#include "casteljau/core/point_array.hpp"

namespace casteljau::detail {

/// Coordinate j of the rows (control points, or homogeneous ones) as Bernstein coefficients.
inline std::vector<double> column(const PointArray& rows, int j) {
  std::vector<double> values(rows.size());
  for (std::size_t i = 0; i < rows.size(); ++i) values[i] = rows[i][j];
  return values;
}

/// The derivative's Bernstein coefficients n (b_{i+1} - b_i) (Farin §4.3);
/// the zero constant for a constant.
inline std::vector<double> derivative(const std::vector<double>& b) {
  if (b.size() < 2) return {0.0};
  const double n = static_cast<double>(b.size() - 1);
  std::vector<double> d(b.size() - 1);
  for (std::size_t i = 0; i + 1 < b.size(); ++i) d[i] = n * (b[i + 1] - b[i]);
  return d;
}

/// a - b, two polynomials of the same degree in Bernstein form.
inline std::vector<double> difference(const std::vector<double>& a, const std::vector<double>& b) {
  assert(a.size() == b.size());
  std::vector<double> c(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) c[i] = a[i] - b[i];
  return c;
}

/// a + b, two polynomials of the same degree in Bernstein form.
inline std::vector<double> sum(const std::vector<double>& a, const std::vector<double>& b) {
  assert(a.size() == b.size());
  std::vector<double> c(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) c[i] = a[i] + b[i];
  return c;
}

}  // namespace casteljau::detail
