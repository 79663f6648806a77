#pragma once
// Curves and surfaces written for CAD systems: IGES 5.3 (entities 126 and
// 128) and STEP AP214 (ISO 10303-21 files of B_SPLINE_CURVE_WITH_KNOTS and
// B_SPLINE_SURFACE_WITH_KNOTS). Both are exact: every model is written in its
// B-spline form (to_bspline: a Bézier curve or surface on clamped knots, a
// piecewise curve with its joints as knots, a Coons patch as its tensor
// product), knots, control points and weights as they are, each number in
// the shortest form that reads back as the same double. Plane models are
// written at z = 0. Checked by OpenCASCADE's readers (tests/exchange/).
// docs/formats.md, "IGES and STEP", says what each file holds.

#include <span>
#include <string>

#include "casteljau/core/expected.hpp"
#include "casteljau/io/model.hpp"

namespace casteljau {

/// The length unit a CAD file states for its numbers (both formats require
/// one; the numbers are written unchanged, never scaled).
enum class ExchangeUnit { millimetre, inch };

/// What an exchange file says about itself besides the geometry.
struct ExchangeHeader {
  std::string file_name = "casteljau";  ///< the name the file states for itself (IGES global 4, STEP FILE_NAME)
  /// When it was written, UTC, "YYYY-MM-DDTHH:MM:SS" (ISO 8601, as STEP's
  /// FILE_NAME has it; IGES gets the same instant as 15HYYYYMMDD.HHNNSS).
  std::string timestamp = "2000-01-01T00:00:00";
  std::string author;        ///< IGES global 21, STEP FILE_NAME's author
  std::string organization;  ///< IGES global 22, STEP FILE_NAME's organization
  ExchangeUnit unit = ExchangeUnit::millimetre;
};

/// An IGES 5.3 file (US PRO/IPO-100, 1996): Start, Global, Directory Entry,
/// Parameter Data and Terminate sections of 80-column records; each curve a
/// rational B-spline curve (entity 126, form 0: planar flag and normal, closed
/// flag, polynomial flag, knots, weights, control points, the parameter
/// range), each surface a rational B-spline surface (entity 128, form 0),
/// weights 1 and the polynomial flag set when the model has none. Errors: no
/// models, a model outside R^2 and R^3, those of to_bspline; a header text
/// IGES cannot hold (a timestamp not of the form above).
Expected<std::string> write_iges(std::span<const Model> models, const ExchangeHeader& header = {});

/// A STEP file (ISO 10303-21) of the AP214 schema AUTOMOTIVE_DESIGN: the
/// header, the product structure a reader expects (application context and
/// protocol, product, its definition and shape), and one shape
/// representation: a GEOMETRICALLY_BOUNDED_WIREFRAME_SHAPE_REPRESENTATION of a
/// GEOMETRIC_CURVE_SET when every model is a curve, else a
/// GEOMETRICALLY_BOUNDED_SURFACE_SHAPE_REPRESENTATION of a GEOMETRIC_SET;
/// its context states the unit and an uncertainty of 1e-12 of the size.
/// Curves are B_SPLINE_CURVE_WITH_KNOTS, surfaces B_SPLINE_SURFACE_WITH_KNOTS,
/// rational ones as the complex entities with RATIONAL_B_SPLINE_CURVE /
/// _SURFACE (ISO 10303-42). Errors: those of write_iges.
Expected<std::string> write_step(std::span<const Model> models, const ExchangeHeader& header = {});

}  // namespace casteljau
