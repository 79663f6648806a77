// Knot insertion (Boehm, The NURBS Book A5.1) and refinement (A5.4): the
// same curve on more knots, checked against exact rational Boehm insertion
// and the book's Example 5.1.
#include "casteljau/bspline/knot_insertion.hpp"

#include <gmpxx.h>
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <vector>

#include "casteljau/bspline/evaluate.hpp"
#include "casteljau/bspline/knot_vector.hpp"
#include "support/bspline_generators.hpp"
#include "support/exact.hpp"
#include "support/exact_bspline.hpp"

namespace casteljau {
namespace {

using test::book_example_5_1;

TEST(InsertKnot, BookExample5_1) {
  // Inserting u = 5/2 into span [2,3) (k = 5): the book gives
  // alpha_3 = 5/6, alpha_4 = 1/2, alpha_5 = 1/6 and Q_i = a_i P_i + (1 - a_i) P_{i-1}
  // for i = 3, 4, 5; the other points are kept (shifted by one after Q_5).
  const auto curve = book_example_5_1();
  const auto inserted = insert_knot(curve, 2.5).value();
  const std::vector<double> expected_knots = {0, 0, 0, 0, 1, 2, 2.5, 3, 4, 5, 5, 5, 5};
  EXPECT_EQ(std::vector<double>(inserted.knots().begin(), inserted.knots().end()), expected_knots);
  ASSERT_EQ(inserted.control_points().size(), 9u);
  const auto& P = curve.control_points();
  const auto& Q = inserted.control_points();
  const mpq_class alpha[] = {mpq_class(5, 6), mpq_class(1, 2), mpq_class(1, 6)};
  for (int i = 0; i <= 8; ++i)
    for (int c = 0; c < 2; ++c) {
      mpq_class exact;
      if (i <= 2) exact = P[i][c];
      else if (i >= 6) exact = P[i - 1][c];
      else exact = alpha[i - 3] * mpq_class(P[i][c]) + (1 - alpha[i - 3]) * mpq_class(P[i - 1][c]);
      EXPECT_LE(test::error_of(Q[i][c], exact), 1e-15 * 10) << "Q" << i << " coordinate " << c;
    }
}

RC_GTEST_PROP(InsertKnot, EqualsExactBoehmInsertion, ()) {
  const auto curve = *test::bspline_curve({.max_degree = 5, .max_extra_points = 6});
  const double u = *test::parameter_in(curve);
  RC_PRE(multiplicity_of(curve.knots(), u) < curve.degree() + 1);
  const auto inserted = insert_knot(curve, u).value();
  const auto exact = test::ExactBSpline::of(curve).inserted(mpq_class(u));
  RC_ASSERT(inserted.knots().size() == exact.knots.size());
  for (std::size_t i = 0; i < exact.knots.size(); ++i) RC_ASSERT(mpq_class(inserted.knots()[i]) == exact.knots[i]);
  // Each new point is one convex combination: a few ulps of the scale (x weight ratio).
  const double tol = test::shape_tolerance(curve, 1e-14);
  for (std::size_t i = 0; i < exact.rows.size(); ++i) {
    const auto& row = exact.rows[i];
    const int d = curve.dimension();
    for (int c = 0; c < d; ++c)
      RC_ASSERT(test::error_of(inserted.control_points()[i][c], mpq_class(row[c] / row[d])) <= tol);
    if (curve.is_rational()) RC_ASSERT(test::error_of(inserted.weights()[i], row[d]) <= 1e-14 * 5);
  }
}

RC_GTEST_PROP(InsertKnot, KeepsTheShape, ()) {
  const auto curve = *test::bspline_curve();
  const double u = *test::parameter_in(curve);
  const int room = curve.degree() + 1 - multiplicity_of(curve.knots(), u);
  RC_PRE(room > 0);
  const int times = *rc::gen::inRange(1, room + 1);
  const auto inserted = insert_knot(curve, u, times).value();
  RC_ASSERT(inserted.control_points().size() == curve.control_points().size() + static_cast<std::size_t>(times));
  RC_ASSERT(multiplicity_of(inserted.knots(), u) == multiplicity_of(curve.knots(), u) + times);
  RC_ASSERT(inserted.domain() == curve.domain());
  RC_ASSERT(test::largest_distance(curve, inserted) <= test::shape_tolerance(curve));
}

RC_GTEST_PROP(RefineKnots, KeepsTheShapeAndMatchesRepeatedInsertion, ()) {
  const auto curve = *test::bspline_curve();
  const auto count = *rc::gen::inRange(0, 12);
  std::vector<double> news;
  for (int i = 0; i < count; ++i) {
    const double u = *test::parameter_in(curve);
    const int have = multiplicity_of(curve.knots(), u) + static_cast<int>(std::count(news.begin(), news.end(), u));
    if (have < curve.degree() + 1) news.push_back(u);
  }
  const auto refined = refine_knots(curve, news).value();
  RC_ASSERT(refined.control_points().size() == curve.control_points().size() + news.size());
  RC_ASSERT(test::largest_distance(curve, refined) <= test::shape_tolerance(curve));
  // Inserting one by one gives the same knots and nearly the same points.
  BSplineCurve one_by_one = curve;
  for (double u : news) one_by_one = insert_knot(one_by_one, u).value();
  RC_ASSERT(std::vector<double>(one_by_one.knots().begin(), one_by_one.knots().end()) ==
            std::vector<double>(refined.knots().begin(), refined.knots().end()));
  const double tol = test::shape_tolerance(curve, 1e-12);
  for (std::size_t i = 0; i < refined.control_points().size(); ++i)
    RC_ASSERT(distance(refined.control_points()[i], one_by_one.control_points()[i]) <= tol);
}

TEST(InsertKnot, UpToMultiplicityDegreePlusOneKeepsTheCurveContinuous) {
  // A5.1 stops at multiplicity p; the refinement kernel goes to p+1, which
  // only duplicates the point C(u) (the curve does not jump).
  const auto curve = book_example_5_1();
  const auto full = insert_knot(curve, 2.5, 4).value();
  EXPECT_EQ(multiplicity_of(full.knots(), 2.5), 4);
  const Point at = point_at(curve, 2.5);
  // Knots 0000 1 2 | 2.5 x4 at indices 6..9: control points 5 and 6 both equal C(2.5).
  EXPECT_LE(distance(full.control_points()[5], at), 1e-14 * 10);
  EXPECT_LE(distance(full.control_points()[6], at), 1e-14 * 10);
  EXPECT_LE(test::largest_distance(curve, full), 1e-13);
}

TEST(InsertKnot, ZeroTimesIsTheSameCurve) {
  const auto curve = book_example_5_1();
  EXPECT_EQ(insert_knot(curve, 1.5, 0).value(), curve);
  EXPECT_EQ(refine_knots(curve, {}).value(), curve);
}

TEST(InsertKnot, RefusesBadRequestsWithClearMessages) {
  const auto curve = book_example_5_1();
  auto outside = insert_knot(curve, 7.5);
  ASSERT_FALSE(outside.has_value());
  EXPECT_EQ(outside.error().message, "knot to insert (7.5) is outside the domain [0, 5]");
  auto nan = insert_knot(curve, std::nan(""));
  ASSERT_FALSE(nan.has_value());
  EXPECT_EQ(nan.error().message, "knot to insert is NaN");
  auto negative = insert_knot(curve, 1.5, -1);
  ASSERT_FALSE(negative.has_value());
  EXPECT_NE(negative.error().message.find("-1 times"), std::string::npos);
  auto too_many = insert_knot(curve, 2, 4);  // 2 has multiplicity 1, 1 + 4 > p + 1 = 4
  ASSERT_FALSE(too_many.has_value());
  EXPECT_EQ(too_many.error().message,
            "inserting 4 x 2 would give that knot multiplicity 5 (it has 1), above degree + 1 = 4");
  auto at_clamped_end = insert_knot(curve, 0.0);
  ASSERT_FALSE(at_clamped_end.has_value());
  EXPECT_NE(at_clamped_end.error().message.find("multiplicity 5"), std::string::npos);
  const double bad[] = {1.5, 2.5, -1.0};
  auto refine = refine_knots(curve, bad);
  ASSERT_FALSE(refine.has_value());
  EXPECT_EQ(refine.error().message, "new knot 2 (-1) is outside the domain [0, 5]");
}

TEST(InsertKnot, ClampsAnUnclampedEnd) {
  // Uniform knots: inserting the domain start p times makes the curve start
  // at a control point, which is then C(t_p).
  const auto curve = BSplineCurve::make(3, {0, 1, 2, 3, 4, 5, 6, 7},
                                        PointArray::make({{0, 0}, {1, 2}, {3, 3}, {4, 0}}).value())
                         .value();
  const auto clamped = insert_knot(curve, 3.0, 2).value();  // 3 = t_p has multiplicity 1
  const Point start = point_at(curve, 3.0);
  EXPECT_LE(distance(clamped.control_points()[2], start), 1e-14 * 4);
  // Uniform cubic: C(t_p) = (P0 + 4 P1 + P2) / 6 (the classic B-spline-to-Bézier rule).
  EXPECT_NEAR(start[0], (0 + 4 * 1 + 3) / 6.0, 1e-15);
  EXPECT_NEAR(start[1], (0 + 4 * 2 + 3) / 6.0, 1e-15);
}

}  // namespace
}  // namespace casteljau
