// The JSON of one shard's results (written by src/report/comparison_report.cpp), read back
// and checked against the study: the same study, the same deflection rule, each variant at
// its index.
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>

#include "input/input_file.hpp"
#include "railmodal/errors.hpp"
#include "railmodal/provenance.hpp"
#include "railmodal/study.hpp"

namespace railmodal {
namespace {

using nlohmann::json;

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
  for (const auto& c : j.at("critical_speeds"))
    r.critical_speeds.push_back({c.at("speed_m_s").get<double>(), c.at("source").get<int>(),
                                 c.at("source_kind").get<std::string>(), c.at("harmonic").get<int>(),
                                 c.at("mode_name").get<std::string>(), c.at("friction_stops").get<bool>()});
  for (const auto& p : j.at("peaks"))
    r.peaks.push_back({p.at("source").get<int>(), p.at("output").get<std::string>(), p.at("quantity").get<std::string>(),
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
      if (!o.at("max_sperling_wz").is_null()) summary.max_wz = o.at("max_sperling_wz").get<double>();
      summary.unbounded = o.at("unbounded").get<bool>();
      r.ride.push_back(summary);
    }
    if (!j.at("max_nmv").is_null()) r.max_nmv = j.at("max_nmv").get<double>();
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
      d.source = c.at("source").get<int>();
      d.unbounded = c.at("unbounded").get<bool>();
      r.deflections.push_back(d);
    }
  }
  return r;
}

}  // namespace

namespace {

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

}  // namespace

std::vector<VariantResult> read_shard(const std::string& file, const Study& study) {
  std::ifstream in = input::open_input(file);
  return read_shard(in, file, study);
}

std::vector<VariantResult> read_shard(std::istream& in, const std::string& file, const Study& study) {
  json j;
  try {
    j = json::parse(in);
  } catch (const json::parse_error& e) {
    throw InputError(file, 0, 0, std::string("not a shard of railmodal compare (JSON: ") + e.what() + ")");
  }
  std::vector<VariantResult> results;
  try {
    if (j.value("format", "") != "railmodal-compare-shard")
      throw InputError(file, 0, 0, "not a shard written by railmodal compare --shard");
    if (j.at("study").get<std::string>() != study.name || j.at("variant_count").get<size_t>() != static_cast<size_t>(variant_count(study)))
      throw InputError(file, 0, 0, "a shard of another study ('" + j.at("study").get<std::string>() + "', " +
                                       std::to_string(j.at("variant_count").get<size_t>()) + " variants), not of '" +
                                       study.name + "' (" + std::to_string(variant_count(study)) + " variants)");
    // A shard evaluated under another deflection rule would merge into a ranking it was not
    // checked for.
    if (!j.contains("permissible_dynamic_deflection"))
      for (const auto& r : j.at("results"))
        if (r.contains("dynamic_deflections"))
          throw InputError(file, 0, 0, "a shard from an older railmodal that does not record its deflection rule: "
                                       "evaluate it again");
    const std::string rule = j.value("permissible_dynamic_deflection", "none");
    if (rule != to_string(study.deflection_rule))
      throw InputError(file, 0, 0, "a shard checked for permissible dynamic deflections by '" + rule +
                                       "', the study asks for '" + to_string(study.deflection_rule) + "'");
    check_study_digest(j, file, study);
    for (const auto& r : j.at("results")) results.push_back(result_from_json(r));
  } catch (const json::exception& e) {
    throw InputError(file, 0, 0, std::string("a shard with missing or mistyped fields: ") + e.what());
  }
  for (const auto& r : results)
    if (r.index < 0 || r.index >= variant_count(study) || variant_name(study, r.index) != r.name)
      throw InputError(file, 0, 0, "variant '" + r.name + "' is not at index " + std::to_string(r.index) + " of the study");
  return results;
}

}  // namespace railmodal
