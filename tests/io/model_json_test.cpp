// Model JSON version 1 (docs/formats.md, "Model JSON"): every accepted form,
// every refused one with its exact message (line and column for syntax,
// field path for content), and the round trip to_json -> parse, bit for bit.
#include "casteljau/core/tolerance.hpp"
#include "casteljau/io/model_file.hpp"
#include "casteljau/io/model_json.hpp"
#include "support/make.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <string>
#include <vector>

#include "io_test_support.hpp"

namespace casteljau {
namespace {

using test::bezier_of;
using test::json_error;

std::vector<Model> parse(const std::string& text) {
  auto models = parse_models_json(text, "m.json");
  EXPECT_TRUE(models.has_value()) << models.error().message;
  return models ? *models : std::vector<Model>{};
}

TEST(ModelJson, ReadsABezierCurve) {
  const auto models = parse(R"({"type": "bezier", "control_points": [[0,0],[1,2],[2,2],[4,1],[4,0]]})");
  ASSERT_EQ(models.size(), 1u);
  EXPECT_EQ(std::get<BezierCurve>(models[0]), bezier_of(2, {0, 0, 1, 2, 2, 2, 4, 1, 4, 0}));
}

TEST(ModelJson, ReadsARationalBezierCurve) {
  const auto models =
      parse(R"({"type": "bezier", "control_points": [[1,0],[1,1],[0,1]], "weights": [1, 0.7071067811865476, 1]})");
  ASSERT_EQ(models.size(), 1u);
  EXPECT_EQ(std::get<BezierCurve>(models[0]), bezier_of(2, {1, 0, 1, 1, 0, 1}, {1, 0.7071067811865476, 1}));
}

TEST(ModelJson, ReadsAnyDimensionAndFieldOrder) {
  const auto models = parse(" \n{\"control_points\": [[1.5],[-2e3],[7]], \"type\": \"bezier\"}\n ");
  EXPECT_EQ(std::get<BezierCurve>(models.at(0)), bezier_of(1, {1.5, -2000, 7}));
  const auto three = parse(R"({"type": "bezier", "control_points": [[0,0,0],[1,2,3]]})");
  EXPECT_EQ(dimension_of(three.at(0)), 3);
}

TEST(ModelJson, ReadsAPiecewiseCurveWithPolynomialAndRationalPieces) {
  const auto models = parse(R"({"type": "piecewise_bezier", "pieces": [
      [[0,0],[1,1],[2,1],[3,0]],
      {"type": "bezier", "control_points": [[3,0],[4,-1],[5,0]], "weights": [1,2,1]}]})");
  ASSERT_EQ(models.size(), 1u);
  const auto& piecewise = std::get<PiecewiseBezierCurve>(models[0]);
  ASSERT_EQ(piecewise.size(), 2);
  EXPECT_EQ(piecewise.pieces()[0], bezier_of(2, {0, 0, 1, 1, 2, 1, 3, 0}));
  EXPECT_EQ(piecewise.pieces()[1], bezier_of(2, {3, 0, 4, -1, 5, 0}, {1, 2, 1}));
  EXPECT_EQ(curve_view(models[0]).domain(), (Interval{0.0, 2.0}));
}

TEST(ModelJson, ReadsSeveralModelsInOrder) {
  const auto models = parse(R"({"models": [
      {"type": "bezier", "control_points": [[0,0],[1,0]]},
      {"type": "piecewise_bezier", "pieces": [[[0],[1]]]},
      {"type": "bezier", "control_points": [[5,5,5]]}]})");
  ASSERT_EQ(models.size(), 3u);
  EXPECT_STREQ(type_name(models[0]), "bezier");
  EXPECT_STREQ(type_name(models[1]), "piecewise_bezier");
  EXPECT_EQ(std::get<BezierCurve>(models[2]), bezier_of(3, {5, 5, 5}));
}

TEST(ModelJson, ReadsLargeIntegersAndTinyNumbersAsJsonReadersDo) {
  // 2^64 - 1 is an unsigned integer token, 1e400 digits overflow the integer
  // types and go through strtod; 1e-400 underflows to 0 (as in Python's json).
  const auto models =
      parse(R"({"type": "bezier", "control_points": [[18446744073709551615, 1e-400, -9223372036854775808]]})");
  const auto& points = std::get<BezierCurve>(models.at(0)).control_points();
  EXPECT_EQ(points[0][0], 18446744073709551615.0);
  EXPECT_EQ(points[0][1], 0.0);
  EXPECT_EQ(points[0][2], -9223372036854775808.0);
}

