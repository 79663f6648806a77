// Operations in one direction of a surface, each the curve algorithm run on
// the rows of the homogeneous net: knot insertion, refinement and clamping, degree
// elevation, splitting (B-spline and Bézier), iso-curves. Properties: the
// surface is unchanged (points compared on a grid, relative to its scale);
// bad input refused with a message naming the direction and the value.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>

#include "casteljau/bezier/evaluate.hpp"
#include "casteljau/bspline/evaluate.hpp"
#include "casteljau/bspline/knot_insertion.hpp"
#include "casteljau/bspline/knot_vector.hpp"
#include "casteljau/surfaces/degree.hpp"
#include "casteljau/surfaces/evaluate.hpp"
#include "casteljau/surfaces/iso_curve.hpp"
#include "casteljau/surfaces/refinement.hpp"
#include "casteljau/surfaces/split.hpp"
#include "support/exact_surface.hpp"
#include "support/surface_generators.hpp"

namespace casteljau {
namespace {

/// Largest distance between a and b at the 9 x 9 grid of a's domain (plus
/// a's knots), b evaluated at map(u, v).
template <class A, class B, class Map>
double largest_distance(const A& a, Interval du, Interval dv, const B& b, Map map) {
  double worst = 0.0;
  for (int i = 0; i <= 8; ++i)
    for (int j = 0; j <= 8; ++j) {
      const double u = du.lerp(i / 8.0), v = dv.lerp(j / 8.0);
      const auto [x, y] = map(u, v);
      worst = std::max(worst, distance(point_at(a, u, v), point_at(b, x, y)));
    }
  return worst;
}
const auto identity = [](double u, double v) { return std::make_pair(u, v); };

Direction any_direction() { return *rc::gen::element(Direction::u, Direction::v); }

RC_GTEST_PROP(SurfaceDirectionOps, InsertKnotKeepsTheSurface, ()) {
  const BSplineSurface s = *test::bspline_surface();
  const Direction direction = any_direction();
  const double value = *test::parameter_in(s, direction);
  const int times = *rc::gen::inRange(1, s.degree(direction) + 1);
  const int have = multiplicity_of(s.knots(direction), value);
  RC_PRE(have + times <= s.degree(direction) + 1);
  const auto refined = insert_knot(s, direction, value, times);
  RC_ASSERT(refined.has_value());
  const std::size_t before = direction == Direction::u ? s.control_net().rows() : s.control_net().columns();
  const std::size_t after = direction == Direction::u ? refined->control_net().rows() : refined->control_net().columns();
  RC_ASSERT(after == before + static_cast<std::size_t>(times));
  RC_ASSERT(multiplicity_of(refined->knots(direction), value) == have + times);
  RC_ASSERT(largest_distance(s, s.domain_u(), s.domain_v(), *refined, identity) <= test::surface_tolerance(s));
}

RC_GTEST_PROP(SurfaceDirectionOps, ClampingKeepsTheSurfaceAndItsDomain, ()) {
  const BSplineSurface s = *test::bspline_surface();
  const Direction direction = any_direction();
  const BSplineSurface c = clamped(s, direction);
  const auto knots = c.knots(direction);
  const auto p = static_cast<std::size_t>(c.degree(direction));
  RC_ASSERT(knots[0] == knots[p]);
  RC_ASSERT(knots[knots.size() - 1] == knots[knots.size() - 1 - p]);
  RC_ASSERT(c.domain(direction) == s.domain(direction));
  const Direction other = direction == Direction::u ? Direction::v : Direction::u;
  RC_ASSERT(std::equal(c.knots(other).begin(), c.knots(other).end(), s.knots(other).begin(), s.knots(other).end()));
  RC_ASSERT(largest_distance(s, s.domain_u(), s.domain_v(), c, identity) <= test::surface_tolerance(s));
  RC_ASSERT(clamped(c, direction) == c);  // clamped stays as it is
}

RC_GTEST_PROP(SurfaceDirectionOps, RefineKnotsKeepsTheSurface, ()) {
  const BSplineSurface s = *test::bspline_surface();
  const Direction direction = any_direction();
  const Interval domain = s.domain(direction);
  const auto fractions = *rc::gen::container<std::vector<int>>(*rc::gen::inRange(1, 6), rc::gen::inRange(1, 64));
  std::vector<double> knots;
  for (int f : fractions) knots.push_back(domain.lerp(f / 64.0));
  std::vector<int> counts;
  for (double k : knots) counts.push_back(multiplicity_of(s.knots(direction), k) + static_cast<int>(std::count(knots.begin(), knots.end(), k)));
  for (int c : counts) RC_PRE(c <= s.degree(direction) + 1);
  const auto refined = refine_knots(s, direction, knots);
  RC_ASSERT(refined.has_value());
  RC_ASSERT(largest_distance(s, s.domain_u(), s.domain_v(), *refined, identity) <= test::surface_tolerance(s));
  // The other direction is untouched.
  const Direction other = direction == Direction::u ? Direction::v : Direction::u;
  RC_ASSERT(std::equal(refined->knots(other).begin(), refined->knots(other).end(), s.knots(other).begin(),
                       s.knots(other).end()));
}

RC_GTEST_PROP(SurfaceDirectionOps, ElevateDegreeKeepsTheSurface, ()) {
  const BSplineSurface s = *test::bspline_surface({.max_degree = 3});
  const Direction direction = any_direction();
  const int times = *rc::gen::inRange(1, 3);
  const auto elevated = elevate_degree(s, direction, times);
  RC_ASSERT(elevated.has_value());
  RC_ASSERT(elevated->degree(direction) == s.degree(direction) + times);
  RC_ASSERT(elevated->domain(direction) == s.domain(direction));
  RC_ASSERT(largest_distance(s, s.domain_u(), s.domain_v(), *elevated, identity) <= test::surface_tolerance(s, 1e-11));
}

RC_GTEST_PROP(SurfaceDirectionOps, ElevateBezierKeepsThePatch, ()) {
  const BezierSurface patch = *test::bezier_surface(5);
  const Direction direction = any_direction();
  const int times = *rc::gen::inRange(0, 3);
  const auto elevated = elevate_degree(patch, direction, times);
  RC_ASSERT(elevated.has_value());
  const int before = direction == Direction::u ? patch.degree_u() : patch.degree_v();
  const int after = direction == Direction::u ? elevated->degree_u() : elevated->degree_v();
  RC_ASSERT(after == before + times);
  const double tol = test::surface_tolerance(to_bspline_surface(patch), 1e-13);
  RC_ASSERT(largest_distance(patch, Interval{}, Interval{}, *elevated, identity) <= tol);
}

RC_GTEST_PROP(SurfaceDirectionOps, SplitPartsAreTheSurfaceRestricted, ()) {
  const BSplineSurface s = *test::bspline_surface();
  const Direction direction = any_direction();
  const Interval domain = s.domain(direction);
  const double value = domain.lerp(*rc::gen::inRange(1, 64) / 64.0);
  const auto parts = split_at(s, direction, value);
  RC_ASSERT(parts.has_value());
  const auto& [first, second] = *parts;
  RC_ASSERT(first.domain(direction) == (Interval{domain.lower, value}));
  RC_ASSERT(second.domain(direction) == (Interval{value, domain.upper}));
  const double tol = test::surface_tolerance(s);
  RC_ASSERT(largest_distance(first, first.domain_u(), first.domain_v(), s, identity) <= tol);
  RC_ASSERT(largest_distance(second, second.domain_u(), second.domain_v(), s, identity) <= tol);
}

RC_GTEST_PROP(SurfaceDirectionOps, BezierSplitHalvesAreThePatchRestricted, ()) {
  const BezierSurface patch = *test::bezier_surface(5);
  const Direction direction = any_direction();
  const double t = *rc::gen::inRange(1, 1000) / 1000.0;
  const auto parts = split_at(patch, direction, t);
  RC_ASSERT(parts.has_value());
  const double tol = test::surface_tolerance(to_bspline_surface(patch), 1e-13);
  const bool u = direction == Direction::u;
  RC_ASSERT(largest_distance(parts->first, Interval{}, Interval{}, patch, [&](double a, double b) {
              return u ? std::make_pair(t * a, b) : std::make_pair(a, t * b);
            }) <= tol);
  RC_ASSERT(largest_distance(parts->second, Interval{}, Interval{}, patch, [&](double a, double b) {
              return u ? std::make_pair(t + (1 - t) * a, b) : std::make_pair(a, t + (1 - t) * b);
            }) <= tol);
}

RC_GTEST_PROP(SurfaceDirectionOps, IsoCurvesOfBezierPatches, ()) {
  const BezierSurface patch = *test::bezier_surface(5);
  const double a = *test::unit_parameter(), b = *test::unit_parameter();
  const auto along_v = iso_curve(patch, Direction::u, a);
  const auto along_u = iso_curve(patch, Direction::v, b);
  RC_ASSERT(along_v.has_value());
  RC_ASSERT(along_u.has_value());
  RC_ASSERT(along_v->degree() == patch.degree_v());
  RC_ASSERT(along_u->degree() == patch.degree_u());
  const double tol = test::surface_tolerance(to_bspline_surface(patch), 1e-13);
  RC_ASSERT(distance(point_at(*along_v, b), point_at(patch, a, b)) <= tol);
  RC_ASSERT(distance(point_at(*along_u, a), point_at(patch, a, b)) <= tol);
}

TEST(SurfaceDirectionOps, IsoCurveOfANurbsSurfaceIsExact) {
  // The iso-curve's points against the exact surface point (GMP).
  std::vector<double> c, w;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 5; ++j) {
      c.insert(c.end(), {i * 1.0, j * 0.5, ((i + j) % 3) * 0.25});
      w.push_back(0.5 + ((i * 2 + j) % 4) * 0.5);
    }
  const auto s = *BSplineSurface::make(2, 3, {0, 0, 0, 0.5, 1, 1, 1}, {0, 0, 0, 0, 0.25, 1, 1, 1, 1},
                                       *ControlNet::make(4, 5, *PointArray::make(3, c)), w);
  double worst = 0.0;
  for (double u : {0.0, 0.3, 0.5, 1.0})
    for (double v : {0.0, 0.25, 0.7, 1.0}) {
      const auto exact = test::exact_surface_point(s, u, v);
      worst = std::max(worst, test::relative_error(point_at(*iso_curve(s, Direction::u, u), v), exact, 3.0));
      worst = std::max(worst, test::relative_error(point_at(*iso_curve(s, Direction::v, v), u), exact, 3.0));
    }
  EXPECT_LE(worst, 1e-15);
}

BSplineSurface small_surface() {
  std::vector<double> c;
  for (int k = 0; k < 12; ++k) c.insert(c.end(), {k * 1.0, k * 0.5, 1.0});
  return *BSplineSurface::make(1, 2, {0, 0, 2, 4, 4}, {0, 0, 0, 0.5, 1, 1, 1}, *ControlNet::make(3, 4, *PointArray::make(3, c)));
}

TEST(SurfaceDirectionOps, BadValuesAreRefusedNamingTheDirection) {
  const BSplineSurface s = small_surface();
  auto message = [](const auto& result) { return result.has_value() ? std::string("(no error)") : result.error().message; };
  EXPECT_EQ(message(insert_knot(s, Direction::u, 7.5)), "direction u: knot to insert (7.5) is outside the domain [0, 4]");
  EXPECT_EQ(message(insert_knot(s, Direction::v, NAN)), "direction v: knot to insert is NaN");
  EXPECT_EQ(message(insert_knot(s, Direction::v, 0.5, -1)),
            "direction v: a knot cannot be inserted -1 times, the count must be >= 0");
  EXPECT_EQ(message(insert_knot(s, Direction::u, 2.0, 2)),
            "direction u: inserting 2 x 2 would give that knot multiplicity 3 (it has 1), above degree + 1 = 2");
  const double knots[] = {0.5, -1.0};
  EXPECT_EQ(message(refine_knots(s, Direction::v, knots)),
            "direction v: new knot 1 (-1) is outside the domain [0, 1]");
  EXPECT_EQ(message(elevate_degree(s, Direction::u, -2)),
            "direction u: cannot elevate the degree -2 times, times must be >= 0");
  EXPECT_EQ(message(split_at(s, Direction::u, 4.0)),
            "direction u: the split parameter 4 is not strictly inside the domain [0, 4]");
  EXPECT_EQ(message(split_at(s, Direction::v, INFINITY)), "direction v: the split parameter is infinite");
  EXPECT_EQ(message(iso_curve(s, Direction::u, 4.5)), "the iso-curve parameter u = 4.5 is outside the domain [0, 4]");
  EXPECT_EQ(message(iso_curve(s, Direction::v, NAN)), "the iso-curve parameter v is NaN");
  // times = 0 and no new knots give the surface unchanged.
  EXPECT_EQ(*insert_knot(s, Direction::u, 1.0, 0), s);
  EXPECT_EQ(*refine_knots(s, Direction::u, {}), s);
  EXPECT_EQ(*elevate_degree(s, Direction::v, 0), s);

  const BezierSurface patch = *BezierSurface::make(*ControlNet::make(2, 2, *PointArray::make(3, std::vector<double>(12, 1.0))));
  EXPECT_EQ(message(split_at(patch, Direction::u, 1.0)),
            "the split parameter u = 1 is not strictly inside the domain (0, 1)");
  EXPECT_EQ(message(split_at(patch, Direction::v, NAN)), "the split parameter v is NaN");
  EXPECT_EQ(message(iso_curve(patch, Direction::u, -0.5)),
            "the iso-curve parameter u = -0.5 is outside the domain [0, 1]");
  EXPECT_EQ(message(elevate_degree(patch, Direction::v, -1)),
            "direction v: cannot elevate the degree -1 times, times must be >= 0");
  EXPECT_EQ(message(elevate_degree(patch, Direction::v, 10'000)),
            "direction v: degree 1 + 10000 is above the limit 10000");
}

TEST(SurfaceDirectionOps, InsertionInUIsTheCurveInsertionOnEveryColumn) {
  // The NURBS Book A5.3: each column of the net is a curve along u; inserting
  // into the surface equals inserting into each column curve.
  const BSplineSurface s = small_surface();
  const BSplineSurface refined = *insert_knot(s, Direction::u, 1.0);
  for (std::size_t j = 0; j < s.control_net().columns(); ++j) {
    std::vector<double> column;
    for (std::size_t i = 0; i < s.control_net().rows(); ++i)
      column.insert(column.end(), s.control_net()(i, j).begin(), s.control_net()(i, j).end());
    const auto curve = *BSplineCurve::make(1, {0, 0, 2, 4, 4}, *PointArray::make(3, column));
    const auto inserted = *insert_knot(curve, 1.0);
    for (std::size_t i = 0; i < refined.control_net().rows(); ++i)
      for (int c = 0; c < 3; ++c) EXPECT_EQ(refined.control_net()(i, j)[c], inserted.control_points()[i][c]);
  }
}

}  // namespace
}  // namespace casteljau
