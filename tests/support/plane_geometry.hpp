#pragma once
// Distances in the plane that figure tests measure drawn polylines with.

#include <algorithm>

#include "casteljau/core/vec.hpp"

namespace casteljau::test {

/// Distance from p to the segment [a, b] (to a when the segment is a point).
inline double distance_to_segment(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 ab = b - a;
  const double length2 = dot(ab, ab);
  const double u = length2 > 0.0 ? std::clamp(dot(p - a, ab) / length2, 0.0, 1.0) : 0.0;
  return distance(p, a + u * ab);
}

}  // namespace casteljau::test
