// The study reader: [study], [[variant]], [[sweep]], [permissible_dynamic_deflection] and
// [ranking] (docs/studies.md) into the study's plan; then each variant as its base vehicle's
// (or scene's) TOML with the variant's values written into it, read by the usual readers.
// Their complaints about a value are sent back to the study line that wrote it.
#include "input/study_reader.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <utility>

#include "input/document_readers.hpp"
#include "input/key_path.hpp"
#include "input/table_reader.hpp"
#include "input/value_place.hpp"
#include "railmodal/errors.hpp"
#include "shortest_text.hpp"

namespace railmodal::input {
namespace {

// A value on one line, as a study would write it; table keys sorted (the TOML library keeps
// no order), strings unquoted at the top level only.
std::string value_text(const toml::value& v, bool top = true) {
  if (v.is_string()) return top ? v.as_string().str : "\"" + v.as_string().str + "\"";
  if (v.is_integer()) return std::to_string(v.as_integer());
  if (v.is_floating()) return shortest_text(v.as_floating());
  if (v.is_boolean()) return v.as_boolean() ? "true" : "false";
  std::string out;
  if (v.is_array()) {
    for (const auto& item : v.as_array()) out += (out.empty() ? "" : ", ") + value_text(item, false);
    return "[" + out + "]";
  }
  if (v.is_table()) {
    std::map<std::string, const toml::value*> sorted;
    for (const auto& [key, item] : v.as_table()) sorted[key] = &item;
    for (const auto& [key, item] : sorted) out += (out.empty() ? "" : ", ") + key + " = " + value_text(*item, false);
    return "{ " + out + " }";
  }
  return "(date or time)";
}

study::Place place(const toml::value& v) {
  const KeyPlace p = place_of(v);
  return {p.line, p.column};
}

// A number with an optional unit after it: "40 mm" → 40, "mm"; 40 → 40, "".
study::WrittenNumber number_with_unit(TableReader& t, const std::string& key) {
  const toml::value& v = t.raw(key);
  study::WrittenNumber out;
  if (v.is_integer()) {
    out.number = static_cast<double>(v.as_integer());
    out.integer = true;
  } else if (v.is_floating()) {
    out.number = v.as_floating();
  } else if (v.is_string()) {
    const std::string& text = v.as_string().str;
    char* end = nullptr;
    out.number = std::strtod(text.c_str(), &end);
    if (end == text.c_str()) t.fail(key, "expected a number with its unit, such as \"40 mm\"");
    out.unit = std::string(end);
    out.unit.erase(0, out.unit.find_first_not_of(' '));
  } else {
    t.fail(key, "expected a number, or a string with a number and its unit such as \"40 mm\"");
  }
  if (!std::isfinite(out.number)) t.fail(key, "the value is not a finite number");
  return out;
}


// Keeps a value as the study writes it, for the variants that use it.
study::WrittenValue keep(const toml::value& v, StudyFile* file) {
  file->written.push_back(v);
  return {value_text(v), static_cast<int>(file->written.size() - 1)};
}

// A range whose ends differ in unit (from = "40 kg", to = "80 mm"): the end its key cannot take
// is blamed, with the reader's reason. Each end is tried by reading the base vehicle (or scene)
// with the key set to it, on this error path only; an end every reading takes, or a key no
// reading blames, leaves `to` blamed for differing from `from`. (Blaming `to` always put the
// error on the right value when `from` was wrong: the audit of 2026-11-27.)
[[noreturn]] void refuse_mixed_units(TableReader& t, const study::SweepParameter& p, const StudyFile& file,
                                     const study::WrittenNumber& from, const study::WrittenNumber& to) {
  const std::string document_file = p.scene ? file.scene_file : file.plan.vehicle_file;
  for (const char* end : {"from", "to"}) {
    const toml::value value = drawn_value(end == std::string("from") ? from : to);
    std::string path;
    try {
      toml::value document = parse_toml_file(document_file);
      path = set_at_path(document, p.key, value);
      if (p.scene)
        (void)read_scene(document, document_file);
      else
        (void)read_vehicle(document, document_file);
    } catch (const InputError& e) {
      const std::string prefix = "key '" + path + "': ";
      if (!path.empty() && e.message().rfind(prefix, 0) == 0)
        t.fail(end, "'" + value_text(value) + "' is not a value of key '" + p.key + "': " +
                        e.message().substr(prefix.size()));
    } catch (const std::exception&) {
      // A key the document cannot hold: its own error comes with the variants.
    }
  }
  t.fail("to", "must be in the same unit as from ('" + from.unit + "')");
}

// The values of a grid parameter: a list, or a range stepped through.
void read_values(TableReader& t, study::SweepParameter* p, StudyFile* file) {
  if (t.has("values")) {
    const toml::value& list = t.raw("values");
    if (!list.is_array() || list.as_array().empty()) t.fail("values", "expected a non-empty array of values");
    for (const toml::value& v : list.as_array()) p->values.push_back(keep(v, file));
    return;
  }
  const study::WrittenNumber from = number_with_unit(t, "from");
  const study::WrittenNumber to = number_with_unit(t, "to");
  if (to.unit != from.unit) refuse_mixed_units(t, *p, *file, from, to);
  if (!(to.number >= from.number)) t.fail("to", "must not be below from");
  const study::WrittenNumber step = number_with_unit(t, "step");
  if (step.unit != from.unit) t.fail("step", "must be in the same unit as from ('" + from.unit + "')");
  if (!(step.number > 0.0)) t.fail("step", "must be positive");
  const double count = std::floor((to.number - from.number) / step.number * (1.0 + 1e-12)) + 1.0;
  if (count > 1e6) t.fail("step", "gives more than a million values");
  study::WrittenNumber value = from;
  value.integer = from.integer && to.integer && step.integer;
  for (int i = 0; i < static_cast<int>(count); ++i) {
    value.number = from.number + i * step.number;
    p->values.push_back(keep(drawn_value(value), file));
  }
}

// The interval a sample draws a parameter from.
void read_interval(TableReader& t, study::SweepParameter* p, const StudyFile* file) {
  if (t.has("values")) t.fail("values", "a sample draws from an interval: give from and to");
  p->from = number_with_unit(t, "from");
  p->to = number_with_unit(t, "to");
  if (p->to.unit != p->from.unit) refuse_mixed_units(t, *p, *file, p->from, p->to);
  if (!(p->to.number >= p->from.number)) t.fail("to", "must not be below from");
  if (t.has("step")) t.fail("step", "a sample draws from the interval: no step");
  if (p->from.integer && p->to.integer) t.fail("from", "a sample draws real numbers: write 1.0 rather than 1");
}

// One parameter of a sweep, with its values (a list, or a range) or its interval (a sample).
study::SweepParameter read_parameter(TableReader& t, bool sample, StudyFile* file) {
  study::SweepParameter p;
  if (t.has("key") == t.has("scene_key")) t.fail("key", "give exactly one of key (a vehicle key) and scene_key");
  p.scene = t.has("scene_key");
  p.key = t.string(p.scene ? "scene_key" : "key");
  const size_t dot = p.key.find_last_of('.');
  p.label = t.optional_string("label").value_or(dot == std::string::npos ? p.key : p.key.substr(dot + 1));
  const toml::value& where = t.raw(p.scene ? "scene_key" : "key");
  p.place = place(where);
  if (p.scene && file->scene_file.empty())
    t.fail("scene_key", "a scene key, and the study names no scene ([study] scene = \"...\")");
  if (sample) read_interval(t, &p, file);
  else read_values(t, &p, file);
  t.finish();
  return p;
}

// "a million variants" for the limit (kMaxStudyVariants, 10^6), "64 variants" otherwise.
std::string variants_text(size_t count) {
  static_assert(kMaxStudyVariants == 1000000, "the text below names the limit");
  return count == kMaxStudyVariants ? "a million variants" : std::to_string(count) + " variants";
}

// A sweep of the study, which adds its variants to the `*listed` so far; `max_variants` in all.
study::Sweep read_sweep(TableReader& t, int number, size_t* listed, size_t max_variants, StudyFile* file) {
  study::Sweep sweep;
  sweep.name = t.optional_string("name").value_or("sweep " + std::to_string(number));
  const bool sample = t.has("sample");
  for (auto& p : t.tables("parameters")) sweep.parameters.push_back(read_parameter(p, sample, file));
  if (sweep.parameters.empty()) t.fail("parameters", "expected at least one parameter");
  sweep.line = place(t.raw("parameters")).line;
  const size_t room = max_variants - *listed;
  if (sample) {
    TableReader s = t.table("sample");
    sweep.samples = s.count("count", 1);
    if (static_cast<size_t>(sweep.samples) > room)
      s.fail("count", "would take the study over " + variants_text(max_variants) + " (each is held in memory, in every shard)");
    sweep.seed = static_cast<uint64_t>(s.count("seed", 0));
    s.finish();
    *listed += static_cast<size_t>(sweep.samples);
  } else {
    // Checked factor by factor: four parameters of 65 536 values multiply to 2^64, which a
    // running product would wrap to 0 (an empty sweep, silently).
    size_t total = 1;
    for (const auto& p : sweep.parameters) {
      if (p.values.size() > room / total)
        t.fail("parameters", "the grid would take the study over " + variants_text(max_variants) +
                                 " (each is held in memory, in every shard)");
      total *= p.values.size();
    }
    *listed += total;
  }
  t.finish();
  return sweep;
}

// The keys of an overrides table, sorted so that parents come before their keys (the TOML
// library keeps no order).
std::vector<study::Assignment> read_overrides(TableReader& t, const std::string& key, bool scene, StudyFile* file) {
  std::vector<study::Assignment> out;
  if (!t.has(key)) return out;
  if (scene && file->scene_file.empty())
    t.fail(key, "scene overrides, and the study names no scene ([study] scene = \"...\")");
  const toml::value& table = t.raw(key);
  if (!table.is_table()) t.fail(key, "expected a table of key paths and values, such as { \"body.weight\" = \"30 tf\" }");
  std::map<std::string, const toml::value*> sorted;
  for (const auto& [path, value] : table.as_table()) sorted[path] = &value;
  for (const auto& [path, value] : sorted) {
    const study::WrittenValue written = keep(*value, file);
    out.push_back({path, scene, place(*value), written.text, written.index, {}});
  }
  return out;
}

// A [[variant]]: its name, its vehicle file (the base's unless it names another) and its
// overrides.
study::VariantSpec read_variant_table(TableReader& t, const std::string& base_vehicle, StudyFile* file) {
  study::VariantSpec spec;
  spec.name = t.string("name");
  spec.place = place(t.raw("name"));
  spec.vehicle_file = base_vehicle;
  if (t.has("vehicle")) {
    spec.vehicle_file = t.existing_file("vehicle");
    spec.parameters.push_back({"vehicle", t.string("vehicle")});
  }
  spec.assignments = read_overrides(t, "overrides", false, file);
  for (auto& a : read_overrides(t, "scene_overrides", true, file)) spec.assignments.push_back(a);
  for (const auto& a : spec.assignments) spec.parameters.push_back({(a.scene ? "scene:" : "") + a.key, a.text});
  t.finish();
  return spec;
}

// [permissible_dynamic_deflection]: the book whose limits apply, the service, and limits of
// named elements.
DeflectionRule read_deflection_rule(TableReader& t, int* elements_line, int* elements_column) {
  DeflectionRule rule;
  if (const auto book = t.optional_string("rule")) {
    if (*book == "korotkevich") rule.book = DeflectionRule::Book::korotkevich;
    else if (*book == "lehner") rule.book = DeflectionRule::Book::lehner;
    else t.fail("rule", "must be \"korotkevich\" or \"lehner\" (springs digest §5)");
  }
  if (const auto service = t.optional_string("service")) {
    if (*service == "passenger") rule.service = DeflectionRule::Service::passenger;
    else if (*service == "freight") rule.service = DeflectionRule::Service::freight;
    else t.fail("service", "must be \"passenger\" or \"freight\"");
  }
  if (t.has("elements")) {
    TableReader e = t.table("elements");
    for (const std::string& name : e.keys()) rule.element_limits.push_back({name, e.positive(name, Quantity::length)});
    const study::Place at = place(t.raw("elements"));
    *elements_line = at.line, *elements_column = at.column;
    e.finish();
  }
  if (!rule.active()) t.fail("rule", "name a rule (\"korotkevich\" or \"lehner\") or give element limits");
  t.finish();
  return rule;
}

// The quantity a limit on the metric is read as, from the metric's SI unit. Vehicle files
// have no units of angular acceleration: such limits are plain numbers (rad/s²).
Quantity limit_quantity(const std::string& metric) {
  const std::string unit = metric_unit(metric);
  // A vehicle's speed (shown in km/h) needs its unit; a vibration's velocity (a peak or an RMS,
  // shown in m/s) is a velocity: a bare number is m/s.
  if (unit == "m/s") return metric_is_vehicle_speed(metric) ? Quantity::speed : Quantity::velocity;
  if (unit == "m") return Quantity::length;
  if (unit == "s") return Quantity::time;
  if (unit == "m/s^2") return Quantity::acceleration;
  if (unit == "N") return Quantity::force;
  if (unit == "rad") return Quantity::angle;
  if (unit == "rad/s") return Quantity::angular_speed;
  return Quantity::dimensionless;
}

void read_ranking(TableReader& t, Ranking* ranking, bool deflections_checked) {
  const std::string method = t.optional_string("method").value_or("lexicographic");
  if (method != "lexicographic" && method != "weighted") t.fail("method", "must be \"lexicographic\" or \"weighted\"");
  ranking->weighted = method == "weighted";
  auto check_metric = [deflections_checked](TableReader& r, const std::string& key, const std::string& metric) {
    if (!is_metric(metric))
      r.fail(key, "unknown metric '" + metric +
                      "' (lowest_critical_speed, critical_speed:<mode name>, bounce_critical_speed, period:<mode name>, bounce_period, static_deflection[:<body>], "
                      "metacentric_height, hunting_speed, peak:<dof>:<displacement|velocity|acceleration>, dynamic_deflection_ratio, "
                      "dynamic_deflection_ratio:<element>, max_wz, max_nmv, rms_acceleration:<ride output name>, "
                      "rms_velocity:, rms_displacement: and rms_force:<ride output name>)");
    if (!deflections_checked && canonical_metric(metric).rfind("dynamic_deflection", 0) == 0)
      r.fail(key, "metric '" + metric + "' needs a [permissible_dynamic_deflection] table naming the rule");
  };
  // Shorthand constraints: min_<metric> = limit, max_<metric> = limit.
  for (const std::string& key : t.keys()) {
    if (key.rfind("min_", 0) != 0 && key.rfind("max_", 0) != 0) continue;
    RankingConstraint c;
    c.metric = canonical_metric(key.substr(4));
    check_metric(t, key, key.substr(4));
    c.written = {t.key_path(key), t.place(key)};
    (key[1] == 'i' ? c.min : c.max) = t.quantity(key, limit_quantity(c.metric));
    ranking->constraints.push_back(c);
  }
  if (t.has("constraints"))
    for (auto& r : t.tables("constraints")) {
      RankingConstraint c;
      const std::string metric = r.string("metric");
      check_metric(r, "metric", metric);
      c.metric = canonical_metric(metric);
      c.written = {r.key_path("metric"), r.place("metric")};
      c.min = r.optional_quantity("min", limit_quantity(c.metric));
      c.max = r.optional_quantity("max", limit_quantity(c.metric));
      if (!c.min && !c.max) r.fail("metric", "a constraint needs min or max");
      r.finish();
      ranking->constraints.push_back(c);
    }
  if (t.has("objective"))
    for (auto& r : t.tables("objective")) {
      RankingCriterion c;
      const std::string metric = r.string("metric");
      check_metric(r, "metric", metric);
      c.metric = canonical_metric(metric);
      c.written = {r.key_path("metric"), r.place("metric")};
      const std::string goal = r.string("goal");
      if (goal != "min" && goal != "max") r.fail("goal", "must be \"min\" or \"max\"");
      c.maximise = goal == "max";
      if (r.has("weight")) {
        if (!ranking->weighted) r.fail("weight", "weights apply to method = \"weighted\" only");
        c.weight = r.positive("weight", Quantity::dimensionless);
      }
      r.finish();
      ranking->objective.push_back(c);
    }
  t.finish();
}

// [study], [[variant]] and [[sweep]]: the variants, in study order.
void read_variants(TableReader& root, const toml::value& document, size_t max_variants, StudyFile* file) {
  study::StudyPlan& plan = file->plan;
  TableReader head = root.table("study");
  plan.name = head.optional_string("name").value_or(std::filesystem::path(file->path).stem().string());
  plan.vehicle_file = head.existing_file("vehicle");
  // Optional: a study ranked only by metrics that need no scene (modes, statics, the hunting
  // speed) has none (read_study_file checks the ranking).
  if (head.has("scene")) file->scene_file = head.existing_file("scene");
  const bool base = head.optional_boolean("base").value_or(true);
  head.finish();
  if (base)
    plan.variants.push_back({"base", {place(document.as_table().at("study")).line, 0}, plan.vehicle_file, {}, {}});
  if (root.has("variant"))
    for (auto& t : root.tables("variant")) {
      study::VariantSpec spec = read_variant_table(t, plan.vehicle_file, file);
      if (plan.variants.size() >= max_variants)
        throw InputError(file->path, spec.place.line, spec.place.column,
                         "the study has more than " + variants_text(max_variants) +
                             " (each listed costs about 3 kB of memory, in every shard)");
      plan.variants.push_back(std::move(spec));
    }
  if (root.has("sweep")) {
    size_t listed = plan.variants.size();
    int number = 0;
    for (auto& t : root.tables("sweep")) plan.sweeps.push_back(read_sweep(t, ++number, &listed, max_variants, file));
  }
}

// An InputError about a vehicle or scene document with the values one variant gives its keys
// written into it (the reader's, or an analysis's of the variant read), sent back to the study:
// "key 'a.b[2].c': why" to the assignment that wrote that key (or a table above it), whose
// `reader_paths` (set_at_path's) are given in order; anything else to the variant's line, naming
// the error's own file and line.
InputError blamed_on_variant(const StudyFile& study, const study::VariantSpec& spec,
                             const std::vector<const study::Assignment*>& assignments,
                             const std::vector<std::string>& reader_paths, const InputError& e) {
  const std::string& message = e.message();
  if (message.rfind("key '", 0) == 0) {
    const size_t end = message.find("': ", 5);
    const std::string key = message.substr(5, end == std::string::npos ? 0 : end - 5);
    for (size_t k = 0; k < assignments.size() && k < reader_paths.size(); ++k) {
      const std::string& p = reader_paths[k];
      if (key == p || key.rfind(p + ".", 0) == 0 || key.rfind(p + "[", 0) == 0)
        return InputError(study.path, assignments[k]->place.line, assignments[k]->place.column,
                          "variant '" + spec.name + "': key '" + assignments[k]->key + "': " + message.substr(end + 3));
    }
  }
  return InputError(study.path, spec.place.line, spec.place.column, "variant '" + spec.name + "': " + e.what());
}

// Writes the values of `assignments` into `document`; returns their paths as the readers name
// them (set_at_path). A value that cannot be written is the assignment's error.
std::vector<std::string> write_assignments(toml::value* document, const std::vector<const study::Assignment*>& assignments,
                                           const StudyFile& study, const study::VariantSpec& spec) {
  std::vector<std::string> reader_paths;
  reader_paths.reserve(assignments.size());
  for (const study::Assignment* a : assignments) {
    try {
      reader_paths.push_back(set_at_path(*document, a->key, assignment_value(study, *a)));
    } catch (const std::invalid_argument& e) {
      throw InputError(study.path, a->place.line, a->place.column, "variant '" + spec.name + "': key '" + a->key + "': " + e.what());
    }
  }
  return reader_paths;
}

// Reads a vehicle or scene document with the values one variant gives its keys written into it.
template <class Result, class Reader>
Result read_with_assignments(const toml::value& base, const std::string& file,
                             const std::vector<const study::Assignment*>& assignments, const StudyFile& study,
                             const study::VariantSpec& spec, Reader reader) {
  toml::value document = base;
  const std::vector<std::string> reader_paths = write_assignments(&document, assignments, study, spec);
  try {
    return reader(document, file);
  } catch (const InputError& e) {
    throw blamed_on_variant(study, spec, assignments, reader_paths, e);
  }
}

// The deflection rule's demands on a variant read: vertical DOFs, and the elements it limits.
void check_rule(const StudyFile& file, const study::VariantSpec& spec, const StudyVariant& variant) {
  const DeflectionRule& rule = file.plan.deflection_rule;
  if (rule.active() && variant.scene.dofs == DofSet::lateral)
    throw InputError(file.path, file.rule_place.line, file.rule_place.column,
                     "key 'permissible_dynamic_deflection': variant '" + spec.name + "': the scene's dofs = \"lateral\" "
                     "has no bounce or pitch, so no vertical spring deflection to check (use \"vertical\" or \"all\")");
  for (const auto& [element, limit] : rule.element_limits) {
    bool found = false;
    for (const Element& e : variant.vehicle.elements) found = found || (e.name == element && !e.vertical_stages.empty());
    if (!found)
      throw InputError(file.path, file.elements_place.line, file.elements_place.column,
                       "key 'permissible_dynamic_deflection.elements': variant '" + spec.name + "': no element '" +
                           element + "' with vertical springs in vehicle '" + variant.vehicle.name + "'");
  }
}

// A study without a scene: every metric its ranking names must need none (metric_needs_scene:
// critical speeds, peaks and dynamic deflections are the scene's sources', the ride its track's),
// and it names no deflection rule. Refused at the metric's key, naming it.
void refuse_metrics_needing_a_scene(const StudyFile& file) {
  const Ranking& ranking = file.plan.ranking;
  const auto refuse = [&](const std::string& metric, const MetricPlace& written) {
    throw InputError(file.path, written.place.line, written.place.column,
                     "key '" + written.key + "': metric '" + metric +
                         "' needs a scene (the critical speeds and responses of its sources, or its ride), and "
                         "[study] names none: add scene = \"...\" (docs/studies.md)");
  };
  for (const RankingCriterion& c : ranking.objective)
    if (metric_needs_scene(c.metric)) refuse(c.metric, c.written);
  for (const RankingConstraint& c : ranking.constraints)
    if (metric_needs_scene(c.metric)) refuse(c.metric, c.written);
  if (file.plan.deflection_rule.active())
    throw InputError(file.path, file.rule_place.line, file.rule_place.column,
                     "key 'permissible_dynamic_deflection': the dynamic deflections are those under the scene's "
                     "sources, and [study] names no scene: add scene = \"...\"");
}

}  // namespace

StudyFile read_study_file(const std::string& path, size_t max_variants) {
  StudyFile file;
  file.path = path;
  const toml::value document = parse_toml_file(path);
  TableReader root(document, path, "");
  read_variants(root, document, max_variants, &file);
  study::StudyPlan& plan = file.plan;
  if (root.has("permissible_dynamic_deflection")) {
    const toml::value& where = root.raw("permissible_dynamic_deflection");
    file.rule_place = place(where);
    TableReader t = root.table("permissible_dynamic_deflection");
    plan.deflection_rule = read_deflection_rule(t, &file.elements_place.line, &file.elements_place.column);
  }
  if (root.has("ranking")) {
    TableReader t = root.table("ranking");
    read_ranking(t, &plan.ranking, plan.deflection_rule.active());
  }
  root.finish();
  // Every sweep lists at least one variant.
  if (plan.variants.empty() && plan.sweeps.empty())
    throw InputError(path, 0, 0, "no variants: base = false and no [[variant]] or [[sweep]]");

  if (file.scene_file.empty()) {
    refuse_metrics_needing_a_scene(file);
    return file;  // every variant in the default scene: no source, every DOF (Scene's defaults)
  }
  file.scene_document = parse_toml_file(file.scene_file);
  file.base_scene = read_scene(file.scene_document, file.scene_file);
  // A ride scene whose only source is random track is ridden at its [ride] speeds and has no
  // critical speeds to sweep (docs/studies.md); any other scene needs the range.
  const bool ride_only = file.base_scene.ride && file.base_scene.irregularity && file.base_scene.sources.empty();
  if (!(file.base_scene.max_speed > 0.0) && !ride_only)
    throw InputError(file.scene_file, 0, 0, "the scene has no [speed] range: a study sweeps the speeds for critical speeds");
  return file;
}

void check_variants(StudyFile* file) {
  std::vector<std::string> vehicle_files;
  for (const study::VariantSpec& spec : file->plan.variants) vehicle_files.push_back(spec.vehicle_file);
  if (!file->plan.sweeps.empty()) vehicle_files.push_back(file->plan.vehicle_file);
  for (const std::string& vehicle_file : vehicle_files)
    if (!file->vehicle_documents.count(vehicle_file)) file->vehicle_documents[vehicle_file] = parse_toml_file(vehicle_file);
  file->fast = resolve_fast_path(*file);
}

toml::value drawn_value(const study::WrittenNumber& x) {
  if (!x.unit.empty()) return toml::value(shortest_text(x.number) + " " + x.unit);
  if (x.integer) return toml::value(static_cast<toml::integer>(std::llround(x.number)));
  return toml::value(x.number);
}

toml::value assignment_value(const StudyFile& file, const study::Assignment& a) {
  return a.written >= 0 ? file.written[a.written] : drawn_value(a.drawn);
}

Vehicle read_overridden_vehicle(const StudyFile& file, const study::VariantSpec& spec,
                                const std::vector<const study::Assignment*>& on_vehicle) {
  // A variant's overrides draw no warnings: the base file's are said once (open_study).
  const auto read = [](const toml::value& document, const std::string& path) { return read_vehicle(document, path); };
  return read_with_assignments<Vehicle>(file.vehicle_documents.at(spec.vehicle_file), spec.vehicle_file, on_vehicle,
                                        file, spec, read);
}

namespace {

// read_variant's vehicle and scene written into *variant (its name and parameters left to the
// caller); its vehicle's storage reused by the fast path.
void read_into(const StudyFile& file, const study::VariantSpec& spec, std::map<std::string, Vehicle>* plain,
               StudyVariant* variant) {
  const toml::value& vehicle_document = file.vehicle_documents.at(spec.vehicle_file);
  std::vector<const study::Assignment*> on_vehicle, on_scene;
  on_vehicle.reserve(spec.assignments.size());
  for (const auto& a : spec.assignments) (a.scene ? on_scene : on_vehicle).push_back(&a);
  if (on_vehicle.empty() && plain) {
    const auto [cached, fresh] = plain->try_emplace(spec.vehicle_file);
    if (fresh) cached->second = read_vehicle(vehicle_document, spec.vehicle_file);
    variant->vehicle = cached->second;
  } else if (on_vehicle.empty()) {
    variant->vehicle = read_vehicle(vehicle_document, spec.vehicle_file);
  } else if (!fast_vehicle_into(file, spec, on_vehicle, &variant->vehicle)) {
    variant->vehicle = read_overridden_vehicle(file, spec, on_vehicle);
  }
  // Assigned (not a copy then a move): a worker's scene of the variant before keeps its
  // strings' and key places' storage.
  if (on_scene.empty())
    variant->scene = file.base_scene;
  else
    variant->scene = read_with_assignments<Scene>(file.scene_document, file.scene_file, on_scene, file, spec, read_scene);
  check_rule(file, spec, *variant);
}

}  // namespace

StudyVariant read_variant(const StudyFile& file, const study::VariantSpec& spec, std::map<std::string, Vehicle>* plain) {
  StudyVariant variant;
  variant.name = spec.name;
  variant.parameters = spec.parameters;
  read_into(file, spec, plain, &variant);
  return variant;
}

void read_variant_into(const StudyFile& file, const study::VariantSpec& spec, StudyVariant* variant) {
  read_into(file, spec, nullptr, variant);
  variant->name = spec.name;  // copied into the variant's own storage (a worker's, reused)
  variant->parameters = spec.parameters;
  variant->read = true;
}

InputError variant_input_error(const StudyFile& file, const study::VariantSpec& spec, const InputError& e) {
  // The assignments to the file the error names, and their paths as the readers name them.
  const bool scene = !file.scene_file.empty() && e.file() == file.scene_file;
  const bool vehicle = e.file() == spec.vehicle_file && file.vehicle_documents.count(spec.vehicle_file);
  std::vector<const study::Assignment*> on_file;
  for (const study::Assignment& a : spec.assignments)
    if ((scene && a.scene) || (vehicle && !a.scene)) on_file.push_back(&a);
  std::vector<std::string> reader_paths;
  if (!on_file.empty()) {
    toml::value document = scene ? file.scene_document : file.vehicle_documents.at(spec.vehicle_file);
    try {
      reader_paths = write_assignments(&document, on_file, file, spec);
    } catch (const InputError&) {
      reader_paths.clear();  // written when the variant was read: not expected; the variant's line is blamed
    }
  }
  return blamed_on_variant(file, spec, on_file, reader_paths, e);
}

}  // namespace railmodal::input
