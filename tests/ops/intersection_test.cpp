// Intersections against answers known in closed form: crossing lines, a
// cubic and a line through its centre of symmetry, tangencies of
// multiplicity 2 and 3 (a parabola and an inflection on the axis), overlaps
// of a curve and its own segment (same and opposite direction, and across the
// pieces of a piecewise curve), shared end points, hits at knots reported
// once, nearly parallel lines, and the self-intersection of a loop at
// (5 - sqrt 15) / 10; every kind; bad input. Parameter errors are in ulps.
// In space: the twisted cubic (t, t^2, t^3) and a line through its point at
// 1/2 (a crossing), the line moved off it by 1e-12 (a meeting within the
// tolerance) and by 1e-6 (none), its tangent line (a tangency), its own
// segment (an overlap both ways), a hit at a knot once; a loop lifted into
// space that still crosses itself, and one that passes over itself.
#include "casteljau/ops/intersection.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "casteljau/bezier/evaluate.hpp"
#include "casteljau/bezier/piecewise_bezier.hpp"
#include "casteljau/bezier/split.hpp"
#include "casteljau/bspline/bezier_pieces.hpp"
#include "casteljau/bspline/bspline_curve.hpp"
#include "casteljau/nurbs/conics.hpp"
#include "support/make.hpp"
#include "support/power_curves.hpp"

