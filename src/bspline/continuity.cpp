// Measured and predicted continuity at the knots of a B-spline curve.
#include "casteljau/bspline/continuity.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <vector>

#include "casteljau/bspline/basis.hpp"
#include "casteljau/bspline/knot_vector.hpp"
#include "casteljau/bspline/tolerance.hpp"
#include "casteljau/core/tolerance.hpp"
#include "working_rows.hpp"

namespace casteljau {
namespace {

/// Derivatives of orders 0..p of the rows' curve on span `span` at u,
/// out[k*w + c], and for each order the rounding scale sum_r |N^(k)_r| max|P|.
void span_derivatives(const detail::CurveRows& rows, int span, double u, std::vector<double>& basis,
                      std::vector<double>& out, std::vector<double>& noise) {
  const int p = rows.degree, w = rows.width;
  basis.assign(static_cast<std::size_t>((p + 1) * (p + 1)), 0.0);
  basis_function_derivatives(rows.knots, p, span, u, p, basis);
  out.assign(static_cast<std::size_t>((p + 1) * w), 0.0);
  noise.assign(static_cast<std::size_t>(p + 1), 0.0);
  double local_scale = 0.0;
  for (int r = 0; r <= p; ++r)
    for (int c = 0; c < w; ++c) local_scale = std::max(local_scale, std::abs(rows.row(span - p + r)[c]));
  for (int k = 0; k <= p; ++k) {
    double absolute = 0.0;
    for (int r = 0; r <= p; ++r) {
      const double n = basis[static_cast<std::size_t>(k * (p + 1) + r)];
      absolute += std::abs(n);
      for (int c = 0; c < w; ++c) out[static_cast<std::size_t>(k * w + c)] += n * rows.row(span - p + r)[c];
    }
    noise[static_cast<std::size_t>(k)] = absolute * local_scale;
  }
}

double norm_of(const double* v, int w) {
  double sum = 0.0;
  for (int c = 0; c < w; ++c) sum += v[c] * v[c];
  return std::sqrt(sum);
}

/// The Cartesian first derivative C' = (A' - w' C) / w of the homogeneous
/// derivatives (order 0 and 1 in `h`), or the first derivative itself, into t.
void tangent_of(const std::vector<double>& h, int w, bool rational, std::vector<double>& t) {
  if (!rational) {
    t.assign(h.begin() + w, h.begin() + 2 * w);
    return;
  }
  const int d = w - 1;
  const double weight = h[static_cast<std::size_t>(d)], weight1 = h[static_cast<std::size_t>(w + d)];
  t.resize(static_cast<std::size_t>(d));
  for (int c = 0; c < d; ++c) t[c] = (h[static_cast<std::size_t>(w + c)] - weight1 * h[c] / weight) / weight;
}

/// Storage reused from knot to knot (no allocation per knot once grown).
struct Scratch {
  std::vector<double> basis, left, right, left_noise, right_noise, left_tangent, right_tangent;
};

Continuity measure(const detail::CurveRows& rows, double u, Scratch& scratch) {
  const int p = rows.degree, w = rows.width;
  const auto& t = rows.knots;
  const int first = static_cast<int>(std::lower_bound(t.begin(), t.end(), u) - t.begin());
  const int last = static_cast<int>(std::upper_bound(t.begin(), t.end(), u) - t.begin()) - 1;
  // Not a knot: first = last + 1, both sides are the span that holds u.
  const int left_span = first - 1;
  const int right_span = last >= first ? last : first - 1;
  auto& left = scratch.left;
  auto& right = scratch.right;
  auto& left_noise = scratch.left_noise;
  auto& right_noise = scratch.right_noise;
  span_derivatives(rows, left_span, u, scratch.basis, left, left_noise);
  span_derivatives(rows, right_span, u, scratch.basis, right, right_noise);
  Continuity result;
  for (int k = 0; k <= p; ++k) {
    const double* a = left.data() + k * w;
    const double* b = right.data() + k * w;
    double difference = 0.0;
    for (int c = 0; c < w; ++c) difference += (a[c] - b[c]) * (a[c] - b[c]);
    difference = std::sqrt(difference);
    const double scale = std::max({norm_of(a, w), norm_of(b, w), left_noise[k], right_noise[k]});
    if (!(difference <= tolerances::kContinuityRelative * scale)) break;
    result.parametric = k;
  }
  if (result.parametric >= 0 && p >= 1) {
    auto& ta = scratch.left_tangent;
    auto& tb = scratch.right_tangent;
    tangent_of(left, w, rows.rational, ta);
    tangent_of(right, w, rows.rational, tb);
    const int d = static_cast<int>(ta.size());
    const double na = norm_of(ta.data(), d), nb = norm_of(tb.data(), d);
    const double floor = tolerances::kVanishingDerivative * std::max(left_noise[1], right_noise[1]);
    if (na > floor && nb > floor) {
      double sum = 0.0, dif = 0.0;
      for (int c = 0; c < d; ++c) {
        sum += (ta[c] / na + tb[c] / nb) * (ta[c] / na + tb[c] / nb);
        dif += (ta[c] / na - tb[c] / nb) * (ta[c] / na - tb[c] / nb);
      }
      result.tangent = 2.0 * std::atan2(std::sqrt(dif), std::sqrt(sum)) <= tolerances::kTangentAngle;
    }
  }
  return result;
}

}  // namespace

Continuity continuity_at(const BSplineCurve& curve, double u) {
  assert(curve.domain().lower < u && u < curve.domain().upper);
  Scratch scratch;
  return measure(detail::rows_of(curve), u, scratch);
}

std::vector<KnotContinuity> continuity_at_knots(const BSplineCurve& curve) {
  const detail::CurveRows rows = detail::rows_of(curve);
  const Interval domain = curve.domain();
  Scratch scratch;
  std::vector<KnotContinuity> out;
  for (const KnotMultiplicity& k : knot_multiplicities(curve.knots())) {
    if (!(domain.lower < k.value && k.value < domain.upper)) continue;
    out.push_back({k.value, k.multiplicity, curve.degree() - k.multiplicity, measure(rows, k.value, scratch)});
  }
  return out;
}

}  // namespace casteljau
