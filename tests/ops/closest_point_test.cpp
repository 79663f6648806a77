// Closest point against answers known in closed form (a segment, the
// parabola y = x^2, the NURBS circle, queries beyond the ends) with their
// parameter errors in ulps, and against a brute-force oracle: the exact
// minimum over a dense sampling of the curve (every sample visited; chunks
// of consecutive samples are skipped only when their box is farther than the
// best sample), refined by golden-section search beside the best sample. A
// miss is an answer farther than the oracle's by more than 1e-9 of the
// curve's size; 10^5 random queries per curve kind, none may miss.
#include "casteljau/ops/closest_point.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "casteljau/bezier/bezier_curve.hpp"
#include "casteljau/bezier/evaluate.hpp"
#include "casteljau/bezier/piecewise_bezier.hpp"
#include "casteljau/bspline/bspline_curve.hpp"
#include "casteljau/bspline/knot_vector.hpp"
#include "casteljau/nurbs/conics.hpp"
#include "support/bspline_generators.hpp"
#include "support/make.hpp"
#include "support/nearest_oracle.hpp"
#include "support/splitmix.hpp"

namespace casteljau {
namespace {

using test::bezier;

/// Distance between two doubles in units in the last place.
double ulps(double x, double reference) {
  if (x == reference) return 0.0;
  const double spacing = std::nextafter(std::abs(reference), INFINITY) - std::abs(reference);
  return std::abs(x - reference) / spacing;
}

TEST(ClosestPoint, OnASegmentIsTheOrthogonalProjection) {
  const BezierCurve segment = bezier({{0, 0}, {4, 2}});
  // q = (1, 3): t = (q . (4, 2)) / 20 = 1/2, the point (2, 1), distance sqrt(5).
  const NearestPoint nearest = closest_point(segment, std::vector<double>{1, 3}).value();
  EXPECT_EQ(nearest.parameter, 0.5);
  EXPECT_EQ(nearest.point, (Point{2, 1}));
  EXPECT_NEAR(nearest.distance, std::sqrt(5.0), 1e-15);
  // Beyond either end, the end itself, exactly.
  EXPECT_EQ(closest_point(segment, std::vector<double>{-3, -1}).value().parameter, 0.0);
  const NearestPoint beyond = closest_point(segment, std::vector<double>{9, 1}).value();
  EXPECT_EQ(beyond.parameter, 1.0);
  EXPECT_EQ(beyond.point, (Point{4, 2}));
  EXPECT_EQ(beyond.distance, std::sqrt(26.0));
}

TEST(ClosestPoint, OnTheParabolaHasTwoSymmetricMinimaAndEndsWhenBeyond) {
  // (-1, 1), (0, -1), (1, 1): x = 2t - 1, y = x^2. From q = (0, 1) the squared
  // distance x^2 + (x^2 - 1)^2 has minima at x = +-1/sqrt(2) (distance
  // sqrt(3)/2) and a maximum at x = 0; at the ends it grows.
  const BezierCurve parabola = bezier({{-1, 1}, {0, -1}, {1, 1}});
  const std::vector<double> q{0, 1};
  const double left = (1 - std::sqrt(0.5)) / 2, right = (1 + std::sqrt(0.5)) / 2;
  const NearestPoint global = closest_point(parabola, q).value();
  EXPECT_LE(ulps(global.parameter, left), 2.0);  // the tie goes to the lower parameter
  EXPECT_NEAR(global.distance, std::sqrt(3.0) / 2, 1e-15);
  const std::vector<NearestPoint> all = local_closest_points(parabola, q).value();
  ASSERT_EQ(all.size(), 2u);
  EXPECT_LE(ulps(all[0].parameter, left), 2.0);
  EXPECT_LE(ulps(all[1].parameter, right), 2.0);
  // From (2, 5) the distance still falls at x = 1: the end is the answer, exactly.
  const NearestPoint end = closest_point(parabola, std::vector<double>{2, 5}).value();
  EXPECT_EQ(end.parameter, 1.0);
  EXPECT_EQ(end.distance, std::sqrt(17.0));
  // From (0, -1) the vertex: one minimum, t = 1/2.
  const NearestPoint vertex = closest_point(parabola, std::vector<double>{0, -1}).value();
  EXPECT_EQ(vertex.parameter, 0.5);
  EXPECT_EQ(vertex.distance, 1.0);
}

TEST(ClosestPoint, OnTheNurbsCircleIsAlongTheRay) {
  const BSplineCurve circle = make_circle(1.0, -2.0, 3.0).value();
  test::SplitMix random{41};
  double worst_distance = 0.0;
  for (int i = 0; i < 1000; ++i) {
    const double angle = 2 * M_PI * random.unit(), radius = 10 * random.unit();
    const std::vector<double> q{1.0 + radius * std::cos(angle), -2.0 + radius * std::sin(angle)};
    const NearestPoint nearest = closest_point(circle, q).value();
    worst_distance = std::max(worst_distance, std::abs(nearest.distance - std::abs(radius - 3.0)));
    // The nearest point is on the ray from the centre through q.
    const double along = std::atan2(nearest.point[1] + 2.0, nearest.point[0] - 1.0);
    const double gap = std::remainder(along - angle, 2 * M_PI);
    if (radius > 1e-6) {
      EXPECT_LT(std::abs(gap), 1e-9) << "query " << i;
    }
  }
  EXPECT_LT(worst_distance, 1e-13);
  // From the centre every point is at distance 3: the answer is one of them.
  EXPECT_NEAR(closest_point(circle, std::vector<double>{1, -2}).value().distance, 3.0, 1e-14);
}

TEST(ClosestPoint, RefusesBadQueries) {
  const BezierCurve segment = bezier({{0, 0}, {4, 2}});
  EXPECT_EQ(closest_point(segment, std::vector<double>{1, 2, 3}).error().message,
            "the query point has 3 coordinates, the curve lives in R^2");
  EXPECT_EQ(closest_point(segment, std::vector<double>{1, NAN}).error().message,
            "coordinate 1 of the query point is NaN");
  std::vector<double> parameters(2), distances(2);
  const std::vector<double> queries{0, 0, 1, INFINITY};
  EXPECT_EQ(closest_points(segment, queries, parameters, distances).error().message,
            "coordinate 1 of query 1 is infinite");
  EXPECT_FALSE(closest_points(segment, std::vector<double>{0, 0, 1}, parameters, distances));
  EXPECT_FALSE(closest_points(segment, queries, std::span<double>(parameters).first(1), distances));
}

struct OracleResult {
  int missed = 0;
  double worst_miss = 0.0;  // largest (ours - oracle) / size
  double worst_gain = 0.0;  // largest (oracle - ours) / size: where sampling stopped short
};

/// 10^5 queries per kind in the default build; the AddressSanitizer build
/// (a Debug build, ten times slower) runs the first 10^4 of the same stream.
#if defined(__SANITIZE_ADDRESS__)
constexpr int kOracleQueries = 10000;
#else
constexpr int kOracleQueries = 100000;
#endif

/// kOracleQueries queries: 90% uniform in the curve's box grown by half its size on
/// every side, 10% within 1e-6 of its size from a random point of the curve.
/// The batch answers them in one call; some are also checked one by one.
OracleResult against_oracle(CurveView curve, std::uint64_t seed, int count = kOracleQueries);
/// The same for a temporary curve (a CurveView cannot be made of one).
template <class Kind>
OracleResult against_oracle(const Kind& curve, std::uint64_t seed, int count = kOracleQueries) {
  return against_oracle(CurveView(curve), seed, count);
}

OracleResult against_oracle(CurveView curve, std::uint64_t seed, int count) {
  const int d = curve.dimension();
  const test::NearestOracle oracle(curve, 4096 / static_cast<int>(breakpoints(curve).size() - 1) + 64);
  const double size = size_of(curve);
  std::vector<double> lower(d, INFINITY), upper(d, -INFINITY);
  std::vector<double> samples(1001 * static_cast<std::size_t>(d)), us(1001);
  const Interval domain = curve.domain();
  for (int i = 0; i <= 1000; ++i) us[i] = domain.lerp(i / 1000.0);
  points_at(curve, us, samples);
  for (std::size_t i = 0; i < us.size(); ++i)
    for (int j = 0; j < d; ++j)
      lower[j] = std::min(lower[j], samples[i * d + j]), upper[j] = std::max(upper[j], samples[i * d + j]);
  test::SplitMix random{seed};
  std::vector<double> queries(static_cast<std::size_t>(count) * d);
  for (int i = 0; i < count; ++i) {
    if (i % 10 == 9) {
      const Point on = point_at(curve, domain.lerp(random.unit()));
      for (int j = 0; j < d; ++j) queries[i * d + j] = on[j] + 1e-6 * size * (2 * random.unit() - 1);
    } else {
      for (int j = 0; j < d; ++j)
        queries[i * d + j] = lower[j] - size / 2 + (upper[j] - lower[j] + size) * random.unit();
    }
  }
  std::vector<double> parameters(count), distances(count);
  EXPECT_TRUE(closest_points(curve, queries, parameters, distances));
  OracleResult result;
  for (int i = 0; i < count; ++i) {
    const double* q = queries.data() + static_cast<std::ptrdiff_t>(i) * d;
    const double reference = oracle.distance(q);
    const double excess = (distances[i] - reference) / size;
    result.worst_miss = std::max(result.worst_miss, excess);
    result.worst_gain = std::max(result.worst_gain, -excess);
    if (excess > 1e-9) ++result.missed;
    // The reported distance is that of the reported parameter's point.
    const Point p = point_at(curve, parameters[i]);
    double g = 0.0;
    for (int j = 0; j < d; ++j) g += (p[j] - q[j]) * (p[j] - q[j]);
    EXPECT_NEAR(std::sqrt(g), distances[i], 1e-12 * size) << "query " << i;
    if (i % 1000 == 0) {
      const NearestPoint single = closest_point(curve, std::span<const double>(q, d)).value();
      EXPECT_NEAR(single.distance, distances[i], 1e-12 * size) << "query " << i;
    }
  }
  std::printf("closest point oracle: %d queries, %d missed, worst excess %.3g, worst gain %.3g (of the size)\n",
              count, result.missed, result.worst_miss, result.worst_gain);
  return result;
}

TEST(ClosestPointOracle, CubicBezier) {
  const BezierCurve loop = bezier({{0, 0}, {6, 5}, {-2, 5}, {4, 0}});
  EXPECT_EQ(against_oracle(loop, 1).missed, 0);
}

TEST(ClosestPointOracle, RationalBezier) {
  const BezierCurve rational = bezier({{0, 0}, {2, 4}, {5, -1}, {6, 3}}, {1.0, 3.0, 0.4, 2.0});
  EXPECT_EQ(against_oracle(rational, 2).missed, 0);
}

TEST(ClosestPointOracle, HighDegreeBezier) {
  test::SplitMix random{3};
  std::vector<std::vector<double>> rows;
  for (int i = 0; i <= 20; ++i) rows.push_back({i + 3 * random.unit(), 10 * random.unit()});
  EXPECT_EQ(against_oracle(bezier(rows), 3, kOracleQueries / 10).missed, 0);  // the general kernel: a tenth
}

TEST(ClosestPointOracle, PiecewiseBezierWithCorners) {
  const PiecewiseBezierCurve pieces =
      PiecewiseBezierCurve::make({bezier({{0, 0}, {1, 3}, {3, 3}, {4, 0}}), bezier({{4, 0}, {5, 2}, {6, -2}}),
                                  bezier({{6, -2}, {3, -4}, {0, -3}, {0, 0}})})
          .value();
  EXPECT_EQ(against_oracle(pieces, 4).missed, 0);
}

TEST(ClosestPointOracle, SpatialBSpline) {
  test::SplitMix random{5};
  std::vector<double> coordinates;
  for (int i = 0; i < 3 * 14; ++i) coordinates.push_back(10 * random.unit());
  const BSplineCurve curve =
      BSplineCurve::make(3, clamped_uniform_knots(3, 14), PointArray::make(3, coordinates).value()).value();
  EXPECT_EQ(against_oracle(curve, 6).missed, 0);
}

TEST(ClosestPointOracle, NurbsCircle) {
  EXPECT_EQ(against_oracle(make_circle(0.5, 0.25, 2.0).value(), 7).missed, 0);
}

TEST(ClosestPoint, LocalMinimaIncludeEndsAndCorners) {
  // A V: two segments meeting at (0, 0). From (0, 1) the squared distance
  // to (x, |x|) is 2x^2 - 2|x| + 1: minima at the feet (-1/2, 1/2), (1/2,
  // 1/2) (u = 3/4 and 5/4), the corner a maximum. From (0, -1) it is
  // 2x^2 + 2|x| + 1: the corner is the only minimum (a corner minimum,
  // where the distance falls into it from both sides).
  const PiecewiseBezierCurve v =
      PiecewiseBezierCurve::make({bezier({{-2, 2}, {0, 0}}), bezier({{0, 0}, {2, 2}})}).value();
  const auto above = local_closest_points(v, std::vector<double>{0, 1}).value();
  ASSERT_EQ(above.size(), 2u);
  EXPECT_EQ(above[0].parameter, 0.75);
  EXPECT_EQ(above[1].parameter, 1.25);
  const auto below = local_closest_points(v, std::vector<double>{0, -1}).value();
  ASSERT_EQ(below.size(), 1u);
  EXPECT_EQ(below[0].parameter, 1.0);
  // From (0, 5) the distance falls towards both far ends of the V and rises
  // into the corner: the ends are the two minima, and (-2, 2) comes first on
  // a tie; the perpendicular feet at (+-2.5, 2.5) lie beyond the ends.
  const auto far = local_closest_points(v, std::vector<double>{0, 5}).value();
  ASSERT_EQ(far.size(), 2u);
  EXPECT_EQ(far[0].parameter, 0.0);
  EXPECT_EQ(far[1].parameter, 2.0);
  EXPECT_EQ(closest_point(v, std::vector<double>{0, 5}).value().parameter, 0.0);
}

TEST(ClosestPoint, LocalMinimaAtAKnotAreReportedOnce) {
  // Issue 39: two cubics meeting with one tangent at J, the query 0.1 from J
  // along the normal: the slope's root 0.9999999999999997 on the first piece
  // and the knot itself were two minima, printed twice by `closest --all`.
  const PiecewiseBezierCurve joined =
      PiecewiseBezierCurve::make(
          {bezier({{1.6474352160846735, -1.3287616857291198}, {3.8273202406645375, 2.7583764995996516},
                   {1.1983899585681894, 3.250042837071972}, {-1.0664637693016044, 3.5328795041535663}}),
           bezier({{-1.0664637693016044, 3.5328795041535663}, {-2.3882038998823054, 3.6979394233356535},
                   {1.6375780484398073, -3.920687379059001}, {2.3821546416508426, -4.135324102717517}})})
          .value();
  const auto minima = local_closest_points(joined, std::vector<double>{-1.078855593141042, 3.433650260974288}).value();
  ASSERT_EQ(minima.size(), 1u);
  EXPECT_NEAR(minima[0].parameter, 1.0, 1e-12);
  EXPECT_NEAR(minima[0].distance, 0.1, 1e-12);
}

RC_GTEST_PROP(ClosestPoint, LocalMinimaNearTangentJointsAreDistinct, ()) {
  // Two cubics meeting at J with one tangent d, the query on J's normal: no
  // minimum is reported twice (189 of 300 such cases were, at the knot).
  const auto coordinate = [] { return *rc::gen::inRange(-500, 501) / 100.0; };
  const double angle = *rc::gen::inRange(0, 628) / 100.0, dx = std::cos(angle), dy = std::sin(angle);
  const double jx = coordinate(), jy = coordinate();
  const double before = *rc::gen::inRange(20, 300) / 100.0, after = *rc::gen::inRange(20, 300) / 100.0;
  const double reach = *rc::gen::element(0.1, 1.0, 3.0);
  const PiecewiseBezierCurve joined =
      PiecewiseBezierCurve::make({bezier({{coordinate(), coordinate()}, {coordinate(), coordinate()},
                                          {jx - before * dx, jy - before * dy}, {jx, jy}}),
                                  bezier({{jx, jy}, {jx + after * dx, jy + after * dy}, {coordinate(), coordinate()},
                                          {coordinate(), coordinate()}})})
          .value();
  const auto minima = local_closest_points(joined, std::vector<double>{jx - reach * dy, jy + reach * dx}).value();
  // (A curve may pass one point twice: two minima there, far apart in u.)
  for (std::size_t i = 0; i < minima.size(); ++i)
    for (std::size_t k = i + 1; k < minima.size(); ++k)
      RC_ASSERT(distance(minima[i].point, minima[k].point) > 1e-6 ||
                std::abs(minima[i].parameter - minima[k].parameter) > 1e-6);
}

TEST(ClosestPoint, FindsPointsNextToAnEndWhereTheVelocityVanishes) {
  // An SVG 'S' after a line repeats the start as the first control point, so
  // C'(0) = 0 and g' = 2 (C - q).C' has a root at 0 besides the minimum: the
  // minimum must still be found (it was not: the root at the end was taken).
  for (const BezierCurve& curve : {bezier({{100, 100}, {100, 100}, {200, 10}, {290, 290}}),
                                   bezier({{100, 100}, {200, 10}, {290, 290}, {290, 290}}),
                                   bezier({{150, 150}, {150, 150}, {290, 150}})}) {
    for (int k = 0; k <= 20; ++k) {
      const Point q = point_at(curve, k / 20.0);
      const NearestPoint nearest = closest_point(curve, q).value();
      EXPECT_LE(nearest.distance, 1e-12 * 290) << k;
    }
  }
}

RC_GTEST_PROP(ClosestPoint, FindsEveryPointOfCurvesWithRepeatedEndControlPoints, ()) {
  const int n = *rc::gen::inRange(2, 7);
  std::vector<std::vector<double>> rows;
  for (int i = 0; i <= n; ++i) rows.push_back({*rc::gen::inRange(-100, 101) * 1.0, *rc::gen::inRange(-100, 101) * 1.0});
  const bool at_start = *rc::gen::arbitrary<bool>(), at_end = *rc::gen::arbitrary<bool>();
  if (at_start) rows[1] = rows[0];
  if (at_end) rows[static_cast<std::size_t>(n) - 1] = rows[static_cast<std::size_t>(n)];
  const BezierCurve curve = bezier(rows);
  const double size = std::max(size_of(curve), 1.0);
  for (int k = 0; k <= 16; ++k) {
    const Point q = point_at(curve, k / 16.0);
    RC_ASSERT(closest_point(curve, q).value().distance <= 1e-9 * size);
  }
}

RC_GTEST_PROP(ClosestPoint, IsNoFartherThanTheOracleOnRandomCurves, ()) {
  const BSplineCurve curve = *test::bspline_curve(
      {.max_degree = 5, .dimension = 2, .max_extra_points = 8, .rational = test::Rational::sometimes, .allow_jumps = true});
  const test::NearestOracle oracle(curve, 512);
  const double size = size_of(curve);
  for (int i = 0; i < 20; ++i) {
    const std::vector<double> q{*rc::gen::inRange(-40, 41) * 0.5, *rc::gen::inRange(-40, 41) * 0.5};
    const NearestPoint nearest = closest_point(curve, q).value();
    RC_ASSERT(nearest.distance <= oracle.distance(q.data()) + 1e-9 * std::max(size, 1.0));
    const std::vector<NearestPoint> locals = local_closest_points(curve, q).value();
    for (const NearestPoint& local : locals)
      RC_ASSERT(local.distance >= nearest.distance - 1e-9 * std::max(size, 1.0));
  }
}

}  // namespace
}  // namespace casteljau