namespace casteljau {
namespace {

using test::bezier;

/// Both curves by reference, so a test may pass temporaries (a CurveView
/// cannot be made of one: docs/cpp.md, "Lifetimes").
template <class A, class B>
std::vector<CurveIntersection> between(const A& a, const B& b) {
  return intersections(a, b, default_intersection_tolerance(a, b)).value();
}

double ulps(double x, double reference) {
  if (x == reference) return 0.0;
  return std::abs(x - reference) / (std::nextafter(std::abs(reference), INFINITY) - std::abs(reference));
}

TEST(Intersections, OfCrossingLinesAndACubicThroughItsCentre) {
  const auto lines = between(bezier({{0, 0}, {2, 2}}), bezier({{0, 2}, {2, 0}}));
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_EQ(lines[0].kind, IntersectionKind::transversal);
  EXPECT_EQ(lines[0].a.lower, 0.5);
  EXPECT_EQ(lines[0].b.lower, 0.5);
  EXPECT_EQ(lines[0].point, (Point{1, 1}));
  // The cubic (0,0),(1,3),(2,-3),(3,0) is point-symmetric about (3/2, 0),
  // as is the line through it: three crossings, the middle at t = 1/2 on
  // both and the outer two mirror images (t and 1 - t).
  const BezierCurve cubic = bezier({{0, 0}, {1, 3}, {2, -3}, {3, 0}});
  const BezierCurve line = bezier({{0, 0.5}, {3, -0.5}});
  const auto three = between(cubic, line);
  ASSERT_EQ(three.size(), 3u);
  for (const CurveIntersection& x : three) EXPECT_EQ(x.kind, IntersectionKind::transversal);
  EXPECT_EQ(three[1].a.lower, 0.5);
  EXPECT_LE(ulps(three[0].a.lower, 1.0 - three[2].a.lower), 16.0);
  for (const CurveIntersection& x : three) {
    const Point p = point_at(cubic, x.a.lower), q = point_at(line, x.b.lower);
    EXPECT_LT(std::hypot(p[0] - q[0], p[1] - q[1]), 1e-15);
  }
}

TEST(Intersections, ClassifyTangenciesByMultiplicity) {
  const BezierCurve axis = bezier({{-2, 0}, {2, 0}});
  // y = x^2 touches the axis at its vertex: multiplicity 2.
  const auto touch = between(bezier({{-1, 1}, {0, -1}, {1, 1}}), axis);
  ASSERT_EQ(touch.size(), 1u);
  EXPECT_EQ(touch[0].kind, IntersectionKind::tangent);
  EXPECT_EQ(touch[0].multiplicity, 2);
  EXPECT_NEAR(touch[0].a.lower, 0.5, 1e-7);
  // y = x^3 (x = 2t - 1) crosses the axis along it: multiplicity 3.
  const auto inflection = between(bezier({{-1, -1}, {-1.0 / 3, 1}, {1.0 / 3, -1}, {1, 1}}), axis);
  ASSERT_EQ(inflection.size(), 1u);
  EXPECT_EQ(inflection[0].kind, IntersectionKind::tangent);
  EXPECT_EQ(inflection[0].multiplicity, 3);
  // Lines whose slopes differ by 2^-40 still cross once, transversally.
  const auto parallel = between(bezier({{0, 0}, {1, 0}}), bezier({{0, -0x1p-41}, {1, 0x1p-41}}));
  ASSERT_EQ(parallel.size(), 1u);
  EXPECT_EQ(parallel[0].kind, IntersectionKind::transversal);
  EXPECT_EQ(parallel[0].a.lower, 0.5);
}

TEST(Intersections, FindOverlapsInBothDirections) {
  const BezierCurve cubic = bezier({{0, 0}, {1, 3}, {2, -3}, {3, 0}});
  const BezierCurve middle = segment(cubic, 0.25, 0.75).value();
  const auto same = between(cubic, middle);
  ASSERT_EQ(same.size(), 1u);
  EXPECT_EQ(same[0].kind, IntersectionKind::overlap);
  EXPECT_EQ(same[0].a.lower, 0.25);
  EXPECT_EQ(same[0].a.upper, 0.75);
  EXPECT_EQ(same[0].b.lower, 0.0);
  EXPECT_EQ(same[0].b.upper, 1.0);
  const auto opposite = between(cubic, reversed(middle));
  ASSERT_EQ(opposite.size(), 1u);
  EXPECT_EQ(opposite[0].b.lower, 1.0);
  EXPECT_EQ(opposite[0].b.upper, 0.0);
  // The cubic against itself split in two pieces: one overlap over both.
  const auto halves = split_at(cubic, 0.5).value();
  const PiecewiseBezierCurve two = PiecewiseBezierCurve::make({halves.first, halves.second}).value();
  const auto whole = between(cubic, two);
  ASSERT_EQ(whole.size(), 1u);
  EXPECT_EQ(whole[0].kind, IntersectionKind::overlap);
  EXPECT_EQ(whole[0].a.lower, 0.0);
  EXPECT_EQ(whole[0].a.upper, 1.0);
  EXPECT_EQ(whole[0].b.lower, 0.0);
  EXPECT_EQ(whole[0].b.upper, 2.0);
}

TEST(Intersections, AnOverlapThatBeginsAtASmoothJointIsReportedOnce) {
  // examples/sailboat.svg: the mast (x = 115 from y = 40 to 120) and the
  // flag, a skewed rounded rectangle whose corner, a quadratic, arrives
  // tangent to x = 115 at y = 115.27..., then its side runs along x = 115. The meeting at the joint is
  // where the overlap begins, not a crossing of its own: it was reported as
  // one too, 1.3e-7 from the overlap's start (1.6e-9 and 4.5e-8 off in the
  // parameters).
  const double y0 = 115.27025409136847;
  const std::vector<double> corner{1, 0.7071067811865476, 1};  // exact quarter ellipses, skewed
  const PiecewiseBezierCurve flag =
      PiecewiseBezierCurve::make(
          {bezier({{117, 121.98917242196369}, {129, 120.302682405535}}),
           bezier({{129, 120.302682405535}, {131, 120.02160073613021}, {131, 118.02160073613021}}, corner),
           bezier({{131, 118.02160073613021}, {131, 113.02160073613021}}),
           bezier({{131, 113.02160073613021}, {131, 111.02160073613021}, {129, 111.302682405535}}, corner),
           bezier({{129, 111.302682405535}, {117, 112.98917242196369}}),
           bezier({{117, 112.98917242196369}, {115, 113.27025409136847}, {115, y0}}, corner),
           bezier({{115, y0}, {115, 120.27025409136847}}),
           bezier({{115, 120.27025409136847}, {115, 122.27025409136847}, {117, 121.98917242196369}}, corner)})
          .value();
  const BezierCurve mast = bezier({{115, 40}, {115, 120}});
  for (const auto& found : {between(mast, flag), between(flag, mast)}) {
    ASSERT_EQ(found.size(), 1u) << (found.size() > 1 ? kind_name(found[0].kind) : "");
    EXPECT_EQ(found[0].kind, IntersectionKind::overlap);
  }
  const auto along = between(mast, flag);
  EXPECT_NEAR(along[0].a.lower, (y0 - 40) / 80, 1e-12);
  EXPECT_EQ(along[0].a.upper, 1.0);
  EXPECT_NEAR(along[0].b.lower, 6.0, 1e-12);
  EXPECT_NEAR(along[0].b.upper, 6 + (120 - y0) / 5, 1e-12);
}

TEST(Intersections, ReportEndsAndKnotsOnce) {
  const auto ends = between(bezier({{0, 0}, {1, 1}}), bezier({{1, 1}, {2, 0}}));
  ASSERT_EQ(ends.size(), 1u);
  EXPECT_EQ(ends[0].a.lower, 1.0);
  EXPECT_EQ(ends[0].b.lower, 0.0);
  // A V of two pieces and a vertical line through its joint: one hit, at u = 1.
  const PiecewiseBezierCurve v =
      PiecewiseBezierCurve::make({bezier({{-1, 1}, {0, 0}}), bezier({{0, 0}, {1, 1}})}).value();
  const auto joint = between(v, bezier({{0, -1}, {0, 1}}));
  ASSERT_EQ(joint.size(), 1u);
  EXPECT_EQ(joint[0].a.lower, 1.0);
  EXPECT_EQ(joint[0].b.lower, 0.5);
  // The NURBS circle (4 rational pieces) and a line through its centre: two
  // hits, at the knots where the circle meets the axis (the seam, u = 0 and
  // u = 1 of the closed circle, once).
  const BSplineCurve circle = make_circle(0.0, 0.0, 1.0).value();
  const auto diameter = between(circle, bezier({{-2, 0}, {2, 0}}));
  ASSERT_EQ(diameter.size(), 2u);
  EXPECT_NEAR(diameter[0].b.lower, 0.75, 1e-15);
  EXPECT_NEAR(diameter[1].b.lower, 0.25, 1e-15);
}

TEST(SelfIntersections, OfALoopAndNoneAtACusp) {
  // (0,0),(2,2),(-1,2),(1,0): y = 6 t (1 - t) is symmetric, and x(t) = x(1 - t)
  // at t = (5 - sqrt 15) / 10.
  const BezierCurve looped = bezier({{0, 0}, {2, 2}, {-1, 2}, {1, 0}});
  const auto loop = self_intersections(looped, Tolerance{1e-9}).value();
  ASSERT_EQ(loop.size(), 1u);
  const double s = (5 - std::sqrt(15.0)) / 10;
  EXPECT_LE(ulps(loop[0].a.lower, s), 4.0);
  EXPECT_LE(ulps(loop[0].b.lower, 1 - s), 4.0);
  // (0,0),(1,1),(0,1),(1,0) has a cusp at t = 1/2 (x' = 3 (1 - 2t)^2, y' = 3 (1 - 2t)): no crossing.
  const BezierCurve crossed_hull = bezier({{0, 0}, {1, 1}, {0, 1}, {1, 0}});
  EXPECT_TRUE(self_intersections(crossed_hull, Tolerance{1e-9}).value().empty());
  // A closed circle has no self-intersection: neither its seam nor its knots.
  const BSplineCurve circle = make_circle(0.0, 0.0, 1.0).value();
  EXPECT_TRUE(self_intersections(circle, Tolerance{1e-9}).value().empty());
  // A figure eight of two pieces crossing at (0, 0).
  const PiecewiseBezierCurve eight =
      PiecewiseBezierCurve::make({bezier({{0, 0}, {2, 2}, {2, -2}, {0, 0}}), bezier({{0, 0}, {-2, 2}, {-2, -2}, {0, 0}})})
          .value();
  const auto crossing = self_intersections(eight, Tolerance{1e-9}).value();
  EXPECT_FALSE(crossing.empty());
}

// Issue 42 (the curve_numbers fuzzer): a cubic on a line that turns back
// covers stretches twice. The subdivision saw every pair of points on the two
// passes as a tangency (thousands of them, seconds); the passes are overlaps.
// Rational folds: y(t) = Y(t) / W(t) along the line turns where Y' W - Y W'
// changes sign. Weights all equal change nothing (the turn stays at 2/3, as
// above; issue 42's fuzzer found such a cubic taking 9.6 s); the quadratic
// (0,0) (0,2) (0,0) with weights 1, 3, 1 is symmetric under t -> 1 - t, so it
// turns at 1/2 and retraces itself.
TEST(SelfIntersections, ARationalLineThatTurnsBackOverlapsItself) {
  const BezierCurve equal_weights = bezier({{0, 0}, {0, 0}, {0, 2}, {0, 0}}, {5, 5, 5, 5});
  const auto equal = self_intersections(equal_weights, Tolerance{1e-9}).value();
  ASSERT_EQ(equal.size(), 1u);
  EXPECT_EQ(equal[0].kind, IntersectionKind::overlap);
  EXPECT_NEAR(equal[0].a.upper, 2.0 / 3.0, 1e-15);
  EXPECT_NEAR(equal[0].b.upper, 2.0 / 3.0, 1e-15);
  const BezierCurve symmetric = bezier({{0, 0}, {0, 2}, {0, 0}}, {1, 3, 1});
  const auto folds = self_intersections(symmetric, Tolerance{1e-9}).value();
  ASSERT_EQ(folds.size(), 1u);
  EXPECT_EQ(folds[0].kind, IntersectionKind::overlap);
  EXPECT_EQ(folds[0].a.lower, 0.0);
  EXPECT_NEAR(folds[0].a.upper, 0.5, 1e-15);
  EXPECT_EQ(folds[0].b.lower, 1.0);
  EXPECT_NEAR(folds[0].b.upper, 0.5, 1e-15);
}

// Issue 42 (the dxf fuzzer): two pieces that each run out along a line and
// back. Where two passes of different pieces cover one stretch, the general
// searches saw every pair of their points as a tangency (an arc whose four
// pieces ran out and back along one chord: 84 hits in 4.2 s). A on
// (0,0) (2,0) (0,0) has x = 4t(1 - t), out to 1 at t = 1/2; B on (0,0) (4,0)
// (0,0) has x = 8t(1 - t), out to 2, and reaches x = 1 at
// t1 = (1 - sqrt(1/2)) / 2 and 1 - t1. Each pass of A covers [0, 1], and so
// does each pass of B over [0, t1] and [1 - t1, 1]: four overlaps, two with
// b running the way a runs, two against.
TEST(Intersections, PiecesRunningOutAndBackAlongOneLineOverlapPassByPass) {
  const BezierCurve a = bezier({{0, 0}, {2, 0}, {0, 0}}), b = bezier({{0, 0}, {4, 0}, {0, 0}});
  const auto found = between(a, b);
  ASSERT_EQ(found.size(), 4u);
  const double t1 = (1.0 - std::sqrt(0.5)) / 2.0;
  // Each as (a from, a to, b from, b to), sorted by (a from, b from).
  const std::vector<std::array<double, 4>> expected = {
      {0.0, 0.5, 0.0, t1}, {0.0, 0.5, 1.0, 1.0 - t1}, {0.5, 1.0, t1, 0.0}, {0.5, 1.0, 1.0 - t1, 1.0}};
  std::vector<std::array<double, 4>> got;
  for (const CurveIntersection& x : found) {
    EXPECT_EQ(x.kind, IntersectionKind::overlap);
    got.push_back({x.a.lower, x.a.upper, x.b.lower, x.b.upper});
  }
  std::sort(got.begin(), got.end());
  for (std::size_t k = 0; k < expected.size(); ++k)
    for (std::size_t c = 0; c < 4; ++c) EXPECT_NEAR(got[k][c], expected[k][c], 1e-12) << k << ", " << c;
  // On one line, passes that only touch meet at one point (a tangency of
  // order 0, as two arcs continuing one another do): end to end, and at the
  // tip of a fold; passes that do not reach one another do not meet.
  const auto end_to_end = between(bezier({{0, 0}, {1, 0}}), bezier({{1, 0}, {3, 0}}));
  ASSERT_EQ(end_to_end.size(), 1u);
  EXPECT_EQ(end_to_end[0].kind, IntersectionKind::tangent);
  EXPECT_EQ(end_to_end[0].a.lower, 1.0);
  EXPECT_EQ(end_to_end[0].b.lower, 0.0);
  const auto at_the_tip = between(a, bezier({{1, 0}, {2, 0}}));
  ASSERT_EQ(at_the_tip.size(), 1u);
  EXPECT_EQ(at_the_tip[0].kind, IntersectionKind::tangent);
  EXPECT_NEAR(at_the_tip[0].a.lower, 0.5, 1e-8);  // the fold's tip, x = 1, where x' = 0
  EXPECT_EQ(at_the_tip[0].b.lower, 0.0);
  EXPECT_TRUE(between(a, bezier({{1.5, 0}, {2, 0}})).empty());
}

// A closed curve that rests at its closing point (five repeated control points
// at each end) and loops once: x has control values 0 x5, 2, -12, 12, -2, 0 x5,
// so x(t) = 2574 t^5 (1 - t)^5 (1 - 2t)(9t^2 - 9t + 1), and the mirror symmetry
// C(1 - t) = (-x(t), y(t)) puts the loop's crossing on x = 0 at
// t = 1/2 -+ sqrt(5)/6. Every pair of points of the two rests is within the
// tolerance: the subdivision used to spend its pair budget there and miss
// the loop (issue 42's curve_numbers fuzzer found a degree-15 such curve
// taking 140 s).
TEST(SelfIntersections, ACurveRestingAtItsClosingPointStillFindsItsLoop) {
  const auto resting = [](std::vector<std::vector<double>> middle) {
    std::vector<std::vector<double>> rows(5, {0.0, 0.0});
    rows.insert(rows.end(), middle.begin(), middle.end());
    rows.insert(rows.end(), 5, {0.0, 0.0});
    return bezier(rows);
  };
  const BezierCurve loop = resting({{2, 2}, {-12, 6}, {12, 6}, {-2, 2}});
  const auto crossings = self_intersections(loop, default_intersection_tolerance(loop, loop)).value();
  ASSERT_EQ(crossings.size(), 1u);
  EXPECT_EQ(crossings[0].kind, IntersectionKind::transversal);
  EXPECT_NEAR(crossings[0].a.lower, 0.5 - std::sqrt(5.0) / 6, 1e-12);
  EXPECT_NEAR(crossings[0].b.lower, 0.5 + std::sqrt(5.0) / 6, 1e-12);
  EXPECT_NEAR(crossings[0].point[0], 0.0, 1e-12);
  // x = c t^6 (1 - t)^6 (2t - 1) vanishes inside only at t = 1/2, where y > 0:
  // no crossing, and the rests at the seam are not one.
  const BezierCurve arch = resting({{0, 1}, {-8, 4}, {8, 4}, {0, 1}});
  EXPECT_TRUE(self_intersections(arch, default_intersection_tolerance(arch, arch)).value().empty());
}

TEST(SelfIntersections, ALineThatTurnsBackOverlapsItself) {
  // Up and back: y = 6 t^2 (1 - t) turns at t = 2/3; the whole curve is traced twice.
  const BezierCurve up_and_back_curve = bezier({{0, 0}, {0, 0}, {0, 2}, {0, 0}});
  const auto up_and_back = self_intersections(up_and_back_curve, Tolerance{1e-9}).value();
  ASSERT_EQ(up_and_back.size(), 1u);
  EXPECT_EQ(up_and_back[0].kind, IntersectionKind::overlap);
  EXPECT_EQ(up_and_back[0].a.lower, 0.0);
  EXPECT_NEAR(up_and_back[0].a.upper, 2.0 / 3.0, 1e-15);
  EXPECT_EQ(up_and_back[0].b.lower, 1.0);
  EXPECT_NEAR(up_and_back[0].b.upper, 2.0 / 3.0, 1e-15);
  // Three passes: x = 9t - 21t^2 + 14t^3 turns at t1,2 = 1/2 -+ sqrt(7)/14; the
  // value at a turning point is taken once more at 3/2 - 2 t (the roots' sum
  // is 21/14): at 1/2 + sqrt(7)/7 and 1/2 - sqrt(7)/7. Every two passes overlap,
  // over [x(t2), x(t1)], each overlap with b one way (none joined across a turn).
  const double t1 = 0.5 - std::sqrt(7.0) / 14, t2 = 0.5 + std::sqrt(7.0) / 14;
  const double early = 0.5 - std::sqrt(7.0) / 7, late = 0.5 + std::sqrt(7.0) / 7;
  const BezierCurve folded = bezier({{0, 0}, {3, 0}, {-1, 0}, {2, 0}});
  const auto folds = self_intersections(folded, Tolerance{1e-9}).value();
  ASSERT_EQ(folds.size(), 3u);
  const double expected[3][4] = {{early, t1, t2, t1}, {early, t1, t2, late}, {t1, t2, late, t2}};
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(folds[k].kind, IntersectionKind::overlap);
    EXPECT_NEAR(folds[k].a.lower, expected[k][0], 1e-13) << k;
    EXPECT_NEAR(folds[k].a.upper, expected[k][1], 1e-13) << k;
    EXPECT_NEAR(folds[k].b.lower, expected[k][2], 1e-13) << k;
    EXPECT_NEAR(folds[k].b.upper, expected[k][3], 1e-13) << k;
  }
  // A line that does not turn back has no self-intersection.
  const BezierCurve straight = bezier({{0, 0}, {1, 1}, {2, 2}, {5, 5}});
  EXPECT_TRUE(self_intersections(straight, Tolerance{1e-9}).value().empty());
}

// Issue 42 (the dxf fuzzer): two arcs of one circle with other weights are
// not parameterized alike (a Möbius map between them, not an affine one):
// the stretch they share was skipped along a straight diagonal and 200
// "tangencies" were found beside the overlap, in 2 s.
TEST(SelfIntersections, TwoArcsOfOneCircleWithOtherWeightsOverlapOnce) {
  const double half = std::sqrt(0.5);
  // A quarter circle from (1, 0) to (0, 1), then 135 degrees back from (0, 1)
  // to angle -45 degrees (middle point at angle 22.5 degrees, 1 / cos 67.5 from
  // the centre, weight cos 67.5): it retraces the whole quarter.
  const double w = std::cos(67.5 * M_PI / 180), r = 1 / w;
  const BezierCurve quarter = bezier({{1, 0}, {1, 1}, {0, 1}}, {1, half, 1});
  const BezierCurve back = bezier({{0, 1}, {r * std::cos(22.5 * M_PI / 180), r * std::sin(22.5 * M_PI / 180)}, {half, -half}},
                                  {1, w, 1});
  const PiecewiseBezierCurve path = PiecewiseBezierCurve::make({quarter, back}).value();
  const auto found = self_intersections(path, default_intersection_tolerance(path, path)).value();
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].kind, IntersectionKind::overlap);
  EXPECT_NEAR(found[0].a.lower, 0.0, 1e-9);
  EXPECT_NEAR(found[0].a.upper, 1.0, 1e-9);
  EXPECT_NEAR(found[0].b.upper, 1.0, 1e-9);
  // b's other end is where the way back passes (1, 0).
  const Point there = point_at(back, found[0].b.lower - 1.0);
  EXPECT_NEAR(there[0], 1.0, 1e-9);
  EXPECT_NEAR(there[1], 0.0, 1e-9);
}

