// The study's fast path (variant_fast_path.hpp): which keys set only numbers, by probing them
// through the general path, and the vehicles of variants built from those keys alone.
#include "input/variant_fast_path.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>

#include "input/document_readers.hpp"
#include "input/key_path.hpp"
#include "input/study_reader.hpp"
#include "input/table_reader.hpp"
#include "input/vehicle_numbers.hpp"

namespace railmodal::input {
namespace {

// Probes of a key beyond this many (a long grid) are not worth their reads: the key takes the
// general path.
constexpr size_t kMaxProbes = 256;

// The value as the reader reads it for a quantity of `kind` (TableReader::quantity, the
// readers' own conversion and checks); nothing when it refuses it.
// The value is read as it stands, not copied into a table of its own: a study reads each
// variant's values here, and the table's hash map cost more than the conversion.
std::optional<double> read_as(const toml::value& value, Quantity kind) {
  static const toml::value kNoTable{toml::table{}};
  try {
    return TableReader(kNoTable, "", "").to_quantity(value, "v", kind);
  } catch (const InputError&) {
    return std::nullopt;
  }
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

std::vector<SpringStage>& stage_list(Element& e, int list) {
  return list == 0 ? e.vertical_stages : list == 1 ? e.lateral_stages : e.longitudinal_stages;
}

double& number_at(Vehicle& v, const FastKey::StagePlace& p) {
  SpringStage& s = stage_list(v.elements[p.element], p.list)[p.stage];
  return p.stiffness ? s.stiffness : s.relative_friction;
}

// FastKey::places of `numbers` (vehicle_numbers order) on `base`: each found among the spring
// stages' stiffnesses and frictions by its address; empty when one is elsewhere.
std::vector<FastKey::StagePlace> stage_places(Vehicle& base, const std::vector<size_t>& numbers) {
  const std::vector<double*> all = vehicle_numbers(&base);
  std::vector<FastKey::StagePlace> places;
  for (size_t i : numbers) {
    bool found = false;
    for (size_t e = 0; e < base.elements.size() && !found; ++e)
      for (int list = 0; list < 3 && !found; ++list)
        for (size_t s = 0; s < stage_list(base.elements[e], list).size() && !found; ++s)
          for (const bool stiffness : {true, false}) {
            const FastKey::StagePlace p{e, list, s, stiffness};
            if (&number_at(base, p) == all[i]) {
              places.push_back(p);
              found = true;
              break;
            }
          }
    if (!found) return {};
  }
  return places;
}

// read_as of a drawn value with a unit, without its text (FastKey::unit_scales): the value
// times its unit's scale, with the reader's checks of a finite, representable result; nothing
// when the unit was not scaled or a check fails (read_as then says what the reader does).
std::optional<double> drawn_si(const FastKey& key, const study::WrittenNumber& x) {
  if (x.unit.empty() || !std::isfinite(x.number)) return std::nullopt;
  for (const auto& [unit, scale] : key.unit_scales)
    if (unit == x.unit) {
      const double si = x.number * scale;
      if (!std::isfinite(si) || !within_magnitudes(si)) return std::nullopt;
      return si;
    }
  return std::nullopt;
}

std::vector<double> numbers_of(Vehicle vehicle) {
  std::vector<double> out;
  for (double* x : vehicle_numbers(&vehicle)) out.push_back(*x);
  return out;
}

// One probe: a value of the key, the vehicle the general path reads with it (none: refused,
// or of another shape than the base) and the numbers that differ from the base's.
struct Probe {
  toml::value value;
  int written = -1;  // WrittenValue::index, -1 for a sample's probe
  std::optional<std::vector<double>> numbers;
  std::vector<size_t> changed;
};

Probe probe(const StudyFile& file, const std::string& base_shape,
            const std::vector<double>& base, const std::string& key, const toml::value& value, int written) {
  Probe p{value, written, std::nullopt, {}};
  toml::value document = file.vehicle_documents.at(file.plan.vehicle_file);
  Vehicle vehicle;
  try {
    set_at_path(document, key, value);
    vehicle = read_vehicle(document, file.plan.vehicle_file);
  } catch (const std::exception&) {
    return p;  // refused: the general path says why
  }
  if (vehicle_shape(vehicle) != base_shape) return p;
  p.numbers = numbers_of(std::move(vehicle));
  for (size_t i = 0; i < base.size(); ++i)
    if (!same_bits((*p.numbers)[i], base[i])) p.changed.push_back(i);
  return p;
}

// Whether the probe's vehicle is the base with exactly `numbers` set to the value read as `kind`.
bool sets_only(const Probe& p, const std::vector<size_t>& numbers, Quantity kind) {
  if (!p.numbers) return false;
  const std::optional<double> si = read_as(p.value, kind);
  if (!si) return false;
  for (size_t i : p.changed)
    if (!std::binary_search(numbers.begin(), numbers.end(), i)) return false;
  for (size_t i : numbers)
    if (!same_bits((*p.numbers)[i], *si)) return false;
  return true;
}

// The key's numbers and the quantity its value is read as, from its probes; nothing when no
// probe changes a number or no quantity reads the values as the reader did.
std::optional<FastKey> resolve_key(const std::vector<Probe>& probes) {
  FastKey key;
  for (const Probe& p : probes) key.numbers.insert(key.numbers.end(), p.changed.begin(), p.changed.end());
  std::sort(key.numbers.begin(), key.numbers.end());
  key.numbers.erase(std::unique(key.numbers.begin(), key.numbers.end()), key.numbers.end());
  if (key.numbers.empty()) return std::nullopt;
  for (int q = 0; q <= static_cast<int>(Quantity::frequency); ++q) {
    const auto kind = static_cast<Quantity>(q);
    if (std::any_of(probes.begin(), probes.end(), [&](const Probe& p) { return !p.changed.empty() && sets_only(p, key.numbers, kind); })) {
      key.kind = kind;
      return key;
    }
  }
  return std::nullopt;
}

// The values each vehicle key of the study is probed with: every written value (grids and
// [[variant]] overrides of the base vehicle) and each sample's interval, by its ends and middle.
struct KeyProbes {
  std::vector<std::pair<toml::value, int>> written;
  std::vector<std::array<study::WrittenNumber, 3>> samples;
};

std::map<std::string, KeyProbes> probe_values(const StudyFile& file) {
  std::map<std::string, KeyProbes> keys;
  for (const study::Sweep& sweep : file.plan.sweeps)
    for (const study::SweepParameter& p : sweep.parameters) {
      if (p.scene) continue;
      KeyProbes& k = keys[p.key];
      if (sweep.samples > 0) {
        study::WrittenNumber middle = p.from;
        middle.number = p.from.number + (p.to.number - p.from.number) / 2.0;
        middle.integer = false;
        k.samples.push_back({p.from, p.to, middle});
      } else {
        for (const study::WrittenValue& v : p.values) k.written.push_back({file.written[v.index], v.index});
      }
    }
  for (const study::VariantSpec& spec : file.plan.variants)
    if (spec.vehicle_file == file.plan.vehicle_file)
      for (const study::Assignment& a : spec.assignments)
        if (!a.scene && a.written >= 0) keys[a.key].written.push_back({file.written[a.written], a.written});
  return keys;
}

// One end of the values a fast key takes in the study: the value to write and its number as
// read.
struct End {
  toml::value value;
  double si = 0.0;
};

// The least and largest values each fast key takes (written values probed, drawn intervals'
// ends), in the keys' order.
std::vector<std::pair<End, End>> key_ranges(const std::map<std::string, KeyProbes>& probes, const FastPath& fast) {
  std::vector<std::pair<End, End>> ranges;
  for (const auto& [key, k] : fast.keys) {
    std::vector<End> ends;
    const KeyProbes& values = probes.at(key);
    for (const auto& [value, index] : values.written)
      if (k.written.count(index)) ends.push_back({value, *read_as(value, k.kind)});
    for (const auto& sample : values.samples)
      for (const study::WrittenNumber& x : {sample[0], sample[1]})
        if (const std::optional<double> si = read_as(drawn_value(x), k.kind))
          if (std::any_of(k.drawn.begin(), k.drawn.end(), [&](const auto& d) { return d.first <= *si && *si <= d.second; }))
            ends.push_back({drawn_value(x), *si});
    const auto [low, high] =
        std::minmax_element(ends.begin(), ends.end(), [](const End& a, const End& b) { return a.si < b.si; });
    ranges.push_back({*low, *high});
  }
  return ranges;
}

// More fast keys than this: the 2^n corners are not worth reading; the readers read every
// variant.
constexpr size_t kMaxJointKeys = 8;

// Each key was probed alone on the base; the readers also check numbers against each other
// (a bending beam's length and centre against where the elements attach). So every corner of
// the box the keys' ranges span is read by the general path too, and must be the base with
// exactly those numbers set: a check that compares numbers linearly and refuses a point inside
// the box refuses a corner. (A check that refuses only points inside, never a corner, is not
// caught: none of the readers' checks is of that kind.)
bool corners_read_as_set(const StudyFile& file, const std::map<std::string, KeyProbes>& probes, const FastPath& fast,
                         const std::string& base_shape, const std::vector<double>& base) {
  if (fast.keys.size() < 2) return true;
  if (fast.keys.size() > kMaxJointKeys) return false;
  const std::vector<std::pair<End, End>> ranges = key_ranges(probes, fast);
  for (unsigned corner = 0; corner < (1u << fast.keys.size()); ++corner) {
    toml::value document = file.vehicle_documents.at(file.plan.vehicle_file);
    std::vector<double> expected = base;
    size_t i = 0;
    for (const auto& [key, k] : fast.keys) {
      const End& end = (corner >> i & 1u) ? ranges[i].second : ranges[i].first;
      set_at_path(document, key, end.value);
      for (size_t n : k.numbers) expected[n] = end.si;
      ++i;
    }
    try {
      Vehicle vehicle = read_vehicle(document, file.plan.vehicle_file);
      if (vehicle_shape(vehicle) != base_shape) return false;
      const std::vector<double> numbers = numbers_of(std::move(vehicle));
      for (size_t n = 0; n < numbers.size(); ++n)
        if (!same_bits(numbers[n], expected[n])) return false;
    } catch (const std::exception&) {
      return false;
    }
  }
  return true;
}

}  // namespace

std::optional<FastPath> resolve_fast_path(const StudyFile& file) {
  // No variant on the base vehicle (base = false, every [[variant]] on a file of its own): the
  // base file is not read at all, as before.
  if (!file.vehicle_documents.count(file.plan.vehicle_file)) return std::nullopt;
  FastPath fast;
  try {
    fast.base = read_vehicle(file.vehicle_documents.at(file.plan.vehicle_file), file.plan.vehicle_file);
  } catch (const std::exception&) {
    return std::nullopt;  // every variant on the base then fails by the general path, saying why
  }
  const std::string base_shape = vehicle_shape(fast.base);
  const std::vector<double> base = numbers_of(fast.base);
  const std::map<std::string, KeyProbes> probes = probe_values(file);
  for (const auto& [key, values] : probes) {
    if (values.written.size() + 3 * values.samples.size() > kMaxProbes) continue;
    std::vector<Probe> written, drawn;
    for (const auto& [value, index] : values.written)
      written.push_back(probe(file, base_shape, base, key, value, index));
    for (const auto& sample : values.samples)
      for (const study::WrittenNumber& x : sample) drawn.push_back(probe(file, base_shape, base, key, drawn_value(x), -1));
    std::vector<Probe> all = written;
    all.insert(all.end(), drawn.begin(), drawn.end());
    std::optional<FastKey> k = resolve_key(all);
    if (!k) continue;
    for (const Probe& p : written)
      if (sets_only(p, k->numbers, k->kind)) k->written.insert(p.written);
    for (size_t s = 0; s < values.samples.size(); ++s) {
      const bool all_three = std::all_of(drawn.begin() + 3 * s, drawn.begin() + 3 * s + 3,
                                         [&](const Probe& p) { return sets_only(p, k->numbers, k->kind); });
      if (!all_three) continue;
      const double from = *read_as(drawn[3 * s].value, k->kind), to = *read_as(drawn[3 * s + 1].value, k->kind);
      k->drawn.push_back({std::min(from, to), std::max(from, to)});
      const std::string& unit = values.samples[s][0].unit;
      const bool known = std::any_of(k->unit_scales.begin(), k->unit_scales.end(),
                                     [&](const std::pair<std::string, double>& u) { return u.first == unit; });
      if (unit.empty() || known) continue;
      if (const std::optional<double> scale = read_as(toml::value("1 " + unit), k->kind))
        k->unit_scales.push_back({unit, *scale});
    }
    if (!k->written.empty() || !k->drawn.empty()) fast.keys[key] = std::move(*k);
  }
  // Two keys that set a number in common: which wins depends on the readers' order, so both
  // take the general path.
  std::map<size_t, int> setters;
  for (const auto& [key, k] : fast.keys)
    for (size_t i : k.numbers) ++setters[i];
  for (auto it = fast.keys.begin(); it != fast.keys.end();)
    if (std::any_of(it->second.numbers.begin(), it->second.numbers.end(), [&](size_t i) { return setters[i] > 1; }))
      it = fast.keys.erase(it);
    else
      ++it;
  if (!corners_read_as_set(file, probes, fast, base_shape, base)) return std::nullopt;
  for (auto& [key, k] : fast.keys) k.places = stage_places(fast.base, k.numbers);
  return fast;
}

bool fast_vehicle_into(const StudyFile& file, const study::VariantSpec& spec,
                       const std::vector<const study::Assignment*>& on_vehicle, Vehicle* vehicle) {
  if (!file.fast || spec.vehicle_file != file.plan.vehicle_file) return false;
  std::vector<std::pair<const FastKey*, double>> sets;
  sets.reserve(on_vehicle.size());
  for (const study::Assignment* a : on_vehicle) {
    const auto found = file.fast->keys.find(a->key);
    if (found == file.fast->keys.end()) return false;
    const FastKey& key = found->second;
    if (a->written >= 0 && !key.written.count(a->written)) return false;
    std::optional<double> si = a->written < 0 ? drawn_si(key, a->drawn) : std::nullopt;
    if (!si) si = read_as(assignment_value(file, *a), key.kind);
    if (!si) return false;
    if (a->written < 0 && std::none_of(key.drawn.begin(), key.drawn.end(),
                                       [&](const std::pair<double, double>& d) { return d.first <= *si && *si <= d.second; }))
      return false;
    sets.push_back({&key, *si});
  }
  // Assigned, not constructed: a vehicle of the base's shape (a worker's previous variant)
  // keeps its names', lists' and stages' storage.
  *vehicle = file.fast->base;
  if (std::all_of(sets.begin(), sets.end(), [](const auto& set) { return !set.first->places.empty(); })) {
    for (const auto& [key, si] : sets)
      for (const FastKey::StagePlace& p : key->places) number_at(*vehicle, p) = si;
    return true;
  }
  // This thread's list, its storage kept between variants (the list is a few kilobytes: its
  // allocation cost as much as the walk).
  thread_local std::vector<double*> numbers;
  vehicle_numbers(vehicle, &numbers);
  for (const auto& [key, si] : sets)
    for (size_t i : key->numbers) *numbers[i] = si;
  return true;
}

}  // namespace railmodal::input
