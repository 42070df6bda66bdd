// The balance report (include/railmodal/balance_report.hpp): sections built once as tables, then
// written in each format.
#include "railmodal/balance_report.hpp"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "report/document_table.hpp"
#include "report/svg_chart.hpp"
#include "report/text_format.hpp"

namespace railmodal {

namespace {

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
  std::vector<std::string> headers = {"phi [deg]"};
  if (rods)
    for (const std::string& c : cylinders)
      for (const char* q : {"X", "Y", "Z"}) headers.push_back(std::string(q) + " " + c + " [kN]");
  for (const std::string& w : wheels) headers.push_back("dP " + w + " [kN]");
  headers.push_back("sum X [kN]");
  headers.push_back("sum MX [kN m]");
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
  Section s{"Harmonics of the gear as given (amplitudes, kN; sum MX in kN m)",
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
                      "at [deg]", "total [kg]", "at [deg]", "max dP [kN]", "least load [kN]", "alpha", "alpha (89a)",
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
  std::vector<std::string> headers = {"rule", "max sum X [kN]", "unbalanced surging [%]", "max sum MX [kN m]",
                                      "unbalanced nosing [%]", "max alpha"};
  for (double limit : kAlphaLimits) headers.push_back("alpha " + report::fixed(limit, 2) + " at [km/h]");
  Section s{"After balancing: surging, nosing, and the speeds at which the largest alpha reaches the limits",
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
  Section s{"Trade-off (" + rule_of(b) + " rule): alpha against the fraction of reciprocating mass balanced",
            table_of({"balanced [%]", "max alpha", "max sum X [kN]", "max sum MX [kN m]"})};
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
                            "the guide bar, dP on the rail)",
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

void write_csv(std::ostream& out, const std::vector<Section>& sections) {
  bool first = true;
  for (const Section& s : sections) {
    if (!first) out << "\n";
    first = false;
    out << "# " << s.title << "\n";
    for (std::size_t c = 0; c < s.table.headers.size(); ++c) out << (c ? "," : "") << report::csv_field(s.table.headers[c]);
    out << "\n";
    for (const auto& row : s.table.rows) {
      for (std::size_t c = 0; c < row.size(); ++c) out << (c ? "," : "") << report::csv_field(row[c]);
      out << "\n";
    }
  }
}

nlohmann::json cell_json(const std::string& text, bool numeric) {
  if (!numeric || text.empty() || text == "never") return text.empty() ? nlohmann::json(nullptr) : nlohmann::json(text);
  return nlohmann::json(std::stod(text));
}

void write_json(std::ostream& out, const BalanceStudy& study, const std::vector<Section>& sections) {
  nlohmann::json j;
  j["engine"] = study.name;
  j["speed_kmh"] = study.gear.speed * 3.6;
  j["omega_per_s"] = study.gear.omega;
  j["frequency_hz"] = study.gear.frequency_hz;
  j["allowed_alpha"] = study.options.allowed_alpha;
  j["reciprocating_fraction"] = study.options.reciprocating_fraction;
  j["sections"] = nlohmann::json::array();
  for (const Section& s : sections) {
    nlohmann::json rows = nlohmann::json::array();
    for (const auto& row : s.table.rows) {
      nlohmann::json r = nlohmann::json::array();
      for (std::size_t c = 0; c < row.size(); ++c) r.push_back(cell_json(row[c], s.table.numeric[c]));
      rows.push_back(r);
    }
    j["sections"].push_back({{"title", s.title}, {"columns", s.table.headers}, {"rows", rows}});
  }
  out << j.dump(2) << "\n";
}

std::string heading(const BalanceStudy& study) {
  return "Driving gear of " + study.name + " at " + report::fixed(study.gear.speed * 3.6, 1) + " km/h (omega " +
         report::fixed(study.gear.omega, 3) + " 1/s, f1 " + report::fixed(study.gear.frequency_hz, 3) + " Hz)";
}

std::string overbalance_line(const BalanceStudy& study) {
  if (study.options.allowed_alpha > 0)
    return "Overbalance: the coupled wheels up to alpha = " + report::fixed(study.options.allowed_alpha, 3) +
           " (Zhdanov eq. (89a)); alpha is max|dP|/P over every mass (eq. (78)), alpha (89a) adds the overbalance's "
           "blow to the rest.";
  return "Overbalance: " + report::fixed(100 * study.options.reciprocating_fraction, 0) +
         " % of the reciprocating masses; alpha is max|dP|/P over every mass (eq. (78)), alpha (89a) adds the "
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
  const BalanceResult& b = chosen(study);
  report::Chart loads = angle_chart("wheel-loads", "Dynamic wheel loads after balancing (" + rule_of(b) + " rule)",
                                    "dP (kN)");
  for (std::size_t w = 0; w < wheels.size(); ++w) {
    report::ChartSeries s;
    s.label = wheels[w];
    for (const GearState& st : b.after.states) {
      s.x.push_back(st.crank_angle / kDegree);
      s.y.push_back(st.wheel_loads[w] / 1000.0);
    }
    loads.series.push_back(s);
  }
  // One chart each: an axis carries one unit.
  report::Chart surging = angle_chart("surging", "Surging after balancing", "sum X (kN)");
  report::Chart nosing = angle_chart("nosing", "Nosing after balancing", "sum MX (kN m)");
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
    trade.title = "Largest alpha against the reciprocating mass balanced (" + rule_of(b) + " rule)";
    trade.x_label = "reciprocating mass balanced (%)";
    trade.y_label = "largest alpha (% of the static wheel load)";
    report::ChartSeries alpha;
    alpha.label = "largest alpha of any wheel";
    for (const BalanceTradeOff& t : b.trade_off) {
      alpha.x.push_back(100 * t.fraction);
      alpha.y.push_back(100 * t.max_alpha);
    }
    trade.series = {alpha};
    for (double limit : {0.3, 1.0})
      trade.lines.push_back(
          {report::fixed(limit, 1), 100 * limit, false, limit < 1 ? "the passenger-engine limit" : "wheel lift"});
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
    wheels.push_back(axle + " R");
    wheels.push_back(axle + " L");
  }
  const std::vector<std::string>& cylinders = study.cylinder_names;
  const std::vector<Section> sections = sections_of(study, cylinders, wheels);
  switch (format) {
    case OutputFormat::table:
      out << heading(study) << "\n" << overbalance_line(study) << "\n";
      write_text(out, sections);
      return;
    case OutputFormat::csv:
      write_csv(out, sections);
      return;
    case OutputFormat::json:
      write_json(out, study, sections);
      return;
    case OutputFormat::markdown:
      out << "# " << heading(study) << "\n\n" << overbalance_line(study) << "\n";
      for (const Section& s : sections) {
        out << "\n## " << s.title << "\n\n";
        report::write_markdown_table(out, s.table);
      }
      return;
    case OutputFormat::html:
      write_html(out, study, sections, wheels, inputs);
      return;
  }
}

}  // namespace railmodal
