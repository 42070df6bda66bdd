// Where the study reader (input) and the study plan (study) meet: the reader fills the plan
// from the study file, the plan lists its variants, and the reader reads those asked for.
// Neither layer calls the other.
#include "load_study.hpp"

#include <algorithm>
#include <initializer_list>
#include <map>
#include <optional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "input/study_reader.hpp"
#include "railmodal/errors.hpp"
#include "input/document_readers.hpp"
#include "input/table_reader.hpp"
#include "study/metrics.hpp"
#include "study/offered_metrics.hpp"
#include "study/period_notes.hpp"
#include "study/planned_variants.hpp"

namespace railmodal {

namespace detail {

// What read_variant needs to read any variant later: the study file read and its variants.
struct StudySource {
  input::StudyFile file;
  study::PlannedVariants variants;  // made from their index when asked for
};

}  // namespace detail

namespace {

// Whether a variant of the plan sets a key whose path starts with one of `prefixes` (in the
// vehicle file, or with `scene` in the scene file).
bool overrides_under(const study::StudyPlan& plan, bool scene, std::initializer_list<const char*> prefixes) {
  const auto under = [&](const std::string& key) {
    return std::any_of(prefixes.begin(), prefixes.end(), [&](const char* p) { return key.rfind(p, 0) == 0; });
  };
  for (const study::VariantSpec& spec : plan.variants)
    for (const study::Assignment& a : spec.assignments)
      if (a.scene == scene && under(a.key)) return true;
  for (const study::Sweep& sweep : plan.sweeps)
    for (const study::SweepParameter& p : sweep.parameters)
      if (p.scene == scene && under(p.key)) return true;
  return false;
}

// The study's vehicle files read as written, once each; *complete false when one does not read
// alone (the variant that reads it reports why).
std::vector<Vehicle> vehicles_as_written(const input::StudyFile& file, bool* complete) {
  std::vector<Vehicle> vehicles;
  vehicles.reserve(file.vehicle_documents.size());
  *complete = true;
  for (const auto& [path, document] : file.vehicle_documents) {
    try {
      vehicles.push_back(input::read_vehicle(document, path));
    } catch (const InputError&) {
      *complete = false;
    }
  }
  return vehicles;
}

// What the study's scene and vehicle files (read as written) offer its ranking
// (study/offered_metrics.hpp), pointing into `file` and `vehicles`.
study::OfferedMetrics offered_by(const input::StudyFile& file, const std::vector<Vehicle>& vehicles, bool complete) {
  study::OfferedMetrics offered;
  offered.scene_file = file.scene_file;
  offered.scene = &file.base_scene;
  for (const Vehicle& v : vehicles) offered.vehicles.push_back(&v);
  offered.vehicles_complete = complete;
  offered.vehicle_may_gain_wheelsets = overrides_under(file.plan, false, {"wheelset"});
  offered.scene_may_change_ride = overrides_under(file.plan, true, {"ride", "source"});
  offered.scene_may_add_sources = overrides_under(file.plan, true, {"source"});
  return offered;
}

// The warnings of the study's base vehicle file and its scene as written (not a variant's
// overrides), appended to `warnings`: the input a user wrote, said once rather than by every
// variant that reads it. A base file that does not read alone (its variants' overrides complete
// it) has none: the variants that read it report what is wrong.
void append_base_warnings(const input::StudyFile& file, std::vector<std::string>* warnings) {
  const std::string& path = file.plan.vehicle_file;
  const auto parsed = file.vehicle_documents.find(path);
  std::vector<std::string> found;
  try {
    const Vehicle base = parsed != file.vehicle_documents.end()
                             ? input::read_vehicle(parsed->second, path, &found)
                             : input::read_vehicle(input::parse_toml_file(path), path, &found);
    const std::vector<std::string> scene = scene_warnings(file.base_scene, base);
    found.insert(found.end(), scene.begin(), scene.end());
  } catch (const InputError&) {
    return;
  }
  warnings->insert(warnings->end(), found.begin(), found.end());
}

// The study file read and checked, its variants not listed (open_study).
Study opened_study(const std::string& path, size_t max_variants, std::vector<std::string>* warnings = nullptr) {
  input::StudyFile file = input::read_study_file(path, max_variants);
  // Metrics a scene without periodic sources cannot give, refused before the variants are
  // listed, as the reader refuses those that need a scene.
  study::check_periodic_source_metrics(file.plan.ranking, file.plan.deflection_rule, file.rule_place, file.path,
                                       offered_by(file, {}, true));
  study::PlannedVariants planned(file.plan);
  if (const std::optional<size_t> repeated = planned.first_repeated_name()) {
    const study::VariantSpec spec = planned.at(*repeated);
    throw InputError(file.path, spec.place.line, spec.place.column, "variant '" + spec.name + "': another variant has this name");
  }
  input::check_variants(&file);
  // The ranking's ride and hunting metrics against what the study's vehicles and scene give: a
  // metric no variant can have is refused here rather than ranked as missing in every variant.
  bool complete = true;
  const std::vector<Vehicle> vehicles = vehicles_as_written(file, &complete);
  const study::OfferedMetrics offered = offered_by(file, vehicles, complete);
  study::check_offered_metrics(file.plan.ranking, file.path, offered);
  if (warnings) append_base_warnings(file, warnings);
  Study study;
  study.name = file.plan.name;
  study.source = path;
  study.ranking = file.plan.ranking;
  study.deflection_rule = file.plan.deflection_rule;
  study.notes = study::period_notes(offered.vehicles, file.base_scene.dofs);
  study.plan = std::make_shared<detail::StudySource>(detail::StudySource{std::move(file), std::move(planned)});
  return study;
}

}  // namespace

Study load_study(const std::string& path, const std::function<bool(int index)>& read_only, size_t max_variants,
                 std::vector<std::string>* warnings) {
  Study study = opened_study(path, max_variants, warnings);
  const detail::StudySource& source = *study.plan;
  std::map<std::string, Vehicle> plain_vehicles;  // files without changes, read once
  for (int i = 0; i < static_cast<int>(source.variants.size()); ++i) {
    const study::VariantSpec spec = source.variants.at(static_cast<size_t>(i));
    if (!read_only || read_only(i)) {
      study.variants.push_back(input::read_variant(source.file, spec, &plain_vehicles));
    } else {
      StudyVariant named;
      named.name = spec.name;
      named.parameters = spec.parameters;
      named.read = false;
      study.variants.push_back(std::move(named));
    }
  }
  return study;
}

Study load_study(const std::string& path, const std::function<bool(int index)>& read_only,
                 std::vector<std::string>* warnings) {
  return load_study(path, read_only, kMaxStudyVariants, warnings);
}

Study open_study(const std::string& path, std::vector<std::string>* warnings) {
  return opened_study(path, kMaxStudyVariants, warnings);
}

namespace {

// Whether the study was opened (open_study): its variants are listed by the plan alone.
bool opened(const Study& study) { return study.variants.empty() && study.plan; }

}  // namespace

int variant_count(const Study& study) {
  return static_cast<int>(opened(study) ? study.plan->variants.size() : study.variants.size());
}

std::string variant_name(const Study& study, int index) {
  if (index < 0 || index >= variant_count(study))
    throw std::out_of_range("variant_name: the study has no variant " + std::to_string(index + 1));
  return opened(study) ? study.plan->variants.name(static_cast<size_t>(index)) : study.variants[index].name;
}

StudyVariant read_variant(const Study& study, int index) {
  StudyVariant variant;
  detail::read_variant_into(study, index, &variant);
  return variant;
}

void detail::read_variant_into(const Study& study, int index, StudyVariant* variant) {
  if (index < 0 || index >= variant_count(study))
    throw std::out_of_range("read_variant: the study has no variant " + std::to_string(index + 1));
  if (!opened(study) && study.variants[index].read) {
    *variant = study.variants[index];
    return;
  }
  if (!study.plan) throw std::invalid_argument("read_variant: variant '" + study.variants[index].name + "' was never read");
  // This thread's spec, its strings and lists kept from its previous variant: a worker reads one
  // variant after another (the spec is fully written each time).
  thread_local study::VariantSpec spec;
  study.plan->variants.at_into(static_cast<size_t>(index), &spec);
  input::read_variant_into(study.plan->file, spec, variant);
}

InputError detail::variant_input_error(const Study& study, int index, const InputError& e) {
  if (!study.plan || index < 0 || static_cast<size_t>(index) >= study.plan->variants.size()) return e;
  return input::variant_input_error(study.plan->file, study.plan->variants.at(static_cast<size_t>(index)), e);
}

std::string study::parameter_label(const Study& study, const std::string& key) {
  if (study.plan)
    for (const study::Sweep& sweep : study.plan->file.plan.sweeps)
      for (const study::SweepParameter& p : sweep.parameters)
        if ((p.scene ? "scene:" : "") + p.key == key) return p.label;
  const size_t dot = key.find_last_of(".:");  // as a sweep names an unlabelled parameter
  return dot == std::string::npos ? key : key.substr(dot + 1);
}

std::vector<std::string> study_files(const Study& study) {
  std::vector<std::string> files{study.source};
  if (!study.plan) return files;
  if (!study.plan->file.scene_file.empty()) files.push_back(study.plan->file.scene_file);  // a study may have none
  for (const auto& [file, document] : study.plan->file.vehicle_documents) files.push_back(file);
  return files;
}

}  // namespace railmodal
