// Intersections against exact answers: every case of the torture corpus
// (tests/support/intersection_corpus.hpp: crossings up to 36 between two
// sextics, tangencies of order 2 to 4, overlaps both ways and of sub-arcs and
// elevated copies, shared ends, hits at parameters 0, 1/2, 1, near misses by
// one ulp, nearly parallel lines, loops, cusps, self-intersections) solved in
// exact rational arithmetic by tests/support/exact_intersections.hpp
// (resultants, exact root isolation in GMP), not by the code under test.
//
// How an answer is judged. Exact point intersections closer than 1e-6 in both
// parameters form a cluster (a tangency, or crossings that rounding cannot
// tell apart: the parabola 2^-52 above a line crosses it at 1/2 +- 2^-27).
// A cluster is found when our answers inside it are its points one for one
// with their kinds and multiplicities, or one tangency whose multiplicity is
// the cluster's total (the crossings merged within rounding). None inside is
// a miss; more than the cluster's points is a double; anything else a
// misclassification. An answer in no cluster is spurious unless it is a
// tangency where the curves come within the tolerance (a near miss by an
// ulp is a contact at any tolerance users ask for); likewise an overlap is
// spurious unless the curves stay within the tolerance all along it (a copy
// moved by 2^-50), the exact points on its stretch then belonging to it.
// Exact overlaps must be found with their intervals and direction. Simple crossings are also measured in ulps
// against the exact isolating intervals.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "casteljau/ops/closest_point.hpp"
#include "casteljau/ops/intersection.hpp"
#include "support/exact_intersections.hpp"
#include "support/intersection_corpus.hpp"

