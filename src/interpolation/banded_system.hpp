#pragma once
// A banded linear system A x = B (A square, kl sub- and ku superdiagonals)
// solved by Gaussian elimination with partial pivoting inside the band: the
// unblocked algorithm of LAPACK's dgbtf2/dgbtrs (Golub & Van Loan, Matrix
// Computations, 4th ed., Algorithm 4.3.5 with pivoting, §4.3.5).
//
// Why ours: Eigen 3.4 has no banded solver (only dense and general sparse LU,
// whose symbolic analysis alone costs more than this whole solve for a
// tridiagonal system of 10^6 rows), and LAPACK is not available to the em++
// build of the core. The storage is LAPACK's band layout, so the algorithm
// reads like dgbtf2.
//
// Why pivoting: B-spline collocation matrices at sites that satisfy the
// Schoenberg–Whitney conditions are totally positive, and for those Gaussian
// elimination without pivoting is stable (de Boor & Pinkus 1977, "Backward
// error analysis for totally positive linear systems"; de Boor 1976). The
// rows for end derivatives (clamped, natural, prescribed derivatives) break
// total positivity, so we pivot like dgbtf2; the cost is kl extra
// superdiagonals of fill, still O(n kl (kl + ku)). When the matrix happens to
// be totally positive, partial pivoting picks the diagonal anyway in most
// rows and changes nothing.
//
// Internal to src/interpolation.

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace casteljau::detail {

/// A square banded matrix in LAPACK band storage with room for the fill of
/// partial pivoting: entry (r, c), c - ku <= r <= c + kl, lives at
/// storage[c * ld + kl + ku + r - c] with ld = 2 kl + ku + 1 (column major,
/// each column contiguous). Factored in place into P L U.
class BandedSystem {
 public:
  /// An n x n zero matrix with `lower` subdiagonals and `upper` superdiagonals.
  BandedSystem(std::size_t size, int lower, int upper);

  std::size_t size() const noexcept { return size_; }
  int lower() const noexcept { return lower_; }
  int upper() const noexcept { return upper_; }

  /// Entry (row, column); |row - column| inside the band (asserted).
  double& at(std::size_t row, std::size_t column) noexcept {
    return storage_[column * leading_ + static_cast<std::size_t>(lower_ + upper_) + row - column];
  }

  /// LU with partial pivoting inside the band (dgbtf2). Returns the first
  /// column whose pivot is exactly zero (the matrix is singular), or -1.
  /// O(n kl (kl + ku)).
  long factor();

  /// Solves A X = B in place after factor(): `rhs` holds n rows of `width`
  /// values each (row-major, the layout of a PointArray), all solved in one
  /// sweep (dgbtrs). O(n (2 kl + ku) width).
  void solve(std::span<double> rhs, std::size_t width) const;

 private:
  std::size_t size_;
  int lower_;
  int upper_;
  std::size_t leading_;
  std::vector<double> storage_;
  std::vector<std::uint32_t> pivots_;  // row swapped with row j; n < 2^32
};

}  // namespace casteljau::detail
