// Placeholder: the model bindings are not written yet (docs/python.md).
#include "bindings.hpp"

namespace railmodal::python {

void bind_model(pybind11::module_&) {}

}  // namespace railmodal::python