TEST(ModelJson, SyntaxErrorsGiveLineAndColumn) {
  EXPECT_EQ(json_error("{\"type\": \"bezier\",\n  \"control_points\": [[0,0],[1,2],]}"),
            "m.json, line 2, column 34: syntax error while parsing value - unexpected ']'; expected '[', '{', or a "
            "literal");
  EXPECT_EQ(json_error(""),
            "m.json, line 1, column 1: syntax error while parsing value - unexpected end of input; expected '[', '{', "
            "or a literal");
  EXPECT_EQ(json_error("{\"type\": \"bezier\"\n"),
            "m.json, line 2, column 1: syntax error while parsing object - unexpected end of input; expected '}'");
  EXPECT_EQ(json_error("{\"type\": \"bezier\", \"control_points\": [[0]]} x"),
            "m.json, line 1, column 45: syntax error while parsing value - invalid literal; last read: '0]]} x'; "
            "expected end of input");
  // The column counts characters, not bytes: "é" is two bytes of UTF-8. The
  // parser stops at the 'a' of "nan" (column 8), where no JSON literal fits.
  EXPECT_EQ(json_error("{\"é\": nan}"),
            "m.json, line 1, column 8: syntax error while parsing value - invalid literal; "
            "last read: '\"é\": na'");
  // A raw line break inside a string: the message stays on one line.
  const std::string message = json_error("{\"type\": \"bez\nier\"}");
  EXPECT_EQ(message.find('\n'), std::string::npos);
  EXPECT_EQ(message.substr(0, 26), "m.json, line 1, column 14:");
}

TEST(ModelJson, NumbersThatOverflowGiveLineColumnAndPath) {
  EXPECT_EQ(json_error("{\"type\": \"bezier\",\n \"control_points\": [[0,0],[1,1e999]]}"),
            "m.json, line 2, column 30, control_points[1][1]: the number '1e999' overflows to infinity, numbers must "
            "be finite");
  EXPECT_EQ(json_error("{\"models\": [{}, {\"type\": \"bezier\", \"control_points\": [[-1e400]]}]}"),
            "m.json, line 1, column 56, models[1].control_points[0][0]: the number '-1e400' overflows to infinity, "
            "numbers must be finite");
}

TEST(ModelJson, BadFieldsNameTheirPath) {
  EXPECT_EQ(json_error(R"({"models": [{"type": "bezier", "control_points": [[0,0]]},
                                   {"type": "bezier", "control_points": [[0,1],[1,"a"]]}]})"),
            "m.json, models[1].control_points[1][1]: expected a number, found the string 'a'");
  EXPECT_EQ(json_error(R"({"type": "bezier", "control_points": [[0,true]]})"),
            "m.json, control_points[0][1]: expected a number, found true");
  EXPECT_EQ(json_error(R"({"type": "bezier", "control_points": [[0,null]]})"),
            "m.json, control_points[0][1]: expected a number, found null");
  EXPECT_EQ(json_error(R"({"type": "bezier", "control_points": [[0,[1]]]})"),
            "m.json, control_points[0][1]: expected a number, found an array");
  EXPECT_EQ(json_error(R"({"type": "bezier", "control_points": [[0,0], 3]})"),
            "m.json, control_points[1]: expected a point (an array of numbers), found the number 3");
  EXPECT_EQ(json_error(R"({"type": "bezier", "control_points": {"x": 1}})"),
            "m.json, control_points: expected an array of points, found an object");
  EXPECT_EQ(json_error(R"({"type": "piecewise_bezier", "pieces": 4})"),
            "m.json, pieces: expected an array of pieces, found the number 4");
}

TEST(ModelJson, UnknownFieldsAreErrors) {
  EXPECT_EQ(json_error(R"({"type": "bezier", "control_points": [[0,0]], "colour": "red"})"),
            "m.json, the top level: unknown field 'colour' (a bezier model has the fields type, control_points, "
            "weights)");
  EXPECT_EQ(json_error(R"({"models": [{"type": "piecewise_bezier", "pieces": [[[0]]], "closed": true}]})"),
            "m.json, models[0]: unknown field 'closed' (a piecewise_bezier model has the fields type, pieces)");
  EXPECT_EQ(json_error(R"({"models": [{"type": "bezier", "control_points": [[0]]}], "version": 1})"),
            "m.json, the top level: unknown field 'version' (a file of several models has only the field 'models')");
  EXPECT_EQ(
      json_error(R"({"type": "piecewise_bezier", "pieces": [{"type": "bezier", "control_points": [[0]], "w": 1}]})"),
      "m.json, pieces[0]: unknown field 'w' (a bezier model has the fields type, control_points, weights)");
}

