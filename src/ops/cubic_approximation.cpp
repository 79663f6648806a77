// Cubic Hermite approximation with a certified bound (ops/cubic_approximation.hpp).
#include "casteljau/ops/cubic_approximation.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "casteljau/bezier/bernstein_roots.hpp"
#include "casteljau/bezier/split.hpp"
#include "casteljau/bezier/tolerance.hpp"
#include "casteljau/bspline/bezier_pieces.hpp"
#include "casteljau/core/point_array.hpp"
#include "casteljau/core/tolerance.hpp"
#include "certified_budget.hpp"

namespace casteljau {
namespace {

/// H(0) = B(0), H(1) = B(1), H'(0) = B'(0), H'(1) = B'(1), with the rational
/// end derivatives n (w_1 / w_0)(P_1 - P_0) and n (w_{n-1} / w_n)(P_n - P_{n-1}).
BezierCurve hermite_cubic(const BezierCurve& piece) {
  const PointArray& p = piece.control_points();
  const int d = p.dimension();
  const int n = piece.degree();
  const std::size_t last = p.size() - 1;
  if (n == 0) {  // a point: the constant cubic
    std::vector<double> h;
    for (int i = 0; i < 4; ++i) h.insert(h.end(), p[0].begin(), p[0].end());
    return BezierCurve::make(PointArray::from_trusted(d, std::move(h))).value();
  }
  double start_ratio = 1.0, end_ratio = 1.0;
  if (piece.is_rational()) {
    start_ratio = piece.weights()[1] / piece.weights()[0];
    end_ratio = piece.weights()[last - 1] / piece.weights()[last];
  }
  std::vector<double> h(4 * static_cast<std::size_t>(d));
  for (int k = 0; k < d; ++k) {
    const double p0 = p[0][k], p1 = p[1][k], pn = p[last][k], pm = p[last - 1][k];
    h[k] = p0;
    h[d + k] = p0 + n * start_ratio * (p1 - p0) / 3.0;
    h[2 * d + k] = pn - n * end_ratio * (pn - pm) / 3.0;
    h[3 * d + k] = pn;
  }
  return BezierCurve::make(PointArray::from_trusted(d, std::move(h))).value();
}

/// A bound on max |B(t) - H(t)| over [0, 1] (see the header).
double deviation_bound(const BezierCurve& piece, const BezierCurve& cubic) {
  const PointArray& p = piece.control_points();
  const PointArray& h = cubic.control_points();
  const int d = p.dimension();
  const std::size_t n = p.size() - 1;
  std::vector<double> numerator(p.size()), weights(p.size(), 1.0), hermite(4);
  if (piece.is_rational()) std::copy(piece.weights().begin(), piece.weights().end(), weights.begin());
  // Polynomial: B - H with H elevated to n (the product with 1 of degree n - 3);
  // rational: P - W H with P elevated by 3 (the product with 1 of degree 3).
  const bool rational = piece.is_rational();
  const std::vector<double> ones(rational ? 4 : n - 3 + 1, 1.0);
  std::vector<double> squared;
  for (int k = 0; k < d; ++k) {
    for (std::size_t i = 0; i <= n; ++i) numerator[i] = weights[i] * p[i][k];
    for (std::size_t i = 0; i < 4; ++i) hermite[i] = h[i][k];
    std::vector<double> difference;
    if (rational) {
      const std::vector<double> left = bernstein_product(numerator, ones);
      const std::vector<double> scaled = bernstein_product(weights, hermite);
      difference.resize(scaled.size());
      for (std::size_t i = 0; i < scaled.size(); ++i) difference[i] = left[i] - scaled[i];
    } else {
      const std::vector<double> elevated = bernstein_product(hermite, ones);
      difference.resize(elevated.size());
      for (std::size_t i = 0; i < elevated.size(); ++i) difference[i] = numerator[i] - elevated[i];
    }
    if (squared.empty()) squared.assign(difference.size(), 0.0);
    for (std::size_t i = 0; i < difference.size(); ++i) squared[i] += difference[i] * difference[i];
  }
  const double largest = std::sqrt(*std::max_element(squared.begin(), squared.end()));
  return rational ? largest / *std::min_element(weights.begin(), weights.end()) : largest;
}

struct Approximator {
  std::vector<BezierCurve> cubics;
  double bound = 0.0;
  std::size_t control_points = 0;

  Status add(BezierCurve cubic) {
    control_points += cubic.control_points().size();
    if (control_points > tolerances::kMaxControlPoints)
      return Error{"the cubics need more than " + std::to_string(tolerances::kMaxControlPoints) + " control points",
                   ErrorKind::limit};
    cubics.push_back(std::move(cubic));
    return {};
  }

  Status approximate(const BezierCurve& piece, double budget, int depth) {
    BezierCurve cubic = hermite_cubic(piece);
    const double deviation = deviation_bound(piece, cubic);
    if (deviation <= budget) {
      bound = std::max(bound, deviation);
      return add(std::move(cubic));
    }
    if (depth == tolerances::kMaxSubdivisionDepth)
      return Error{"the cubics need more than " + std::to_string(tolerances::kMaxSubdivisionDepth) +
                       " halvings of a piece (its deviation is still " + std::to_string(deviation) + ")",
                   ErrorKind::limit};
    auto halves = split_at(piece, 0.5);
    if (!halves) return halves.error();
    if (Status left = approximate(halves->first, budget, depth + 1); !left) return left;
    return approximate(halves->second, budget, depth + 1);
  }
};

}  // namespace

Expected<CubicApproximation> approximate_by_cubics(CurveView curve, Tolerance tolerance) {
  const BezierPieces pieces = to_bezier_pieces(curve);
  Approximator approximator;
  std::size_t replaced = 0;
  // A tolerance that is no distance is refused even when every piece is
  // exact (certified_budget's first check); one below what doubles certify
  // matters only for pieces that are approximated (issue 39: a line at 1e6
  // could not be written to SVG).
  if (!(std::isfinite(tolerance.distance) && tolerance.distance > 0.0))
    return ops_detail::certified_budget(pieces.pieces.front(), tolerance, "cubic approximation").error();
  for (std::size_t i = 0; i < pieces.pieces.size(); ++i) {
    const BezierCurve& piece = pieces.pieces[i];
    if (!piece.is_rational() && piece.degree() <= 3) {
      if (Status kept = approximator.add(piece); !kept) return kept.error();
      continue;
    }
    auto budget = ops_detail::certified_budget(piece, tolerance, "cubic approximation");
    if (!budget) return budget.error();
    ++replaced;
    if (Status done = approximator.approximate(piece, *budget, 0); !done)
      return with_context(done.error(), "piece " + std::to_string(i));
  }
  auto result = PiecewiseBezierCurve::make(std::move(approximator.cubics));
  if (!result) return result.error();
  return CubicApproximation{std::move(*result), approximator.bound, replaced};
}

}  // namespace casteljau
