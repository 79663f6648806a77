#include "banded_qr.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

#include "casteljau/interpolation/tolerance.hpp"

namespace casteljau::detail {

void BandedQr::reset(std::size_t size, int half_bandwidth, std::size_t width) {
  size_ = size;
  band_ = static_cast<std::size_t>(half_bandwidth) + 1;
  width_ = width;
  r_.assign(size * band_, 0.0);
  rhs_.assign(size * width, 0.0);
  row_.resize(band_);
  target_.resize(width);
  last_first_ = 0;
}

namespace {

/// add_row's rotations (fpgivs, then fprota on the rest of the row and on the
/// right side) with the band and the width known at compile time where they
/// are a fit's (p + 1 = 3..6, d = 1..3; 0: read from `band` and `width`), so
/// that the short loops unroll (GCV rotates 3 · 10⁶ rows per λ on 10⁶ points).
template <std::size_t FixedBand, std::size_t FixedWidth>
void rotate_in(double* r, double* rhs, std::size_t size, std::size_t band, std::size_t width, std::size_t first,
               double* row, double* target) {
  if constexpr (FixedBand != 0) band = FixedBand;
  if constexpr (FixedWidth != 0) width = FixedWidth;
  for (std::size_t k = 0; k < band && first + k < size; ++k) {
    const double pivot = row[k];
    if (pivot == 0.0) continue;
    const std::size_t column = first + k;
    double* r_row = r + column * band;
    const double diagonal = r_row[0];
    // The rotation that zeroes the pivot against R's diagonal: the plain
    // root where the squares stay finite, hypot where they would not.
    double length = std::sqrt(diagonal * diagonal + pivot * pivot);
    if (!std::isfinite(length) || length == 0.0) length = std::hypot(diagonal, pivot);
    const double inverse = 1.0 / length;
    const double cosine = diagonal * inverse, sine = pivot * inverse;
    r_row[0] = length;
    const std::size_t end = std::min(band - k, size - column);
    for (std::size_t i = 1; i < end; ++i) {
      const double a = r_row[i], b = row[k + i];
      r_row[i] = cosine * a + sine * b;
      row[k + i] = cosine * b - sine * a;
    }
    double* z = rhs + column * width;
    for (std::size_t c = 0; c < width; ++c) {
      const double a = z[c], b = target[c];
      z[c] = cosine * a + sine * b;
      target[c] = cosine * b - sine * a;
    }
  }
}

template <std::size_t FixedBand>
void rotate_in_band(double* r, double* rhs, std::size_t size, std::size_t band, std::size_t width, std::size_t first,
                    double* row, double* target) {
  switch (width) {
    case 1: return rotate_in<FixedBand, 1>(r, rhs, size, band, width, first, row, target);
    case 2: return rotate_in<FixedBand, 2>(r, rhs, size, band, width, first, row, target);
    case 3: return rotate_in<FixedBand, 3>(r, rhs, size, band, width, first, row, target);
    default: return rotate_in<FixedBand, 0>(r, rhs, size, band, width, first, row, target);
  }
}

}  // namespace

void BandedQr::add_row(std::size_t first, std::span<const double> values, std::span<const double> target,
                       double scale) {
  assert(values.size() <= band_ && target.size() == width_ && first >= last_first_);
  last_first_ = first;
  for (std::size_t k = 0; k < band_; ++k) row_[k] = k < values.size() ? scale * values[k] : 0.0;
  for (std::size_t c = 0; c < width_; ++c) target_[c] = scale * target[c];
  double* const r = r_.data();
  double* const z = rhs_.data();
  switch (band_) {
    case 3: return rotate_in_band<3>(r, z, size_, band_, width_, first, row_.data(), target_.data());
    case 4: return rotate_in_band<4>(r, z, size_, band_, width_, first, row_.data(), target_.data());
    case 5: return rotate_in_band<5>(r, z, size_, band_, width_, first, row_.data(), target_.data());
    case 6: return rotate_in_band<6>(r, z, size_, band_, width_, first, row_.data(), target_.data());
    default: return rotate_in_band<0>(r, z, size_, band_, width_, first, row_.data(), target_.data());
  }
}

bool BandedQr::regular(std::span<const double> column_norms) const noexcept {
  assert(column_norms.size() == size_);
  for (std::size_t i = 0; i < size_; ++i) {
    const double pivot = r(i, i);
    if (!(pivot * pivot > tolerances::kFitSingularPivot * column_norms[i])) return false;
  }
  return true;
}

void BandedQr::solve(std::span<double> solution) const noexcept {
  assert(solution.size() == size_ * width_);
  for (std::size_t i = size_; i-- > 0;) {
    const std::size_t end = std::min(size_, i + band_);
    for (std::size_t c = 0; c < width_; ++c) {
      double value = rhs_[i * width_ + c];
      for (std::size_t j = i + 1; j < end; ++j) value -= r(i, j) * solution[j * width_ + c];
      solution[i * width_ + c] = value / r(i, i);
    }
  }
}

void BandedQr::factored_normal_matrix(SymmetricBand& factored) const {
  const int half_bandwidth = static_cast<int>(band_) - 1;
  if (factored.size() != size_ || factored.half_bandwidth() != half_bandwidth)
    factored = SymmetricBand(size_, half_bandwidth);
  for (std::size_t i = 0; i < size_; ++i) {
    const double diagonal = r(i, i);
    factored.at(i, i) = diagonal * diagonal;
    const std::size_t end = std::min(size_, i + band_);
    for (std::size_t j = i + 1; j < end; ++j) factored.at(j, i) = r(i, j) / diagonal;
  }
}

}  // namespace casteljau::detail
