// Model JSON `bspline` models (docs/formats.md): reading (full and
// Rhino/openNURBS knot counts), every refusal with the field it names, the
// writer's exact text, the bit-exact round trip, and the Model functions on a
// B-spline against the bspline layer's own.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "casteljau/bspline/evaluate.hpp"
#include "casteljau/io/model.hpp"
#include "casteljau/io/model_file.hpp"
#include "casteljau/io/model_json.hpp"
#include "io_test_support.hpp"

namespace casteljau {
namespace {

using test::json_error;

BSplineCurve parse_bspline(const std::string& text) {
  const Model model = test::parse_one_model(text);
  if (!std::holds_alternative<BSplineCurve>(model)) {
    ADD_FAILURE() << "expected a bspline model: " << text;
    return BSplineCurve::from_trusted(0, {0, 1}, PointArray::from_trusted(1, {0}));
  }
  return std::get<BSplineCurve>(model);
}

BSplineCurve make(int p, std::vector<double> knots, int d, std::vector<double> c, std::vector<double> w = {}) {
  return BSplineCurve::make(p, std::move(knots), PointArray::make(d, std::move(c)).value(), std::move(w)).value();
}

TEST(ModelJsonBSpline, ReadsTheInterfaceExample) {
  const auto curve = parse_bspline(
      R"({"type": "bspline", "degree": 3, "knots": [0,0,0,0,1,2,2,2,2],
          "control_points": [[0,0],[1,2],[2,2],[4,1],[4,0]]})");
  EXPECT_EQ(curve, make(3, {0, 0, 0, 0, 1, 2, 2, 2, 2}, 2, {0, 0, 1, 2, 2, 2, 4, 1, 4, 0}));
  EXPECT_FALSE(curve.is_rational());
  const Model model{curve};
  EXPECT_EQ(curve_view(model).domain(), (Interval{0.0, 2.0}));
}

TEST(ModelJsonBSpline, ReadsANurbsCurveInAnyFieldOrderAndDegreeWrittenAsAFloat) {
  const auto curve = parse_bspline(
      R"({"weights": [1, 0.7071067811865476, 1], "control_points": [[1,0,5],[1,1,5],[0,1,5]],
          "knots": [0,0,0,1,1,1], "degree": 2.0, "type": "bspline"})");
  EXPECT_EQ(curve, make(2, {0, 0, 0, 1, 1, 1}, 3, {1, 0, 5, 1, 1, 5, 0, 1, 5}, {1, 0.7071067811865476, 1}));
  EXPECT_TRUE(curve.is_rational());
}

TEST(ModelJsonBSpline, AcceptsTheRhinoKnotCountAndConvertsIt) {
  // openNURBS stores n + p - 1 knots (the outermost two dropped): 8 for six
  // control points of degree 3 instead of 10.
  const auto rhino = parse_bspline(
      R"({"type": "bspline", "degree": 3, "knots": [0,0,0,1,2,3,3,3],
          "control_points": [[0,0],[1,2],[2,2],[3,1],[4,0],[5,1]]})");
  const auto full = parse_bspline(
      R"({"type": "bspline", "degree": 3, "knots": [0,0,0,0,1,2,3,3,3,3],
          "control_points": [[0,0],[1,2],[2,2],[3,1],[4,0],[5,1]]})");
  EXPECT_EQ(rhino, full);
  // The writer always writes the full vector.
  EXPECT_NE(to_json(Model{rhino}).find(R"("knots":[0,0,0,0,1,2,3,3,3,3])"), std::string::npos);
}

