// BSplineCurve in Python: the class (polynomial and NURBS, as in C++) and its
// evaluation, single and batch. The batch functions hand numpy's buffers to
// the C++ kernels (include/casteljau/bspline/evaluate.hpp) without copies,
// checking the parameters chunk by chunk and releasing the GIL.

#include <pybind11/stl.h>

#include <fmt/format.h>

#include <limits>

#include "arrays.hpp"
#include "bindings.hpp"
#include "casteljau/bspline/bspline_curve.hpp"
#include "casteljau/bspline/evaluate.hpp"

namespace casteljau::python {

void bind_bspline_curve(py::module_& module) {
  py::class_<BSplineCurve>(module, "BSplineCurve",
                           "A B-spline or NURBS curve of degree p in R^d: knots t_0..t_{n+p+1}, control points "
                           "P_0..P_n as an (n+1, d) array and, for NURBS, one weight w_i > 0 per control point "
                           "(The NURBS Book eq. 4.1). A value: operations return new curves.")
      .def(py::init([](int degree, const py::object& knots, const py::object& control_points,
                       const py::object& weights) {
             std::vector<double> weight_values;
             if (!weights.is_none()) weight_values = values_from(weights, "weights");
             return unwrap(BSplineCurve::make(degree, values_from(knots, "knots"),
                                              points_from(control_points, "control_points"),
                                              std::move(weight_values)));
           }),
           py::arg("degree"), py::arg("knots"), py::arg("control_points"), py::arg("weights") = py::none(),
           "Validates and builds (BSplineCurve::make): 0 <= degree, len(knots) == n + degree + 2 non-decreasing, "
           "finite control points, weights None or n+1 finite values > 0. ValueError names the bad field.")
      .def_property_readonly("degree", &BSplineCurve::degree, "p, the degree.")
      .def_property_readonly("dimension", &BSplineCurve::dimension, "d, the number of coordinates.")
      .def_property_readonly("knots", [](const BSplineCurve& c) { return to_numpy(c.knots()); },
                             "t_0 .. t_{n+p+1} (a new array).")
      .def_property_readonly("control_points", [](const BSplineCurve& c) { return to_numpy(c.control_points()); },
                             "P_0 .. P_n as an (n+1, d) array (a new array).")
      .def_property_readonly("weights", [](const BSplineCurve& c) { return to_numpy(c.weights()); },
                             "w_0 .. w_n, an empty array for a polynomial curve.")
      .def_property_readonly("is_rational", &BSplineCurve::is_rational, "True when the curve carries weights (NURBS).")
      .def_property_readonly("domain", [](const BSplineCurve& c) { return py::make_tuple(c.domain().lower, c.domain().upper); },
                             "(t_p, t_{n+1}), where the basis functions sum to one.")
      .def("__eq__", [](const BSplineCurve& a, const BSplineCurve& b) { return a == b; }, py::is_operator())
      .def("__repr__", [](const BSplineCurve& c) {
        return fmt::format("BSplineCurve(degree={}, {} control points in R^{}{}, domain [{}, {}])", c.degree(),
                           c.control_points().size(), c.dimension(), c.is_rational() ? ", rational" : "",
                           c.domain().lower, c.domain().upper);
      })
      .def(py::pickle(
          [](const BSplineCurve& c) {
            return py::make_tuple(c.degree(), to_numpy(c.knots()), to_numpy(c.control_points()), to_numpy(c.weights()));
          },
          [](const py::tuple& state) {
            if (state.size() != 4) throw py::value_error("BSplineCurve pickle state must have 4 entries");
            return unwrap(BSplineCurve::make(state[0].cast<int>(), values_from(state[1], "knots"),
                                             points_from(state[2], "control_points"),
                                             values_from(state[3], "weights")));
          }));






  module.def(
      "point_at_basis_sum",
      [](const BSplineCurve& curve, double u, bool extrapolate) {
        check_parameter(u, curve.domain(), extrapolate, "u");
        return to_numpy(point_at_basis_sum(curve, u));
      },
      py::arg("curve"), py::arg("u"), py::kw_only(), py::arg("extrapolate") = false,
      "C(u) as sum N_{i,p}(u) P_i from the basis functions (The NURBS Book A3.1, A4.1): an independent check of "
      "point_at.");

  module.def(
      "de_boor_net",
      [](const BSplineCurve& curve, double u) {
        check_parameter(u, curve.domain(), false, "u");
        const DeBoorNet net = de_boor_net(curve, u);
        py::list levels;
        for (const PointArray& level : net.levels) levels.append(to_numpy(level));
        return py::make_tuple(net.span, levels);
      },
      py::arg("curve"), py::arg("u"),
      "De Boor's algorithm at u as data (The NURBS Book §5.3, fig. 5.11): (span, levels), level r an (p+1-r, d) "
      "array, level 0 the control points of the span, level p the point C(u).");
}

}  // namespace casteljau::python
