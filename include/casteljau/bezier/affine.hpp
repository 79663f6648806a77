#pragma once
// Affine maps x -> A x + b of R^d and their action on curves. Bézier curves
// (rational ones too) are affinely invariant: mapping the control points maps
// the curve (seed 000, 004 §2).

#include <vector>

#include "casteljau/bezier/bezier_curve.hpp"
#include "casteljau/core/expected.hpp"

namespace casteljau {

/// x -> A x + b with A a d x d matrix (row-major) and b in R^d.
struct AffineMap {
  int dimension = 0;
  std::vector<double> linear;       ///< A, row-major, d*d entries
  std::vector<double> translation;  ///< b, d entries

  /// Validates sizes and finiteness ("entry 4 of the linear part is NaN").
  static Expected<AffineMap> make(int dimension, std::vector<double> linear,
                                  std::vector<double> translation);
  /// The identity of R^d.
  static AffineMap identity(int dimension);
  /// x -> x + b.
  static AffineMap translate(std::vector<double> offset);
  /// x -> s x (uniform scaling about the origin).
  static AffineMap scale(int dimension, double factor);
  /// The plane rotation by `radians` about the origin (counter-clockwise).
  static AffineMap rotate_2d(double radians);
  /// The composition: (this after first)(x) = this(first(x)).
  AffineMap after(const AffineMap& first) const;
};

/// A x + b for one point (x.size() == map.dimension).
Point transformed_point(const AffineMap& map, std::span<const double> x);

/// Every point of the array mapped; error when the map's dimension is not the
/// points' ("the affine map acts on R^3, the curve lives in R^2"). What every
/// curve kind's transformed runs on its control points.
Expected<PointArray> transformed_points(const AffineMap& map, const PointArray& points);

/// The curve with every control point mapped (weights unchanged): the image of
/// the curve under the map. Error when the dimensions differ.
Expected<BezierCurve> transformed(const BezierCurve& curve, const AffineMap& map);

}  // namespace casteljau
