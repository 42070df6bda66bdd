// A study plan's variants: the ones it writes, then each sweep's grid or seeded sample
// (docs/studies.md, "Sweeps and samples"), each made from its index.
#include "study/planned_variants.hpp"
#include "shortest_text.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <utility>

namespace railmodal::study {
namespace {

// The rest of a sweep's point once its name and assignments are written into `spec`: where it
// is written, its vehicle file, and its parameters as Study lists them. Member by member into
// the spec's own strings (a worker's, kept from its previous variant), without a string made anew.
void finish_sweep_point(const StudyPlan& plan, const Sweep& sweep, VariantSpec* spec) {
  spec->place = {sweep.line, 0};
  spec->vehicle_file = plan.vehicle_file;
  spec->parameters.resize(spec->assignments.size());
  for (size_t j = 0; j < spec->assignments.size(); ++j) {
    const Assignment& a = spec->assignments[j];
    spec->parameters[j].first.assign(a.scene ? "scene:" : "").append(a.key);
    spec->parameters[j].second = a.text;
  }
}

size_t grid_size(const Sweep& sweep) {
  size_t total = 1;  // the reader has checked that the grid fits in size_t
  for (const SweepParameter& p : sweep.parameters) total *= p.values.size();
  return total;
}

// Point n of the full grid, the first parameter varying slowest (nested loops in the order
// written): the value of each parameter.
std::vector<const WrittenValue*> grid_values(const Sweep& sweep, size_t n) {
  const std::vector<SweepParameter>& parameters = sweep.parameters;
  std::vector<const WrittenValue*> values(parameters.size());
  for (size_t j = parameters.size(); j-- > 0;) {
    values[j] = &parameters[j].values[n % parameters[j].values.size()];
    n /= parameters[j].values.size();
  }
  return values;
}

// "<sweep>: <label> = <value>, ...", or "<label> = <value>" for a sweep of one parameter named
// as its label ("ky: ky = 100 kN/m" repeated it: the user audit of 2026-11-27b).
std::string grid_name(const Sweep& sweep, const std::vector<const WrittenValue*>& values) {
  if (values.size() == 1 && sweep.parameters[0].label == sweep.name) return sweep.name + " = " + values[0]->text;
  std::string name = sweep.name;
  for (size_t j = 0; j < values.size(); ++j) name += (j ? ", " : ": ") + sweep.parameters[j].label + " = " + values[j]->text;
  return name;
}

std::string sample_name(const Sweep& sweep, size_t n) { return sweep.name + " #" + std::to_string(n + 1); }

}  // namespace

std::string WrittenNumber::text() const {
  std::string t;
  write_text(&t);
  return t;
}

void WrittenNumber::write_text(std::string* text) const {
  text->clear();
  if (integer && unit.empty()) {
    *text = std::to_string(std::llround(number));
    return;
  }
  append_shortest_text(text, number);  // in place: no temporaries (a sample point writes one per parameter)
  if (unit.empty()) return;
  *text += ' ';
  *text += unit;
}

PlannedVariants::PlannedVariants(StudyPlan plan) : plan_(std::move(plan)), size_(plan_.variants.size()) {
  for (size_t k = 0; k < plan_.sweeps.size(); ++k) {
    const Sweep& sweep = plan_.sweeps[k];
    Points points;
    points.sweep = k;
    points.first = size_;
    if (sweep.samples > 0) {
      // Point n draws the uniforms n·P ... n·P + P − 1 of the sweep's sequence (P parameters).
      points.count = static_cast<size_t>(sweep.samples);
      Xoshiro256 generator(sweep.seed);
      for (size_t n = 0; n < points.count; ++n) {
        if (n % kCheckpoint == 0) points.checkpoints.push_back(generator);
        for (size_t j = 0; j < sweep.parameters.size(); ++j) generator.next();
      }
    } else {
      points.count = grid_size(sweep);
    }
    size_ += points.count;
    points_.push_back(std::move(points));
  }
}

const PlannedVariants::Points& PlannedVariants::points_of(size_t index) const {
  const auto after = std::upper_bound(points_.begin(), points_.end(), index,
                                      [](size_t i, const Points& p) { return i < p.first; });
  return *std::prev(after);
}

VariantSpec PlannedVariants::at(size_t index) const {
  VariantSpec spec;
  at_into(index, &spec);
  return spec;
}

void PlannedVariants::at_into(size_t index, VariantSpec* into) const {
  if (index < plan_.variants.size()) {
    *into = plan_.variants[index];
    return;
  }
  const Points& points = points_of(index);
  const Sweep& sweep = plan_.sweeps[points.sweep];
  const size_t n = index - points.first;
  VariantSpec& spec = *into;
  const size_t count = sweep.parameters.size();
  spec.assignments.resize(count);
  if (sweep.samples > 0) {
    spec.name.assign(sweep.name).append(" #").append(std::to_string(n + 1));  // sample_name
    Xoshiro256 generator = points.checkpoints[n / kCheckpoint];
    for (size_t skip = (n % kCheckpoint) * count; skip > 0; --skip) generator.next();
    for (size_t j = 0; j < count; ++j) {
      const SweepParameter& p = sweep.parameters[j];
      const double u = generator.uniform();
      Assignment& a = spec.assignments[j];
      a.key = p.key;
      a.scene = p.scene;
      a.place = p.place;
      a.written = -1;
      a.drawn.number = p.from.number + u * (p.to.number - p.from.number);
      a.drawn.unit = p.from.unit;
      a.drawn.integer = p.from.integer;
      a.drawn.write_text(&a.text);
    }
  } else {
    const std::vector<const WrittenValue*> values = grid_values(sweep, n);
    spec.name = grid_name(sweep, values);
    for (size_t j = 0; j < count; ++j) {
      const SweepParameter& p = sweep.parameters[j];
      spec.assignments[j] = {p.key, p.scene, p.place, values[j]->text, values[j]->index, {}};
    }
  }
  finish_sweep_point(plan_, sweep, &spec);
}

std::string PlannedVariants::name(size_t index) const {
  if (index < plan_.variants.size()) return plan_.variants[index].name;
  const Points& points = points_of(index);
  const Sweep& sweep = plan_.sweeps[points.sweep];
  const size_t n = index - points.first;
  return sweep.samples > 0 ? sample_name(sweep, n) : grid_name(sweep, grid_values(sweep, n));
}

std::optional<size_t> PlannedVariants::first_repeated_name() const {
  // The names' hashes sorted, 16 bytes a variant rather than a set of 10^6 names; names are
  // compared only where hashes are equal.
  std::vector<std::pair<uint64_t, size_t>> hashes(size_);
  for (size_t i = 0; i < size_; ++i) hashes[i] = {std::hash<std::string>{}(name(i)), i};
  std::sort(hashes.begin(), hashes.end());
  std::optional<size_t> first;
  for (size_t a = 0; a < size_;) {
    size_t b = a + 1;
    while (b < size_ && hashes[b].first == hashes[a].first) ++b;
    for (size_t j = a + 1; j < b; ++j)  // indices ascend within a run: an earlier one with the same name
      for (size_t i = a; i < j; ++i)
        if ((!first || hashes[j].second < *first) && name(hashes[i].second) == name(hashes[j].second)) {
          first = hashes[j].second;
          break;
        }
    a = b;
  }
  return first;
}

}  // namespace railmodal::study
