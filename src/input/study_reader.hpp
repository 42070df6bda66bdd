// The study reader: a study file (docs/studies.md) into the study's plan, and each variant the
// plan lists into a vehicle and a scene. Each variant is its base vehicle's (or scene's) TOML
// with the variant's values written into it, read by the usual readers; their complaints
// about a value are sent back to the study line that wrote it.
#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <toml.hpp>
#include <vector>

#include "input/variant_fast_path.hpp"
#include "railmodal/errors.hpp"
#include "railmodal/study.hpp"
#include "study/study_plan.hpp"

namespace railmodal::input {

/// The limit on a study's variants is railmodal::kMaxStudyVariants (study.hpp). Every variant is
/// listed in memory, in every shard, even when not read: about 2.5 kB each, and a read one about
/// 10 kB. An explicit [[variant]] table costs about 3 kB with its parsed TOML, and 45 µs to read
/// (100 000: 320 MB, 4.7 s CPU; tools/benchmarks/study_variants_linearity.py).

/// A study file read: the plan it writes, and what reading its variants needs.
struct StudyFile {
  std::string path;
  study::StudyPlan plan;
  std::vector<toml::value> written;  ///< the values the plan's WrittenValue::index refer to
  std::string scene_file;
  toml::value scene_document;
  Scene base_scene;
  std::map<std::string, toml::value> vehicle_documents;  ///< by file, filled by check_variants
  study::Place rule_place, elements_place;  ///< [permissible_dynamic_deflection] and its elements
  std::optional<FastPath> fast;  ///< filled by check_variants; none: every variant by the readers
};

/// Reads the study file and its scene. Throws InputError at the [[variant]] or [[sweep]] that
/// takes the study over `max_variants` variants, or for anything else wrong in the file.
StudyFile read_study_file(const std::string& path, size_t max_variants);

/// Parses the vehicle files of the plan's written variants and, when it has sweeps, its base
/// vehicle file (which every sweep point varies), in study order. (That the variants have names
/// of their own is checked where they are listed: study::PlannedVariants::first_repeated_name.) Then probes
/// the keys the fast path can set (resolve_fast_path).
void check_variants(StudyFile* file);

/// One variant with its vehicle and scene; `plain` (optional) caches vehicles read without
/// changes.
StudyVariant read_variant(const StudyFile& file, const study::VariantSpec& spec, std::map<std::string, Vehicle>* plain);

/// read_variant(file, spec, nullptr) written into *variant, whose vehicle's storage is reused
/// where it has the sizes (a study's worker reads each variant into the vehicle of the one
/// before), its name and parameters copied into the variant's own (reused as well). Where it
/// throws, *variant is left valid but unspecified.
void read_variant_into(const StudyFile& file, const study::VariantSpec& spec, StudyVariant* variant);

/// An InputError raised by an analysis of a variant once read (a scene's output or source that
/// does not fit its vehicle, a series damper the critical speeds refuse) sent back to the study,
/// as the readers' errors are: to the assignment that writes the key it names in the file it
/// names (the scene's or the variant's vehicle file), else to the variant's line, naming the
/// variant and the error's own file, line and key.
InputError variant_input_error(const StudyFile& file, const study::VariantSpec& spec, const InputError& e);

/// A number written as the study writes it: "40 mm", 40 or 40.0 (a swept range's values, a
/// sample's draws).
toml::value drawn_value(const study::WrittenNumber& x);

/// The value an assignment writes into its file: the study's written value, or the drawn
/// number written as the sample's `from` is.
toml::value assignment_value(const StudyFile& file, const study::Assignment& assignment);

/// The vehicle of a variant by the general path: its base file with the variant's values
/// written into it, read by read_vehicle; errors sent back to the study line that wrote the
/// value.
Vehicle read_overridden_vehicle(const StudyFile& file, const study::VariantSpec& spec,
                                const std::vector<const study::Assignment*>& on_vehicle);

}  // namespace railmodal::input
