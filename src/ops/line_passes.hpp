#pragma once
// Internal to src/ops (intersection.cpp): a Bézier piece that lies within the
// tolerance of a straight line, as its position x(t) along the line, cut at
// its turning points into monotone passes. Pieces on a line are where the
// general intersection searches fail: every pair of points of two passes over
// one stretch is a "tangency" to them, thousands, slowly (issue 42's fuzzers:
// a cubic retracing a line, 4.8 s; a DXF arc whose pieces each run out and
// back along one chord, 4.9 s). On a line the question is one-dimensional:
// two passes overlap where their ranges of x do.
#include <optional>
#include <vector>

#include "casteljau/bezier/bezier_curve.hpp"
#include "casteljau/core/point_array.hpp"

namespace casteljau::detail {

/// A piece on a line: x(t) = X(t) / W(t) along the unit direction from the
/// origin (W = 1 for a polynomial piece), and the parameters 0 = c_0 < ... <
/// c_m = 1 between which it is monotone.
struct LinePasses {
  Point origin, direction;
  std::vector<double> weighted;  // the control points' x times their weights (x alone when polynomial)
  std::vector<double> weights;   // empty for a polynomial piece
  std::vector<double> cuts;

  /// The position along the line at parameter t.
  double x_at(double t) const;
  /// The parameter in pass [cuts[p], cuts[p + 1]] where x takes `value`
  /// (clamped to the pass's range): an end exactly when the value is the
  /// end's, else by bisection to the last bit.
  double parameter_of(std::size_t pass, double value) const;
};

/// The piece as passes along a line, when its control points (positive
/// weights: it lies in their hull) are all within `tolerance` of one: its own
/// line (through P_0 and the control point farthest from it), or `line`'s when
/// given. No value for a piece off the line, with a weight that is not
/// positive, or within the tolerance of one point.
std::optional<LinePasses> line_passes(const BezierCurve& piece, double tolerance, const LinePasses* line = nullptr);

/// Where two passes meet: an overlap from (s, t) to (s_end, t_end), or, when
/// their ranges only touch, the point (s, t).
struct PassContact {
  double s, t, s_end, t_end;
  bool overlap;
};

/// The overlaps of a piece's passes with one another (a fold covers stretches
/// of the line twice); passes that only touch (at a turning point) are not
/// contacts of a piece with itself.
std::vector<PassContact> self_overlaps(const LinePasses& piece, double tolerance);

/// Every contact of a pass of `a` with a pass of `b` (both on `a`'s line):
/// overlaps where their ranges share more than the tolerance, points where
/// they touch within it. s on a, t on b; overlaps run up in s.
std::vector<PassContact> pass_contacts(const LinePasses& a, const LinePasses& b, double tolerance);

}  // namespace casteljau::detail
