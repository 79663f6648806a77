#pragma once
// Least squares on a banded design matrix by Givens rotations, row by row, as
// FITPACK does (Dierckx, "Curve and Surface Fitting with Splines", 1993,
// §4.1.2; its fpgivs and fprota): each row of p+1 entries (a data point's
// basis functions, or a penalty row) is rotated into an upper triangular band
// R of n rows and p+1 entries, its right side into Qᵀb. R x = Qᵀb then solves
// min ‖A x − b‖ with the error of the problem's condition number, where the
// normal equations AᵀA x = Aᵀb square it (issue 43: the seed's head with as
// many control points as points, κ = 3e6, is 0.43 of the scale off by the
// normal equations and 7.2e-10 by rotations).
//
// Why ours rather than Eigen: Eigen's dense HouseholderQR is O(m n²) and its
// SparseQR stores Q and permutes columns; the band of R, unpermuted, is what
// GCV's trace needs (RᵀR = L D Lᵀ with D_i = R_ii², the SymmetricBand of
// fit_banded.hpp), and rows arrive one at a time (10⁶ points) without forming
// the matrix. Internal to src/interpolation.

#include <cstddef>
#include <span>
#include <vector>

#include "fit_banded.hpp"

namespace casteljau::detail {

/// An upper triangular band R (n x n, p superdiagonals) and the rotated right
/// sides (n rows of `width` values), built from rows whose first columns do
/// not decrease. Then row j of R has no entry beyond the latest row's last
/// column, and a row's rotations stay within its p+1 columns (FITPACK's order:
/// data sorted by parameter); a row starting before an earlier one would fill
/// in to the last column. R's own rows are such rows: a penalized problem is
/// R's rows merged with the penalty rows by first column, whatever the number
/// of data points.
class BandedQr {
 public:
  BandedQr(std::size_t size, int half_bandwidth, std::size_t width)
      : size_(size), band_(static_cast<std::size_t>(half_bandwidth) + 1), width_(width),
        r_(size * band_, 0.0), rhs_(size * width, 0.0), row_(band_), target_(width) {}

  std::size_t size() const noexcept { return size_; }

  /// Empties the factorization for n columns, band p, `width` right-side
  /// values (the storage reused).
  void reset(std::size_t size, int half_bandwidth, std::size_t width);

  /// Row i of R: R_ii .. R_i,i+p (0 beyond column n − 1), and (Qᵀb)_i.
  std::span<const double> row(std::size_t i) const noexcept { return {r_.data() + i * band_, band_}; }
  std::span<const double> right_side(std::size_t i) const noexcept { return {rhs_.data() + i * width_, width_}; }

  /// Rotates the row a_j = values[j - first] (for columns first..first+p;
  /// columns at or beyond n must hold 0) with right side `target`, both
  /// multiplied by `scale`, into R and Qᵀb; `first` at least the previous
  /// row's. O(p² + p width).
  void add_row(std::size_t first, std::span<const double> values, std::span<const double> target, double scale);

  /// R_ii² > kFitSingularPivot · column_norms[i] for every i: the pivots of
  /// L D Lᵀ = RᵀR against the diagonal of AᵀA they came from (the test
  /// SymmetricBand::factor makes, so that both call the same systems singular).
  bool regular(std::span<const double> column_norms) const noexcept;

  /// x = R⁻¹ Qᵀb into `solution` (n rows of width values). Call regular() first.
  void solve(std::span<double> solution) const noexcept;

  /// RᵀR as L D Lᵀ in `factored` (made n x n, band p): L_ji = R_ij / R_ii,
  /// D_i = R_ii², what SymmetricBand::trace_of_inverse_times reads.
  void factored_normal_matrix(SymmetricBand& factored) const;

 private:
  double& r(std::size_t row, std::size_t column) noexcept { return r_[row * band_ + (column - row)]; }
  double r(std::size_t row, std::size_t column) const noexcept { return r_[row * band_ + (column - row)]; }

  std::size_t size_, band_, width_;
  std::vector<double> r_;    // row i: R_ii .. R_i,i+p
  std::vector<double> rhs_;  // row i: (Qᵀb)_i, width values
  std::vector<double> row_, target_;  // the row being rotated in
  std::size_t last_first_ = 0;        // the previous row's first column
};

}  // namespace casteljau::detail
