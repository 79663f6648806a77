#include "casteljau/render/bernstein_graph.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "casteljau/bezier/bernstein.hpp"
#include "casteljau/core/tolerance.hpp"
#include "casteljau/ops/tolerance.hpp"

namespace casteljau::render {
namespace {

// The furthest-reach search (ratios of steps, not tolerances): a certified
// step within 5 % of the shortest refused one is kept, and so is the longest
// certified one after 16 trials.
constexpr double kReachRatio = 0.95;
constexpr int kMaxReachTrials = 16;

/// The largest value of B_{m,j} on [a, b]: B_{m,j} rises up to its mode j/m
/// and falls after it, so the maximum is at the mode clamped into [a, b].
double largest_on(int m, int j, double a, double b) {
  if (j < 0 || j > m) return 0.0;
  const double mode = m == 0 ? 0.0 : static_cast<double>(j) / m;
  return bernstein(m, j, std::clamp(mode, a, b));
}

/// What the vertical deviation d of a graph from its chord (slope m) is as a
/// distance: every point of the graph lies within d / sqrt(1 + m^2) of the
/// chord's line, and every point of the chord within that of the graph (the
/// graph crosses the chord's normal at the point). The curve's points project
/// inside the chord, so the distance to the line is the distance to the
/// segment, as long as h M |m| <= 2 (1 + m^2) (M bounds |f''|: a point at
/// t - a from an end deviates by at most (t - a) h M / 2 vertically, which
/// moves its projection by at most |m| / (1 + m^2) times that along the
/// chord); otherwise the factor is 1 (the vertical distance always bounds
/// it). The end values are off by up to `rounding`: the slope is taken at its
/// most unfavourable.
double chord_distance_factor(double h, double fa, double fb, double bound, double rounding) {
  const double rise = std::abs(fb - fa);
  const double low = std::max(0.0, rise - 2.0 * rounding) / h, high = (rise + 2.0 * rounding) / h;
  if (!(h * bound * high <= 2.0 * (1.0 + low * low))) return 1.0;
  return 1.0 / std::sqrt(1.0 + low * low);
}

}  // namespace

double bernstein_second_derivative_bound(int n, int k, double a, double b) {
  if (n < 2) return 0.0;
  const double factor = 1.0 + 4.0 * n * tolerances::kRoundingSlack;
  const double c = n * (n - 1.0);
  const double triangle = c * std::max(largest_on(n - 2, k - 2, a, b) + largest_on(n - 2, k, a, b),
                                       2.0 * largest_on(n - 2, k - 1, a, b));
  if (!(a > 0.0 && b < 1.0)) return factor * triangle;
  // g = k/t - (n-k)/(1-t); a term whose exponent is 0 is left out (no 0/0).
  const double left = static_cast<double>(k), right = static_cast<double>(n - k);
  auto g = [&](double t) { return (k == 0 ? 0.0 : left / t) - (k == n ? 0.0 : right / (1.0 - t)); };
  const double ga = g(a), gb = g(b);
  const double slope = (k == 0 ? 0.0 : left / (a * a)) + (k == n ? 0.0 : right / ((1.0 - b) * (1.0 - b)));
  const double logarithmic = largest_on(n, k, a, b) * std::max({ga * ga, gb * gb, slope});
  return factor * std::min(triangle, logarithmic);
}

Expected<std::vector<Vec2>> bernstein_graph_polyline(int n, int k, Tolerance tolerance) {
  if (n < 1 || n > tolerances::kMaxBezierDegree)
    return Error{fmt::format("the degree of a Bernstein polynomial must be in [1, {}], got {}",
                             tolerances::kMaxBezierDegree, n)};
  if (k < 0 || k > n) return Error{fmt::format("B_{{{},{}}} does not exist: the index must be in [0, {}]", n, k, n)};
  // Each vertex value is off by at most 3n ulps of B <= 1 (bernstein()), and
  // so is the chord between two of them: 2 n kRoundingSlack (16 n ulps)
  // covers that with room.
  const double rounding = 2.0 * n * tolerances::kRoundingSlack;
  if (!(std::isfinite(tolerance.distance) && tolerance.distance > tolerances::kFlattenSmallestToleranceFactor * rounding))
    return Error{fmt::format("the tolerance for drawing B_{{{},{}}} must be finite and > {}, got {}", n, k,
                             tolerances::kFlattenSmallestToleranceFactor * rounding, tolerance.distance)};
  const double budget = tolerance.distance - rounding;
  std::vector<Vec2> points{Vec2{{0.0, bernstein(n, k, 0.0)}}};
  double a = 0.0, fa = points[0][1], guess = 1.0;
  while (a < 1.0) {
    // Furthest reach from a: the longest step the bound certifies, to within
    // kReachRatio, by growing from the last step and then narrowing the
    // bracket [certified, refused] (geometrically while it spans more than a
    // factor 4: a step out of a flat tail can grow a thousandfold).
    double certified = 0.0, refused = std::numeric_limits<double>::infinity(), h = guess;
    Vec2 end{};  // the vertex at the end of the certified step
    for (int trial = 0; trial < kMaxReachTrials; ++trial) {
      const double b = a + h >= 1.0 ? 1.0 : a + h;
      if (!(b > a)) break;
      h = b - a;
      const double fb = bernstein(n, k, b);
      const double bound = bernstein_second_derivative_bound(n, k, a, b);
      const double deviation = h * h * bound * chord_distance_factor(h, fa, fb, bound, rounding) / 8.0;
      if (deviation <= budget) {
        certified = h, end = Vec2{{b, fb}};
        if (b == 1.0 || certified >= kReachRatio * refused) break;
      } else {
        refused = h;
        if (certified >= kReachRatio * refused) break;
      }
      if (refused == std::numeric_limits<double>::infinity()) h = 2.0 * h;
      else if (certified == 0.0) h = std::min(0.5 * h, 0.95 * h * std::sqrt(budget / deviation));  // deviation ~ h^2
      else h = refused > 4.0 * certified ? std::sqrt(certified * refused) : 0.5 * (certified + refused);
    }
    if (!(certified > 0.0))
      return Error{fmt::format("cannot certify a segment of B_{{{},{}}} from t = {} in double precision", n, k, a)};
    if (static_cast<long>(points.size()) > tolerances::kMaxFlattenSegments)
      return Error{fmt::format("drawing B_{{{},{}}} needs more than {} segments at this tolerance", n, k,
                               tolerances::kMaxFlattenSegments), ErrorKind::limit};
    points.push_back(end);
    a = end[0], fa = end[1];
    guess = certified;
  }
  return points;
}

}  // namespace casteljau::render
