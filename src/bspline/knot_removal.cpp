// Knot removal within a tolerance (The NURBS Book §5.4, A5.8).
#include "casteljau/bspline/knot_removal.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "casteljau/bspline/knot_vector.hpp"
#include "../core/number_text.hpp"
#include "working_rows.hpp"

namespace casteljau {
namespace detail {

int remove_in_place(CurveRows& c, int r, int s, int num, double budget, double radius, double& min_weight,
                    double& error_bound, std::vector<double>& temp) {
  const int p = c.degree, w = c.width, order = p + 1;
  const double u = c.knots[static_cast<std::size_t>(r)];
  const auto& knot = c.knots;
  // Scratch for the two recursions of A5.8: at most 2p+1 rows (its temp).
  temp.resize(static_cast<std::size_t>(2 * p + 2) * static_cast<std::size_t>(w));
  const auto tmp = [&](int k) { return temp.data() + static_cast<std::ptrdiff_t>(k) * w; };
  const auto distance_rows = [w](const double* a, const double* b) {
    double sum = 0.0;
    for (int k = 0; k < w; ++k) sum += (a[k] - b[k]) * (a[k] - b[k]);
    return std::sqrt(sum);
  };
  const int fout = (2 * r - s - p) / 2;  // where the first removed point sits
  int first = r - p, last = r - s;
  int t = 0;
  for (; t < num; ++t) {
    const int off = first - 1;
    std::copy(c.row(off), c.row(off) + w, tmp(0));
    std::copy(c.row(last + 1), c.row(last + 1) + w, tmp(last + 1 - off));
    int i = first, j = last, ii = 1, jj = last - off;
    // New points from the left (ii) and from the right (jj) until they meet.
    while (j - i > t) {
      const double alpha_i = (u - knot[i]) / (knot[i + order + t] - knot[i]);
      const double alpha_j = (u - knot[j - t]) / (knot[j + order] - knot[j - t]);
      for (int k = 0; k < w; ++k) {
        tmp(ii)[k] = (c.row(i)[k] - (1.0 - alpha_i) * tmp(ii - 1)[k]) / alpha_i;
        tmp(jj)[k] = (c.row(j)[k] - alpha_j * tmp(jj + 1)[k]) / (1.0 - alpha_j);
      }
      ++i, ++ii, --j, --jj;
    }
    double delta = 0.0;
    if (j - i < t) {
      // Both recursions computed the middle point: how far apart they are.
      delta = distance_rows(tmp(ii - 1), tmp(jj + 1));
    } else {
      // One point left over: re-inserting u must give it back.
      const double alpha_i = (u - knot[i]) / (knot[i + order + t] - knot[i]);
      double sum = 0.0;
      for (int k = 0; k < w; ++k) {
        const double back = alpha_i * tmp(ii + t + 1)[k] + (1.0 - alpha_i) * tmp(ii - 1)[k];
        sum += (c.row(i)[k] - back) * (c.row(i)[k] - back);
      }
      delta = std::sqrt(sum);
    }
    double step_bound = delta;
    double new_min_weight = min_weight;
    if (c.rational) {
      // A weight <= 0 would not be a NURBS curve: such a knot is not removable.
      // The rows computed from both sides (in the odd case the middle one is not).
      for (int k = 0; k < ii; ++k) new_min_weight = std::min(new_min_weight, tmp(k)[w - 1]);
      for (int k = jj + 1; k <= last + 1 - off; ++k) new_min_weight = std::min(new_min_weight, tmp(k)[w - 1]);
      if (!(new_min_weight > 0.0)) break;
      step_bound = delta * (1.0 + radius + error_bound) / new_min_weight;
    }
    if (!(error_bound + step_bound <= budget)) break;
    error_bound += step_bound;
    min_weight = new_min_weight;
    i = first, j = last;
    while (j - i > t) {
      std::copy(tmp(i - off), tmp(i - off) + w, c.row(i));
      std::copy(tmp(j - off), tmp(j - off) + w, c.row(j));
      ++i, --j;
    }
    --first, ++last;
  }
  if (t == 0) return 0;
  c.knots.erase(c.knots.begin() + (r - t + 1), c.knots.begin() + (r + 1));
  // The t points to drop are consecutive: [j, i] found as in A5.8.
  int j = fout, i = fout;
  for (int k = 1; k < t; ++k) (k % 2 == 1) ? ++i : --j;
  c.rows.erase(c.rows.begin() + static_cast<std::ptrdiff_t>(j) * w,
               c.rows.begin() + static_cast<std::ptrdiff_t>(i + 1) * w);
  return t;
}

namespace {

/// The curve as it is being rewritten: `buffer` holds its first knots and
/// rows (changed by removals), the source its remaining, untouched ones.
class Stream {
 public:
  explicit Stream(const CurveRows& source) : source_(source) {
    buffer_.degree = source.degree;
    buffer_.rational = source.rational;
    buffer_.width = source.width;
  }
  /// Makes sure the buffer holds `knots` knots and `rows` rows (or all there are).
  void pull(std::size_t knots, std::size_t rows) {
    while (buffer_.knots.size() < knots && next_knot_ < source_.knots.size())
      buffer_.knots.push_back(source_.knots[next_knot_++]);
    const std::size_t w = static_cast<std::size_t>(source_.width);
    while (buffer_.count() < rows && next_row_ < source_.count()) {
      buffer_.rows.insert(buffer_.rows.end(), source_.row(next_row_), source_.row(next_row_) + w);
      ++next_row_;
    }
  }
  CurveRows& buffer() { return buffer_; }
  CurveRows finish() {
    pull(std::numeric_limits<std::size_t>::max(), std::numeric_limits<std::size_t>::max());
    return std::move(buffer_);
  }

