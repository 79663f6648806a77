// Batch B-spline evaluation (src/bspline/points_at.cpp) against the scalar
// functions: points_at equals point_at, points_and_derivatives_at and
// derivatives_at(us, 1) equal point_at / derivative_at(u, 1), bit for bit,
// for degrees 0..9, dimensions 1..4, rational or not, clamped or not, with
// repeated interior knots, parameters sorted, shuffled and reversed, at
// knots, at and beyond the domain's ends, any batch size and output offset.
//
// The scalar functions themselves are checked here against independent
// formulas: the de Boor point against the basis-function sum (The NURBS
// Book A3.1/A4.1) and the de Boor-triangle derivative against the sum of
// basis-function derivatives (A3.2/A4.2), within a few units in the last
// place of each sum's magnitude (sum of |terms|), which is what the
// reciprocal arithmetic of de_boor.hpp may cost.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <utility>
#include <vector>

#include "casteljau/bspline/basis.hpp"
#include "casteljau/bspline/evaluate.hpp"
#include "casteljau/bspline/knot_vector.hpp"
#include "../support/splitmix.hpp"

namespace casteljau {
namespace {

using Random = test::SplitMix;

bool same_bits(double a, double b) {
  std::uint64_t x, y;
  std::memcpy(&x, &a, sizeof x);
  std::memcpy(&y, &b, sizeof y);
  return x == y;
}

/// A random curve: degree p, dimension d, 1..12 more control points than
/// p+1, coordinates in [-100, 100), weights in [0.1, 10); knots clamped or
/// not on a random interval, with interior knots repeated up to p times.
BSplineCurve random_curve(Random& random, int p, int d, bool rational, bool clamped) {
  for (;;) {
    const int count = p + 1 + 1 + random.below(12);
    const int knot_count = count + p + 1;
    const double lower = -3.0 + 6.0 * random.unit();
    const double width = 0.5 + 4.0 * random.unit();
    std::vector<double> knots(static_cast<std::size_t>(knot_count));
    for (double& t : knots) t = lower + width * random.unit();
    std::sort(knots.begin(), knots.end());
    // Repeat some interior knots (multiplicity up to p).
    for (int i = 1; i < knot_count; ++i) {
      int multiplicity = 1;
      while (multiplicity < i && knots[static_cast<std::size_t>(i - multiplicity)] == knots[static_cast<std::size_t>(i)])
        ++multiplicity;
      if (p > 0 && multiplicity < p && random.below(4) == 0) knots[static_cast<std::size_t>(i)] = knots[static_cast<std::size_t>(i - 1)];
    }
    if (clamped) {
      for (int i = 0; i <= p; ++i) {
        knots[static_cast<std::size_t>(i)] = knots[static_cast<std::size_t>(p)];
        knots[static_cast<std::size_t>(knot_count - 1 - i)] = knots[static_cast<std::size_t>(count)];
      }
    }
    std::vector<double> coordinates(static_cast<std::size_t>(count * d));
    for (double& x : coordinates) x = -100.0 + 200.0 * random.unit();
    std::vector<double> weights;
    if (rational)
      for (int i = 0; i < count; ++i) weights.push_back(0.1 + 9.9 * random.unit());
    auto points = PointArray::make(d, coordinates);
    if (!points) continue;
    auto curve = BSplineCurve::make(p, knots, *points, weights);
    if (curve) return *curve;  // else (empty domain, multiplicity) draw again
  }
}

/// Parameters that exercise every path: the knots themselves (inside and
/// outside the domain), the ends, neighbours of knots, random points,
/// points outside the domain, and a dense sorted run.
std::vector<double> parameters_for(Random& random, const BSplineCurve& curve) {
  const Interval domain = curve.domain();
  const double width = domain.upper - domain.lower;
  std::vector<double> us;
  for (double t : curve.knots()) {
    us.push_back(t);
    us.push_back(std::nextafter(t, -INFINITY));
    us.push_back(std::nextafter(t, INFINITY));
  }
  us.push_back(domain.lower);
  us.push_back(domain.upper);
  for (int i = 0; i < 40; ++i) us.push_back(domain.lower + width * random.unit());
  for (int i = 0; i < 6; ++i) us.push_back(domain.lower - 0.3 * width * random.unit());
  for (int i = 0; i < 6; ++i) us.push_back(domain.upper + 0.3 * width * random.unit());
  return us;
}

/// Checks every batch function against the scalar ones on `us`, with the
/// outputs at an offset of `shift` doubles (alignment).
void expect_batch_equals_scalar(const BSplineCurve& curve, const std::vector<double>& us, std::size_t shift = 0) {
  const std::size_t d = static_cast<std::size_t>(curve.dimension());
  const std::size_t size = us.size() * d;
  std::vector<double> points(size + shift, NAN), points2(size + shift, NAN), first(size + shift, NAN),
      first2(size + shift, NAN);
  const std::span<double> p(points.data() + shift, size), p2(points2.data() + shift, size),
      f(first.data() + shift, size), f2(first2.data() + shift, size);
  points_at(curve, us, p);
  points_and_derivatives_at(curve, us, p2, f);
  derivatives_at(curve, us, 1, f2);
  int failures = 0;
  for (std::size_t i = 0; i < us.size() && failures < 5; ++i) {
    const Point expected = point_at(curve, us[i]);
    const Point expected_derivative = derivative_at(curve, us[i], 1);
    for (std::size_t c = 0; c < d; ++c) {
      const bool ok = same_bits(p[i * d + c], expected[c]) && same_bits(p2[i * d + c], expected[c]) &&
                      same_bits(f[i * d + c], expected_derivative[c]) &&
                      same_bits(f2[i * d + c], expected_derivative[c]);
      if (!ok) {
        ++failures;
        ADD_FAILURE() << "degree " << curve.degree() << " dimension " << d << (curve.is_rational() ? " rational" : "")
                      << " u = " << us[i] << " (index " << i << " of " << us.size() << ") coordinate " << c
                      << ": points_at " << p[i * d + c] << ", points_and_derivatives_at " << p2[i * d + c]
                      << ", point_at " << expected[c] << "; derivative " << f[i * d + c] << " / " << f2[i * d + c]
                      << ", derivative_at " << expected_derivative[c];
        break;
      }
    }
  }
}

TEST(BSplinePointsAt, EqualsPointAtBitForBit) {
  Random random{20261122u};
  for (int p = 0; p <= 9; ++p) {
    for (int d = 1; d <= 4; ++d) {
      for (int rational = 0; rational <= 1; ++rational) {
        for (int clamped = 0; clamped <= 1; ++clamped) {
          const BSplineCurve curve = random_curve(random, p, d, rational == 1, clamped == 1);
          std::vector<double> us = parameters_for(random, curve);
          // Shuffled (as drawn, then a random permutation), sorted, reversed.
          for (std::size_t i = us.size(); i > 1; --i) std::swap(us[i - 1], us[static_cast<std::size_t>(random.below(static_cast<int>(i)))]);
          expect_batch_equals_scalar(curve, us);
          std::sort(us.begin(), us.end());
          expect_batch_equals_scalar(curve, us);
          std::reverse(us.begin(), us.end());
          expect_batch_equals_scalar(curve, us);
          // A dense sorted run: many parameters per span (the broadcast path).
          std::vector<double> dense(300);
          const Interval domain = curve.domain();
          for (std::size_t i = 0; i < dense.size(); ++i)
            dense[i] = domain.lerp(static_cast<double>(i) / static_cast<double>(dense.size() - 1));
          expect_batch_equals_scalar(curve, dense);
        }
      }
    }
  }
}

TEST(BSplinePointsAt, AnyBatchSizeAndOutputOffset) {
  Random random{77u};
  for (int p : {1, 2, 3, 5, 8}) {
    for (int d : {1, 2, 3, 4}) {
      for (int rational = 0; rational <= 1; ++rational) {
        const BSplineCurve curve = random_curve(random, p, d, rational == 1, true);
        const std::vector<double> all = parameters_for(random, curve);
        for (std::size_t size = 0; size <= 20; ++size) {
          const std::vector<double> us(all.begin(), all.begin() + static_cast<std::ptrdiff_t>(size));
          for (std::size_t shift : {0u, 1u, 3u}) expect_batch_equals_scalar(curve, us, shift);
        }
      }
    }
  }
}

/// A clamped polynomial curve gives its end control points exactly; a NURBS
/// curve gives (w P) / w, which rounds twice: within one ulp of P.
void expect_end(double value, double control, bool rational, int p, std::size_t i) {
  if (rational) {
    EXPECT_NEAR(value, control, 0x1p-52 * std::abs(control)) << "p " << p << " i " << i;
  } else {
    EXPECT_EQ(value, control) << "p " << p << " i " << i;
  }
}

TEST(BSplinePointsAt, ClampedCurvesGiveTheirEndPointsExactly) {
  Random random{5u};
  for (int p = 1; p <= 9; ++p) {
    for (int rational = 0; rational <= 1; ++rational) {
      const BSplineCurve curve = random_curve(random, p, 3, rational == 1, true);
      const Interval domain = curve.domain();
      // Ends inside blocks of every position, sorted and not.
      const std::vector<double> us{domain.lower, domain.upper, domain.lerp(0.5), domain.upper, domain.lower,
                                   domain.lerp(0.25), domain.upper, domain.upper, domain.lower};
      std::vector<double> out(us.size() * 3), first(us.size() * 3);
      points_at(curve, us, out);
      const auto& control = curve.control_points();
      const std::size_t last = control.size() - 1;
      for (std::size_t i = 0; i < us.size(); ++i) {
        const std::span<const double> expected = us[i] == domain.lower ? control[0] : control[last];
        if (us[i] != domain.lower && us[i] != domain.upper) continue;
        for (std::size_t c = 0; c < 3; ++c) expect_end(out[i * 3 + c], expected[c], rational == 1, p, i);
      }
      points_and_derivatives_at(curve, us, out, first);
      for (std::size_t i = 0; i < us.size(); ++i) {
        const std::span<const double> expected = us[i] == domain.lower ? control[0] : control[last];
        if (us[i] != domain.lower && us[i] != domain.upper) continue;
        for (std::size_t c = 0; c < 3; ++c) expect_end(out[i * 3 + c], expected[c], rational == 1, p, i);
      }
    }
  }
}

TEST(BSplinePointsAt, LargeSortedAndRandomBatches) {
  // Over 4 MiB of output: the streaming-store path, sorted and random.
  Random random{99u};
  for (int rational = 0; rational <= 1; ++rational) {
    const std::size_t count = 1000;
    std::vector<double> coordinates(count * 3);
    for (double& x : coordinates) x = 100.0 * random.unit();
    std::vector<double> weights;
    if (rational)
      for (std::size_t i = 0; i < count; ++i) weights.push_back(0.5 + random.unit());
    const BSplineCurve curve = *BSplineCurve::make(3, clamped_uniform_knots(3, count),
                                                   *PointArray::make(3, coordinates), weights);
    std::vector<double> us(180'001);
    for (std::size_t i = 0; i < us.size(); ++i) us[i] = static_cast<double>(i) / static_cast<double>(us.size() - 1);
    for (int pass = 0; pass < 2; ++pass) {
      if (pass == 1)
        for (std::size_t i = us.size(); i > 1; --i) std::swap(us[i - 1], us[random.next() % i]);
      std::vector<double> out(us.size() * 3 + 1), first(us.size() * 3 + 1);
      for (std::size_t shift : {0u, 1u}) {
        const std::span<double> o(out.data() + shift, us.size() * 3), f(first.data() + shift, us.size() * 3);
        points_and_derivatives_at(curve, us, o, f);
        std::size_t mismatches = 0;
        for (std::size_t i = 0; i < us.size(); i += 7) {
          const Point expected = point_at(curve, us[i]);
          const Point expected_derivative = derivative_at(curve, us[i], 1);
          for (std::size_t c = 0; c < 3; ++c)
            mismatches += !same_bits(o[i * 3 + c], expected[c]) || !same_bits(f[i * 3 + c], expected_derivative[c]);
        }
        EXPECT_EQ(mismatches, 0u) << "pass " << pass << " shift " << shift;
      }
    }
  }
}

// Streaming stores (outputs of 4 MiB and more, where the kernels bypass the
// cache) for every fixed kernel, not only the cubic in space above: degrees
// 1..7, dimensions 1..3, rational or not, points alone and with derivatives,
// each on just over 4 MiB of points, sorted (whole blocks in one span) and
// with every 13th parameter moved to another span (gathered blocks). Every
// 61st result and the first and last blocks against the scalar functions'
// bits.
TEST(BSplinePointsAt, EveryKernelStreamsTheSameBits) {
  Random random{5150u};
  constexpr std::size_t kBytes = (std::size_t{4} << 20) + 4096;
  for (int p = 1; p <= 7; ++p) {
    for (int d = 1; d <= 3; ++d) {
      for (int rational = 0; rational <= 1; ++rational) {
        const BSplineCurve curve = random_curve(random, p, d, rational == 1, true);
        const std::size_t dimension = static_cast<std::size_t>(d);
        const std::size_t count = kBytes / (sizeof(double) * dimension);
        const Interval domain = curve.domain();
        std::vector<double> us(count);
        for (std::size_t i = 0; i < count; ++i) us[i] = domain.lerp(static_cast<double>(i) / static_cast<double>(count - 1));
        for (std::size_t i = 0; i < count; i += 13) us[i] = domain.lerp(random.unit());
        std::vector<double> points(count * dimension), alone(count * dimension), first(count * dimension);
        points_and_derivatives_at(curve, us, points, first);
        points_at(curve, us, alone);
        std::size_t mismatches = 0;
        for (std::size_t i = 0; i < count; i += (i < 64 || i + 64 > count) ? 1 : 61) {
          const Point expected = point_at(curve, us[i]), derivative = derivative_at(curve, us[i], 1);
          for (std::size_t c = 0; c < dimension; ++c) {
            const std::size_t k = i * dimension + c;
            mismatches += !same_bits(points[k], expected[c]) || !same_bits(alone[k], expected[c]) ||
                          !same_bits(first[k], derivative[c]);
          }
        }
        EXPECT_EQ(mismatches, 0u) << "degree " << p << " dimension " << d << (rational ? " rational" : "");
      }
    }
  }
}

TEST(BSplinePointsAt, KnotsCloserThanTheReciprocalRange) {
  // Knot differences below 2^-1024 have no finite reciprocal: the scalar code
  // divides there, and the batch must give the same finite values. make()
  // refuses such spans (narrower than tolerances::kMinKnotSpan); a computed
  // curve (a knot inserted next to another) can still have them.
  const std::vector<double> knots{0, 0, 0, 0, 1e-310, 2e-310, 1, 1, 1, 1};
  const BSplineCurve curve = BSplineCurve::from_trusted(
      3, knots, *PointArray::make(2, {0, 0, 1, 2, 3, 1, 4, 4, 6, 0, 7, 3}));
  std::vector<double> us{0.0, 5e-311, 1e-310, 1.5e-310, 2e-310, 0.5, 1.0, 0.0, 3e-311, 1.2e-310, 1.7e-310};
  for (double u : us) {
    for (double c : point_at(curve, u)) EXPECT_TRUE(std::isfinite(c)) << u;
  }
  expect_batch_equals_scalar(curve, us);
  std::sort(us.begin(), us.end());
  expect_batch_equals_scalar(curve, us);
}

// The same for every fixed kernel (degrees 1..7, dimensions 1..3, rational
// or not, with derivatives or not, lanes in one span and gathered from
// several): a lane that comes out non-finite is recomputed by the scalar
// code, and the batch gives point_at's and derivative_at's bits.
TEST(BSplinePointsAt, EveryKernelRecomputesLanesInSpansBeyondTheReciprocalRange) {
  Random random{4242u};
  for (int p = 1; p <= 7; ++p) {
    std::vector<double> knots(static_cast<std::size_t>(p + 1), 0.0);
    knots.push_back(1e-310);
    knots.push_back(2e-310);
    knots.insert(knots.end(), static_cast<std::size_t>(p + 1), 1.0);
    const int count = p + 3;
    for (int d = 1; d <= 3; ++d) {
      for (int rational = 0; rational <= 1; ++rational) {
        std::vector<double> coordinates(static_cast<std::size_t>(count * d)), weights;
        for (double& x : coordinates) x = -10.0 + 20.0 * random.unit();
        if (rational == 1)
          for (int i = 0; i < count; ++i) weights.push_back(0.5 + random.unit());
        const BSplineCurve curve = BSplineCurve::from_trusted(p, knots, *PointArray::make(d, coordinates), weights);
        std::vector<double> us{0.0, 5e-311, 1e-310, 1.5e-310, 2e-310, 0.5, 1.0, 3e-311, 1.2e-310, 1.7e-310};
        for (int i = 0; i < 20; ++i) us.push_back(random.unit() * 3e-310);
        for (double u : us) {
          for (double c : point_at(curve, u)) ASSERT_TRUE(std::isfinite(c)) << p << ", " << d << ": " << u;
        }
        expect_batch_equals_scalar(curve, us);
        std::sort(us.begin(), us.end());
        expect_batch_equals_scalar(curve, us);
      }
    }
  }
}

// --- the scalar arithmetic against independent formulas ----------------------

/// sum |N_j| |R_j| and sum N_j R_j over the rows R_j (homogeneous if rational)
/// for derivative order k (0: the point), from The NURBS Book A2.3.
struct BasisSum {
  std::vector<double> value, magnitude;  // width entries each
};
BasisSum basis_sum(const BSplineCurve& curve, double u, int k) {
  const int p = curve.degree(), d = curve.dimension();
  const int width = curve.is_rational() ? d + 1 : d;
  const int span = find_span(curve.knots(), p, u);
  std::vector<double> ders(static_cast<std::size_t>((k + 1) * (p + 1)));
  basis_function_derivatives(curve.knots(), p, span, u, k, ders);
  BasisSum s{std::vector<double>(static_cast<std::size_t>(width)), std::vector<double>(static_cast<std::size_t>(width))};
  for (int j = 0; j <= p; ++j) {
    const std::size_t i = static_cast<std::size_t>(span - p + j);
    const double n = ders[static_cast<std::size_t>(k * (p + 1) + j)];
    const double w = curve.is_rational() ? curve.weights()[i] : 1.0;
    for (int c = 0; c < width; ++c) {
      const double r = c < d ? w * curve.control_points()[i][static_cast<std::size_t>(c)] : w;
      s.value[static_cast<std::size_t>(c)] += n * r;
      s.magnitude[static_cast<std::size_t>(c)] += std::abs(n) * std::abs(r);
    }
  }
  return s;
}

TEST(BSplinePointsAt, ScalarArithmeticAgreesWithTheBasisFunctionSums) {
  // Point: |C - sum N_j P_j| <= 16 eps * sum |N_j||P_j| (each side rounds
  // O(p) times; 16 ulps is far below any wrong answer). Derivative: the same
  // bound on A' against sum N'_j P_j, and for NURBS on C' = (A' - w' C)/w.
  constexpr double kEps = 0x1p-52;
  Random random{31337u};
  for (int p = 0; p <= 9; ++p) {
    for (int d = 1; d <= 3; ++d) {
      for (int rational = 0; rational <= 1; ++rational) {
        const BSplineCurve curve = random_curve(random, p, d, rational == 1, random.below(2) == 0);
        const Interval domain = curve.domain();
        for (int i = 0; i <= 50; ++i) {
          const double u = domain.lerp(i / 50.0);
          const BasisSum a = basis_sum(curve, u, 0);
          const BasisSum a1 = basis_sum(curve, u, std::min(1, p));
          const Point point = point_at(curve, u);
          const Point derivative = derivative_at(curve, u, 1);
          const double w = rational ? a.value[static_cast<std::size_t>(d)] : 1.0;
          const double w1 = rational && p > 0 ? a1.value[static_cast<std::size_t>(d)] : 0.0;
          for (int c = 0; c < d; ++c) {
            const std::size_t k = static_cast<std::size_t>(c);
            const double expected = a.value[k] / w;
            const double bound = 16 * p * kEps * (a.magnitude[k] + (rational ? a.magnitude[static_cast<std::size_t>(d)] * std::abs(expected) : 0.0)) / w + 1e-300;
            EXPECT_NEAR(point[k], expected, bound + 4 * kEps * std::abs(expected)) << "p " << p << " u " << u;
            if (p == 0) {
              EXPECT_EQ(derivative[k], 0.0);
              continue;
            }
            const double slope = (a1.value[k] - w1 * expected) / w;
            const double slope_bound =
                16 * p * kEps * (a1.magnitude[k] + std::abs(w1) * std::abs(expected) +
                                 (rational ? a1.magnitude[static_cast<std::size_t>(d)] * std::abs(expected) : 0.0)) / w;
            EXPECT_NEAR(derivative[k], slope, slope_bound + 4 * kEps * std::abs(slope)) << "p " << p << " u " << u;
          }
        }
      }
    }
  }
}

// points_at_within: the whole batch when every parameter is inside (the same
// bits as points_at), else the index of the first one outside, NaN or
// infinite, wherever it falls: the head before aligned streaming blocks, a
// streaming block, a plain block, the tail, and the scalar path (degree 8,
// dimension 4).
TEST(BSplinePointsAtWithin, StopsAtTheFirstParameterOutside) {
  Random random{2026u};
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  for (const auto& [p, d] : {std::pair{3, 3}, std::pair{2, 1}, std::pair{8, 4}}) {
    const BSplineCurve curve = random_curve(random, p, d, p == 2, true);
    const Interval domain = curve.domain();
    for (const std::size_t count : {std::size_t{5}, std::size_t{37}, std::size_t{200'003}}) {
      std::vector<double> us(count);
      for (std::size_t i = 0; i < count; ++i) us[i] = domain.lerp(static_cast<double>(i) / static_cast<double>(count));
      std::vector<double> out(count * static_cast<std::size_t>(d) + 1), reference(count * static_cast<std::size_t>(d));
      const std::span<double> shifted(out.data() + 1, count * static_cast<std::size_t>(d));  // not pack-aligned
      ASSERT_EQ(points_at_within(curve, us, domain, shifted), count);
      points_at(curve, us, reference);
      EXPECT_TRUE(std::equal(reference.begin(), reference.end(), shifted.begin(), same_bits)) << p << " " << count;
      for (const std::size_t at : {std::size_t{0}, std::size_t{3}, count / 2, count - 1}) {
        for (const double bad : {nan, inf, -inf, domain.upper + 1e-9 * domain.length(), domain.lower - 1.0}) {
          const double kept = us[at];
          us[at] = bad;
          EXPECT_EQ(points_at_within(curve, us, domain, shifted), at) << p << " " << count << " " << bad;
          us[at] = kept;
        }
      }
      // The finite check alone: outside the domain is allowed, NaN is not.
      const Interval finite{-std::numeric_limits<double>::max(), std::numeric_limits<double>::max()};
      us[count - 1] = domain.upper + 1.0;
      EXPECT_EQ(points_at_within(curve, us, finite, shifted), count);
      us[count - 1] = nan;
      EXPECT_EQ(points_at_within(curve, us, finite, shifted), count - 1);
    }
  }
}

}  // namespace
}  // namespace casteljau
