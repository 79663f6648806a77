#pragma once
// Interval: a closed parameter interval, the domain of a curve ([0,1] for a
// Bézier curve, [t_p, t_{n+1}] for a B-spline) or of one surface direction.

namespace casteljau {

/// A closed parameter interval [lower, upper] (lower <= upper).
struct Interval {
  double lower = 0.0;
  double upper = 1.0;
  /// lower + f (upper - lower): f = 0 gives lower, f = 1 gives upper exactly.
  double lerp(double f) const { return f == 1.0 ? upper : lower + f * (upper - lower); }
  /// upper - lower.
  double length() const { return upper - lower; }
  /// lower <= u <= upper (false for NaN).
  bool contains(double u) const { return lower <= u && u <= upper; }
  /// u moved into [lower, upper] (NaN stays NaN).
  double clamp(double u) const { return u < lower ? lower : (u > upper ? upper : u); }
  friend bool operator==(const Interval&, const Interval&) = default;
};

}  // namespace casteljau
