#include "bindings.hpp"

namespace casteljau::python {
void bind_io(pybind11::module_&) {}
}  // namespace casteljau::python
