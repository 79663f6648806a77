// Pieces on a straight line as monotone passes (line_passes.hpp).
#include "line_passes.hpp"

#include <algorithm>
#include <cmath>
#include <span>

#include "casteljau/bezier/bernstein_roots.hpp"

namespace casteljau::detail {
namespace {

/// The contact of pass p of `a` with pass q of `b`, if any: an overlap where
/// their ranges of x share more than the tolerance, a point where they touch
/// within it (only when `touches` counts).
std::optional<PassContact> contact(const LinePasses& a, std::size_t p, const LinePasses& b, std::size_t q,
                                   double tolerance, bool touches) {
  const double p0 = a.x_at(a.cuts[p]), p1 = a.x_at(a.cuts[p + 1]);
  const double q0 = b.x_at(b.cuts[q]), q1 = b.x_at(b.cuts[q + 1]);
  const double low = std::max(std::min(p0, p1), std::min(q0, q1));
  const double high = std::min(std::max(p0, p1), std::max(q0, q1));
  if (high - low > tolerance) {
    const double s_low = a.parameter_of(p, low), s_high = a.parameter_of(p, high);
    const double t_low = b.parameter_of(q, low), t_high = b.parameter_of(q, high);
    const bool up = s_low < s_high;
    return PassContact{up ? s_low : s_high, up ? t_low : t_high, up ? s_high : s_low, up ? t_high : t_low, true};
  }
  if (!touches || high - low < -tolerance) return std::nullopt;
  // The ranges touch: at the middle of the gap (or of the sliver they share).
  const double middle = 0.5 * (low + high);
  const double s = a.parameter_of(p, middle), t = b.parameter_of(q, middle);
  return PassContact{s, t, s, t, false};
}

}  // namespace

double LinePasses::x_at(double t) const {
  return weights.empty() ? bernstein_value(weighted, t) : bernstein_value(weighted, t) / bernstein_value(weights, t);
}

double LinePasses::parameter_of(std::size_t pass, double value) const {
  double a = cuts[pass], b = cuts[pass + 1];
  const double xa = x_at(a), xb = x_at(b);
  const bool rising = xb >= xa;
  if (value == xa || (rising ? value < xa : value > xa)) return a;
  if (value == xb || (rising ? value > xb : value < xb)) return b;
  // A turning point is an end of its passes, where bisection would find it
  // only to the square root of the rounding: the ends are returned exactly.
  for (int i = 0; i < 80 && b - a > 0.0; ++i) {
    const double m = 0.5 * (a + b);
    if ((x_at(m) < value) == rising) a = m;
    else b = m;
  }
  return 0.5 * (a + b);
}

std::optional<LinePasses> line_passes(const BezierCurve& piece, double tolerance, const LinePasses* line) {
  const std::span<const double> weights = piece.weights();
  if (std::any_of(weights.begin(), weights.end(), [](double w) { return !(w > 0.0); })) return std::nullopt;
  const PointArray& control = piece.control_points();
  LinePasses passes;
  if (line != nullptr) {
    passes.origin = line->origin;
    passes.direction = line->direction;
  } else {
    // The line: through P_0 and the control point farthest from it.
    passes.origin.assign(control[0].begin(), control[0].end());
    double farthest = 0.0;
    for (std::size_t k = 1; k < control.size(); ++k) {
      if (const double d = distance(control[k], passes.origin); d > farthest) {
        farthest = d;
        passes.direction.assign(control[k].begin(), control[k].end());
      }
    }
    if (farthest <= tolerance) return std::nullopt;  // a point: left out by the callers
    for (std::size_t c = 0; c < passes.direction.size(); ++c)
      passes.direction[c] = (passes.direction[c] - passes.origin[c]) / farthest;
  }
  const std::size_t dimension = passes.direction.size();
  if (static_cast<std::size_t>(piece.dimension()) != dimension) return std::nullopt;
  std::vector<double> along(control.size());
  for (std::size_t k = 0; k < control.size(); ++k) {
    double x = 0.0, off = 0.0;
    for (std::size_t c = 0; c < dimension; ++c) x += (control[k][c] - passes.origin[c]) * passes.direction[c];
    for (std::size_t c = 0; c < dimension; ++c) {
      const double r = control[k][c] - passes.origin[c] - x * passes.direction[c];
      off += r * r;
    }
    if (std::sqrt(off) > tolerance) return std::nullopt;  // the hull leaves the line's tolerance
    along[k] = x;
  }
  if (std::all_of(along.begin(), along.end(), [&](double x) { return std::abs(x - along[0]) <= tolerance; }))
    return std::nullopt;  // a point of the line
  // Turning points: the roots of x'(t) inside (0, 1); of its numerator
  // X' W - X W' (degree 2n - 1 in Bernstein form) when rational.
  std::vector<double> slope(along.size() - 1);
  if (piece.is_rational()) {
    passes.weights.assign(weights.begin(), weights.end());
    passes.weighted.resize(along.size());
    for (std::size_t k = 0; k < along.size(); ++k) passes.weighted[k] = weights[k] * along[k];
    std::vector<double> weight_slope(along.size() - 1);
    for (std::size_t k = 0; k + 1 < along.size(); ++k) {
      slope[k] = passes.weighted[k + 1] - passes.weighted[k];
      weight_slope[k] = weights[k + 1] - weights[k];
    }
    const std::vector<double> left = bernstein_product(slope, weights);
    const std::vector<double> right = bernstein_product(passes.weighted, weight_slope);
    slope.resize(left.size());
    for (std::size_t k = 0; k < left.size(); ++k) slope[k] = left[k] - right[k];
  } else {
    passes.weighted = along;
    for (std::size_t k = 0; k + 1 < along.size(); ++k) slope[k] = along[k + 1] - along[k];
  }
  passes.cuts.push_back(0.0);
  for (const BernsteinRoot& root : bernstein_roots(slope))
    if (root.t > 0.0 && root.t < 1.0 && root.multiplicity % 2 == 1) passes.cuts.push_back(root.t);
  passes.cuts.push_back(1.0);
  return passes;
}

std::vector<PassContact> self_overlaps(const LinePasses& piece, double tolerance) {
  std::vector<PassContact> overlaps;
  for (std::size_t p = 0; p + 1 < piece.cuts.size(); ++p)
    for (std::size_t q = p + 1; q + 1 < piece.cuts.size(); ++q)
      if (auto met = contact(piece, p, piece, q, tolerance, false)) overlaps.push_back(*met);
  return overlaps;
}

std::vector<PassContact> pass_contacts(const LinePasses& a, const LinePasses& b, double tolerance) {
  std::vector<PassContact> contacts;
  for (std::size_t p = 0; p + 1 < a.cuts.size(); ++p)
    for (std::size_t q = 0; q + 1 < b.cuts.size(); ++q)
      if (auto met = contact(a, p, b, q, tolerance, true)) contacts.push_back(*met);
  return contacts;
}

}  // namespace casteljau::detail
