// The tight bounding box (bounds.hpp): end points and coordinate extrema per Bézier piece.
#include "casteljau/ops/bounds.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "casteljau/bezier/bernstein_roots.hpp"
#include "casteljau/bezier/evaluate.hpp"
#include "casteljau/bspline/bezier_pieces.hpp"

namespace casteljau {
namespace {

/// Coordinate j of the points as Bernstein coefficients (homogeneous: w P_j).
std::vector<double> coordinate(const PointArray& points, int j) {
  std::vector<double> values(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) values[i] = points[i][j];
  return values;
}

/// n (b_{i+1} - b_i): the derivative's Bernstein coefficients.
std::vector<double> differences(const std::vector<double>& b) {
  const double n = static_cast<double>(b.size() - 1);
  std::vector<double> d(b.size() > 1 ? b.size() - 1 : 1, 0.0);
  for (std::size_t i = 0; i + 1 < b.size(); ++i) d[i] = n * (b[i + 1] - b[i]);
  return d;
}

/// The parameters in (0, 1) where coordinate j of the piece has a zero derivative.
std::vector<double> stationary_parameters(const BezierCurve& piece, int j) {
  std::vector<double> numerator;
  if (!piece.is_rational()) {
    numerator = differences(coordinate(piece.control_points(), j));
  } else {
    const PointArray h = homogeneous_points(piece);
    const int d = piece.dimension();
    const std::vector<double> a = coordinate(h, j), w = coordinate(h, d);
    const std::vector<double> left = bernstein_product(differences(a), w), right = bernstein_product(a, differences(w));
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

}  // namespace casteljau
