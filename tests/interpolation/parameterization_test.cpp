// Parameter values for interpolation: hand-worked chord and centripetal
// steps (Pythagorean triples, so the lengths are exact), the closed step,
// the errors, and invariance under similarity maps (rapidcheck).

#include "casteljau/interpolation/parameterization.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <string>

#include "support/generators.hpp"
#include "support/make.hpp"

namespace casteljau {
namespace {

using test::message_of;

PointArray plane_points(std::vector<double> coordinates) {
  return PointArray::make(2, std::move(coordinates)).value();
}

TEST(ParameterValues, UniformStepsAreExactFractions) {
  const auto t = parameter_values(plane_points({0, 0, 5, 1, 5, 1, 9, 9, 2, 2}), Parameterization::uniform);
  ASSERT_TRUE(t);
  EXPECT_EQ(*t, (std::vector<double>{0.0, 0.25, 0.5, 0.75, 1.0}));  // repeated points are fine when uniform
}

TEST(ParameterValues, ChordLengthFollowsTheDistances) {
  // Steps 5 and 6: t = 0, 5/11, 1.
  const auto t = parameter_values(plane_points({0, 0, 3, 4, 3, 10}), Parameterization::chord_length);
  ASSERT_TRUE(t);
  ASSERT_EQ(t->size(), 3u);
  EXPECT_EQ((*t)[0], 0.0);
  EXPECT_NEAR((*t)[1], 5.0 / 11.0, 1e-16);
  EXPECT_EQ((*t)[2], 1.0);
}

TEST(ParameterValues, CentripetalUsesSquareRootsOfTheDistances) {
  // Distances 4 and 9, steps 2 and 3: t = 0, 2/5, 1.
  const auto t = parameter_values(plane_points({0, 0, 0, 4, 0, 13}), Parameterization::centripetal);
  ASSERT_TRUE(t);
  EXPECT_NEAR((*t)[1], 0.4, 1e-16);
  EXPECT_EQ((*t)[2], 1.0);
}

TEST(ParameterValues, ClosedAddsTheStepBackToTheFirstPoint) {
  // The unit square: four equal sides, the fourth from (0,1) back to (0,0).
  const auto t = parameter_values(plane_points({0, 0, 1, 0, 1, 1, 0, 1}), Parameterization::chord_length, Closure::closed);
  ASSERT_TRUE(t);
  EXPECT_EQ(*t, (std::vector<double>{0.0, 0.25, 0.5, 0.75, 1.0}));
  const auto uniform = parameter_values(plane_points({0, 0, 1, 0, 1, 1}), Parameterization::uniform, Closure::closed);
  ASSERT_TRUE(uniform);
  EXPECT_EQ(uniform->size(), 4u);
}

TEST(ParameterValues, HugeAndTinyCoordinatesNeitherOverflowNorUnderflow) {
  // Up to the largest valid coordinate (10 x 1e99 = tolerances::kMaxCoordinate).
  for (const double scale : {1e-300, 1e-200, 1.0, 1e50, 1e99}) {
    const auto t = parameter_values(plane_points({0, 0, 3 * scale, 4 * scale, 3 * scale, 10 * scale}),
                                    Parameterization::chord_length);
    ASSERT_TRUE(t) << message_of(t);
    EXPECT_NEAR((*t)[1], 5.0 / 11.0, 1e-15) << scale;
  }
  // Beyond it, the points are refused (core/model_numbers.hpp).
  EXPECT_EQ(message_of(parameter_values(plane_points({0, 0, 3e200, 4e200}), Parameterization::chord_length)),
            "coordinate 0 of point 1 is 3e+200, outside [-1e+100, 1e+100], the range of coordinates");
}

TEST(ParameterValues, RefusesCoincidentConsecutivePointsNamingThem) {
  const auto points = plane_points({0, 0, 1, 1, 1, 1, 2, 0});
  EXPECT_EQ(message_of(parameter_values(points, Parameterization::chord_length)),
            "points 1 and 2 coincide, chord parameters need distinct consecutive points");
  EXPECT_EQ(message_of(parameter_values(points, Parameterization::centripetal)),
            "points 1 and 2 coincide, centripetal parameters need distinct consecutive points");
  const auto closed = plane_points({0, 0, 1, 0, 1, 1, 0, 0});
  EXPECT_EQ(message_of(parameter_values(closed, Parameterization::chord_length, Closure::closed)),
            "the last point 3 and the first point 0 coincide, chord parameters need distinct consecutive points");
  EXPECT_EQ(message_of(parameter_values(plane_points({0, 0}), Parameterization::uniform)),
            "interpolation needs at least 2 points, got 1");
  EXPECT_EQ(message_of(parameter_values(plane_points({5, 5, 5, 5}), Parameterization::chord_length)),
            "points 0 and 1 coincide, chord parameters need distinct consecutive points");
}

TEST(ParameterValues, RefusesStepsBelowTheRoundingOfTheTotal) {
  const auto points = plane_points({0, 0, 1, 0, 1 + 1e-17, 0, 2, 0});
  const auto t = parameter_values(points, Parameterization::chord_length);
  // 1 + 1e-17 rounds to 1: the points coincide as stored.
  EXPECT_EQ(message_of(t), "points 1 and 2 coincide, chord parameters need distinct consecutive points");
  const auto far = plane_points({0, 0, 1e17, 0, 1e17, 1.0, 2e17, 0});
  EXPECT_EQ(message_of(parameter_values(far, Parameterization::chord_length)),
            "points 1 and 2 are too close together (chord step below the rounding of the total length)");
}

TEST(ParameterValues, RefusesNonFiniteCoordinates) {
  const auto points = PointArray::from_trusted(2, {0, 0, 1, std::nan(""), 2, 0});
  EXPECT_EQ(message_of(parameter_values(points, Parameterization::uniform)), "coordinate 1 of point 1 is NaN");
}

TEST(ParameterValues, NamesRoundTrip) {
  for (const auto kind : {Parameterization::uniform, Parameterization::chord_length, Parameterization::centripetal}) {
    const auto read = parameterization_from_name(name_of(kind));
    ASSERT_TRUE(read);
    EXPECT_EQ(*read, kind);
  }
  EXPECT_EQ(*parameterization_from_name("chord-length"), Parameterization::chord_length);
  const auto bad = parameterization_from_name("arc");
  ASSERT_FALSE(bad);
  EXPECT_EQ(bad.error().message, "unknown parameterization 'arc', expected uniform, chord (or chord-length) or centripetal");
}

TEST(FunctionParameters, TakesTheFirstColumnAndRequiresItToIncrease) {
  const auto t = function_parameters(plane_points({-1, 5, 0.5, 2, 3, 3}));
  ASSERT_TRUE(t);
  EXPECT_EQ(*t, (std::vector<double>{-1, 0.5, 3}));
  EXPECT_EQ(message_of(function_parameters(plane_points({0, 1, 2, 1, 2, 5}))),
            "x must increase strictly: point 2 has x = 2, point 1 has x = 2");
  EXPECT_EQ(message_of(function_parameters(plane_points({0, 1, 0.1, 1, 0.05, 5}))),
            "x must increase strictly: point 2 has x = 0.05, point 1 has x = 0.1");
  EXPECT_EQ(message_of(function_parameters(PointArray::make(1, {0, 1, 2}).value())),
            "a function y(x) needs at least 2 columns (x and y), got 1");
}

TEST(WithoutClosingDuplicate, DropsOnlyARepeatedFirstPoint) {
  const auto closed = plane_points({0, 0, 4, 0, 4, 3, 0, 0});
  EXPECT_EQ(without_closing_duplicate(closed), plane_points({0, 0, 4, 0, 4, 3}));
  const auto nearly = plane_points({0, 0, 4, 0, 4, 3, 1e-12, 0});  // within 1e-9 of the scale 4
  EXPECT_EQ(without_closing_duplicate(nearly).size(), 3u);
  const auto open = plane_points({0, 0, 4, 0, 4, 3, 0.01, 0});
  EXPECT_EQ(without_closing_duplicate(open), open);
}

// Chord-length and centripetal parameters depend only on ratios of
// distances: a rotation, a uniform scaling and a translation keep them
// (up to rounding), and they always run strictly from 0 to 1.
RC_GTEST_PROP(ParameterValuesProperty, InvariantUnderSimilarities, ()) {
  const int count = *rc::gen::inRange(2, 40);
  std::vector<double> coordinates;
  for (int i = 0; i < count; ++i) {
    coordinates.push_back(*test::coordinate());
    coordinates.push_back(*test::coordinate());
  }
  const auto points = plane_points(coordinates);
  const double angle = *rc::gen::inRange(0, 628) * 0.01;
  const double factor = std::pow(10.0, *rc::gen::inRange(-5, 6));
  std::vector<double> moved;
  for (int i = 0; i < count; ++i) {
    const double x = coordinates[2 * i], y = coordinates[2 * i + 1];
    moved.push_back(factor * (std::cos(angle) * x - std::sin(angle) * y) + 17.0);
    moved.push_back(factor * (std::sin(angle) * x + std::cos(angle) * y) - 3.0);
  }
  const bool closed = *rc::gen::arbitrary<bool>();
  for (const auto kind : {Parameterization::chord_length, Parameterization::centripetal}) {
    const auto original = parameter_values(points, kind, closed ? Closure::closed : Closure::open);
    const auto image = parameter_values(plane_points(moved), kind, closed ? Closure::closed : Closure::open);
    RC_PRE(original.has_value() && image.has_value());  // coincident random points are rare and refused alike
    RC_ASSERT(original->front() == 0.0 && original->back() == 1.0);
    for (std::size_t i = 0; i < original->size(); ++i) {
      if (i > 0) RC_ASSERT((*original)[i] > (*original)[i - 1]);
      RC_ASSERT(std::abs((*original)[i] - (*image)[i]) <= 1e-9);
    }
  }
}

}  // namespace
}  // namespace casteljau
