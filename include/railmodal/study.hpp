// railmodal — design studies: variants of a base vehicle in a scene, evaluated, compared and
// ranked (docs/studies.md describes the study file).
//
//   #include <railmodal/comparison_report.hpp>
//   #include <iostream>
//
//   int main() {
//     railmodal::Study study = railmodal::load_study("data/studies/resort_against_fette.toml");
//     std::vector<railmodal::VariantResult> results = railmodal::evaluate_study(study, {});
//     railmodal::Comparison comparison = railmodal::rank_variants(study, results);
//     railmodal::write_comparison(std::cout, comparison, railmodal::OutputFormat::table);
//   }
#pragma once

#include <cstddef>
#include <functional>
#include <istream>
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "railmodal/critical_speed.hpp"
#include "railmodal/errors.hpp"
#include "railmodal/hunting.hpp"
#include "railmodal/ride.hpp"
#include "railmodal/scene.hpp"
#include "railmodal/summary.hpp"
#include "railmodal/vehicle.hpp"

namespace railmodal {

/// What sets a variant apart from the study's base: "key = value" as written in the study
/// (scene keys carry the prefix "scene:"; another vehicle file is "vehicle = path").
using StudyParameter = std::pair<std::string, std::string>;

/// One design to evaluate: a vehicle and a scene, both checked like files of their own.
struct StudyVariant {
  std::string name;
  std::vector<StudyParameter> parameters;
  Vehicle vehicle;
  Scene scene;
  /// false: load_study named this variant but did not read it (another shard's); its vehicle
  /// and scene are empty, and read_variant reads them.
  bool read = true;
};

namespace detail {
struct StudySource;  // how to read each variant: the study file read and its variants (load_study.cpp)
}

/// Where a study file names a metric: its key ("ranking.min_period:body bounce",
/// "ranking.constraints[1].metric") and line, for an error found only once the variants are
/// evaluated (a mode name no variant has).
struct MetricPlace {
  std::string key;
  KeyPlace place;
};

/// A bound on a metric (docs/studies.md lists the metrics), SI.
struct RankingConstraint {
  std::string metric;
  std::optional<double> min;
  std::optional<double> max;
  MetricPlace written;
};

struct RankingCriterion {
  std::string metric;
  bool maximise = false;
  double weight = 1.0;  ///< weighted objective only; SI values times weights are summed
  MetricPlace written;
};

struct Ranking {
  std::vector<RankingConstraint> constraints;
  /// Lexicographic: the first criterion decides, the next breaks its ties, and so on.
  /// Weighted: the sum of weight × value (negated for maximised criteria) is minimised.
  std::vector<RankingCriterion> objective;
  bool weighted = false;
};

/// Which book's permissible dynamic deflections a study checks (springs digest §5). The
/// limit applies to the largest dynamic deflection over the scene's sources and speeds.
///   Korotkevich: axle-box springs (elements standing on the track) 40 mm in passenger cars
///   and 25 mm in bogie-less freight cars; elliptic springs of passenger cars 30 mm.
///   Lehner: elliptic springs 0.2 f_st, coil springs 30 mm, freight leaf springs 0.4 f_st
///   (f_st the stage's static deflection).
/// A stage in series takes its share k_element/k_stage of the element's deflection. An
/// undamped resonance that leaf friction does not stop exceeds every limit it stretches;
/// otherwise leaf friction is linearised at the limit itself (docs/studies.md, "Permissible
/// dynamic deflections"): for one mode, as in the book's (169a), that is exactly whether the
/// friction-limited amplitude stays within the limit. That amplitude is an upper bound of
/// where the resonance settles (it leaves out the stiffening while a series leaf holds), so the
/// check is conservative.
struct DeflectionRule {
  enum class Book { none, korotkevich, lehner };
  enum class Service { passenger, freight };
  Book book = Book::none;
  Service service = Service::passenger;
  /// By element name: a limit on the element's whole deflection, m, in place of the book's.
  std::vector<std::pair<std::string, double>> element_limits;
  bool active() const { return book != Book::none || !element_limits.empty(); }
};
const char* to_string(DeflectionRule::Book book);  ///< "none", "korotkevich", "lehner"
const char* to_string(DeflectionRule::Service service);  ///< "passenger", "freight"
/// Inverses of to_string; std::nullopt for an unknown word.
std::optional<DeflectionRule::Book> deflection_book_from_string(const std::string& word);
std::optional<DeflectionRule::Service> deflection_service_from_string(const std::string& word);
/// The rule in one line, as a shard records it to tell results of different rules apart:
/// "none", or "lehner freight" followed by the element limits ("; spring = 0.03 m", exact).
std::string to_string(const DeflectionRule& rule);

struct Study {
  std::string name;
  std::string source;  ///< the study file
  /// Base (unless base = false), variants, sweep points; empty for a study open_study opened
  /// (variant_count and variant_name give them).
  std::vector<StudyVariant> variants;
  Ranking ranking;
  DeflectionRule deflection_rule;  ///< [permissible_dynamic_deflection]; none: not checked
  /// Every analysis of each variant whatever the ranking reads (Python's evaluate_variants,
  /// which ranks nothing); false: only what the ranking reads (variant_work_of).
  bool every_analysis = false;
  /// What compare's outputs say once of the study's periods (the table's and reports' notes,
  /// the JSON's "notes"; the CSV has no place for them): the notes `railmodal modes` prints of
  /// each vehicle file as written, in the scene's DOF set, such as that a vehicle on wheelsets
  /// has its suspension modes, without the wheel–rail contact terms. Filled by load_study and
  /// open_study.
  std::vector<std::string> notes;
  std::shared_ptr<const detail::StudySource> plan;  ///< for read_variant; shared by copies
};

/// The most variants a study may hold: the base, [[variant]] tables and sweep points.
/// load_study and open_study refuse a study over it, at the table that goes over. Only
/// load_study lists the variants in memory (about 2.5 kB each, 10^6: 2.5 GB and 7.6 s on the
/// development machine; docs/studies.md); open_study lists none, and railmodal compare ranks
/// 10^6 in tens of megabytes (docs/performance.md, "Memory"). It bounds the number of shards
/// too: that many give each at most one variant.
inline constexpr std::size_t kMaxStudyVariants = 1000000;

/// Whether variant `index` is in shard `shard` of `shards` (1 <= shard <= shards): index mod
/// shards = shard − 1. Shards interleave, so each gets a like mix of the study's variants.
inline bool in_shard(int index, int shard, int shards) { return index % shards == shard - 1; }

/// Reads a study file and every variant it defines: overrides are applied to the vehicle's
/// (or scene's) TOML before the usual readers check it. Throws InputError naming the study
/// file, line, variant and key for a bad override, and the vehicle or scene file for their
/// own errors.
///
/// With `read_only`, the variants it rejects are named but not read (StudyVariant::read is
/// false): a shard reads its own share only, in its share of the time and memory (about 10 kB
/// a read variant), and a bad override in another shard's variant is that shard's error.
/// Names, sweeps and ranking are checked for the whole study either way.
///
/// `warnings`, when given, gets the warnings of the base vehicle file and of the scene as
/// written, once (as open_study's).
Study load_study(const std::string& path, const std::function<bool(int index)>& read_only = {},
                 std::vector<std::string>* warnings = nullptr);

/// Reads a study file and checks it as load_study does (names, sweeps, ranking, the vehicle
/// files), but lists none of its variants: Study::variants stays empty and each variant is
/// made from its index when asked for (variant_count, variant_name, read_variant). A study of
/// 10^6 variants opens in a few megabytes; evaluate_study reads each variant in the worker that
/// evaluates it (EvaluationOptions::read_in_workers), compare_study keeps only its keys.
/// `warnings`, when given, gets the warnings of the base vehicle file and of the scene as
/// written, appended once (load_vehicle's and scene_warnings' lines), not those of each
/// variant; without it none are made.
Study open_study(const std::string& path, std::vector<std::string>* warnings = nullptr);

/// The number of variants of the study: Study::variants', or, for an opened study, its plan's.
int variant_count(const Study& study);
/// The name of variant `index` (0 <= index < variant_count), as Study::variants[index].name
/// (std::out_of_range otherwise).
std::string variant_name(const Study& study, int index);

/// Variant `index` with its vehicle and scene: a copy of the one load_study read, or read now
/// from the study's files (throwing InputError as load_study would).
StudyVariant read_variant(const Study& study, int index);

/// The files the study is read from, whichever variants load_study read: the study file, its
/// scene and every variant's vehicle file, each once (a program must not write over them).
std::vector<std::string> study_files(const Study& study);

/// What the evaluation found for one variant (SI inside).
struct VariantResult {
  struct ModeSummary {
    std::string name;
    std::string kind;  ///< "oscillatory", "rigid-body" or "unstable"
    double frequency_hz = 0.0;
    double period_s = 0.0;
    double divergence_rate = 0.0;  ///< 1/s, unstable modes
  };
  struct CriticalSpeedSummary {
    double speed = 0.0;  ///< m/s
    int source = 0;
    std::string source_kind;
    int harmonic = 1;
    std::string mode_name;
    bool friction_stops = false;
  };
  /// The largest response of one output over the scene's speed range, for one source.
  struct PeakSummary {
    int source = 0;
    std::string output;    ///< DOF label
    std::string quantity;  ///< displacement, velocity, acceleration
    double amplitude = 0.0;  ///< largest finite value on the grid and refined peaks
    double speed = 0.0;      ///< m/s where it is
    bool unbounded = false;  ///< an undamped resonance in the range: no finite peak
  };
  /// One permissible-deflection check: an element, or one stage of it, against its limit.
  struct DeflectionCheck {
    std::string element;
    std::string stage;          ///< spring kind of the stage checked; "" for the whole element
    std::string basis;          ///< where the limit comes from ("Lehner: coil springs 30 mm")
    double permissible = 0.0;   ///< m
    double deflection = 0.0;    ///< m, the largest over sources and speeds (0 when unbounded)
    double speed = 0.0;         ///< m/s where it is
    int source = 0;
    bool unbounded = false;     ///< an undamped resonance stretches it without limit
    bool kept() const { return !unbounded && deflection <= permissible; }
  };
  int index = 0;  ///< position in Study::variants
  std::string name;
  std::vector<StudyParameter> parameters;
  std::string failure;  ///< why the variant could not be evaluated; "" when it was
  std::vector<ModeSummary> modes;  ///< in the scene's DOF set, ascending
  /// Static deflection of each body's reference point under its own and carried weight
  /// (the sum of the spring deflections between it and the track), m.
  std::vector<std::pair<std::string, double>> static_deflections;
  std::optional<double> metacentric_height;  ///< of the body named "body", m (eq. (235b))
  std::vector<CriticalSpeedSummary> critical_speeds;  ///< ascending speed
  std::vector<PeakSummary> peaks;
  /// The linear hunting critical speed (solve_hunting_stability of the lateral assembly at the
  /// vehicle's own conicity over HuntingOptions' default range, 10–500 km/h), m/s; +∞ when the
  /// vehicle is stable over the whole range, 0 when it is already unstable at the lowest speed
  /// (so that maximising it ranks such a design last). None when the study does not ask for the
  /// metric "hunting_speed", or when the vehicle has no wheelsets.
  std::optional<double> hunting_speed;
  /// The ride on the scene's random track (a scene with a `[[source]] kind = "irregularity"`
  /// and a [ride] table: solve_ride of the variant over the ride's speeds and outputs).
  struct RideSummary {
    std::string output;  ///< RideOutput::name
    std::string unit;    ///< of max_rms: "m", "m/s", "m/s^2", "N"
    double max_rms = 0.0;           ///< the largest RMS over the speeds (0 when unbounded)
    std::optional<double> max_wz;   ///< the largest Sperling Wz over the speeds, when it has one
    bool unbounded = false;         ///< an undamped mode the track excites: no finite RMS
  };
  bool ride_evaluated = false;      ///< the scene has a ride, and it was computed
  /// The scene's critical speeds and peaks were computed (VariantWork::critical_speeds); when
  /// false, critical_speeds and peaks are empty because nothing was asked, not because none exist.
  bool critical_speeds_evaluated = false;
  std::vector<RideSummary> ride;    ///< in the ride's output order
  /// The largest N_MV estimate over the floor points and speeds; none without comfort points.
  std::optional<double> max_nmv;
  /// What max_nmv covers when its floor point has no lateral or no vertical output, as the ride
  /// says it ("vertical only"; the missing axes taken as 0); "" when it is over both.
  std::string max_nmv_partial;
  bool deflections_checked = false;  ///< the study names a deflection rule
  std::vector<DeflectionCheck> deflections;  ///< every element or stage the rule limits
  /// The checks (modes, critical speeds, deflections kept) and the stage times of the
  /// evaluation; not written to shards (read_shard leaves it empty).
  AnalysisSummary summary;

