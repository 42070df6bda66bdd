// The response curves a comparison report draws. Here, beside load_study, because results
// merged from shards come without their variants: those the report draws are read now
// (read_variant), then studied, so that the report itself reads no file and runs no analysis.
#include <exception>

#include "railmodal/ride.hpp"
#include "railmodal/study.hpp"

namespace railmodal {
namespace {

// The design's ride as the study's variants are ridden (study/evaluate_variant.cpp,
// ride_summary): the scene's ride speeds and outputs (its default floor points when it names
// none), without spectra.
RideResult design_ride(const StudyVariant& variant) {
  const Scene& scene = variant.scene;
  const LinearSystem system = assemble(variant.vehicle, scene.dofs);
  check_scene_fits(scene, system);
  RideOptions options = scene.ride->options;
  options.keep_spectra = false;
  const std::vector<RideOutput> outputs = scene.ride->outputs.empty() ? default_ride_outputs(system) : scene.ride->outputs;
  return solve_ride(system, *scene.irregularity, outputs, options);
}

}  // namespace

ComparisonCurves comparison_curves(const Study& study, const Comparison& comparison, int best) {
  // As much as the study computes of each variant: a report shows what ranks its variants, and
  // never runs an analysis the study did not (one its designs' vehicles may not allow).
  const VariantWork work = variant_work_of(comparison.ranking, comparison.deflection_rule);
  ComparisonCurves curves;
  if (!work.critical_speeds && !work.ride) return curves;
  std::vector<std::pair<const RankedVariant*, bool>> wanted;
  if (const RankedVariant* base = comparison_base(comparison); base && base->result.ok()) wanted.push_back({base, true});
  for (const RankedVariant* v : best_designs(comparison, best)) wanted.push_back({v, false});
  for (const auto& [v, base] : wanted) {
    DesignCurves d;
    // An infeasible design is drawn with its mark, base or not: the reader of a curve that looks
    // best sees that a constraint rules it out (the ranked table says which).
    d.label = (base ? "base" : std::to_string(v->rank) + ". " + v->result.name) + (v->feasible ? "" : " (infeasible)");
    d.base = base;
    d.variant = v->result.index;
    try {
      const StudyVariant variant = read_variant(study, v->result.index);
      // A ride scene has no periodic source to sweep (evaluate_variant skips it too).
      const bool sources = !(variant.scene.sources.empty() && variant.scene.irregularity);
      if (work.critical_speeds && sources) d.study = study_critical_speeds(variant.scene, variant.vehicle);
      if (work.ride && variant.scene.irregularity && variant.scene.ride) d.ride = design_ride(variant);
      curves.designs.push_back(std::move(d));
    } catch (const std::exception& e) {  // NumericalError, InputError: say so, draw the rest
      curves.notes.push_back("No curves for " + v->result.name + ": " + e.what());
    }
  }
  return curves;
}

}  // namespace railmodal