TEST(ModelJson, EveryTypeOfTheInterfaceIsKnownAndUnknownTypesAreNamed) {
  // The surface kinds are parsed (tests/io/model_json_surface_test.cpp); an
  // incomplete one is refused for its missing field, not for its type.
  EXPECT_EQ(json_error(R"({"models": [{"type": "bezier_surface"}]})"), "m.json, models[0]: missing field 'control_points'");
  EXPECT_EQ(json_error(R"({"models": [{"type": "bspline_surface"}]})"), "m.json, models[0]: missing field 'degree'");
  EXPECT_EQ(json_error(R"({"models": [{"type": "coons"}]})"),
            "m.json, models[0]: missing field 'boundaries' (u0, u1, v0, v1)");
  EXPECT_EQ(json_error(R"({"models": [{"type": "nurbs"}]})"),
            "m.json, models[0].type: unknown model type 'nurbs' (model JSON version 1 has bezier, piecewise_bezier, "
            "bspline, bezier_surface, bspline_surface, coons)");
  EXPECT_EQ(json_error(R"({"control_points": [[0,0]]})"),
            "m.json, the top level: missing field 'type' (bezier, piecewise_bezier, bspline, bezier_surface, "
            "bspline_surface, coons)");
  EXPECT_EQ(json_error(R"({"type": 1})"), "m.json, type: expected a string, found the number 1");
}

TEST(ModelJson, EmptyPolygonsAndPointsAreErrors) {
  EXPECT_EQ(json_error(R"({"type": "bezier", "control_points": []})"),
            "m.json, control_points: " + test::refusal(BezierCurve::make(PointArray{})));
  EXPECT_EQ(json_error(R"({"type": "bezier", "control_points": [[]]})"),
            "m.json, control_points[0]: the point has no coordinates");
  EXPECT_EQ(json_error(R"({"type": "bezier"})"), "m.json, the top level: missing field 'control_points'");
  EXPECT_EQ(json_error(R"({"type": "piecewise_bezier", "pieces": []})"),
            "m.json, pieces: " + test::refusal(PiecewiseBezierCurve::make({})));
  EXPECT_EQ(json_error(R"({"type": "piecewise_bezier", "pieces": [[[0]], []]})"),
            "m.json, pieces[1]: " + test::refusal(BezierCurve::make(PointArray{})));
  EXPECT_EQ(json_error(R"({"type": "piecewise_bezier"})"), "m.json, the top level: missing field 'pieces'");
}

TEST(ModelJson, MixedDimensionsAreErrors) {
  EXPECT_EQ(json_error(R"({"type": "bezier", "control_points": [[0,0],[1,2],[1,2,3]]})"),
            "m.json, control_points[2]: 3 coordinates, but control_points[0] has 2 (all points must have the same "
            "dimension)");
  EXPECT_EQ(json_error(R"({"type": "piecewise_bezier", "pieces": [[[0,0],[1,1]], [[1,1,0],[2,2,0]]]})"),
            "m.json, pieces: " +
                test::refusal(PiecewiseBezierCurve::make({bezier_of(2, {0, 0, 1, 1}), bezier_of(3, {1, 1, 0, 2, 2, 0})})));
}

TEST(ModelJson, BadWeightsAreErrors) {
  // The values are make()'s to judge: its words, at the field's path.
  const auto line = PointArray::make(2, {0, 0, 1, 2}).value();
  EXPECT_EQ(json_error(R"({"type": "bezier", "control_points": [[0,0],[1,2]], "weights": [1, 0]})"),
            "m.json, weights: " + test::refusal(BezierCurve::make(line, {1, 0})));
  EXPECT_EQ(json_error(R"({"models": [{"type": "bezier", "control_points": [[0,0],[1,2]], "weights": [-0.5, 1]}]})"),
            "m.json, models[0].weights: " + test::refusal(BezierCurve::make(line, {-0.5, 1})));
  EXPECT_EQ(json_error(R"({"type": "bezier", "control_points": [[0,0],[1,2]], "weights": [1]})"),
            "m.json, weights: " + test::refusal(BezierCurve::make(line, {1})));
  EXPECT_EQ(json_error(R"({"type": "bezier", "control_points": [[0,0]], "weights": ["1"]})"),
            "m.json, weights[0]: expected a number, found the string '1'");
  EXPECT_EQ(json_error(R"({"type": "bezier", "control_points": [[0,0]], "weights": 1})"),
            "m.json, weights: expected an array of numbers, found the number 1");
}

