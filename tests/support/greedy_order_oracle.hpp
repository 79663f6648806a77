#pragma once
// Greedy nearest-neighbour cutting order the plain way, the reference for
// io/gcode_order.hpp's k-d tree (tests/io/gcode_order_test.cpp) and the
// baseline beside it in bench/w11_gcode.cpp: at every step, every way into
// every contour left (a closed one at any joint, an open one at either end),
// the first of the nearest taken. Quadratic in the contours.

#include <cstddef>
#include <limits>
#include <span>
#include <vector>

#include "casteljau/core/tolerance.hpp"
#include "casteljau/io/gcode.hpp"

namespace casteljau::test {

/// The length of the rapid moves of that order from the origin, with
/// `passes` passes (an open contour cut an even number of times leaves the
/// tool where it entered); closed: ends within `tolerance`.
inline double plain_greedy_length(std::span<const GcodeContour> contours, Tolerance tolerance, int passes) {
  std::vector<char> done(contours.size(), 0);
  Vec2 tool{};
  double length = 0.0;
  for (std::size_t step = 0; step < contours.size(); ++step) {
    double best = std::numeric_limits<double>::infinity();
    Vec2 exit{};
    std::size_t chosen = 0;
    for (std::size_t c = 0; c < contours.size(); ++c) {
      if (done[c]) continue;
      const GcodeContour& contour = contours[c];
      const auto consider = [&](Vec2 in, Vec2 out) {
        if (distance(tool, in) < best) {
          best = distance(tool, in);
          exit = out;
          chosen = c;
        }
      };
      if (distance(contour.front().start, contour.back().end) <= tolerance.distance) {
        for (const ArcSegment& s : contour) consider(s.start, s.start);
      } else {
        consider(contour.front().start, passes % 2 == 0 ? contour.front().start : contour.back().end);
        consider(contour.back().end, passes % 2 == 0 ? contour.back().end : contour.front().start);
      }
    }
    done[chosen] = 1;
    length += best;
    tool = exit;
  }
  return length;
}

}  // namespace casteljau::test
