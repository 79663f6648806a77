// The curve concept in Python: every function that C++ writes once on the
// concept (curves/curve.hpp) is bound here once, as a template over the curve
// kinds, so BezierCurve, PiecewiseBezierCurve and BSplineCurve get the same
// functions with the same checks and errors: evaluation one parameter at a
// time and in batches, breakpoints, differential geometry (flattening, in
// the ops layer, is bound in ops.cpp).
// Parameter names follow the C++ rule: t for a Bézier curve, u for the others.

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <fmt/format.h>

#include <string>

#include "arrays.hpp"
#include "bindings.hpp"
#include "casteljau/curves/curve.hpp"
#include "casteljau/curves/curve_view.hpp"
#include "casteljau/curves/differential_geometry.hpp"

namespace casteljau::python {
namespace {

namespace py = pybind11;

/// The parameter's name for a kind, and its batch name.
template <class Kind>
struct ParameterName {
  static constexpr const char* one = "u";
  static constexpr const char* many = "us";
};
template <>
struct ParameterName<BezierCurve> {
  static constexpr const char* one = "t";
  static constexpr const char* many = "ts";
};

/// (k+1, d) array of the rows C, C', ..., C^(k).
DoubleArray rows_array(const std::vector<Point>& values, int dimension) {
  DoubleArray result({static_cast<py::ssize_t>(values.size()), static_cast<py::ssize_t>(dimension)});
  for (std::size_t k = 0; k < values.size(); ++k)
    std::copy(values[k].begin(), values[k].end(), result.mutable_data() + k * values[k].size());
  return result;
}

void check_plane(int dimension, const char* what) {
  if (dimension != 2) throw py::value_error(fmt::format("{} needs a plane curve, this one lives in R^{}", what, dimension));
}

void check_space(int dimension, const char* what) {
  if (dimension != 3) throw py::value_error(fmt::format("{} needs a space curve (R^3), this one lives in R^{}", what, dimension));
}

/// Binds name(curve, u, *, extrapolate=False) -> value(curve, u), the
/// parameter checked first (finite, in the domain unless extrapolate).
template <class Kind, class Value>
void def_at(py::module_& module, const char* name, Value value, const char* doc) {
  module.def(
      name,
      [value](const Kind& curve, double u, bool extrapolate) {
        check_parameter(u, curve.domain(), extrapolate, ParameterName<Kind>::one);
        return value(curve, u);
      },
      py::arg("curve"), py::arg(ParameterName<Kind>::one), py::kw_only(), py::arg("extrapolate") = false, doc);
}

template <class Kind>
void bind_kind(py::module_& module) {
  const char* one = ParameterName<Kind>::one;
  const char* many = ParameterName<Kind>::many;
  // One parameter: finite and in the domain unless extrapolate=True.
  const auto checked = [one](const Kind& curve, double u, bool extrapolate) {
    check_parameter(u, curve.domain(), extrapolate, one);
  };

  def_at<Kind>(
      module, "point_at", [](const Kind& curve, double u) { return to_numpy(point_at(curve, u)); },
      "C at one parameter, a (d,) array (de Casteljau on a Bézier curve or on the piece that holds it, de Boor on "
      "a B-spline). ValueError outside the domain unless extrapolate=True.");

  module.def(
      "derivative_at",
      [checked](const Kind& curve, double u, int order, bool extrapolate) {
        check_derivative_order(order, 0, "derivative order");
        checked(curve, u, extrapolate);
        return to_numpy(derivative_at(curve, u, order));
      },
      py::arg("curve"), py::arg(one), py::arg("order") = 1, py::kw_only(), py::arg("extrapolate") = false,
      "The k-th derivative, a (d,) array (Farin §4.3, The NURBS Book §3.3/A3.2; rational curves by A4.2). At a "
      "knot or junction, the span or piece to the right.");

  module.def(
      "derivatives_up_to",
      [checked](const Kind& curve, double u, int max_order, bool extrapolate) {
        check_derivative_order(max_order, 0, "derivative order");
        checked(curve, u, extrapolate);
        return rows_array(derivatives_up_to(curve, u, max_order), curve.dimension());
      },
      py::arg("curve"), py::arg(one), py::arg("max_order"), py::kw_only(), py::arg("extrapolate") = false,
      "C, C', ..., C^(max_order) at one parameter, as a (max_order+1, d) array (A3.2/A4.2).");

  module.def(
      "points_at",
      [many](const Kind& curve, const py::object& us, const py::object& out, bool extrapolate) {
        return evaluate_batch(parameters_from(us, many), static_cast<std::size_t>(curve.dimension()), out,
                              curve.domain(), extrapolate, many,
                              [&](std::span<const double> chunk, std::span<double> target) {
                                points_at(curve, chunk, target);
                              });
      },
      py::arg("curve"), py::arg(many), py::kw_only(), py::arg("out") = py::none(), py::arg("extrapolate") = false,
      "C at every parameter of a (k,) array, as a (k, d) array: the batch kernel (bit for bit point_at), no copy "
      "of a float64 array, the GIL released. out: an optional (k, d) C-contiguous float64 array to write into (as "
      "numpy's out=). On ValueError out may be partly written.");

  module.def(
      "derivatives_at",
      [many](const Kind& curve, const py::object& us, int order, const py::object& out, bool extrapolate) {
        check_derivative_order(order, 0, "derivative order");
        return evaluate_batch(parameters_from(us, many), static_cast<std::size_t>(curve.dimension()), out,
                              curve.domain(), extrapolate, many,
                              [&](std::span<const double> chunk, std::span<double> target) {
                                derivatives_at(curve, chunk, order, target);
                              });
      },
      py::arg("curve"), py::arg(many), py::arg("order"), py::kw_only(), py::arg("out") = py::none(),
      py::arg("extrapolate") = false,
      "The order-th derivative at every parameter of a (k,) array, as a (k, d) array (the batch kernels), the GIL "
      "released. One parameter, all orders: derivatives_up_to.");

  module.def(
      "points_and_derivatives_at",
      [many](const Kind& curve, const py::object& us, bool extrapolate) {
        const DoubleArray parameters = parameters_from(us, many);
        const std::size_t d = static_cast<std::size_t>(curve.dimension());
        const std::size_t k = static_cast<std::size_t>(parameters.shape(0));
        DoubleArray points = output_array(k, d, py::none()), derivatives = output_array(k, d, py::none());
        double* point_target = points.mutable_data();
        double* derivative_target = derivatives.mutable_data();
        for_each_checked_chunk(std::span<const double>(parameters.data(), k), curve.domain(), extrapolate, many,
                               [&](std::span<const double> chunk, std::size_t offset) {
                                 points_and_derivatives_at(
                                     curve, chunk, std::span<double>(point_target + offset * d, chunk.size() * d),
                                     std::span<double>(derivative_target + offset * d, chunk.size() * d));
                               });
        return py::make_tuple(points, derivatives);
      },
      py::arg("curve"), py::arg(many), py::kw_only(), py::arg("extrapolate") = false,
      "(C, C') at every parameter of a (k,) array, two (k, d) arrays (one de Boor triangle per parameter on a "
      "B-spline: W2).");

  module.def(
      "breakpoints", [](const Kind& curve) { return to_numpy(std::span<const double>(breakpoints(curve))); },
      py::arg("curve"),
      "The parameters where the curve may be less smooth, increasing, both ends of the domain included: [0, 1] "
      "for a Bézier curve, 0..m for m pieces, the distinct knots of the domain for a B-spline.");

  def_at<Kind>(
      module, "unit_tangent_at",
      [](const Kind& curve, double u) {
        return to_numpy(unit_tangent_at(curve, u));
      },
      "C'/|C'|, a (d,) array; where C' vanishes the direction of the first non-vanishing derivative (the "
      "one-sided limit from inside the domain), zero for a single point (curves/differential_geometry.hpp).");

  def_at<Kind>(
      module, "unit_normal_at",
      [](const Kind& curve, double u) {
        return to_numpy(unit_normal_at(curve, u));
      },
      "The unit principal normal (toward the centre of curvature), a (d,) array; where the curvature is zero the "
      "left normal in the plane, else zero.");

  def_at<Kind>(
      module, "binormal_at",
      [](const Kind& curve, double u) {
        check_space(curve.dimension(), "the binormal"); return to_numpy(binormal_at(curve, u));
      },
      "The unit binormal T x N of a space curve, a (3,) array (zero where the normal is undefined). ValueError "
      "unless d == 3.");

  def_at<Kind>(
      module, "curvature_at",
      [](const Kind& curve, double u) {
        return curvature_at(curve, u);
      },
      "kappa = sqrt(|C'|^2 |C''|^2 - (C'.C'')^2) / |C'|^3 in any dimension (unsigned; +inf at a cusp, 0 where "
      "C' and C'' vanish).");

  def_at<Kind>(
      module, "signed_curvature_at",
      [](const Kind& curve, double u) {
        check_plane(curve.dimension(), "signed curvature"); return signed_curvature_at(curve, u);
      },
      "(C' x C'') / |C'|^3 of a plane curve, positive when it turns left. ValueError unless d == 2.");

  def_at<Kind>(
      module, "torsion_at",
      [](const Kind& curve, double u) {
        check_space(curve.dimension(), "torsion"); return torsion_at(curve, u);
      },
      "tau = (C' x C'') . C''' / |C' x C''|^2 of a space curve (0 where C' x C'' = 0). ValueError unless d == 3.");

  def_at<Kind>(
      module, "frenet_frame_at",
      [](const Kind& curve, double u) {
        const FrenetFrame frame = frenet_frame_at(curve, u);
        py::dict result;
        result["tangent"] = to_numpy(frame.tangent);
        result["normal"] = to_numpy(frame.normal);
        result["binormal"] = to_numpy(frame.binormal);
        result["curvature"] = frame.curvature;
        result["torsion"] = frame.torsion;
        return result;
      },
      "The Frenet frame as a dict: tangent, normal, binormal ((3,) for a space curve, (0,) otherwise), curvature "
      "and torsion (0 unless d == 3), the values of the single functions.");
}

}  // namespace

void bind_curves(py::module_& module) {
  bind_kind<BezierCurve>(module);
  bind_kind<PiecewiseBezierCurve>(module);
  bind_kind<BSplineCurve>(module);
}

}  // namespace casteljau::python
