// The curve concept (curves/curve.hpp) holds the same way on every kind:
// each property below is written once and run on Bézier (polynomial and
// rational), piecewise Bézier and B-spline/NURBS curves. References: the
// kind's own functions (CurveView must agree bit for bit), the curve itself
// at mapped parameters (split, segment, reversal, affine maps, derivative
// curves: the algorithms are exact, so agreement to rounding), and fixed
// messages for the failure contract.
#include "casteljau/curves/curve.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "casteljau/curves/curve_view.hpp"
#include "support/bspline_generators.hpp"
#include "support/generators.hpp"

namespace casteljau {
namespace {

/// A random curve of each kind (dimension 1..4 for Bézier pieces, 2..3 for B-splines).
template <class Kind>
rc::Gen<Kind> any_curve();

template <>
rc::Gen<BezierCurve> any_curve<BezierCurve>() {
  return test::any_bezier_curve(8);
}

template <>
rc::Gen<PiecewiseBezierCurve> any_curve<PiecewiseBezierCurve>() {
  return rc::gen::exec([] {
    const int d = *rc::gen::inRange(1, 5);
    const int m = *rc::gen::inRange(1, 5);
    std::vector<BezierCurve> pieces;
    for (int i = 0; i < m; ++i) pieces.push_back(*test::bezier_curve(0, 6, *rc::gen::arbitrary<bool>(), d));
    return PiecewiseBezierCurve::make(std::move(pieces)).value();
  });
}

template <>
rc::Gen<BSplineCurve> any_curve<BSplineCurve>() {
  return test::bspline_curve();
}

/// |p|.
double norm_of(const Point& p) { return distance(p, Point(p.size(), 0.0)); }

/// max w / min w over every weight of the curve (1 when polynomial).
double weight_ratio(CurveView curve) {
  double lowest = 1.0, highest = 1.0;
  for (const BezierCurve& piece : to_bezier_pieces(curve).pieces)
    for (double w : piece.weights()) lowest = std::min(lowest, w), highest = std::max(highest, w);
  return highest / lowest;
}

/// Agreement to rounding for two computations of one point of the curve.
double point_tolerance(CurveView curve) {
  return 1e-11 * std::max(1.0, scale_of(curve)) * weight_ratio(curve) * weight_ratio(curve);
}

/// A parameter of the domain: an end, a breakpoint, or a 1e-6 grid fraction.
rc::Gen<double> parameter_of(CurveView curve) {
  const Interval domain = curve.domain();
  return rc::gen::weightedOneOf<double>(
      {{1, rc::gen::elementOf(breakpoints(curve))},
       {4, rc::gen::map(rc::gen::inRange(0, 1000001), [domain](int i) { return domain.lerp(i * 1e-6); })}});
}

/// A parameter strictly inside the domain, on a 1e-3 grid.
rc::Gen<double> interior_parameter_of(CurveView curve) {
  const Interval domain = curve.domain();
  return rc::gen::map(rc::gen::inRange(1, 1000), [domain](int i) { return domain.lerp(i * 1e-3); });
}

template <class Kind>
void view_agrees_with_the_kind() {
  const Kind curve = *any_curve<Kind>();
  const CurveView view(curve);
  RC_ASSERT(view.domain() == curve.domain());
  RC_ASSERT(view.dimension() == curve.dimension());
  RC_ASSERT(view.degree() == curve.degree());
  RC_ASSERT(view.is_rational() == curve.is_rational());
  RC_ASSERT(breakpoints(view) == breakpoints(curve));
  RC_ASSERT(to_bezier_pieces(view) == to_bezier_pieces(curve));
  const auto us = *rc::gen::container<std::vector<double>>(*rc::gen::inRange(1, 20), parameter_of(view));
  const std::size_t d = curve.dimension();
  std::vector<double> direct(us.size() * d), through(us.size() * d);
  points_at(curve, us, direct);
  points_at(view, us, through);
  RC_ASSERT(direct == through);
  for (std::size_t i = 0; i < us.size(); ++i) {
    RC_ASSERT(point_at(view, us[i]) == point_at(curve, us[i]));
    RC_ASSERT(Point(direct.begin() + i * d, direct.begin() + (i + 1) * d) == point_at(curve, us[i]));
    const int k = *rc::gen::inRange(0, 4);
    RC_ASSERT(derivative_at(view, us[i], k) == derivative_at(curve, us[i], k));
    RC_ASSERT(derivatives_up_to(view, us[i], k) == derivatives_up_to(curve, us[i], k));
  }
}

template <class Kind>
void batches_match_the_single_functions() {
  const Kind curve = *any_curve<Kind>();
  const CurveView view(curve);
  const auto us = *rc::gen::container<std::vector<double>>(*rc::gen::inRange(1, 40), parameter_of(view));
  const std::size_t d = curve.dimension();
  const int order = *rc::gen::inRange(0, 3);
  std::vector<double> batch(us.size() * d), points(us.size() * d), first(us.size() * d);
  derivatives_at(view, us, order, batch);
  points_and_derivatives_at(view, us, points, first);
  const double falling = std::pow(std::max(1, curve.degree()), order);
  for (std::size_t i = 0; i < us.size(); ++i) {
    const Point expected = derivative_at(curve, us[i], order);
    const Point point = point_at(curve, us[i]);
    const Point slope = derivative_at(curve, us[i], 1);
    const double size = std::max({1.0, scale_of(view), norm_of(expected)});
    for (std::size_t j = 0; j < d; ++j) {
      RC_ASSERT(std::abs(batch[i * d + j] - expected[j]) <= 1e-11 * falling * size * weight_ratio(view));
      RC_ASSERT(std::abs(points[i * d + j] - point[j]) <= point_tolerance(view));
      RC_ASSERT(std::abs(first[i * d + j] - slope[j]) <=
                1e-11 * std::max({1.0, scale_of(view), norm_of(slope)}) * curve.degree() *
                    weight_ratio(view));
    }
  }
}

template <class Kind>
void points_at_within_stops_at_the_first_parameter_outside() {
  const Kind curve = *any_curve<Kind>();
  const CurveView view(curve);
  const Interval domain = curve.domain();
  // Long enough to cross a checked block (512 parameters) sometimes.
  auto us = *rc::gen::container<std::vector<double>>(*rc::gen::inRange(1, 1200), parameter_of(view));
  const std::size_t d = curve.dimension();
  std::vector<double> out(us.size() * d), all(us.size() * d);
  points_at(curve, us, all);
  RC_ASSERT(points_at_within(view, us, domain, out) == us.size());
  RC_ASSERT(out == all);
  const std::size_t bad = *rc::gen::inRange<std::size_t>(0, us.size());
  us[bad] = *rc::gen::element<double>(std::nan(""), domain.upper + 1.0, domain.lower - 0.5, INFINITY, -INFINITY);
  RC_ASSERT(points_at_within(view, us, domain, out) == bad);
  RC_ASSERT(std::equal(out.begin(), out.begin() + static_cast<std::ptrdiff_t>(bad * d), all.begin()));
}

template <class Kind>
void breakpoints_are_the_bezier_pieces_joints() {
  const Kind curve = *any_curve<Kind>();
  const CurveView view(curve);
  const std::vector<double> b = breakpoints(view);
  const BezierPieces pieces = to_bezier_pieces(view);
  RC_ASSERT(b == pieces.breakpoints);
  RC_ASSERT(b.front() == curve.domain().lower && b.back() == curve.domain().upper);
  RC_ASSERT(std::adjacent_find(b.begin(), b.end(), std::greater_equal<double>()) == b.end());
  // Each piece traces the curve on its interval.
  for (std::size_t i = 0; i + 1 < b.size(); ++i) {
    const double s = *rc::gen::map(rc::gen::inRange(0, 1001), [](int k) { return k * 1e-3; });
    const double u = Interval{b[i], b[i + 1]}.lerp(s);
    RC_ASSERT(distance(point_at(pieces.pieces[i], s), point_at(curve, u)) <= point_tolerance(view));
  }
}

template <class Kind>
void split_and_segment_keep_the_ends() {
  const Kind curve = *any_curve<Kind>();
  const CurveView view(curve);
  const Interval domain = curve.domain();
  const double u = *interior_parameter_of(view);
  const auto parts = split_at(curve, u);
  RC_ASSERT(parts.has_value());
  const double tolerance = point_tolerance(view);
  const CurveView first(parts->first), second(parts->second);
  RC_ASSERT(distance(point_at(first, first.domain().lower), point_at(curve, domain.lower)) <= tolerance);
  RC_ASSERT(distance(point_at(second, second.domain().upper), point_at(curve, domain.upper)) <= tolerance);
  // The cut: C(u) from the right (a knot of multiplicity p+1 would jump; the generators make none).
  RC_ASSERT(distance(point_at(second, second.domain().lower), point_at(curve, u)) <= tolerance);
  RC_ASSERT(distance(point_at(first, first.domain().upper), point_at(curve, u)) <= tolerance);

  const double a = *interior_parameter_of(view), b = *interior_parameter_of(view);
  RC_PRE(a < b);
  const auto piece = segment(curve, a, b);
  RC_ASSERT(piece.has_value());
  const CurveView part(*piece);
  RC_ASSERT(distance(point_at(part, part.domain().lower), point_at(curve, a)) <= tolerance);
  RC_ASSERT(distance(point_at(part, part.domain().upper), point_at(curve, b)) <= tolerance);
}

template <class Kind>
void reversal_runs_backwards_on_the_same_domain() {
  const Kind curve = *any_curve<Kind>();
  const CurveView view(curve);
  const Kind back = reversed(curve);
  const Interval domain = curve.domain();
  RC_ASSERT(back.domain() == domain);
  const double u = *parameter_of(view);
  // Not at an interior joint: pieces of a piecewise curve need not meet, and
  // there each side takes the piece to its right.
  const std::vector<double> joints = breakpoints(view);
  RC_PRE(std::find(joints.begin() + 1, joints.end() - 1, u) == joints.end() - 1);
  RC_ASSERT(distance(point_at(back, domain.lower + domain.upper - u), point_at(curve, u)) <= point_tolerance(view));
}

template <class Kind>
void affine_maps_map_the_curve() {
  const Kind curve = *any_curve<Kind>();
  const CurveView view(curve);
  const int d = curve.dimension();
  const auto entry = rc::gen::map(rc::gen::inRange(-100, 101), [](int i) { return i * 0.01; });
  const auto map = AffineMap::make(d, *rc::gen::container<std::vector<double>>(d * d, entry),
                                   *rc::gen::container<std::vector<double>>(d, entry))
                       .value();
  const auto image = transformed(curve, map);
  RC_ASSERT(image.has_value());
  const double u = *parameter_of(view);
  RC_ASSERT(distance(point_at(*image, u), transformed_point(map, point_at(curve, u))) <=
            point_tolerance(view) * d * 4);
  const auto wrong = AffineMap::identity(d + 1);
  RC_ASSERT(!transformed(curve, wrong).has_value());
}

template <class Kind>
void derivative_curves_give_the_derivative() {
  const Kind curve = *any_curve<Kind>();
  const CurveView view(curve);
  const auto derivative = derivative_curve(curve, 1);
  if (curve.is_rational()) {
    RC_ASSERT(!derivative.has_value());
    return;
  }
  RC_ASSERT(derivative.has_value());
  // Inside the spans (at a knot the derivative curve and derivative_at may
  // take different sides of a jump in C').
  const double u = *interior_parameter_of(view);
  const Point expected = derivative_at(curve, u, 1);
  RC_ASSERT(distance(point_at(*derivative, u), expected) <=
            1e-11 * std::max({1.0, scale_of(view), norm_of(expected)}) * std::max(1, curve.degree()) * 64);
}

#define CASTELJAU_CURVE_PROPERTY(Name)                                                    \
  RC_GTEST_PROP(CurveConcept, Name##OnBezierCurves, ()) { Name<BezierCurve>(); }         \
  RC_GTEST_PROP(CurveConcept, Name##OnPiecewiseCurves, ()) { Name<PiecewiseBezierCurve>(); } \
  RC_GTEST_PROP(CurveConcept, Name##OnBSplineCurves, ()) { Name<BSplineCurve>(); }

CASTELJAU_CURVE_PROPERTY(view_agrees_with_the_kind)
CASTELJAU_CURVE_PROPERTY(batches_match_the_single_functions)
CASTELJAU_CURVE_PROPERTY(points_at_within_stops_at_the_first_parameter_outside)
CASTELJAU_CURVE_PROPERTY(breakpoints_are_the_bezier_pieces_joints)
CASTELJAU_CURVE_PROPERTY(split_and_segment_keep_the_ends)
CASTELJAU_CURVE_PROPERTY(reversal_runs_backwards_on_the_same_domain)
CASTELJAU_CURVE_PROPERTY(affine_maps_map_the_curve)
CASTELJAU_CURVE_PROPERTY(derivative_curves_give_the_derivative)

/// The same mistake reads the same on every kind (the domain [0, 1] for all three).
TEST(CurveConcept, OneFailureContractForEveryKind) {
  const auto bezier = BezierCurve::make(PointArray::make({{0, 0}, {1, 2}, {2, 0}}).value()).value();
  const auto piecewise = PiecewiseBezierCurve::make({bezier}).value();
  const auto bspline = to_bspline(bezier);
  auto messages = [](const auto& curve) {
    std::vector<std::string> result;
    for (double u : {0.0, 1.0, -0.5, std::nan(""), double{INFINITY}}) result.push_back(split_at(curve, u).error().message);
    for (auto [a, b] : {std::pair{0.5, 0.25}, std::pair{0.5, 0.5}, std::pair{-1.0, 0.5}, std::pair{0.25, 2.0}})
      result.push_back(segment(curve, a, b).error().message);
    return result;
  };
  const std::vector<std::string> expected = {
      "the split parameter 0 is not strictly inside the domain [0, 1]",
      "the split parameter 1 is not strictly inside the domain [0, 1]",
      "the split parameter -0.5 is not strictly inside the domain [0, 1]",
      "the split parameter is NaN",
      "the split parameter is infinite",
      "the segment [0.5, 0.25] needs its start below its end",
      "the segment [0.5, 0.5] needs its start below its end",
      "the segment [-1, 0.5] is not inside the domain [0, 1]",
      "the segment [0.25, 2] is not inside the domain [0, 1]",
  };
  EXPECT_EQ(messages(bezier), expected);
  EXPECT_EQ(messages(piecewise), expected);
  EXPECT_EQ(messages(bspline), expected);
  const auto rational = BezierCurve::make(PointArray::make({{0, 0}, {1, 2}, {2, 0}}).value(), {1, 2, 1}).value();
  EXPECT_FALSE(derivative_curve(rational).has_value());
  EXPECT_FALSE(derivative_curve(PiecewiseBezierCurve::make({bezier, rational}).value()).has_value());
}

TEST(CurveConcept, PiecewiseSplitAtAJunctionSharesThePiecesOut) {
  const auto a = BezierCurve::make(PointArray::make({{0, 0}, {1, 1}}).value()).value();
  const auto b = BezierCurve::make(PointArray::make({{1, 1}, {2, 0}, {3, 1}}).value()).value();
  const auto curve = PiecewiseBezierCurve::make({a, b, a}).value();
  const auto parts = split_at(curve, 2.0).value();
  EXPECT_EQ(parts.first, PiecewiseBezierCurve::make({a, b}).value());
  EXPECT_EQ(parts.second, PiecewiseBezierCurve::make({a}).value());
  const auto middle = segment(curve, 1.0, 2.0).value();
  EXPECT_EQ(middle, PiecewiseBezierCurve::make({b}).value());
  const auto inside = segment(curve, 0.5, 1.5).value();
  ASSERT_EQ(inside.size(), 2);
  EXPECT_EQ(point_at(inside, 0.0), point_at(curve, 0.5));
  EXPECT_EQ(point_at(inside, 2.0), point_at(curve, 1.5));
  EXPECT_EQ(breakpoints(curve), (std::vector<double>{0, 1, 2, 3}));
}

}  // namespace
}  // namespace casteljau
