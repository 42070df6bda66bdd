// Placeholder: the stability bindings are not written yet (docs/python.md).
#include "bindings.hpp"

namespace railmodal::python {

void bind_stability(pybind11::module_&) {}

}  // namespace railmodal::python
