// points_at (the batch evaluator) against point_at: the same de Casteljau
// arithmetic, so the same bits, for every degree, dimension, kind of curve,
// parameter count and output alignment. point_at itself is checked against
// exact arithmetic in evaluate_test.cpp; equality here carries that over.
#include "casteljau/bezier/evaluate.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>
#include <vector>

#include "casteljau/core/tolerance.hpp"
#include "support/exact.hpp"
#include "support/generators.hpp"
#include "support/sanitizers.hpp"

namespace casteljau {
namespace {

/// The same bits (so -0.0 differs from 0.0, as a bit-for-bit promise requires).
bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

/// Index of the first coordinate where points_at and point_at differ, or -1.
/// `offset` shifts the output inside its buffer (unaligned output spans).
/// With stride > 1, the first and last 64 points and every stride-th between.
long first_difference(const BezierCurve& curve, const std::vector<double>& ts, std::size_t offset,
                      std::size_t stride = 1) {
  const std::size_t d = curve.dimension();
  std::vector<double> buffer(ts.size() * d + offset + 1, -7.0);
  std::span<double> out(buffer.data() + offset, ts.size() * d);
  points_at(curve, ts, out);
  for (std::size_t k = 0; k < ts.size(); ++k) {
    if (k >= 64 && k + 64 < ts.size() && k % stride != 0) continue;
    const Point p = point_at(curve, ts[k]);
    for (std::size_t j = 0; j < d; ++j)
      if (!same_bits(out[k * d + j], p[j])) return static_cast<long>(k * d + j);
  }
  // Nothing written outside the span.
  for (std::size_t i = 0; i < offset; ++i)
    if (buffer[i] != -7.0) return -2;
  if (buffer.back() != -7.0) return -2;
  return -1;
}

/// Parameters in [0,1] with the ends, plus some outside (points_at extrapolates like point_at).
rc::Gen<double> any_parameter() {
  return rc::gen::weightedOneOf<double>(
      {{8, test::unit_parameter()},
       {1, rc::gen::map(rc::gen::inRange(-500000, 1500001), [](int i) { return i * 1e-6; })}});
}

/// A random curve of degree in [lo, hi], dimension 1..5, rational or not.
rc::Gen<BezierCurve> curve_of_degree(int lo, int hi) {
  return rc::gen::exec([=] {
    const int d = *rc::gen::inRange(1, 6);
    const bool rational = *rc::gen::arbitrary<bool>();
    return *test::bezier_curve(lo, hi, rational, d);
  });
}

RC_GTEST_PROP(PointsAt, EqualsPointAtBitForBit, ()) {
  const BezierCurve curve = *curve_of_degree(0, 40);
  const auto ts = *rc::gen::container<std::vector<double>>(*rc::gen::inRange(0, 70), any_parameter());
  const std::size_t offset = *rc::gen::inRange(0, 3);
  RC_ASSERT(first_difference(curve, ts, offset) == -1);
}

RC_GTEST_PROP(PointsAt, EqualsPointAtAboveTheStackDegree, ()) {
  const BezierCurve curve =
      *curve_of_degree(tolerances::kMaxStackDegree - 2, tolerances::kMaxStackDegree + 40);
  const auto ts = *rc::gen::container<std::vector<double>>(*rc::gen::inRange(1, 20), any_parameter());
  RC_ASSERT(first_difference(curve, ts, 1) == -1);
}

/// Random curve and parameters from a fixed seed (the standard mt19937_64 stream).
struct Seeded {
  std::mt19937_64 rng;
  double unit() { return static_cast<double>(rng() >> 11) * 0x1p-53; }
  BezierCurve curve(int n, int d, bool rational) {
    std::vector<double> c((n + 1) * d), w;
    for (double& x : c) x = 100.0 * unit();
    if (rational)
      for (int i = 0; i <= n; ++i) w.push_back(0.1 + 10.0 * unit());
    return BezierCurve::make(PointArray::make(d, c).value(), w).value();
  }
  std::vector<double> parameters(std::size_t count) {
    std::vector<double> ts(count);
    for (double& t : ts) t = unit();
    return ts;
  }
};

// Large batches take another store path (streaming stores from the first
// aligned block on): every alignment of the output and a ragged end.
TEST(PointsAt, LargeBatchesEqualPointAt) {
  Seeded seeded{std::mt19937_64(20260303)};
  const auto ts = seeded.parameters(530'003);  // > 4 MiB of output even in 1D
  for (int d = 1; d <= 3; ++d)
    for (bool rational : {false, true})
      for (int n : {1, 3, 15}) {
        // Under the sanitizers one degree: the store paths, alignments and
        // ragged ends (what memory errors hide in) are the same for each.
        if (test::kUnderSanitizers && n != 3) continue;
        const BezierCurve curve = seeded.curve(n, d, rational);
        for (std::size_t offset : {0, 1, 3}) {
          EXPECT_EQ(first_difference(curve, ts, offset, 11), -1)
              << "degree " << n << ", dimension " << d << (rational ? ", rational" : "") << ", offset " << offset;
        }
      }
}

TEST(PointsAt, EmptyBatchWritesNothing) {
  Seeded seeded{std::mt19937_64(5)};
  for (int n : {0, 3, 300}) {
    const BezierCurve curve = seeded.curve(n, 2, false);
    std::vector<double> out;
    points_at(curve, {}, out);
    EXPECT_TRUE(out.empty());
  }
}

// Against the exact value directly (not only point_at): a W3-like cubic in
// the plane, whose error must stay within a few rounding units of the scale.
TEST(PointsAt, CubicIsWithinRoundingOfExact) {
  Seeded seeded{std::mt19937_64(99)};
  const BezierCurve curve = seeded.curve(3, 2, false);
  const auto ts = seeded.parameters(1001);
  std::vector<double> out(ts.size() * 2);
  points_at(curve, ts, out);
  double worst = 0.0;
  for (std::size_t k = 0; k < ts.size(); ++k) {
    const auto exact = test::exact_point(curve, ts[k]);
    for (int j = 0; j < 2; ++j) worst = std::max(worst, test::error_of(out[k * 2 + j], exact[j]));
  }
  // 3 rounds of one product and one FMA: a few ulps of 100 (ulp = 1.4e-14).
  EXPECT_LE(worst, 3 * 2 * tolerances::kRoundingSlack * 100.0);
  EXPECT_GT(worst, 0.0);  // the check can fail: rounding is visible at all
}

}  // namespace
}  // namespace casteljau
