#pragma once
// PointArray: n points of R^d, d >= 1 chosen at run time, stored row by row
// in one contiguous block (the layout of a C-ordered numpy (n, d) array).
// Control polygons, point sets read from CSV and polylines are PointArrays.

#include <cstddef>
#include <span>
#include <vector>

#include "casteljau/core/expected.hpp"
#include "casteljau/core/vec.hpp"

namespace casteljau {

/// A point of R^d returned by single-point evaluations (d coordinates).
/// Batch functions write into caller storage instead and never allocate.
using Point = std::vector<double>;

/// n points of R^d in one row-major block; a regular value.
class PointArray {
 public:
  PointArray() = default;

  /// Validated construction from a flat row-major block: d >= 1, size a multiple
  /// of d, every coordinate finite. Errors name the point and coordinate,
  /// e.g. "coordinate 1 of point 3 is NaN". `what` names the points in messages.
  static Expected<PointArray> make(int dimension, std::vector<double> coordinates,
                                   const char* what = "point");

  /// Validated construction from rows; all rows must have the same length
  /// ("point 2 has 3 coordinates, point 0 has 2").
  static Expected<PointArray> make(const std::vector<std::vector<double>>& rows,
                                   const char* what = "point");

  /// Unchecked construction for values produced by casteljau itself
  /// (asserts the shape; coordinates are trusted to be finite).
  static PointArray from_trusted(int dimension, std::vector<double> coordinates);

  /// n points of dimension d, all at the origin (d >= 1).
  static PointArray zeros(int dimension, std::size_t count);

  int dimension() const noexcept { return dimension_; }
  std::size_t size() const noexcept { return dimension_ == 0 ? 0 : coordinates_.size() / dimension_; }
  bool empty() const noexcept { return coordinates_.empty(); }

  /// Coordinates of point i (d values).
  std::span<const double> operator[](std::size_t i) const {
    return {coordinates_.data() + i * dimension_, static_cast<std::size_t>(dimension_)};
  }
  std::span<double> operator[](std::size_t i) {
    return {coordinates_.data() + i * dimension_, static_cast<std::size_t>(dimension_)};
  }
  /// Point i as a Vec<D>; requires D == dimension().
  template <int D>
  Vec<D> vec(std::size_t i) const { return Vec<D>::from((*this)[i]); }

  /// All coordinates, row-major (point 0's d values, then point 1's, ...).
  std::span<const double> coordinates() const noexcept { return coordinates_; }
  std::span<double> coordinates() noexcept { return coordinates_; }

  /// Appends one point (its size must be dimension()).
  void push_back(std::span<const double> point);

  friend bool operator==(const PointArray&, const PointArray&) = default;

 private:
  PointArray(int dimension, std::vector<double> coordinates)
      : dimension_(dimension), coordinates_(std::move(coordinates)) {}
  int dimension_ = 0;
  std::vector<double> coordinates_;
};

/// The largest absolute coordinate of the points: the scale that relative
/// tolerances and error reports are measured against (0 for the origin only).
double scale_of(const PointArray& points);

/// Euclidean distance between two points of the same dimension.
double distance(std::span<const double> a, std::span<const double> b);

/// Checks that a value read from outside is finite; the error names it:
/// "<what> is NaN" or "<what> is infinite".
Status check_finite(double value, const std::string& what);

}  // namespace casteljau