TEST(SelfIntersections, NoneAtJointsAndSeamsFoundOffByRounding) {
  // Issue 39: a corner of two lines whose joint was found at b = 1 + 4e-16.
  const PiecewiseBezierCurve corner =
      PiecewiseBezierCurve::make({bezier({{9.4454926, 5.9609562}, {12.540921, 8.0804904}}),
                                  bezier({{12.540921, 8.0804904}, {8.8324052, 8.6470683}})})
          .value();
  EXPECT_TRUE(self_intersections(corner, default_intersection_tolerance(corner, corner)).value().empty());
  // Cantarell's "S" at size 10 (`casteljau text S`): smooth joints are roots
  // of multiplicity 2 of the implicit equation, known to ~1e-9 of a piece,
  // and a line meets a cubic at the joint; a simple closed contour.
  const std::vector<std::vector<std::vector<double>>> s_contour{
      {{2.63, -0.1}, {4.18, -0.1}, {5.19, 0.69}, {5.19, 1.91}},  {{5.19, 1.91}, {5.19, 4.37}, {1.3, 3.39}, {1.3, 5.18}},
      {{1.3, 5.18}, {1.3, 5.91}, {1.89, 6.31}, {2.95, 6.31}},    {{2.95, 6.31}, {3.54, 6.31}, {4.18, 6.19}, {4.68, 5.98}},
      {{4.68, 5.98}, {4.93, 6.63}},                              {{4.93, 6.63}, {4.34, 6.89}, {3.67, 7.03}, {3.01, 7.03}},
      {{3.01, 7.03}, {1.46, 7.03}, {0.45, 6.26}, {0.45, 5.05}},  {{0.45, 5.05}, {0.45, 2.67}, {4.33, 3.56}, {4.33, 1.79}},
      {{4.33, 1.79}, {4.33, 1.09}, {3.73, 0.64}, {2.68, 0.64}},  {{2.68, 0.64}, {2.05, 0.64}, {1.27, 0.81}, {0.59, 1.09}},
      {{0.59, 1.09}, {0.34, 0.44}},                              {{0.34, 0.44}, {1.11, 0.09}, {1.89, -0.1}, {2.63, -0.1}}};
  std::vector<BezierCurve> pieces;
  for (const auto& rows : s_contour) pieces.push_back(bezier(rows));
  const PiecewiseBezierCurve s = PiecewiseBezierCurve::make(pieces).value();
  EXPECT_TRUE(self_intersections(s, default_intersection_tolerance(s, s)).value().empty());
  // The same contour started in the middle of a smooth piece: its seam is
  // tangent-continuous (no tangency reported there).
  const auto halves = split_at(pieces[0], 0.5).value();
  std::vector<BezierCurve> rotated{halves.second};
  rotated.insert(rotated.end(), pieces.begin() + 1, pieces.end());
  rotated.push_back(halves.first);
  const PiecewiseBezierCurve started = PiecewiseBezierCurve::make(rotated).value();
  EXPECT_TRUE(self_intersections(started, default_intersection_tolerance(started, started)).value().empty());
  // A closed curve of one piece, a teardrop: its seam is no crossing either.
  const BezierCurve drop = bezier({{0, 0}, {1, 1}, {-1, 1}, {0, 0}});
  EXPECT_TRUE(self_intersections(drop, default_intersection_tolerance(drop, drop)).value().empty());
  // Pieces of length zero (an SVG path closed by a segment back to its start,
  // then `z`; Adwaita's media-playback-start icon) are no crossings either.
  const PiecewiseBezierCurve triangle =
      PiecewiseBezierCurve::make({bezier({{2, 2.5}, {12, 8}}), bezier({{12, 8}, {12, 8}}), bezier({{12, 8}, {2, 13.5}}),
                                  bezier({{2, 13.5}, {2, 2.5}}), bezier({{2, 2.5}, {2, 2.5}})})
          .value();
  EXPECT_TRUE(self_intersections(triangle, default_intersection_tolerance(triangle, triangle)).value().empty());
  // A true crossing next to a joint is kept: the second arm turns back and
  // crosses the first 1.1e-6 from the joint, (1 - 1.1e-6, 0), at t = 2/3 on the
  // second piece (y = 1e-6 (2t - 3t^2)).
  const PiecewiseBezierCurve back = PiecewiseBezierCurve::make({bezier({{0, 0}, {1, 0}}),
                                                                bezier({{1, 0}, {0.999999, 1e-6}, {0.9999985, -1e-6}})})
                                        .value();
  const auto near_joint = self_intersections(back, default_intersection_tolerance(back, back)).value();
  ASSERT_EQ(near_joint.size(), 1u);
  EXPECT_NEAR(near_joint[0].b.lower, 1.0 + 2.0 / 3.0, 1e-9);
}

