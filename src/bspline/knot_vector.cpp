// Knot vectors: validation, builders, multiplicities, the Rhino convention.
#include "casteljau/bspline/knot_vector.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <string>

#include "casteljau/core/model_numbers.hpp"
#include "casteljau/core/point_array.hpp"
#include "../core/number_text.hpp"

namespace casteljau {
namespace {

using detail::number_text;

std::string knot_text(std::size_t index, double value) {
  return "knot " + std::to_string(index) + " (" + number_text(value) + ")";
}

// The shared checks of validate_knots, knots_from_rhino and
// check_knot_structure; `offset` maps an index of `knots` to the index the
// caller knows (the Rhino vector lacks the first knot, so its indices are one
// less). With `ranges`, every knot must also be a valid knot (check_knot) and
// every non-empty span at least tolerances::kMinKnotSpan wide (check_span).
Status check_knots(std::span<const double> knots, int degree, std::size_t expected_count,
                   std::ptrdiff_t offset, const char* convention, bool ranges) {
  if (knots.size() != expected_count) {
    return Error{std::to_string(knots.size()) + " knots given, " + convention + " needs " +
                 std::to_string(expected_count) + " (control points + degree + 1)"};
  }
  const auto index = [&](std::size_t i) { return static_cast<std::size_t>(static_cast<std::ptrdiff_t>(i) + offset); };
  for (std::size_t i = 0; i < knots.size(); ++i) {
    // The Rhino input does not contain the two outermost (copied) knots.
    if (offset != 0 && (i == 0 || i + 1 == knots.size())) continue;
    if (ranges ? is_valid_knot(knots[i]) : std::isfinite(knots[i])) continue;  // the name only for a failure
    const std::string name = "knot " + std::to_string(index(i));
    return ranges ? check_knot(knots[i], name) : check_finite(knots[i], name);
  }
  int run = 1;
  for (std::size_t i = 1; i < knots.size(); ++i) {
    if (knots[i] < knots[i - 1]) {
      return Error{knot_text(index(i), knots[i]) + " is smaller than " + knot_text(index(i - 1), knots[i - 1]) +
                   ", knots must be non-decreasing"};
    }
    run = knots[i] == knots[i - 1] ? run + 1 : 1;
    if (run > degree + 1) {
      return Error{knot_text(index(i), knots[i]) + " has multiplicity " + std::to_string(run) +
                   ", above degree + 1 = " + std::to_string(degree + 1)};
    }
  }
  const std::size_t p = static_cast<std::size_t>(degree);
  const std::size_t last = knots.size() - p - 1;  // n + 1
  if (!(knots[p] < knots[last])) {
    const std::string a = std::to_string(index(p));
    const std::string b = std::to_string(index(last));
    return Error{"the domain [knot " + a + ", knot " + b + "] = [" + number_text(knots[p]) + ", " +
                 number_text(knots[last]) + "] is empty, knot " + a + " must be smaller than knot " + b};
  }
  if (ranges) {
    for (std::size_t i = 1; i < knots.size(); ++i) {
      if (is_valid_span(knots[i - 1], knots[i])) continue;
      return check_span(knots[i - 1], knots[i],
                        "knots " + std::to_string(index(i - 1)) + " and " + std::to_string(index(i)));
    }
  }
  return {};
}

}  // namespace

Status validate_knots(std::span<const double> knots, int degree, std::size_t control_point_count) {
  assert(degree >= 0 && control_point_count >= static_cast<std::size_t>(degree) + 1);
  return check_knots(knots, degree, control_point_count + static_cast<std::size_t>(degree) + 1, 0,
                     "a B-spline of this degree and control point count", true);
}

Status check_added_knot_spans(std::span<const double> knots, std::span<const double> added, const std::string& what) {
  assert(std::is_sorted(knots.begin(), knots.end()) && std::is_sorted(added.begin(), added.end()));
  for (std::size_t i = 0; i < added.size(); ++i) {
    const double u = added[i];
    if (i > 0 && added[i - 1] == u) continue;
    const std::string name = "the " + (added.size() == 1 ? what : what + " " + std::to_string(i));
    // The nearest old knots on each side, by binary search.
    const auto above = std::upper_bound(knots.begin(), knots.end(), u);
    const auto index = static_cast<std::size_t>(above - knots.begin());
    if (above != knots.begin() && !is_valid_span(*(above - 1), u)) {
      return check_span(*(above - 1), u, "knot " + std::to_string(index - 1) + " and " + name);
    }
    if (above != knots.end() && !is_valid_span(u, *above)) {
      return check_span(u, *above, name + " and knot " + std::to_string(index));
    }
    // The next distinct added knot.
    std::size_t next = i + 1;
    while (next < added.size() && added[next] == u) ++next;
    if (next < added.size() && !is_valid_span(u, added[next])) {
      return check_span(u, added[next], "the " + what + "s " + std::to_string(i) + " and " + std::to_string(next));
    }
  }
  return {};
}

Status check_knot_structure(std::span<const double> knots, int degree, std::size_t control_point_count) {
  assert(degree >= 0 && control_point_count >= static_cast<std::size_t>(degree) + 1);
  return check_knots(knots, degree, control_point_count + static_cast<std::size_t>(degree) + 1, 0,
                     "a B-spline of this degree and control point count", false);
}

std::vector<double> clamped_uniform_knots(int degree, std::size_t control_point_count, Interval domain) {
  const std::size_t p = static_cast<std::size_t>(degree);
  assert(degree >= 0 && control_point_count >= p + 1 && domain.lower < domain.upper);
  const std::size_t n = control_point_count - 1;
  const std::size_t spans = n - p + 1;
  std::vector<double> knots(n + p + 2);
  for (std::size_t i = 0; i <= p; ++i) {
    knots[i] = domain.lower;
    knots[n + 1 + i] = domain.upper;
  }
  for (std::size_t j = 1; j < spans; ++j) {
    knots[p + j] = domain.lerp(static_cast<double>(j) / static_cast<double>(spans));
  }
  return knots;
}

std::vector<double> uniform_knots(int degree, std::size_t control_point_count, Interval domain) {
  const std::size_t p = static_cast<std::size_t>(degree);
  assert(degree >= 0 && control_point_count >= p + 1 && domain.lower < domain.upper);
  const std::size_t n = control_point_count - 1;
  const double spans = static_cast<double>(n - p + 1);
  std::vector<double> knots(n + p + 2);
  // t_i = lower + (i - p) h, computed as a fraction of the domain so that
  // t_p and t_{n+1} are exactly its ends.
  for (std::size_t i = 0; i < knots.size(); ++i) {
    const double f = (static_cast<double>(i) - static_cast<double>(p)) / spans;
    knots[i] = f == 1.0 ? domain.upper : domain.lower + f * domain.length();
  }
  return knots;
}

std::vector<double> periodic_knots(int degree, std::size_t distinct_control_point_count, Interval domain) {
  // m distinct points wrapped by p: n + 1 = m + p control points, and the
  // domain [t_p, t_{n+1}] holds m spans, one per distinct point.
  return uniform_knots(degree, distinct_control_point_count + static_cast<std::size_t>(degree), domain);
}

Expected<std::vector<double>> knots_from_rhino(std::span<const double> rhino_knots, int degree,
                                               std::size_t control_point_count) {
  assert(degree >= 0);
  const std::size_t needed = control_point_count + static_cast<std::size_t>(degree) - 1;
  if (degree < 1 || rhino_knots.size() != needed) {
    return Error{std::to_string(rhino_knots.size()) + " knots given, the Rhino/openNURBS convention needs " +
                 std::to_string(needed) + " (control points + degree - 1) and degree >= 1"};
  }
  std::vector<double> knots;
  knots.reserve(needed + 2);
  knots.push_back(rhino_knots.front());
  knots.insert(knots.end(), rhino_knots.begin(), rhino_knots.end());
  knots.push_back(rhino_knots.back());
  if (auto ok = check_knots(knots, degree, needed + 2, -1, "the Rhino/openNURBS convention", true); !ok) {
    return ok.error();
  }
  return knots;
}

std::vector<KnotMultiplicity> knot_multiplicities(std::span<const double> knots) {
  std::vector<KnotMultiplicity> result;
  for (double u : knots) {
    if (!result.empty() && result.back().value == u) {
      ++result.back().multiplicity;
    } else {
      result.push_back({u, 1});
    }
  }
  return result;
}

int multiplicity_of(std::span<const double> knots, double u) {
  int count = 0;
  for (double t : knots) count += t == u ? 1 : 0;
  return count;
}

}  // namespace casteljau
