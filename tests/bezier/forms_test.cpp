// Vector form (seed 003 "pantin vectoriel"), the de Casteljau construction as
// data, affine invariance, and piecewise curves.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>

#include "casteljau/bezier/affine.hpp"
#include "casteljau/bezier/construction.hpp"
#include "casteljau/bezier/evaluate.hpp"
#include "casteljau/bezier/piecewise_bezier.hpp"
#include "casteljau/bezier/split.hpp"
#include "casteljau/bezier/vector_form.hpp"
#include "support/generators.hpp"

namespace casteljau {
namespace {

TEST(VectorForm, SeedThreeCubic) {
  // Seed 003: OM(t) = V0 + (3t - 3t^2 + t^3) V1 + (3t^2 - 2t^3) V2 + t^3 V3.
  const auto polygon = PointArray::make({{0, 0}, {1, 2}, {3, 3}, {4, 0}}).value();
  const auto v = to_vector_form(polygon);
  EXPECT_EQ(v, PointArray::make({{0, 0}, {1, 2}, {2, 1}, {1, -3}}).value());
  EXPECT_EQ(from_vector_form(v), polygon);
  const auto curve = BezierCurve::make(polygon).value();
  for (double t : {0.0, 0.25, 0.5, 0.8, 1.0}) {
    const double f1 = 3 * t - 3 * t * t + t * t * t, f2 = 3 * t * t - 2 * t * t * t, f3 = t * t * t;
    const Point p = point_at_vector_form(v, t), q = point_at(curve, t);
    for (int j = 0; j < 2; ++j) {
      EXPECT_NEAR(p[j], v[0][j] + f1 * v[1][j] + f2 * v[2][j] + f3 * v[3][j], 1e-14);
      EXPECT_NEAR(p[j], q[j], 1e-14);
    }
  }
}

RC_GTEST_PROP(VectorForm, RoundTripAndSameCurve, ()) {
  const auto curve = *test::bezier_curve(0, 15, false);
  const auto v = to_vector_form(curve.control_points());
  const auto back = from_vector_form(v);
  const double tol = 1e-12 * std::max(1.0, scale_of(curve.control_points()));
  for (std::size_t i = 0; i < back.size(); ++i) RC_ASSERT(distance(back[i], curve.control_points()[i]) <= tol);
  const double t = *test::unit_parameter();
  RC_ASSERT(distance(point_at_vector_form(v, t), point_at(curve, t)) <= tol * (curve.degree() + 1));
}

RC_GTEST_PROP(Construction, LevelsGiveThePointAndTheHalves, ()) {
  const auto curve = *test::any_bezier_curve(12);
  const double t = *test::unit_parameter();
  const auto levels = casteljau_construction(curve, t);
  const int n = curve.degree();
  RC_ASSERT(static_cast<int>(levels.size()) == n + 1);
  for (int r = 0; r <= n; ++r) RC_ASSERT(static_cast<int>(levels[r].size()) == n + 1 - r);
  RC_ASSERT(Point(levels[n][0].begin(), levels[n][0].end()) == point_at(curve, t));
  RC_PRE(t > 0.0 && t < 1.0);
  const auto [left, right] = split_at(curve, t).value();
  for (int r = 0; r <= n; ++r) {
    RC_ASSERT(distance(levels[r][0], left.control_points()[r]) == 0.0);
    RC_ASSERT(distance(levels[r][n - r], right.control_points()[n - r]) == 0.0);
  }
}

RC_GTEST_PROP(Affine, MappingControlPointsMapsTheCurve, ()) {
  const auto curve = *test::any_bezier_curve(10);
  const int d = curve.dimension();
  std::vector<double> a = *rc::gen::container<std::vector<double>>(d * d, test::coordinate());
  std::vector<double> b = *rc::gen::container<std::vector<double>>(d, test::coordinate());
  const auto map = AffineMap::make(d, a, b).value();
  const auto image = transformed(curve, map).value();
  const double t = *test::unit_parameter();
  const Point expected = transformed_point(map, point_at(curve, t));
  double scale = 1.0;
  for (double c : expected) scale = std::max(scale, std::abs(c));
  RC_ASSERT(distance(point_at(image, t), expected) <= 1e-9 * scale * std::max(1.0, scale_of(curve.control_points())));
}

TEST(Affine, RotationAndComposition) {
  const auto line = BezierCurve::make(PointArray::make({{1, 0}, {2, 0}}).value()).value();
  const auto map = AffineMap::translate({1, 1}).after(AffineMap::rotate_2d(M_PI / 2));
  const auto image = transformed(line, map).value();
  EXPECT_NEAR(image.control_points()[1][0], 1.0, 1e-15);
  EXPECT_NEAR(image.control_points()[1][1], 3.0, 1e-15);
  const auto wrong = transformed(line, AffineMap::identity(3));
  ASSERT_FALSE(wrong.has_value());
  EXPECT_NE(wrong.error().message.find("R^3"), std::string::npos);
  EXPECT_FALSE(AffineMap::make(2, {1, 0, 0}, {0, 0}).has_value());
  EXPECT_FALSE(AffineMap::make(2, {1, 0, 0, NAN}, {0, 0}).has_value());
}

TEST(PiecewiseBezier, PiecesCoverUnitIntervals) {
  const auto a = BezierCurve::make(PointArray::make({{0, 0}, {1, 1}}).value()).value();
  const auto b = BezierCurve::make(PointArray::make({{1, 1}, {2, 1}, {3, 0}}).value()).value();
  const auto curve = PiecewiseBezierCurve::make({a, b}).value();
  EXPECT_EQ(point_at(curve, 0.5), (Point{0.5, 0.5}));
  EXPECT_EQ(point_at(curve, 1.0), (Point{1, 1}));
  EXPECT_EQ(point_at(curve, 2.0), (Point{3, 0}));
  const std::vector<double> us{0.0, 1.5, 2.0};
  std::vector<double> out(6);
  points_at(curve, us, out);
  EXPECT_EQ(out[2], 2.0);
  EXPECT_EQ(out[3], 0.75);
  const auto c3 = BezierCurve::make(PointArray::make({{1, 1, 1}, {2, 1, 1}}).value()).value();
  const auto mixed = PiecewiseBezierCurve::make({a, c3});
  ASSERT_FALSE(mixed.has_value());
  EXPECT_EQ(mixed.error().message, "piece 1 has dimension 3, piece 0 has 2");
  EXPECT_FALSE(PiecewiseBezierCurve::make({}).has_value());
}

// Extrapolation accepts any finite u: far beyond int's range the end pieces
// are still chosen (the piece index is clamped before the conversion to int,
// which would be undefined behaviour, caught by UBSan in the ASan build).
TEST(PiecewiseBezier, LocateFarOutsideTheDomainPicksTheEndPieces) {
  const auto a = BezierCurve::make(PointArray::make({{0, 0}, {1, 1}}).value()).value();
  const auto b = BezierCurve::make(PointArray::make({{1, 1}, {2, 1}, {3, 0}}).value()).value();
  const auto curve = PiecewiseBezierCurve::make({a, b}).value();
  EXPECT_EQ(locate(curve, 1e300), (std::pair<int, double>{1, 1e300 - 1.0}));
  EXPECT_EQ(locate(curve, -1e300), (std::pair<int, double>{0, -1e300}));
  EXPECT_EQ(locate(curve, 3e9).first, 1);
  EXPECT_EQ(locate(curve, -3e9).first, 0);
}

}  // namespace
}  // namespace casteljau
