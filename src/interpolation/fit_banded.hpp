#pragma once
// A symmetric positive definite band matrix (half-bandwidth p), factored in
// place as L D Lᵀ (L unit lower triangular with p subdiagonals), with the
// band of its inverse by the recursion of Hutchinson & de Hoog (1985,
// "Smoothing noisy data with spline functions", Numer. Math. 47, eq. 2.6).
// The normal equations of every fit in fit.cpp are of this kind.
//
// Why ours rather than Eigen: Eigen 3.4 has band storage (BandMatrix) but no
// band factorization; its sparse LDLᵀ (SimplicialLDLT) would solve the system
// in O(n p²) too, but the trace of the hat matrix needs the band of the
// inverse, which is computed from the entries of L and D themselves, and a
// sparse factor (column-compressed, possibly permuted) makes that recursion
// awkward and slower. LDLᵀ without pivoting is stable for symmetric positive
// definite matrices (Golub & Van Loan, Matrix Computations, 4th ed., §4.2,
// §4.3.6, Algorithm 4.3.6 in its LDLᵀ form); no square roots, so the
// recursion reads D directly.
//
// Internal to src/interpolation.

#include <algorithm>
#include <cassert>
#include <cstddef>
#include <span>
#include <vector>

#include "casteljau/interpolation/tolerance.hpp"


namespace casteljau::detail {

/// Lower band of a symmetric n x n matrix: entry (i, j) with i - p <= j <= i
/// at values[i (p+1) + (j - i + p)], so each row's band is contiguous in j.
class SymmetricBand {
 public:
  SymmetricBand(std::size_t size, int half_bandwidth)
      : size_(size), width_(static_cast<std::size_t>(half_bandwidth) + 1), values_(size * width_, 0.0) {}

  std::size_t size() const noexcept { return size_; }
  int half_bandwidth() const noexcept { return static_cast<int>(width_) - 1; }

  /// Entry (row, column) of the lower band: column <= row <= column + p (asserted).
  double& at(std::size_t row, std::size_t column) noexcept {
    assert(column <= row && row - column < width_);
    return values_[row * width_ + (column + width_ - 1 - row)];
  }
  double at(std::size_t row, std::size_t column) const noexcept {
    assert(column <= row && row - column < width_);
    return values_[row * width_ + (column + width_ - 1 - row)];
  }

  /// The first column of the band of row i (max(0, i - p)).
  std::size_t first_column(std::size_t row) const noexcept { return row + 1 >= width_ ? row + 1 - width_ : 0; }
  /// The last row of the band of column j (min(n - 1, j + p)).
  std::size_t last_row(std::size_t column) const noexcept { return std::min(size_ - 1, column + width_ - 1); }

  /// Σ_i a_ii: the trace.
  double trace() const noexcept {
    double sum = 0.0;
    for (std::size_t i = 0; i < size_; ++i) sum += at(i, i);
    return sum;
  }

  /// In place: the strict lower band becomes L, the diagonal D, with
  /// A = L D Lᵀ. False (the matrix left half-factored) when a pivot D_i is
  /// not above tolerances::kFitSingularPivot times the diagonal entry it came
  /// from (or is NaN): the matrix is singular to working precision.
  /// O(n p²).
  bool factor() noexcept { return factor_rows(nullptr, nullptr, 0.0); }

  /// The same for A = a + factor * b (a and b of one size and bandwidth),
  /// each row formed just before it is factored, in this matrix's storage
  /// (reused: no allocation once its size is reached). One pass over a, b
  /// and the result instead of a sum and then a factorization.
  bool factor_sum(const SymmetricBand& a, const SymmetricBand& b, double factor) {
    assert(a.size_ == b.size_ && a.width_ == b.width_);
    size_ = a.size_;
    width_ = a.width_;
    values_.resize(a.values_.size());
    return factor_rows(&a, &b, factor);
  }

