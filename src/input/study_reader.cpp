// load_study: [study], [[variant]], [[sweep]] and [ranking] (docs/studies.md). Each variant
// is its base vehicle's (or scene's) TOML with the overrides written into it, read by the
// usual readers; their complaints about an override are sent back to the study line that
// wrote it.
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <set>
#include <sstream>
#include <algorithm>

#include "input/document_readers.hpp"
#include "input/key_path.hpp"
#include "input/study_loader.hpp"
#include "input/table_reader.hpp"
#include "railmodal/errors.hpp"
#include "railmodal/study.hpp"
#include "study/metrics.hpp"
#include "study/sampling.hpp"

namespace railmodal {
namespace input {

struct Override {
  std::string key;
  bool scene = false;  // a key of the scene file, not the vehicle file
  toml::value value;
  std::string text;    // the value as shown in names and reports
  int line = 0, column = 0;
};

struct VariantSpec {
  std::string name;
  int line = 0, column = 0;
  std::string vehicle_file;
  std::vector<StudyParameter> parameters;
  std::vector<Override> overrides;
};

}  // namespace input

namespace detail {

// What read_variant needs to read any variant later: the specs, and the files parsed once.
struct StudyPlan {
  std::string path;
  std::vector<input::VariantSpec> specs;
  std::map<std::string, toml::value> vehicle_documents;
  std::string scene_file;
  toml::value scene_document;
  Scene base_scene;
  DeflectionRule rule;
  int rule_line = 0, rule_column = 0, elements_line = 0, elements_column = 0;
};

}  // namespace detail

namespace input {
namespace {

std::string shortest(double x) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, x);
  return std::string(buffer, result.ptr);
}

// A value on one line, as a study would write it; table keys sorted (the TOML library keeps
// no order), strings unquoted at the top level only.
std::string value_text(const toml::value& v, bool top = true) {
  if (v.is_string()) return top ? v.as_string().str : "\"" + v.as_string().str + "\"";
  if (v.is_integer()) return std::to_string(v.as_integer());
  if (v.is_floating()) return shortest(v.as_floating());
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

int line_of(const toml::value& v) { return static_cast<int>(v.location().line()); }
int column_of(const toml::value& v) { return static_cast<int>(v.location().column()); }

std::string resolve(const std::string& study_file, const std::string& relative) {
  const std::filesystem::path p(relative);
  return (p.is_absolute() ? p : std::filesystem::path(study_file).parent_path() / p).lexically_normal().string();
}

std::string existing_file(TableReader& t, const std::string& key) {
  const std::string file = resolve(t.file(), t.string(key));
  if (!std::filesystem::exists(file)) t.fail(key, "no such file: " + file);
  return file;
}

// A number with an optional unit after it: "40 mm" → 40, "mm"; 40 → 40, "".
struct NumberWithUnit {
  double number = 0.0;
  std::string unit;
  bool integer = false;
};

NumberWithUnit number_with_unit(TableReader& t, const std::string& key) {
  const toml::value& v = t.raw(key);
  NumberWithUnit out;
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

toml::value make_value(double x, const NumberWithUnit& like) {
  if (!like.unit.empty()) return toml::value(shortest(x) + " " + like.unit);
  if (like.integer) return toml::value(static_cast<toml::integer>(std::llround(x)));
  return toml::value(x);
}

// One parameter of a sweep, with its values (a list, or a range) or its interval (a sample).
struct SweepParameter {
  std::string key;
  bool scene = false;
  std::string label;
  std::vector<toml::value> values;
  NumberWithUnit from, to;
  bool interval = false;  // from/to without step: for samples
  int line = 0, column = 0;
};

SweepParameter read_parameter(TableReader& t, bool sample) {
  SweepParameter p;
  if (t.has("key") == t.has("scene_key")) t.fail("key", "give exactly one of key (a vehicle key) and scene_key");
  p.scene = t.has("scene_key");
  p.key = t.string(p.scene ? "scene_key" : "key");
  const size_t dot = p.key.find_last_of('.');
  p.label = t.optional_string("label").value_or(dot == std::string::npos ? p.key : p.key.substr(dot + 1));
  const toml::value& where = t.raw(p.scene ? "scene_key" : "key");
  p.line = line_of(where), p.column = column_of(where);
  if (t.has("values")) {
    if (sample) t.fail("values", "a sample draws from an interval: give from and to");
    const toml::value& list = t.raw("values");
    if (!list.is_array() || list.as_array().empty()) t.fail("values", "expected a non-empty array of values");
    p.values = list.as_array();
  } else {
    p.from = number_with_unit(t, "from");
    p.to = number_with_unit(t, "to");
    if (p.to.unit != p.from.unit) t.fail("to", "must be in the same unit as from ('" + p.from.unit + "')");
    if (!(p.to.number >= p.from.number)) t.fail("to", "must not be below from");
    if (sample) {
      if (t.has("step")) t.fail("step", "a sample draws from the interval: no step");
      if (p.from.integer && p.to.integer) t.fail("from", "a sample draws real numbers: write 1.0 rather than 1");
      p.interval = true;
    } else {
      const NumberWithUnit step = number_with_unit(t, "step");
      if (step.unit != p.from.unit) t.fail("step", "must be in the same unit as from ('" + p.from.unit + "')");
      if (!(step.number > 0.0)) t.fail("step", "must be positive");
      const double count = std::floor((p.to.number - p.from.number) / step.number * (1.0 + 1e-12)) + 1.0;
      if (count > 1e6) t.fail("step", "gives more than a million values");
      NumberWithUnit like = p.from;
      like.integer = p.from.integer && p.to.integer && step.integer;
      for (int i = 0; i < static_cast<int>(count); ++i) p.values.push_back(make_value(p.from.number + i * step.number, like));
    }
  }
  t.finish();
  return p;
}

// "a million variants" for the default limit.
std::string variants_text(size_t count) {
  return count == kMaxStudyVariants ? "a million variants" : std::to_string(count) + " variants";
}

// A sweep's parameters, and how each of its variants overrides the base vehicle (or scene).
struct SweepPlan {
  std::string name;
  std::vector<SweepParameter> parameters;
  int line = 0;  // of its parameters: where its variants come from
  std::string base_vehicle;

  VariantSpec variant(const std::string& variant_name, const std::vector<toml::value>& values) const {
    VariantSpec spec;
    spec.name = variant_name;
    spec.line = line;
    spec.vehicle_file = base_vehicle;
    for (size_t j = 0; j < parameters.size(); ++j) {
      const SweepParameter& p = parameters[j];
      const std::string text = value_text(values[j]);
      spec.overrides.push_back({p.key, p.scene, values[j], text, p.line, p.column});
      spec.parameters.push_back({(p.scene ? "scene:" : "") + p.key, text});
    }
    return spec;
  }
};

// [sweep.sample]: `count` variants drawn uniformly between each parameter's bounds, from `seed`.
void add_sampled_variants(TableReader s, const SweepPlan& plan, std::vector<VariantSpec>* specs, size_t max_variants) {
  const int count = s.count("count", 1);
  if (static_cast<size_t>(count) > max_variants - specs->size())
    s.fail("count", "would take the study over " + variants_text(max_variants) + " (each is held in memory, in every shard)");
  const int seed = s.count("seed", 0);
  s.finish();
  study::Xoshiro256 generator(static_cast<uint64_t>(seed));
  for (int i = 0; i < count; ++i) {
    std::vector<toml::value> values;
    for (const auto& p : plan.parameters) {
      const double u = generator.uniform();
      values.push_back(make_value(p.from.number + u * (p.to.number - p.from.number), p.from));
    }
    specs->push_back(plan.variant(plan.name + " #" + std::to_string(i + 1), values));
  }
}

// Full grid, the first parameter varying slowest (nested loops in the order written).
// Checked factor by factor: four parameters of 65 536 values multiply to 2^64, which a
// running product would wrap to 0 (an empty sweep, silently).
void add_grid_variants(TableReader& t, const SweepPlan& plan, std::vector<VariantSpec>* specs, size_t max_variants) {
  const std::vector<SweepParameter>& parameters = plan.parameters;
  const size_t room = max_variants - specs->size();
  size_t total = 1;
  for (const auto& p : parameters) {
    if (p.values.size() > room / total)
      t.fail("parameters", "the grid would take the study over " + variants_text(max_variants) +
                               " (each is held in memory, in every shard)");
    total *= p.values.size();
  }
  for (size_t n = 0; n < total; ++n) {
    std::vector<toml::value> values(parameters.size());
    std::string label;
    size_t rest = n;
    for (size_t j = parameters.size(); j-- > 0;) {
      values[j] = parameters[j].values[rest % parameters[j].values.size()];
      rest /= parameters[j].values.size();
    }
    for (size_t j = 0; j < parameters.size(); ++j)
      label += (j ? ", " : ": ") + parameters[j].label + " = " + value_text(values[j]);
    specs->push_back(plan.variant(plan.name + label, values));
  }
}

// Adds the sweep's variants to `specs`, which may hold `max_variants` in all.
void read_sweep(TableReader& t, int number, std::vector<VariantSpec>* specs, const std::string& base_vehicle,
                size_t max_variants) {
  SweepPlan plan;
  plan.name = t.optional_string("name").value_or("sweep " + std::to_string(number));
  const bool sample = t.has("sample");
  for (auto& p : t.tables("parameters")) plan.parameters.push_back(read_parameter(p, sample));
  if (plan.parameters.empty()) t.fail("parameters", "expected at least one parameter");
  plan.line = line_of(t.raw("parameters"));
  plan.base_vehicle = base_vehicle;
  if (sample)
    add_sampled_variants(t.table("sample"), plan, specs, max_variants);
  else
    add_grid_variants(t, plan, specs, max_variants);
  t.finish();
}

std::vector<Override> read_overrides(TableReader& t, const std::string& key, bool scene) {
  std::vector<Override> out;
  if (!t.has(key)) return out;
  const toml::value& table = t.raw(key);
  if (!table.is_table()) t.fail(key, "expected a table of key paths and values, such as { \"body.weight\" = \"30 t\" }");
  for (const auto& [path, value] : table.as_table())
    out.push_back({path, scene, value, value_text(value), line_of(value), column_of(value)});
  // Parents before their keys, whatever order the TOML library keeps.
  std::sort(out.begin(), out.end(), [](const Override& a, const Override& b) { return a.key < b.key; });
  return out;
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
    *elements_line = line_of(t.raw("elements")), *elements_column = column_of(t.raw("elements"));
    e.finish();
  }
  if (!rule.active()) t.fail("rule", "name a rule (\"korotkevich\" or \"lehner\") or give element limits");
  t.finish();
  return rule;
}

void read_ranking(TableReader& t, Ranking* ranking, bool deflections_checked) {
  const std::string method = t.optional_string("method").value_or("lexicographic");
  if (method != "lexicographic" && method != "weighted") t.fail("method", "must be \"lexicographic\" or \"weighted\"");
  ranking->weighted = method == "weighted";
  auto check_metric = [deflections_checked](TableReader& r, const std::string& key, const std::string& metric) {
    if (!is_metric(metric))
      r.fail(key, "unknown metric '" + metric +
                      "' (lowest_critical_speed, critical_speed:<mode name>, bounce_critical_speed, period:<mode name>, bounce_period, static_deflection[:<body>], "
                      "metacentric_height, peak:<dof>:<displacement|velocity|acceleration>, dynamic_deflection_ratio, "
                      "dynamic_deflection_ratio:<element>)");
    if (!deflections_checked && canonical_metric(metric).rfind("dynamic_deflection", 0) == 0)
      r.fail(key, "metric '" + metric + "' needs a [permissible_dynamic_deflection] table naming the rule");
  };
  // Shorthand constraints: min_<metric> = limit, max_<metric> = limit.
  for (const std::string& key : t.keys()) {
    if (key.rfind("min_", 0) != 0 && key.rfind("max_", 0) != 0) continue;
    RankingConstraint c;
    c.metric = canonical_metric(key.substr(4));
    check_metric(t, key, key.substr(4));
    (key[1] == 'i' ? c.min : c.max) = t.quantity(key, study::metric_quantity(c.metric));
    ranking->constraints.push_back(c);
  }
  if (t.has("constraints"))
    for (auto& r : t.tables("constraints")) {
      RankingConstraint c;
      const std::string metric = r.string("metric");
      check_metric(r, "metric", metric);
      c.metric = canonical_metric(metric);
      c.min = r.optional_quantity("min", study::metric_quantity(c.metric));
      c.max = r.optional_quantity("max", study::metric_quantity(c.metric));
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

// Reads a vehicle or scene document with the overrides of one variant written into it.
template <class Result, class Reader>
Result read_with_overrides(const toml::value& base, const std::string& file, const std::vector<const Override*>& overrides,
                           const VariantSpec& spec, const std::string& study_file, Reader reader) {
  toml::value document = base;
  std::vector<std::string> reader_paths;
  for (const Override* o : overrides) {
    try {
      reader_paths.push_back(set_at_path(document, o->key, o->value));
    } catch (const std::invalid_argument& e) {
      throw InputError(study_file, o->line, o->column, "variant '" + spec.name + "': key '" + o->key + "': " + e.what());
    }
  }
  try {
    return reader(document, file);
  } catch (const InputError& e) {
    // "key 'a.b[2].c': why" from the reader: the override that wrote that key (or a table
    // above it) is to blame.
    const std::string& message = e.message();
    if (message.rfind("key '", 0) == 0) {
      const size_t end = message.find("': ", 5);
      const std::string key = message.substr(5, end == std::string::npos ? 0 : end - 5);
      for (size_t k = 0; k < overrides.size(); ++k) {
        const std::string& p = reader_paths[k];
        if (key == p || key.rfind(p + ".", 0) == 0 || key.rfind(p + "[", 0) == 0)
          throw InputError(study_file, overrides[k]->line, overrides[k]->column,
                           "variant '" + spec.name + "': key '" + overrides[k]->key + "': " + message.substr(end + 3));
      }
    }
    throw InputError(study_file, spec.line, spec.column, "variant '" + spec.name + "': " + e.what());
  }
}

// Variant `index` of the plan read in full; `plain` caches vehicles read without overrides.
StudyVariant read_planned(const detail::StudyPlan& plan, int index, std::map<std::string, Vehicle>* plain) {
  const VariantSpec& spec = plan.specs.at(static_cast<size_t>(index));
  const std::string& path = plan.path;
  const toml::value& vehicle_document = plan.vehicle_documents.at(spec.vehicle_file);
  std::vector<const Override*> on_vehicle, on_scene;
  for (const auto& o : spec.overrides) (o.scene ? on_scene : on_vehicle).push_back(&o);
  StudyVariant variant;
  variant.name = spec.name;
  variant.parameters = spec.parameters;
  if (on_vehicle.empty() && plain) {
    const auto [cached, fresh] = plain->try_emplace(spec.vehicle_file);
    if (fresh) cached->second = read_vehicle(vehicle_document, spec.vehicle_file);
    variant.vehicle = cached->second;
  } else if (on_vehicle.empty()) {
    variant.vehicle = read_vehicle(vehicle_document, spec.vehicle_file);
  } else {
    variant.vehicle = read_with_overrides<Vehicle>(vehicle_document, spec.vehicle_file, on_vehicle, spec, path, read_vehicle);
  }
  variant.scene = on_scene.empty()
                      ? plan.base_scene
                      : read_with_overrides<Scene>(plan.scene_document, plan.scene_file, on_scene, spec, path, read_scene);
  if (plan.rule.active() && variant.scene.dofs == DofSet::lateral)
    throw InputError(path, plan.rule_line, plan.rule_column,
                     "key 'permissible_dynamic_deflection': variant '" + spec.name + "': the scene's dofs = \"lateral\" "
                     "has no bounce or pitch, so no vertical spring deflection to check (use \"vertical\" or \"all\")");
  for (const auto& [element, limit] : plan.rule.element_limits) {
    bool found = false;
    for (const Element& e : variant.vehicle.elements) found = found || (e.name == element && !e.vertical_stages.empty());
    if (!found)
      throw InputError(path, plan.elements_line, plan.elements_column,
                       "key 'permissible_dynamic_deflection.elements': variant '" + spec.name + "': no element '" +
                           element + "' with vertical springs in vehicle '" + variant.vehicle.name + "'");
  }
  return variant;
}

}  // namespace

Study load_study(const std::string& path, const std::function<bool(int index)>& read_only, size_t max_variants) {
  const toml::value document = parse_toml_file(path);
  TableReader root(document, path, "");
  auto plan = std::make_shared<detail::StudyPlan>();
  plan->path = path;
  Study study;
  study.source = path;
  TableReader head = root.table("study");
  study.name = head.optional_string("name").value_or(std::filesystem::path(path).stem().string());
  const std::string vehicle_file = existing_file(head, "vehicle");
  plan->scene_file = existing_file(head, "scene");
  const bool base = head.optional_boolean("base").value_or(true);
  head.finish();

  std::vector<VariantSpec>& specs = plan->specs;
  if (base) specs.push_back({"base", line_of(document.as_table().at("study")), 0, vehicle_file, {}, {}});
  if (root.has("variant"))
    for (auto& t : root.tables("variant")) {
      VariantSpec spec;
      spec.name = t.string("name");
      spec.line = line_of(t.raw("name")), spec.column = column_of(t.raw("name"));
      spec.vehicle_file = vehicle_file;
      if (t.has("vehicle")) {
        spec.vehicle_file = existing_file(t, "vehicle");
        spec.parameters.push_back({"vehicle", t.string("vehicle")});
      }
      spec.overrides = read_overrides(t, "overrides", false);
      for (auto& o : read_overrides(t, "scene_overrides", true)) spec.overrides.push_back(o);
      for (const auto& o : spec.overrides) spec.parameters.push_back({(o.scene ? "scene:" : "") + o.key, o.text});
      t.finish();
      if (specs.size() >= max_variants)
        throw InputError(path, spec.line, spec.column, "the study has more than " + variants_text(max_variants));
      specs.push_back(spec);
    }
  if (root.has("sweep")) {
    int number = 0;
    for (auto& t : root.tables("sweep")) read_sweep(t, ++number, &specs, vehicle_file, max_variants);
  }
  if (root.has("permissible_dynamic_deflection")) {
    plan->rule_line = line_of(root.raw("permissible_dynamic_deflection"));
    plan->rule_column = column_of(root.raw("permissible_dynamic_deflection"));
    TableReader t = root.table("permissible_dynamic_deflection");
    plan->rule = read_deflection_rule(t, &plan->elements_line, &plan->elements_column);
  }
  study.deflection_rule = plan->rule;
  if (root.has("ranking")) {
    TableReader t = root.table("ranking");
    read_ranking(t, &study.ranking, study.deflection_rule.active());
  }
  root.finish();
  if (specs.empty()) throw InputError(path, 0, 0, "no variants: base = false and no [[variant]] or [[sweep]]");

  plan->scene_document = parse_toml_file(plan->scene_file);
  plan->base_scene = read_scene(plan->scene_document, plan->scene_file);
  if (!(plan->base_scene.max_speed > 0.0))
    throw InputError(plan->scene_file, 0, 0, "the scene has no [speed] range: a study sweeps the speeds for critical speeds");
  std::set<std::string> names;
  for (const VariantSpec& spec : specs) {
    if (!names.insert(spec.name).second)
      throw InputError(path, spec.line, spec.column, "variant '" + spec.name + "': another variant has this name");
    if (!plan->vehicle_documents.count(spec.vehicle_file))
      plan->vehicle_documents[spec.vehicle_file] = parse_toml_file(spec.vehicle_file);
  }
  std::map<std::string, Vehicle> plain_vehicles;  // files without overrides, read once
  for (int i = 0; i < static_cast<int>(specs.size()); ++i) {
    if (!read_only || read_only(i)) {
      study.variants.push_back(read_planned(*plan, i, &plain_vehicles));
    } else {
      StudyVariant named;
      named.name = specs[i].name;
      named.parameters = specs[i].parameters;
      named.read = false;
      study.variants.push_back(std::move(named));
    }
  }
  study.plan = std::move(plan);
  return study;
}

}  // namespace input

Study load_study(const std::string& path, const std::function<bool(int index)>& read_only) {
  return input::load_study(path, read_only, input::kMaxStudyVariants);
}

StudyVariant read_variant(const Study& study, int index) {
  if (index < 0 || index >= static_cast<int>(study.variants.size()))
    throw std::out_of_range("read_variant: the study has no variant " + std::to_string(index + 1));
  if (study.variants[index].read) return study.variants[index];
  if (!study.plan) throw std::invalid_argument("read_variant: variant '" + study.variants[index].name + "' was never read");
  return input::read_planned(*study.plan, index, nullptr);
}

}  // namespace railmodal
