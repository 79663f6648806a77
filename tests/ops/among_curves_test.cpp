// Queries over a set of curves (ops/closest_among_curves.hpp,
// ops/intersections_among_curves.hpp). The references: closest_point on
// every curve in turn, and intersections() on every pair plus
// self_intersections() on every curve (both checked against their own
// oracles in closest_point_test and intersection_oracle_test): the box
// pruning and the sweep must give the same answers as asking every curve and
// every pair. Seeded random cubics (splitmix64), and cases worked by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <optional>
#include <tuple>
#include <vector>

#include "casteljau/bezier/bezier_curve.hpp"
#include "casteljau/ops/closest_among_curves.hpp"
#include "casteljau/ops/intersections_among_curves.hpp"
#include "support/make.hpp"
#include "support/splitmix.hpp"

namespace casteljau {
namespace {

/// `count` cubics, each in a box of side `spread` at a random place of a 100 x 100 field.
std::vector<BezierCurve> scattered_cubics(std::size_t count, double spread, std::uint64_t seed) {
  test::SplitMix random{seed};
  std::vector<BezierCurve> cubics;
  for (std::size_t k = 0; k < count; ++k) {
    const double x = 100.0 * random.unit(), y = 100.0 * random.unit();
    std::vector<double> coordinates;
    for (int i = 0; i < 4; ++i) {
      coordinates.push_back(x + spread * random.unit());
      coordinates.push_back(y + spread * random.unit());
    }
    cubics.push_back(test::bezier_of(2, coordinates));
  }
  return cubics;
}

std::vector<CurveView> views_of(const std::vector<BezierCurve>& curves) {
  return std::vector<CurveView>(curves.begin(), curves.end());
}

TEST(ClosestAmongCurves, TheNearestOfEveryCurveAsked) {
  const std::vector<BezierCurve> cubics = scattered_cubics(300, 8.0, 0xC105E);
  const std::vector<CurveView> curves = views_of(cubics);
  test::SplitMix random{0x9E7};
  std::vector<double> queries;
  for (int i = 0; i < 400; ++i) queries.push_back(-10.0 + 120.0 * random.unit());
  const auto answers = closest_among_curves(curves, queries);
  ASSERT_TRUE(answers) << answers.error().message;
  ASSERT_EQ(answers->size(), 200u);
  for (std::size_t i = 0; i < answers->size(); ++i) {
    const std::span<const double> q(queries.data() + 2 * i, 2);
    double best = INFINITY;
    std::size_t which = 0;
    for (std::size_t c = 0; c < curves.size(); ++c) {
      const double d = closest_point(curves[c], q).value().distance;
      if (d < best) best = d, which = c;
    }
    EXPECT_EQ((*answers)[i].curve, which) << "query " << i;
    EXPECT_EQ((*answers)[i].nearest.distance, best) << "query " << i;
  }
}

TEST(ClosestAmongCurves, WorkedByHand) {
  // The segments y = 0 and y = 3 (x from 0 to 4), and the same y = 0 again:
  // (1, 1) is nearest the first, at (1, 0), distance 1, t = 1/4; (2, 2.5) the
  // second at (2, 3); a tie between the two equal segments goes to the first.
  const BezierCurve low = test::bezier({{0, 0}, {4, 0}}), high = test::bezier({{0, 3}, {4, 3}});
  const std::vector<CurveView> curves{high, low, low};
  const auto answers = closest_among_curves(curves, std::vector<double>{1, 1, 2, 2.5});
  ASSERT_TRUE(answers);
  EXPECT_EQ((*answers)[0].curve, 1u);
  EXPECT_EQ((*answers)[0].nearest.parameter, 0.25);
  EXPECT_EQ((*answers)[0].nearest.distance, 1.0);
  EXPECT_EQ((*answers)[1].curve, 0u);
  EXPECT_EQ((*answers)[1].nearest.point, (Point{2.0, 3.0}));
}

TEST(ClosestAmongCurves, Errors) {
  const BezierCurve plane = test::bezier({{0, 0}, {1, 1}}), space = test::bezier({{0, 0, 0}, {1, 1, 1}});
  EXPECT_EQ(test::message_of(closest_among_curves({}, std::vector<double>{0, 0})),
            "the nearest point among curves needs at least one curve");
  const std::vector<CurveView> mixed{plane, space};
  EXPECT_EQ(test::message_of(closest_among_curves(mixed, std::vector<double>{0, 0})), "curve 1 lives in R^3, curve 0 in R^2");
  const std::vector<CurveView> one{plane};
  EXPECT_EQ(test::message_of(closest_among_curves(one, std::vector<double>{0, 0, 0})),
            "3 query coordinates are not whole points of R^2");
  EXPECT_NE(test::message_of(closest_among_curves(one, std::vector<double>{0, NAN})).find("query 0"), std::string::npos);
}

/// Every pair and every curve asked: the reference for the sweep.
std::vector<IntersectionAmongCurves> every_pair(const std::vector<CurveView>& curves) {
  std::vector<IntersectionAmongCurves> found;
  for (std::size_t a = 0; a < curves.size(); ++a)
    for (std::size_t b = a; b < curves.size(); ++b) {
      const auto result = a == b ? self_intersections(curves[a], default_intersection_tolerance(curves[a], curves[a]))
                                 : intersections(curves[a], curves[b], default_intersection_tolerance(curves[a], curves[b]));
      for (const CurveIntersection& x : result.value()) found.push_back({a, b, x});
    }
  return found;
}

TEST(IntersectionsAmongCurves, TheSameAsEveryPairAsked) {
  // Loops (the last control points crossing back) meet themselves too.
  const std::vector<BezierCurve> cubics = scattered_cubics(150, 12.0, 0x1A7E);
  const std::vector<CurveView> curves = views_of(cubics);
  const auto swept = intersections_among_curves(curves, std::nullopt);
  ASSERT_TRUE(swept) << swept.error().message;
  const std::vector<IntersectionAmongCurves> reference = every_pair(curves);
  ASSERT_EQ(swept->size(), reference.size());
  std::size_t selves = 0;
  for (std::size_t k = 0; k < reference.size(); ++k) {
    const auto& x = (*swept)[k];
    const auto& y = reference[k];
    EXPECT_EQ(std::tie(x.a, x.b), std::tie(y.a, y.b)) << k;
    EXPECT_EQ(x.intersection.a.lower, y.intersection.a.lower) << k;
    EXPECT_EQ(x.intersection.b.lower, y.intersection.b.lower) << k;
    selves += x.a == x.b;
  }
  std::cout << "[measured] 150 cubics: " << reference.size() << " intersections, " << selves << " of a curve with itself\n";
  EXPECT_GT(reference.size(), 50u);
  EXPECT_GT(selves, 0u);
}

TEST(IntersectionsAmongCurves, WorkedByHand) {
  // The diagonals of the square [0, 2]^2 meet at (1, 1), halfway along
  // both; a segment far away meets nothing; the loop, symmetric about x =
  // 23, meets itself at (23, 3), at t = (2 -+ sqrt 2) / 4 (x(t) + x(1 - t) = 46
  // for this control polygon, and y(t) = 24 t (1 - t) = 3 there).
  const BezierCurve up = test::bezier({{0, 0}, {2, 2}}), down = test::bezier({{0, 2}, {2, 0}});
  const BezierCurve far = test::bezier({{10, 10}, {11, 10}});
  const BezierCurve loop = test::bezier({{20, 0}, {30, 8}, {16, 8}, {26, 0}});
  const std::vector<CurveView> curves{up, far, down, loop};
  const auto found = intersections_among_curves(curves, std::nullopt);
  ASSERT_TRUE(found);
  ASSERT_EQ(found->size(), 2u);
  EXPECT_EQ((*found)[0].a, 0u);
  EXPECT_EQ((*found)[0].b, 2u);
  EXPECT_EQ((*found)[0].intersection.a.lower, 0.5);
  EXPECT_EQ((*found)[0].intersection.b.lower, 0.5);
  EXPECT_EQ((*found)[1].a, 3u);
  EXPECT_EQ((*found)[1].b, 3u);
  EXPECT_NEAR((*found)[1].intersection.a.lower, (2 - std::sqrt(2.0)) / 4, 1e-12);
  EXPECT_NEAR((*found)[1].intersection.b.lower, (2 + std::sqrt(2.0)) / 4, 1e-12);
  EXPECT_NEAR((*found)[1].intersection.point[0], 23.0, 1e-12);
  EXPECT_NEAR((*found)[1].intersection.point[1], 3.0, 1e-12);
  // A given tolerance: the same two.
  EXPECT_EQ(intersections_among_curves(curves, Tolerance{1e-6}).value().size(), 2u);
}

TEST(IntersectionsAmongCurves, Errors) {
  const BezierCurve plane = test::bezier({{0, 0}, {1, 1}}), space = test::bezier({{0, 0, 0}, {1, 1, 1}});
  const BezierCurve line = test::bezier({{0}, {1}});
  EXPECT_TRUE(intersections_among_curves({}, std::nullopt).value().empty());
  const std::vector<CurveView> mixed{plane, space};
  EXPECT_EQ(test::message_of(intersections_among_curves(mixed, std::nullopt)),
            "intersections need curves in one space, curve 1 lives in R^3, curve 0 in R^2");
  const std::vector<CurveView> flat{line};
  EXPECT_EQ(test::message_of(intersections_among_curves(flat, std::nullopt)),
            "intersections need curves in R^2 or more, curve 0 lives in R^1");
  const std::vector<CurveView> one{plane};
  EXPECT_NE(test::message_of(intersections_among_curves(one, Tolerance{-1})).find("tolerance"), std::string::npos);
}

}  // namespace
}  // namespace casteljau