  /// Solves A X = B after factor(): `rhs` holds n rows of `width` values
  /// (row-major, a PointArray's layout), overwritten by X. O(n p width).
  void solve(std::span<double> rhs, std::size_t width) const noexcept {
    assert(rhs.size() == size_ * width);
    // Each unknown is accumulated in a register, column by column (the same
    // operations in the same order as updating it in memory, without the
    // store-to-load chain that would make each step wait for the last).
    for (std::size_t i = 0; i < size_; ++i) {  // L y = b
      const std::size_t low = first_column(i);
      for (std::size_t c = 0; c < width; ++c) {
        double value = rhs[i * width + c];
        for (std::size_t k = low; k < i; ++k) value -= at(i, k) * rhs[k * width + c];
        rhs[i * width + c] = value;
      }
    }
    for (std::size_t i = 0; i < size_; ++i) {  // D z = y
      const double inverse = 1.0 / at(i, i);
      for (std::size_t c = 0; c < width; ++c) rhs[i * width + c] *= inverse;
    }
    for (std::size_t i = size_; i-- > 0;) {  // Lᵀ x = z
      const std::size_t high = last_row(i);
      for (std::size_t c = 0; c < width; ++c) {
        double value = rhs[i * width + c];
        for (std::size_t k = i + 1; k <= high; ++k) value -= at(k, i) * rhs[k * width + c];
        rhs[i * width + c] = value;
      }
    }
  }

  /// After factor(): tr(A⁻¹ B) = Σ_ij z_ij b_ij for a symmetric band matrix B
  /// of the same shape (the entries of Z = A⁻¹ outside the band meet zeros of
  /// B). The band of Z comes from Lᵀ Z = D⁻¹ L⁻¹, whose right side is lower
  /// triangular with diagonal 1/D_i: the upper part of each row i of Z needs
  /// only rows below it,
  ///   z_ij = δ_ij / D_i − Σ_{k=i+1..i+p} l_ki z_kj,   j = i+p, ..., i,
  /// and every z_kj it reads lies in the band (|k − j| < p) of the p columns
  /// after i (Hutchinson & de Hoog 1985, eq. 2.6). Columns run from n−1 down
  /// and only the latest p+1 are kept, so Z is never stored: O(n p²) time,
  /// O(p²) memory, one read of L and B.
  double trace_of_inverse_times(const SymmetricBand& other) const {
    assert(other.size_ == size_ && other.width_ == width_);
    const std::size_t w = width_;
    // Column c of Z's band, z(c..c+p, c), in slot c mod (p+1); start[r] is
    // where column i + r starts while column i is computed.
    std::vector<double> ring(w * w, 0.0);
    std::vector<std::size_t> start(w);
    std::size_t i_slot = 0;  // i mod (p+1)
    const auto z = [&](std::size_t row, std::size_t column, std::size_t i) -> double& {
      return ring[start[column - i] + (row - column)];
    };
    double trace = 0.0;
    for (std::size_t i = size_; i-- > 0;) {
      i_slot = i % w;
      for (std::size_t r = 0; r < w; ++r) start[r] = (i_slot + r < w ? i_slot + r : i_slot + r - w) * w;
      const std::size_t high = last_row(i);
      for (std::size_t j = high + 1; j-- > i;) {
        double sum = j == i ? 1.0 / at(i, i) : 0.0;
        for (std::size_t k = i + 1; k <= high; ++k) sum -= at(k, i) * (k >= j ? z(k, j, i) : z(j, k, i));
        z(j, i, i) = sum;
      }
      trace += z(i, i, i) * other.at(i, i);
      for (std::size_t j = i + 1; j <= high; ++j) trace += 2.0 * z(j, i, i) * other.at(j, i);
    }
    return trace;
  }

 private:
  /// factor() and factor_sum(): row i (from a + factor b when given) is
  /// factored with the rows above it, which are done.
  bool factor_rows(const SymmetricBand* a, const SymmetricBand* b, double factor) noexcept {
    std::vector<double> scaled(width_);  // L_ik D_k for the current row
    for (std::size_t i = 0; i < size_; ++i) {
      if (a != nullptr) {
        const std::size_t row = i * width_;
        for (std::size_t k = row; k < row + width_; ++k) values_[k] = a->values_[k] + factor * b->values_[k];
      }
      const std::size_t low = first_column(i);
      for (std::size_t j = low; j < i; ++j) {
        double sum = at(i, j);
        for (std::size_t k = low; k < j; ++k) sum -= scaled[k - low] * at(j, k);
        scaled[j - low] = sum;          // L_ij D_j
        at(i, j) = sum / at(j, j);      // L_ij
      }
      const double diagonal = at(i, i);
      double pivot = diagonal;
      for (std::size_t k = low; k < i; ++k) pivot -= scaled[k - low] * at(i, k);
      if (!(pivot > tolerances::kFitSingularPivot * diagonal)) return false;
      at(i, i) = pivot;
    }
    return true;
  }

  std::size_t size_;
  std::size_t width_;
  std::vector<double> values_;
};

}  // namespace casteljau::detail
