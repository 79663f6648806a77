// Roots of polynomials in Bernstein form against polynomials built from
// known roots: products of linear factors (t - r_i) converted exactly to the
// Bernstein basis (the product of degree-1 Bernstein polynomials with
// coefficients (-r, 1 - r), bernstein_product, is exact for dyadic r up to
// rounding of the binomial ratios), double and triple roots, roots at 0 and 1,
// a root cluster closer than the resolution, no roots.
#include "casteljau/bezier/bernstein_roots.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace casteljau {
namespace {

/// The coefficients of prod (t - r_i), times `scale`.
std::vector<double> from_roots(const std::vector<double>& roots, double scale = 1.0) {
  std::vector<double> p{scale};
  for (double r : roots) p = bernstein_product(p, std::vector<double>{-r, 1.0 - r});
  return p;
}

std::vector<double> ts(const std::vector<BernsteinRoot>& roots) {
  std::vector<double> out;
  for (const auto& r : roots) out.push_back(r.t);
  return out;
}

TEST(BernsteinRoots, SimpleRootsToFullPrecision) {
  const std::vector<double> roots{0.125, 0.3, 0.7, 0.9};
  const auto found = bernstein_roots(from_roots(roots));
  ASSERT_EQ(found.size(), roots.size());
  for (std::size_t i = 0; i < roots.size(); ++i) {
    EXPECT_NEAR(found[i].t, roots[i], 1e-15);
    EXPECT_EQ(found[i].multiplicity, 1);
  }
}

TEST(BernsteinRoots, RootsAtTheEndsAndOutside) {
  // Roots 0, 1 (exact zeros of b_0 and b_n), 0.5, and -1, 2 outside [0, 1].
  const auto found = bernstein_roots(from_roots({0.0, 0.5, 1.0, -1.0, 2.0}));
  EXPECT_EQ(ts(found), (std::vector<double>{0.0, 0.5, 1.0}));
  // A double root at 0 counts twice.
  const auto twice = bernstein_roots(from_roots({0.0, 0.0, 0.75}));
  ASSERT_EQ(twice.size(), 2u);
  EXPECT_EQ(twice[0].t, 0.0);
  EXPECT_EQ(twice[0].multiplicity, 2);
  EXPECT_NEAR(twice[1].t, 0.75, 1e-15);
}

TEST(BernsteinRoots, MultipleRootsAreReportedOnceWithTheirMultiplicity) {
  const auto found = bernstein_roots(from_roots({0.375, 0.375, 0.8}), 1e-12);
  ASSERT_EQ(found.size(), 2u);
  EXPECT_NEAR(found[0].t, 0.375, 1e-6);  // a double root is only known to sqrt(eps)
  EXPECT_EQ(found[0].multiplicity, 2);
  EXPECT_NEAR(found[1].t, 0.8, 1e-14);
  const auto triple = bernstein_roots(from_roots({0.6, 0.6, 0.6}), 1e-12);
  ASSERT_EQ(triple.size(), 1u);
  EXPECT_NEAR(triple[0].t, 0.6, 1e-4);
  EXPECT_GE(triple[0].multiplicity, 2);  // multiple; rounding blurs 2 and 3 apart
}

TEST(BernsteinRoots, NoRootsAndTheZeroPolynomial) {
  EXPECT_TRUE(bernstein_roots(std::vector<double>{1.0, 2.0, 0.5, 3.0}).empty());
  EXPECT_TRUE(bernstein_roots(from_roots({-0.5, 1.5})).empty());
  EXPECT_TRUE(bernstein_roots(std::vector<double>{0.0, 0.0, 0.0}).empty());
  EXPECT_TRUE(bernstein_roots(std::vector<double>{4.0}).empty());
  // (t - 1/2)^2 + 1e-6 > 0: two sign changes, no root; subdivision must see it.
  auto p = from_roots({0.5, 0.5});
  for (double& c : p) c += 1e-6;  // adding a constant adds it to every coefficient
  EXPECT_TRUE(bernstein_roots(p).empty());
}

RC_GTEST_PROP(BernsteinRoots, FindsEveryDistinctRootOfARandomProduct, ()) {
  // Roots on a 1/1024 grid inside (0, 1), at least 1/128 apart, and a few outside.
  auto inside = *rc::gen::unique<std::vector<int>>(*rc::gen::inRange(0, 7), rc::gen::inRange(1, 128));
  std::sort(inside.begin(), inside.end());
  std::vector<double> roots;
  for (int k : inside) roots.push_back(k / 128.0);
  std::vector<double> all = roots;
  for (int k = *rc::gen::inRange(0, 3); k > 0; --k) all.push_back(*rc::gen::element(-0.5, 1.25, 3.0));
  const double scale = *rc::gen::element(1e-3, 1.0, 1e4);
  const auto found = bernstein_roots(from_roots(all, scale));
  RC_ASSERT(found.size() == roots.size());
  // Up to 7 roots 1/128 apart: conditioned like Wilkinson's, known to ~1e-10.
  for (std::size_t i = 0; i < roots.size(); ++i) RC_ASSERT(std::abs(found[i].t - roots[i]) <= 1e-9);
}

RC_GTEST_PROP(BernsteinRoots, FindsATangencyAmongSimpleRoots, ()) {
  // A double root (a tangency: no sign change, rounding may lift it off the
  // axis) at a random grid point, simple roots at least 1/16 away from it.
  const double tangent = *rc::gen::inRange(4, 61) / 64.0;
  std::vector<double> simple;
  for (int k : *rc::gen::unique<std::vector<int>>(*rc::gen::inRange(0, 4), rc::gen::inRange(1, 16)))
    if (std::abs(k / 16.0 - tangent) >= 1.0 / 16) simple.push_back(k / 16.0);
  std::vector<double> all = simple;
  all.push_back(tangent);
  all.push_back(tangent);
  const auto found = bernstein_roots(from_roots(all, *rc::gen::element(1e-2, 1.0, 1e3)), 1e-12);
  RC_ASSERT(found.size() == simple.size() + 1);
  bool seen = false;
  for (const auto& root : found) {
    if (std::abs(root.t - tangent) <= 1e-6) {
      seen = true;
      RC_ASSERT(root.multiplicity >= 2);
    } else {
      RC_ASSERT(root.multiplicity == 1);
    }
  }
  RC_ASSERT(seen);
}

TEST(BernsteinRoots, ProductAndValueAgreeWithTheFactors) {
  const auto p = from_roots({0.2, 0.9}, 3.0);  // 3 (t - 0.2)(t - 0.9)
  for (double t : {0.0, 0.1, 0.5, 1.0}) EXPECT_NEAR(bernstein_value(p, t), 3 * (t - 0.2) * (t - 0.9), 1e-15);
}

}  // namespace
}  // namespace casteljau
