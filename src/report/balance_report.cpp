// The balance report (include/railmodal/balance_report.hpp): sections built once as tables, then
// written in each format.
#include "railmodal/balance_report.hpp"

#include <algorithm>
#include <cmath>

#include "gear/wheel_name.hpp"
#include "report/csv_writer.hpp"
#include "report/document_table.hpp"
#include "report/json_writer.hpp"
#include "report/report_page.hpp"
#include "report/svg_chart.hpp"
#include "report/text_format.hpp"
#include "shortest_text.hpp"

namespace railmodal {

namespace {

using report::JsonWriter;

constexpr double kDegree = M_PI / 180.0;
// The overload-coefficient limits of Zhdanov §III.3 (eq. (89a,b), citing ИТС «Паровоз» p. 236):
// 0.2-0.25 freight, 0.2-0.3 passenger, 0.3-0.35 at higher design speeds; 1: the wheel lifts.
constexpr double kAlphaLimits[] = {0.2, 0.25, 0.3, 0.35, 1.0};

struct Section {
  std::string title;
  report::Table table;
};

std::string kn(double newtons) { return report::fixed(newtons / 1000.0, 2); }
std::string deg(double radians) { return report::fixed(radians / kDegree, 1); }

report::Table table_of(std::vector<std::string> headers) {
  report::Table t;
  t.numeric.assign(headers.size(), true);
  t.headers = std::move(headers);
  return t;
}

// Every 15° of the reference crank: each cylinder's X, Y, Z, the engine's ΣX and ΣMX, and the
// wheel loads ΔP of `result`.
Section angle_table(const std::string& title, const GearResult& r, const std::vector<std::string>& cylinders,
                    const std::vector<std::string>& wheels, bool rods) {
  std::vector<std::string> headers = {"φ [deg]"};
  if (rods)
    for (const std::string& c : cylinders)
      for (const char* q : {"X", "Y", "Z"}) headers.push_back(std::string(q) + " " + c + " [kN]");
  for (const std::string& w : wheels) headers.push_back("dP " + w + " [kN]");
  headers.push_back("sum X [kN]");
  headers.push_back("sum MX [kN·m]");
  Section s{title, table_of(headers)};
  const int steps = static_cast<int>(r.states.size());
  for (int degree = 0; degree < 360; degree += 15) {
    if ((degree * steps) % 360 != 0) continue;  // steps that miss the 15° grid print the ones they hit
    const GearState& st = r.states[static_cast<std::size_t>(degree * steps / 360)];
    std::vector<std::string> row = {std::to_string(degree)};
    if (rods)
      for (const RodForces& f : st.cylinders)
        for (double v : {f.horizontal, f.vertical, f.guide}) row.push_back(kn(v));
    for (double p : st.wheel_loads) row.push_back(kn(p));
    row.push_back(kn(st.surging));
    row.push_back(kn(st.nosing));
    s.table.rows.push_back(row);
  }
  return s;
}

Section harmonics_table(const GearResult& r, const std::vector<std::string>& cylinders,
                        const std::vector<std::string>& wheels) {
  Section s{"Harmonics of the gear as given (amplitudes, kN; sum MX in kN·m)",
            table_of({"quantity", "order 0", "order 1", "order 2", "order 3", "order 4"})};
  s.table.numeric[0] = false;
  const int highest = std::min<int>(4, static_cast<int>(r.surging_harmonics.size()) - 1);
  const auto add = [&](const std::string& name, const std::vector<GearHarmonic>& h) {
    std::vector<std::string> row = {name};
    for (int k = 0; k <= 4; ++k) row.push_back(k <= highest ? kn(k == 0 ? h[0].cosine : h[k].amplitude()) : "");
    s.table.rows.push_back(row);
  };
  for (std::size_t c = 0; c < cylinders.size(); ++c) {
    add("X " + cylinders[c], r.horizontal_harmonics[c]);
    add("Y " + cylinders[c], r.vertical_harmonics[c]);
    add("Z " + cylinders[c], r.guide_harmonics[c]);
  }
  for (std::size_t w = 0; w < wheels.size(); ++w) add("dP " + wheels[w], r.wheels[w].harmonics);
  add("sum X", r.surging_harmonics);
  add("sum MX", r.nosing_harmonics);
  return s;
}

Section counterweight_table(const BalanceStudy& study, const std::vector<std::string>& wheels) {
  Section s{"Counterweights by rule (kg on the crank radius, degrees ahead of the wheel's crank)",
            table_of({"rule", "wheel", "rotating [kg]", "at [deg]", "vertical [kg]", "at [deg]", "overbalance [kg]",
                      "at [deg]", "total [kg]", "at [deg]", "max hammer blow [kN]", "least load [kN]", "α", "α (89a)",
                      "wheel lift"})};
  s.table.numeric[0] = s.table.numeric[1] = s.table.numeric[14] = false;
  for (const BalanceResult& b : study.by_rule) {
    for (std::size_t w = 0; w < b.wheels.size(); ++w) {
      const WheelBalance& x = b.wheels[w];
      s.table.rows.push_back({to_string(b.rule), wheels[w], report::fixed(x.rotating_mass, 1), deg(x.rotating_angle),
                              report::fixed(x.vertical_mass, 1), deg(x.vertical_angle), report::fixed(x.overbalance_mass, 1),
                              deg(x.overbalance_angle), report::fixed(x.total_mass, 1), deg(x.total_angle),
                              kn(x.max_hammer_blow),
                              kn(b.after.wheels[w].static_load + b.after.wheels[w].min_dynamic_load),
                              report::fixed(x.alpha, 3), report::fixed(x.alpha_89a, 3),
                              x.alpha >= 1.0 ? "yes" : "no"});
    }
  }
  return s;
}

std::string rule_of(const BalanceResult& b) { return to_string(b.rule); }

Section after_table(const BalanceStudy& study) {
  std::vector<std::string> headers = {"rule", "max sum X [kN]", "unbalanced surging [%]", "max sum MX [kN·m]",
                                      "unbalanced nosing [%]", "max α"};
  for (double limit : kAlphaLimits) headers.push_back("α " + report::fixed(limit, 2) + " at [km/h]");
  Section s{"After balancing: surging, nosing, and the speeds at which the largest α reaches the limits",
            table_of(headers)};
  s.table.numeric[0] = false;
  for (const BalanceResult& b : study.by_rule) {
    double alpha = 0.0;
    for (const WheelBalance& w : b.wheels) alpha = std::max(alpha, w.alpha);
    std::vector<std::string> row = {rule_of(b), kn(b.after.max_surging), report::fixed(b.percent_unbalanced_surging, 1),
                                    kn(b.after.max_nosing), report::fixed(b.percent_unbalanced_nosing, 1),
                                    report::fixed(alpha, 3)};
    for (double limit : kAlphaLimits) {
      const double v = speed_at_alpha(alpha, b.speed, limit);
      row.push_back(std::isfinite(v) ? report::fixed(v * 3.6, 1) : "never");
    }
    s.table.rows.push_back(row);
  }
  return s;
}

Section trade_off_table(const BalanceResult& b) {
  Section s{"Trade-off (" + rule_of(b) + " rule): α against the fraction of reciprocating mass balanced",
            table_of({"balanced [%]", "max α", "max sum X [kN]", "max sum MX [kN·m]"})};
  for (const BalanceTradeOff& t : b.trade_off)
    s.table.rows.push_back({report::fixed(100 * t.fraction, 0), report::fixed(t.max_alpha, 3), kn(t.max_surging),
                            kn(t.max_nosing)});
  return s;
}

const BalanceResult& chosen(const BalanceStudy& study) {
  for (const BalanceResult& b : study.by_rule)
    if (b.rule == study.options.rule) return b;
  return study.by_rule.front();
}

std::vector<Section> sections_of(const BalanceStudy& study, const std::vector<std::string>& cylinders,
                                 const std::vector<std::string>& wheels) {
  const BalanceResult& b = chosen(study);
  std::vector<Section> out;
  out.push_back(angle_table("Forces every 15 degrees of the right crank, the gear as given (X, Y on the crank pin, Z on "
                            "the guide bar, dP on the rail: the hammer blow)",
                            study.gear, cylinders, wheels, true));
  out.push_back(harmonics_table(study.gear, cylinders, wheels));
  out.push_back(counterweight_table(study, wheels));
  out.push_back(after_table(study));
  out.push_back(angle_table("Wheel loads every 15 degrees after balancing by the " + rule_of(b) + " rule", b.after,
                            cylinders, wheels, false));
  if (!b.trade_off.empty()) out.push_back(trade_off_table(b));
  return out;
}

void write_text(std::ostream& out, const std::vector<Section>& sections) {
  for (const Section& s : sections) {
    out << "\n" << s.title << "\n";
    std::vector<std::size_t> width(s.table.headers.size());
    for (std::size_t c = 0; c < width.size(); ++c) {
      width[c] = s.table.headers[c].size() + 2;
      for (const auto& row : s.table.rows) width[c] = std::max(width[c], row[c].size() + 2);
    }
    // Right-aligned numbers end at their column's edge; a text column after one starts two spaces on.
    const auto cell = [&](const std::string& text, std::size_t c) {
      if (s.table.numeric[c]) return report::right_cell(text, width[c]);
      return (c > 0 ? "  " : "") + report::left_cell(text, width[c]);
    };
    std::string line;
    for (std::size_t c = 0; c < width.size(); ++c) line += cell(s.table.headers[c], c);
    out << line.substr(0, line.find_last_not_of(' ') + 1) << "\n";
    for (const auto& row : s.table.rows) {
      line.clear();
      for (std::size_t c = 0; c < width.size(); ++c) line += cell(row[c], c);
      out << line.substr(0, line.find_last_not_of(' ') + 1) << "\n";
    }
  }
}

// ---- Machine-readable outputs: every number at full precision (the shortest text that reads
// back as the same double), in SI units named in the keys or in a unit column; harmonics with
// amplitude and phase, q(φ) = Σ_k A_k cos(kφ − ψ_k), φ the reference (right) crank's angle.
// JSON members in the order written (the file had nlohmann::ordered_json's, the insertion order),
// streamed by JsonWriter with no document tree.

// The states every 15° of the reference crank (the book's tables), as the text tables, with
// their angle in whole degrees (the state's own angle in radians is 2π·i/steps, which need not
// convert back to a whole number of degrees exactly).
std::vector<std::pair<int, const GearState*>> tabled_states(const GearResult& r) {
  std::vector<std::pair<int, const GearState*>> out;
  const int steps = static_cast<int>(r.states.size());
  for (int degree = 0; degree < 360; degree += 15)
    if ((degree * steps) % 360 == 0) out.push_back({degree, &r.states[static_cast<std::size_t>(degree * steps / 360)]});
  return out;
}

double phase_of(const GearHarmonic& h) { return std::atan2(h.sine, h.cosine); }

void write_harmonics(JsonWriter& j, const std::vector<GearHarmonic>& hs) {
  j.begin_array();
  for (const GearHarmonic& h : hs)
    j.begin_object().member("order", h.order).member("amplitude", h.order == 0 ? std::abs(h.cosine) : h.amplitude())
        .member("phase_deg", phase_of(h) / kDegree).end_object();
  j.end_array();
}

void write_states(JsonWriter& j, const GearResult& r, const std::vector<std::string>& cylinders,
                  const std::vector<std::string>& wheels, bool rods) {
  j.begin_array();
  for (const auto& [degree, st] : tabled_states(r)) {
    j.begin_object().member("crank_angle_deg", degree);
    if (rods) {
      j.key("cylinders").begin_array();
      for (std::size_t c = 0; c < st->cylinders.size(); ++c)
        j.begin_object().member("cylinder", cylinders[c]).member("X_n", st->cylinders[c].horizontal)
            .member("Y_n", st->cylinders[c].vertical).member("Z_n", st->cylinders[c].guide).end_object();
      j.end_array();
    }
    j.key("wheel_loads").begin_array();
    for (std::size_t w = 0; w < st->wheel_loads.size(); ++w)
      j.begin_object().member("wheel", wheels[w]).member("dP_n", st->wheel_loads[w]).end_object();
    j.end_array().member("surging_n", st->surging).member("nosing_n_m", st->nosing).end_object();
  }
  j.end_array();
}

// A wheel's load over the revolution, the same members for the gear as given and after balancing
// (user audit 2026-11-27c, F7: the hammer blow had two names): the hammer blow max|ΔP| = α·П,
// the signed extremes of ΔP (+ pressing the rail), the least load П + min ΔP, α and ΔP's harmonics.
void write_wheel_load(JsonWriter& j, const GearWheelLoad& x) {
  j.member("max_hammer_blow_n", x.alpha * x.static_load);
  j.member("max_dP_n", x.max_dynamic_load).member("min_dP_n", x.min_dynamic_load);
  j.member("least_load_n", x.static_load + x.min_dynamic_load).member("alpha", x.alpha);
  j.member("alpha_89a", x.alpha_89a).member("wheel_lift", x.wheel_lift).key("dP_harmonics_n");
  write_harmonics(j, x.harmonics);
}

void write_gear(JsonWriter& j, const GearResult& r, const std::vector<std::string>& cylinders,
                const std::vector<std::string>& wheels) {
  j.begin_object().key("states_every_15_deg");
  write_states(j, r, cylinders, wheels, true);
  j.key("harmonics").begin_object().key("cylinders").begin_array();
  for (std::size_t c = 0; c < cylinders.size(); ++c) {
    j.begin_object().member("cylinder", cylinders[c]).key("X_n");
    write_harmonics(j, r.horizontal_harmonics[c]);
    j.key("Y_n");
    write_harmonics(j, r.vertical_harmonics[c]);
    j.key("Z_n");
    write_harmonics(j, r.guide_harmonics[c]);
    j.end_object();
  }
  j.end_array().key("surging_n");
  write_harmonics(j, r.surging_harmonics);
  j.key("nosing_n_m");
  write_harmonics(j, r.nosing_harmonics);
  j.end_object().key("wheels").begin_array();
  for (std::size_t w = 0; w < r.wheels.size(); ++w) {
    const GearWheelLoad& x = r.wheels[w];
    j.begin_object().member("wheel", wheels[w]).member("static_load_n", x.static_load);
    write_wheel_load(j, x);
    j.end_object();
  }
  j.end_array().member("max_surging_n", r.max_surging).member("max_nosing_n_m", r.max_nosing).end_object();
}

double largest_alpha(const BalanceResult& b) {
  double alpha = 0.0;
  for (const WheelBalance& w : b.wheels) alpha = std::max(alpha, w.alpha);
  return alpha;
}

void write_rule(JsonWriter& j, const BalanceStudy& study, const BalanceResult& b,
                const std::vector<std::string>& cylinders, const std::vector<std::string>& wheels) {
  j.begin_object().member("rule", to_string(b.rule)).key("wheels").begin_array();
  for (std::size_t w = 0; w < b.wheels.size(); ++w) {
    const WheelBalance& x = b.wheels[w];
    j.begin_object().member("wheel", wheels[w]);
    j.member("rotating_mass_kg", x.rotating_mass).member("rotating_angle_deg", x.rotating_angle / kDegree);
    j.member("vertical_mass_kg", x.vertical_mass).member("vertical_angle_deg", x.vertical_angle / kDegree);
    j.member("overbalance_mass_kg", x.overbalance_mass).member("overbalance_angle_deg", x.overbalance_angle / kDegree);
    j.member("total_mass_kg", x.total_mass).member("total_angle_deg", x.total_angle / kDegree);
    write_wheel_load(j, b.after.wheels[w]);
    j.end_object();
  }
  const double alpha = largest_alpha(b);
  j.end_array().member("max_surging_n", b.after.max_surging);
  j.member("unbalanced_surging_percent", b.percent_unbalanced_surging).member("max_nosing_n_m", b.after.max_nosing);
  j.member("unbalanced_nosing_percent", b.percent_unbalanced_nosing).member("max_alpha", alpha);
  j.key("speed_at_alpha").begin_array();
  // JSON has no infinity: a speed that is never reached is null (JsonWriter).
  for (double limit : kAlphaLimits) {
    const double speed = speed_at_alpha(alpha, b.speed, limit);
    j.begin_object().member("alpha", limit).member("speed_kmh", speed * 3.6).member("speed_m_s", speed).end_object();
  }
  j.end_array().key("surging_harmonics_n");
  write_harmonics(j, b.after.surging_harmonics);
  j.key("nosing_harmonics_n_m");
  write_harmonics(j, b.after.nosing_harmonics);
  if (b.rule == study.options.rule) {
    j.key("states_every_15_deg");
    write_states(j, b.after, cylinders, wheels, false);
  }
  if (!b.trade_off.empty()) {
    j.key("trade_off").begin_array();
    for (const BalanceTradeOff& x : b.trade_off)
      j.begin_object().member("balanced_fraction", x.fraction).member("max_alpha", x.max_alpha)
          .member("max_surging_n", x.max_surging).member("max_nosing_n_m", x.max_nosing).end_object();
    j.end_array();
  }
  j.end_object();
}

std::vector<std::string> alpha_notes(const BalanceStudy& study);

void write_json(std::ostream& out, const BalanceStudy& study, const std::vector<std::string>& cylinders,
                const std::vector<std::string>& wheels) {
  JsonWriter j(out);
  j.begin_object().member("engine", study.name).member("speed_m_s", study.gear.speed);
  j.member("speed_kmh", study.gear.speed * 3.6).member("omega_rad_s", study.gear.omega);
  j.member("frequency_hz", study.gear.frequency_hz).key("options").begin_object();
  j.member("rule", to_string(study.options.rule)).member("allowed_alpha", study.options.allowed_alpha);
  j.member("reciprocating_fraction", study.options.reciprocating_fraction);
  j.member("overbalance_driving_axles", study.options.overbalance_driving_axles).end_object();
  j.key("conventions").begin_object();
  j.member("crank_angle",
           "φ: the right (reference) crank's angle from its rear dead centre, in the direction of rotation running "
           "forward (Zhdanov; docs/driving_gear.md)");
  j.member("harmonics", "q(φ) = sum over k of amplitude_k cos(k φ - phase_k), k = 0 the mean");
  j.member("signs",
           "X + forward, Y and Z + up, dP + pressing the rail, surging + forward, nosing + turning the engine to the "
           "right");
  j.member("masses", "counterweights in kg on the crank radius, angles in degrees ahead of the wheel's crank");
  j.end_object().member("cylinders", cylinders).member("wheels", wheels).member("notes", alpha_notes(study));
  j.key("gear");
  write_gear(j, study.gear, cylinders, wheels);
  j.key("by_rule").begin_array();
  for (const BalanceResult& b : study.by_rule) write_rule(j, study, b, cylinders, wheels);
  j.end_array().end_object();
}

// One long ("tidy") table that any CSV reader loads: a row per number, with the section it
// belongs to, the rule ("" for the gear as given), the cylinder, wheel or "engine", the quantity
// and its unit, and the crank angle, harmonic order or balanced fraction it is taken at.
class CsvRows {
 public:
  explicit CsvRows(std::ostream& out) : csv_(out) {
    csv_.line("section,rule,item,quantity,unit,crank_angle_deg,order,balanced_fraction,value");
  }
  struct At {
    std::string angle, order, fraction;
  };
  void row(const std::string& section, const std::string& rule, const std::string& item, const std::string& quantity,
           const std::string& unit, const At& at, double value) {
    csv_.field(section).field(rule).field(item).field(quantity).field(unit).field(at.angle).field(at.order);
    csv_.field(at.fraction).field(value).end_row();
  }

