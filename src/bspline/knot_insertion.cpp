// Knot insertion and refinement (The NURBS Book §5.2, A5.4), and the private
// helpers built on them (restriction to a sub-domain, working_rows.hpp).
#include "casteljau/bspline/knot_insertion.hpp"

#include <algorithm>
#include <cassert>
#include <string>
#include <vector>

#include "casteljau/bspline/basis.hpp"
#include "casteljau/bspline/knot_vector.hpp"
#include "casteljau/core/tolerance.hpp"
#include "../core/number_text.hpp"
#include "working_rows.hpp"

namespace casteljau {
namespace detail {

CurveRows refine(const CurveRows& curve, std::span<const double> x) {
  if (x.empty()) return curve;
  const int p = curve.degree, w = curve.width;
  const std::span<const double> u = curve.knots;
  const int n = static_cast<int>(curve.count()) - 1;
  const int m = n + p + 1;
  const int r = static_cast<int>(x.size()) - 1;
  // The spans that hold the first and the last new knot bound the part of
  // the control polygon that changes (A5.4's a and b).
  const int a = find_span(u, p, x.front());
  const int b = find_span(u, p, x.back()) + 1;

  CurveRows out;
  out.degree = p;
  out.rational = curve.rational;
  out.width = w;
  out.knots.assign(static_cast<std::size_t>(m + r + 2), 0.0);
  out.rows.assign(static_cast<std::size_t>(n + r + 2) * static_cast<std::size_t>(w), 0.0);
  const auto copy_row = [&](double* to, const double* from) { std::copy(from, from + w, to); };

  for (int j = 0; j <= a - p; ++j) copy_row(out.row(j), curve.row(j));
  for (int j = b - 1; j <= n; ++j) copy_row(out.row(j + r + 1), curve.row(j));
  for (int j = 0; j <= a; ++j) out.knots[j] = u[j];
  for (int j = b + p; j <= m; ++j) out.knots[j + r + 1] = u[j];

  // Backwards over the new knots: each one is inserted by one column of
  // Boehm's triangle; old knots not below it are shifted right first.
  int i = b + p - 1;
  int k = b + p + r;
  for (int j = r; j >= 0; --j) {
    while (x[j] <= u[i] && i > a) {
      copy_row(out.row(k - p - 1), curve.row(i - p - 1));
      out.knots[k] = u[i];
      --k;
      --i;
    }
    copy_row(out.row(k - p - 1), out.row(k - p));
    for (int l = 1; l <= p; ++l) {
      const int index = k - p + l;
      double alpha = out.knots[k + l] - x[j];
      double* target = out.row(index - 1);
      const double* right = out.row(index);
      if (alpha == 0.0) {
        // The new knot equals a knot already placed to its right: the point is copied.
        copy_row(target, right);
      } else {
        alpha /= out.knots[k + l] - u[i - p + l];
        for (int c = 0; c < w; ++c) target[c] = alpha * target[c] + (1.0 - alpha) * right[c];
      }
    }
    out.knots[k] = x[j];
    --k;
  }
  return out;
}

std::vector<double> knots_missing_for(std::span<const double> knots, double lower, double upper, int target) {
  std::vector<double> missing;
  auto add = [&](double value) {
    const int have = multiplicity_count(knots, value);
    for (int c = have; c < target; ++c) missing.push_back(value);
  };
  add(lower);
  for (std::size_t i = 0; i < knots.size(); ++i) {
    const double v = knots[i];
    if (v > lower && v < upper && (i == 0 || knots[i - 1] != v)) add(v);
  }
  if (upper != lower) add(upper);
  return missing;
}

int multiplicity_count(std::span<const double> knots, double value) {
  const auto range = std::equal_range(knots.begin(), knots.end(), value);
  return static_cast<int>(range.second - range.first);
}

CurveRows restrict_to(const CurveRows& curve, double lower, double upper) {
  assert(lower < upper);
  const int p = curve.degree;
  std::vector<double> missing;
  for (int c = multiplicity_count(curve.knots, lower); c < p; ++c) missing.push_back(lower);
  for (int c = multiplicity_count(curve.knots, upper); c < p; ++c) missing.push_back(upper);
  const CurveRows refined = refine(curve, missing);
  const auto& t = refined.knots;
  // k2: last index of `lower` (the first span of the piece starts there);
  // u1: first index of `upper` (the last span ends there).
  const int k2 = static_cast<int>(std::upper_bound(t.begin(), t.end(), lower) - t.begin()) - 1;
  const int u1 = static_cast<int>(std::lower_bound(t.begin(), t.end(), upper) - t.begin());
  assert(k2 >= p && u1 > k2);
  CurveRows out;
  out.degree = p;
  out.rational = curve.rational;
  out.width = curve.width;
  out.knots.assign(static_cast<std::size_t>(p + 1), lower);
  out.knots.insert(out.knots.end(), t.begin() + k2 + 1, t.begin() + u1);
  out.knots.insert(out.knots.end(), static_cast<std::size_t>(p + 1), upper);
  out.rows.assign(refined.rows.begin() + static_cast<std::ptrdiff_t>(k2 - p) * curve.width,
                  refined.rows.begin() + static_cast<std::ptrdiff_t>(u1) * curve.width);
  return out;
}

}  // namespace detail

namespace {

using detail::number_text;

std::string domain_text(const BSplineCurve& curve) {
  return "[" + number_text(curve.domain().lower) + ", " + number_text(curve.domain().upper) + "]";
}

/// Checks the new knots (named `what` i) and returns them sorted.
Expected<std::vector<double>> checked_new_knots(const BSplineCurve& curve, std::span<const double> new_knots,
                                                const std::string& what) {
  const Interval domain = curve.domain();
  for (std::size_t i = 0; i < new_knots.size(); ++i) {
    const std::string name = new_knots.size() == 1 ? what : what + " " + std::to_string(i);
    if (auto ok = check_finite(new_knots[i], name); !ok) return ok.error();
    if (!domain.contains(new_knots[i]))
      return Error{name + " (" + number_text(new_knots[i]) + ") is outside the domain " + domain_text(curve), ErrorKind::out_of_domain};
  }
  if (curve.control_points().size() + new_knots.size() > tolerances::kMaxControlPoints)
    return Error{"inserting " + std::to_string(new_knots.size()) + " knots would give more than " +
                 std::to_string(tolerances::kMaxControlPoints) + " control points", ErrorKind::limit};
  std::vector<double> sorted(new_knots.begin(), new_knots.end());
  std::sort(sorted.begin(), sorted.end());
  const int p = curve.degree();
  for (std::size_t i = 0; i < sorted.size();) {
    std::size_t j = i;
    while (j < sorted.size() && sorted[j] == sorted[i]) ++j;
    const int have = detail::multiplicity_count(curve.knots(), sorted[i]);
    const int total = have + static_cast<int>(j - i);
    if (total > p + 1)
      return Error{"inserting " + std::to_string(j - i) + " x " + number_text(sorted[i]) +
                   " would give that knot multiplicity " + std::to_string(total) + " (it has " +
                   std::to_string(have) + "), above degree + 1 = " + std::to_string(p + 1)};
    i = j;
  }
  if (auto spans = check_added_knot_spans(curve.knots(), sorted, what); !spans) return spans.error();
  return sorted;
}

}  // namespace

Expected<BSplineCurve> refine_knots(const BSplineCurve& curve, std::span<const double> new_knots) {
  auto sorted = checked_new_knots(curve, new_knots, "new knot");
  if (!sorted) return sorted.error();
  if (sorted->empty()) return curve;
  return detail::curve_of(detail::refine(detail::rows_of(curve), *sorted));
}

Expected<BSplineCurve> insert_knot(const BSplineCurve& curve, double u, int times) {
  if (times < 0) return Error{"a knot cannot be inserted " + std::to_string(times) + " times, the count must be >= 0"};
  if (times > static_cast<int>(tolerances::kMaxControlPoints))
    return Error{"inserting a knot " + std::to_string(times) + " times is above the limit of " +
                 std::to_string(tolerances::kMaxControlPoints) + " control points", ErrorKind::limit};
  // Also checked for times = 0, so that a bad u is reported whatever the count.
  const double one[] = {u};
  if (auto ok = checked_new_knots(curve, one, "knot to insert"); !ok) return ok.error();
  if (times == 0) return curve;
  const std::vector<double> copies(static_cast<std::size_t>(times), u);
  auto sorted = checked_new_knots(curve, copies, "knot to insert");
  if (!sorted) return sorted.error();
  return detail::curve_of(detail::refine(detail::rows_of(curve), *sorted));
}

}  // namespace casteljau
