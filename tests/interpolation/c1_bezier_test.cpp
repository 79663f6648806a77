// Seed 000's C¹ interpolant: control points against the seed's formulas in
// exact rational arithmetic on the seed's own data (head.csv, car.csv), C¹ at
// every joint, α = 2 against uniform Catmull–Rom, the closed extension, errors.
#include "casteljau/interpolation/c1_bezier.hpp"

#include <gmpxx.h>
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "casteljau/bezier/evaluate.hpp"
#include "casteljau/bspline/bezier_pieces.hpp"
#include "casteljau/interpolation/catmull_rom.hpp"
#include "support/exact.hpp"
#include "support/examples_dir.hpp"
#include "support/generators.hpp"

namespace casteljau {
namespace {

/// A decimal such as "-4.25" as the exact rational it denotes.
mpq_class exact_decimal(const std::string& text) {
  std::string digits;
  long scale = 0;
  bool after_point = false;
  for (char c : text) {
    if (c == '.') after_point = true;
    else {
      digits += c;
      if (after_point && c != '-' && c != '+') ++scale;
    }
  }
  mpz_class ten_power;
  mpz_ui_pow_ui(ten_power.get_mpz_t(), 10, static_cast<unsigned long>(scale));
  mpq_class q(mpz_class(digits), ten_power);
  q.canonicalize();
  return q;
}

/// A seed point set read as text: the doubles and the exact decimals.
struct SeedPoints {
  PointArray points;
  std::vector<std::vector<mpq_class>> exact;
};

SeedPoints read_seed_points(const std::string& name) {
  std::ifstream in(test::examples_dir() / name);
  EXPECT_TRUE(in) << "cannot open " << (test::examples_dir() / name);
  SeedPoints result;
  std::vector<double> coordinates;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#' || line[0] == 'x') continue;
    const auto comma = line.find(',');
    const std::string x = line.substr(0, comma), y = line.substr(comma + 1);
    coordinates.push_back(std::stod(x));
    coordinates.push_back(std::stod(y));
    result.exact.push_back({exact_decimal(x), exact_decimal(y)});
  }
  result.points = PointArray::make(2, coordinates).value();
  return result;
}

/// The seed's control points Q_i, R_i (000 §2, seeds.md) computed exactly.
struct ExactControl {
  std::vector<std::vector<mpq_class>> q, r;
};

ExactControl seed_formulas(const std::vector<std::vector<mpq_class>>& p, const mpq_class& alpha) {
  const std::size_t m = p.size() - 1;
  const mpq_class three_alpha = 3 * alpha;
  ExactControl c;
  c.q.resize(m);
  c.r.resize(m);
  for (std::size_t i = 0; i < m; ++i)
    for (int k = 0; k < 2; ++k) {
      c.q[i].push_back(i == 0 ? mpq_class(p[0][k] + 2 * (p[1][k] - p[0][k]) / three_alpha)
                              : mpq_class(p[i][k] + (p[i + 1][k] - p[i - 1][k]) / three_alpha));
      c.r[i].push_back(i + 1 == m ? mpq_class(p[m][k] - 2 * (p[m][k] - p[m - 1][k]) / three_alpha)
                                  : mpq_class(p[i + 1][k] - (p[i + 2][k] - p[i][k]) / three_alpha));
    }
  return c;
}

void expect_seed_control_points(const std::string& file, double alpha) {
  const SeedPoints seed = read_seed_points(file);
  const auto curve = interpolate_c1_bezier(seed.points, alpha);
  ASSERT_TRUE(curve) << curve.error().message;
  const std::size_t m = seed.points.size() - 1;
  ASSERT_EQ(curve->size(), static_cast<int>(m));
  const ExactControl exact = seed_formulas(seed.exact, mpq_class(alpha));  // alpha's exact double value
  // The CSV decimals are not all dyadic (car.csv has 4.2): the inputs carry
  // half an ulp each, the formulas a few more operations.
  const double tolerance = 8 * std::numeric_limits<double>::epsilon() * scale_of(seed.points);
  for (std::size_t i = 0; i < m; ++i) {
    const PointArray& b = curve->pieces()[i].control_points();
    ASSERT_EQ(b.size(), 4u);
    for (int k = 0; k < 2; ++k) {
      EXPECT_LE(test::error_of(b[0][k], seed.exact[i][k]), tolerance) << file << " piece " << i;
      EXPECT_LE(test::error_of(b[1][k], exact.q[i][k]), tolerance) << file << " Q_" << i << " alpha " << alpha;
      EXPECT_LE(test::error_of(b[2][k], exact.r[i][k]), tolerance) << file << " R_" << i << " alpha " << alpha;
      EXPECT_LE(test::error_of(b[3][k], seed.exact[i + 1][k]), tolerance) << file << " piece " << i;
    }
  }
}

}  // namespace

