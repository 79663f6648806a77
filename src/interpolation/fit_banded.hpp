#pragma once
// A symmetric band matrix (half-bandwidth p) in lower band storage, and the
// band of the inverse of one held as L D Lᵀ (L unit lower triangular with p
// subdiagonals) by the recursion of Hutchinson & de Hoog (1985, "Smoothing
// noisy data with spline functions", Numer. Math. 47, eq. 2.6): the trace of
// the hat matrix that GCV needs. The fits of fit.cpp keep G = BᵀWB and Ω here
// and take L D Lᵀ = RᵀR from their QR factorization (banded_qr.hpp).
//
// Why ours rather than Eigen: Eigen 3.4 has band storage (BandMatrix) but no
// band factorization, and the trace needs the band of the inverse, computed
// from the entries of L and D themselves.
//
// Internal to src/interpolation.

#include <algorithm>
#include <cassert>
#include <cstddef>
#include <span>
#include <vector>


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

  /// Adds weight · v vᵀ for a row v of p+1 values over the columns first ..
  /// first + p (those at or beyond n ignored): a design or penalty row's
  /// share of BᵀWB or Ω.
  void add_outer_product(std::size_t first, std::span<const double> v, double weight) noexcept {
    for (std::size_t r = 0; r < v.size() && first + r < size_; ++r)
      for (std::size_t s = 0; s <= r; ++s) at(first + r, first + s) += weight * v[r] * v[s];
  }

  /// Σ_i a_ii: the trace.
  double trace() const noexcept {
    double sum = 0.0;
    for (std::size_t i = 0; i < size_; ++i) sum += at(i, i);
    return sum;
  }

  /// When this band holds A = L D Lᵀ (the strict lower band L, the diagonal
  /// D; BandedQr::factored_normal_matrix): tr(A⁻¹ B) = Σ_ij z_ij b_ij for a
  /// symmetric band matrix B of the same shape (the entries of Z = A⁻¹ outside the band meet zeros of
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
  std::size_t size_;
  std::size_t width_;
  std::vector<double> values_;
};

}  // namespace casteljau::detail
