// ControlNet: validation of rectangular nets and the transpose.
#include "casteljau/surfaces/control_net.hpp"

#include <cassert>
#include <string>
#include <utility>

#include "casteljau/core/tolerance.hpp"

namespace casteljau {
namespace {

std::string index_text(std::size_t i, std::size_t j) {
  return "[" + std::to_string(i) + "][" + std::to_string(j) + "]";
}

}  // namespace

Expected<ControlNet> ControlNet::make(std::size_t rows, std::size_t columns, PointArray points) {
  if (rows == 0 || columns == 0) {
    return Error{"a control net of " + std::to_string(rows) + " x " + std::to_string(columns) +
                 " is empty, it needs at least one row and one column"};
  }
  if (rows > tolerances::kMaxControlPoints / columns) {
    return Error{"a control net of " + std::to_string(rows) + " x " + std::to_string(columns) +
                 " has more control points than the limit " + std::to_string(tolerances::kMaxControlPoints)};
  }
  if (points.size() != rows * columns) {
    return Error{"a control net of " + std::to_string(rows) + " x " + std::to_string(columns) + " needs " +
                 std::to_string(rows * columns) + " points, found " + std::to_string(points.size())};
  }
  return ControlNet(rows, columns, std::move(points));
}

Expected<ControlNet> ControlNet::make(const std::vector<std::vector<std::vector<double>>>& rows) {
  if (rows.empty()) return Error{"the control net has no rows"};
  if (rows[0].empty()) return Error{"row 0 of the control net has no points"};
  const std::size_t columns = rows[0].size();
  for (std::size_t i = 1; i < rows.size(); ++i) {
    if (rows[i].size() != columns) {
      return Error{"row " + std::to_string(i) + " of the control net has " + std::to_string(rows[i].size()) +
                   " points, row 0 has " + std::to_string(columns)};
    }
  }
  if (rows.size() > tolerances::kMaxControlPoints / columns) {
    return Error{"a control net of " + std::to_string(rows.size()) + " x " + std::to_string(columns) +
                 " has more control points than the limit " + std::to_string(tolerances::kMaxControlPoints)};
  }
  const std::size_t d = rows[0][0].size();
  if (d == 0) return Error{"control point [0][0] has no coordinates"};
  std::vector<double> coordinates;
  coordinates.reserve(rows.size() * columns * d);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    for (std::size_t j = 0; j < columns; ++j) {
      const std::vector<double>& point = rows[i][j];
      if (point.size() != d) {
        return Error{"control point " + index_text(i, j) + " has " + std::to_string(point.size()) +
                     " coordinates, [0][0] has " + std::to_string(d)};
      }
      for (std::size_t c = 0; c < d; ++c) {
        if (auto ok = check_finite(point[c], "coordinate " + std::to_string(c) + " of control point " +
                                                 index_text(i, j));
            !ok) {
          return ok.error();
        }
        coordinates.push_back(point[c]);
      }
    }
  }
  return ControlNet(rows.size(), columns, PointArray::from_trusted(static_cast<int>(d), std::move(coordinates)));
}

ControlNet ControlNet::from_trusted(std::size_t rows, std::size_t columns, PointArray points) {
  assert(rows >= 1 && columns >= 1 && points.size() == rows * columns);
  return ControlNet(rows, columns, std::move(points));
}

ControlNet transposed(const ControlNet& net) {
  const std::size_t rows = net.rows(), columns = net.columns();
  const std::size_t d = static_cast<std::size_t>(net.dimension());
  std::vector<double> coordinates(rows * columns * d);
  for (std::size_t i = 0; i < rows; ++i) {
    for (std::size_t j = 0; j < columns; ++j) {
      const auto point = net(i, j);
      for (std::size_t c = 0; c < d; ++c) coordinates[(j * rows + i) * d + c] = point[c];
    }
  }
  return ControlNet::from_trusted(columns, rows,
                                  PointArray::from_trusted(static_cast<int>(d), std::move(coordinates)));
}

}  // namespace casteljau