TEST(ModelJson, TheValuesAreMakesToJudgeAtTheFieldTheyAreAbout) {
  // The reader passes make()'s message on unchanged, after the file and the
  // path of the field it names; a message about the model as a whole (no
  // field named) stays at the model's path.
  const auto messages = [](const std::string& text) {
    const auto models = parse_models_json(text, "m.json");
    return models ? std::string("accepted") : models.error().message;
  };
  const auto two = PointArray::make(1, {0, 1}).value();
  EXPECT_EQ(messages(R"({"models": [{"type": "bezier", "control_points": [[0]]},
                                    {"type": "bezier", "control_points": [[0],[1]], "weights": [2, -1]}]})"),
            "m.json, models[1].weights: " + test::refusal(BezierCurve::make(two, {2, -1})));
  EXPECT_EQ(messages(R"({"models": [{"type": "bezier", "control_points": [[0]]},
                                    {"type": "bspline", "degree": 20000, "knots": [0,1], "control_points": [[0]]}]})"),
            "m.json, models[1].degree: " +
                test::refusal(BSplineCurve::make(20000, {0, 1}, PointArray::make(1, {0}).value())));
  // A rational piece's own fields keep the piece's path.
  EXPECT_EQ(messages(R"({"type": "piecewise_bezier", "pieces": [[[0],[1]],
                        {"type": "bezier", "control_points": [[1],[2]], "weights": [1]}]})"),
            "m.json, pieces[1].weights: " + test::refusal(BezierCurve::make(two, {1})));
}

/// A valid model text of some kind, for the mutations below.
rc::Gen<std::string> model_text() {
  return rc::gen::element<std::string>(
      R"({"type": "bezier", "control_points": [[0,0],[1,2],[2,2]], "weights": [1,2,1]})",
      R"({"type": "piecewise_bezier", "pieces": [[[0,0],[1,1]], {"type": "bezier", "control_points": [[1,1],[2,0]]}]})",
      R"({"type": "bspline", "degree": 2, "knots": [0,0,0,0.5,1,1,1], "control_points": [[0],[1],[2],[3]]})",
      R"({"type": "bspline", "degree": 2, "knots": [0,0,0.5,1,1], "control_points": [[0],[1],[2],[3]]})",
      R"({"type": "bezier_surface", "control_points": [[[0,0,0],[0,1,0]],[[1,0,0],[1,1,1]]], "weights": [[1,1],[1,2]]})",
      R"({"models": [{"type": "bspline_surface", "degree": [1,1], "knots": [[0,0,1,1],[0,0,1,1]],
                      "control_points": [[[0,0,0],[0,1,0]],[[1,0,0],[1,1,1]]]}]})",
      R"({"type": "coons", "blending": "cubic", "boundaries": {
            "u0": {"type": "bezier", "control_points": [[0,0],[0,1]]},
            "u1": {"type": "bezier", "control_points": [[1,0],[1,1]]},
            "v0": {"type": "bezier", "control_points": [[0,0],[1,0]]},
            "v1": {"type": "bezier", "control_points": [[0,1],[1,1]]}}})");
}

RC_GTEST_PROP(ModelJson, EveryRefusalNamesTheFileOnOneLine, ()) {
  // Valid models with a few tokens replaced by something else: whatever
  // breaks (syntax, shape, or a value that make() refuses), the message
  // starts with the file and is one line.
  std::string text = *model_text();
  const int edits = *rc::gen::inRange(1, 4);
  for (int k = 0; k < edits; ++k) {
    const std::size_t at = *rc::gen::inRange<std::size_t>(0, text.size());
    const std::size_t length = *rc::gen::inRange<std::size_t>(0, 4);
    const std::string replacement = *rc::gen::element<std::string>(
        "", "0", "-1", "0.5", "1e308", "5e-324", "[]", "[0]", "[[0]]", "{}", "\"x\"", ",", "null", "2.5", "\"degree\"");
    text.replace(at, std::min(length, text.size() - at), replacement);
  }
  const auto models = parse_models_json(text, "m.json");
  if (!models) {
    const std::string& message = models.error().message;
    RC_ASSERT(message.rfind("m.json, ", 0) == 0u);
    RC_ASSERT(message.find('\n') == std::string::npos);
  }
}

