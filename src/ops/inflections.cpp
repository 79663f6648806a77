// Inflections (inflections.hpp): roots of det[A, A', A''] on each Bézier piece.
#include "casteljau/ops/inflections.hpp"

#include <algorithm>
#include <string>

#include "casteljau/bezier/bernstein_roots.hpp"
#include "casteljau/bspline/bezier_pieces.hpp"
#include "casteljau/ops/tolerance.hpp"
#include "bernstein_columns.hpp"

namespace casteljau {
namespace {

using detail::column;
using detail::derivative;
using detail::difference;

/// det[A, A', A''] of one plane piece, expanded along the first row:
/// x (y' w'' - w' y'') - y (x' w'' - w' x'') + w (x' y'' - y' x'').
std::vector<double> determinant(const BezierCurve& piece) {
  const PointArray h = homogeneous_points(piece);
  const std::vector<double> x = column(h, 0), y = column(h, 1), w = column(h, 2);
  const std::vector<double> x1 = derivative(x), y1 = derivative(y), w1 = derivative(w);
  const std::vector<double> x2 = derivative(x1), y2 = derivative(y1), w2 = derivative(w1);
  auto minor = [](const std::vector<double>& a1, const std::vector<double>& b2, const std::vector<double>& b1,
                  const std::vector<double>& a2) {
    return difference(bernstein_product(a1, b2), bernstein_product(b1, a2));
  };
  const std::vector<double> tx = bernstein_product(x, minor(y1, w2, w1, y2));
  const std::vector<double> ty = bernstein_product(y, minor(x1, w2, w1, x2));
  const std::vector<double> tw = bernstein_product(w, minor(x1, y2, y1, x2));
  std::vector<double> det(tx.size());
  for (std::size_t i = 0; i < det.size(); ++i) det[i] = tx[i] - ty[i] + tw[i];
  return det;
}

}  // namespace

Expected<std::vector<double>> inflection_parameters(CurveView curve) {
  if (curve.dimension() != 2)
    return Error{"inflections need a plane curve, this one lives in R^" + std::to_string(curve.dimension())};
  const BezierPieces pieces = to_bezier_pieces(curve);
  std::vector<double> result;
  for (std::size_t k = 0; k < pieces.pieces.size(); ++k) {
    const BezierCurve& piece = pieces.pieces[k];
    if (piece.degree() < 2) continue;  // a segment or a point: no curvature
    const Interval span{pieces.breakpoints[k], pieces.breakpoints[k + 1]};
    for (const BernsteinRoot& root : bernstein_roots(determinant(piece), tolerances::kCurvatureRootResolution)) {
      if (root.multiplicity % 2 == 0) continue;  // a flat point, not an inflection
      const double u = span.lerp(root.t);
      if (!result.empty() && u <= result.back()) continue;  // a junction seen from both pieces
      result.push_back(u);
    }
  }
  // The ends of the domain are not inflections (the curvature does not change sign there).
  const Interval domain = curve.domain();
  result.erase(std::remove_if(result.begin(), result.end(),
                              [&](double u) { return u <= domain.lower || u >= domain.upper; }),
               result.end());
  return result;
}

}  // namespace casteljau
