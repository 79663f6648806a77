#include "bindings.hpp"

namespace casteljau::python {
void bind_bezier(pybind11::module_&) {}
}  // namespace casteljau::python