TEST(ModelJson, TheDocumentShapeIsChecked) {
  EXPECT_EQ(
      json_error("[1]"),
      "m.json, the top level: expected an object (one model, or {\"models\": [...]} for several), found an array");
  EXPECT_EQ(json_error(R"({"models": []})"), "m.json, models: the array is empty, expected at least one model");
  EXPECT_EQ(json_error(R"({"models": {}})"), "m.json, models: expected an array of models, found an object");
  EXPECT_EQ(json_error(R"({"models": [3]})"), "m.json, models[0]: expected a model object, found the number 3");
  EXPECT_EQ(json_error(R"({"type": "bezier", "type": "bezier", "control_points": [[0]]})"),
            "m.json, type: the key 'type' appears twice in the same object");
  EXPECT_EQ(json_error(R"({"type": "piecewise_bezier", "pieces": [{"type": "piecewise_bezier"}]})"),
            "m.json, pieces[0].type: expected \"bezier\" (a piece object is a bezier model), found the string "
            "'piecewise_bezier'");
  EXPECT_EQ(json_error(R"({"type": "piecewise_bezier", "pieces": [5]})"),
            "m.json, pieces[0]: expected a piece (an array of control points, or a bezier model object), found the "
            "number 5");
}

TEST(ModelJson, EscapedControlCharactersStayEscapedInMessages) {
  EXPECT_EQ(json_error(R"({"type": "bezier", "control_points": [[0]], "a\nb": 1})"),
            "m.json, the top level: unknown field 'a\\x0ab' (a bezier model has the fields type, control_points, "
            "weights)");
}

TEST(ModelJson, DeepNestingIsRefusedWithoutExhaustingTheStack) {
  const std::size_t depth = 200000;
  EXPECT_EQ(
      json_error(std::string(depth, '[') + std::string(depth, ']')),
      "m.json, the top level: expected an object (one model, or {\"models\": [...]} for several), found an array");
}

TEST(ModelJson, ArraysLongerThanTheControlPointLimitAreRefusedWhileParsing) {
  std::string text = R"({"type": "bezier", "control_points": [)";
  text.reserve(text.size() + 2 * (tolerances::kMaxControlPoints + 1) + 4);
  for (std::size_t i = 0; i <= tolerances::kMaxControlPoints; ++i) text += "0,";
  text.back() = ']';
  text += '}';
  EXPECT_EQ(json_error(text),
            "m.json, control_points[10000000]: an array of more than 10000000 elements, the limit for one model");
}

TEST(ModelJson, WritesOneLineWithShortestNumbers) {
  EXPECT_EQ(to_json(Model{bezier_of(2, {0, 0, 1, 2.5, 0.1, -0.0})}),
            R"({"type":"bezier","control_points":[[0,0],[1,2.5],[0.1,-0.0]]})");
  EXPECT_EQ(to_json(Model{bezier_of(2, {1, 0, 1, 1, 0, 1}, {1, 0.7071067811865476, 1})}),
            R"({"type":"bezier","control_points":[[1,0],[1,1],[0,1]],"weights":[1,0.7071067811865476,1]})");
  const auto piecewise = PiecewiseBezierCurve::make({bezier_of(1, {0, 1}), bezier_of(1, {1, 2, 3}, {1, 1e-50, 2})}).value();
  EXPECT_EQ(
      to_json(Model{piecewise}),
      R"({"type":"piecewise_bezier","pieces":[[[0],[1]],{"type":"bezier","control_points":[[1],[2],[3]],"weights":[1,1e-50,2]}]})");
  EXPECT_EQ(models_to_json({Model{bezier_of(1, {0})}}), "{\"type\":\"bezier\",\"control_points\":[[0]]}\n");
  EXPECT_EQ(models_to_json({Model{bezier_of(1, {0})}, Model{bezier_of(1, {1})}}),
            "{\"models\":[\n{\"type\":\"bezier\",\"control_points\":[[0]]},\n"
            "{\"type\":\"bezier\",\"control_points\":[[1]]}\n]}\n");
}

