// Model JSON surface models (docs/formats.md, interfaces.md): bezier_surface,
// bspline_surface and coons. Reading the interface's shapes, every refusal
// with the JSON path it names, the exact round trip parse(to_json(m)) == m,
// and the Model functions (is_surface, surface_view, type_name...) on surfaces.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "casteljau/bspline/evaluate.hpp"
#include "casteljau/bspline/knot_vector.hpp"
#include "casteljau/io/model.hpp"
#include "casteljau/io/model_json.hpp"
#include "io_test_support.hpp"

namespace casteljau {
namespace {

using test::json_error;
using test::parse_one_model;

ControlNet net(std::size_t rows, std::size_t columns, int d, std::vector<double> coordinates) {
  return ControlNet::make(rows, columns, PointArray::make(d, std::move(coordinates)).value()).value();
}

// A 2 x 3 net in R^3, written out by hand in both notations.
const char* kBezierSurface =
    R"({"type": "bezier_surface", "control_points": [[[0,0,0],[0,1,1],[0,2,0]], [[1,0,1],[1,1,2],[1,2,1]]]})";

TEST(ModelJsonSurface, ReadsABezierSurfaceRowByRowWithIAlongU) {
  const Model model = parse_one_model(kBezierSurface);
  ASSERT_TRUE(std::holds_alternative<BezierSurface>(model));
  const auto& surface = std::get<BezierSurface>(model);
  EXPECT_EQ(surface.control_net(), net(2, 3, 3, {0, 0, 0, 0, 1, 1, 0, 2, 0, 1, 0, 1, 1, 1, 2, 1, 2, 1}));
  EXPECT_EQ(surface.degree_u(), 1);
  EXPECT_EQ(surface.degree_v(), 2);
  EXPECT_FALSE(surface.is_rational());
  EXPECT_TRUE(is_surface(model));
  EXPECT_STREQ(type_name(model), "bezier_surface");
  EXPECT_EQ(dimension_of(model), 3);
  EXPECT_EQ(control_point_count(model), 6u);
  // The corners of a Bézier patch are its corner control points.
  const SurfaceView view = surface_view(model);
  EXPECT_EQ(view.domain_u(), (Interval{0.0, 1.0}));
  EXPECT_EQ(view.domain_v(), (Interval{0.0, 1.0}));
  EXPECT_EQ(view.point_at(1.0, 0.0), (Point{1, 0, 1}));
  EXPECT_EQ(view.point_at(0.0, 1.0), (Point{0, 2, 0}));
}

TEST(ModelJsonSurface, ReadsARationalBezierSurface) {
  const Model model = parse_one_model(
      R"({"type": "bezier_surface", "control_points": [[[0,0],[1,0]], [[0,1],[1,1]]], "weights": [[1, 2], [3, 0.5]]})");
  const auto& surface = std::get<BezierSurface>(model);
  EXPECT_TRUE(surface.is_rational());
  EXPECT_EQ(std::vector<double>(surface.weights().begin(), surface.weights().end()),
            (std::vector<double>{1, 2, 3, 0.5}));
}

TEST(ModelJsonSurface, ReadsABSplineSurfaceWithKnotsPerDirection) {
  const Model model = parse_one_model(
      R"({"type": "bspline_surface", "degree": [2, 1], "knots": [[0,0,0,1,1,1], [0,0,0.5,3,3]],
          "control_points": [[[0,0,0],[0,1,0],[0,2,0]], [[1,0,1],[1,1,1],[1,2,1]], [[2,0,0],[2,1,0],[2,2,0]]],
          "weights": [[1,1,1],[0.5,0.5,0.5],[1,1,1]]})");
  ASSERT_TRUE(std::holds_alternative<BSplineSurface>(model));
  const auto& surface = std::get<BSplineSurface>(model);
  EXPECT_EQ(surface.degree_u(), 2);
  EXPECT_EQ(surface.degree_v(), 1);
  EXPECT_EQ(std::vector<double>(surface.knots_v().begin(), surface.knots_v().end()),
            (std::vector<double>{0, 0, 0.5, 3, 3}));
  EXPECT_TRUE(surface.is_rational());
  EXPECT_STREQ(type_name(model), "bspline_surface");
  const SurfaceView view = surface_view(model);
  EXPECT_EQ(view.domain_u(), (Interval{0.0, 1.0}));
  EXPECT_EQ(view.domain_v(), (Interval{0.0, 3.0}));
}

TEST(ModelJsonSurface, AcceptsTheRhinoKnotCountInEachDirection) {
  // 4 points of degree 3 along u: 8 knots in full, 6 in the openNURBS form.
  const Model rhino = parse_one_model(
      R"({"type": "bspline_surface", "degree": [3, 1], "knots": [[0,0,0,1,1,1], [0,1]],
          "control_points": [[[0],[1]], [[2],[3]], [[4],[5]], [[6],[7]]]})");
  const Model full = parse_one_model(
      R"({"type": "bspline_surface", "degree": [3, 1], "knots": [[0,0,0,0,1,1,1,1], [0,0,1,1]],
          "control_points": [[[0],[1]], [[2],[3]], [[4],[5]], [[6],[7]]]})");
  EXPECT_EQ(rhino, full);
}

