// Placeholder: the ride bindings are not written yet (docs/python.md).
#include "bindings.hpp"

namespace railmodal::python {

void bind_ride(pybind11::module_&) {}

}  // namespace railmodal::python
