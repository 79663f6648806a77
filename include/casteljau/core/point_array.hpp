#pragma once
// PointArray: n points of R^d, d >= 1 chosen at run time, stored row by row
// in one contiguous block (the layout of a C-ordered numpy (n, d) array).
// Control polygons, point sets read from CSV and polylines are PointArrays.

#include <compare>
#include <cstddef>
#include <iterator>
#include <span>
#include <type_traits>
#include <vector>

#include "casteljau/core/expected.hpp"
#include "casteljau/core/vec.hpp"

namespace casteljau {

/// A point of R^d returned by single-point evaluations (d coordinates).
/// Batch functions write into caller storage instead and never allocate.
using Point = std::vector<double>;

/// A random-access iterator over the points of a PointArray: each element
/// is a span of the point's d coordinates, pointing into the array (T is
/// `const double` or `double`).
template <class T>
class PointIterator {
 public:
  using iterator_category = std::random_access_iterator_tag;
  using iterator_concept = std::random_access_iterator_tag;
  using value_type = std::span<T>;
  using reference = std::span<T>;
  using difference_type = std::ptrdiff_t;

  PointIterator() = default;
  PointIterator(T* first, std::size_t dimension) noexcept : at_(first), dimension_(dimension) {}
  /// The const iterator from the mutable one.
  template <class U = T>
    requires(!std::is_const_v<U>)
  operator PointIterator<const U>() const noexcept { return {at_, dimension_}; }  // NOLINT: implicit by design

  std::span<T> operator*() const noexcept { return {at_, dimension_}; }
  std::span<T> operator[](difference_type n) const noexcept { return *(*this + n); }
  PointIterator& operator++() noexcept { at_ += dimension_; return *this; }
  PointIterator operator++(int) noexcept { PointIterator old = *this; ++*this; return old; }
  PointIterator& operator--() noexcept { at_ -= dimension_; return *this; }
  PointIterator operator--(int) noexcept { PointIterator old = *this; --*this; return old; }
  PointIterator& operator+=(difference_type n) noexcept {
    at_ += n * static_cast<difference_type>(dimension_);
    return *this;
  }
  PointIterator& operator-=(difference_type n) noexcept { return *this += -n; }
  friend PointIterator operator+(PointIterator i, difference_type n) noexcept { return i += n; }
  friend PointIterator operator+(difference_type n, PointIterator i) noexcept { return i += n; }
  friend PointIterator operator-(PointIterator i, difference_type n) noexcept { return i -= n; }
  /// The number of points between two iterators of one array (0 for an empty one).
  friend difference_type operator-(const PointIterator& a, const PointIterator& b) noexcept {
    return a.dimension_ == 0 ? 0 : (a.at_ - b.at_) / static_cast<difference_type>(a.dimension_);
  }
  friend bool operator==(const PointIterator& a, const PointIterator& b) noexcept { return a.at_ == b.at_; }
  friend std::strong_ordering operator<=>(const PointIterator& a, const PointIterator& b) noexcept {
    return a.at_ <=> b.at_;
  }

 private:
  T* at_ = nullptr;
  std::size_t dimension_ = 0;
};

/// n points of R^d in one row-major block; a regular value. Iterating it
/// gives each point as a span of d coordinates: `for (auto p : points)`.
/// Accessors that return a view into the array (operator[], coordinates,
/// begin/end) are deleted on a temporary, whose storage the view would outlive.
class PointArray {
 public:
  PointArray() = default;

  /// Validated construction from a flat row-major block: d >= 1, size a multiple
  /// of d, every coordinate finite. Errors name the point and coordinate,
  /// e.g. "coordinate 1 of point 3 is NaN". `what` names the points in messages.
  static Expected<PointArray> make(int dimension, std::vector<double> coordinates,
                                   const char* what = "point");

  /// Validated construction from rows; all rows must have the same length
  /// ("point 2 has 3 coordinates, point 0 has 2"). No rows is refused: they
  /// give no dimension (an empty set of dimension d is make(d, {})).
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
  std::span<const double> operator[](std::size_t i) const& {
    return {coordinates_.data() + i * dimension_, static_cast<std::size_t>(dimension_)};
  }
  std::span<double> operator[](std::size_t i) & {
    return {coordinates_.data() + i * dimension_, static_cast<std::size_t>(dimension_)};
  }
  std::span<const double> operator[](std::size_t i) const&& = delete;  // a view into a temporary dangles
  /// Point i as a Vec<D>; requires D == dimension().
  template <int D>
  Vec<D> vec(std::size_t i) const { return Vec<D>::from((*this)[i]); }

  /// All coordinates, row-major (point 0's d values, then point 1's, ...).
  std::span<const double> coordinates() const& noexcept { return coordinates_; }
  std::span<double> coordinates() & noexcept { return coordinates_; }
  std::span<const double> coordinates() const&& = delete;  // a view into a temporary dangles

  /// The points in order, each a span of d coordinates.
  using iterator = PointIterator<double>;
  using const_iterator = PointIterator<const double>;
  const_iterator begin() const& noexcept { return {coordinates_.data(), static_cast<std::size_t>(dimension_)}; }
  const_iterator end() const& noexcept {
    return {coordinates_.data() + coordinates_.size(), static_cast<std::size_t>(dimension_)};
  }
  iterator begin() & noexcept { return {coordinates_.data(), static_cast<std::size_t>(dimension_)}; }
  iterator end() & noexcept {
    return {coordinates_.data() + coordinates_.size(), static_cast<std::size_t>(dimension_)};
  }
  const_iterator begin() const&& = delete;  // a view into a temporary dangles
  const_iterator end() const&& = delete;  // a view into a temporary dangles

  /// Appends one point (its size must be dimension()).
  void push_back(std::span<const double> point);

  friend bool operator==(const PointArray&, const PointArray&) = default;

 private:
  PointArray(int dimension, std::vector<double> coordinates)
      : dimension_(dimension), coordinates_(std::move(coordinates)) {}
  int dimension_ = 0;
  std::vector<double> coordinates_;
};

static_assert(std::random_access_iterator<PointArray::const_iterator>);
static_assert(std::random_access_iterator<PointArray::iterator>);

/// The largest absolute coordinate of the points: the scale that relative
/// tolerances and error reports are measured against (0 for the origin only).
double scale_of(const PointArray& points);

/// Euclidean distance between two points of the same dimension.
double distance(std::span<const double> a, std::span<const double> b);

/// Checks that a value read from outside is finite; the error names it:
/// "<what> is NaN" or "<what> is infinite".
Status check_finite(double value, const std::string& what);

}  // namespace casteljau