TEST(ModelJsonBSpline, EveryBadFieldIsNamed) {
  const std::string points = R"("control_points": [[0,0],[1,2],[2,2],[4,1]])";
  const auto with = [&](const std::string& fields) { return R"({"type": "bspline", )" + fields + "}"; };
  EXPECT_EQ(json_error(with(R"("knots": [0,0,0,0,1,1,1,1], )" + points)), "m.json, the top level: missing field 'degree'");
  EXPECT_EQ(json_error(with(R"("degree": 3, )" + points)), "m.json, the top level: missing field 'knots'");
  EXPECT_EQ(json_error(with(R"("degree": 3, "knots": [0,0,0,0,1,1,1,1])")),
            "m.json, the top level: missing field 'control_points'");
  EXPECT_EQ(json_error(with(R"("degree": "3", "knots": [0,0,0,0,1,1,1,1], )" + points)),
            "m.json, degree: expected a whole number, found the string '3'");
  EXPECT_EQ(json_error(with(R"("degree": 2.5, "knots": [0,0,0,0,1,1,1,1], )" + points)),
            "m.json, degree: expected a whole number, found the number 2.5");
  EXPECT_EQ(json_error(with(R"("degree": 1e10, "knots": [0,0,0,0,1,1,1,1], )" + points)),
            "m.json, degree: expected a whole number, found the number 10000000000, beyond the range of an int");
  // The values are make()'s to judge: its words, at the field's path.
  const auto four = PointArray::make(2, {0, 0, 1, 2, 2, 2, 4, 1}).value();
  const std::vector<double> clamped{0, 0, 0, 0, 1, 1, 1, 1};
  EXPECT_EQ(json_error(with(R"("degree": -1, "knots": [0,0,0,0,1,1,1,1], )" + points)),
            "m.json, degree: " + test::refusal(BSplineCurve::make(-1, clamped, four)));
  EXPECT_EQ(json_error(with(R"("degree": 4, "knots": [0,0,0,0,1,1,1,1], )" + points)),
            "m.json, control_points: " + test::refusal(BSplineCurve::make(4, clamped, four)));
  // A count that fits neither convention: make()'s words and the other count.
  EXPECT_EQ(json_error(with(R"("degree": 3, "knots": [0,0,0,0,1,1,1], )" + points)),
            "m.json, knots: " + test::refusal(BSplineCurve::make(3, {0, 0, 0, 0, 1, 1, 1}, four)) +
                "; model JSON also reads 6 knots (control points + degree - 1, the Rhino/openNURBS convention)");
  EXPECT_EQ(json_error(with(R"("degree": 3, "knots": [0,0,0,0,1,0.5,1,1], )" + points)),
            "m.json, knots: " + test::refusal(BSplineCurve::make(3, {0, 0, 0, 0, 1, 0.5, 1, 1}, four)));
  EXPECT_EQ(json_error(with(R"("degree": 3, "knots": [0,0,0,0,1,1,1,"x"], )" + points)),
            "m.json, knots[7]: expected a number, found the string 'x'");
  EXPECT_EQ(json_error(with(R"("degree": 3, "knots": {"a": 1}, )" + points)),
            "m.json, knots: expected an array of numbers, found an object");
  EXPECT_EQ(json_error(with(R"("degree": 3, "knots": [0,0,0,0,1,1,1,1], "weights": [1,1,0,1], )" + points)),
            "m.json, weights: " + test::refusal(BSplineCurve::make(3, clamped, four, {1, 1, 0, 1})));
  EXPECT_EQ(json_error(with(R"("degree": 3, "knots": [0,0,0,0,1,1,1,1], "weights": [1,1,1], )" + points)),
            "m.json, weights: " + test::refusal(BSplineCurve::make(3, clamped, four, {1, 1, 1})));
  EXPECT_EQ(json_error(with(R"("degree": 3, "knots": [0,0,0,0,1,1,1,1], "closed": true, )" + points)),
            "m.json, the top level: unknown field 'closed' (a bspline model has the fields type, degree, knots, "
            "control_points, weights)");
  EXPECT_EQ(json_error(with(R"("degree": 3, "knots": [0,0,0,0,1,1,1,1], "control_points": [[0,0],[1,2],[2],[4,1]])")),
            "m.json, control_points[2]: 1 coordinate, but control_points[0] has 2 (all points must have the same "
            "dimension)");
}

TEST(ModelJsonBSpline, KnotErrorsFromTheValidatorKeepItsWords) {
  // Each message comes from validate_knots / knots_from_rhino behind the
  // field path; the test pins the path and the index, not the wording.
  const auto message = json_error(
      R"({"models": [{"type": "bezier", "control_points": [[0]]},
                     {"type": "bspline", "degree": 1, "knots": [0,1,1,1,1], "control_points": [[0],[1],[2]]}]})");
  EXPECT_EQ(message.rfind("m.json, models[1].knots: ", 0), 0u) << message;
  EXPECT_NE(message.find("knot"), std::string::npos) << message;
  const auto empty_domain =
      json_error(R"({"type": "bspline", "degree": 1, "knots": [0,0,0,0], "control_points": [[0],[1]]})");
  EXPECT_EQ(empty_domain.rfind("m.json, knots: ", 0), 0u) << empty_domain;
  const auto rhino = json_error(R"({"type": "bspline", "degree": 2, "knots": [0,2,1], "control_points": [[0],[1],[2]]})");
  EXPECT_EQ(rhino.rfind("m.json, knots: ", 0), 0u) << rhino;
  EXPECT_NE(rhino.find("Rhino/openNURBS"), std::string::npos) << rhino;
}