// Boundary curves of a unit square patch in z = 0 lifted in the middle:
// u0 = P(0,v) from (0,0,0) to (0,1,0), u1 = P(1,v) from (1,0,0) to (1,1,0),
// v0 = P(u,0) from (0,0,0) to (1,0,0), v1 = P(u,1) from (0,1,0) to (1,1,0),
// each a different curve kind.
const char* kCoons = R"({"type": "coons", "blending": "cubic", "boundaries": {
    "u0": {"type": "bezier", "control_points": [[0,0,0],[0,0.5,1],[0,1,0]]},
    "u1": {"type": "piecewise_bezier", "pieces": [[[1,0,0],[1,0.25,0.5],[1,0.5,0.5]], [[1,0.5,0.5],[1,0.75,0.5],[1,1,0]]]},
    "v0": {"type": "bspline", "degree": 1, "knots": [0,0,2,4,4], "control_points": [[0,0,0],[0.5,0,-1],[1,0,0]]},
    "v1": {"type": "bezier", "control_points": [[0,1,0],[1,1,0]]}}})";

TEST(ModelJsonSurface, ReadsACoonsPatchFromFourCurvesOfAnyKind) {
  const Model model = parse_one_model(kCoons);
  ASSERT_TRUE(std::holds_alternative<CoonsPatch>(model));
  const auto& patch = std::get<CoonsPatch>(model);
  EXPECT_EQ(patch.blending(), CoonsBlending::cubic);
  EXPECT_STREQ(type_name(model), "coons");
  // The two pieces of u1 share their joint in the B-spline form: 5 points.
  EXPECT_EQ(control_point_count(model), 3u + 5u + 3u + 2u);
  // Each boundary is held on [0,1] and keeps its shape: the B-spline v0 on
  // [0,4] reaches its middle control point at 2, the middle of [0,4].
  for (const BSplineCurve* curve : {&patch.u0(), &patch.u1(), &patch.v0(), &patch.v1()})
    EXPECT_EQ(curve->domain(), (Interval{0.0, 1.0}));
  const Point middle = point_at(patch.v0(), 0.5);
  EXPECT_NEAR(middle[0], 0.5, 1e-15);
  EXPECT_NEAR(middle[2], -1.0, 1e-15);
  // The patch reproduces its boundaries: P(0, 1/2) = u0(1/2) = (0, 0.5, 0.5).
  const SurfaceView view = surface_view(model);
  const Point edge = view.point_at(0.0, 0.5);
  EXPECT_NEAR(edge[1], 0.5, 1e-15);
  EXPECT_NEAR(edge[2], 0.5, 1e-15);
}

TEST(ModelJsonSurface, CoonsBlendingDefaultsToLinear) {
  const Model model = parse_one_model(R"({"type": "coons", "boundaries": {
      "u0": {"type": "bezier", "control_points": [[0,0],[0,1]]},
      "u1": {"type": "bezier", "control_points": [[1,0],[1,1]]},
      "v0": {"type": "bezier", "control_points": [[0,0],[1,0]]},
      "v1": {"type": "bezier", "control_points": [[0,1],[1,1]]}}})");
  EXPECT_EQ(std::get<CoonsPatch>(model).blending(), CoonsBlending::linear);
}

