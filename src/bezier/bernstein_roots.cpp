// Root isolation in the Bernstein basis (bernstein_roots.hpp).
#include "casteljau/bezier/bernstein_roots.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <iterator>
#include <utility>

#include "casteljau/bezier/bernstein.hpp"
#include "casteljau/core/tolerance.hpp"

namespace casteljau {
namespace {

/// Sign changes of the coefficients, zeros skipped.
int sign_changes(std::span<const double> b) {
  int changes = 0;
  double last = 0.0;
  for (const double c : b) {
    if (c == 0.0) continue;
    if (last != 0.0 && (c > 0.0) != (last > 0.0)) ++changes;
    last = c;
  }
  return changes;
}

/// The two halves of b at 1/2 (de Casteljau): left and right, each n + 1.
void halve(std::span<const double> b, std::span<double> left, std::span<double> right, std::span<double> work) {
  const std::size_t n = b.size() - 1;
  std::copy(b.begin(), b.end(), work.begin());
  left[0] = work[0];
  right[n] = work[n];
  for (std::size_t r = 1; r <= n; ++r) {
    for (std::size_t i = 0; i + r <= n; ++i) work[i] = 0.5 * (work[i] + work[i + 1]);
    left[r] = work[0];
    right[n - r] = work[n - r];
  }
}

/// p and p' at t from the coefficients (de Casteljau with the last two rows).
void value_and_slope(std::span<const double> b, double t, std::span<double> work, double& value, double& slope) {
  const std::size_t n = b.size() - 1;
  std::copy(b.begin(), b.end(), work.begin());
  const double s = 1.0 - t;
  slope = 0.0;
  for (std::size_t r = 1; r <= n; ++r) {
    if (r == n) slope = static_cast<double>(n) * (work[1] - work[0]);
    for (std::size_t i = 0; i + r <= n; ++i) work[i] = s * work[i] + t * work[i + 1];
  }
  value = work[0];
}

/// The one root in (0, 1) of the polynomial with coefficients b (ends of
/// opposite signs): Newton inside the bracket, bisection when a step leaves
/// it, until the bracket is down to adjacent doubles or p(s) = 0.
double refine(std::span<const double> b, std::span<double> work) {
  double lo = 0.0, hi = 1.0;
  const bool rising = b.back() > 0.0;
  double s = 0.5, value = 0.0, slope = 0.0;
  for (int iteration = 0; iteration < 200; ++iteration) {
    value_and_slope(b, s, work, value, slope);
    if (value == 0.0) return s;
    ((value > 0.0) == rising ? hi : lo) = s;
    double next = slope != 0.0 ? s - value / slope : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (!(lo < next && next < hi)) break;
    s = next;
  }
  return s;
}

/// Removes the roots at the ends: b_0 = 0 means p = t q with
/// q_j = b_{j+1} n / (j+1) (B_{i,n} = (n/i) t B_{i-1,n-1}); b_n = 0 means
/// p = (1 - t) q with q_i = b_i n / (n - i). Returns how many were removed at
/// the start and at the end. After an exact zero, coefficients within `noise`
/// are taken for zeros too.
std::pair<int, int> deflate(std::vector<double>& b, double noise) {
  int start = 0, end = 0;
  // An exact zero first; then values within the noise count as further
  // zeros (a double root whose second zero rounding lifted off the axis).
  const auto zero = [&](double c, int removed) { return c == 0.0 || (removed > 0 && std::abs(c) <= noise); };
  while (b.size() > 1 && zero(b.front(), start)) {
    const double n = static_cast<double>(b.size() - 1);
    for (std::size_t j = 0; j + 1 < b.size(); ++j) b[j] = b[j + 1] * n / static_cast<double>(j + 1);
    b.pop_back();
    ++start;
  }
  while (b.size() > 1 && zero(b.back(), end)) {
    const double n = static_cast<double>(b.size() - 1);
    for (std::size_t i = 0; i + 1 < b.size(); ++i) b[i] = b[i] * n / (n - static_cast<double>(i));
    b.pop_back();
    ++end;
  }
  return {start, end};
}

/// What the subdivision found on one interval [a, b], in left-to-right order.
struct Finding {
  double a, b;
  double t;          // the root (the middle of [a, b] for a cluster or a flat interval)
  int changes;       // sign changes it accounts for (1 for a refined root)
  bool flat;         // every coefficient within the noise: p is zero there within rounding
};

/// The findings merged into roots. Touching flat intervals form a zone
/// where p is zero within rounding; a root found within one zone width of a
/// zone is part of it (rounding spread it); a zone is one root at its middle:
/// a simple one (multiplicity 1, at its refined value) when it holds one
/// refined crossing and |p'| there is what crossing a zone of that width
/// needs (|p'| w >= noise / 4), else a multiple one at the zone's middle
/// (2 when the sign changes are even, 3 when odd: a tangency, an inflection
/// on the axis).
std::vector<BernsteinRoot> merged(const std::vector<Finding>& findings, std::span<const double> coefficients,
                                  double noise, double resolution) {
  struct Zone {
    double start, end;
    int changes = 0;
    int crossings = 0;     // refined simple roots absorbed
    double crossing = 0.0;  // the last of them
  };
  std::vector<Zone> zones;
  for (const Finding& f : findings) {
    if (!f.flat) continue;
    if (zones.empty() || f.a > zones.back().end + resolution) zones.push_back({f.a, f.b});
    Zone& zone = zones.back();
    zone.end = f.b;
    zone.changes += f.changes;
    if (f.changes == 1) ++zone.crossings, zone.crossing = f.t;
  }
  std::vector<BernsteinRoot> roots;
  for (const Finding& f : findings) {
    if (f.flat) continue;
    bool absorbed = false;
    for (Zone& zone : zones) {
      const double w = std::max(zone.end - zone.start, resolution);
      if (f.t >= zone.start - w && f.t <= zone.end + w) {
        zone.changes += f.changes;
        if (f.changes == 1) ++zone.crossings, zone.crossing = f.t;
        absorbed = true;
        break;
      }
    }
    if (!absorbed) roots.push_back({f.t, f.changes});
  }
  std::vector<double> work(coefficients.size());
  for (const Zone& zone : zones) {
    const double middle = 0.5 * (zone.start + zone.end), w = std::max(zone.end - zone.start, resolution);
    const bool odd = zone.changes % 2 == 1;
    if (odd && zone.crossings == 1) {
      // A simple root whose zone rounding widened, when p' crosses the zone
      // (one-sided zones are about noise / |p'| wide): keep its refined value.
      double value = 0.0, slope = 0.0;
      value_and_slope(coefficients, zone.crossing, work, value, slope);
      if (std::abs(slope) * w >= 0.25 * noise) {
        roots.push_back({zone.crossing, 1});
        continue;
      }
    }
    roots.push_back({middle, odd ? 3 : 2});
  }
  std::sort(roots.begin(), roots.end(), [](const BernsteinRoot& x, const BernsteinRoot& y) { return x.t < y.t; });
  // Two roots closer than rounding can tell apart (each is uncertain by
  // noise / |p'|) are one multiple root that rounding split: a subdivision
  // point may fall between them before any interval there looks flat.
  // At most kMerge apart: roots that close are not told apart by this
  // function whatever their slopes (it keeps a multiple root's zone from
  // swallowing distinct neighbours).
  constexpr double kMerge = 1e-7;
  auto uncertainty = [&](const BernsteinRoot& root) {
    if (root.multiplicity > 1) return resolution;
    double value = 0.0, slope = 0.0;
    value_and_slope(coefficients, root.t, work, value, slope);
    return slope != 0.0 ? std::min(noise / std::abs(slope), kMerge) : kMerge;
  };
  std::vector<BernsteinRoot> result;
  double last_uncertainty = 0.0;
  for (const BernsteinRoot& root : roots) {
    const double here = uncertainty(root);
    if (!result.empty() && root.t - result.back().t <= std::max(resolution, last_uncertainty + here)) {
      BernsteinRoot& previous = result.back();
      // The same root seen from both sides of a subdivision point lands within
      // a few ulps of itself; a multiple root that rounding split lies further apart.
      const bool exact = root.t - previous.t <= 64 * 2.220446049250313e-16 * std::max(1e-300, std::abs(root.t));
      previous.multiplicity = exact ? std::max(previous.multiplicity, root.multiplicity)
                                    : previous.multiplicity + root.multiplicity;
      if (!exact) previous.t = 0.5 * (previous.t + root.t);
      last_uncertainty = std::max(last_uncertainty, here);
      continue;
    }
    result.push_back(root);
    last_uncertainty = here;
  }
  return result;
}

}  // namespace

double bernstein_value(std::span<const double> coefficients, double t) {
  std::vector<double> work(coefficients.begin(), coefficients.end());
  double value = 0.0, slope = 0.0;
  value_and_slope(coefficients, t, work, value, slope);
  return value;
}

std::vector<double> bernstein_product(std::span<const double> p, std::span<const double> q) {
  assert(!p.empty() && !q.empty());
  const int m = static_cast<int>(p.size()) - 1, n = static_cast<int>(q.size()) - 1;
  std::vector<double> c(static_cast<std::size_t>(m + n + 1), 0.0);
  // The binomials of q's row once, on the stack for the usual degrees (the
  // same products, in the same order, as one lookup per term).
  double small[32];
  std::vector<double> large;
  double* row = small;
  if (q.size() > std::size(small)) {
    large.resize(q.size());
    row = large.data();
  }
  for (int j = 0; j <= n; ++j) row[j] = binomial(n, j);
  for (int i = 0; i <= m; ++i) {
    const double left = binomial(m, i);
    for (int j = 0; j <= n; ++j) c[i + j] += left * row[j] * p[i] * q[j];
  }
  for (int k = 0; k <= m + n; ++k) c[k] /= binomial(m + n, k);
  return c;
}

std::vector<BernsteinRoot> bernstein_roots(std::span<const double> coefficients, double resolution) {
  assert(!coefficients.empty() && resolution > 0.0);
  double largest = 0.0;
  for (const double c : coefficients) largest = std::max(largest, std::abs(c));
  if (largest == 0.0) return {};
  // Values below this are zero within the rounding of the coefficients and
  // of de Casteljau's subdivision (a few ulps per level of n).
  const double noise = tolerances::kRoundingSlack * static_cast<double>(coefficients.size()) * largest;
  std::vector<Finding> findings;
  // Depth first over dyadic intervals, left half first, so findings come in order.
  struct Part {
    double a, b;
    std::vector<double> coefficients;  // of p on [a, b], in its local parameter
  };
  std::vector<Part> stack;
  stack.push_back({0.0, 1.0, {coefficients.begin(), coefficients.end()}});
  std::vector<double> work(coefficients.size()), left(coefficients.size()), right(coefficients.size());
  while (!stack.empty()) {
    Part part = std::move(stack.back());
    stack.pop_back();
    const auto [at_start, at_end] = deflate(part.coefficients, noise);
    if (at_start > 0) findings.push_back({part.a, part.a, part.a, at_start, false});
    const std::span<const double> b(part.coefficients);
    const int changes = b.size() > 1 ? sign_changes(b) : 0;
    double nearest = INFINITY, farthest = 0.0;
    for (const double c : b) nearest = std::min(nearest, std::abs(c)), farthest = std::max(farthest, std::abs(c));
    const double middle = 0.5 * (part.a + part.b);
    const bool splittable = part.b - part.a > resolution && part.a < middle && middle < part.b;
    if (b.size() > 1 && farthest <= noise) {
      // A flat interval with one sign change holds the crossing: refined, it
      // places a simple root whose zone rounding made flat.
      const double t = changes == 1 ? part.a + refine(b, work) * (part.b - part.a) : middle;
      findings.push_back({part.a, part.b, t, changes, true});
    } else if (changes == 1 && (!splittable || (std::abs(b.front()) > noise && std::abs(b.back()) > noise))) {
      findings.push_back({part.a, part.b, part.a + refine(b, work) * (part.b - part.a), 1, false});
    } else if (changes >= 1 || (changes == 0 && b.size() > 1 && nearest <= noise)) {
      // (One sign change with p nearly zero at an end: a tangency may sit on
      // that end beside the crossing; the halves tell them apart.)
      if (!splittable) {
        if (changes >= 2) findings.push_back({part.a, part.b, middle, changes, false});
      } else {
        const std::size_t size = b.size();
        halve(b, std::span<double>(left.data(), size), std::span<double>(right.data(), size), work);
        // The right half first on the stack, so that the left one is visited first.
        if (at_end > 0) {
          // The end root after the halves: a part of its own that deflation reports.
          std::vector<double> root(static_cast<std::size_t>(at_end), 0.0);
          root.push_back(1.0);
          stack.push_back(Part{part.b, part.b, std::move(root)});
        }
        stack.push_back({middle, part.b, {right.begin(), right.begin() + static_cast<std::ptrdiff_t>(size)}});
        stack.push_back({part.a, middle, {left.begin(), left.begin() + static_cast<std::ptrdiff_t>(size)}});
        continue;
      }
    }
    if (at_end > 0) findings.push_back({part.b, part.b, part.b, at_end, false});
  }
  return merged(findings, coefficients, noise, resolution);
}

}  // namespace casteljau
