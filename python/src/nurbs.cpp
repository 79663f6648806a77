// The nurbs layer in Python: exact conics as rational quadratic B-splines
// (circle, arcs, ellipse; The NURBS Book §7.5, A7.1) and seed 003's
// semicircle with its cubic approximation. The C++ functions validate
// everything they take (Expected), so the bindings only convert: the centre
// and the optional axes become the C++ ConicFrame.

#include <pybind11/stl.h>

#include <utility>

#include "arrays.hpp"
#include "bindings.hpp"
#include "casteljau/nurbs/conics.hpp"

namespace casteljau::python {

namespace {

/// The plane of a conic from Python: the centre O (a point of R^d, d >= 2) and
/// the axes X, Y given together, or neither (then the first two coordinate
/// axes of R^d: the plane of x and y). The C++ make_* check the rest (finite,
/// of one dimension, orthonormal).
ConicFrame frame_from(const py::object& center, const py::object& x_axis, const py::object& y_axis) {
  Point origin = values_from(center, "center");
  if (x_axis.is_none() != y_axis.is_none()) {
    throw py::value_error("x_axis and y_axis go together: give both (the plane's orthonormal directions) or "
                          "neither (the first two coordinate axes)");
  }
  if (!x_axis.is_none()) return ConicFrame{std::move(origin), values_from(x_axis, "x_axis"), values_from(y_axis, "y_axis")};
  Point x(origin.size(), 0.0), y(origin.size(), 0.0);
  if (!x.empty()) x[0] = 1.0;
  if (y.size() >= 2) y[1] = 1.0;
  return ConicFrame{std::move(origin), std::move(x), std::move(y)};
}

}  // namespace

void bind_nurbs(py::module_& module) {
  // Every conic takes its centre as one point-like argument first, as
  // make_sphere and make_torus do, and its plane by the keywords x_axis and
  // y_axis (default: the plane of the first two coordinates).
  module.def(
      "make_arc",
      [](const py::object& center, double radius, double start_angle, double sweep, const py::object& x_axis,
         const py::object& y_axis) {
        return unwrap(make_arc(frame_from(center, x_axis, y_axis), radius, start_angle, sweep));
      },
      py::arg("center"), py::arg("radius"), py::arg("start_angle"), py::arg("sweep"), py::kw_only(),
      py::arg("x_axis") = py::none(), py::arg("y_axis") = py::none(),
      "The circular arc C(0) = center + r (cos a X + sin a Y) over `sweep` radians (negative: from Y towards -X, "
      "clockwise in the plane) as a rational quadratic B-spline on [0, 1] with 1 to 4 pieces (The NURBS Book "
      "A7.1). center: a point of R^d, d >= 2; x_axis, y_axis: orthonormal directions of the plane (default the "
      "first two coordinate axes). ValueError for radius <= 0, sweep 0 or |sweep| > 2π, non-finite values, axes "
      "not orthonormal or of another dimension.");

  module.def(
      "make_circle",
      [](const py::object& center, double radius, const py::object& x_axis, const py::object& y_axis) {
        return unwrap(make_circle(frame_from(center, x_axis, y_axis), radius));
      },
      py::arg("center"), py::arg("radius"), py::kw_only(), py::arg("x_axis") = py::none(),
      py::arg("y_axis") = py::none(),
      "The full circle center + r (cos θ X + sin θ Y) as the nine-point rational quadratic B-spline (The NURBS "
      "Book §7.5, fig. 7.16): weights 1, √½, 1, ..., knots 0,0,0,¼,¼,½,½,¾,¾,1,1,1. Plane and errors as "
      "make_arc.");

  module.def(
      "make_ellipse",
      [](const py::object& center, double semi_axis_x, double semi_axis_y, const py::object& x_axis,
         const py::object& y_axis) {
        return unwrap(make_ellipse(frame_from(center, x_axis, y_axis), semi_axis_x, semi_axis_y));
      },
      py::arg("center"), py::arg("semi_axis_x"), py::arg("semi_axis_y"), py::kw_only(),
      py::arg("x_axis") = py::none(), py::arg("y_axis") = py::none(),
      "The ellipse center + a cos θ X + b sin θ Y: the circle's control net scaled by (a, b) along X and Y, "
      "weights unchanged (The NURBS Book §4.1, §7.5). Plane as make_arc; ValueError also for a or b <= 0.");

  module.def("seed_semicircle", &seed_semicircle,
             "Seed 003's semicircle exactly: the upper half of the circle of radius 3 at the origin from (-3, 0) to "
             "(3, 0), make_arc((0, 0), 3, π, -π).");

  module.def("seed_semicircle_cubic", &seed_semicircle_cubic,
             "Seed 003's cubic approximation of the same semicircle: the Bézier curve (-3,0), (-3,4), (3,4), (3,0).");
}

}  // namespace casteljau::python
