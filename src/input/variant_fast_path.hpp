// A study's variants built from the base vehicle read once: a key of the vehicle file that the
// probes show sets some of the vehicle's numbers to its own value (read as one quantity) and
// changes nothing else is written straight into a copy of the base vehicle, with no TOML tree
// copied and no reader run (docs/performance.md, "Studies"). Any other key, value
// or vehicle file takes the general path (the readers on the overridden TOML), whose errors
// are the study's errors.
#pragma once

#include <map>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "input/units.hpp"
#include "railmodal/vehicle.hpp"
#include "study/study_plan.hpp"

namespace railmodal::input {

struct StudyFile;

/// A key of the base vehicle file that sets numbers of the vehicle to its value and nothing
/// else, for the values probed.
struct FastKey {
  Quantity kind = Quantity::dimensionless;  ///< what the reader reads its value as
  std::vector<size_t> numbers;              ///< the numbers it sets (vehicle_numbers order)
  std::set<int> written;                    ///< the written values probed (WrittenValue::index)
  /// The intervals of samples that draw it, SI, ends and middle probed: a drawn value inside
  /// reads as its ends do (the readers' checks of one number accept an interval).
  std::vector<std::pair<double, double>> drawn;
  /// SI per unit of each unit its samples are drawn in, as the reader reads "1 <unit>": a drawn
  /// value x of that unit reads as x times it (the reader's strtod of x's shortest round-trip
  /// text is x), so the fast path multiplies instead of writing and parsing the text.
  std::vector<std::pair<std::string, double>> unit_scales;
  /// Where each of `numbers` lies when every one is a spring stage's stiffness or relative
  /// friction (what a study's keys set most), found once on the base: a variant's numbers are
  /// then written there without walking the whole vehicle for them. Empty otherwise.
  struct StagePlace {
    size_t element = 0;
    int list = 0;  ///< 0 vertical, 1 lateral, 2 longitudinal stages
    size_t stage = 0;
    bool stiffness = true;  ///< false: the relative friction
  };
  std::vector<StagePlace> places;
};

/// The base vehicle read once, and the keys the fast path sets.
struct FastPath {
  Vehicle base;
  std::map<std::string, FastKey> keys;
};

/// Probes every vehicle key of the study's sweeps and [[variant]] overrides on the base
/// vehicle: each written value, and each sample's ends and middle, read by the general path
/// and compared number by number with the base vehicle; then, with two fast keys or more, every
/// corner of the box their values span read together (the readers check some numbers against
/// each other). Nothing when the base cannot be read, no variant is on it (check_variants parsed
/// no document for it), or a corner is refused or reads as anything but the base with exactly
/// those numbers set.
std::optional<FastPath> resolve_fast_path(const StudyFile& file);

/// The variant's vehicle by the fast path, written into *vehicle, whose storage is reused where
/// it has the base's sizes (a study's worker reads each variant into the vehicle of the one
/// before); false, and *vehicle unchanged, when one of its keys or values is not one the fast
/// path knows (the caller then reads it by the general path).
bool fast_vehicle_into(const StudyFile& file, const study::VariantSpec& spec,
                       const std::vector<const study::Assignment*>& on_vehicle, Vehicle* vehicle);

}  // namespace railmodal::input
