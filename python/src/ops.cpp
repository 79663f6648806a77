#include "bindings.hpp"

namespace casteljau::python {
void bind_ops(pybind11::module_&) {}
}  // namespace casteljau::python