TEST(ModelJsonSurface, WritesTheExactText) {
  EXPECT_EQ(to_json(parse_one_model(kBezierSurface)),
            R"({"type":"bezier_surface","control_points":[[[0,0,0],[0,1,1],[0,2,0]],[[1,0,1],[1,1,2],[1,2,1]]]})");
  EXPECT_EQ(to_json(parse_one_model(R"({"type":"bspline_surface","degree":[1,1],"knots":[[0,0,1,1],[0,0,1,1]],
                                  "control_points":[[[0],[1]],[[2],[3]]],"weights":[[1,2],[3,4]]})")),
            R"({"type":"bspline_surface","degree":[1,1],"knots":[[0,0,1,1],[0,0,1,1]],)"
            R"("control_points":[[[0],[1]],[[2],[3]]],"weights":[[1,2],[3,4]]})");
  const std::string coons = to_json(parse_one_model(R"({"type": "coons", "boundaries": {
      "u0": {"type": "bezier", "control_points": [[0,0],[0,1]]},
      "u1": {"type": "bezier", "control_points": [[1,0],[1,1]]},
      "v0": {"type": "bezier", "control_points": [[0,0],[1,0]]},
      "v1": {"type": "bezier", "control_points": [[0,1],[1,1]]}}})"));
  EXPECT_EQ(coons, R"({"type":"coons","blending":"linear","boundaries":{)"
                   R"("u0":{"type":"bspline","degree":1,"knots":[0,0,1,1],"control_points":[[0,0],[0,1]]},)"
                   R"("u1":{"type":"bspline","degree":1,"knots":[0,0,1,1],"control_points":[[1,0],[1,1]]},)"
                   R"("v0":{"type":"bspline","degree":1,"knots":[0,0,1,1],"control_points":[[0,0],[1,0]]},)"
                   R"("v1":{"type":"bspline","degree":1,"knots":[0,0,1,1],"control_points":[[0,1],[1,1]]}}})");
}

TEST(ModelJsonSurface, RoundTripsTheCoonsPatchFromCurvesOfEveryKind) {
  const Model model = parse_one_model(kCoons);
  EXPECT_EQ(parse_one_model(to_json(model)), model);
  // And several models in one file, surfaces and curves mixed.
  const std::vector<Model> models{model, parse_one_model(kBezierSurface),
                                  Model{BezierCurve::make(PointArray::from_trusted(2, {0, 0, 1, 1})).value()}};
  const auto again = parse_models_json(models_to_json(models), "m.json");
  ASSERT_TRUE(again.has_value());
  EXPECT_EQ(*again, models);
}

/// Random coordinates of every mantissa (within the range of coordinates), so the writer must be exact.
std::vector<double> any_coordinates(std::size_t count) {
  return *rc::gen::container<std::vector<double>>(count, test::any_model_coordinate());
}

std::vector<double> any_weights(std::size_t count) {
  return *rc::gen::container<std::vector<double>>(
      count, rc::gen::map(rc::gen::inRange(1, 1 << 20), [](int k) { return k / 4096.0; }));
}

/// A non-decreasing knot vector of `count` knots with the end multiplicities
/// of a clamped or unclamped spline, values of every magnitude.
std::vector<double> any_knots(std::size_t count) {
  auto knots = *rc::gen::container<std::vector<double>>(
      count, rc::gen::map(rc::gen::inRange(-1000000, 1000001), [](int k) { return k / 977.0; }));
  std::sort(knots.begin(), knots.end());
  return knots;
}

RC_GTEST_PROP(ModelJsonSurface, BezierSurfacesRoundTripExactly, ()) {
  const auto rows = static_cast<std::size_t>(*rc::gen::inRange(1, 6));
  const auto columns = static_cast<std::size_t>(*rc::gen::inRange(1, 6));
  const int d = *rc::gen::inRange(1, 4);
  const auto count = rows * columns;
  const bool rational = *rc::gen::arbitrary<bool>();
  const Model model{BezierSurface::make(net(rows, columns, d, any_coordinates(count * static_cast<std::size_t>(d))),
                                        rational ? any_weights(count) : std::vector<double>{})
                        .value()};
  auto again = parse_models_json(to_json(model), "m.json");
  RC_ASSERT(again.has_value());
  RC_ASSERT(again->size() == 1u);
  RC_ASSERT(again->front() == model);
  // Bitwise, -0 included (== would accept 0 for -0).
  const auto& a = std::get<BezierSurface>(model).control_net().points();
  const auto& b = std::get<BezierSurface>(again->front()).control_net().points();
  for (std::size_t i = 0; i < a.size(); ++i)
    for (int c = 0; c < d; ++c) RC_ASSERT(test::bits_of(a[i][c]) == test::bits_of(b[i][c]));
}

