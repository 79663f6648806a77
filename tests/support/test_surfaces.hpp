#pragma once
// Fixed surfaces that several tessellation tests measure on (the refinement
// test and the estimate's lower-bound test must see the same patch).
#include <vector>

#include "casteljau/surfaces/bezier_surface.hpp"

namespace casteljau::test {

/// A bicubic Bézier patch over [0,3] x [0,2] with a saddle and a hump:
/// x = 3u, y = 2v (control points at i, 2j/3), z from the table.
inline BezierSurface bicubic_patch() {
  const double z[4][4] = {{0, 0.5, 0, 0}, {0.5, 2, -1, 0}, {0, -1, 1.5, 0.3}, {0, 0, 0.3, 0}};
  std::vector<double> points;
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) points.insert(points.end(), {double(i), 2.0 * j / 3.0, z[i][j]});
  }
  return BezierSurface::from_trusted(ControlNet::from_trusted(4, 4, PointArray::from_trusted(3, points)));
}

}  // namespace casteljau::test
