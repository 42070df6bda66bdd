// Placeholder: the modes bindings are not written yet (docs/python.md).
#include "bindings.hpp"

namespace railmodal::python {

void bind_modes(pybind11::module_&) {}

}  // namespace railmodal::python
