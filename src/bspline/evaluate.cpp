// Points and derivatives of B-spline and NURBS curves (scalar paths).
#include "casteljau/bspline/evaluate.hpp"

#include <algorithm>
#include <cassert>
#include <cstddef>

#include "casteljau/bezier/bernstein.hpp"
#include "casteljau/bspline/basis.hpp"
#include "casteljau/core/precondition.hpp"
#include "../bezier/de_casteljau.hpp"
#include "../core/workspace.hpp"
#include "de_boor.hpp"

namespace casteljau {
namespace {

/// The width of the rows de Boor runs on: d, or d + 1 (homogeneous) for NURBS.
int row_width(const BSplineCurve& curve) { return curve.dimension() + (curve.is_rational() ? 1 : 0); }

/// Copies the p+1 control rows of `span` (homogeneous for NURBS) into rows.
void load_span_rows(const BSplineCurve& curve, int span, double* rows) {
  const int p = curve.degree();
  const int d = curve.dimension();
  const int width = row_width(curve);
  for (int j = 0; j <= p; ++j) {
    const std::size_t i = static_cast<std::size_t>(span - p + j);
    const auto point = curve.control_points()[i];
    double* row = rows + static_cast<std::ptrdiff_t>(j) * width;
    const double w = curve.is_rational() ? curve.weights()[i] : 1.0;
    for (int k = 0; k < d; ++k) row[k] = curve.is_rational() ? w * point[static_cast<std::size_t>(k)] : point[static_cast<std::size_t>(k)];
    if (curve.is_rational()) row[d] = w;
  }
}

/// One round r of de Boor's algorithm on rows[0..p] of the span (in place,
/// from the top down): row j becomes (1-a) row j-1 + a row j for j = p..r,
/// with the arithmetic of de_boor.hpp shared with the batch kernels.
void de_boor_round(std::span<const double> knots, int p, int span, double u, int r, double* rows, int width) {
  detail::de_boor_rounds(knots, p, span, u, r, r, rows, width);
}

/// Writes the projection of a homogeneous row (or the row itself) to out.
void project(const double* row, int d, bool rational, double* out) {
  if (rational) {
    for (int k = 0; k < d; ++k) out[k] = row[k] / row[d];
  } else {
    for (int k = 0; k < d; ++k) out[k] = row[k];
  }
}

void point_into(const BSplineCurve& curve, double u, double* out) {
  const int p = curve.degree();
  const int width = row_width(curve);
  const int span = find_span(curve.knots(), p, u);
  detail::Workspace<2048> workspace;
  double* rows = workspace.take(static_cast<std::size_t>(p + 1) * static_cast<std::size_t>(width)).data();
  load_span_rows(curve, span, rows);
  for (int r = 1; r <= p; ++r) de_boor_round(curve.knots(), p, span, u, r, rows, width);
  project(rows + static_cast<std::ptrdiff_t>(p) * width, curve.dimension(), curve.is_rational(), out);
}

/// Rows k = 0..max_order of the derivatives of the (homogeneous, for NURBS)
/// curve at u, each `width` wide (The NURBS Book A3.2).
void homogeneous_derivatives(const BSplineCurve& curve, double u, int max_order, std::span<double> out) {
  const int p = curve.degree();
  const int width = row_width(curve);
  const std::size_t columns = static_cast<std::size_t>(p) + 1;
  const int orders = std::min(max_order, p);
  const int span = find_span(curve.knots(), p, u);
  std::vector<double> basis((static_cast<std::size_t>(orders) + 1) * columns);
  basis_function_derivatives(curve.knots(), p, span, u, orders, basis);
  std::vector<double> rows(columns * static_cast<std::size_t>(width));
  load_span_rows(curve, span, rows.data());
  std::fill(out.begin(), out.end(), 0.0);
  for (int k = 0; k <= orders; ++k) {
    double* target = out.data() + static_cast<std::ptrdiff_t>(k) * width;
    for (std::size_t j = 0; j < columns; ++j) {
      const double n = basis[static_cast<std::size_t>(k) * columns + j];
      for (int c = 0; c < width; ++c) target[c] += n * rows[j * static_cast<std::size_t>(width) + static_cast<std::size_t>(c)];
    }
  }
}

}  // namespace

Point point_at(const BSplineCurve& curve, double u) {
  Point point(static_cast<std::size_t>(curve.dimension()));
  point_into(curve, u, point.data());
  return point;
}

void point_at(const BSplineCurve& curve, double u, std::span<double> out) {
  detail::require(out.size() == static_cast<std::size_t>(curve.dimension()), "point_at",
                  "out must hold dimension() values");
  point_into(curve, u, out.data());
}

Point point_at_basis_sum(const BSplineCurve& curve, double u) {
  const int p = curve.degree();
  const int d = curve.dimension();
  const int span = find_span(curve.knots(), p, u);
  std::vector<double> basis(static_cast<std::size_t>(p) + 1);
  basis_functions(curve.knots(), p, span, u, basis);
  Point numerator(static_cast<std::size_t>(d), 0.0);
  double denominator = 0.0;
  for (int j = 0; j <= p; ++j) {
    const std::size_t i = static_cast<std::size_t>(span - p + j);
    const double w = curve.is_rational() ? curve.weights()[i] : 1.0;
    const double nw = basis[static_cast<std::size_t>(j)] * w;
    for (int k = 0; k < d; ++k) numerator[static_cast<std::size_t>(k)] += nw * curve.control_points()[i][static_cast<std::size_t>(k)];
    denominator += nw;
  }
  if (curve.is_rational()) {
    for (double& c : numerator) c /= denominator;
  }
  return numerator;
}

std::vector<Point> derivatives_up_to(const BSplineCurve& curve, double u, int max_order) {
  detail::require(max_order >= 0, "derivatives_up_to", "max_order must be >= 0");
  const int d = curve.dimension();
  const int width = row_width(curve);
  std::vector<double> rows((static_cast<std::size_t>(max_order) + 1) * static_cast<std::size_t>(width));
  homogeneous_derivatives(curve, u, max_order, rows);
  std::vector<Point> result(static_cast<std::size_t>(max_order) + 1, Point(static_cast<std::size_t>(d), 0.0));
  // The point itself by de Boor (exact at clamped ends) rather than the basis
  // sum, and the first derivative from the same triangle: the values of the
  // batch functions (points_at.cpp), bit for bit.
  if (max_order == 0) {
    point_into(curve, u, result[0].data());
  } else {
    const int p = curve.degree();
    const int span = find_span(curve.knots(), p, u);
    detail::Workspace<2048> workspace;
    double* triangle = workspace.take(static_cast<std::size_t>(p + 1) * static_cast<std::size_t>(width)).data();
    load_span_rows(curve, span, triangle);
    detail::de_boor_point_and_derivative(curve.knots(), p, span, u, triangle, d, curve.is_rational(),
                                         result[0].data(), result[1].data());
  }
  if (!curve.is_rational()) {
    for (int k = 2; k <= max_order; ++k) {
      for (int c = 0; c < d; ++c) result[static_cast<std::size_t>(k)][static_cast<std::size_t>(c)] = rows[static_cast<std::size_t>(k * width + c)];
    }
    return result;
  }
  // A4.2: C^(k) = (A^(k) - sum_{j=1..k} C(k,j) w^(j) C^(k-j)) / w.
  const double w = rows[static_cast<std::size_t>(d)];
  for (int k = 2; k <= max_order; ++k) {
    Point& target = result[static_cast<std::size_t>(k)];
    for (int c = 0; c < d; ++c) target[static_cast<std::size_t>(c)] = rows[static_cast<std::size_t>(k * width + c)];
    for (int j = 1; j <= k; ++j) {
      const double factor = binomial(k, j) * rows[static_cast<std::size_t>(j * width + d)];
      const Point& lower = result[static_cast<std::size_t>(k - j)];
      for (int c = 0; c < d; ++c) target[static_cast<std::size_t>(c)] -= factor * lower[static_cast<std::size_t>(c)];
    }
    for (double& c : target) c /= w;
  }
  return result;
}

Point derivative_at(const BSplineCurve& curve, double u, int order) {
  detail::require(order >= 0, "derivative_at", "the derivative order must be >= 0");
  if (order == 0) return point_at(curve, u);
  if (!curve.is_rational() && order > curve.degree()) return Point(static_cast<std::size_t>(curve.dimension()), 0.0);
  return derivatives_up_to(curve, u, order)[static_cast<std::size_t>(order)];
}

// The batch functions (points_at, points_and_derivatives_at, derivatives_at
// over a span of parameters) are in points_at.cpp.

DeBoorNet de_boor_net(const BSplineCurve& curve, double u) {
  const int p = curve.degree();
  const int d = curve.dimension();
  const int width = row_width(curve);
  DeBoorNet net;
  net.parameter = u;
  net.span = find_span(curve.knots(), p, u);
  std::vector<double> rows(static_cast<std::size_t>(p + 1) * static_cast<std::size_t>(width));
  load_span_rows(curve, net.span, rows.data());
  const auto store_level = [&](int r) {
    PointArray level = PointArray::zeros(d, static_cast<std::size_t>(p + 1 - r));
    for (int j = r; j <= p; ++j) {
      project(rows.data() + static_cast<std::ptrdiff_t>(j) * width, d, curve.is_rational(),
              level[static_cast<std::size_t>(j - r)].data());
    }
    net.levels.push_back(std::move(level));
  };
  store_level(0);
  for (int r = 1; r <= p; ++r) {
    de_boor_round(curve.knots(), p, net.span, u, r, rows.data(), width);
    store_level(r);
  }
  return net;
}

std::vector<double> breakpoints(const BSplineCurve& curve) {
  const Interval domain = curve.domain();
  std::vector<double> result;
  for (double knot : curve.knots())
    if (domain.contains(knot) && (result.empty() || knot != result.back())) result.push_back(knot);
  return result;
}

}  // namespace casteljau
