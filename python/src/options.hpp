// Keyword arguments → a C++ options struct (docs/python.md, "Conventions"): each field is read
// by its C++ name, omitted ones keep their defaults, and finish() refuses a keyword nobody read
// with a TypeError naming it, so a misspelt option never passes silently.
#pragma once

#include <pybind11/pybind11.h>

#include <optional>
#include <set>
#include <string>

namespace railmodal::python {

class OptionReader {
 public:
  /// `what` names the call in messages ("modes()").
  OptionReader(pybind11::dict options, std::string what) : options_(std::move(options)), what_(std::move(what)) {}

  /// Reads `name` into *field when given (a pybind11 cast: a wrong type is a TypeError).
  template <typename T>
  void read(const char* name, T* field) {
    if (!take(name)) return;
    try {
      *field = options_[name].template cast<T>();
    } catch (const pybind11::cast_error&) {
      throw pybind11::type_error(what_ + ": option '" + std::string(name) + "' has the wrong type (" +
                                 std::string(pybind11::str(pybind11::type::of(options_[name]).attr("__name__"))) +
                                 ")");
    }
  }

  /// Reads an enum spelt as its to_string spells it, through <name>_from_string.
  template <typename T, typename FromString>
  void read_enum(const char* name, T* field, FromString from_string, const char* accepted) {
    if (!take(name)) return;
    const std::string word = pybind11::str(options_[name]);
    const std::optional<T> value = from_string(word);
    if (!value)
      throw pybind11::value_error(what_ + ": option '" + std::string(name) + "' is '" + word + "'; expected one of " +
                                  accepted);
    *field = *value;
  }

  /// A nested options struct given as a dict keyword; empty when not given.
  pybind11::dict nested(const char* name) {
    if (!take(name)) return {};
    if (!pybind11::isinstance<pybind11::dict>(options_[name]))
      throw pybind11::type_error(what_ + ": option '" + std::string(name) + "' must be a dict");
    return options_[name].cast<pybind11::dict>();
  }

  bool has(const char* name) const { return options_.contains(name); }

  /// Throws TypeError for the first keyword no read() took.
  void finish() const {
    for (const auto& item : options_) {
      const std::string key = pybind11::str(item.first);
      if (!read_.count(key)) throw pybind11::type_error(what_ + ": unknown option '" + key + "'");
    }
  }

 private:
  bool take(const char* name) {
    read_.insert(name);
    return options_.contains(name) && !options_[name].is_none();
  }
  pybind11::dict options_;
  std::string what_;
  std::set<std::string> read_;
};

}  // namespace railmodal::python
