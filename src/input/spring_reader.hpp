// Reading the parts of a suspension element: spring stages (stiffness given directly, as
// flexibility, as static deflection under the carried load, or from coil, leaf or elliptic
// spring geometry) and swing hangers.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "input/table_reader.hpp"
#include "railmodal/vehicle.hpp"

namespace railmodal::input {

/// One stage. `element_load` is the static load through the whole element (N), used when
/// the stage is given by static deflection or as a leaf spring on inclined shackles and has
/// no `load` of its own; each of the stage's `count` springs carries element_load / count.
SpringStage read_spring_stage(TableReader& table, std::optional<double> element_load);

/// The stages of `key` (a table or an array of tables, in series); empty when absent.
std::vector<SpringStage> read_spring_stages(TableReader& parent, const std::string& key,
                                            std::optional<double> element_load);

/// The same for longitudinal stages, refusing leaf friction at its key: friction is taken from
/// vertical stages only (the friction criterion and its equivalent damping), so there it would
/// be read and silently ignored.
std::vector<SpringStage> read_longitudinal_stages(TableReader& parent, const std::string& key,
                                                  std::optional<double> element_load);

/// `rotational = { roll, pitch, yaw }` of an element (N·m/rad), zero when absent.
Eigen::Vector3d read_rotational_stiffness(TableReader& parent);

/// `series_dampers = [{ direction, damping, stiffness }, ...]` of an element: dampers with a
/// spring in series (direction "longitudinal", "lateral" or "vertical"); empty when absent.
std::vector<SeriesDamper> read_series_dampers(TableReader& parent);

/// The `hanger = {length, inclination}` table of an element or a cradle.
SwingHanger read_hanger(TableReader& parent);

}  // namespace railmodal::input