TEST(C1Bezier, HeadControlPointsAreTheSeedFormulas) {
  for (double alpha : {1.0, 2.0, 0.7}) expect_seed_control_points("head.csv", alpha);
}

TEST(C1Bezier, CarControlPointsAreTheSeedFormulas) {
  for (double alpha : {1.0, 2.0, 0.7}) expect_seed_control_points("car.csv", alpha);
}

TEST(C1Bezier, HeadAndCarAreC1AtEveryJoint) {
  for (const char* file : {"head.csv", "car.csv"}) {
    const SeedPoints seed = read_seed_points(file);
    for (double alpha : {1.0, 2.0}) {
      const auto curve = interpolate_c1_bezier(seed.points, alpha).value();
      const double scale = scale_of(seed.points);
      for (int i = 0; i + 1 < curve.size(); ++i) {
        const auto& left = curve.pieces()[static_cast<std::size_t>(i)];
        const auto& right = curve.pieces()[static_cast<std::size_t>(i) + 1];
        // Continuity of position (bit-exact: both pieces copy P_{i+1}).
        EXPECT_EQ(point_at(left, 1.0), point_at(right, 0.0));
        // Equal first derivatives 3(P − R) = 3(Q − P) = (P_{i+2} − P_i)/α.
        const Point d_left = derivative_at(left, 1.0, 1), d_right = derivative_at(right, 0.0, 1);
        for (int k = 0; k < 2; ++k) {
          const double expected = (seed.points[i + 2][k] - seed.points[i][k]) / alpha;
          EXPECT_NEAR(d_left[k], d_right[k], 1e-14 * scale) << file << " joint " << i + 1;
          EXPECT_NEAR(d_left[k], expected, 1e-14 * scale) << file << " joint " << i + 1;
        }
        // The second derivatives do jump in general: C¹, not C².
      }
    }
  }
}

TEST(C1Bezier, SecondDerivativeJumpsSoTheCheckAboveCanFail) {
  const SeedPoints seed = read_seed_points("head.csv");
  const auto curve = interpolate_c1_bezier(seed.points, 1.0).value();
  double largest_jump = 0;
  for (int i = 0; i + 1 < curve.size(); ++i) {
    const Point a = derivative_at(curve.pieces()[i], 1.0, 2), b = derivative_at(curve.pieces()[i + 1], 0.0, 2);
    largest_jump = std::max(largest_jump, std::hypot(a[0] - b[0], a[1] - b[1]));
  }
  EXPECT_GT(largest_jump, 1.0);
}

TEST(C1Bezier, AlphaTwoIsUniformCatmullRomOnHeadAndCar) {
  for (const char* file : {"head.csv", "car.csv"}) {
    const SeedPoints seed = read_seed_points(file);
    const auto c1 = interpolate_c1_bezier(seed.points, 2.0).value();
    std::vector<double> parameters(seed.points.size());
    for (std::size_t i = 0; i < parameters.size(); ++i) parameters[i] = static_cast<double>(i);
    const auto catmull_rom = interpolate_catmull_rom(seed.points, parameters).value();
    const BezierPieces pieces = to_bezier_pieces(catmull_rom);
    ASSERT_EQ(pieces.pieces.size(), c1.pieces().size());
    const double tolerance = 1e-14 * scale_of(seed.points);
    for (std::size_t i = 0; i < pieces.pieces.size(); ++i)
      for (std::size_t j = 0; j < 4; ++j)
        for (std::size_t k = 0; k < 2; ++k)
          EXPECT_NEAR(pieces.pieces[i].control_points()[j][k], c1.pieces()[i].control_points()[j][k], tolerance)
              << file << " piece " << i << " point " << j;
  }
}

