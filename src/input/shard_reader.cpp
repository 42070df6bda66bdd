// The JSON of one shard's results (written by src/report/comparison_report.cpp), read back
// and checked against the study: the same study, the same deflection rule, each variant at
// its index.
#include <fstream>
#include <functional>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>

#include "input/input_file.hpp"
#include "input/shard_reader.hpp"
#include "railmodal/errors.hpp"
#include "railmodal/provenance.hpp"
#include "railmodal/study.hpp"

namespace railmodal {
namespace {

using nlohmann::json;

// A source by its number in the scene, from 1 (`source_index`, as compare's JSON and
// critical-speed's write it), as the index into the scene's sources that VariantResult keeps.
int source_of(const json& item) { return item.at("source_index").get<int>() - 1; }

VariantResult result_from_json(const json& j) {
  VariantResult r;
  r.index = j.at("index").get<int>();
  r.name = j.at("name").get<std::string>();
  for (const auto& p : j.at("parameters")) r.parameters.push_back({p.at("key").get<std::string>(), p.at("value").get<std::string>()});
  if (!j.at("failure").is_null()) r.failure = j.at("failure").get<std::string>();
  for (const auto& m : j.at("modes"))
    r.modes.push_back({m.at("name").get<std::string>(), m.at("kind").get<std::string>(), m.at("frequency_hz").get<double>(),
                       m.at("period_s").get<double>(), m.at("divergence_rate_per_s").get<double>()});
  for (const auto& s : j.at("static_deflections"))
    r.static_deflections.push_back({s.at("body").get<std::string>(), s.at("deflection_m").get<double>()});
  if (!j.at("metacentric_height_m").is_null()) r.metacentric_height = j.at("metacentric_height_m").get<double>();
  r.critical_speeds_evaluated = j.contains("critical_speeds");
  if (r.critical_speeds_evaluated)
    for (const auto& c : j.at("critical_speeds"))
      r.critical_speeds.push_back({c.at("speed_m_s").get<double>(), source_of(c),
                                   c.at("source_kind").get<std::string>(), c.at("harmonic").get<int>(),
                                   c.at("mode_name").get<std::string>(), c.at("friction_stops").get<bool>()});
  if (j.contains("peaks"))
    for (const auto& p : j.at("peaks"))
      r.peaks.push_back({source_of(p), p.at("output").get<std::string>(), p.at("quantity").get<std::string>(),
                         p.at("amplitude").get<double>(), p.at("speed_m_s").get<double>(), p.at("unbounded").get<bool>()});
  if (j.contains("hunting_speed_m_s")) {
    const json& h = j.at("hunting_speed_m_s");
    r.hunting_speed =
        h.is_string() && h.get<std::string>() == "none" ? std::numeric_limits<double>::infinity() : h.get<double>();
  }
  if (j.contains("ride")) {
    r.ride_evaluated = true;
    for (const auto& o : j.at("ride")) {
      VariantResult::RideSummary summary;
      summary.output = o.at("output").get<std::string>();
      summary.unit = o.at("unit").get<std::string>();
      summary.max_rms = o.at("max_rms").get<double>();
      if (!o.at("max_wz").is_null()) summary.max_wz = o.at("max_wz").get<double>();
      summary.unbounded = o.at("unbounded").get<bool>();
      r.ride.push_back(summary);
    }
    if (!j.at("max_nmv").is_null()) r.max_nmv = j.at("max_nmv").get<double>();
    if (j.contains("max_nmv_partial")) r.max_nmv_partial = j.at("max_nmv_partial").get<std::string>();
  }
  if (j.contains("dynamic_deflections")) {
    r.deflections_checked = true;
    for (const auto& c : j.at("dynamic_deflections")) {
      VariantResult::DeflectionCheck d;
      d.element = c.at("element").get<std::string>();
      d.stage = c.at("stage").get<std::string>();
      d.basis = c.at("basis").get<std::string>();
      d.permissible = c.at("permissible_m").get<double>();
      d.deflection = c.at("deflection_m").get<double>();
      d.speed = c.at("speed_m_s").get<double>();
      d.source = source_of(c);
      d.unbounded = c.at("unbounded").get<bool>();
      r.deflections.push_back(d);
    }
  }
  return r;
}

// Whether a result's ride writes the largest Wz under its name before 2026-11-28,
// `max_sperling_wz` (now `max_wz`, the metric's name). Such a shard is refused, as one with
// `source` for `source_index` is, but with the renamed key named: a result is evaluated again
// rather than read under two spellings.
bool wrote_sperling_key(const json& result) {
  if (!result.is_object() || !result.contains("ride") || !result.at("ride").is_array()) return false;
  for (const json& o : result.at("ride"))
    if (o.is_object() && o.contains("max_sperling_wz")) return true;
  return false;
}

// A shard that records its study file's digest (write_shard's inputs, the study file first) is of
// the study file as it is now, or its results are of variants the study no longer defines. The
// study file is hashed as it is read now (provenance_of); one that is not a regular file, and a
// shard that records no digest (a library caller, one sent over MPI), are not checked.
void check_study_digest(const json& shard, const std::string& file, const Study& study) {
  if (!shard.contains("inputs") || shard.at("inputs").empty()) return;
  const json& recorded = shard.at("inputs").at(0);
  const std::string then = recorded.at("digest").get<std::string>();
  const std::string now = provenance_of({study.source}).files.at(0).digest;
  if (!then.empty() && !now.empty() && then != now)
    throw InputError(file, 0, 0,
                     "a shard of another version of the study file: written from " +
                         recorded.at("path").get<std::string>() + " (FNV-1a 64 " + then + "), " + study.source +
                         " is now FNV-1a 64 " + now + ": evaluate the shard again");
}

// Parses a shard and checks it, handing each result to `each` as it is read: the results are
// converted one at a time and dropped from the document, so that only one is in memory at once.
// The errors are read_shard's, in its order: the JSON, the head (format, study, deflection rule,
// study digest), then the first result with missing or mistyped fields, then the first result
// at the wrong index; a result after an error is not handed on.
void parse_shard(std::istream& in, const std::string& file, const Study& study,
                 const std::function<void(VariantResult&&)>& each) {
  std::string key;          // the last key of the outermost object
  bool in_results = false;  // inside its "results" array
  bool deflections = false;  // a result holds dynamic deflections
  std::string field_error, index_error;
  const auto read_result = [&](const json& element) {
    deflections = deflections || (element.is_object() && element.contains("dynamic_deflections"));
    if (!field_error.empty()) return;
    if (wrote_sperling_key(element)) {
      field_error = "a shard from an older railmodal: its ride's 'max_sperling_wz' is now 'max_wz' (the study "
                    "metric's name, since 2026-11-28): evaluate the shard again";
      return;
    }
    VariantResult r;
    try {
      r = result_from_json(element);
    } catch (const json::exception& e) {
      field_error = std::string("a shard with missing or mistyped fields: ") + e.what();
      return;
    }
    if (index_error.empty() &&
        (r.index < 0 || r.index >= variant_count(study) || variant_name(study, r.index) != r.name))
      index_error = "variant '" + r.name + "' is not at index " + std::to_string(r.index) + " of the study";
    if (index_error.empty()) each(std::move(r));
  };
  json j;
  try {
    j = json::parse(in, [&](int depth, json::parse_event_t event, json& parsed) {
      if (depth == 1 && event == json::parse_event_t::key) key = parsed.get<std::string>();
      if (depth == 1 && event == json::parse_event_t::array_start) in_results = key == "results";
      if (depth == 1 && event == json::parse_event_t::array_end) in_results = false;
      if (!in_results || depth != 2 || (event != json::parse_event_t::object_end && event != json::parse_event_t::value &&
                                        event != json::parse_event_t::array_end))
        return true;
      read_result(parsed);
      return false;  // read: not kept in the document
    });
  } catch (const json::parse_error& e) {
    throw InputError(file, 0, 0, std::string("not a shard of railmodal compare (JSON: ") + e.what() + ")");
  }
  try {
    if (j.value("format", "") != "railmodal-compare-shard")
      throw InputError(file, 0, 0, "not a shard written by railmodal compare --shard");
    if (j.at("study").get<std::string>() != study.name || j.at("variant_count").get<size_t>() != static_cast<size_t>(variant_count(study)))
      throw InputError(file, 0, 0, "a shard of another study ('" + j.at("study").get<std::string>() + "', " +
                                       std::to_string(j.at("variant_count").get<size_t>()) + " variants), not of '" +
                                       study.name + "' (" + std::to_string(variant_count(study)) + " variants)");
    // A shard evaluated under another deflection rule would merge into a ranking it was not
    // checked for.
    static_cast<void>(j.at("results"));  // a shard without results is missing a field
    if (!j.contains("permissible_dynamic_deflection") && deflections)
      throw InputError(file, 0, 0, "a shard from an older railmodal that does not record its deflection rule: "
                                   "evaluate it again");
    const std::string rule = j.value("permissible_dynamic_deflection", "none");
    if (rule != to_string(study.deflection_rule))
      throw InputError(file, 0, 0, "a shard checked for permissible dynamic deflections by '" + rule +
                                       "', the study asks for '" + to_string(study.deflection_rule) + "'");
    check_study_digest(j, file, study);
    if (!j.at("results").is_array()) throw InputError(file, 0, 0, "a shard whose results are not an array");
  } catch (const json::exception& e) {
    throw InputError(file, 0, 0, std::string("a shard with missing or mistyped fields: ") + e.what());
  }
  if (!field_error.empty()) throw InputError(file, 0, 0, field_error);
  if (!index_error.empty()) throw InputError(file, 0, 0, index_error);
}

}  // namespace

std::vector<VariantResult> read_shard(const std::string& file, const Study& study) {
  std::ifstream in = input::open_input(file);
  return read_shard(in, file, study);
}

std::vector<VariantResult> read_shard(std::istream& in, const std::string& file, const Study& study) {
  std::vector<VariantResult> results;
  parse_shard(in, file, study, [&](VariantResult&& r) { results.push_back(std::move(r)); });
  return results;
}

void input::read_shard_each(const std::string& file, const Study& study,
                            const std::function<void(VariantResult&&)>& sink) {
  for (const bool check : {true, false}) {
    std::ifstream in = input::open_input(file);
    parse_shard(in, file, study, check ? std::function<void(VariantResult&&)>([](VariantResult&&) {}) : sink);
  }
}

}  // namespace railmodal
