// A study plan's variants: the ones it writes, then each sweep's grid or seeded sample
// (docs/studies.md, "Sweeps and samples").
#include "study/planned_variants.hpp"
#include "shortest_text.hpp"

#include <cmath>

#include "study/sampling.hpp"

namespace railmodal::study {
namespace {

// A variant of the sweep with the given assignments, one per parameter.
VariantSpec sweep_point(const StudyPlan& plan, const Sweep& sweep, std::string name, std::vector<Assignment> assignments) {
  VariantSpec spec;
  spec.name = std::move(name);
  spec.place = {sweep.line, 0};
  spec.vehicle_file = plan.vehicle_file;
  for (const Assignment& a : assignments) spec.parameters.push_back({(a.scene ? "scene:" : "") + a.key, a.text});
  spec.assignments = std::move(assignments);
  return spec;
}

// Seeded uniform points of the parameters' intervals, named "<sweep> #1", "#2", ...
void add_sample(const StudyPlan& plan, const Sweep& sweep, std::vector<VariantSpec>* specs) {
  Xoshiro256 generator(sweep.seed);
  for (int i = 0; i < sweep.samples; ++i) {
    std::vector<Assignment> assignments;
    for (const SweepParameter& p : sweep.parameters) {
      const double u = generator.uniform();
      WrittenNumber drawn{p.from.number + u * (p.to.number - p.from.number), p.from.unit, p.from.integer};
      assignments.push_back({p.key, p.scene, p.place, drawn.text(), -1, drawn});
    }
    specs->push_back(sweep_point(plan, sweep, sweep.name + " #" + std::to_string(i + 1), std::move(assignments)));
  }
}

// Full grid, the first parameter varying slowest (nested loops in the order written); named
// "<sweep>: <label> = <value>, ...". The reader has checked that the grid fits in size_t.
void add_grid(const StudyPlan& plan, const Sweep& sweep, std::vector<VariantSpec>* specs) {
  const std::vector<SweepParameter>& parameters = sweep.parameters;
  size_t total = 1;
  for (const SweepParameter& p : parameters) total *= p.values.size();
  for (size_t n = 0; n < total; ++n) {
    std::vector<const WrittenValue*> values(parameters.size());
    size_t rest = n;
    for (size_t j = parameters.size(); j-- > 0;) {
      values[j] = &parameters[j].values[rest % parameters[j].values.size()];
      rest /= parameters[j].values.size();
    }
    std::string label;
    std::vector<Assignment> assignments;
    for (size_t j = 0; j < parameters.size(); ++j) {
      const SweepParameter& p = parameters[j];
      label += (j ? ", " : ": ") + p.label + " = " + values[j]->text;
      assignments.push_back({p.key, p.scene, p.place, values[j]->text, values[j]->index, {}});
    }
    specs->push_back(sweep_point(plan, sweep, sweep.name + label, std::move(assignments)));
  }
}

}  // namespace

std::string WrittenNumber::text() const {
  if (!unit.empty()) return shortest_text(number) + " " + unit;
  if (integer) return std::to_string(std::llround(number));
  return shortest_text(number);
}

std::vector<VariantSpec> planned_variants(const StudyPlan& plan) {
  std::vector<VariantSpec> specs = plan.variants;
  for (const Sweep& sweep : plan.sweeps) (sweep.samples > 0 ? add_sample : add_grid)(plan, sweep, &specs);
  return specs;
}

}  // namespace railmodal::study
