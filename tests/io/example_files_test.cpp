// The files of examples/ (examples/README.md): every model and point set
// reads, and each is what the page says it is, checked against the function
// or formula it names rather than against its own numbers.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include "casteljau/bspline/knot_vector.hpp"
#include "casteljau/io/csv.hpp"
#include "casteljau/io/model_file.hpp"
#include "casteljau/io/model_json.hpp"
#include "casteljau/surfaces/revolution.hpp"
#include "support/examples_dir.hpp"

namespace casteljau {
namespace {

const std::filesystem::path kExamples = test::examples_dir();

Model only_model(const std::string& name) {
  auto models = read_models(kExamples / name);
  EXPECT_TRUE(models.has_value()) << name << ": " << (models ? "" : models.error().message);
  if (!models || models->size() != 1) {
    ADD_FAILURE() << name << ": expected one model";
    return Model{BezierCurve::from_trusted(PointArray::from_trusted(1, {0}))};
  }
  return models->front();
}

TEST(ExampleFiles, EveryModelAndPointSetReads) {
  std::size_t count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(kExamples)) {
    const auto extension = entry.path().extension();
    if (extension != ".json" && extension != ".csv") continue;
    const auto models = read_models(entry.path());
    EXPECT_TRUE(models.has_value()) << (models ? "" : models.error().message);
    ++count;
  }
  EXPECT_GE(count, 16u);  // the seeds' 8 point sets and the README's inputs
}

TEST(ExampleFiles, TheNotebookCurveIsTheNotebookPolygonsCurve) {
  EXPECT_EQ(only_model("notebook_curve.json"), only_model("notebook_polygon.csv"));
}

TEST(ExampleFiles, TheSphereIsMakeSpheres) {
  const double center[3] = {0.0, 0.0, 0.0};
  EXPECT_EQ(only_model("sphere.json"), Model{make_sphere(center, 1.0).value()});
}

TEST(ExampleFiles, TheSplineIsACubicOnClampedUniformKnots) {
  const Model model = only_model("spline.json");
  ASSERT_TRUE(std::holds_alternative<BSplineCurve>(model));
  const auto& spline = std::get<BSplineCurve>(model);
  EXPECT_EQ(spline.degree(), 3);
  const auto knots = clamped_uniform_knots(3, 11, Interval{0.0, 8.0});
  EXPECT_EQ(std::vector<double>(spline.knots().begin(), spline.knots().end()), knots);
}

TEST(ExampleFiles, RungeHoldsTheFunctionAtTwentyOneUniformNodes) {
  const auto points = read_points_csv(kExamples / "runge.csv");
  ASSERT_TRUE(points.has_value()) << points.error().message;
  ASSERT_EQ(points->size(), 21u);
  for (std::size_t i = 0; i < points->size(); ++i) {
    const double x = (static_cast<double>(i) - 10.0) / 10.0;
    EXPECT_EQ((*points)[i][0], x);
    EXPECT_EQ((*points)[i][1], 1.0 / (1.0 + 25.0 * x * x)) << x;
  }
}

TEST(ExampleFiles, NoisyHoldsSamplesOfTheSineOnAGrid) {
  const auto points = read_points_csv(kExamples / "noisy.csv");
  ASSERT_TRUE(points.has_value()) << points.error().message;
  ASSERT_EQ(points->size(), 101u);
  double largest = 0.0;
  for (std::size_t i = 0; i < points->size(); ++i) {
    EXPECT_EQ((*points)[i][0], static_cast<double>(i) / 100.0);
    largest = std::max(largest, std::abs((*points)[i][1] - std::sin(2.0 * std::numbers::pi * (*points)[i][0])));
  }
  EXPECT_LT(largest, 0.5);  // noise of standard deviation 0.1: 5 sigma
}

}  // namespace
}  // namespace casteljau
