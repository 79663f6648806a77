#pragma once
// Internal to src/ops: a piece's coordinates as scalar polynomials in
// Bernstein form, and their derivatives, for the questions that reduce to
// roots of one polynomial (bounds.cpp, inflections.cpp, curvature_extrema.cpp,
// intersection.cpp).
#include <cassert>
#include <vector>

#include "casteljau/bezier/bernstein_roots.hpp"
#include "casteljau/bezier/bezier_curve.hpp"
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

/// The velocity of a piece, coordinate by coordinate: C' for a polynomial
/// piece; for a rational one the numerator W X' - W' X of C' = (W X' - W' X)
/// / W^2 (X the homogeneous coordinates w x, W the weight), which points the
/// same way.
inline std::vector<std::vector<double>> velocity_numerators(const BezierCurve& piece) {
  const int d = piece.dimension();
  std::vector<std::vector<double>> velocity;
  if (!piece.is_rational()) {
    for (int j = 0; j < d; ++j) velocity.push_back(derivative(column(piece.control_points(), j)));
    return velocity;
  }
  const PointArray h = homogeneous_points(piece);
  const std::vector<double> w = column(h, d), dw = derivative(w);
  for (int j = 0; j < d; ++j) {
    const std::vector<double> x = column(h, j);
    velocity.push_back(difference(bernstein_product(w, derivative(x)), bernstein_product(dw, x)));
  }
  return velocity;
}

}  // namespace casteljau::detail
