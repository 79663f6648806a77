// Decomposition into Bézier pieces (The NURBS Book A5.6) and recomposition,
// with knot removal bringing the smoothness back.
#include "casteljau/bspline/bezier_pieces.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <vector>

#include "casteljau/bezier/evaluate.hpp"
#include "casteljau/bspline/evaluate.hpp"
#include "casteljau/bspline/knot_removal.hpp"
#include "casteljau/bspline/knot_vector.hpp"
#include "casteljau/bspline/transform.hpp"
#include "support/bspline_generators.hpp"
#include "support/generators.hpp"

namespace casteljau {
namespace {

/// The number of non-empty spans inside the domain.
std::size_t span_count(const BSplineCurve& curve) {
  std::size_t count = 0;
  const auto t = curve.knots();
  for (int k = curve.degree(); k < static_cast<int>(curve.control_points().size()); ++k)
    if (t[k] < t[k + 1]) ++count;
  return count;
}

RC_GTEST_PROP(ToBezierPieces, EachPieceIsTheCurveOnItsSpan, ()) {
  const auto curve = *test::bspline_curve();
  const BezierPieces pieces = to_bezier_pieces(curve);
  RC_ASSERT(pieces.pieces.size() == span_count(curve));
  RC_ASSERT(pieces.breakpoints.size() == pieces.pieces.size() + 1);
  RC_ASSERT(pieces.breakpoints.front() == curve.domain().lower);
  RC_ASSERT(pieces.breakpoints.back() == curve.domain().upper);
  const double tol = test::shape_tolerance(curve);
  for (std::size_t i = 0; i < pieces.pieces.size(); ++i) {
    const auto& piece = pieces.pieces[i];
    RC_ASSERT(piece.degree() == curve.degree());
    RC_ASSERT(piece.is_rational() == curve.is_rational());
    const double a = pieces.breakpoints[i], b = pieces.breakpoints[i + 1];
    for (int j = 0; j <= 8; ++j) {
      const double t = j / 8.0;
      const double u = j == 8 ? b : a + t * (b - a);
      RC_ASSERT(distance(point_at(piece, t), point_at(curve, u)) <= tol);
    }
  }
}

RC_GTEST_PROP(FromBezierPieces, RoundTripKeepsTheShapeAndRemovalRestoresTheKnots, ()) {
  const auto curve = *test::bspline_curve();
  const BSplineCurve joined = from_bezier_pieces(to_bezier_pieces(curve)).value();
  RC_ASSERT(joined.domain() == curve.domain());
  RC_ASSERT(test::largest_distance(curve, joined) <= test::shape_tolerance(curve));
  // The joints have multiplicity p; removing what is removable gives back the
  // (clamped) original knots: random control points make no knot removable
  // beyond its original multiplicity.
  const double tol = test::shape_tolerance(curve, 1e-9);
  const KnotRemoval smooth = remove_knots(joined, Tolerance{tol}).value();
  RC_ASSERT(smooth.error_bound <= tol);
  const BSplineCurve original = clamped(curve);
  RC_ASSERT(std::vector<double>(smooth.curve.knots().begin(), smooth.curve.knots().end()) ==
            std::vector<double>(original.knots().begin(), original.knots().end()));
  RC_ASSERT(test::largest_distance(curve, smooth.curve) <= tol + test::shape_tolerance(curve));
}

TEST(ToBezierPieces, UniformCubicGivesTheClassicRule) {
  // Uniform cubic B-spline, span [3,4] of knots 0..7 (unclamped): Bézier points
  // (P0 + 4P1 + P2)/6, (2P1 + P2)/3, (P1 + 2P2)/3, (P1 + 4P2 + P3)/6
  // (Böhm's B-spline to Bézier rule; Farin, "Curves and Surfaces for CAGD", §8.5).
  const auto curve = BSplineCurve::make(3, {0, 1, 2, 3, 4, 5, 6, 7},
                                        PointArray::make({{0, 0}, {6, 12}, {12, 6}, {18, 0}}).value())
                         .value();
  const auto pieces = to_bezier_pieces(curve);
  ASSERT_EQ(pieces.pieces.size(), 1u);
  EXPECT_EQ(pieces.breakpoints, (std::vector<double>{3, 4}));
  const double expected[4][2] = {{(0 + 24 + 12) / 6.0, (0 + 48 + 6) / 6.0},
                                 {(12 + 12) / 3.0, (24 + 6) / 3.0},
                                 {(6 + 24) / 3.0, (12 + 12) / 3.0},
                                 {(6 + 48 + 18) / 6.0, (12 + 24 + 0) / 6.0}};
  for (int i = 0; i < 4; ++i)
    for (int c = 0; c < 2; ++c)
      EXPECT_NEAR(pieces.pieces[0].control_points()[i][c], expected[i][c], 1e-14) << i << "," << c;
}

TEST(ToBezierPieces, ABezierCurveIsOnePiece) {
  const auto bezier = BezierCurve::make(PointArray::make({{1, 0}, {1, 1}, {0, 1}}).value(), {1, 0.5, 2}).value();
  const auto pieces = to_bezier_pieces(to_bspline(bezier));
  ASSERT_EQ(pieces.pieces.size(), 1u);
  EXPECT_EQ(pieces.pieces[0], bezier);  // no knot inserted: bit for bit
}

TEST(ToBezierPieces, PiecewiseBezierRoundTrip) {
  const auto a = BezierCurve::make(PointArray::make({{0, 0}, {1, 2}, {2, 2}, {3, 0}}).value()).value();
  const auto b = BezierCurve::make(PointArray::make({{3, 0}, {4, -1}, {5, 0}}).value()).value();
  const auto piecewise = PiecewiseBezierCurve::make({a, b}).value();
  const auto pieces = to_bezier_pieces(piecewise);
  EXPECT_EQ(pieces.breakpoints, (std::vector<double>{0, 1, 2}));
  EXPECT_EQ(to_piecewise_bezier(pieces), piecewise);
  // Different degrees: the quadratic is elevated, the B-spline is cubic with a C0 joint.
  const auto spline = from_bezier_pieces(pieces).value();
  EXPECT_EQ(spline.degree(), 3);
  EXPECT_EQ(std::vector<double>(spline.knots().begin(), spline.knots().end()),
            (std::vector<double>{0, 0, 0, 0, 1, 1, 1, 2, 2, 2, 2}));
  for (int i = 0; i <= 20; ++i) {
    const double u = i / 10.0;
    EXPECT_LE(distance(point_at(spline, u), point_at(piecewise, u)), 1e-14 * 8) << u;
  }
}

TEST(FromBezierPieces, RationalPiecesAgreeOnTheJointWeight) {
  // The same quarter circle written with weights (1, s, 1) and (2, 2s, 2):
  // the second is rescaled so the joint weight is shared.
  const double s = std::sqrt(0.5);
  const auto q1 = BezierCurve::make(PointArray::make({{1, 0}, {1, 1}, {0, 1}}).value(), {1, s, 1}).value();
  const auto q2 = BezierCurve::make(PointArray::make({{0, 1}, {-1, 1}, {-1, 0}}).value(), {2, 2 * s, 2}).value();
  const auto spline = from_bezier_pieces({{0, 1, 2}, {q1, q2}}).value();
  ASSERT_TRUE(spline.is_rational());
  EXPECT_EQ(spline.weights()[2], 1.0);
  EXPECT_NEAR(spline.weights()[3], s, 1e-16);
  for (int i = 0; i <= 40; ++i) {
    const Point p = point_at(spline, i / 20.0);
    EXPECT_NEAR(std::hypot(p[0], p[1]), 1.0, 1e-15 * 4);  // a half circle of radius 1
  }
}

TEST(FromBezierPieces, RefusesBadPiecesWithClearMessages) {
  const auto a = BezierCurve::make(PointArray::make({{0, 0}, {1, 1}}).value()).value();
  const auto b = BezierCurve::make(PointArray::make({{1.5, 1}, {2, 0}}).value()).value();
  auto gap = from_bezier_pieces({{0, 1, 2}, {a, b}});
  ASSERT_FALSE(gap.has_value());
  EXPECT_EQ(gap.error().message,
            "piece 1 starts 0.5 away from the end of piece 0 (more than 2e-09), consecutive pieces must meet");
  EXPECT_FALSE(from_bezier_pieces({{}, {}}).has_value());
  auto count = from_bezier_pieces({{0, 1}, {a, a}});
  ASSERT_FALSE(count.has_value());
  EXPECT_EQ(count.error().message, "2 breakpoints for 2 pieces, there must be one more breakpoint than pieces");
  auto order = from_bezier_pieces({{0, 1, 1}, {a, a}});
  ASSERT_FALSE(order.has_value());
  EXPECT_NE(order.error().message.find("breakpoint 2 (1) is not above breakpoint 1 (1)"), std::string::npos);
  const auto c3 = BezierCurve::make(PointArray::make({{1, 1, 0}, {2, 0, 0}}).value()).value();
  auto dimension = from_bezier_pieces({{0, 1, 2}, {a, c3}});
  ASSERT_FALSE(dimension.has_value());
  EXPECT_EQ(dimension.error().message, "piece 1 has dimension 3, piece 0 has 2");
}

TEST(FromBezierPieces, DegreeZeroPiecesArePiecewiseConstant) {
  const auto a = BezierCurve::make(PointArray::make({{1, 2}}).value()).value();
  const auto b = BezierCurve::make(PointArray::make({{3, 4}}).value()).value();
  const auto spline = from_bezier_pieces({{0, 1, 3}, {a, b}}).value();
  EXPECT_EQ(spline.degree(), 0);
  EXPECT_EQ(point_at(spline, 0.5), (Point{1, 2}));
  EXPECT_EQ(point_at(spline, 2.0), (Point{3, 4}));
}

}  // namespace
}  // namespace casteljau
