#pragma once
// Exact reference arithmetic for B-spline tests: de Boor's algorithm and
// Boehm's knot insertion done in GMP rationals (mpq_class) on the exact
// values of the doubles of a curve. Every operation of both algorithms is a
// rational function of the knots and control points, so the results are
// exact; a double result is then compared with test::error_of.
//
// Independent of the library's algorithms: written from the textbook
// formulas (The NURBS Book eq. 5.11 for de Boor, eq. 5.15 for Boehm), with
// a linear span search, for small curves only.

#include <gmpxx.h>

#include <cassert>
#include <stdexcept>
#include <vector>

#include "casteljau/bspline/bspline_curve.hpp"

namespace casteljau::test {

/// A B-spline in exact rationals: homogeneous rows (w P, w) of width d+1.
struct ExactBSpline {
  int degree = 0;
  int dimension = 0;
  std::vector<mpq_class> knots;
  std::vector<std::vector<mpq_class>> rows;  // rows[i] = (w_i P_i, w_i)

  static ExactBSpline of(const BSplineCurve& curve) {
    ExactBSpline e;
    e.degree = curve.degree();
    e.dimension = curve.dimension();
    for (double t : curve.knots()) e.knots.emplace_back(t);
    for (std::size_t i = 0; i < curve.control_points().size(); ++i) {
      const mpq_class w(curve.is_rational() ? curve.weights()[i] : 1.0);
      std::vector<mpq_class> row;
      for (double c : curve.control_points()[i]) row.push_back(w * mpq_class(c));
      row.push_back(w);
      e.rows.push_back(std::move(row));
    }
    return e;
  }

  int last_index() const { return static_cast<int>(rows.size()) - 1; }

  /// The span k with t_k <= u < t_{k+1}, t_k < t_{k+1}, p <= k <= n; the
  /// last non-empty one at the end of the domain.
  int span_of(const mpq_class& u) const {
    const int p = degree, n = last_index();
    int span = p;
    for (int k = p; k <= n; ++k)
      if (knots[k] < knots[k + 1] && knots[k] <= u) span = k;
    return span;
  }

  /// C(u) exactly (Cartesian), by de Boor's algorithm on the homogeneous rows.
  std::vector<mpq_class> point_at(const mpq_class& u) const {
    const int p = degree, k = span_of(u);
    std::vector<std::vector<mpq_class>> d;
    for (int j = 0; j <= p; ++j) d.push_back(rows[k - p + j]);
    for (int r = 1; r <= p; ++r)
      for (int j = p; j >= r; --j) {
        const int i = k - p + j;
        const mpq_class alpha = (u - knots[i]) / (knots[i + p + 1 - r] - knots[i]);
        for (std::size_t c = 0; c < d[j].size(); ++c) d[j][c] = (1 - alpha) * d[j - 1][c] + alpha * d[j][c];
      }
    std::vector<mpq_class> point;
    for (int c = 0; c < dimension; ++c) point.push_back(d[p][c] / d[p][dimension]);
    return point;
  }

  /// The derivative curve of a polynomial B-spline (The NURBS Book eq. 3.8):
  /// degree p-1 on the knots without their first and last, control points
  /// Q_i = p (P_{i+1} - P_i) / (t_{i+p+1} - t_{i+1}), i = 0..n-1 (Q_i = 0
  /// when that knot span is empty: its basis function is zero). Its
  /// point_at is C'(u) exactly.
  ExactBSpline derivative() const {
    for (const auto& row : rows)
      if (degree < 1 || row.back() != 1) throw std::logic_error("ExactBSpline::derivative: polynomial, degree >= 1");
    ExactBSpline out;
    out.degree = degree - 1;
    out.dimension = dimension;
    out.knots.assign(knots.begin() + 1, knots.end() - 1);
    for (int i = 0; i < last_index(); ++i) {
      const mpq_class width = knots[i + degree + 1] - knots[i + 1];
      const mpq_class factor = width == 0 ? mpq_class(0) : mpq_class(degree) / width;
      std::vector<mpq_class> row;
      for (int c = 0; c < dimension; ++c) row.push_back(factor * (rows[i + 1][c] - rows[i][c]));
      row.push_back(1);
      out.rows.push_back(std::move(row));
    }
    return out;
  }

  /// Boehm's insertion of u once (u inside the domain, multiplicity < p+1):
  /// Q_i = a_i P_i + (1 - a_i) P_{i-1}, a_i = (u - t_i)/(t_{i+p} - t_i)
  /// for k-p+1 <= i <= k, Q_i = P_i below, P_{i-1} above (eq. 5.15).
  ExactBSpline inserted(const mpq_class& u) const {
    const int p = degree, n = last_index(), k = span_of(u);
    ExactBSpline out = *this;
    out.rows.clear();
    for (int i = 0; i <= n + 1; ++i) {
      if (i <= k - p) {
        out.rows.push_back(rows[i]);
      } else if (i > k) {
        out.rows.push_back(rows[i - 1]);
      } else {
        const mpq_class a = (u - knots[i]) / (knots[i + p] - knots[i]);
        std::vector<mpq_class> row(rows[i].size());
        for (std::size_t c = 0; c < row.size(); ++c) row[c] = a * rows[i][c] + (1 - a) * rows[i - 1][c];
        out.rows.push_back(std::move(row));
      }
    }
    out.knots.insert(out.knots.begin() + k + 1, u);
    return out;
  }
};

}  // namespace casteljau::test