 private:
  report::CsvWriter csv_;
};

void csv_states(CsvRows& csv, const std::string& rule, const GearResult& r, const std::vector<std::string>& cylinders,
                const std::vector<std::string>& wheels, bool rods) {
  for (const auto& [degree, st] : tabled_states(r)) {
    const CsvRows::At at{std::to_string(degree), "", ""};
    if (rods)
      for (std::size_t c = 0; c < st->cylinders.size(); ++c) {
        csv.row("state", rule, cylinders[c], "X", "N", at, st->cylinders[c].horizontal);
        csv.row("state", rule, cylinders[c], "Y", "N", at, st->cylinders[c].vertical);
        csv.row("state", rule, cylinders[c], "Z", "N", at, st->cylinders[c].guide);
      }
    for (std::size_t w = 0; w < st->wheel_loads.size(); ++w) csv.row("state", rule, wheels[w], "dP", "N", at, st->wheel_loads[w]);
    csv.row("state", rule, "engine", "surging", "N", at, st->surging);
    csv.row("state", rule, "engine", "nosing", "N·m", at, st->nosing);
  }
}

void csv_harmonics(CsvRows& csv, const std::string& rule, const std::string& item, const std::string& quantity,
                   const std::string& unit, const std::vector<GearHarmonic>& hs) {
  for (const GearHarmonic& h : hs) {
    const CsvRows::At at{"", std::to_string(h.order), ""};
    csv.row("harmonic", rule, item, quantity + " amplitude", unit, at, h.order == 0 ? std::abs(h.cosine) : h.amplitude());
    csv.row("harmonic", rule, item, quantity + " phase", "deg", at, phase_of(h) / kDegree);
  }
}

void write_csv(std::ostream& out, const BalanceStudy& study, const std::vector<std::string>& cylinders,
               const std::vector<std::string>& wheels) {
  CsvRows csv(out);
  const GearResult& g = study.gear;
  csv_states(csv, "", g, cylinders, wheels, true);
  for (std::size_t c = 0; c < cylinders.size(); ++c) {
    csv_harmonics(csv, "", cylinders[c], "X", "N", g.horizontal_harmonics[c]);
    csv_harmonics(csv, "", cylinders[c], "Y", "N", g.vertical_harmonics[c]);
    csv_harmonics(csv, "", cylinders[c], "Z", "N", g.guide_harmonics[c]);
  }
  for (std::size_t w = 0; w < wheels.size(); ++w) csv_harmonics(csv, "", wheels[w], "dP", "N", g.wheels[w].harmonics);
  csv_harmonics(csv, "", "engine", "surging", "N", g.surging_harmonics);
  csv_harmonics(csv, "", "engine", "nosing", "N·m", g.nosing_harmonics);
  const CsvRows::At none{"", "", ""};
  for (const BalanceResult& b : study.by_rule) {
    const std::string rule = to_string(b.rule);
    for (std::size_t w = 0; w < b.wheels.size(); ++w) {
      const WheelBalance& x = b.wheels[w];
      const auto put = [&](const char* q, const char* unit, double v) { csv.row("counterweight", rule, wheels[w], q, unit, none, v); };
      put("rotating mass", "kg", x.rotating_mass);
      put("rotating angle", "deg", x.rotating_angle / kDegree);
      put("vertical mass", "kg", x.vertical_mass);
      put("vertical angle", "deg", x.vertical_angle / kDegree);
      put("overbalance mass", "kg", x.overbalance_mass);
      put("overbalance angle", "deg", x.overbalance_angle / kDegree);
      put("total mass", "kg", x.total_mass);
      put("total angle", "deg", x.total_angle / kDegree);
      put("max hammer blow", "N", x.max_hammer_blow);
      put("least load", "N", b.after.wheels[w].static_load + b.after.wheels[w].min_dynamic_load);
      put("alpha", "1", x.alpha);
      put("alpha (89a)", "1", x.alpha_89a);
      put("wheel lift", "bool", x.alpha >= 1.0 ? 1.0 : 0.0);
    }
    const auto put = [&](const std::string& q, const char* unit, double v) { csv.row("after", rule, "engine", q, unit, none, v); };
    put("max surging", "N", b.after.max_surging);
    put("unbalanced surging", "%", b.percent_unbalanced_surging);
    put("max nosing", "N·m", b.after.max_nosing);
    put("unbalanced nosing", "%", b.percent_unbalanced_nosing);
    const double alpha = largest_alpha(b);
    put("max alpha", "1", alpha);
    for (double limit : kAlphaLimits)  // inf: never reached ("inf" reads back as a number)
      put("speed at alpha " + shortest_text(limit), "km/h", speed_at_alpha(alpha, b.speed, limit) * 3.6);
    if (b.rule == study.options.rule) csv_states(csv, rule, b.after, cylinders, wheels, false);
    for (std::size_t w = 0; w < wheels.size(); ++w) csv_harmonics(csv, rule, wheels[w], "dP", "N", b.after.wheels[w].harmonics);
    for (const BalanceTradeOff& t : b.trade_off) {
      const CsvRows::At at{"", "", shortest_text(t.fraction)};
      csv.row("trade_off", rule, "engine", "max alpha", "1", at, t.max_alpha);
      csv.row("trade_off", rule, "engine", "max surging", "N", at, t.max_surging);
      csv.row("trade_off", rule, "engine", "max nosing", "N·m", at, t.max_nosing);
    }
  }
}

// Why a wheel's α after balancing can exceed the allowed α that --alpha gives: the allowed α
// sizes the overbalance of the coupled wheels; a driving wheel keeps the residual its vertical
// counterweight leaves, which each rule sizes differently.
std::vector<std::string> alpha_notes(const BalanceStudy& study) {
  std::vector<std::string> notes;
  const double allowed = study.options.allowed_alpha;
  if (!(allowed > 0)) return notes;
  for (const BalanceResult& b : study.by_rule) {
    std::size_t worst = 0;
    for (std::size_t w = 0; w < b.wheels.size(); ++w)
      if (b.wheels[w].alpha > b.wheels[worst].alpha) worst = w;
    if (b.wheels.empty() || !(b.wheels[worst].alpha > allowed * (1 + 1e-9))) continue;
    const WheelBalance& w = b.wheels[worst];
    notes.push_back(
        "The " + std::string(to_string(b.rule)) + " rule leaves α = " + report::fixed(w.alpha, 3) + " at wheel " +
        gear::wheel_name(study.axle_names[static_cast<std::size_t>(w.axle)], w.right) + ", above the allowed " +
        report::fixed(allowed, 3) + ": --alpha sizes the overbalance of the coupled wheels so that their α is " +
        report::fixed(allowed, 3) + "; a driving wheel" +
        (study.options.overbalance_driving_axles ? "" : ", not overbalanced,") +
        " keeps what its vertical counterweight leaves of the rods' Y: the second harmonic, which no "
        "counterweight cancels, plus what the rule leaves of the first (the book's rule sizes the counterweight "
        "from |Y| at 90 degrees of the wheel's crank, not from the first harmonic). Right and left differ because the "
        "left crank lags by 90 degrees: the left wheel's first harmonic is turned by -90 degrees and its second by "
        "-180, so what is left of the first adds to the second at another phase and peaks higher on one side.");
  }
  return notes;
}

std::string heading(const BalanceStudy& study) {
  return "Driving gear of " + study.name + " at " + shortest_text(study.gear.speed * 3.6, 6) + " km/h (ω " +
         report::fixed(study.gear.omega, 3) + " rad/s, f1 " + report::fixed(study.gear.frequency_hz, 3) + " Hz)";
}

std::string overbalance_line(const BalanceStudy& study) {
  if (study.options.allowed_alpha > 0)
    return "Overbalance: the coupled wheels up to α = " + report::fixed(study.options.allowed_alpha, 3) +
           " (Zhdanov eq. (89a)); α is max|dP|/P over every mass (eq. (78)), α (89a) adds the overbalance's "
           "blow to the rest.";
  return "Overbalance: " + report::fixed(100 * study.options.reciprocating_fraction, 0) +
         " % of the reciprocating masses; α is max|dP|/P over every mass (eq. (78)), α (89a) adds the "
         "overbalance's blow to the rest.";
}

report::Chart angle_chart(const std::string& id, const std::string& title, const std::string& y_label) {
  report::Chart c;
  c.id = id;
  c.title = title;
  c.x_label = "crank angle of the right crank (deg)";
  c.y_label = y_label;
  c.x_min = 0;
  c.x_max = 360;
  return c;
}

void write_html(std::ostream& out, const BalanceStudy& study, const std::vector<Section>& sections,
                const std::vector<std::string>& wheels, const Provenance& inputs) {
  report::write_html_head(out, heading(study));
  out << "<h1>" << report::html_escape(heading(study)) << "</h1>\n<p>" << report::html_escape(overbalance_line(study))
      << "</p>\n";
  for (const std::string& note : alpha_notes(study)) out << "<p>" << report::html_escape(note) << "</p>\n";
  const BalanceResult& b = chosen(study);
  report::Chart loads = angle_chart("wheel-loads", "Dynamic wheel loads after balancing (" + rule_of(b) + " rule)",
                                    "dP (kN)");
  // A colour per axle, its left wheel dashed. Wheels whose curves coincide (balanced coupled
  // wheels often do: coupled 1 and coupled 3 of the Су with --alpha) are one series whose label
  // names them all, since one line drawn over another would hide it.
  double largest = 0.0;
  for (const GearState& st : b.after.states)
    for (double p : st.wheel_loads) largest = std::max(largest, std::abs(p));
  std::vector<std::size_t> drawn;  // the wheel each series is drawn for
  for (std::size_t w = 0; w < wheels.size(); ++w) {
    const auto same = [&](std::size_t v) {
      for (const GearState& st : b.after.states)
        if (std::abs(st.wheel_loads[w] - st.wheel_loads[v]) > 1e-6 * largest) return false;  // far below a pixel, far above round-off
      return true;
    };
    const auto twin = std::find_if(drawn.begin(), drawn.end(), same);
    if (twin != drawn.end()) {
      loads.series[static_cast<std::size_t>(twin - drawn.begin())].label += " = " + wheels[w];
      continue;
    }
    report::ChartSeries s;
    s.label = wheels[w];
    s.colour = static_cast<int>(w / 2);
    s.dashed = w % 2 == 1;
    for (const GearState& st : b.after.states) {
      s.x.push_back(st.crank_angle / kDegree);
      s.y.push_back(st.wheel_loads[w] / 1000.0);
    }
    loads.series.push_back(s);
    drawn.push_back(w);
  }
  // One chart each: an axis carries one unit.
  report::Chart surging = angle_chart("surging", "Surging after balancing", "sum X (kN)");
  report::Chart nosing = angle_chart("nosing", "Nosing after balancing", "sum MX (kN·m)");
  report::ChartSeries x, mx;
  x.label = "sum X";
  mx.label = "sum MX";
  for (const GearState& st : b.after.states) {
    x.x.push_back(st.crank_angle / kDegree);
    x.y.push_back(st.surging / 1000.0);
    mx.x.push_back(st.crank_angle / kDegree);
    mx.y.push_back(st.nosing / 1000.0);
  }
  surging.series = {x};
  nosing.series = {mx};
  out << report::svg_chart(loads) << "\n" << report::svg_chart(surging) << "\n" << report::svg_chart(nosing) << "\n";
  if (!b.trade_off.empty()) {
    report::Chart trade;
    trade.id = "trade-off";
    trade.title = "Largest α against the reciprocating mass balanced (" + rule_of(b) + " rule)";
    trade.x_label = "reciprocating mass balanced (%)";
    // α itself on the axis (max|dP| over the static wheel load), so that the limit lines' labels
    // read in the axis' unit.
    trade.y_label = "largest α (max|dP| / static load)";
    report::ChartSeries alpha;
    alpha.label = "largest α of any wheel";
    for (const BalanceTradeOff& t : b.trade_off) {
      alpha.x.push_back(100 * t.fraction);
      alpha.y.push_back(t.max_alpha);
    }
    trade.series = {alpha};
    for (double limit : {0.3, 1.0})
      trade.lines.push_back(
          {report::fixed(limit, 1), limit, false, limit < 1 ? "the passenger-engine limit" : "wheel lift"});
    out << report::svg_chart(trade) << "\n";
  }
  for (const Section& s : sections) {
    out << "<h2>" << report::html_escape(s.title) << "</h2>\n";
    report::write_html_table(out, s.table);
  }
  report::write_html_footer(out, "balance", inputs);
}

}  // namespace

void write_balance(std::ostream& out, const BalanceStudy& study, OutputFormat format, const Provenance& inputs) {
  std::vector<std::string> wheels;
  for (const std::string& axle : study.axle_names) {
    wheels.push_back(gear::wheel_name(axle, true));
    wheels.push_back(gear::wheel_name(axle, false));
  }
  const std::vector<std::string>& cylinders = study.cylinder_names;
  const std::vector<Section> sections = sections_of(study, cylinders, wheels);
  const auto write_table = [&] {
    out << heading(study) << "\n" << overbalance_line(study) << "\n";
    for (const std::string& note : alpha_notes(study)) out << note << "\n";
    write_text(out, sections);
  };
  const auto write_markdown = [&] {
    out << "# " << heading(study) << "\n\n" << overbalance_line(study) << "\n";
    for (const std::string& note : alpha_notes(study)) out << "\n" << note << "\n";
    for (const Section& s : sections) {
      out << "\n## " << s.title << "\n\n";
      report::write_markdown_table(out, s.table);
    }
  };
  report::write_in_format(
      format, "write_balance", write_table, [&] { write_csv(out, study, cylinders, wheels); },
      [&] { write_json(out, study, cylinders, wheels); }, write_markdown,
      [&] { write_html(out, study, sections, wheels, inputs); });
}

}  // namespace railmodal
