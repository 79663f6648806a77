// Point inversion on surfaces (point_inversion.hpp): grid samples along the
// knot lines, then damped Newton on the gradient of |S - q|^2 / 2 from the
// nearest local minima of the grid, kept inside the domain.
#include "casteljau/ops/point_inversion.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "casteljau/core/model_numbers.hpp"
#include "casteljau/core/tolerance.hpp"

namespace casteljau {
namespace {

// Samples per knot span, and in all per direction at least and at most
// (the grid is evaluated once per query: from 33 x 33 to 129 x 129 points).
constexpr int kSamplesPerSpan = 4;
constexpr std::size_t kMinSamplesPerDirection = 33;
constexpr std::size_t kMaxSamplesPerDirection = 129;
// Newton starts at most (see closest_point).
constexpr std::size_t kStarts = 32;

/// The sample parameters of one direction: every breakpoint, each span cut
/// in kSamplesPerSpan or more (at least kMinSamplesPerDirection in all;
/// fewer per span when there are many spans; uniform beyond the cap).
std::vector<double> samples_of(const std::vector<double>& breaks) {
  const std::size_t spans = breaks.size() - 1;
  std::vector<double> result;
  if (spans + 1 > kMaxSamplesPerDirection) {
    const Interval domain{breaks.front(), breaks.back()};
    for (std::size_t i = 0; i < kMaxSamplesPerDirection; ++i)
      result.push_back(domain.lerp(static_cast<double>(i) / static_cast<double>(kMaxSamplesPerDirection - 1)));
    return result;
  }
  const std::size_t wanted = std::max<std::size_t>(kSamplesPerSpan, (kMinSamplesPerDirection - 1 + spans - 1) / spans);
  const int per = static_cast<int>(std::max<std::size_t>(1, std::min(wanted, (kMaxSamplesPerDirection - 1) / spans)));
  for (std::size_t k = 0; k < spans; ++k) {
    const Interval span{breaks[k], breaks[k + 1]};
    for (int i = 0; i < per; ++i) result.push_back(span.lerp(static_cast<double>(i) / per));
  }
  result.push_back(breaks.back());
  return result;
}

double squared_distance(std::span<const double> p, std::span<const double> q) {
  double sum = 0.0;
  for (std::size_t j = 0; j < p.size(); ++j) sum += (p[j] - q[j]) * (p[j] - q[j]);
  return sum;
}

double dot(const Point& a, const Point& b) {
  double sum = 0.0;
  for (std::size_t j = 0; j < a.size(); ++j) sum += a[j] * b[j];
  return sum;
}

struct Candidate {
  double u, v, g;  // g = |S - q|^2
};

/// Whether the surface closes on itself across the two borders of a
/// direction (a seam: S(lower, t) = S(upper, t) along the other direction,
/// within rounding of its size), sampled at 9 parameters.
bool closed_in(SurfaceView surface, bool along_u) {
  const Interval du = surface.domain_u(), dv = surface.domain_v();
  double gap = 0.0, size = 0.0;
  for (int k = 0; k <= 8; ++k) {
    const double t = (along_u ? dv : du).lerp(k / 8.0);
    const Point a = along_u ? surface.point_at(du.lower, t) : surface.point_at(t, dv.lower);
    const Point b = along_u ? surface.point_at(du.upper, t) : surface.point_at(t, dv.upper);
    for (std::size_t j = 0; j < a.size(); ++j) {
      gap = std::max(gap, std::abs(a[j] - b[j]));
      size = std::max(size, std::abs(a[j]));
    }
  }
  return gap <= tolerances::kJointRelativeGap * std::max(size, tolerances::kScaleFloor);
}

/// u + step inside the domain: wrapped across a seam, else clamped to the border.
double moved(Interval domain, bool closed, double u, double step) {
  const double next = u + step;
  if (!closed || domain.contains(next)) return domain.clamp(next);
  const double width = domain.length();
  double offset = std::fmod(next - domain.lower, width);
  if (offset < 0.0) offset += width;
  return domain.clamp(domain.lower + offset);
}

/// Damped Newton on the gradient of |S - q|^2 / 2 from (u, v), inside the
/// domain (across a seam where the surface closes).
Candidate descend(SurfaceView surface, std::span<const double> q, double u, double v, bool closed_u, bool closed_v) {
  const Interval du = surface.domain_u(), dv = surface.domain_v();
  Point s = surface.point_at(u, v);
  double g = squared_distance(s, q);
  for (int iteration = 0; iteration < 50 && g > 0.0; ++iteration) {
    const Point su = surface.partial_derivative_at(u, v, 1, 0), sv = surface.partial_derivative_at(u, v, 0, 1);
    const Point suu = surface.partial_derivative_at(u, v, 2, 0), suv = surface.partial_derivative_at(u, v, 1, 1);
    const Point svv = surface.partial_derivative_at(u, v, 0, 2);
    Point d(s.size());
    for (std::size_t j = 0; j < s.size(); ++j) d[j] = s[j] - q[j];
    const double gu = dot(su, d), gv = dot(sv, d);
    const double a = dot(su, su) + dot(d, suu), b = dot(su, sv) + dot(d, suv), c = dot(sv, sv) + dot(d, svv);
    // A parameter on a border whose gradient points out of the domain stays there.
    const bool fixed_u = !closed_u && ((u <= du.lower && gu > 0.0) || (u >= du.upper && gu < 0.0));
    const bool fixed_v = !closed_v && ((v <= dv.lower && gv > 0.0) || (v >= dv.upper && gv < 0.0));
    if (fixed_u && fixed_v) break;
    const double scale = std::max({std::abs(a), std::abs(c), tolerances::kScaleFloor});
    bool improved = false;
    for (double lambda = 0.0; lambda <= 1e12 * scale; lambda = lambda == 0.0 ? 1e-9 * scale : lambda * 10.0) {
      double step_u = 0.0, step_v = 0.0;
      if (fixed_u) {
        step_v = c + lambda > 0.0 ? -gv / (c + lambda) : 0.0;
      } else if (fixed_v) {
        step_u = a + lambda > 0.0 ? -gu / (a + lambda) : 0.0;
      } else {
        const double aa = a + lambda, cc = c + lambda, det = aa * cc - b * b;
        if (!(aa > 0.0 && det > 0.0)) continue;  // not a descent direction yet: more damping
        step_u = (-gu * cc + b * gv) / det;
        step_v = (-gv * aa + b * gu) / det;
      }
      const double u1 = moved(du, closed_u, u, step_u), v1 = moved(dv, closed_v, v, step_v);
      if (u1 == u && v1 == v) break;
      const Point s1 = surface.point_at(u1, v1);
      const double g1 = squared_distance(s1, q);
      // Near the minimum g is flat to rounding: an undamped Newton step that
      // does not make it worse beyond rounding still brings the parameters home.
      if (g1 < g || (lambda == 0.0 && g1 <= g * (1.0 + 8 * 2.220446049250313e-16))) {
        const bool settled = std::abs(u1 - u) <= 4 * 2.220446049250313e-16 * std::max(1.0, std::abs(u)) &&
                             std::abs(v1 - v) <= 4 * 2.220446049250313e-16 * std::max(1.0, std::abs(v));
        u = u1, v = v1, g = g1, s = s1;
        improved = !settled;
        break;
      }
    }
    if (!improved) break;
  }
  return {u, v, g};
}

}  // namespace

Expected<SurfaceNearestPoint> closest_point(SurfaceView surface, std::span<const double> query) {
  const int d = surface.dimension();
  if (static_cast<int>(query.size()) != d)
    return Error{"the query point has " + std::to_string(query.size()) + " coordinates, the surface lives in R^" +
                 std::to_string(d)};
  for (std::size_t j = 0; j < query.size(); ++j)
    if (Status status = check_coordinate(query[j], "coordinate " + std::to_string(j) + " of the query point"); !status)
      return status.error();
  const std::vector<double> us = samples_of(surface.breakpoints_u()), vs = samples_of(surface.breakpoints_v());
  std::vector<double> grid(us.size() * vs.size() * static_cast<std::size_t>(d));
  surface.grid_points_at(us, vs, grid);
  const std::size_t nu = us.size(), nv = vs.size();
  std::vector<double> g(nu * nv);
  for (std::size_t k = 0; k < g.size(); ++k)
    g[k] = squared_distance(std::span<const double>(grid).subspan(k * d, static_cast<std::size_t>(d)), query);
  // Starts: every sample that may be the nearest to the nearest point. That
  // point lies inside a grid cell, within the largest spacing h between
  // neighbouring samples of one of its corners (half the cell's diagonal and
  // the bulge of the surface over it), whose distance is then at most the
  // nearest point's + h: the samples within the nearest sample's + h, the
  // grid's local minima among them first (one per basin), then by distance,
  // at most kStarts.
  double spacing = 0.0;
  const auto at = [&](std::size_t i, std::size_t j) { return std::span<const double>(grid).subspan((i * nv + j) * d, static_cast<std::size_t>(d)); };
  for (std::size_t i = 0; i < nu; ++i)
    for (std::size_t j = 0; j < nv; ++j) {
      if (i + 1 < nu) spacing = std::max(spacing, squared_distance(at(i, j), at(i + 1, j)));
      if (j + 1 < nv) spacing = std::max(spacing, squared_distance(at(i, j), at(i, j + 1)));
    }
  const double best_sample = std::sqrt(*std::min_element(g.begin(), g.end()));
  const double margin = best_sample + std::sqrt(spacing);
  struct Start {
    Candidate at;
    bool minimum;
  };
  std::vector<Start> starts;
  for (std::size_t i = 0; i < nu; ++i)
    for (std::size_t j = 0; j < nv; ++j) {
      const double here = g[i * nv + j];
      if (std::sqrt(here) > margin) continue;
      bool lowest = true;
      for (int di = -1; di <= 1 && lowest; ++di)
        for (int dj = -1; dj <= 1 && lowest; ++dj) {
          const long ii = static_cast<long>(i) + di, jj = static_cast<long>(j) + dj;
          if ((di == 0 && dj == 0) || ii < 0 || jj < 0 || ii >= static_cast<long>(nu) || jj >= static_cast<long>(nv)) continue;
          if (g[static_cast<std::size_t>(ii) * nv + static_cast<std::size_t>(jj)] < here) lowest = false;
        }
      starts.push_back({{us[i], vs[j], here}, lowest});
    }
  std::sort(starts.begin(), starts.end(), [](const Start& x, const Start& y) {
    return x.minimum != y.minimum ? x.minimum : x.at.g < y.at.g;
  });
  Candidate best{0.0, 0.0, INFINITY};
  for (const Start& start : starts)
    if (start.at.g < best.g) best = start.at;
  const bool closed_u = closed_in(surface, true), closed_v = closed_in(surface, false);
  for (std::size_t k = 0; k < std::min(kStarts, starts.size()); ++k) {
    const Candidate found = descend(surface, query, starts[k].at.u, starts[k].at.v, closed_u, closed_v);
    if (found.g < best.g) best = found;
  }
  SurfaceNearestPoint result;
  result.u = best.u;
  result.v = best.v;
  result.point = surface.point_at(best.u, best.v);
  result.distance = std::sqrt(squared_distance(result.point, query));
  return result;
}

}  // namespace casteljau
