// railmodal._railmodal: the compiled part of the Python package (python/railmodal/__init__.py
// re-exports it). docs/python.md describes the package.
#include "bindings.hpp"
#include "railmodal/version.hpp"

PYBIND11_MODULE(_railmodal, m) {
  m.doc() = "railmodal: modal and frequency-response analysis of railway vehicles";
  m.attr("__version__") = railmodal::version();
  railmodal::python::bind_errors(m);
  railmodal::python::bind_model(m);
  railmodal::python::bind_modes(m);
  railmodal::python::bind_response(m);
  railmodal::python::bind_simulation(m);
  railmodal::python::bind_study(m);
  railmodal::python::bind_stability(m);
  railmodal::python::bind_ride(m);
  railmodal::python::bind_balance(m);
}
