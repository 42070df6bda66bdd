// BodyList, ElementList, SpringStageList: a vehicle's lists with items by reference
// (vehicle_lists.hpp says why, and how a dangling item is prevented).
#include "vehicle_lists.hpp"

#include <pybind11/pybind11.h>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

namespace py = pybind11;

namespace railmodal::python {

namespace {

// Whether a Python object of type T refers to *item (a reference handed out by a list).
template <typename T>
bool registered(const T& item) {
  return static_cast<bool>(py::detail::get_object_handle(&item, py::detail::get_type_info(typeid(T))));
}

bool in_use(const Body& b) { return registered(b); }
bool in_use(const SpringStage& s) { return registered(s); }
bool in_use(const std::vector<SpringStage>& stages) {
  if (registered(stages)) return true;
  for (const SpringStage& s : stages)
    if (in_use(s)) return true;
  return false;
}
// An element's stage lists live in the element: they move (are copied and freed) with it.
bool in_use(const Element& e) {
  return registered(e) || in_use(e.vertical_stages) || in_use(e.lateral_stages) || in_use(e.longitudinal_stages);
}

template <typename T>
void refuse_if_in_use(const std::vector<T>& list, const char* what) {
  for (const T& item : list)
    if (in_use(item))
      throw std::runtime_error(std::string(what) +
                               " cannot change length while an item read from it is still held in Python (an item "
                               "is a reference into the vehicle's storage, which a change of length moves): del "
                               "that variable, and build new lists from copies, e.g. "
                               "[e.copy() for e in vehicle.elements if ...]");
}

template <typename T>
void assign(std::vector<T>& list, const std::vector<T>& values, const char* what);

void assign_item(Body& to, const Body& from) { to = from; }
void assign_item(SpringStage& to, const SpringStage& from) { to = from; }
// An element's stage lists keep their storage (a move keeps it), so stages held in Python stay
// valid; only their values change.
void assign_item(Element& to, const Element& from) {
  std::vector<SpringStage> vertical = std::move(to.vertical_stages);
  std::vector<SpringStage> lateral = std::move(to.lateral_stages);
  std::vector<SpringStage> longitudinal = std::move(to.longitudinal_stages);
  to = from;
  assign(vertical, from.vertical_stages, "the element's vertical_stages");
  assign(lateral, from.lateral_stages, "the element's lateral_stages");
  assign(longitudinal, from.longitudinal_stages, "the element's longitudinal_stages");
  to.vertical_stages = std::move(vertical);
  to.lateral_stages = std::move(lateral);
  to.longitudinal_stages = std::move(longitudinal);
}

template <typename T>
void assign(std::vector<T>& list, const std::vector<T>& values, const char* what) {
  if (&list == &values) return;
  if (values.size() == list.size()) {
    // In place: items held in Python stay valid and show the new values.
    for (std::size_t i = 0; i < values.size(); ++i) assign_item(list[i], values[i]);
    return;
  }
  refuse_if_in_use(list, what);
  list = values;
}

std::size_t checked_index(const py::ssize_t index, std::size_t size) {
  const py::ssize_t n = static_cast<py::ssize_t>(size);
  const py::ssize_t i = index < 0 ? index + n : index;
  if (i < 0 || i >= n) throw py::index_error("index " + std::to_string(index) + " out of range for " + std::to_string(size) + " items");
  return static_cast<std::size_t>(i);
}

template <typename T>
void bind_list(py::module_& m, const char* name, const char* item, const char* what) {
  using List = std::vector<T>;
  py::class_<List>(m, name,
                   (std::string("A list of ") + item + " by reference: list[i] is the vehicle's own " + item +
                    ", so list[i].x = v changes the vehicle. Changing the length (append, insert, pop, or "
                    "assigning a longer or shorter list) is refused while an item is held in a variable.")
                       .c_str())
      .def(py::init<>())
      .def(py::init([](const py::iterable& items) {
             List list;
             for (py::handle h : items) list.push_back(h.cast<T>());
             return list;
           }),
           py::arg("items"))
      .def("__len__", [](const List& l) { return l.size(); })
      .def(
          "__getitem__", [](List& l, py::ssize_t i) -> T& { return l[checked_index(i, l.size())]; },
          py::return_value_policy::reference_internal)
      .def("__getitem__",
           [](const List& l, const py::slice& s) {
             std::size_t start = 0, stop = 0, step = 0, count = 0;
             if (!s.compute(l.size(), &start, &stop, &step, &count)) throw py::error_already_set();
             py::list copies;  // a slice is a new Python list of copies, as for a list
             for (std::size_t k = 0; k < count; ++k) copies.append(py::cast(l[start + k * step]));
             return copies;
           })
      .def("__setitem__",
           [](List& l, py::ssize_t i, const T& value) { assign_item(l[checked_index(i, l.size())], value); })
      .def(
          "__iter__", [](List& l) { return py::make_iterator<py::return_value_policy::reference_internal>(l.begin(), l.end()); },
          py::keep_alive<0, 1>())
      .def("append", [what](List& l, const T& value) {
        refuse_if_in_use(l, what);
        l.push_back(value);
      })
      .def("insert", [what](List& l, py::ssize_t i, const T& value) {
        refuse_if_in_use(l, what);
        const py::ssize_t n = static_cast<py::ssize_t>(l.size());
        const py::ssize_t at = std::clamp(i < 0 ? i + n : i, py::ssize_t{0}, n);
        l.insert(l.begin() + at, value);
      })
      .def(
          "pop",
          [what](List& l, py::ssize_t i) {
            const std::size_t at = checked_index(i, l.size());
            refuse_if_in_use(l, what);
            T value = l[at];
            l.erase(l.begin() + static_cast<std::ptrdiff_t>(at));
            return value;
          },
          py::arg("index") = -1)
      .def(
          "copy",
          [](const List& l) {
            py::list copies;
            for (const T& item : l) copies.append(py::cast(T(item)));
            return copies;
          },
          "a Python list of copies of the items (independent of the vehicle)")
      .def("__add__",
           [](const List& l, const py::iterable& other) {
             py::list out;  // a new Python list, as list + list gives: copies, then the other's items
             for (const T& item : l) out.append(py::cast(T(item)));
             for (py::handle h : other) out.append(h);
             return out;
           })
      .def("__radd__",
           [](const List& l, const py::iterable& other) {
             py::list out;
             for (py::handle h : other) out.append(h);
             for (const T& item : l) out.append(py::cast(T(item)));
             return out;
           })
      .def("__repr__", [name](const List& l) {
        std::string text = std::string(name) + "[";
        for (std::size_t i = 0; i < l.size(); ++i) {
          const py::str item_text = py::repr(py::cast(l[i]));
          text += std::string(i ? ", " : "") + std::string(item_text);
        }
        return text + "]";
      });
  py::implicitly_convertible<py::list, List>();
  py::implicitly_convertible<py::tuple, List>();
}

// The Python items of `values` to assign to `list`, as a vector. Items of `values` that are
// references into `list` itself (the filter idiom [e for e in car.elements if ...]) are replaced
// in the Python list by copies first, so that they do not count as held and do not dangle.
template <typename T>
std::vector<T> values_for(const std::vector<T>& list, const py::handle& values) {
  if (py::isinstance<std::vector<T>>(values)) return values.cast<const std::vector<T>&>();
  std::vector<T> out;
  if (py::isinstance<py::list>(values)) {
    py::list items = py::reinterpret_borrow<py::list>(values);
    for (std::size_t k = 0; k < items.size(); ++k) {
      const py::object item = items[k];
      if (!py::isinstance<T>(item)) continue;
      const T* p = &item.cast<const T&>();
      if (!list.empty() && p >= list.data() && p < list.data() + list.size()) items[k] = py::cast(T(*p));
    }
  }
  for (py::handle h : py::reinterpret_borrow<py::iterable>(values)) out.push_back(h.cast<T>());
  return out;
}

}  // namespace

void assign_list(std::vector<Body>& list, const py::handle& values, const char* what) {
  const std::vector<Body> v = values_for(list, values);
  assign(list, v, what);
}
void assign_list(std::vector<Element>& list, const py::handle& values, const char* what) {
  const std::vector<Element> v = values_for(list, values);
  assign(list, v, what);
}
void assign_list(std::vector<SpringStage>& list, const py::handle& values, const char* what) {
  const std::vector<SpringStage> v = values_for(list, values);
  assign(list, v, what);
}

void bind_vehicle_lists(py::module_& m) {
  bind_list<Body>(m, "BodyList", "bodies", "vehicle.bodies");
  bind_list<Element>(m, "ElementList", "elements", "vehicle.elements");
  bind_list<SpringStage>(m, "SpringStageList", "spring stages", "the element's stages");
}

}  // namespace railmodal::python
