#pragma once
// One function per binding file, each adding its layer's classes and
// functions to the module (python/src/module.cpp calls them in layer order,
// so a layer's types are registered before the layers that use them).

#include <pybind11/pybind11.h>

namespace casteljau::python {

void bind_core(pybind11::module_& module);           // core.cpp: Interval, tolerances
void bind_bezier(pybind11::module_& module);         // bezier.cpp
void bind_bspline_curve(pybind11::module_& module);  // bspline_curve.cpp: the class and its evaluation
void bind_bspline(pybind11::module_& module);        // bspline.cpp: basis, knots, exact algorithms
void bind_curves(pybind11::module_& module);         // curves.cpp: what every curve kind offers (the concept)
void bind_nurbs(pybind11::module_& module);          // nurbs.cpp: conics
void bind_interpolation(pybind11::module_& module);  // interpolation.cpp
void bind_surfaces(pybind11::module_& module);       // surfaces.cpp
void bind_ops(pybind11::module_& module);            // ops.cpp: flattening, tessellation, meshes
void bind_io(pybind11::module_& module);             // io.cpp: model JSON, CSV, mesh files

}  // namespace casteljau::python