  bool ok() const { return failure.empty(); }
};

/// Which of a variant's analyses in its scene a study pays for (docs/studies.md, "What is
/// computed"): modes, static deflections and the metacentric height always; the rest only when
/// the ranking reads it.
struct VariantWork {
  /// The scene's critical-speed study: critical speeds, peak responses and (with a deflection
  /// rule) the permissible dynamic deflections. Without it those stay empty.
  bool critical_speeds = true;
  /// The ride on the scene's random track, when the scene has one.
  bool ride = true;
};

/// What a study's ranking reads: critical speeds when it names lowest_critical_speed,
/// critical_speed:<mode>, peak:… or dynamic_deflection_ratio, or the study names a deflection
/// rule; the ride when it names a ride metric (max_wz, max_nmv, rms_…:). A ranking with no
/// objective and no constraint reads everything.
VariantWork variant_work_of(const Ranking& ranking, const DeflectionRule& rule);

/// Whether a metric reads the study's scene (critical speeds, peaks, dynamic deflections, the
/// ride); periods, static deflections, the metacentric height and hunting_speed need no scene.
bool metric_needs_scene(const std::string& metric);

/// Evaluates one variant: modes, static deflections, metacentric height, and as `work` asks
/// critical speeds and peak responses in its scene (when `rule` is active the permissible dynamic
/// deflections too) and the ride; when `hunting` is given the hunting speed
/// (VariantResult::hunting_speed) with those options.
/// With `ride_rms_only` the ride (a scene with random track) is solved with RideOptions::rms_only:
/// each output's max_rms bit for bit the same, no max_wz and no max_nmv (ride_rms_only(study)).
/// Never throws for a bad design: an unstable or singular vehicle, or a wheelset contact out of
/// range, is a result with its `failure`; so is, here, input an analysis refuses (a scene output
/// that does not fit the vehicle, a series damper the critical speeds do not represent), naming
/// its file, line and key. evaluate_study stops at it instead.
VariantResult evaluate_variant(const StudyVariant& variant, int index, const DeflectionRule& rule = {},
                               const std::optional<HuntingOptions>& hunting = std::nullopt,
                               bool ride_rms_only = false, const VariantWork& work = {});

/// The hunting options a study evaluates "hunting_speed" with, when its ranking names that metric
/// (HuntingOptions' defaults, one thread: the variants are spread over the threads); none otherwise,
/// and then no variant pays for it.
std::optional<HuntingOptions> hunting_options_of(const Study& study);

/// Whether a study's ride needs only each output's RMS: its ranking (objective or constraints)
/// names an rms_acceleration:<output> metric and neither max_wz nor max_nmv. evaluate_study then
/// solves the ride with RideOptions::rms_only (the same RMS bit for bit, at about 55 % of the
/// CPU), and the variants' results have no max_wz and no max_nmv (null in JSON and shards). A
/// study that names no ride metric keeps every index: its JSON reports them.
bool ride_rms_only(const Study& study);

struct EvaluationOptions {
  int threads = 0;      ///< ≥ 0; 0: std::thread::hardware_concurrency()
  int shard = 1;        ///< this process evaluates the variants with index % shards == shard − 1
  int shards = 1;
  std::function<void(double)> progress;  ///< fraction done, called from one thread at a time
  /// true: a variant load_study did not read (StudyVariant::read false) is read by the thread
  /// that evaluates it (read_variant: its overrides written into the study's parsed files, no
  /// text parsed again) and dropped once evaluated, so that reading runs on every thread and
  /// holds one vehicle per thread rather than one per variant. A variant that cannot be read
  /// (a bad override) stops the evaluation: its InputError, the lowest-index one whatever the
  /// thread count, is thrown once the threads have stopped, as load_study would have thrown it.
  /// false: every variant of the shard must have been read.
  bool read_in_workers = false;
  /// Returns false and explains in *why when an option is out of range.
  bool is_valid(std::string* why) const;
};

/// The variants of this shard, in index order; the same whatever the thread count. Each must
/// have been read (load_study with this shard, or all) unless options.read_in_workers;
/// std::invalid_argument otherwise, and for invalid options. In a study read from a file, input
/// an analysis refuses (a scene output that does not fit a variant's vehicle, a series damper the
/// critical speeds do not represent) stops it, as a variant that cannot be read does: an
/// InputError at the study file's line of the variant (or of its override that writes the key),
/// naming the variant and the error's own file and key; the lowest-index one whatever the thread
/// count. In a study built in code it is the variant's failure, as evaluate_variant makes it. `summary`, if
/// given, receives the threads, the variants evaluated and failed, and the stage time.
std::vector<VariantResult> evaluate_study(const Study& study, const EvaluationOptions& options,
                                          AnalysisSummary* summary = nullptr);

/// The value of a metric for a result, SI, or nothing when the result has no such value
/// (no mode of that name). "lowest_critical_speed" and "critical_speed:<mode>" are +∞ without
/// a critical speed in range.
std::optional<double> metric_value(const VariantResult& result, const std::string& metric);
/// "hunting_speed" is VariantResult::hunting_speed (+∞ stable throughout, 0 unstable at the lowest speed).
/// "dynamic_deflection_ratio" is the largest dynamic deflection over its permissible value
/// (≤ 1: the design keeps the book's limits; +∞ for an unbounded resonance) and
/// "dynamic_deflection_ratio:<element>" the same for one element.
/// Whether `metric` names a metric (after aliases: "critical_speed" is
/// "lowest_critical_speed", "bounce_period" is "period:body bounce", "bounce_critical_speed"
/// is "critical_speed:body bounce").
bool is_metric(const std::string& metric);
std::string canonical_metric(const std::string& metric);
/// The SI unit of a metric's values and limits: "m/s" (critical speeds, peak velocities), "m",
/// "s", "m/s^2", "rad", "rad/s", "rad/s^2", or "" for a ratio.
const char* metric_unit(const std::string& metric);
/// Whether a metric's values are the vehicle's speed (lowest_critical_speed,
/// critical_speed:<mode>, hunting_speed: m/s, reports show km/h) rather than a vibration's
/// velocity (peak:<dof>:velocity, rms_velocity:<output>: m/s as m/s). Both are "m/s" to
/// metric_unit; a limit on the first must carry its unit, a bare number on the second is m/s.
bool metric_is_vehicle_speed(const std::string& metric);

struct RankedVariant {
  VariantResult result;
  int rank = 0;            ///< 1 = best; feasible first, then infeasible, then failed
  bool feasible = false;   ///< evaluated and within every constraint
  std::vector<std::string> violations;
  std::vector<std::optional<double>> criteria;  ///< per objective criterion, SI
  std::optional<double> objective;  ///< weighted sum, or the first criterion's value
};

struct Comparison {
  std::string study;
  std::string source;
  Ranking ranking;
  DeflectionRule deflection_rule;  ///< the study's; active: results hold deflection checks
  std::vector<RankedVariant> variants;  ///< in rank order
  /// The order applied, the feasible and failed counts, and the time the ranking took.
  AnalysisSummary summary;
};

/// Ranks every variant of the study; `results` must hold each index once (from one run or
/// merged shards). Ties keep study order. Throws InputError naming the study file, line and
/// key when a metric names a mode (period:<mode>, critical_speed:<mode>) that no evaluated
/// variant has, listing the names they have: a renamed mode must not silently drop a metric.
Comparison rank_variants(const Study& study, std::vector<VariantResult> results);

/// The comparison's base design (the study's vehicle unmodified, when the study keeps it), or
/// nullptr.
const RankedVariant* comparison_base(const Comparison& comparison);
/// The best `count` evaluated designs other than the base, in rank order, feasible or not (the
/// ranking puts the feasible first; a report marks the infeasible ones).
std::vector<const RankedVariant*> best_designs(const Comparison& comparison, int count);

/// A design's critical-speed study, as a comparison report draws it.
struct DesignCurves {
  std::string label;  ///< "base", "1. softer springs", "2. soft springs (infeasible)"
  bool base = false;
  int variant = -1;  ///< the design's VariantResult::index
  CriticalSpeedStudy study;  ///< empty when the study computes no critical speeds (variant_work_of)
  /// The design's ride at the scene's ride speeds (no spectra), when the study ranks a ride metric.
  std::optional<RideResult> ride;
};
/// The response curves a comparison report draws: the base's (when it was evaluated) and the
/// best designs', in that order, and a note for each design that could not be studied.
struct ComparisonCurves {
  std::vector<DesignCurves> designs;
  std::vector<std::string> notes;  ///< "No curves for NAME: why"
};
/// Studies the base and the best `best` designs of `comparison`, as much as the study computes of
/// each variant (variant_work_of): study_critical_speeds of each when it computes critical
/// speeds, its ride when it ranks a ride metric, nothing otherwise. Reads those the study did not
/// read (results merged from shards) with read_variant. A design that cannot be solved gets a
/// note, not an exception.
ComparisonCurves comparison_curves(const Study& study, const Comparison& comparison, int best);

/// The results of one shard read back from the JSON write_shard wrote (comparison_report.hpp),
/// checked against the study: same name, same number of variants, each name at its index, and,
/// when the shard records the study file's digest (write_shard's inputs), the same bytes as the
/// study file has now. Throws InputError naming `file`.
std::vector<VariantResult> read_shard(const std::string& file, const Study& study);
/// The same from a stream (a shard received over MPI, say); messages name `origin`.
std::vector<VariantResult> read_shard(std::istream& in, const std::string& origin, const Study& study);

}  // namespace railmodal