/// The twisted cubic (t, t^2, t^3) on [0, 1] and, at its point (1/2, 1/4,
/// 1/8), the line through it along `direction` (u = 1/2 there), moved by
/// `offset`.
BezierCurve twisted_cubic() { return test::power_curve({{0, 1}, {0, 0, 1}, {0, 0, 0, 1}}); }

BezierCurve line_through_middle(const std::vector<double>& direction, const std::vector<double>& offset) {
  const std::vector<double> p{0.5, 0.25, 0.125};
  std::vector<std::vector<double>> rows(2, std::vector<double>(3));
  for (int i = 0; i < 3; ++i) {
    rows[0][i] = p[i] - 0.5 * direction[i] + offset[i];
    rows[1][i] = p[i] + 0.5 * direction[i] + offset[i];
  }
  return bezier(rows);
}

TEST(SpaceIntersections, CrossingsMeetingsWithinTheToleranceAndNearMisses) {
  const BezierCurve cubic = twisted_cubic();
  const std::vector<double> direction{1, -1, 2};
  const auto crossing = between(cubic, line_through_middle(direction, {0, 0, 0}));
  ASSERT_EQ(crossing.size(), 1u);
  EXPECT_EQ(crossing[0].kind, IntersectionKind::transversal);
  EXPECT_LE(ulps(crossing[0].a.lower, 0.5), 4);
  EXPECT_LE(ulps(crossing[0].b.lower, 0.5), 4);
  EXPECT_NEAR(crossing[0].point[2], 0.125, 1e-16);
  // Moved along the common normal a'(1/2) x direction = (2.75, -1.25, -2).
  const std::vector<double> normal{2.75, -1.25, -2};
  const double length = std::sqrt(2.75 * 2.75 + 1.25 * 1.25 + 4);
  const auto moved = [&](double by) {
    std::vector<double> offset(3);
    for (int i = 0; i < 3; ++i) offset[i] = by * normal[i] / length;
    return line_through_middle(direction, offset);
  };
  const auto close = between(cubic, moved(1e-12));  // the tolerance is 1e-9 of the size
  ASSERT_EQ(close.size(), 1u);
  EXPECT_EQ(close[0].kind, IntersectionKind::transversal);
  EXPECT_NEAR(close[0].a.lower, 0.5, 1e-11);
  EXPECT_NEAR(close[0].b.lower, 0.5, 1e-11);
  EXPECT_TRUE(between(cubic, moved(1e-6)).empty());
  // The tangent line at 1/2, along a'(1/2) = (1, 1, 3/4): one tangency.
  const auto touching = between(cubic, line_through_middle({1, 1, 0.75}, {0, 0, 0}));
  ASSERT_EQ(touching.size(), 1u);
  EXPECT_EQ(touching[0].kind, IntersectionKind::tangent);
  EXPECT_EQ(touching[0].multiplicity, 2);
  EXPECT_NEAR(touching[0].a.lower, 0.5, 1e-4);
  // A line in R^3 and a curve in R^2 are refused.
  const BezierCurve planar = bezier({{0, 0}, {1, 1}});
  EXPECT_FALSE(intersections(cubic, planar, Tolerance{1e-9}));
}

