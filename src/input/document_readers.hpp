// Vehicle and scene readers over an already parsed TOML document, so that a study can change
// keys of the document (its overrides) before the usual checks run. `file` names the file
// in messages; a scene's relative `vehicle` path is resolved against its folder.
#pragma once

#include <string>
#include <vector>
#include <toml.hpp>

#include "railmodal/scene.hpp"
#include "railmodal/vehicle.hpp"

namespace railmodal::input {

/// `warnings`: as load_vehicle's (input.hpp); nullptr: none are made.
Vehicle read_vehicle(const toml::value& document, const std::string& file,
                     std::vector<std::string>* warnings = nullptr);
Scene read_scene(const toml::value& document, const std::string& file);

}  // namespace railmodal::input
