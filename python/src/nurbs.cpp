// The nurbs layer in Python: exact conics as rational quadratic B-splines
// (circle, arcs, ellipse; The NURBS Book §7.5, A7.1) and seed 003's
// semicircle with its cubic approximation. The C++ functions validate
// everything they take (Expected), so the bindings only convert.

#include <pybind11/stl.h>

#include <fmt/format.h>

#include "arrays.hpp"
#include "bindings.hpp"
#include "casteljau/nurbs/conics.hpp"

namespace casteljau::python {

namespace {

ConicFrame frame_from(const py::object& center, const py::object& x_axis, const py::object& y_axis) {
  return ConicFrame{values_from(center, "center"), values_from(x_axis, "x_axis"), values_from(y_axis, "y_axis")};
}

}  // namespace

void bind_nurbs(py::module_& module) {
  py::class_<ConicFrame>(module, "ConicFrame",
                         "The plane of a conic in R^d, d >= 2: centre O and orthonormal axes X, Y; the point at "
                         "angle θ of the circle of radius r is O + r (cos θ X + sin θ Y) (conics.hpp).")
      .def(py::init(&frame_from), py::arg("center"), py::arg("x_axis"), py::arg("y_axis"),
           "From three (d,) arrays; checked (d >= 2, finite, orthonormal within 1e-12) by make_arc/make_circle/"
           "make_ellipse.")
      .def_property_readonly("center", [](const ConicFrame& f) { return to_numpy(f.center); }, "O, a (d,) array.")
      .def_property_readonly("x_axis", [](const ConicFrame& f) { return to_numpy(f.x_axis); }, "X, a (d,) array.")
      .def_property_readonly("y_axis", [](const ConicFrame& f) { return to_numpy(f.y_axis); }, "Y, a (d,) array.")
      .def("__eq__",
           [](const ConicFrame& a, const ConicFrame& b) {
             return a.center == b.center && a.x_axis == b.x_axis && a.y_axis == b.y_axis;
           },
           py::is_operator())
      .def("__repr__", [](const ConicFrame& f) {
        return fmt::format("ConicFrame(center=[{}], x_axis=[{}], y_axis=[{}])", fmt::join(f.center, ", "),
                           fmt::join(f.x_axis, ", "), fmt::join(f.y_axis, ", "));
      })
      .def(py::pickle(
          [](const ConicFrame& f) { return py::make_tuple(to_numpy(f.center), to_numpy(f.x_axis), to_numpy(f.y_axis)); },
          [](const py::tuple& state) {
            if (state.size() != 3) throw py::value_error("ConicFrame pickle state must have 3 entries");
            return frame_from(state[0], state[1], state[2]);
          }));

  module.def("plane_frame", &plane_frame, py::arg("center_x"), py::arg("center_y"),
             "The frame of the plane in 2D: O = (center_x, center_y), X = (1, 0), Y = (0, 1).");

  module.def(
      "make_arc",
      [](double center_x, double center_y, double radius, double start_angle, double sweep) {
        return unwrap(make_arc(center_x, center_y, radius, start_angle, sweep));
      },
      py::arg("center_x"), py::arg("center_y"), py::arg("radius"), py::arg("start_angle"), py::arg("sweep"),
      "The circular arc of the plane circle of centre (center_x, center_y) from start_angle over sweep radians "
      "(negative: clockwise), a rational quadratic B-spline on [0, 1] with 1 to 4 pieces (The NURBS Book A7.1). "
      "ValueError for radius <= 0, sweep 0 or |sweep| > 2π, non-finite values.");

  module.def(
      "make_arc",
      [](const ConicFrame& frame, double radius, double start_angle, double sweep) {
        return unwrap(make_arc(frame, radius, start_angle, sweep));
      },
      py::arg("frame"), py::arg("radius"), py::arg("start_angle"), py::arg("sweep"),
      "The circular arc in the plane of a ConicFrame in R^d (The NURBS Book A7.1); ValueError also for a frame "
      "that is not orthonormal.");

  module.def(
      "make_circle",
      [](double center_x, double center_y, double radius) { return unwrap(make_circle(center_x, center_y, radius)); },
      py::arg("center_x"), py::arg("center_y"), py::arg("radius"),
      "The full plane circle as the nine-point rational quadratic B-spline (The NURBS Book §7.5, fig. 7.16): "
      "weights 1, √½, 1, ..., knots 0,0,0,¼,¼,½,½,¾,¾,1,1,1.");

  module.def(
      "make_circle", [](const ConicFrame& frame, double radius) { return unwrap(make_circle(frame, radius)); },
      py::arg("frame"), py::arg("radius"),
      "The full circle O + r (cos θ X + sin θ Y) in the plane of a ConicFrame (The NURBS Book §7.5).");

  module.def(
      "make_ellipse",
      [](double center_x, double center_y, double semi_axis_x, double semi_axis_y) {
        return unwrap(make_ellipse(center_x, center_y, semi_axis_x, semi_axis_y));
      },
      py::arg("center_x"), py::arg("center_y"), py::arg("semi_axis_x"), py::arg("semi_axis_y"),
      "The axis-aligned plane ellipse: the circle's control net scaled by (a, b), weights unchanged (The NURBS "
      "Book §4.1, §7.5).");

  module.def(
      "make_ellipse",
      [](const ConicFrame& frame, double semi_axis_x, double semi_axis_y) {
        return unwrap(make_ellipse(frame, semi_axis_x, semi_axis_y));
      },
      py::arg("frame"), py::arg("semi_axis_x"), py::arg("semi_axis_y"),
      "The ellipse O + a cos θ X + b sin θ Y in the plane of a ConicFrame (The NURBS Book §4.1, §7.5).");

  module.def("seed_semicircle", &seed_semicircle,
             "Seed 003's semicircle exactly: the upper half of the circle of radius 3 at the origin from (-3, 0) to "
             "(3, 0), make_arc(0, 0, 3, π, -π).");

  module.def("seed_semicircle_cubic", &seed_semicircle_cubic,
             "Seed 003's cubic approximation of the same semicircle: the Bézier curve (-3,0), (-3,4), (3,4), (3,0).");
}

}  // namespace casteljau::python