TEST(SpaceIntersections, OverlapsAndKnots) {
  const BezierCurve cubic = twisted_cubic();
  const BezierCurve middle = segment(cubic, 0.25, 0.75).value();
  const auto same = between(cubic, middle);
  ASSERT_EQ(same.size(), 1u);
  EXPECT_EQ(same[0].kind, IntersectionKind::overlap);
  EXPECT_NEAR(same[0].a.lower, 0.25, 1e-12);
  EXPECT_NEAR(same[0].a.upper, 0.75, 1e-12);
  EXPECT_NEAR(same[0].b.lower, 0.0, 1e-12);
  EXPECT_NEAR(same[0].b.upper, 1.0, 1e-12);
  const auto back = between(cubic, reversed(middle));
  ASSERT_EQ(back.size(), 1u);
  EXPECT_EQ(back[0].kind, IntersectionKind::overlap);
  EXPECT_NEAR(back[0].b.lower, 1.0, 1e-12);
  EXPECT_NEAR(back[0].b.upper, 0.0, 1e-12);
  // The cubic cut at 1/2 into two pieces: the crossing at the knot, once.
  const auto [left, right] = split_at(cubic, 0.5).value();
  const PiecewiseBezierCurve halves = PiecewiseBezierCurve::make({left, right}).value();
  const auto at_knot = between(halves, line_through_middle({1, -1, 2}, {0, 0, 0}));
  ASSERT_EQ(at_knot.size(), 1u);
  EXPECT_EQ(at_knot[0].kind, IntersectionKind::transversal);
  EXPECT_NEAR(at_knot[0].a.lower, 1.0, 1e-15);
}

