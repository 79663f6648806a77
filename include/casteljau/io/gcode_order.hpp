#pragma once
// The cutting order of a toolpath: which contour the tool cuts next and where
// it enters it, so that the rapid moves between contours are short (a path
// through the contours from the machine's zero: an open travelling-salesman
// tour). Greedy nearest neighbour over a k-d tree of the entry points, then
// 2-opt on neighbour lists, then each closed contour entered at its best
// joint; docs/formats.md, "G-code" (Order) says what and docs/cnc.md what it
// measures. write_gcode (io/gcode.hpp) calls cutting_order.

#include <span>
#include <vector>

#include "casteljau/core/tolerance.hpp"
#include "casteljau/io/gcode.hpp"

namespace casteljau {

/// Whether the contour ends where it starts, within the tolerance (it may
/// then be entered at any joint). An empty contour is not closed.
bool contour_is_closed(const GcodeContour& contour, Tolerance tolerance);

/// The contour run backwards: segments in reverse order, each from its end
/// to its start, bulge negated (the same arcs, turning the other way).
GcodeContour reversed_contour(const GcodeContour& contour);

/// Where the tool is after cutting the contour, entered at its front, in
/// `passes` passes: where it entered for a closed contour or an even number
/// of passes (an open contour is cut back and forth), else its end.
Vec2 contour_exit(const GcodeContour& contour, Tolerance tolerance, int passes);

/// The length in the plane of the rapid moves that cut the contours in this
/// order, each entered at its front, from the origin (empty ones skipped).
double rapid_length_of(std::span<const GcodeContour> order, Tolerance tolerance, int passes);

/// Greedy nearest neighbour from the origin: the contour with the entry point
/// nearest the tool next, a closed one rotated to start at that joint, an open
/// one reversed when that is its end; empty contours are left out. A k-d tree
/// of the entry points (J. L. Bentley, "Multidimensional binary search trees
/// used for associative searching", CACM 18, 1975) finds each in about
/// log(points) steps: O(p log p) for p joints in all, where the plain search
/// was O(contours x p). Of entries equally near, the first contour's first
/// (an open contour is then cut as drawn).
std::vector<GcodeContour> nearest_neighbour_order(std::span<const GcodeContour> contours, Tolerance tolerance,
                                                  int passes);

/// 2-opt (G. A. Croes, Operations Research 6, 1958) on an order from the
/// origin: reversing a run of contours (each one run the other way, which
/// for an open contour cut an odd number of times swaps its entry and exit)
/// where that shortens the rapid moves, trying only the moves that join a
/// contour to one of its tolerances::kGcodeTwoOptNeighbours nearest (neighbour
/// lists with a work queue, D. S. Johnson and L. A. McGeoch, "The traveling
/// salesman problem: a case study in local optimization", 1997: every
/// shortening 2-opt move makes one new edge shorter than the edge it
/// replaces, so a near neighbour stands at one of its ends), until no such
/// move shortens the tour. Then, in turn, every closed contour is rotated to
/// the joint, and every open one cut an even number of times (which leaves
/// the tool where it entered) is entered at the end, that makes the rapid
/// moves to it and on to the next entry shortest. Never lengthens the rapid
/// moves; empty contours are left out.
void improve_order(std::vector<GcodeContour>& order, Tolerance tolerance, int passes);

/// The order write_gcode cuts: nearest_neighbour_order then improve_order,
/// or the input's own order improved the same way when that is shorter (a
/// drawing may come in a good order already).
std::vector<GcodeContour> cutting_order(std::span<const GcodeContour> contours, Tolerance tolerance, int passes);

}  // namespace casteljau
