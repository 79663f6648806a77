#pragma once
// What the IGES and STEP writers share (io/cad_exchange.hpp): every model as
// the one form both formats hold, a B-spline curve or surface in R^3 with its
// whole knot vectors and a weight per control point, and their numbers
// written as reals with a decimal point. Internal to src/io/.

#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "casteljau/core/expected.hpp"
#include "casteljau/core/interval.hpp"
#include "casteljau/io/model.hpp"

namespace casteljau::detail {

/// A B-spline or NURBS curve in R^3 (a plane curve at z = 0), as IGES entity
/// 126 and STEP's B_SPLINE_CURVE_WITH_KNOTS hold it.
struct ExchangeCurve {
  int degree = 0;
  std::vector<double> knots;    ///< all n + p + 2 of them, as the model has them
  std::vector<double> points;   ///< x y z per control point
  std::vector<double> weights;  ///< one per control point (1 when polynomial)
  bool rational = false;
  Interval domain{0.0, 1.0};
  bool closed = false;     ///< the end point equals the start point, bit for bit
  int plane_axis = -1;     ///< 0, 1 or 2 when every control point has that coordinate equal, else -1
};

/// A B-spline or NURBS surface in R^3, control point (i, j) at i * columns + j
/// with i along u (the rows of ControlNet).
struct ExchangeSurface {
  int degree_u = 0, degree_v = 0;
  std::vector<double> knots_u, knots_v;
  std::size_t rows = 0, columns = 0;
  std::vector<double> points;   ///< x y z per control point, rows first
  std::vector<double> weights;  ///< one per control point (1 when polynomial)
  bool rational = false;
  Interval domain_u{0.0, 1.0}, domain_v{0.0, 1.0};
  bool closed_u = false, closed_v = false;  ///< first and last rows (columns) equal, weights included
};

/// The models to write, in their B-spline form (to_bspline: exact) with
/// clamped knots (clamped: the same curve, its points within rounding), in
/// the models' order (item i is model i). Errors name the model
/// ("<format>: model 2 lives in R^4, <format> holds plane and space
/// geometry") and pass on to_bspline's (pieces that do not meet, a Coons
/// patch with a rational boundary); an empty list is refused too.
struct ExchangeGeometry {
  std::vector<std::variant<ExchangeCurve, ExchangeSurface>> items;
  bool has_surfaces = false;
  double largest_coordinate = 0.0;  ///< max |x|, |y|, |z| over every control point
  double size = 0.0;                ///< the diagonal of the box of every control point
};
Expected<ExchangeGeometry> exchange_geometry(std::span<const Model> models, const char* format);

/// The distinct values of a knot vector and their multiplicities (STEP).
struct DistinctKnots {
  std::vector<double> values;
  std::vector<int> multiplicities;
};
DistinctKnots distinct_knots(std::span<const double> knots);

/// The 14 digits YYYYMMDDHHMMSS of a timestamp "YYYY-MM-DDTHH:MM:SS"
/// (ExchangeHeader::timestamp), or an error naming it when it is not of that form.
Expected<std::string> timestamp_digits(std::string_view timestamp);

/// A real as both formats want it: the shortest digits that read back as the
/// same double, always with a decimal point ("1.", "0.5", "1.E-05",
/// "-2.5E+100"), -0 as "0.".
std::string exchange_real(double value);

}  // namespace casteljau::detail