// Issue 42 (the dxf fuzzer; an assertion in the sanitizer build): whether a
// rational piece continues another at their shared end was tested on the
// piece extended by half its domain, but its weight polynomial
// W(t) = (1 - t)^2 + 34 t (1 - t) + 0.7 t^2 = 1 + 32 t - 32.3 t^2 vanishes at
// t = -0.0303 and 1.021, just beyond its ends: the extension's weights were
// not all positive (W(-0.5) < 0). The extension now stops short of the
// poles. The two curves meet at (0, 0, 0), a's start and b's end, crossing
// there.
TEST(SpaceIntersections, ARationalPieceIsNotExtendedThroughAPole) {
  const BezierCurve a = bezier({{0, 0, 0}, {1, 1, 0}, {2, 0, 1}}, {1, 17, 0.7});
  const BezierCurve b = bezier({{-2, 1, 0}, {-1, -1, 1}, {0, 0, 0}});
  const auto met = between(a, b);
  ASSERT_EQ(met.size(), 1u);
  EXPECT_EQ(met[0].kind, IntersectionKind::transversal);
  EXPECT_NEAR(met[0].a.lower, 0.0, 1e-12);
  EXPECT_NEAR(met[0].b.lower, 1.0, 1e-12);
  // As two pieces of one curve, joined there: the joint is no intersection.
  const PiecewiseBezierCurve joined = PiecewiseBezierCurve::make({b, a}).value();
  EXPECT_TRUE(self_intersections(joined, default_intersection_tolerance(joined, joined)).value().empty());
}

