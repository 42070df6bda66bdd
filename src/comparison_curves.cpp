// The response curves a comparison report draws. Here, beside load_study, because results
// merged from shards come without their variants: those the report draws are read now
// (read_variant), then studied, so that the report itself reads no file and runs no analysis.
#include <exception>

#include "railmodal/study.hpp"

namespace railmodal {

ComparisonCurves comparison_curves(const Study& study, const Comparison& comparison, int best) {
  std::vector<std::pair<const RankedVariant*, bool>> wanted;
  if (const RankedVariant* base = comparison_base(comparison); base && base->result.ok()) wanted.push_back({base, true});
  for (const RankedVariant* v : best_designs(comparison, best)) wanted.push_back({v, false});
  ComparisonCurves curves;
  for (const auto& [v, base] : wanted) {
    DesignCurves d;
    d.label = base ? "base" : std::to_string(v->rank) + ". " + v->result.name;
    d.base = base;
    try {
      const StudyVariant variant = read_variant(study, v->result.index);
      d.study = study_critical_speeds(variant.scene, variant.vehicle);
      curves.designs.push_back(std::move(d));
    } catch (const std::exception& e) {  // NumericalError, InputError: say so, draw the rest
      curves.notes.push_back("No curves for " + v->result.name + ": " + e.what());
    }
  }
  return curves;
}

}  // namespace railmodal