/// Any model, coordinates and weights of every mantissa within their ranges.
rc::Gen<BezierCurve> any_curve(int d) {
  return rc::gen::exec([d] {
    const int n = *rc::gen::inRange(0, 6);
    auto c = *rc::gen::container<std::vector<double>>((n + 1) * d, test::any_model_coordinate());
    std::vector<double> weights;
    if (*rc::gen::arbitrary<bool>()) {
      weights = *rc::gen::container<std::vector<double>>(n + 1, test::any_model_weight());
    }
    return bezier_of(d, std::move(c), std::move(weights));
  });
}

bool identical(const BezierCurve& a, const BezierCurve& b) {
  if (a.dimension() != b.dimension() || a.control_points().size() != b.control_points().size() ||
      a.weights().size() != b.weights().size())
    return false;
  for (std::size_t k = 0; k < a.control_points().coordinates().size(); ++k)
    if (test::bits_of(a.control_points().coordinates()[k]) != test::bits_of(b.control_points().coordinates()[k]))
      return false;
  for (std::size_t k = 0; k < a.weights().size(); ++k)
    if (test::bits_of(a.weights()[k]) != test::bits_of(b.weights()[k])) return false;
  return true;
}

RC_GTEST_PROP(ModelJson, RoundTripIsBitExact, ()) {
  const int d = *rc::gen::inRange(1, 4);
  std::vector<Model> models;
  const int count = *rc::gen::inRange(1, 4);
  for (int i = 0; i < count; ++i) {
    if (*rc::gen::arbitrary<bool>()) {
      models.emplace_back(*any_curve(d));
    } else {
      auto pieces = *rc::gen::container<std::vector<BezierCurve>>(*rc::gen::inRange(1, 4), any_curve(d));
      models.emplace_back(PiecewiseBezierCurve::make(std::move(pieces)).value());
    }
  }
  const auto back = parse_models_json(models_to_json(models), "round trip");
  RC_ASSERT(back.has_value());
  RC_ASSERT(back->size() == models.size());
  for (std::size_t i = 0; i < models.size(); ++i) {
    RC_ASSERT((*back)[i].index() == models[i].index());
    if (const auto* c = std::get_if<BezierCurve>(&models[i])) {
      RC_ASSERT(identical(std::get<BezierCurve>((*back)[i]), *c));
    } else {
      const auto& original = std::get<PiecewiseBezierCurve>(models[i]).pieces();
      const auto& read = std::get<PiecewiseBezierCurve>((*back)[i]).pieces();
      RC_ASSERT(read.size() == original.size());
      for (std::size_t k = 0; k < read.size(); ++k) RC_ASSERT(identical(read[k], original[k]));
    }
    // And the single-object form of each model.
    const auto single = parse_models_json(to_json(models[i]), "one");
    RC_ASSERT(single.has_value());
    RC_ASSERT(to_json(single->front()) == to_json(models[i]));
  }
}

TEST(ModelFiles, FormatIsChosenByExtensionThenContent) {
  test::TemporaryFolder folder;
  const std::string json = R"({"type": "bezier", "control_points": [[0,0],[4,0]]})";
  test::write_text(folder / "a.json", json);
  test::write_text(folder / "a.JSON", json);
  test::write_text(folder / "a.model", "\xEF\xBB\xBF\n  " + json);
  test::write_text(folder / "a.points", "x,y\n0,0\n4,0\n");
  test::write_text(folder / "a.csv", "0,0\n4,0\n");
  const Model expected{bezier_of(2, {0, 0, 4, 0})};
  for (const char* name : {"a.json", "a.JSON", "a.model", "a.points", "a.csv"}) {
    const auto models = read_models(folder / name);
    ASSERT_TRUE(models.has_value()) << name << ": " << models.error().message;
    ASSERT_EQ(models->size(), 1u);
    EXPECT_EQ(models->front(), expected) << name;
  }
  // The extension wins over the content.
  test::write_text(folder / "b.csv", json);
  EXPECT_EQ(read_models(folder / "b.csv").error().message,
            (folder / "b.csv").string() + ": no points after the header row on line 1");
  test::write_text(folder / "b.json", "0,0\n");
  EXPECT_EQ(read_models(folder / "b.json").error().message,
            (folder / "b.json").string() +
                ", line 1, column 2: syntax error while parsing value - unexpected ','; "
                "expected end of input");
  EXPECT_EQ(read_models_json(folder / "a.json").value().size(), 1u);
}

}  // namespace
}  // namespace casteljau
