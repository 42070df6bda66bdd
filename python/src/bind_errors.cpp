// The library's two failures as Python exceptions (docs/python.md, "Conventions"):
// railmodal::InputError → railmodal.InputError (a ValueError) with file, line, column, message
// and key; railmodal::NumericalError → railmodal.NumericalError (a RuntimeError).
// std::invalid_argument is a ValueError by pybind11's own translation. The text is what() of
// the C++ exception: what the command line prints. A reader's warnings (docs/input.md,
// "Implausible inputs") are railmodal.InputWarning (a UserWarning), issued through Python's
// warnings module: shown once on stderr as the command line shows them, recorded by
// warnings.catch_warnings, made errors by -W error::railmodal.InputWarning.
#include <regex>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "railmodal/errors.hpp"

namespace py = pybind11;

namespace railmodal::python {

namespace {

// The key path an InputError's message names ("key 'body.mass': ..."), or "" when none.
std::string key_of(const std::string& message) {
  static const std::regex key(R"(key '([^']*)')");
  std::smatch m;
  return std::regex_search(message, m, key) ? m[1].str() : std::string();
}

py::object or_none(int value) { return value > 0 ? py::object(py::int_(value)) : py::object(py::none()); }

PyObject* input_warning = nullptr;  // railmodal.InputWarning, kept for the interpreter's life

}  // namespace

void warn_input(const std::vector<std::string>& warnings) {
  for (const std::string& w : warnings)
    if (PyErr_WarnEx(input_warning, w.c_str(), 1) != 0) throw py::error_already_set();
}

void bind_errors(py::module_& m) {
  // Created once and kept for the life of the interpreter (the translator below refers to them).
  static py::exception<InputError> input_error(m, "InputError", PyExc_ValueError);
  static py::exception<NumericalError> numerical_error(m, "NumericalError", PyExc_RuntimeError);
  input_error.doc() =
      "Bad input: str() is 'file:line:col: error: message'. Attributes file, line, column (None when "
      "unknown), message (without the place) and key (the key path, None when the message names none).";
  numerical_error.doc() = "The model cannot be solved as given; the message names the degree of freedom.";
  input_warning = PyErr_NewExceptionWithDoc(
      "railmodal.InputWarning",
      "An input a reader accepted but found unusual (a hanger 734 m long): str() is 'file:line:col: warning: "
      "message', as the command line prints it. It changes no result.",
      PyExc_UserWarning, nullptr);
  if (!input_warning) throw py::error_already_set();
  m.attr("InputWarning") = py::handle(input_warning);

  py::register_exception_translator([](std::exception_ptr thrown) {
    try {
      if (thrown) std::rethrow_exception(thrown);
    } catch (const InputError& e) {
      py::object error = py::handle(input_error.ptr())(e.what());
      error.attr("file") = e.file();
      error.attr("line") = or_none(e.line());
      error.attr("column") = or_none(e.column());
      error.attr("message") = e.message();
      const std::string key = key_of(e.message());
      error.attr("key") = key.empty() ? py::object(py::none()) : py::object(py::str(key));
      PyErr_SetObject(input_error.ptr(), error.ptr());
    } catch (const NumericalError& e) {
      numerical_error(e.what());
    }
  });
}

}  // namespace railmodal::python