TEST(ModelJsonBSpline, WritesOneLineWithShortestNumbers) {
  const Model curve{make(2, {0, 0, 0, 0.5, 1, 1, 1}, 2, {0, 0, 1, 2, 3, 2, 4, -0.0}, {1, 0.1, 2, 1})};
  EXPECT_EQ(to_json(curve),
            R"({"type":"bspline","degree":2,"knots":[0,0,0,0.5,1,1,1],"control_points":[[0,0],[1,2],[3,2],[4,-0.0]],)"
            R"("weights":[1,0.1,2,1]})");
  const Model polynomial{make(1, {0, 0, 1, 1}, 1, {2, 3})};
  EXPECT_EQ(to_json(polynomial), R"({"type":"bspline","degree":1,"knots":[0,0,1,1],"control_points":[[2],[3]]})");
}

bool identical(const BSplineCurve& a, const BSplineCurve& b) {
  const auto same = [](std::span<const double> x, std::span<const double> y) {
    if (x.size() != y.size()) return false;
    for (std::size_t k = 0; k < x.size(); ++k)
      if (test::bits_of(x[k]) != test::bits_of(y[k])) return false;
    return true;
  };
  return a.degree() == b.degree() && a.dimension() == b.dimension() && same(a.knots(), b.knots()) &&
         same(a.control_points().coordinates(), b.control_points().coordinates()) && same(a.weights(), b.weights());
}

RC_GTEST_PROP(ModelJsonBSpline, RoundTripIsBitExact, ()) {
  const int p = *rc::gen::inRange(0, 5);
  const int count = p + 1 + *rc::gen::inRange(0, 5);
  const int d = *rc::gen::inRange(1, 4);
  auto knots = *rc::gen::container<std::vector<double>>(static_cast<std::size_t>(count + p + 1),
                                                         test::any_model_knot());
  std::sort(knots.begin(), knots.end());
  auto coordinates =
      *rc::gen::container<std::vector<double>>(static_cast<std::size_t>(count * d), test::any_model_coordinate());
  std::vector<double> weights;
  if (*rc::gen::arbitrary<bool>()) {
    weights = *rc::gen::container<std::vector<double>>(static_cast<std::size_t>(count), test::any_model_weight());
  }
  auto curve = BSplineCurve::make(p, std::move(knots), PointArray::make(d, std::move(coordinates)).value(),
                                  std::move(weights));
  RC_PRE(curve.has_value());  // sorted random knots may repeat too often or leave an empty domain
  const Model model{*curve};
  const auto back = parse_models_json(to_json(model), "round trip");
  RC_ASSERT(back.has_value());
  RC_ASSERT(back->size() == 1u);
  RC_ASSERT(identical(std::get<BSplineCurve>(back->front()), *curve));
  // And inside a file of several models.
  const auto several = parse_models_json(models_to_json({model, model}), "two");
  RC_ASSERT(several.has_value());
  RC_ASSERT(identical(std::get<BSplineCurve>((*several)[1]), *curve));
}

TEST(ModelBSpline, TheModelFunctionsAreTheBSplineOnes) {
  const auto curve =
      make(3, {-1, -1, -1, -1, 0, 0.5, 2, 2, 2, 2}, 3, {0, 0, 0, 1, 2, 0, 2, 2, 1, 4, 1, 2, 4, 0, 3, 5, 1, 1},
           {1, 2, 0.5, 1, 3, 1});
  const Model model{curve};
  EXPECT_STREQ(type_name(model), "bspline");
  EXPECT_EQ(dimension_of(model), 3);
  EXPECT_EQ(control_point_count(model), 6u);
  EXPECT_EQ(curve_view(model).domain(), (Interval{-1.0, 2.0}));
  const std::vector<double> us{-1, -0.5, 0, 0.25, 0.5, 1.999, 2, 0.5, -1};
  std::vector<double> out(us.size() * 3);
  points_at(curve_view(model), us, out);
  for (std::size_t i = 0; i < us.size(); ++i) {
    const Point expected = point_at(curve, us[i]);
    for (std::size_t j = 0; j < 3; ++j) EXPECT_EQ(test::bits_of(out[i * 3 + j]), test::bits_of(expected[j])) << us[i];
    for (int k = 0; k <= 4; ++k) EXPECT_EQ(derivative_at(curve_view(model), us[i], k), derivative_at(curve, us[i], k));
  }
}

TEST(ModelBSpline, ReadModelsTakesBSplineFilesByContent) {
  test::TemporaryFolder folder;
  test::write_text(folder / "curve.model",
                   R"( {"type": "bspline", "degree": 1, "knots": [0,0,1,1], "control_points": [[1,1],[2,3]]})");
  const auto models = read_models(folder / "curve.model");
  ASSERT_TRUE(models.has_value()) << models.error().message;
  EXPECT_EQ(std::get<BSplineCurve>(models->front()), make(1, {0, 0, 1, 1}, 2, {1, 1, 2, 3}));
}

}  // namespace
}  // namespace casteljau
