// What the analysis bindings (simulation, studies, stability, ride, balance) share: reading a
// vehicle or a path argument, building arrays, and choosing an enum by
// its word. Header-only, used by those five files only (the model, modes and response bindings
// have their own).
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "arrays.hpp"
#include "railmodal/errors.hpp"
#include "railmodal/input.hpp"
#include "railmodal/linear_system.hpp"
#include "railmodal/vehicle.hpp"

namespace railmodal::python {

namespace py = pybind11;

/// A path given as str or os.PathLike, as text.
inline std::string path_argument(const py::handle& path) {
  return py::str(py::module_::import("os").attr("fspath")(path)).cast<std::string>();
}

/// A reader of one file as the function Python calls: the path as str or os.PathLike, read
/// without the GIL (other Python threads run meanwhile).
template <class Read>
auto path_reader(Read read) {
  return [read](const py::object& path) {
    const std::string file = path_argument(path);
    py::gil_scoped_release release;
    return read(file);
  };
}

inline bool is_path(const py::handle& value) {
  return py::isinstance<py::str>(value) || py::hasattr(value, "__fspath__");
}

/// `value` as a T, or a TypeError naming what was expected and what came.
template <class T>
T typed_argument(const py::handle& value, const char* expected) {
  try {
    return value.cast<T>();
  } catch (const py::cast_error&) {
    throw py::type_error(std::string("expected ") + expected + ", got " +
                         py::str(py::type::of(value).attr("__name__")).cast<std::string>());
  }
}

/// A vehicle argument: a file (str or os.PathLike, read by load_vehicle) or a Vehicle object.
/// Anything else is a TypeError.
inline Vehicle vehicle_argument(const py::handle& vehicle) {
  if (is_path(vehicle)) {
    const std::string path = path_argument(vehicle);
    py::gil_scoped_release release;
    return load_vehicle(path);
  }
  return typed_argument<Vehicle>(vehicle, "a vehicle file or a Vehicle");
}

/// A system argument of the analyses that take one assembly (hunting stability): a LinearSystem
/// as given (referred to, not copied), or a vehicle (file or Vehicle) assembled in `set`.
class SystemArgument {
 public:
  SystemArgument(const py::handle& system, DofSet set) {
    if (!is_path(system) && !py::isinstance<Vehicle>(system)) {
      system_ = &typed_argument<const LinearSystem&>(system, "a LinearSystem, a vehicle file or a Vehicle");
      return;
    }
    const Vehicle vehicle = vehicle_argument(system);
    py::gil_scoped_release release;
    assembled_ = assemble(vehicle, set);
    system_ = &assembled_;
  }
  SystemArgument(const SystemArgument&) = delete;
  SystemArgument& operator=(const SystemArgument&) = delete;
  const LinearSystem& operator*() const { return *system_; }

 private:
  LinearSystem assembled_;
  const LinearSystem* system_ = nullptr;  // the caller's object (kept alive by the call) or assembled_
};

/// An enum chosen by its word (the C++ <name>_from_string), or ValueError naming the argument
/// and the words there are.
template <class Enum>
Enum enum_argument(const std::string& word, std::optional<Enum> (*from_string)(const std::string&),
                   const char* argument, const char* words) {
  if (const std::optional<Enum> value = from_string(word)) return *value;
  throw py::value_error(std::string(argument) + ": '" + word + "' is not one of " + words);
}

/// An optional double as None or a float.
inline py::object optional_value(const std::optional<double>& value) {
  return value ? py::object(py::float_(*value)) : py::object(py::none());
}

/// A rows × cols array (row-major) filled by value(row, col): the tables the results keep as
/// vectors of structs (speed × branch, crank angle × cylinder) gathered into one new array.
template <class Value>
py::array table(std::size_t rows, std::size_t cols, const Value& value) {
  std::vector<double> out(rows * cols);
  for (std::size_t i = 0; i < rows; ++i)
    for (std::size_t j = 0; j < cols; ++j) out[i * cols + j] = value(i, j);
  return take(std::move(out), rows, cols);
}

/// A new vector of `size` doubles filled by value(i).
template <class Value>
py::array column(std::size_t size, const Value& value) {
  std::vector<double> out(size);
  for (std::size_t i = 0; i < size; ++i) out[i] = value(i);
  return take(std::move(out));
}

/// f applied to every element of `x` (any shape; a Python float is a 0-d array), into a new array
/// of the same shape: the spectra and weightings evaluated over numpy arrays of frequencies.
template <class Result = double, class F>
py::array_t<Result> elementwise(const py::array_t<double, py::array::c_style | py::array::forcecast>& x, const F& f) {
  py::array_t<Result> out(std::vector<py::ssize_t>(x.shape(), x.shape() + x.ndim()));
  const double* in = x.data();
  Result* values = out.mutable_data();
  for (py::ssize_t i = 0; i < x.size(); ++i) values[i] = f(in[i]);
  return out;
}

/// Converts what the analyses of a file throw for a bad argument of that file's content into
/// the CLI's InputError on the file ("FILE: error: ..."), so that Python sees the message the
/// command line prints.
template <class Work>
auto as_input_error(const std::string& file, const Work& work) -> decltype(work()) {
  try {
    return work();
  } catch (const std::invalid_argument& e) {
    throw InputError(file, 0, 0, e.what());
  }
}

}  // namespace railmodal::python
