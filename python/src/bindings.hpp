// The Python module's parts: one function per area of the library, each in its own file,
// registering that area's functions and types on the module (module.cpp calls them in order).
#pragma once

#include <pybind11/pybind11.h>

#include <string>
#include <vector>

#include "vehicle_lists.hpp"  // the vehicle's lists are opaque types: seen by every file

namespace railmodal::python {

/// The policy of a property returning a reference to an array its object holds: a NumPy view of
/// it that keeps the object alive, not a copy (bind_simulation.cpp, bind_ride.cpp).
inline constexpr auto kView = pybind11::return_value_policy::reference_internal;

void bind_errors(pybind11::module_& m);      // InputError, NumericalError → Python exceptions; InputWarning
void bind_model(pybind11::module_& m);       // vehicles (file, dict), assemble, Matrix Market
void bind_modes(pybind11::module_& m);       // undamped and damped modes
void bind_response(pybind11::module_& m);    // harmonic response, FRFs, critical speeds
void bind_simulation(pybind11::module_& m);  // scenes, simulate, spectra, fft-check
void bind_study(pybind11::module_& m);       // design studies (compare)
void bind_stability(pybind11::module_& m);   // hunting stability
void bind_ride(pybind11::module_& m);        // ride on random track
void bind_balance(pybind11::module_& m);     // driving gear and balancing

/// Issues each of a reader's warnings ("file:line:col: warning: ...") as a railmodal.InputWarning
/// through Python's warnings module, at the caller's line; the GIL held. Throws
/// error_already_set when a filter makes the warning an error.
void warn_input(const std::vector<std::string>& warnings);

}  // namespace railmodal::python