TEST(SpaceIntersections, SelfIntersectionsOfALoopLiftedIntoSpace) {
  // The plane loop (0,0) (2,2) (-1,2) (1,0) crosses itself at s = (5 - sqrt 15) / 10
  // and 1 - s. Lifted by z = t (1 - t), symmetric about 1/2, it still does;
  // lifted by z = t it passes over itself.
  const double s = (5 - std::sqrt(15.0)) / 10;
  const BezierCurve lifted = bezier({{0, 0, 0}, {2, 2, 1.0 / 3}, {-1, 2, 1.0 / 3}, {1, 0, 0}});
  const auto crossing = self_intersections(lifted, default_intersection_tolerance(lifted, lifted)).value();
  ASSERT_EQ(crossing.size(), 1u);
  EXPECT_EQ(crossing[0].kind, IntersectionKind::transversal);
  EXPECT_NEAR(crossing[0].a.lower, s, 1e-14);
  EXPECT_NEAR(crossing[0].b.lower, 1 - s, 1e-14);
  const BezierCurve rising = bezier({{0, 0, 0}, {2, 2, 1.0 / 3}, {-1, 2, 2.0 / 3}, {1, 0, 1}});
  EXPECT_TRUE(self_intersections(rising, default_intersection_tolerance(rising, rising)).value().empty());
}

// Issue 42 (the curve_numbers fuzzer): a hairpin out along y = x and back,
// its way back `offset` tolerances off its way out at the ends (0 at the
// tip). Half a tolerance off, the passes are one overlap. A tolerance and a
// half off they come within the tolerance of one another in more pairs of
// sub-curves than the search visits (kIntersectionPairBudget): its answer
// would depend on the order of the search, so it is refused (a limit), naming
// where, in the curve's parameters. Before, the search stopped silently.
BezierCurve hairpin(double offset, int dimension) {
  const double o = offset * 1e-9 / std::sqrt(2.0);
  const std::vector<std::vector<double>> plane = {{0, 0}, {0.5, 0.5}, {1, 1}, {0.5 + o, 0.5 - o}, {o, -o}};
  std::vector<std::vector<double>> rows;
  for (const auto& p : plane) rows.push_back(dimension == 2 ? p : std::vector<double>{p[0], p[1], 0.25 * p[0]});
  return bezier(rows);
}

