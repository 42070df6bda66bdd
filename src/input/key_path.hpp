// Key paths into a TOML document, for the overrides of a study (docs/studies.md):
//
//   secondary.spring.stiffness                              table keys, dot-separated
//   primary.spring[1].stiffness                             [i]: the i-th (0-based) of an array
//   element."front left spring".vertical[0].static_deflection
//                                                           a quoted or bare key applied to an
//                                                           array of tables picks the table
//                                                           whose `name` it is
#pragma once

#include <stdexcept>
#include <string>
#include <toml.hpp>

namespace railmodal::input {

/// Sets the value at `path` in `document`, replacing what is there. The last key may be
/// new (the vehicle reader then decides whether it belongs); every table and array on the
/// way must exist. Returns the path as the readers name it in their messages, with
/// positions for tables picked by name ("element[3].vertical[0].static_deflection").
/// Throws std::invalid_argument saying what does not exist or does not parse.
std::string set_at_path(toml::value& document, const std::string& path, const toml::value& value);

}  // namespace railmodal::input
