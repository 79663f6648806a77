#pragma once
// ControlNet: the (n+1) x (m+1) control points P_ij of a tensor-product
// surface, i along u (rows), j along v (columns), stored row by row in one
// PointArray: P_ij is point i*(m+1) + j (model JSON's control_points[i][j]).
#include <cstddef>
#include <span>
#include <utility>
#include <vector>
#include "casteljau/core/expected.hpp"
#include "casteljau/core/point_array.hpp"

namespace casteljau {

/// A rectangular net of points of R^d; a regular value. Built from outside
/// data only through make(), so a net is never ragged.
class ControlNet {
 public:
  ControlNet() = default;
  /// Validated construction from rows x columns points stored row by row:
  /// rows >= 1, columns >= 1, points.size() == rows * columns (the points are
  /// already a checked PointArray). The error names the shape: "a control net
  /// of 3 x 4 needs 12 points, found 11".
  static Expected<ControlNet> make(std::size_t rows, std::size_t columns, PointArray points);
  /// Validated construction from nested rows (control_points[i][j][c]): no
  /// empty net, no ragged row ("row 2 of the control net has 3 points, row 0
  /// has 4"), one dimension for every point ("control point [1][2] has 2
  /// coordinates, [0][0] has 3"), every coordinate finite ("coordinate 0 of
  /// control point [1][2] is NaN"), at most tolerances::kMaxControlPoints points.
  static Expected<ControlNet> make(const std::vector<std::vector<std::vector<double>>>& rows);
  /// For nets computed by casteljau itself (asserts the shape).
  static ControlNet from_trusted(std::size_t rows, std::size_t columns, PointArray points);

  /// n+1: the number of rows (points along u).
  std::size_t rows() const noexcept { return rows_; }
  /// m+1: the number of columns (points along v).
  std::size_t columns() const noexcept { return columns_; }
  /// d.
  int dimension() const noexcept { return points_.dimension(); }
  /// P_ij (d coordinates).
  std::span<const double> operator()(std::size_t i, std::size_t j) const& { return points_[i * columns_ + j]; }
  std::span<const double> operator()(std::size_t i, std::size_t j) const&& = delete;  // would dangle
  std::span<double> operator()(std::size_t i, std::size_t j) & { return points_[i * columns_ + j]; }
  /// All points, row by row.
  const PointArray& points() const& noexcept { return points_; }
  PointArray points() && noexcept { return std::move(points_); }

  friend bool operator==(const ControlNet&, const ControlNet&) = default;

 private:
  ControlNet(std::size_t rows, std::size_t columns, PointArray points)
      : rows_(rows), columns_(columns), points_(std::move(points)) {}
  std::size_t rows_ = 0;
  std::size_t columns_ = 0;
  PointArray points_;
};

/// The net with rows and columns exchanged: Q_ji = P_ij.
ControlNet transposed(const ControlNet& net);

}  // namespace casteljau
