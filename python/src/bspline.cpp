#include "bindings.hpp"

namespace casteljau::python {
void bind_bspline(pybind11::module_&) {}
}  // namespace casteljau::python
