// Where the study reader (input) and the study plan (study) meet: the reader fills the plan
// from the study file, the plan lists its variants, and the reader reads those asked for.
// Neither layer calls the other.
#include "load_study.hpp"

#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "input/study_reader.hpp"
#include "study/metrics.hpp"
#include "study/planned_variants.hpp"

namespace railmodal {

namespace detail {

// What read_variant needs to read any variant later: the study file read and its variants.
struct StudySource {
  input::StudyFile file;
  std::vector<study::VariantSpec> variants;
};

}  // namespace detail

Study load_study(const std::string& path, const std::function<bool(int index)>& read_only, size_t max_variants) {
  auto source = std::make_shared<detail::StudySource>();
  source->file = input::read_study_file(path, max_variants);
  source->variants = study::planned_variants(source->file.plan);
  input::check_variants(source->variants, &source->file);
  Study study;
  study.name = source->file.plan.name;
  study.source = path;
  study.ranking = source->file.plan.ranking;
  study.deflection_rule = source->file.plan.deflection_rule;
  std::map<std::string, Vehicle> plain_vehicles;  // files without changes, read once
  for (int i = 0; i < static_cast<int>(source->variants.size()); ++i) {
    const study::VariantSpec& spec = source->variants[i];
    if (!read_only || read_only(i)) {
      study.variants.push_back(input::read_variant(source->file, spec, &plain_vehicles));
    } else {
      StudyVariant named;
      named.name = spec.name;
      named.parameters = spec.parameters;
      named.read = false;
      study.variants.push_back(std::move(named));
    }
  }
  study.plan = std::move(source);
  return study;
}

Study load_study(const std::string& path, const std::function<bool(int index)>& read_only) {
  return load_study(path, read_only, kMaxStudyVariants);
}

StudyVariant read_variant(const Study& study, int index) {
  if (index < 0 || index >= static_cast<int>(study.variants.size()))
    throw std::out_of_range("read_variant: the study has no variant " + std::to_string(index + 1));
  if (study.variants[index].read) return study.variants[index];
  if (!study.plan) throw std::invalid_argument("read_variant: variant '" + study.variants[index].name + "' was never read");
  return input::read_variant(study.plan->file, study.plan->variants.at(static_cast<size_t>(index)), nullptr);
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
  files.push_back(study.plan->file.scene_file);
  for (const auto& [file, document] : study.plan->file.vehicle_documents) files.push_back(file);
  return files;
}

}  // namespace railmodal
