// The tight bounding box (bounds.hpp): end points and coordinate extrema per Bézier piece.
#include "casteljau/ops/bounds.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "casteljau/bezier/bernstein_roots.hpp"
#include "casteljau/bezier/evaluate.hpp"
#include "casteljau/bspline/bezier_pieces.hpp"
#include "casteljau/ops/tolerance.hpp"
#include "bernstein_columns.hpp"

namespace casteljau {
namespace {

using detail::column;
using detail::derivative;

/// The parameters in (0, 1) where coordinate j of the piece has a zero derivative.
std::vector<double> stationary_parameters(const BezierCurve& piece, int j) {
  std::vector<double> numerator;
  if (!piece.is_rational()) {
    numerator = derivative(column(piece.control_points(), j));
  } else {
    const PointArray h = homogeneous_points(piece);
    const int d = piece.dimension();
    const std::vector<double> a = column(h, j), w = column(h, d);
    const std::vector<double> left = bernstein_product(derivative(a), w), right = bernstein_product(a, derivative(w));
    numerator.resize(left.size());
    for (std::size_t i = 0; i < left.size(); ++i) numerator[i] = left[i] - right[i];
  }
  std::vector<double> ts;
  for (const BernsteinRoot& root : bernstein_roots(numerator, 1e-12))
    if (root.t > 0.0 && root.t < 1.0) ts.push_back(root.t);
  return ts;
}

}  // namespace

Box bounding_box(CurveView curve) {
  const int d = curve.dimension();
  Box box{Point(d, INFINITY), Point(d, -INFINITY)};
  auto add = [&](const Point& p) {
    for (int j = 0; j < d; ++j) box.lower[j] = std::min(box.lower[j], p[j]), box.upper[j] = std::max(box.upper[j], p[j]);
  };
  for (const BezierCurve& piece : to_bezier_pieces(curve).pieces) {
    add(point_at(piece, 0.0));
    add(point_at(piece, 1.0));
    if (piece.degree() < 2) continue;  // a segment or a point: its ends bound it
    for (int j = 0; j < d; ++j)
      for (const double t : stationary_parameters(piece, j)) add(point_at(piece, t));
  }
  return box;
}

Box pruning_box(CurveView curve, double margin) {
  Box box = bounding_box(curve);
  double extent = 0.0, reach = 0.0;
  for (std::size_t j = 0; j < box.lower.size(); ++j) {
    extent += (box.upper[j] - box.lower[j]) * (box.upper[j] - box.lower[j]);
    reach = std::max({reach, std::abs(box.lower[j]), std::abs(box.upper[j])});
  }
  const double widened = margin + tolerances::kBoxRoundingMargin * (std::sqrt(extent) + reach);
  for (std::size_t j = 0; j < box.lower.size(); ++j) {
    box.lower[j] -= widened;
    box.upper[j] += widened;
  }
  return box;
}

}  // namespace casteljau