 private:
  const CurveRows& source_;
  CurveRows buffer_;
  std::size_t next_knot_ = 0, next_row_ = 0;
};

}  // namespace

CurveRows remove_interior(const CurveRows& source, std::span<const int> counts, double budget, double radius,
                          double& min_weight, int& removed, double& error_bound) {
  const int p = source.degree;
  const auto& knots = source.knots;
  const double lower = knots[static_cast<std::size_t>(p)], upper = knots[source.count()];
  Stream stream(source);
  std::size_t value_index = 0;
  int removed_here = 0;
  std::vector<double> scratch;
  for (std::size_t i = 0; i < knots.size(); ++i) {
    const double u = knots[i];
    // Act at the last copy of each distinct interior value.
    if (!(lower < u && u < upper) || (i + 1 < knots.size() && knots[i + 1] == u)) continue;
    assert(value_index < counts.size());
    const int count = counts[value_index++];
    if (count <= 0) continue;
    const int s = multiplicity_count(knots, u);
    const int r = static_cast<int>(i) - removed_here;  // its index in the buffer
    stream.pull(static_cast<std::size_t>(r + p + 2), static_cast<std::size_t>(r + 2));
    removed_here += remove_in_place(stream.buffer(), r, s, std::min(count, s), budget, radius, min_weight, error_bound,
                                   scratch);
  }
  removed += removed_here;
  return stream.finish();
}

}  // namespace detail

namespace {

using detail::number_text;

Status check_tolerance(Tolerance tolerance) {
  if (!std::isfinite(tolerance.distance) || !(tolerance.distance > 0.0))
    return Error{"the knot removal tolerance is " + number_text(tolerance.distance) + ", it must be finite and > 0"};
  return {};
}

/// Largest |P_i| of the Cartesian control points: a bound of |C(u)| (convex hull).
double radius_of(const BSplineCurve& curve) {
  double radius = 0.0;
  for (std::size_t i = 0; i < curve.control_points().size(); ++i) {
    double sum = 0.0;
    for (double x : curve.control_points()[i]) sum += x * x;
    radius = std::max(radius, std::sqrt(sum));
  }
  return radius;
}

double min_weight_of(const BSplineCurve& curve) {
  if (!curve.is_rational()) return 1.0;
  return *std::min_element(curve.weights().begin(), curve.weights().end());
}

}  // namespace

Expected<KnotRemoval> remove_knot(const BSplineCurve& curve, double u, int times, Tolerance tolerance) {
  if (auto ok = check_finite(u, "the knot to remove"); !ok) return ok.error();
  if (auto ok = check_tolerance(tolerance); !ok) return ok.error();
  const Interval domain = curve.domain();
  if (!(domain.lower < u && u < domain.upper))
    return Error{"the knot to remove (" + number_text(u) + ") is not inside the domain [" + number_text(domain.lower) +
                 ", " + number_text(domain.upper) + "], only interior knots can be removed", ErrorKind::out_of_domain};
  const auto knots = curve.knots();
  const int s = detail::multiplicity_count(knots, u);
  if (s == 0) return Error{number_text(u) + " is not a knot of the curve, it cannot be removed"};
  if (times < 0 || times > s)
    return Error{"cannot remove knot " + number_text(u) + " " + std::to_string(times) + " times, it has multiplicity " +
                 std::to_string(s)};
  KnotRemoval result{curve, 0, 0.0};
  if (times == 0) return result;
  detail::CurveRows rows = detail::rows_of(curve);
  const int r = static_cast<int>(std::upper_bound(knots.begin(), knots.end(), u) - knots.begin()) - 1;
  double min_weight = min_weight_of(curve);
  std::vector<double> scratch;
  result.removed = detail::remove_in_place(rows, r, s, times, tolerance.distance, radius_of(curve), min_weight,
                                           result.error_bound, scratch);
  if (result.removed > 0) result.curve = detail::curve_of(std::move(rows));
  return result;
}

Expected<KnotRemoval> remove_knots(const BSplineCurve& curve, Tolerance tolerance) {
  if (auto ok = check_tolerance(tolerance); !ok) return ok.error();
  const Interval domain = curve.domain();
  std::vector<int> counts;
  for (const KnotMultiplicity& k : knot_multiplicities(curve.knots()))
    if (domain.lower < k.value && k.value < domain.upper) counts.push_back(k.multiplicity);
  double min_weight = min_weight_of(curve);
  KnotRemoval result{curve, 0, 0.0};
  detail::CurveRows rows = detail::remove_interior(detail::rows_of(curve), counts, tolerance.distance,
                                                   radius_of(curve), min_weight, result.removed, result.error_bound);
  if (result.removed > 0) result.curve = detail::curve_of(std::move(rows));
  return result;
}

}  // namespace casteljau
