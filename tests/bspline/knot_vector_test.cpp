// Knot vector validation, builders and the Rhino convention.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "casteljau/bspline/knot_vector.hpp"

namespace casteljau {
namespace {

std::string error_of(const Status& status) { return status ? std::string("(no error)") : status.error().message; }

TEST(ValidateKnots, AcceptsClampedAndUnclampedVectors) {
  const std::vector<double> clamped{0, 0, 0, 0, 0.5, 1, 1, 1, 1};
  EXPECT_TRUE(validate_knots(clamped, 3, 5));
  const std::vector<double> uniform{0, 1, 2, 3, 4, 5, 6, 7};
  EXPECT_TRUE(validate_knots(uniform, 3, 4));
  const std::vector<double> degree0{0, 1, 2};
  EXPECT_TRUE(validate_knots(degree0, 0, 2));
}

TEST(ValidateKnots, NamesEachFault) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(error_of(validate_knots(std::vector<double>{0, 0, 0, 1, 1, 1}, 2, 4)),
            "6 knots given, a B-spline of this degree and control point count needs 7 (control points + degree + 1)");
  EXPECT_EQ(error_of(validate_knots(std::vector<double>{0, 0, 0, nan, 1, 1, 1}, 2, 4)), "knot 3 is NaN");
  EXPECT_EQ(error_of(validate_knots(std::vector<double>{0, 0, 0, 0.5, 1, 1, inf}, 2, 4)), "knot 6 is infinite");
  EXPECT_EQ(error_of(validate_knots(std::vector<double>{0, 0, 0, 0.7, 0.5, 1, 1, 1}, 2, 5)),
            "knot 4 (0.5) is smaller than knot 3 (0.7), knots must be non-decreasing");
  EXPECT_EQ(error_of(validate_knots(std::vector<double>{0, 0, 0, 0.5, 0.5, 0.5, 0.5, 1, 1, 1}, 2, 7)),
            "knot 6 (0.5) has multiplicity 4, above degree + 1 = 3");
  EXPECT_EQ(error_of(validate_knots(std::vector<double>{0, 0, 1, 1, 2, 2}, 2, 3)),
            "the domain [knot 2, knot 3] = [1, 1] is empty, knot 2 must be smaller than knot 3");
}

TEST(KnotBuilders, ClampedUniformMatchesTheTextbookVector) {
  // The NURBS Book eq. 2.13 with p = 2, n + 1 = 6 on [0, 4] (its Ex. 2.3 knots).
  EXPECT_EQ(clamped_uniform_knots(2, 6, {0, 4}), (std::vector<double>{0, 0, 0, 1, 2, 3, 4, 4, 4}));
  EXPECT_EQ(clamped_uniform_knots(3, 4), (std::vector<double>{0, 0, 0, 0, 1, 1, 1, 1}));
  const auto knots = clamped_uniform_knots(3, 1000);
  EXPECT_TRUE(validate_knots(knots, 3, 1000));
  EXPECT_EQ(knots[3], 0.0);
  EXPECT_EQ(knots[1000], 1.0);
}

TEST(KnotBuilders, UniformHasItsDomainExactlyAndEqualSteps) {
  const auto knots = uniform_knots(3, 7, {0, 4});
  EXPECT_EQ(knots, (std::vector<double>{-3, -2, -1, 0, 1, 2, 3, 4, 5, 6, 7}));
  const auto unit = uniform_knots(2, 10, {-1, 2});
  EXPECT_EQ(unit[2], -1.0);
  EXPECT_EQ(unit[10], 2.0);
  EXPECT_TRUE(validate_knots(unit, 2, 10));
  // m distinct points, degree p: m + 2p + 1 knots and m spans in the domain.
  const auto periodic = periodic_knots(3, 5, {0, 5});
  EXPECT_EQ(periodic.size(), 5u + 2 * 3 + 1);
  EXPECT_EQ(periodic[3], 0.0);
  EXPECT_EQ(periodic[8], 5.0);
}

TEST(RhinoKnots, AddsTheTwoOuterKnots) {
  // openNURBS stores a clamped cubic with 5 control points as 0 0 0 0.5 1 1 1.
  const auto full = knots_from_rhino(std::vector<double>{0, 0, 0, 0.5, 1, 1, 1}, 3, 5);
  ASSERT_TRUE(full) << full.error().message;
  EXPECT_EQ(*full, (std::vector<double>{0, 0, 0, 0, 0.5, 1, 1, 1, 1}));
  const auto wrong = knots_from_rhino(std::vector<double>{0, 0, 0, 0, 0.5, 1, 1, 1, 1}, 3, 5);
  ASSERT_FALSE(wrong);
  EXPECT_EQ(wrong.error().message,
            "9 knots given, the Rhino/openNURBS convention needs 7 (control points + degree - 1) and degree >= 1");
  // Indices in errors are those of the Rhino vector the user wrote.
  const auto decreasing = knots_from_rhino(std::vector<double>{0, 0, 0, 0.6, 0.5, 1, 1, 1}, 3, 6);
  ASSERT_FALSE(decreasing);
  EXPECT_EQ(decreasing.error().message,
            "knot 4 (0.5) is smaller than knot 3 (0.6), knots must be non-decreasing");
}

TEST(Multiplicities, GroupEqualKnotsOnly) {
  const std::vector<double> knots{0, 0, 0, 0.3, 0.30000000000000004, 0.5, 0.5, 1, 1, 1};
  const auto groups = knot_multiplicities(knots);
  ASSERT_EQ(groups.size(), 5u);
  EXPECT_EQ(groups[0], (KnotMultiplicity{0.0, 3}));
  EXPECT_EQ(groups[1], (KnotMultiplicity{0.3, 1}));
  EXPECT_EQ(groups[3], (KnotMultiplicity{0.5, 2}));
  EXPECT_EQ(multiplicity_of(knots, 0.5), 2);
  EXPECT_EQ(multiplicity_of(knots, 0.4), 0);
}

}  // namespace
}  // namespace casteljau
