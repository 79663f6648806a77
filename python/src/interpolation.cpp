#include "bindings.hpp"

namespace casteljau::python {
void bind_interpolation(pybind11::module_&) {}
}  // namespace casteljau::python
