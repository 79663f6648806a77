// The model dispatch (io/model.hpp): domain, dimension, batch points and
// derivatives agree with the per-kind functions, bit for bit; the seed's
// worked example through the CSV reader.
#include "casteljau/io/model.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <vector>

#include "casteljau/bezier/evaluate.hpp"
#include "casteljau/io/model_file.hpp"
#include "casteljau/io/model_json.hpp"
#include "support/examples_dir.hpp"
#include "support/generators.hpp"
#include "support/make.hpp"

namespace casteljau {
namespace {

using test::bezier_of;

TEST(Model, NotebookPolygonAsABezierCurveGivesTheSeedValue) {
  // Seed 004: control points (0,0),(1,2),(2,2),(4,1),(4,0) give B(0.5) = (2.25, 1.5).
  // Every de Casteljau step at t = 1/2 on these integers is exact in binary.
  const auto models = read_models(test::examples_dir() / "notebook_polygon.csv");
  ASSERT_TRUE(models.has_value()) << models.error().message;
  ASSERT_EQ(models->size(), 1u);
  const Model& model = models->front();
  EXPECT_STREQ(type_name(model), "bezier");
  EXPECT_EQ(curve_view(model).domain(), (Interval{0.0, 1.0}));
  const double t = 0.5;
  double out[2];
  points_at(curve_view(model), std::span<const double>(&t, 1), out);
  EXPECT_EQ(out[0], 2.25);
  EXPECT_EQ(out[1], 1.5);
  EXPECT_EQ(derivative_at(curve_view(model), 0.5, 0), (Point{2.25, 1.5}));
  // Seed 004: the tangent at the ends, B'(0) = n (P_1 - P_0), B'(1) = n (P_n - P_{n-1}).
  EXPECT_EQ(derivative_at(curve_view(model), 0.0, 1), (Point{4, 8}));
  EXPECT_EQ(derivative_at(curve_view(model), 1.0, 1), (Point{0, -4}));
}

TEST(Model, DescribesEachKind) {
  const Model bezier{bezier_of(3, {0, 0, 0, 1, 1, 1})};
  const Model piecewise{
      PiecewiseBezierCurve::make({bezier_of(2, {0, 0, 1, 0}), bezier_of(2, {1, 0, 1, 1, 2, 1}), bezier_of(2, {2, 1, 3, 3})})
          .value()};
  EXPECT_EQ(curve_view(bezier).domain(), (Interval{0.0, 1.0}));
  EXPECT_EQ(curve_view(piecewise).domain(), (Interval{0.0, 3.0}));
  EXPECT_EQ(dimension_of(bezier), 3);
  EXPECT_EQ(dimension_of(piecewise), 2);
  EXPECT_EQ(control_point_count(bezier), 2u);
  EXPECT_EQ(control_point_count(piecewise), 7u);
  EXPECT_STREQ(type_name(piecewise), "piecewise_bezier");
  EXPECT_TRUE(curve_view(piecewise).domain().contains(3.0));
  EXPECT_FALSE(curve_view(piecewise).domain().contains(3.0000000000000004));
  EXPECT_FALSE(curve_view(piecewise).domain().contains(-0.1));
}

TEST(Model, PiecewiseDerivativesAtJunctionsComeFromThePieceToTheRight) {
  // Two pieces that meet at (1,0) with different tangents: (1,0) on the left, (0,2) on the right.
  const Model model{PiecewiseBezierCurve::make({bezier_of(2, {0, 0, 1, 0}), bezier_of(2, {1, 0, 1, 2})}).value()};
  EXPECT_EQ(derivative_at(curve_view(model), 1.0, 1), (Point{0, 2}));
  EXPECT_EQ(derivative_at(curve_view(model), 0.5, 1), (Point{1, 0}));
  EXPECT_EQ(derivative_at(curve_view(model), 2.0, 1), (Point{0, 2}));  // the end of the domain: the last piece
  EXPECT_EQ(derivative_at(curve_view(model), 2.0, 0), (Point{1, 2}));
}

RC_GTEST_PROP(Model, BatchAndSinglePointsMatchTheCurveFunctionsBitForBit, ()) {
  const BezierCurve c = *test::any_bezier_curve(8);
  const BezierCurve other = *test::bezier_curve(0, 5, *rc::gen::arbitrary<bool>(), c.dimension());
  const Model bezier{c};
  const Model piecewise{PiecewiseBezierCurve::make({c, other}).value()};
  const auto ts = *rc::gen::container<std::vector<double>>(*rc::gen::inRange(1, 10), test::unit_parameter());
  const std::size_t d = c.dimension();
  std::vector<double> out(ts.size() * d);
  points_at(curve_view(bezier), ts, out);
  for (std::size_t i = 0; i < ts.size(); ++i) {
    const Point expected = point_at(c, ts[i]);
    for (std::size_t j = 0; j < d; ++j) RC_ASSERT(out[i * d + j] == expected[j]);
    RC_ASSERT(derivative_at(curve_view(bezier), ts[i], 1) == derivative_at(c, ts[i], 1));
  }
  // Piecewise: u in [1, 2] is the second piece (also at u = 1, the junction,
  // and at u = 2, the end) at the local parameter u - 1.
  std::vector<double> us;
  for (double t : ts) us.push_back(1.0 + t);
  points_at(curve_view(piecewise), us, out);
  for (std::size_t i = 0; i < us.size(); ++i) {
    const Point expected = point_at(other, us[i] - 1.0);
    for (std::size_t j = 0; j < d; ++j) RC_ASSERT(out[i * d + j] == expected[j]);
  }
}

}  // namespace
}  // namespace casteljau
