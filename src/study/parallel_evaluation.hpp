// The shard's variants evaluated on several threads, each result handed to a sink as soon as it
// is made: evaluate_study keeps every result, a streamed ranking (study/streamed_ranking.hpp)
// only its keys.
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "model/assembly.hpp"
#include "railmodal/linear_system.hpp"
#include "railmodal/modal.hpp"
#include "railmodal/study.hpp"
#include "ride/ride_workspace.hpp"

namespace railmodal::study {

/// Evaluates the variants of options' shard on its threads, as evaluate_study does (reading
/// unread ones in the workers with options.read_in_workers), and hands each result to `sink`
/// with its position among the shard's variants (0, 1, ... in index order). `prepare` is told
/// the number of the shard's variants before any is evaluated; `sink` is called from the
/// worker threads, concurrently, once per position. Returns the threads used. Throws
/// as evaluate_study: std::invalid_argument for invalid options or an unread variant, the
/// InputError of the lowest-index variant that could not be read.
/// With `names_written` false the sink writes no mode name (a CSV or table of the ranking):
/// each result then names only the modes its ranking reads (ModeNamesRead).
int evaluate_each(const Study& study, const EvaluationOptions& options,
                  const std::function<void(size_t shard_size)>& prepare,
                  const std::function<void(size_t position, VariantResult&& result)>& sink,
                  bool names_written = true);

/// Which mode names a variant's result carries (issue 19, item 2: naming its modes cost a
/// twentieth of a variant). `all`: every mode's and critical speed's, as evaluate_variant gives
/// them. Otherwise the lowest critical speed's mode (the tables name it) and what the
/// ranking's metrics read: for each mode named by a metric
/// `period:X`, the modes in order up to the first oscillatory one named X; for each
/// `critical_speed:X`, the critical speeds' modes in order up to the first named X; every name
/// when a variant has no such mode (so that a metric naming a mode no variant has is refused
/// with every variant's names listed, study::check_mode_names). Names not read are left empty.
/// metric_value of every metric is the same as with every name.
struct ModeNamesRead {
  bool all = true;
  std::vector<std::string> periods;          ///< X of the metrics period:X
  std::vector<std::string> critical_speeds;  ///< X of the metrics critical_speed:X
  /// The lowest critical speed's mode, which the tables and CSV name beside it (user audit
  /// 2026-11-28b, F8): one eigenspace named a variant.
  bool lowest_critical_speed = true;
};

/// The names a ranking by `ranking` reads: ModeNamesRead without `all`.
ModeNamesRead mode_names_ranked(const Ranking& ranking);

/// What every variant of a study is evaluated with (evaluate_each works them out once).
struct VariantSettings {
  DeflectionRule rule;
  std::optional<HuntingOptions> hunting;
  bool ride_rms_only = false;
  VariantWork work;  ///< variant_work_of the study's ranking
  ModeNamesRead names;
  /// Input an analysis refuses (a scene output that does not fit the vehicle, a series damper)
  /// is the variant's failure, naming the file the analysis names (evaluate_variant, a study
  /// built in code); false: its InputError is thrown, for evaluate_each to send back to the
  /// study file's variant.
  bool input_error_is_failure = false;
};

/// What a worker keeps from one variant to the next (issue 19, item 2): the assembly of the
/// base its variants differ from by coefficients (model::VariantAssembly), the two systems
/// each variant is assembled into (the swept one, and the lateral stiffness of the
/// metacentric height) and the modes of the swept one (its `Mode` objects: shapes, energy
/// shares, names), handed back after each evaluation so that their storage is reused, with the
/// variant's scene (the next variant's is assigned into it: its names and key places keep their
/// storage); and the ride solve's large arrays, for a study with a ride metric.
struct Workspace {
  model::VariantAssembly assembly;
  LinearSystem system, lateral;
  Scene scene;
  ModalResult modes;
  ride::Workspace ride;
};

/// evaluate_variant for a variant the caller gives up (a worker's, read for this evaluation):
/// its vehicle and scene are moved into the evaluation instead of copied, and it is assembled
/// by the worker's `workspace`; the result is evaluate_variant's, bit for bit. `variant` keeps
/// its name and parameters; its vehicle and scene are left valid but unspecified. Throws the
/// InputError of an analysis that refuses the variant's input (a scene output that does not fit
/// its vehicle, a series damper) unless settings.input_error_is_failure.
VariantResult evaluate_owned_variant(StudyVariant&& variant, int index, const VariantSettings& settings,
                                     Workspace* workspace);

/// The same for a variant the caller keeps (read beforehand): its vehicle is copied into the
/// workspace's system, as evaluate_variant copies it into its own.
VariantResult evaluate_in_workspace(const StudyVariant& variant, int index, const VariantSettings& settings,
                                    Workspace* workspace);

}  // namespace railmodal::study
