// The lists of a Vehicle (bodies, elements) and of an Element (its spring stages) as opaque
// Python types whose items are references into the vehicle, so that the obvious
// `car.bodies[0].mass *= 2` changes the car (with pybind11's list conversion it changed a copy
// and nothing happened). An item is a reference into the list's storage: the storage must not
// move while Python holds an item, so every operation that can move it (a change of length)
// first checks pybind11's registry of live objects for an item still in use and refuses with a
// RuntimeError instead of leaving a dangling reference (items of the very list being assigned
// are copied first, so filtering a list into itself works). Same-length assignment copies the new
// values into the existing items, which stay valid and show the new values.
//
// PYBIND11_MAKE_OPAQUE must be seen before any conversion of these vectors in every file of the
// module: bindings.hpp includes this header.
#pragma once

#include <pybind11/pybind11.h>

#include <vector>

#include "railmodal/vehicle.hpp"

PYBIND11_MAKE_OPAQUE(std::vector<railmodal::Body>)
PYBIND11_MAKE_OPAQUE(std::vector<railmodal::Element>)
PYBIND11_MAKE_OPAQUE(std::vector<railmodal::SpringStage>)

namespace railmodal::python {

/// Binds BodyList, ElementList, SpringStageList (bind_model calls it after Body, Element,
/// SpringStage are registered).
void bind_vehicle_lists(pybind11::module_& m);

/// Assigns `values` (a list of these, or any iterable of items) to `list`: in place when the
/// length is the same, else after checking that no item of `list` is in use from Python
/// (RuntimeError naming `what`). Items of a Python list `values` that refer into `list` are
/// replaced in it by copies first (the filter idiom `[e for e in car.elements if ...]`).
void assign_list(std::vector<Body>& list, const pybind11::handle& values, const char* what);
void assign_list(std::vector<Element>& list, const pybind11::handle& values, const char* what);
void assign_list(std::vector<SpringStage>& list, const pybind11::handle& values, const char* what);

}  // namespace railmodal::python