/// The two parameters an unsettled search's refusal names, after `lead`.
std::array<double, 2> named_parameters(const Error& error, const std::string& lead, const std::string& which) {
  EXPECT_EQ(error.kind, ErrorKind::limit) << error.message;
  EXPECT_EQ(error.message.rfind(lead, 0), 0u) << error.message;
  EXPECT_NE(error.message.find(which), std::string::npos) << error.message;
  std::array<double, 2> at{NAN, NAN};
  EXPECT_EQ(std::sscanf(error.message.c_str() + lead.size(), "%lf and %lf", &at[0], &at[1]), 2) << error.message;
  return at;
}

TEST(SelfIntersections, AHairpinAboutTheToleranceWideIsRefusedNamingWhere) {
  const std::string lead = "the intersection search gave up near parameters ";
  const BezierCurve near_hairpin = hairpin(0.5, 2), wider_hairpin = hairpin(1.5, 2);
  const auto close = self_intersections(near_hairpin, Tolerance{1e-9}).value();
  ASSERT_EQ(close.size(), 1u);
  EXPECT_EQ(close[0].kind, IntersectionKind::overlap);
  EXPECT_EQ(close[0].a, (Interval{0.0, 0.5}));
  EXPECT_EQ(close[0].b, (Interval{1.0, 0.5}));
  const auto refused = self_intersections(wider_hairpin, Tolerance{1e-9});
  ASSERT_FALSE(refused);
  const std::array<double, 2> at = named_parameters(refused.error(), lead, "of the curve");
  // On the two passes, where they run about the tolerance apart.
  EXPECT_GT(at[0], 0.0);
  EXPECT_LT(at[0], 0.5);
  EXPECT_GT(at[1], 0.5);
  EXPECT_LT(at[1], 1.0);
  // The two passes as two curves, in the plane (pieces of one algebraic
  // curve) and in space: the same.
  for (const int dimension : {2, 3}) {
    const auto passes = split_at(hairpin(1.5, dimension), 0.5).value();
    const auto between_passes = intersections(passes.first, passes.second, Tolerance{1e-9});
    ASSERT_FALSE(between_passes) << dimension;
    const std::array<double, 2> where = named_parameters(between_passes.error(), lead, "of the first curve and the second");
    EXPECT_TRUE(where[0] > 0.0 && where[0] < 1.0 && where[1] > 0.0 && where[1] < 1.0) << where[0] << " " << where[1];
    const auto near = split_at(hairpin(0.5, dimension), 0.5).value();
    const auto overlap = intersections(near.first, near.second, Tolerance{1e-9}).value();
    ASSERT_EQ(overlap.size(), 1u) << dimension;
    EXPECT_EQ(overlap[0].kind, IntersectionKind::overlap) << dimension;
  }
}

TEST(Intersections, RefuseBadInput) {
  const BezierCurve plane = bezier({{0, 0}, {1, 1}});
  const BezierCurve space = bezier({{0, 0, 0}, {1, 1, 1}});
  EXPECT_EQ(intersections(plane, space, Tolerance{1e-9}).error().message,
            "intersections need curves in one space, the first lives in R^2, the second in R^3");
  const BezierCurve line = bezier({{0}, {1}});
  EXPECT_EQ(intersections(line, line, Tolerance{1e-9}).error().message,
            "intersections need curves in R^2 or more, the first lives in R^1");
  EXPECT_FALSE(intersections(plane, plane, Tolerance{0.0}));
  EXPECT_EQ(self_intersections(line, Tolerance{1e-9}).error().message,
            "self-intersections need a curve in R^2 or more, this one lives in R^1");
  for (const double bad : {0.0, -1.0, std::nan(""), double(INFINITY)})
    EXPECT_NE(self_intersections(plane, Tolerance{bad}).error().message.find("it must be finite and > 0"),
              std::string::npos)
        << bad;
}

// A curve of degree 0 is a point: it meets another curve where it lies on it
// (within the tolerance), at the other curve's nearest parameter, whichever
// of the two it is given as.
TEST(Intersections, APointMeetsACurveWhereItLiesOnIt) {
  const BezierCurve point = bezier({{0.25, 0.25}});
  const BezierCurve diagonal = bezier({{0, 0}, {1, 1}});
  for (const bool point_first : {true, false}) {
    const auto hits = point_first ? intersections(point, diagonal, Tolerance{1e-9}).value()
                                  : intersections(diagonal, point, Tolerance{1e-9}).value();
    ASSERT_EQ(hits.size(), 1u) << point_first;
    const Interval on_point = point_first ? hits[0].a : hits[0].b, on_line = point_first ? hits[0].b : hits[0].a;
    EXPECT_EQ(on_point.lower, 0.0);
    EXPECT_NEAR(on_line.lower, 0.25, 1e-15);
    EXPECT_NEAR(hits[0].point[0], 0.25, 1e-15);
  }
  const BezierCurve off = bezier({{0.25, 0.5}});
  EXPECT_TRUE(intersections(off, diagonal, Tolerance{1e-9}).value().empty());
}

}  // namespace
}  // namespace casteljau