RC_GTEST_PROP(ModelJsonSurface, BSplineSurfacesRoundTripExactly, ()) {
  const int p = *rc::gen::inRange(0, 4), q = *rc::gen::inRange(0, 4);
  const auto rows = static_cast<std::size_t>(p + *rc::gen::inRange(1, 4));
  const auto columns = static_cast<std::size_t>(q + *rc::gen::inRange(1, 4));
  const auto count = rows * columns;
  const bool rational = *rc::gen::arbitrary<bool>();
  auto knots_u = any_knots(rows + static_cast<std::size_t>(p) + 1);
  auto knots_v = any_knots(columns + static_cast<std::size_t>(q) + 1);
  // validate_knots wants a domain of positive length and multiplicities
  // at most p+1: spread the knots so both hold.
  for (std::size_t i = 0; i < knots_u.size(); ++i) knots_u[i] += static_cast<double>(i);
  for (std::size_t i = 0; i < knots_v.size(); ++i) knots_v[i] += static_cast<double>(i);
  auto surface = BSplineSurface::make(p, q, knots_u, knots_v, net(rows, columns, 3, any_coordinates(count * 3)),
                                      rational ? any_weights(count) : std::vector<double>{});
  RC_ASSERT(surface.has_value());
  const Model model{std::move(*surface)};
  auto again = parse_models_json(to_json(model), "m.json");
  RC_ASSERT(again.has_value());
  RC_ASSERT(again->front() == model);
}

// --- refusals, each naming its path ---------------------------------------

TEST(ModelJsonSurface, RefusesARaggedNet) {
  EXPECT_EQ(json_error(R"({"type": "bezier_surface", "control_points": [[[0,0],[1,0],[2,0],[3,0]],
      [[0,1],[1,1],[2,1],[3,1]], [[0,2],[1,2],[2,2]]]})"),
            "m.json, control_points[2]: row 2 has 3 points, row 0 has 4 (a control net is rectangular)");
  EXPECT_EQ(json_error(R"({"models": [{"type": "bspline_surface", "degree": [1,1], "knots": [[0,0,1,1],[0,0,1,1]],
      "control_points": [[[0,0],[1,0]], [[0,1]]]}]})"),
            "m.json, models[0].control_points[1]: row 1 has 1 point, row 0 has 2 (a control net is rectangular)");
}

// Fields of the wrong shape: a net that is not rows, weights that are not
// rows of numbers, knots that are not two lists, a blending that is not a
// name (`make coverage` found these refusals without a test; docs/coverage.md).
TEST(ModelJsonSurface, RefusesFieldsOfTheWrongShape) {
  EXPECT_EQ(json_error(R"({"type": "bezier_surface", "control_points": 5})"),
            "m.json, control_points: expected an array of rows of points, found the number 5");
  EXPECT_EQ(json_error(R"({"type": "bezier_surface", "control_points": [[[0,0]], 7]})"),
            "m.json, control_points[1]: expected a row (an array of points), found the number 7");
  EXPECT_EQ(json_error(R"({"type": "bezier_surface", "control_points": [[[0,0],[1,0]]], "weights": 2})"),
            "m.json, weights: expected an array of rows of numbers, found the number 2");
  EXPECT_EQ(json_error(R"({"type": "bezier_surface", "control_points": [[[0,0],[1,0]]], "weights": [[1, "a"]]})"),
            "m.json, weights[0][1]: expected a number, found the string 'a'");
  EXPECT_EQ(json_error(R"({"type": "bspline_surface", "degree": [1,1], "knots": [[0,0,1,1], 3],
      "control_points": [[[0,0],[1,0]], [[0,1],[1,1]]]})"),
            "m.json, knots[1]: expected an array of numbers, found the number 3");
  EXPECT_EQ(json_error(R"({"type": "coons", "blending": 3, "boundaries": {}})"),
            "m.json, blending: expected \"linear\" or \"cubic\", found the number 3");
}

