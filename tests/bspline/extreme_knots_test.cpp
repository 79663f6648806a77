// Regression tests of issue 15's knot vectors: a span of subnormal width
// (5e-324, 1e-310) crashed points_at (the span search divided by the width
// and cast the NaN to an index), and knots -1e308, 1e308 (a vector wider
// than the largest double) evaluated to (0, 0) silently. validate_knots now
// refuses them, in the full and the Rhino conventions, and make() with them;
// the batch kernels stay defined for computed curves whose knots are only
// well-formed (check_knot_structure), such as a knot inserted beside another.

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "casteljau/bspline/bspline_curve.hpp"
#include "casteljau/bspline/evaluate.hpp"
#include "casteljau/bspline/knot_insertion.hpp"
#include "casteljau/bspline/knot_vector.hpp"
#include "casteljau/bspline/transform.hpp"
#include "casteljau/core/tolerance.hpp"
#include "casteljau/surfaces/bspline_surface.hpp"
#include "support/make.hpp"

namespace casteljau {
namespace {

using test::message_of;

PointArray line() { return PointArray::from_trusted(2, {0, 0, 1, 1}); }

TEST(ExtremeKnots, TheIssuesVectorsAreRefusedWithTheirIndices) {
  EXPECT_EQ(message_of(validate_knots(std::vector<double>{0, 0, 5e-324, 5e-324}, 1, 2)),
            "knots 1 and 2 (0 and 5e-324) are 5e-324 apart, less than the narrowest "
            "knot span 1e-100");
  EXPECT_EQ(message_of(validate_knots(std::vector<double>{0, 0, 1e-310, 1e-310}, 1, 2)),
            "knots 1 and 2 (0 and 1e-310) are 1e-310 apart, less than the narrowest knot span 1e-100");
  EXPECT_EQ(message_of(validate_knots(std::vector<double>{-1e308, -1e308, 1e308, 1e308}, 1, 2)),
            "knot 0 is -1e+308, outside [-1e+100, 1e+100], the range of knots");
  EXPECT_EQ(message_of(BSplineCurve::make(1, {0, 0, 5e-324, 5e-324}, line())),
            "knots 1 and 2 (0 and 5e-324) are 5e-324 apart, less than the narrowest "
            "knot span 1e-100");
  // A narrow span outside the domain counts too (spans are checked everywhere).
  EXPECT_EQ(message_of(validate_knots(std::vector<double>{-1e-310, 0, 1, 2}, 1, 2)),
            "knots 0 and 1 (-1e-310 and 0) are 1e-310 apart, less than the narrowest knot span 1e-100");
}

TEST(ExtremeKnots, TheRhinoConventionNamesItsOwnIndices) {
  // Rhino's [0, 5e-324] is the full vector [0, 0, 5e-324, 5e-324] without its ends.
  EXPECT_EQ(message_of(knots_from_rhino(std::vector<double>{0, 5e-324}, 1, 2)),
            "knots 0 and 1 (0 and 5e-324) are 5e-324 apart, less than the narrowest "
            "knot span 1e-100");
  EXPECT_EQ(message_of(knots_from_rhino(std::vector<double>{0, 1e300}, 1, 2)),
            "knot 1 is 1e+300, outside [-1e+100, 1e+100], the range of knots");
}

TEST(ExtremeKnots, TheEdgesOfTheRangesAreAccepted) {
  const double one_ulp = std::nextafter(1.0, 2.0);
  for (const std::vector<double>& knots : {std::vector<double>{1, 1, one_ulp, one_ulp},
                                           std::vector<double>{0, 0, tolerances::kMinKnotSpan, tolerances::kMinKnotSpan},
                                           std::vector<double>{-tolerances::kMaxKnot, -tolerances::kMaxKnot,
                                                               tolerances::kMaxKnot, tolerances::kMaxKnot}}) {
    const auto curve = BSplineCurve::make(1, knots, line());
    ASSERT_TRUE(curve.has_value()) << curve.error().message;
    // The line from (0, 0) to (1, 1) over the domain: its ends exactly, and
    // the constant derivative (1, 1) / h, finite.
    const Interval domain = curve->domain();
    const std::vector<double> us{domain.lower, domain.upper};
    std::vector<double> points(4), derivatives(4);
    points_and_derivatives_at(*curve, us, points, derivatives);
    EXPECT_EQ(points, (std::vector<double>{0, 0, 1, 1}));
    for (double c : derivatives) EXPECT_TRUE(std::isfinite(c) && c > 0.0) << c;
  }
  EXPECT_FALSE(BSplineCurve::make(1, {0, 0, std::nextafter(tolerances::kMinKnotSpan, 0.0), 1}, line()).has_value());
}

TEST(ExtremeKnots, SurfacesCheckBothDirections) {
  const ControlNet net = ControlNet::from_trusted(2, 2, PointArray::from_trusted(3, {0, 0, 0, 0, 1, 0, 1, 0, 0, 1, 1, 1}));
  const std::vector<double> plain{0, 0, 1, 1}, subnormal{0, 0, 5e-324, 5e-324}, wide{-1e308, -1e308, 1e308, 1e308};
  EXPECT_EQ(message_of(BSplineSurface::make(1, 1, subnormal, plain, net)),
            "knots_u: knots 1 and 2 (0 and 5e-324) are 5e-324 apart, less than the "
            "narrowest knot span 1e-100");
  EXPECT_EQ(message_of(BSplineSurface::make(1, 1, plain, wide, net)),
            "knots_v: knot 0 is -1e+308, outside [-1e+100, 1e+100], the range of knots");
  const ControlNet far = ControlNet::from_trusted(2, 2, PointArray::from_trusted(3, {0, 0, 0, 0, 1, 0, 1, 0, 0, 1, 1, 1e308}));
  EXPECT_EQ(message_of(BSplineSurface::make(1, 1, plain, plain, far)),
            "coordinate 2 of control point [1][1] is 1e+308, outside [-1e+100, 1e+100], the range of coordinates");
  EXPECT_EQ(message_of(BSplineSurface::make(1, 1, plain, plain, net, {1, 1, 1, 1e-320})),
            "weight [1][1] is 1e-320, outside [1e-50, 1e+50], the range of weights");
}

TEST(ExtremeKnots, BatchKernelsStayDefinedForComputedCurvesWithASubnormalDomain) {
  // Well-formed knots make() would refuse: the span search must not turn
  // the infinite 1 / width into an index (it crashed with SIGSEGV). At the
  // ends of the domain the line's ends come out exactly.
  ASSERT_TRUE(check_knot_structure(std::vector<double>{0, 0, 5e-324, 5e-324}, 1, 2).has_value());
  for (const std::vector<double>& knots :
       {std::vector<double>{0, 0, 5e-324, 5e-324}, std::vector<double>{-1e308, -1e308, 1e308, 1e308}}) {
    const BSplineCurve curve = BSplineCurve::from_trusted(1, knots, line());
    const double a = knots[1], b = knots[2];
    // Single parameters (the scalar-fed partial block), and a full block
    // of each end (the SIMD lanes' span guess).
    for (const std::vector<double>& us : {std::vector<double>{a}, std::vector<double>{b},
                                          std::vector<double>(16, a), std::vector<double>(16, b)}) {
      std::vector<double> out(us.size() * 2);
      points_at(curve, us, out);
      const double expected = us[0] == a ? 0.0 : 1.0;
      for (double c : out) EXPECT_EQ(c, expected);
    }
  }
}

// Operations that place a caller's knot keep the rule of make(): a knot
// inserted 5e-324 beside another made the derivative NaN (the difference of
// two control points over a subnormal span overflows).
TEST(ExtremeKnots, InsertedAndSplitKnotsKeepTheNarrowestSpan) {
  const BSplineCurve curve = BSplineCurve::from_trusted(1, {0, 0, 1, 1}, line());
  EXPECT_EQ(message_of(insert_knot(curve, 5e-324)),
            "knot 1 and the knot to insert (0 and 5e-324) are 5e-324 apart, less than the narrowest knot span 1e-100");
  // Spans that narrow exist only near small knots: the new knots 1e-90 and
  // 1e-90 + 1e-101 (representable: the ulp there is 1.5e-106) are each far
  // enough from 0, but not from each other. Equal values are one knot.
  const double close[] = {1e-90, 1e-90 + 1e-101};
  EXPECT_EQ(message_of(refine_knots(curve, close)).substr(0, 43), "the new knots 0 and 1 (1e-90 and 1.00000000")
      << message_of(refine_knots(curve, close));
  const double twice[] = {0.5, 0.5};
  EXPECT_TRUE(refine_knots(curve, twice).has_value());
  EXPECT_EQ(message_of(split_at(curve, 1e-200)).substr(0, 42), "knot 1 and the split parameter (0 and 1e-2");
  // Equal to a knot, or a span of at least 1e-100: accepted, with finite derivatives.
  const auto beside = insert_knot(curve, 1e-100);
  ASSERT_TRUE(beside.has_value());
  EXPECT_TRUE(std::isfinite(derivative_at(*beside, 0.0, 1)[0]));
  EXPECT_TRUE(insert_knot(*beside, 1e-100).has_value());
  EXPECT_TRUE(split_at(curve, 0.5).has_value());
}

TEST(ExtremeKnots, ANewDomainKeepsTheKnotRangeAndTheNarrowestSpan) {
  const BSplineCurve curve = BSplineCurve::from_trusted(1, {0, 0, 0.5, 1, 1}, PointArray::from_trusted(2, {0, 0, 1, 1, 2, 0}));
  EXPECT_EQ(message_of(reparameterized(curve, {0.0, 1e-100})),
            "on [0, 1e-100], knots 1 and 2 (0 and 5e-101) are 5e-101 apart, less than the narrowest knot span 1e-100");
  EXPECT_TRUE(reparameterized(curve, {0.0, 2e-100}).has_value());
  EXPECT_EQ(message_of(reparameterized(curve, {0.0, 1e200})),
            "the new domain's upper end is 1e+200, outside [-1e+100, 1e+100], the range of knots");
}

}  // namespace
}  // namespace casteljau
