#pragma once
// Linear systems solved exactly over the rationals (GMP): the reference that
// interpolation and fitting tests compare the library's floating-point
// solutions with.

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <cstddef>
#include <utility>
#include <vector>

namespace casteljau::test {

/// A matrix of rationals, row after row.
using RationalMatrix = std::vector<std::vector<mpq_class>>;

/// X with A X = B, A square (n x n) and invertible, B n x width, by
/// Gauss-Jordan elimination with exact arithmetic (any nonzero pivot is exact).
/// A singular A is a test failure, and gives an empty X.
inline RationalMatrix solve_exactly(RationalMatrix a, RationalMatrix b) {
  const std::size_t n = a.size();
  for (std::size_t col = 0; col < n; ++col) {
    std::size_t pivot = col;
    while (pivot < n && a[pivot][col] == 0) ++pivot;
    EXPECT_LT(pivot, n) << "exact system singular";
    if (pivot == n) return {};
    std::swap(a[pivot], a[col]);
    std::swap(b[pivot], b[col]);
    for (std::size_t row = 0; row < n; ++row) {
      if (row == col || a[row][col] == 0) continue;
      const mpq_class factor = a[row][col] / a[col][col];
      for (std::size_t k = col; k < n; ++k) a[row][k] -= factor * a[col][k];
      for (std::size_t k = 0; k < b[row].size(); ++k) b[row][k] -= factor * b[col][k];
    }
  }
  for (std::size_t row = 0; row < n; ++row)
    for (auto& value : b[row]) value /= a[row][row];
  return b;
}

}  // namespace casteljau::test