TEST(ModelJsonSurface, RefusesBadNetsAndPoints) {
  EXPECT_EQ(json_error(R"({"type": "bezier_surface", "control_points": []})"),
            "m.json, control_points: " + test::refusal(ControlNet::make(0, 0, PointArray{})));
  EXPECT_EQ(json_error(R"({"type": "bezier_surface", "control_points": [[], []]})"),
            "m.json, control_points: " + test::refusal(ControlNet::make(2, 0, PointArray{})));
  EXPECT_EQ(json_error(R"({"type": "bezier_surface", "control_points": [[0, 1]]})"),
            "m.json, control_points[0][0]: expected a point (an array of numbers), found the number 0");
  EXPECT_EQ(json_error(R"({"type": "bezier_surface", "control_points": [[[0,0,0]], [[0,1]]]})"),
            "m.json, control_points[1][0]: 2 coordinates, but control_points[0][0] has 3 (all points must have the "
            "same dimension)");
  EXPECT_EQ(json_error(R"({"type": "bezier_surface", "control_points": [[[0,"x"]]]})"),
            "m.json, control_points[0][0][1]: expected a number, found the string 'x'");
}

TEST(ModelJsonSurface, RefusesWeightsThatDoNotMatchTheNet) {
  const std::string points = R"("control_points": [[[0,0],[1,0],[2,0]], [[0,1],[1,1],[2,1]]])";
  EXPECT_EQ(json_error(R"({"type": "bezier_surface", )" + points + R"(, "weights": [[1,1,1]]})"),
            "m.json, weights: 1 row of weights for a control net of 2 rows, expected one weight per control point");
  EXPECT_EQ(json_error(R"({"type": "bezier_surface", )" + points + R"(, "weights": [[1,1,1],[1,1]]})"),
            "m.json, weights[1]: row 1 has 2 weights, the control net has 3 points per row");
  EXPECT_EQ(json_error(R"({"type": "bezier_surface", )" + points + R"(, "weights": [1,1,1,1,1,1]})"),
            "m.json, weights: 6 rows of weights for a control net of 2 rows, expected one weight per control point");
  EXPECT_EQ(json_error(R"({"type": "bezier_surface", )" + points + R"(, "weights": [1,1]})"),
            "m.json, weights[0]: expected a row (an array of numbers), found the number 1");
  // The values are make()'s to judge: its words, at the field's path.
  const ControlNet two_by_three = net(2, 3, 2, {0, 0, 1, 0, 2, 0, 0, 1, 1, 1, 2, 1});
  EXPECT_EQ(json_error(R"({"type": "bezier_surface", )" + points + R"(, "weights": [[1,1,1],[1,0,1]]})"),
            "m.json, weights: " + test::refusal(BezierSurface::make(two_by_three, {1, 1, 1, 1, 0, 1})));
  EXPECT_EQ(json_error(R"({"type": "bspline_surface", "degree": [1,1], "knots": [[0,0,1,1],[0,0,0.5,1,1]], )" +
                     points + R"(, "weights": [[1,1,1],[1,1,-2]]})"),
            "m.json, weights: " + test::refusal(BSplineSurface::make(1, 1, {0, 0, 1, 1}, {0, 0, 0.5, 1, 1},
                                                                      two_by_three, {1, 1, 1, 1, 1, -2})));
}

TEST(ModelJsonSurface, RefusesUnknownFields) {
  EXPECT_EQ(json_error(R"({"type": "bezier_surface", "control_points": [[[0]]], "knots": []})"),
            "m.json, the top level: unknown field 'knots' (a bezier_surface model has the fields type, "
            "control_points, weights)");
  EXPECT_EQ(json_error(R"({"type": "bspline_surface", "degree": [0,0], "knots": [[0,1],[0,1]],
      "control_points": [[[0]]], "colour": 1})"),
            "m.json, the top level: unknown field 'colour' (a bspline_surface model has the fields type, degree, "
            "knots, control_points, weights)");
  EXPECT_EQ(json_error(R"({"type": "coons", "boundaries": {}, "degree": 3})"),
            "m.json, the top level: unknown field 'degree' (a coons model has the fields type, blending, "
            "boundaries)");
  EXPECT_EQ(json_error(R"({"type": "coons", "boundaries": {"w0": {}}})"),
            "m.json, boundaries: unknown field 'w0' (the boundaries object of a coons model has the fields u0, u1, v0, v1)");
}

