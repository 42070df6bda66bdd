// Metrics the study's vehicles and scene cannot give, refused when the study is loaded.
#include "study/offered_metrics.hpp"

#include <algorithm>
#include <filesystem>
#include <set>

#include "edit_distance.hpp"
#include "railmodal/errors.hpp"
#include "railmodal/ride.hpp"
#include "study/metrics.hpp"

namespace railmodal::study {
namespace {

// The ride's outputs by name, in the order the ride reports them: the scene's, or each
// vehicle's default floor points (the first of each name).
std::vector<RideOutput> ride_outputs(const OfferedMetrics& offered) {
  if (!offered.scene->ride->outputs.empty()) return offered.scene->ride->outputs;
  std::vector<RideOutput> out;
  std::set<std::string> seen;
  for (const Vehicle* vehicle : offered.vehicles)
    for (RideOutput& o : default_ride_outputs(assemble(*vehicle, offered.scene->dofs)))
      if (seen.insert(o.name).second) out.push_back(std::move(o));
  return out;
}

// What a ride output measures, for a message: "a force", "an element's deflection", ...
std::string quantity_of(const RideOutput& o) {
  switch (o.kind) {
    case RideOutput::Kind::element_deflection: return "an element's deflection";
    case RideOutput::Kind::element_force: return "an element's force";
    case RideOutput::Kind::wheel_rail_force: return "a wheel-rail force";
    case RideOutput::Kind::point: break;
  }
  return o.quantity == ResponseQuantity::acceleration ? "an acceleration"
         : o.quantity == ResponseQuantity::velocity   ? "a velocity"
                                                      : "a displacement";
}

// What an RMS metric asks for, for a message: "an acceleration", ...
std::string quantity_of_metric(const std::string& metric) {
  const std::string unit = rms_ride_unit(metric);
  return unit == "N" ? "a force" : unit == "m" ? "a displacement" : unit == "m/s" ? "a velocity" : "an acceleration";
}

std::string quoted_list(const std::vector<std::string>& names) {
  std::string list;
  for (const std::string& n : names) list += (list.empty() ? "'" : ", '") + n + "'";
  return list;
}

}  // namespace

void check_offered_metrics(const Ranking& ranking, const std::string& study_file, const OfferedMetrics& offered) {
  if (!offered.vehicles_complete) return;
  const bool ride = offered.scene->ride && offered.scene->irregularity;
  bool outputs_found = false;
  std::vector<RideOutput> outputs;
  const auto check = [&](const std::string& metric, const MetricPlace& written) {
    const auto refuse = [&](const std::string& why) {
      throw InputError(study_file, written.place.line, written.place.column, "key '" + written.key + "': " + why);
    };
    if (metric == "hunting_speed" && !offered.vehicle_may_gain_wheelsets &&
        std::none_of(offered.vehicles.begin(), offered.vehicles.end(),
                     [](const Vehicle* v) { return !v->wheelsets.empty(); })) {
      std::vector<std::string> names;
      for (const Vehicle* v : offered.vehicles) names.push_back(v->name);
      refuse("metric 'hunting_speed' needs wheelsets, and no vehicle of the study has any (" + quoted_list(names) +
             "): the hunting speed is that of the wheel-rail contact ([[wheelset]] tables, docs/stability.md)");
    }
    if (!names_ride(metric) || offered.scene_may_change_ride) return;
    if (!ride)
      refuse("metric '" + metric + "' needs a ride, and the scene " + offered.scene_file +
             " has no [ride] table with a track irregularity source (docs/scenes.md, \"Ride scenes\")");
    const std::string output = ride_output_of(metric);
    if (output.empty()) return;
    if (!outputs_found) outputs = ride_outputs(offered), outputs_found = true;
    const auto named = std::find_if(outputs.begin(), outputs.end(), [&](const RideOutput& o) { return o.name == output; });
    if (named != outputs.end()) {
      const std::string unit = unit_of(*named);
      if (unit == rms_ride_unit(metric)) return;
      const std::string instead = rms_metric_for(unit);
      refuse("ride output '" + output + "' is " + quantity_of(*named) + " (" + unit + "), not " +
             quantity_of_metric(metric) + (instead.empty() ? "" : ": use '" + instead + output + "', its RMS in " + unit));
    }
    std::vector<std::string> names;
    const std::string* closest = nullptr;
    size_t distance = output.size() / 8 + 3;  // a few letters off, more in a long name
    for (const RideOutput& o : outputs) {
      names.push_back(o.name);
      const size_t d = edit_distance(o.name, output);
      if (d < distance) distance = d, closest = &o.name;
    }
    refuse("no ride output named '" + output + "'" + (closest ? "; did you mean '" + *closest + "'?" : ".") +
           " The ride's outputs are " + quoted_list(names) +
           (offered.scene->ride->outputs.empty() ? " (the default floor points: docs/ride.md, \"Using it\")"
                                                 : " ([[ride.output]] of the scene)"));
  };
  for (const RankingConstraint& c : ranking.constraints) check(c.metric, c.written);
  for (const RankingCriterion& c : ranking.objective) check(c.metric, c.written);
}

// A scene without a periodic source (a ride on random track alone) has no critical speeds, peaks
// or dynamic deflections: a metric that reads them, or a deflection rule, would be missing (or
// +∞, "none") in every variant and mark them all feasible (user audit 2026-11-28, F3: a
// min_critical_speed meant as the hunting speed). Where a critical speed was asked for, the
// message names the hunting speed.
void check_periodic_source_metrics(const Ranking& ranking, const DeflectionRule& rule, const Place& rule_place,
                                   const std::string& study_file, const OfferedMetrics& offered) {
  if (!offered.scene->sources.empty() || offered.scene_may_add_sources) return;
  const std::string scene = std::filesystem::path(offered.scene_file).filename().string();
  const std::string ridden =
      offered.scene->irregularity ? " (its random track is ridden, not swept for resonances)" : "";
  const auto check = [&](const std::string& metric, const MetricPlace& written) {
    if (!metric_reads_critical_speeds(metric)) return;
    const bool speed = metric == "lowest_critical_speed" || metric.rfind("critical_speed:", 0) == 0;
    std::string why = "key '" + written.key + "': metric '" + metric +
                      "' needs a periodic source ([[source]]: rail joints, a wheel flat, ...), and the scene " + scene +
                      " has none" + ridden + ", so no variant has " +
                      (speed ? "critical speeds: these are resonances with a periodic input"
                             : "its peaks or dynamic deflections");
    if (speed) {
      const std::string name = written.key.substr(written.key.rfind('.') + 1);
      const bool shorthand = name.rfind("min_", 0) == 0 || name.rfind("max_", 0) == 0;
      why += ". For the hunting (stability) critical speed, as `railmodal stability` computes it, use " +
             (shorthand ? "'" + name.substr(0, 4) + "hunting_speed'" : std::string("metric 'hunting_speed'"));
    }
    throw InputError(study_file, written.place.line, written.place.column, why + " (docs/studies.md)");
  };
  for (const RankingConstraint& c : ranking.constraints) check(c.metric, c.written);
  for (const RankingCriterion& c : ranking.objective) check(c.metric, c.written);
  if (rule.active())
    throw InputError(study_file, rule_place.line, rule_place.column,
                     "key 'permissible_dynamic_deflection': the dynamic deflections are those under the scene's "
                     "periodic sources ([[source]]), and the scene " + scene + " has none");
}

}  // namespace railmodal::study
