// Whether a study's ranking names metrics its vehicles and scene can give, checked once when the
// study is loaded (docs/studies.md, "Ranking"): a ride output no vehicle's ride has (a misspelt
// name) or one of another quantity than the metric's, a ride metric on a scene without a ride,
// hunting_speed on vehicles without wheelsets, critical speeds, peaks or a deflection rule on a
// scene without a periodic source.
// Unchecked, every variant would lack the value and the ranking would fall back to study order
// without a word.
#pragma once

#include <string>
#include <vector>

#include "railmodal/study.hpp"
#include "study/study_plan.hpp"

namespace railmodal::study {

/// What the study's vehicle files, read as written, and its scene offer the ranking.
struct OfferedMetrics {
  std::string scene_file;
  const Scene* scene = nullptr;
  std::vector<const Vehicle*> vehicles;  ///< each vehicle file of the study, read as written
  /// Some vehicle file could not be read here (its variant reports why when it is read), or a
  /// variant overrides keys that could add wheelsets or change the ride: nothing absent is
  /// refused, since a variant may have it.
  bool vehicles_complete = true;
  bool vehicle_may_gain_wheelsets = false;
  bool scene_may_change_ride = false;
  bool scene_may_add_sources = false;  ///< a variant sets a scene key under `source`
};

/// Throws InputError at the study's key (file:line:column, the key) for a metric that no
/// variant can have: a ride metric when the scene has no ride, an RMS metric naming no output of
/// the ride ("did you mean" the closest name, and the names there are) or an output of another
/// quantity (rms_acceleration: on a force: the metric that fits is named), hunting_speed when no
/// vehicle has wheelsets.
void check_offered_metrics(const Ranking& ranking, const std::string& study_file, const OfferedMetrics& offered);

/// Throws InputError at the study's key for a metric that reads the scene's critical-speed study
/// (critical speeds, peaks, dynamic deflections) or at [permissible_dynamic_deflection]
/// (`rule_place`) for an active rule, when the scene has no periodic source ([[source]]) and no
/// variant may add one: every variant would lack the value (or have +∞, "none") and pass. Reads
/// only the scene of `offered`, not its vehicles.
void check_periodic_source_metrics(const Ranking& ranking, const DeflectionRule& rule, const Place& rule_place,
                                   const std::string& study_file, const OfferedMetrics& offered);

}  // namespace railmodal::study
