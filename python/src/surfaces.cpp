#include "bindings.hpp"

namespace casteljau::python {
void bind_surfaces(pybind11::module_&) {}
}  // namespace casteljau::python
