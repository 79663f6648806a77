// Reversal, reparameterization, clamping and splitting of B-spline curves.
#include "casteljau/bspline/transform.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "casteljau/bspline/knot_vector.hpp"
#include "casteljau/core/model_numbers.hpp"
#include "casteljau/core/parameter_checks.hpp"
#include "../core/number_text.hpp"
#include "working_rows.hpp"

namespace casteljau {

using detail::number_text;

BSplineCurve reversed(const BSplineCurve& curve) {
  const Interval domain = curve.domain();
  const double a = domain.lower, b = domain.upper, sum = a + b;
  const auto knots = curve.knots();
  std::vector<double> mirrored(knots.size());
  for (std::size_t i = 0; i < knots.size(); ++i) {
    const double t = knots[knots.size() - 1 - i];
    // (a + b) - t rounds; the ends of the domain must map exactly.
    mirrored[i] = t == b ? a : (t == a ? b : sum - t);
  }
  const PointArray& points = curve.control_points();
  const int d = curve.dimension();
  std::vector<double> rows;
  rows.reserve(points.coordinates().size());
  for (std::size_t i = points.size(); i-- > 0;) rows.insert(rows.end(), points[i].begin(), points[i].end());
  std::vector<double> weights(curve.weights().rbegin(), curve.weights().rend());
  return BSplineCurve::from_trusted(curve.degree(), std::move(mirrored), PointArray::from_trusted(d, std::move(rows)),
                                    std::move(weights));
}

Expected<BSplineCurve> reparameterized(const BSplineCurve& curve, Interval target) {
  if (!std::isfinite(target.lower) || !std::isfinite(target.upper) || !(target.lower < target.upper))
    return Error{"the new domain [" + number_text(target.lower) + ", " + number_text(target.upper) +
                 "] must be finite with lower < upper"};
  if (auto ok = check_knot(target.lower, "the new domain's lower end"); !ok) return ok.error();
  if (auto ok = check_knot(target.upper, "the new domain's upper end"); !ok) return ok.error();
  const Interval domain = curve.domain();
  const double a = domain.lower, b = domain.upper;
  const double scale = target.length() / domain.length();
  if (!std::isfinite(scale) || !(scale > 0.0))
    return Error{"the new domain [" + number_text(target.lower) + ", " + number_text(target.upper) +
                 "] is too large or too small against the old one [" + number_text(a) + ", " + number_text(b) + "]"};
  std::vector<double> knots(curve.knots().begin(), curve.knots().end());
  for (double& t : knots) {
    t = t == a ? target.lower : (t == b ? target.upper : target.lower + (t - a) * scale);
    if (!std::isfinite(t))
      return Error{"a knot of the curve maps outside the floating-point range on [" + number_text(target.lower) +
                   ", " + number_text(target.upper) + "]"};
  }
  // Rounding can make an interior knot land beyond an end: keep the order.
  for (std::size_t i = 1; i < knots.size(); ++i) knots[i] = std::max(knots[i], knots[i - 1]);
  // Shrinking the domain shrinks every span: each must stay a valid knot span.
  for (std::size_t i = 1; i < knots.size(); ++i) {
    if (auto ok = check_span(knots[i - 1], knots[i],
                             "on [" + number_text(target.lower) + ", " + number_text(target.upper) + "], knots " +
                                 std::to_string(i - 1) + " and " + std::to_string(i));
        !ok)
      return ok.error();
  }
  std::vector<double> weights(curve.weights().begin(), curve.weights().end());
  return BSplineCurve::from_trusted(curve.degree(), std::move(knots), curve.control_points(), std::move(weights));
}

BSplineCurve clamped(const BSplineCurve& curve) {
  const Interval domain = curve.domain();
  return detail::curve_of(detail::restrict_to(detail::rows_of(curve), domain.lower, domain.upper));
}

Expected<std::pair<BSplineCurve, BSplineCurve>> split_at(const BSplineCurve& curve, double u) {
  const Interval domain = curve.domain();
  if (auto ok = check_split_parameter(u, domain); !ok) return ok.error();
  const double cut[] = {u};
  if (auto spans = check_added_knot_spans(curve.knots(), cut, "split parameter"); !spans) return spans.error();
  // Clamp first and insert u once, so that cutting needs no further
  // insertion and both parts share the very same cut row.
  const detail::CurveRows whole = detail::restrict_to(detail::rows_of(curve), domain.lower, domain.upper);
  std::vector<double> copies;
  for (int c = detail::multiplicity_count(whole.knots, u); c < curve.degree(); ++c) copies.push_back(u);
  const detail::CurveRows rows = detail::refine(whole, copies);
  return std::pair<BSplineCurve, BSplineCurve>{detail::curve_of(detail::restrict_to(rows, domain.lower, u)),
                                               detail::curve_of(detail::restrict_to(rows, u, domain.upper))};
}

Expected<BSplineCurve> segment(const BSplineCurve& curve, double u0, double u1) {
  if (auto ok = check_segment_parameters(u0, u1, curve.domain()); !ok) return ok.error();
  const double ends[] = {u0, u1};
  if (auto spans = check_added_knot_spans(curve.knots(), ends, "segment end"); !spans) return spans.error();
  return detail::curve_of(detail::restrict_to(detail::rows_of(curve), u0, u1));
}

Expected<BSplineCurve> transformed(const BSplineCurve& curve, const AffineMap& map) {
  auto points = transformed_points(map, curve.control_points());
  if (!points) return points.error();
  return BSplineCurve::make(curve.degree(), {curve.knots().begin(), curve.knots().end()}, std::move(*points),
                            {curve.weights().begin(), curve.weights().end()});
}

}  // namespace casteljau
