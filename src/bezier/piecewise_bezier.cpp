#include "casteljau/bezier/piecewise_bezier.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <string>

#include "casteljau/bezier/evaluate.hpp"
#include "casteljau/bezier/split.hpp"
#include "casteljau/core/parameter_checks.hpp"
#include "casteljau/core/precondition.hpp"
#include "checked_batch.hpp"

namespace casteljau {

Expected<PiecewiseBezierCurve> PiecewiseBezierCurve::make(std::vector<BezierCurve> pieces) {
  if (pieces.empty()) return Error{"a piecewise Bézier curve needs at least one piece"};
  for (std::size_t i = 1; i < pieces.size(); ++i)
    if (pieces[i].dimension() != pieces[0].dimension())
      return Error{"piece " + std::to_string(i) + " has dimension " + std::to_string(pieces[i].dimension()) +
                   ", piece 0 has " + std::to_string(pieces[0].dimension())};
  return PiecewiseBezierCurve(std::move(pieces));
}

namespace {

/// The curve whose pieces are f(piece) (an Expected<BezierCurve>), the first
/// error named by its piece ("piece 2: ...").
template <class F>
Expected<PiecewiseBezierCurve> each_piece(const PiecewiseBezierCurve& curve, F&& f) {
  std::vector<BezierCurve> pieces;
  for (std::size_t i = 0; i < curve.pieces().size(); ++i) {
    auto piece = f(curve.pieces()[i]);
    if (!piece) return with_context(piece.error(), "piece " + std::to_string(i));
    pieces.push_back(std::move(*piece));
  }
  return PiecewiseBezierCurve::make(std::move(pieces));
}

}  // namespace

int PiecewiseBezierCurve::degree() const noexcept {
  int degree = 0;
  for (const BezierCurve& piece : pieces_) degree = std::max(degree, piece.degree());
  return degree;
}

bool PiecewiseBezierCurve::is_rational() const noexcept {
  return std::any_of(pieces_.begin(), pieces_.end(), [](const BezierCurve& piece) { return piece.is_rational(); });
}

std::pair<int, double> locate(const PiecewiseBezierCurve& curve, double u) {
  const int m = curve.size();
  // Clamped as a double first: converting a double beyond int's range to int
  // is undefined behaviour, and extrapolation accepts any finite u.
  const int i = static_cast<int>(std::clamp(std::floor(u), 0.0, static_cast<double>(m - 1)));
  return {i, u - i};
}

Point point_at(const PiecewiseBezierCurve& curve, double u) {
  const auto [i, t] = locate(curve, u);
  return point_at(curve.pieces()[i], t);
}

void point_at(const PiecewiseBezierCurve& curve, double u, std::span<double> out) {
  const auto [i, t] = locate(curve, u);
  point_at(curve.pieces()[i], t, out);
}

Point derivative_at(const PiecewiseBezierCurve& curve, double u, int order) {
  const auto [i, t] = locate(curve, u);
  return derivative_at(curve.pieces()[i], t, order);
}

void points_at(const PiecewiseBezierCurve& curve, std::span<const double> us, std::span<double> out) {
  const std::size_t d = curve.dimension();
  detail::require(out.size() == us.size() * d, "points_at", "out must hold us.size() * dimension() values");
  for (std::size_t k = 0; k < us.size(); ++k) {
    const auto [i, t] = locate(curve, us[k]);
    points_at(curve.pieces()[i], std::span<const double>(&t, 1), out.subspan(k * d, d));
  }
}

std::vector<Point> derivatives_up_to(const PiecewiseBezierCurve& curve, double u, int max_order) {
  const auto [i, t] = locate(curve, u);
  return derivatives_up_to(curve.pieces()[i], t, max_order);
}

std::size_t points_at_within(const PiecewiseBezierCurve& curve, std::span<const double> us, Interval allowed,
                             std::span<double> out) {
  detail::require(out.size() == us.size() * static_cast<std::size_t>(curve.dimension()), "points_at_within",
                  "out must hold us.size() * dimension() values");
  return detail::evaluate_within(us, allowed, static_cast<std::size_t>(curve.dimension()), out,
                                 [&](std::span<const double> block, std::span<double> rows) {
                                   points_at(curve, block, rows);
                                 });
}

void derivatives_at(const PiecewiseBezierCurve& curve, std::span<const double> us, int order, std::span<double> out) {
  const std::size_t d = curve.dimension();
  detail::require(order >= 0, "derivatives_at", "the derivative order must be >= 0");
  detail::require(out.size() == us.size() * d, "derivatives_at", "out must hold us.size() * dimension() values");
  for (std::size_t k = 0; k < us.size(); ++k) {
    const auto [i, t] = locate(curve, us[k]);
    derivatives_at(curve.pieces()[i], std::span<const double>(&t, 1), order, out.subspan(k * d, d));
  }
}

void points_and_derivatives_at(const PiecewiseBezierCurve& curve, std::span<const double> us,
                               std::span<double> points, std::span<double> derivatives) {
  points_at(curve, us, points);
  derivatives_at(curve, us, 1, derivatives);
}

std::vector<double> breakpoints(const PiecewiseBezierCurve& curve) {
  std::vector<double> result(static_cast<std::size_t>(curve.size()) + 1);
  for (std::size_t i = 0; i < result.size(); ++i) result[i] = static_cast<double>(i);
  return result;
}

Expected<std::pair<PiecewiseBezierCurve, PiecewiseBezierCurve>> split_at(const PiecewiseBezierCurve& curve,
                                                                         double u) {
  if (auto ok = check_split_parameter(u, curve.domain()); !ok) return ok.error();
  const auto& pieces = curve.pieces();
  const auto [i, t] = locate(curve, u);
  std::vector<BezierCurve> first(pieces.begin(), pieces.begin() + i), second;
  if (t == 0.0) {
    second.assign(pieces.begin() + i, pieces.end());
  } else {
    auto halves = split_at(pieces[i], t).value();  // t in (0, 1): u is not a junction
    first.push_back(std::move(halves.first));
    second.push_back(std::move(halves.second));
    second.insert(second.end(), pieces.begin() + i + 1, pieces.end());
  }
  return std::pair<PiecewiseBezierCurve, PiecewiseBezierCurve>{PiecewiseBezierCurve::make(std::move(first)).value(),
                                                               PiecewiseBezierCurve::make(std::move(second)).value()};
}

Expected<PiecewiseBezierCurve> segment(const PiecewiseBezierCurve& curve, double u0, double u1) {
  if (auto ok = check_segment_parameters(u0, u1, curve.domain()); !ok) return ok.error();
  const auto& pieces = curve.pieces();
  // The pieces [u0, u1] meets with positive length: from floor(u0) to ceil(u1) - 1.
  const int first = locate(curve, u0).first;
  const int last = std::max(first, static_cast<int>(std::ceil(u1)) - 1);
  std::vector<BezierCurve> kept;
  for (int i = first; i <= last; ++i) {
    const double t0 = std::max(u0 - i, 0.0), t1 = std::min(u1 - i, 1.0);
    kept.push_back(t0 == 0.0 && t1 == 1.0 ? pieces[i] : extended_segment(pieces[i], t0, t1));
  }
  return PiecewiseBezierCurve::make(std::move(kept)).value();
}

PiecewiseBezierCurve reversed(const PiecewiseBezierCurve& curve) {
  std::vector<BezierCurve> pieces;
  for (auto it = curve.pieces().rbegin(); it != curve.pieces().rend(); ++it) pieces.push_back(reversed(*it));
  return PiecewiseBezierCurve::make(std::move(pieces)).value();
}

Expected<PiecewiseBezierCurve> transformed(const PiecewiseBezierCurve& curve, const AffineMap& map) {
  return each_piece(curve, [&map](const BezierCurve& piece) { return transformed(piece, map); });
}

Expected<PiecewiseBezierCurve> derivative_curve(const PiecewiseBezierCurve& curve, int order) {
  return each_piece(curve, [order](const BezierCurve& piece) { return derivative_curve(piece, order); });
}

}  // namespace casteljau