namespace casteljau {
namespace {

using test::ExactBezier;
using test::ExactIntersection;
using ExactKind = ExactIntersection::Kind;

BezierCurve as_curve(const ExactBezier& exact) {
  std::vector<double> coordinates;
  for (const auto& p : test::control_points_as_doubles(exact)) coordinates.insert(coordinates.end(), p.begin(), p.end());
  return BezierCurve::make(PointArray::make(2, coordinates).value()).value();
}

/// The same curve in the plane z = x of R^3 (exactly: z copies x), where it
/// meets the other curve where the plane curves meet.
BezierCurve in_space(const ExactBezier& exact) {
  std::vector<double> coordinates;
  for (const auto& p : test::control_points_as_doubles(exact)) coordinates.insert(coordinates.end(), {p[0], p[1], p[0]});
  return BezierCurve::make(PointArray::make(3, coordinates).value()).value();
}

IntersectionKind kind_of(ExactKind kind) {
  return kind == ExactKind::transversal ? IntersectionKind::transversal
                                        : kind == ExactKind::tangent ? IntersectionKind::tangent : IntersectionKind::overlap;
}

struct Tally {
  int cases = 0, exact_points = 0, exact_overlaps = 0;
  int missed = 0, doubled = 0, misclassified = 0, spurious = 0, near_contacts = 0, near_overlaps = 0, merged_clusters = 0;
  double worst_ulps = 0.0;
};

constexpr double kCluster = 1e-6;

/// `space`: the curves were embedded in R^3, where a tangency's multiplicity
/// is 2 or 3 (3 standing for every contact of order 3 or more).
void judge(const std::string& name, const BezierCurve& a, const BezierCurve* b, const std::vector<ExactIntersection>& exact,
           const std::vector<CurveIntersection>& ours, double tolerance, Tally& tally, bool space = false) {
  ++tally.cases;
  // Overlaps.
  std::vector<bool> used(ours.size(), false);
  for (const ExactIntersection& e : exact) {
    if (e.kind != ExactKind::overlap) continue;
    ++tally.exact_overlaps;
    const double a0 = mpq_class(e.a_lower).get_d(), a1 = mpq_class(e.a_upper).get_d();
    const double b0 = (e.reversed ? e.b_upper : e.b_lower).get_d(), b1 = (e.reversed ? e.b_lower : e.b_upper).get_d();
    bool found = false;
    for (std::size_t i = 0; i < ours.size(); ++i) {
      const CurveIntersection& x = ours[i];
      if (used[i] || x.kind != IntersectionKind::overlap) continue;
      if (std::abs(x.a.lower - a0) <= 1e-12 && std::abs(x.a.upper - a1) <= 1e-12 && std::abs(x.b.lower - b0) <= 1e-12 &&
          std::abs(x.b.upper - b1) <= 1e-12) {
        used[i] = found = true;
        break;
      }
    }
    if (!found) {
      ++tally.missed;
      ADD_FAILURE() << name << ": overlap a [" << a0 << ", " << a1 << "] b [" << b0 << ", " << b1 << "] not found";
    }
  }
  // An overlap where the exact curves are distinct but stay within the
  // tolerance of each other all along (a copy moved by 2^-50) is one within
  // the tolerance: the exact points on its stretch belong to it.
  std::vector<Interval> near_overlaps;
  for (std::size_t i = 0; i < ours.size(); ++i) {
    if (used[i] || ours[i].kind != IntersectionKind::overlap) continue;
    used[i] = true;
    bool within = b != nullptr;
    for (int k = 0; k <= 32 && within; ++k) {
      const Point p = point_at(a, ours[i].a.lerp(k / 32.0));
      within = closest_point(*b, p).value().distance <= tolerance;
    }
    if (within) {
      ++tally.near_overlaps;
      std::printf("  %s: an overlap within the tolerance, a [%g, %g]\n", name.c_str(), ours[i].a.lower, ours[i].a.upper);
      near_overlaps.push_back(ours[i].a);
      continue;
    }
    ++tally.spurious;
    ADD_FAILURE() << name << ": overlap a [" << ours[i].a.lower << ", " << ours[i].a.upper << "] is not one";
  }
  // Point clusters.
  std::vector<const ExactIntersection*> points;
  for (const ExactIntersection& e : exact) {
    const double at = test::exact_estimate(e.a_lower, e.a_upper);
    const bool subsumed = std::any_of(near_overlaps.begin(), near_overlaps.end(), [&](Interval o) { return o.contains(at); });
    if (e.kind != ExactKind::overlap && !subsumed) points.push_back(&e);
  }
  tally.exact_points += static_cast<int>(points.size());
  const auto estimate_a = [](const ExactIntersection* e) { return test::exact_estimate(e->a_lower, e->a_upper); };
  const auto estimate_b = [](const ExactIntersection* e) { return test::exact_estimate(e->b_lower, e->b_upper); };
  std::sort(points.begin(), points.end(), [&](auto x, auto y) { return estimate_a(x) < estimate_a(y); });
  std::vector<std::vector<const ExactIntersection*>> clusters;
  for (const ExactIntersection* e : points) {
    bool joined = false;
    for (auto& cluster : clusters)
      for (const ExactIntersection* f : cluster)
        if (!joined && std::abs(estimate_a(e) - estimate_a(f)) <= kCluster &&
            std::abs(estimate_b(e) - estimate_b(f)) <= kCluster) {
          cluster.push_back(e);
          joined = true;
        }
    if (!joined) clusters.push_back({e});
  }
  for (const auto& cluster : clusters) {
    int total = 0;
    for (const ExactIntersection* e : cluster) total += e->multiplicity;
    // In space a contact of order k is located within its zone, where the
    // curves stay within the tolerance: about (tolerance / size)^(1/k) wide.
    const double radius = space && total >= 2 ? std::max(kCluster, std::pow(1e-9, 1.0 / total)) : kCluster;
    std::vector<std::size_t> inside;
    for (std::size_t i = 0; i < ours.size(); ++i) {
      if (used[i]) continue;
      const bool near = std::any_of(cluster.begin(), cluster.end(), [&](const ExactIntersection* e) {
        return std::abs(ours[i].a.lower - estimate_a(e)) <= radius && std::abs(ours[i].b.lower - estimate_b(e)) <= radius;
      });
      if (near) inside.push_back(i);
    }
    for (const std::size_t i : inside) used[i] = true;
    const std::string where = name + " at a = " + std::to_string(estimate_a(cluster.front()));
    if (inside.empty()) {
      ++tally.missed;
      ADD_FAILURE() << where << ": missed (" << cluster.size() << " exact points, multiplicity " << total << ")";
      continue;
    }
    if (inside.size() == cluster.size()) {
      bool same = true;
      for (std::size_t k = 0; k < inside.size(); ++k) {
        const CurveIntersection& x = ours[inside[k]];
        const ExactIntersection& e = *cluster[k];
        const int multiplicity = space ? std::min(e.multiplicity, 3) : e.multiplicity;
        if (x.kind != kind_of(e.kind) || (x.kind == IntersectionKind::tangent && x.multiplicity != multiplicity))
          same = false;
        if (e.kind == ExactKind::transversal)
          tally.worst_ulps = std::max({tally.worst_ulps, test::ulps_from(e.a_lower, e.a_upper, x.a.lower),
                                       test::ulps_from(e.b_lower, e.b_upper, x.b.lower)});
      }
      if (!same) {
        ++tally.misclassified;
        ADD_FAILURE() << where << ": ours " << kind_name(ours[inside[0]].kind) << " multiplicity "
                      << ours[inside[0]].multiplicity << ", exact " << kind_name(kind_of(cluster[0]->kind))
                      << " multiplicity " << cluster[0]->multiplicity;
      }
      continue;
    }
    if (inside.size() == 1 && cluster.size() > 1 && ours[inside[0]].kind == IntersectionKind::tangent &&
        ours[inside[0]].multiplicity == (space ? std::min(total, 3) : total)) {
      ++tally.merged_clusters;
      continue;
    }
    if (inside.size() > cluster.size()) {
      ++tally.doubled;
      ADD_FAILURE() << where << ": " << inside.size() << " answers for " << cluster.size() << " exact points";
    } else {
      ++tally.misclassified;
      ADD_FAILURE() << where << ": " << inside.size() << " answers for " << cluster.size() << " exact points of total multiplicity "
                    << total;
    }
  }
  for (std::size_t i = 0; i < ours.size(); ++i) {
    if (used[i]) continue;
    const CurveIntersection& x = ours[i];
    // How near the curves come there: to the other curve, or for a
    // self-contact between the curve's two parameters.
    double gap = 0.0;
    if (b) {
      gap = closest_point(*b, x.point).value().distance;
    } else {
      const Point p = point_at(a, x.a.lower), q = point_at(a, x.b.lower);
      for (std::size_t j = 0; j < p.size(); ++j) gap += (p[j] - q[j]) * (p[j] - q[j]);
      gap = std::sqrt(gap);
    }
    if (x.kind == IntersectionKind::tangent && gap <= tolerance) {
      ++tally.near_contacts;
      std::printf("  %s: a contact within the tolerance at a = %.17g, b = %.17g (gap %.3g)\n", name.c_str(), x.a.lower,
                  x.b.lower, gap);
      continue;
    }
    ++tally.spurious;
    ADD_FAILURE() << name << ": spurious " << kind_name(x.kind) << " at a = " << x.a.lower << ", b = " << x.b.lower;
  }
}

/// Prints the tally (the numbers the closing notes quote) and fails on any
/// miss, double, misclassification or spurious answer.
void report(const char* title, const Tally& tally) {
  std::printf("%s: %d cases, %d exact points, %d overlaps; missed %d, doubled %d, misclassified %d, spurious %d; "
              "%d clusters merged into one tangency, %d contacts and %d overlaps within the tolerance; simple crossings "
              "within %.0f ulps of the exact parameters\n",
              title, tally.cases, tally.exact_points, tally.exact_overlaps, tally.missed, tally.doubled,
              tally.misclassified, tally.spurious, tally.merged_clusters, tally.near_contacts, tally.near_overlaps,
              tally.worst_ulps);
  EXPECT_EQ(tally.missed + tally.doubled + tally.misclassified + tally.spurious, 0);
}

/// Every case of the corpus, its curves made by `make` (in the plane, or
/// embedded in space), judged and tallied.
void run_corpus(BezierCurve (*make)(const ExactBezier&), bool space, Tally& tally) {
  for (const test::IntersectionCase& c : test::intersection_corpus()) {
    const BezierCurve a = make(c.a);
    if (c.b) {
      const BezierCurve b = make(*c.b);
      const Tolerance tolerance = default_intersection_tolerance(a, b);
      const auto ours = intersections(a, b, tolerance);
      ASSERT_TRUE(ours) << c.name << ": " << ours.error().message;
      judge(c.name, a, &b, test::exact_intersections(c.a, *c.b), *ours, tolerance.distance, tally, space);
    } else {
      const Tolerance tolerance = default_intersection_tolerance(a, a);
      const auto ours = self_intersections(a, tolerance);
      ASSERT_TRUE(ours) << c.name << ": " << ours.error().message;
      // The contract leaves out a closed curve's seam, its pair (0, 1): the
      // exact answer lists every pair s < t with a(s) = a(t).
      std::vector<ExactIntersection> exact = test::exact_self_intersections(c.a);
      std::erase_if(exact, [](const ExactIntersection& e) {
        return e.kind != ExactIntersection::Kind::overlap && e.a_upper == 0 && e.b_lower == 1;
      });
      judge(c.name, a, nullptr, exact, *ours, tolerance.distance, tally, space);
    }
  }
}

TEST(IntersectionCorpus, MatchesTheExactAnswers) {
  Tally tally;
  run_corpus(&as_curve, false, tally);
  report("intersection corpus", tally);
}

// The corpus again, embedded in the plane z = x of R^3: the space path
// (subdivision, Gauss-Newton on the nearest pair, overlaps traced; injective
// parts by the half-space test of the hodograph) must find the same answers
// as the plane one.
TEST(IntersectionCorpus, MatchesTheExactAnswersInSpace) {
  Tally tally;
  run_corpus(&in_space, true, tally);
  report("intersection corpus in space", tally);
}

}  // namespace
}  // namespace casteljau
