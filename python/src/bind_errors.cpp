// The library's two failures as Python exceptions (docs/python.md, "Conventions"):
// railmodal::InputError → railmodal.InputError (a ValueError) with file, line, column, message
// and key; railmodal::NumericalError → railmodal.NumericalError (a RuntimeError).
// std::invalid_argument is a ValueError by pybind11's own translation. The text is what() of
// the C++ exception: what the command line prints.
#include <regex>
#include <string>

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

}  // namespace

void bind_errors(py::module_& m) {
  // Created once and kept for the life of the interpreter (the translator below refers to them).
  static py::exception<InputError> input_error(m, "InputError", PyExc_ValueError);
  static py::exception<NumericalError> numerical_error(m, "NumericalError", PyExc_RuntimeError);
  input_error.doc() =
      "Bad input: str() is 'file:line:col: error: message'. Attributes file, line, column (None when "
      "unknown), message (without the place) and key (the key path, None when the message names none).";
  numerical_error.doc() = "The model cannot be solved as given; the message names the degree of freedom.";

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