TEST(C1Bezier, ClosedIsTheCyclicExtension) {
  const SeedPoints seed = read_seed_points("head.csv");
  const auto curve = interpolate_c1_bezier(seed.points, 1.0, Closure::closed);
  ASSERT_TRUE(curve) << curve.error().message;
  const std::size_t count = seed.points.size();
  ASSERT_EQ(curve->size(), static_cast<int>(count));
  const double tolerance = 8 * std::numeric_limits<double>::epsilon() * scale_of(seed.points);
  for (std::size_t i = 0; i < count; ++i) {
    const auto& p = seed.exact;
    const auto& b = curve->pieces()[i].control_points();
    for (int k = 0; k < 2; ++k) {
      const mpq_class q = p[i][k] + (p[(i + 1) % count][k] - p[(i + count - 1) % count][k]) / 3;
      const mpq_class r = p[(i + 1) % count][k] - (p[(i + 2) % count][k] - p[i][k]) / 3;
      EXPECT_LE(test::error_of(b[1][k], q), tolerance) << "Q_" << i;
      EXPECT_LE(test::error_of(b[2][k], r), tolerance) << "R_" << i;
      EXPECT_EQ(b[3][k], seed.points[(i + 1) % count][k]);
    }
  }
  // C¹ across the seam P_0 as well.
  const Point d_end = derivative_at(curve->pieces().back(), 1.0, 1);
  const Point d_start = derivative_at(curve->pieces().front(), 0.0, 1);
  for (int k = 0; k < 2; ++k) EXPECT_NEAR(d_end[k], d_start[k], 1e-14 * scale_of(seed.points));
}

RC_GTEST_PROP(C1Bezier, InterpolatesAndIsC1, ()) {
  const int count = *rc::gen::inRange(2, 12);
  const int d = *rc::gen::inRange(1, 4);
  const auto coordinates = *rc::gen::container<std::vector<double>>(count * d, test::coordinate());
  const PointArray points = PointArray::make(d, coordinates).value();
  const double alpha = *rc::gen::map(rc::gen::inRange(1, 401), [](int i) { return i / 100.0; });
  const bool closed = count >= 3 && *rc::gen::arbitrary<bool>();
  const auto made = interpolate_c1_bezier(points, alpha, closed ? Closure::closed : Closure::open);
  if (!made) {
    // Only a closed set whose random last point equals its first is refused.
    RC_ASSERT(closed);
    RC_ASSERT(distance(points[count - 1], points[0]) <= 1e-9 * scale_of(points));
    return;
  }
  const auto& curve = *made;
  const int pieces = closed ? count : count - 1;
  RC_ASSERT(curve.size() == pieces);
  const double tolerance = 1e-13 * std::max(1.0, scale_of(points)) / alpha;
  for (int i = 0; i < pieces; ++i) {
    RC_ASSERT(point_at(curve, i) == Point(points[i].begin(), points[i].end()));
    const Point end = point_at(curve.pieces()[i], 1.0);
    const auto expected = points[(i + 1) % count];
    RC_ASSERT(std::equal(end.begin(), end.end(), expected.begin()));
    if (i + 1 < pieces || closed) {
      const Point a = derivative_at(curve.pieces()[i], 1.0, 1);
      const Point b = derivative_at(curve.pieces()[(i + 1) % pieces], 0.0, 1);
      for (int k = 0; k < d; ++k) RC_ASSERT(std::abs(a[k] - b[k]) <= tolerance);
    }
  }
}

TEST(C1Bezier, RefusesBadInput) {
  const PointArray one = PointArray::make(2, {0, 0}).value();
  auto e = interpolate_c1_bezier(one);
  ASSERT_FALSE(e);
  EXPECT_EQ(e.error().message, "c1-bezier curve needs at least 2 points, got 1");
  EXPECT_FALSE(interpolate_c1_bezier(PointArray{}));
  const PointArray two = PointArray::make(2, {0, 0, 1, 1}).value();
  EXPECT_FALSE(interpolate_c1_bezier(two, 1.0, Closure::closed));
  for (double alpha : {0.0, -1.0, std::nan(""), std::numeric_limits<double>::infinity()}) {
    e = interpolate_c1_bezier(two, alpha);
    ASSERT_FALSE(e) << alpha;
    EXPECT_NE(e.error().message.find("alpha is"), std::string::npos) << e.error().message;
  }
  PointArray with_nan = PointArray::from_trusted(2, {0, 0, 1, std::nan(""), 2, 0});
  e = interpolate_c1_bezier(with_nan);
  ASSERT_FALSE(e);
  EXPECT_EQ(e.error().message, "coordinate 1 of point 1 is NaN");
  const PointArray repeated = PointArray::make(2, {0, 0, 1, 0, 1, 1, 0, 0}).value();
  e = interpolate_c1_bezier(repeated, 1.0, Closure::closed);
  ASSERT_FALSE(e);
  EXPECT_NE(e.error().message.find("repeats the first"), std::string::npos) << e.error().message;
  EXPECT_TRUE(interpolate_c1_bezier(repeated, 1.0, Closure::open));  // open: a loop back to P_0 is fine
}

}  // namespace casteljau