TEST(ModelJsonSurface, RefusesBadDegreesAndKnotsPerDirection) {
  const std::string points = R"("control_points": [[[0],[1],[2]], [[3],[4],[5]]])";
  EXPECT_EQ(json_error(R"({"type": "bspline_surface", "degree": 1, "knots": [[0,0,1,1],[0,0,0.5,1,1]], )" + points +
                     "}"),
            "m.json, degree: expected [p, q], the degrees in u and in v, found the number 1");
  EXPECT_EQ(json_error(R"({"type": "bspline_surface", "degree": [1,1.5], "knots": [[0,0,1,1],[0,0,0.5,1,1]], )" +
                     points + "}"),
            "m.json, degree[1]: expected a whole number, found the number 1.5");
  // The values are make()'s to judge: its words, at the field's path (a
  // direction's error at that element of the pair).
  const ControlNet two_by_three = net(2, 3, 1, {0, 1, 2, 3, 4, 5});
  EXPECT_EQ(json_error(R"({"type": "bspline_surface", "degree": [2,1], "knots": [[0,0,0,1,1,1],[0,0,0.5,1,1]], )" +
                     points + "}"),
            "m.json, control_points: " +
                test::refusal(BSplineSurface::make(2, 1, {0, 0, 0, 1, 1, 1}, {0, 0, 0.5, 1, 1}, two_by_three)));
  EXPECT_EQ(json_error(R"({"type": "bspline_surface", "degree": [1,3], "knots": [[0,0,1,1],[0,0,0,0,1,1,1,1]], )" +
                     points + "}"),
            "m.json, control_points: " +
                test::refusal(BSplineSurface::make(1, 3, {0, 0, 1, 1}, {0, 0, 0, 0, 1, 1, 1, 1}, two_by_three)));
  EXPECT_EQ(json_error(R"({"type": "bspline_surface", "degree": [-1,1], "knots": [[0,0,1,1],[0,0,0.5,1,1]], )" +
                     points + "}"),
            "m.json, degree[0]: " +
                test::refusal(BSplineSurface::make(-1, 1, {0, 0, 1, 1}, {0, 0, 0.5, 1, 1}, two_by_three)));
  EXPECT_EQ(json_error(R"({"type": "bspline_surface", "degree": [1,1], "knots": [[0,0,1,1]], )" + points + "}"),
            "m.json, knots: expected [[u knots], [v knots]], two arrays of numbers, found an array of 1 elements");
  EXPECT_EQ(json_error(R"({"type": "bspline_surface", "degree": [1,1], "knots": [[0,0,1,1],[0,0,1,1]], )" + points +
                     "}"),
            "m.json, knots[1]: " + test::refusal(validate_knots(std::vector<double>{0, 0, 1, 1}, 1, 3)) +
                "; model JSON also reads 3 knots (control points + degree - 1, the Rhino/openNURBS convention)");
  EXPECT_EQ(json_error(R"({"type": "bspline_surface", "degree": [1,1], "knots": [[0,0,1,1],[0,0,0.7,0.5,1]], )" +
                     points + "}"),
            "m.json, knots[1]: " + test::refusal(validate_knots(std::vector<double>{0, 0, 0.7, 0.5, 1}, 1, 3)));
  EXPECT_EQ(json_error(R"({"type": "bspline_surface", "degree": [1,1], "knots": [[0,1,1,1],[0,0,0.5,1,1]], )" +
                     points + "}"),
            "m.json, knots[0]: " + test::refusal(validate_knots(std::vector<double>{0, 1, 1, 1}, 1, 2)));
}

