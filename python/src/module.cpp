// casteljau._casteljau: the compiled half of the Python package. The package
// (python/casteljau/__init__.py) re-exports everything defined here and adds
// the scipy-like classes and the matplotlib helpers.

#include "bindings.hpp"

PYBIND11_MODULE(_casteljau, module) {
  module.doc() = "casteljau's C++ library (Bézier, B-spline and NURBS curves and surfaces) on numpy arrays.";
  using namespace casteljau::python;
  bind_core(module);
  bind_bezier(module);
  bind_bspline_curve(module);
  bind_bspline(module);
  bind_curves(module);
  bind_nurbs(module);
  bind_interpolation(module);
  bind_surfaces(module);
  bind_ops(module);
  bind_io(module);
}
