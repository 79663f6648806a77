// Banded LU with partial pivoting (LAPACK dgbtf2 / dgbtrs, unblocked).
#include "banded_system.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdint>
#include <utility>

namespace casteljau::detail {

BandedSystem::BandedSystem(std::size_t size, int lower, int upper)
    : size_(size),
      lower_(lower),
      upper_(upper),
      leading_(2 * static_cast<std::size_t>(lower) + static_cast<std::size_t>(upper) + 1),
      storage_(size * leading_, 0.0),
      pivots_(size, 0) {
  assert(lower >= 0 && upper >= 0 && size < (std::size_t{1} << 32));
}

namespace {

/// dgbtf2 with the band widths known at compile time (0, 0: at run time), so
/// that the loops of the tridiagonal and pentadiagonal systems of cubic
/// interpolation unroll. Returns the first zero-pivot column or -1.
template <std::size_t KL, std::size_t KU>
long factor_band(double* a, std::uint32_t* pivots, std::size_t n, std::size_t runtime_kl, std::size_t runtime_ku,
                 std::size_t ld) {
  const std::size_t kl = KL + KU == 0 ? runtime_kl : KL;
  const std::size_t ku = KL + KU == 0 ? runtime_ku : KU;
  // With pivoting, row j may take a row from up to kl below, whose entries
  // reach ku + kl columns to the right of the diagonal.
  const std::size_t kv = kl + ku;
  std::size_t last_touched = 0;  // ju of dgbtf2: the last column changed so far
  long singular_column = -1;
  for (std::size_t j = 0; j < n; ++j) {
    const std::size_t below = std::min(kl, n - 1 - j);
    double* const column = a + j * ld + kv;  // column[i] = A(j + i, j)
    std::size_t pivot = 0;
    double largest = std::abs(column[0]);
    for (std::size_t i = 1; i <= below; ++i) {
      const double value = std::abs(column[i]);
      if (value > largest) {
        largest = value;
        pivot = i;
      }
    }
    pivots[j] = static_cast<std::uint32_t>(j + pivot);
    if (!(largest > 0.0) || !std::isfinite(largest)) {
      if (singular_column < 0) singular_column = static_cast<long>(j);
      continue;
    }
    last_touched = std::max(last_touched, std::min(j + ku + pivot, n - 1));
    if (pivot != 0) {
      // Swap rows j and j + pivot over columns j..ju: A(r, c) sits at
      // a[c*ld + kv + r - c], so one row steps by ld - 1 between columns.
      for (std::size_t c = j; c <= last_touched; ++c) {
        double* const base = a + c * ld + kv - c;
        std::swap(base[j], base[j + pivot]);
      }
    }
    const double inverse = 1.0 / column[0];
    for (std::size_t i = 1; i <= below; ++i) column[i] *= inverse;
    // Rank-one update of the trailing band: A(j+i, c) -= l_i A(j, c).
    for (std::size_t c = j + 1; c <= last_touched; ++c) {
      double* const target = a + c * ld + kv + j - c;  // target[i] = A(j + i, c)
      const double top = target[0];
      if (top == 0.0) continue;
      for (std::size_t i = 1; i <= below; ++i) target[i] -= column[i] * top;
    }
  }
  return singular_column;
}

}  // namespace

long BandedSystem::factor() {
  const std::size_t kl = static_cast<std::size_t>(lower_), ku = static_cast<std::size_t>(upper_);
  double* const a = storage_.data();
  std::uint32_t* const pivots = pivots_.data();
  if (kl == 1 && ku == 1) return factor_band<1, 1>(a, pivots, size_, kl, ku, leading_);
  if (kl == 1 && ku == 2) return factor_band<1, 2>(a, pivots, size_, kl, ku, leading_);
  if (kl == 2 && ku == 1) return factor_band<2, 1>(a, pivots, size_, kl, ku, leading_);
  if (kl == 2 && ku == 2) return factor_band<2, 2>(a, pivots, size_, kl, ku, leading_);
  return factor_band<0, 0>(a, pivots, size_, kl, ku, leading_);
}

namespace {

/// dgbtrs for `Width` right-hand sides known at compile time (0: `width` at
/// run time): the inner loops over the coordinates unroll for d = 1, 2, 3.
template <std::size_t Width>
void solve_factored(const double* a, const std::uint32_t* pivots, std::size_t n, std::size_t kl, std::size_t kv,
                    std::size_t ld, double* b, std::size_t runtime_width) {
  const std::size_t width = Width == 0 ? runtime_width : Width;
  // L: apply each interchange, then eliminate below the pivot (dgbtrs).
  if (kl > 0) {
    for (std::size_t j = 0; j + 1 < n; ++j) {
      double* const row = b + j * width;
      if (pivots[j] != j) {
        double* const other = b + pivots[j] * width;
        for (std::size_t k = 0; k < width; ++k) std::swap(row[k], other[k]);
      }
      const std::size_t below = std::min(kl, n - 1 - j);
      const double* const column = a + j * ld + kv;
      for (std::size_t i = 1; i <= below; ++i) {
        const double l = column[i];
        double* const target = b + (j + i) * width;
        for (std::size_t k = 0; k < width; ++k) target[k] -= l * row[k];
      }
    }
  }
  // U (upper bandwidth kl + ku after the fill): back substitution by columns.
  for (std::size_t j = n; j-- > 0;) {
    const double* const column = a + j * ld + kv - j;  // column[r] = A(r, j)
    double* const row = b + j * width;
    const double inverse = 1.0 / column[j];
    for (std::size_t k = 0; k < width; ++k) row[k] *= inverse;
    const std::size_t top = j > kv ? j - kv : 0;
    for (std::size_t r = top; r < j; ++r) {
      const double u = column[r];
      if (u == 0.0) continue;
      double* const target = b + r * width;
      for (std::size_t k = 0; k < width; ++k) target[k] -= u * row[k];
    }
  }
}

}  // namespace

void BandedSystem::solve(std::span<double> rhs, std::size_t width) const {
  assert(rhs.size() == size_ * width);
  const std::size_t kl = static_cast<std::size_t>(lower_);
  const std::size_t kv = static_cast<std::size_t>(lower_ + upper_);
  const double* const a = storage_.data();
  switch (width) {
    case 1: solve_factored<1>(a, pivots_.data(), size_, kl, kv, leading_, rhs.data(), width); break;
    case 2: solve_factored<2>(a, pivots_.data(), size_, kl, kv, leading_, rhs.data(), width); break;
    case 3: solve_factored<3>(a, pivots_.data(), size_, kl, kv, leading_, rhs.data(), width); break;
    default: solve_factored<0>(a, pivots_.data(), size_, kl, kv, leading_, rhs.data(), width); break;
  }
}

}  // namespace casteljau::detail
