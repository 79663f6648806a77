// The Schoenberg–Whitney check that interpolation on given knots, the
// least-squares fits and the tolerance fit share (src/interpolation/
// collocation.hpp, schoenberg_whitney_gap):
// - a property against the condition's definition (Schoenberg & Whitney
//   1953; de Boor, A Practical Guide to Splines, ch. XIII): an increasing
//   choice of sites, one per basis function, where it does not vanish,
//   searched exhaustively by dynamic programming over (basis function, site)
//   with basis_function itself deciding "does not vanish";
// - for as many sites as basis functions, the gap is the first j with
//   N_j(s_j) = 0 and names that site;
// - the two wordings of the error.

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cstddef>
#include <optional>
#include <vector>

#include "../../src/interpolation/collocation.hpp"
#include "casteljau/bspline/basis.hpp"

namespace casteljau {
namespace {

/// Clamped knots of degree p on [0, 1], interior knots multiples of 1/16 (repeats allowed up to p).
rc::Gen<std::vector<double>> clamped_knots(int p) {
  return rc::gen::exec([p] {
    const int interior = *rc::gen::inRange(0, 8);
    std::vector<double> knots(static_cast<std::size_t>(p) + 1, 0.0);
    std::vector<int> grid = *rc::gen::container<std::vector<int>>(static_cast<std::size_t>(interior),
                                                                  rc::gen::inRange(1, 16));
    std::sort(grid.begin(), grid.end());
    int run = 0;
    for (std::size_t i = 0; i < grid.size(); ++i) {
      run = i > 0 && grid[i] == grid[i - 1] ? run + 1 : 1;
      if (run <= p) knots.push_back(grid[i] / 16.0);
    }
    knots.insert(knots.end(), static_cast<std::size_t>(p) + 1, 1.0);
    return knots;
  });
}

/// Whether the columns can take increasing usable sites where they do not vanish (exhaustive).
bool holds_by_definition(const std::vector<double>& knots, int p, const std::vector<std::size_t>& columns,
                         const std::vector<double>& sites, const std::vector<double>& weights) {
  const std::size_t m = sites.size();
  // previous[i]: columns 0..c-1 can take increasing sites with column c-1 at site i.
  std::vector<bool> previous(m, false), current(m);
  for (std::size_t c = 0; c < columns.size(); ++c) {
    bool reachable = c == 0;  // columns 0..c-1 fit on sites before i
    for (std::size_t i = 0; i < m; ++i) {
      const bool usable = weights.empty() || weights[i] > 0.0;
      current[i] = reachable && usable && basis_function(knots, p, static_cast<int>(columns[c]), sites[i]) != 0.0;
      if (c > 0 && previous[i]) reachable = true;  // sites after i may take column c
    }
    previous = current;
  }
  if (columns.empty()) return true;
  for (std::size_t i = 0; i < m; ++i)
    if (previous[i]) return true;
  return false;
}

RC_GTEST_PROP(SchoenbergWhitney, TheGreedyCheckAgreesWithTheDefinition, ()) {
  const int p = *rc::gen::inRange(1, 5);
  const std::vector<double> knots = *clamped_knots(p);
  const std::size_t n = knots.size() - static_cast<std::size_t>(p) - 1;  // basis functions
  // Distinct sites on a 1/32 grid of [0, 1], sometimes with zero weights.
  std::vector<int> grid = *rc::gen::unique<std::vector<int>>(rc::gen::inRange(0, 33));
  std::sort(grid.begin(), grid.end());
  std::vector<double> sites;
  for (const int g : grid) sites.push_back(g / 32.0);
  std::vector<double> weights;
  if (*rc::gen::arbitrary<bool>()) {
    for (std::size_t i = 0; i < sites.size(); ++i) weights.push_back(*rc::gen::element(0.0, 1.0, 2.0));
  }
  // All basis functions, or some left out (as derivative rows take them in interpolation).
  std::vector<std::size_t> columns;
  const bool all = *rc::gen::arbitrary<bool>();
  for (std::size_t j = 0; j < n; ++j)
    if (all || *rc::gen::arbitrary<bool>()) columns.push_back(j);

  const auto gap = detail::schoenberg_whitney_gap(knots, p, columns, sites, weights);
  RC_TAG(gap.has_value());
  RC_ASSERT(gap.has_value() == !holds_by_definition(knots, p, columns, sites, weights));
}

RC_GTEST_PROP(SchoenbergWhitney, AsManySitesAsBasisFunctionsNamesTheFirstVanishingPair, ()) {
  const int p = *rc::gen::inRange(1, 5);
  const std::vector<double> knots = *clamped_knots(p);
  const std::size_t n = knots.size() - static_cast<std::size_t>(p) - 1;
  std::vector<int> grid = *rc::gen::unique<std::vector<int>>(static_cast<std::size_t>(n), rc::gen::inRange(0, 33));
  std::sort(grid.begin(), grid.end());
  std::vector<double> sites;
  for (const int g : grid) sites.push_back(g / 32.0);
  std::vector<std::size_t> columns(n);
  for (std::size_t j = 0; j < n; ++j) columns[j] = j;
  std::optional<std::size_t> first;  // the first j with N_j(s_j) = 0
  for (std::size_t j = 0; j < n && !first; ++j)
    if (basis_function(knots, p, static_cast<int>(j), sites[j]) == 0.0) first = j;
  const auto gap = detail::schoenberg_whitney_gap(knots, p, columns, sites);
  RC_ASSERT(gap.has_value() == first.has_value());
  if (gap) {
    RC_ASSERT(gap->basis_function == *first);
    RC_ASSERT(gap->site == first);
  }
}

TEST(SchoenbergWhitney, ErrorsNameTheBasisFunctionItsSupportAndTheParameter) {
  const std::vector<double> knots = {0, 0, 0, 0, 2.25, 2.5, 2.625, 2.75, 7, 7, 7, 7};
  const std::vector<double> sites = {0, 1, 2, 3, 4, 5, 6, 7};
  const std::vector<std::size_t> columns = {0, 1, 2, 3, 4, 5, 6, 7};
  const auto gap = detail::schoenberg_whitney_gap(knots, 3, columns, sites);
  ASSERT_TRUE(gap.has_value());
  EXPECT_EQ(detail::schoenberg_whitney_error(knots, 3, sites, *gap, 0, false, "no spline interpolates them").message,
            "parameter 3 (3) is not inside the support [0, 2.75) of basis function 3: the knots and parameters "
            "violate the Schoenberg–Whitney condition, no spline interpolates them");
  // Fewer basis functions than sites: the one left without a point, counted from the caller's first row.
  const std::vector<double> fit_knots = {0, 0, 0, 0, 5.05, 5.1, 5.15, 5.2, 5.25, 7, 7, 7, 7};
  const std::vector<double> fit_sites = {0, 1, 2, 3, 4, 5, 6, 7};
  const std::vector<std::size_t> free = {1, 2, 3, 4, 5, 6, 7};
  const auto fit_gap = detail::schoenberg_whitney_gap(fit_knots, 3, free, fit_sites);
  ASSERT_TRUE(fit_gap.has_value());
  EXPECT_EQ(detail::schoenberg_whitney_error(fit_knots, 3, fit_sites, *fit_gap, 1, true, "singular").message,
            "no point of positive weight is left for basis function 4 (support [5.05, 5.25)): the knots and "
            "parameters violate the Schoenberg–Whitney condition, singular");
}

}  // namespace
}  // namespace casteljau