const char* kLine00to01 = R"({"type": "bezier", "control_points": [[0,0],[0,1]]})";
const char* kLine10to11 = R"({"type": "bezier", "control_points": [[1,0],[1,1]]})";
const char* kLine00to10 = R"({"type": "bezier", "control_points": [[0,0],[1,0]]})";
const char* kLine01to11 = R"({"type": "bezier", "control_points": [[0,1],[1,1]]})";

std::string coons_with(const std::string& u0, const std::string& u1, const std::string& v0, const std::string& v1,
                       const std::string& extra = "") {
  return R"({"type": "coons", )" + extra + R"("boundaries": {"u0": )" + u0 + R"(, "u1": )" + u1 + R"(, "v0": )" + v0 +
         R"(, "v1": )" + v1 + "}}";
}

TEST(ModelJsonSurface, RefusesBadCoonsPatches) {
  EXPECT_EQ(json_error(R"({"type": "coons", "boundaries": {"u0": )" + std::string(kLine00to01) + R"(, "u1": )" +
                     kLine10to11 + R"(, "v0": )" + kLine00to10 + "}}"),
            "m.json, boundaries: missing boundary 'v1' (a coons patch needs the four curves u0, u1, v0, v1)");
  EXPECT_EQ(json_error(R"({"type": "coons", "blending": "linear"})"),
            "m.json, the top level: missing field 'boundaries' (u0, u1, v0, v1)");
  EXPECT_EQ(json_error(coons_with(kLine00to01, kLine10to11, kLine00to10, kLine01to11, R"("blending": "quintic", )")),
            "m.json, blending: unknown blending 'quintic' (linear or cubic)");
  EXPECT_EQ(json_error(coons_with(kLine00to01, kLine10to11, kLine00to10,
                                R"({"type": "bezier_surface", "control_points": [[[0,1],[1,1]]]})")),
            "m.json, boundaries.v1: a bezier_surface model cannot be a boundary, a coons boundary is a curve (bezier, "
            "piecewise_bezier, bspline)");
  // A boundary's own errors keep their path.
  EXPECT_EQ(json_error(coons_with(kLine00to01, kLine10to11, R"({"type": "bezier", "control_points": [[0,0],[1]]})",
                                kLine01to11)),
            "m.json, boundaries.v0.control_points[1]: 1 coordinate, but boundaries.v0.control_points[0] has 2 (all "
            "points must have the same dimension)");
  // Pieces of a piecewise boundary that do not meet have no B-spline form.
  const std::string broken = json_error(coons_with(
      kLine00to01, kLine10to11, R"({"type": "piecewise_bezier", "pieces": [[[0,0],[0.5,0]], [[0.6,0],[1,0]]]})",
      kLine01to11));
  EXPECT_EQ(broken.rfind("m.json, boundaries.v0: ", 0), 0u) << broken;
}

TEST(ModelJsonSurface, RefusesCoonsBoundariesThatDoNotMeetAndSaysWhere) {
  // v0 ends at (1, 0.5) instead of (1, 0): the corner P(1,0) is open.
  const std::string message = json_error(coons_with(kLine00to01, kLine10to11,
                                                  R"({"type": "bezier", "control_points": [[0,0],[1,0.5]]})",
                                                  kLine01to11));
  EXPECT_EQ(message.rfind("m.json, boundaries: ", 0), 0u) << message;
  EXPECT_NE(message.find("P(1,0)"), std::string::npos) << message;
  EXPECT_NE(message.find("v0"), std::string::npos) << message;
  // Curves of different dimensions.
  const std::string dimensions =
      json_error(coons_with(kLine00to01, kLine10to11, kLine00to10, R"({"type": "bezier", "control_points": [[0,1,0],[1,1,0]]})"));
  EXPECT_EQ(dimensions.rfind("m.json, boundaries: ", 0), 0u) << dimensions;
}

TEST(ModelJsonSurface, CurveFunctionsStillServeCurves) {
  const Model curve = parse_one_model(R"({"type": "bezier", "control_points": [[0,0],[1,2],[2,0]]})");
  EXPECT_FALSE(is_surface(curve));
  EXPECT_EQ(curve_view(curve).domain(), (Interval{0.0, 1.0}));
  EXPECT_EQ(derivative_at(curve_view(curve), 0.5, 0), (Point{1, 1}));
}

}  // namespace
}  // namespace casteljau
