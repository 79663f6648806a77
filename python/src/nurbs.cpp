#include "bindings.hpp"

namespace casteljau::python {
void bind_nurbs(pybind11::module_&) {}
}  // namespace casteljau::python
