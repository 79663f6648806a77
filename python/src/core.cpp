// The core layer in Python: the version and the limits of the tolerance.hpp headers
// that callers meet (as casteljau.tolerances.<name>).

#include "arrays.hpp"
#include "bindings.hpp"
#include "casteljau/core/tolerance.hpp"
#include "casteljau/ops/tolerance.hpp"
#include "casteljau/version.hpp"

#include <fmt/format.h>

#include <cmath>

namespace casteljau::python {

Tolerance tolerance_from(double distance, const std::string& what) {
  if (!std::isfinite(distance) || distance <= 0.0) {
    throw py::value_error(fmt::format("{} is {}, it must be a finite distance > 0", what, distance));
  }
  return Tolerance{distance};
}

void bind_core(py::module_& module) {
  module.attr("__version__") = CASTELJAU_VERSION_STRING;
  py::module_ limits = module.def_submodule(
      "tolerances", "The limits and tolerances of include/casteljau/core/tolerance.hpp and ops/tolerance.hpp (read-only values).");
  limits.attr("MAX_BEZIER_DEGREE") = tolerances::kMaxBezierDegree;
  limits.attr("MAX_BSPLINE_DEGREE") = tolerances::kMaxBSplineDegree;
  limits.attr("MAX_CONTROL_POINTS") = tolerances::kMaxControlPoints;
  limits.attr("MAX_DERIVATIVE_ORDER") = tolerances::kMaxDerivativeOrder;
  limits.attr("MAX_SURFACE_DERIVATIVE_ORDER") = tolerances::kMaxSurfaceDerivativeOrder;
  limits.attr("MAX_STACK_DEGREE") = tolerances::kMaxStackDegree;
  limits.attr("MAX_MESH_TRIANGLES") = tolerances::kMaxMeshTriangles;
  limits.attr("MAX_FLATTEN_SEGMENTS") = tolerances::kMaxFlattenSegments;
  limits.attr("VANISHING_DERIVATIVE") = tolerances::kVanishingDerivative;
}

}  // namespace casteljau::python
