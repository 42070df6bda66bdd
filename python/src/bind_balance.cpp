// The steam locomotive's driving gear and its balancing: forces against crank angle as arrays,
// their harmonics and the counterweights as records (docs/python.md, "Balancing").
#include <pybind11/stl.h>

#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "analysis_values.hpp"
#include "bindings.hpp"
#include "railmodal/balance.hpp"
#include "railmodal/driving_gear.hpp"
#include "railmodal/excitation.hpp"

namespace railmodal::python {
namespace {

py::list cylinder_records(const DrivingGear& gear) {
  py::list out;
  for (const GearCylinder& c : gear.cylinders)
    out.append(py::dict(py::arg("name") = c.name, py::arg("lateral_m") = c.lateral,
                        py::arg("crank_offset_rad") = c.crank_offset, py::arg("axle") = c.axle,
                        py::arg("crank_radius_m") = c.crank_radius, py::arg("rod_length_m") = c.rod_length,
                        py::arg("rod_mass_kg") = c.rod_mass, py::arg("rod_centre_of_mass_m") = c.rod_centre_of_mass,
                        py::arg("rod_inertia_kg_m2") = c.rod_inertia,
                        py::arg("reciprocating_mass_kg") = c.reciprocating_mass));
  return out;
}

// One row per rotating mass of every wheel, axle-major, right then left.
py::list mass_records(const DrivingGear& gear) {
  py::list out;
  for (size_t a = 0; a < gear.axles.size(); ++a)
    for (const bool right : {true, false}) {
      const GearWheel& wheel = right ? gear.axles[a].right : gear.axles[a].left;
      for (const RotatingMass& r : wheel.masses)
        out.append(py::dict(py::arg("axle") = a, py::arg("axle_name") = gear.axles[a].name, py::arg("right") = right,
                            py::arg("name") = r.name, py::arg("mass_kg") = r.mass, py::arg("radius_m") = r.radius,
                            py::arg("angle_rad") = r.angle, py::arg("plane_offset_m") = r.plane_offset,
                            py::arg("overbalance") = r.overbalance));
    }
  return out;
}

void bind_gear(py::module_& m) {
  py::class_<DrivingGear>(m, "DrivingGear", "A steam locomotive's driving gear (SI): load_driving_gear")
      .def_readonly("name", &DrivingGear::name)
      .def_readonly("source", &DrivingGear::source)
      .def_readonly("design_speed_m_s", &DrivingGear::design_speed, "0: not stated")
      .def_readonly("wheel_diameter_m", &DrivingGear::wheel_diameter)
      .def_readonly("wheel_plane_half_spacing_m", &DrivingGear::wheel_plane_half_spacing)
      .def_property_readonly("rotation", [](const DrivingGear& g) { return std::string(to_string(g.rotation)); })
      .def_property_readonly("cylinders", &cylinder_records, "records, one per cylinder")
      .def_property_readonly("axle_names",
                             [](const DrivingGear& g) {
                               std::vector<std::string> names;
                               for (const GearAxle& a : g.axles) names.push_back(a.name);
                               return names;
                             })
      .def_property_readonly("masses", &mass_records, "records of every wheel's rotating masses")
      .def("__repr__", [](const DrivingGear& g) { return "<railmodal.DrivingGear '" + g.name + "'>"; });

  m.def(
      "load_driving_gear", path_reader([](const std::string& file) { return load_driving_gear(file); }), py::arg("path"), "The [driving_gear] table of a TOML file, in SI; InputError with file, line, column and key.");
}

// The cylinders' forces of one kind, crank angles × cylinders.
template <class Force>
py::array rod_table(const GearResult& r, const Force& force) {
  const size_t cylinders = r.states.empty() ? 0 : r.states.front().cylinders.size();
  return table(r.states.size(), cylinders, [&](size_t i, size_t j) { return force(r.states[i].cylinders[j]); });
}

void append_harmonics(py::list& out, const char* quantity, int index, const std::vector<GearHarmonic>& harmonics) {
  for (const GearHarmonic& h : harmonics)
    out.append(py::dict(py::arg("quantity") = quantity, py::arg("index") = index, py::arg("order") = h.order,
                        py::arg("cosine") = h.cosine, py::arg("sine") = h.sine, py::arg("amplitude") = h.amplitude()));
}

py::list harmonic_records(const GearResult& r) {
  py::list out;
  const auto per_cylinder = [&](const char* quantity, const std::vector<std::vector<GearHarmonic>>& all) {
    for (size_t c = 0; c < all.size(); ++c) append_harmonics(out, quantity, static_cast<int>(c), all[c]);
  };
  per_cylinder("horizontal", r.horizontal_harmonics);
  per_cylinder("vertical", r.vertical_harmonics);
  per_cylinder("guide", r.guide_harmonics);
  for (size_t w = 0; w < r.wheels.size(); ++w) append_harmonics(out, "wheel_load", static_cast<int>(w), r.wheels[w].harmonics);
  append_harmonics(out, "surging", 0, r.surging_harmonics);
  append_harmonics(out, "nosing", 0, r.nosing_harmonics);
  return out;
}

// The keys of `railmodal balance --format json`'s wheels (docs/input.md, "Names and units in
// outputs"): the hammer blow max|ΔP| = α·П, the signed extremes of ΔP and the least load.
py::list wheel_load_records(const GearResult& r) {
  py::list out;
  for (const GearWheelLoad& w : r.wheels)
    out.append(py::dict(py::arg("wheel") = w.wheel, py::arg("axle") = w.axle, py::arg("right") = w.right,
                        py::arg("static_load_n") = w.static_load,
                        py::arg("max_hammer_blow_n") = w.alpha * w.static_load,
                        py::arg("max_dP_n") = w.max_dynamic_load, py::arg("min_dP_n") = w.min_dynamic_load,
                        py::arg("least_load_n") = w.static_load + w.min_dynamic_load, py::arg("alpha") = w.alpha,
                        py::arg("alpha_89a") = w.alpha_89a, py::arg("wheel_lift") = w.wheel_lift));
  return out;
}

void bind_gear_result(py::module_& m) {
  py::class_<GearResult>(m, "GearResult",
                         "The driving gear's forces over one revolution: arrays against the reference crank angle")
      .def_readonly("speed_m_s", &GearResult::speed)
      .def_readonly("omega_rad_s", &GearResult::omega)
      .def_readonly("frequency_hz", &GearResult::frequency_hz)
      .def_property_readonly("crank_angle_rad",
                             [](const GearResult& r) { return column(r.states.size(), [&](size_t i) { return r.states[i].crank_angle; }); })
      .def_property_readonly("horizontal_n", [](const GearResult& r) { return rod_table(r, [](const RodForces& f) { return f.horizontal; }); },
                             "X on each crank pin, + forward: crank angles × cylinders")
      .def_property_readonly("vertical_n", [](const GearResult& r) { return rod_table(r, [](const RodForces& f) { return f.vertical; }); },
                             "Y on each crank pin, + up: crank angles × cylinders")
      .def_property_readonly("guide_n", [](const GearResult& r) { return rod_table(r, [](const RodForces& f) { return f.guide; }); },
                             "Z of each crosshead on its guide bars, + up: crank angles × cylinders")
      .def_property_readonly("wheel_loads_n",
                             [](const GearResult& r) {
                               const size_t wheels = r.states.empty() ? 0 : r.states.front().wheel_loads.size();
                               return table(r.states.size(), wheels, [&](size_t i, size_t j) { return r.states[i].wheel_loads[j]; });
                             },
                             "dynamic wheel loads ΔP, + pressing the rail: crank angles × wheels (axle-major, right then left)")
      .def_property_readonly("surging_n",
                             [](const GearResult& r) { return column(r.states.size(), [&](size_t i) { return r.states[i].surging; }); })
      .def_property_readonly("nosing_n_m",
                             [](const GearResult& r) { return column(r.states.size(), [&](size_t i) { return r.states[i].nosing; }); })
      .def_readonly("max_surging_n", &GearResult::max_surging)
      .def_readonly("max_nosing_n_m", &GearResult::max_nosing)
      .def_property_readonly("wheels", &wheel_load_records,
                             "records per wheel (axle-major, right then left): wheel (as the reports name it, "
                             "'coupled 1 R'), axle, right, static_load_n (N), "
                             "max_hammer_blow_n (max |dP|, N), max_dP_n and min_dP_n (N, + pressing the rail), "
                             "least_load_n (N), alpha and alpha_89a (overload coefficients, dimensionless), wheel_lift")
      .def("harmonics", &harmonic_records,
           "records: quantity (horizontal, vertical, guide per cylinder; wheel_load per wheel; surging; nosing), "
           "index, order, cosine, sine, amplitude (N; N·m for nosing)")
      .def_readonly("summary", &GearResult::summary);

  m.def(
      "driving_gear_forces",
      [](const DrivingGear& gear, double speed, int steps, int harmonics) {
        GearOptions options;
        options.steps = steps;
        options.harmonics = harmonics;
        py::gil_scoped_release release;
        return solve_driving_gear(gear, speed, options);
      },
      py::arg("gear"), py::arg("speed_m_s"), py::kw_only(), py::arg("steps") = GearOptions{}.steps,
      py::arg("harmonics") = GearOptions{}.harmonics,
      "The exact inertia forces over one revolution at `speed_m_s` (solve_driving_gear).");
  m.def("speed_at_alpha", &speed_at_alpha, py::arg("alpha"), py::arg("speed_m_s"), py::arg("limit"),
        "The speed at which an overload coefficient found at speed_m_s reaches `limit` (forces grow as V²).");
}

// A wheel as the reports name it, "coupled 1 R": the name the gear's forces give the same wheel
// (GearWheelLoad::wheel), so that the library names it in one place.
const std::string& wheel_name(const GearResult& loads, const WheelBalance& w) {
  for (const GearWheelLoad& load : loads.wheels)
    if (load.axle == w.axle && load.right == w.right) return load.wheel;
  throw std::logic_error("balance: no wheel load for axle " + std::to_string(w.axle));
}

py::list wheel_balance_records(const BalanceResult& r) {
  py::list out;
  for (const WheelBalance& w : r.wheels)
    out.append(py::dict(py::arg("wheel") = wheel_name(r.after, w), py::arg("axle") = w.axle,
                        py::arg("right") = w.right,
                        py::arg("rotating_mass_kg") = w.rotating_mass, py::arg("rotating_angle_rad") = w.rotating_angle,
                        py::arg("vertical_mass_kg") = w.vertical_mass, py::arg("vertical_angle_rad") = w.vertical_angle,
                        py::arg("overbalance_mass_kg") = w.overbalance_mass,
                        py::arg("overbalance_angle_rad") = w.overbalance_angle, py::arg("total_mass_kg") = w.total_mass,
                        py::arg("total_angle_rad") = w.total_angle, py::arg("max_hammer_blow_n") = w.max_hammer_blow,
                        py::arg("alpha") = w.alpha, py::arg("alpha_89a") = w.alpha_89a));
  return out;
}

// The speed asked for, or the gear's design speed (as 'railmodal balance' takes it).
double balance_speed(const DrivingGear& gear, std::optional<double> speed) {
  if (speed) return *speed;
  if (gear.design_speed == 0.0)
    throw InputError(gear.source, 0, 0, "the file states no design_speed in [driving_gear]; give speed_m_s");
  return gear.design_speed;
}

void bind_balance_result(py::module_& m) {
  py::class_<BalanceResult>(m, "BalanceResult", "The counterweights of a driving gear and what they leave")
      .def_readonly("speed_m_s", &BalanceResult::speed)
      .def_property_readonly("rule", [](const BalanceResult& r) { return std::string(to_string(r.rule)); })
      .def("records", &wheel_balance_records,
           "The counterweights, one row per wheel (axle-major, right then left): wheel (as the reports name it, "
           "'coupled 1 R'), axle, right, rotating_mass_kg, vertical_mass_kg, overbalance_mass_kg, total_mass_kg on "
           "the axle's crank radius, rotating_angle_rad, vertical_angle_rad, overbalance_angle_rad, total_angle_rad "
           "ahead of the wheel's crank, max_hammer_blow_n (max |dP| after balancing, N), alpha and alpha_89a")
      .def_readonly("balanced", &BalanceResult::balanced, "the gear with its counterweights")
      .def_readonly("before", &BalanceResult::before)
      .def_readonly("after", &BalanceResult::after)
      .def_readonly("percent_unbalanced_surging", &BalanceResult::percent_unbalanced_surging)
      .def_readonly("percent_unbalanced_nosing", &BalanceResult::percent_unbalanced_nosing)
      .def(
          "trade_off",
          [](const BalanceResult& r) {
            py::list out;
            for (const BalanceTradeOff& t : r.trade_off)
              out.append(py::dict(py::arg("balanced_fraction") = t.fraction, py::arg("max_alpha") = t.max_alpha,
                                  py::arg("max_surging_n") = t.max_surging, py::arg("max_nosing_n_m") = t.max_nosing));
            return out;
          },
          "Records: balanced_fraction (of the reciprocating masses, 0 … 1), max_alpha, max_surging_n (N), "
          "max_nosing_n_m (N·m): α, surging and nosing against the fraction balanced")
      .def_readonly("summary", &BalanceResult::summary);

  py::class_<BalanceStudy>(m, "BalanceStudy", "The gear's forces and its balancing by each vertical rule ('railmodal balance')")
      .def_readonly("name", &BalanceStudy::name)
      .def_readonly("cylinder_names", &BalanceStudy::cylinder_names)
      .def_readonly("axle_names", &BalanceStudy::axle_names)
      .def_readonly("gear", &BalanceStudy::gear, "the gear as given, at the speed")
      .def_property_readonly("by_rule",
                             [](const BalanceStudy& s) {
                               py::dict out;
                               for (const BalanceResult& r : s.by_rule) out[to_string(r.rule)] = r;
                               return out;
                             },
                             "BalanceResult by rule: least_squares, minimax, book");

  const BalanceOptions d;
  const auto options = [](const std::string& rule, double fraction, double alpha, bool driving, int steps,
                          const std::vector<double>& fractions) {
    BalanceOptions o;
    o.rule = enum_argument(rule, vertical_rule_from_string, "rule", "'least_squares', 'minimax', 'book'");
    o.reciprocating_fraction = fraction;
    o.allowed_alpha = alpha;
    o.overbalance_driving_axles = driving;
    o.steps = steps;
    o.trade_off_fractions = fractions;
    return o;
  };
  // `balance` and `balance_study` take the same arguments (BalanceOptions' fields and the speed)
  // and differ in what they run with them: solve(gear, speed, options).
  const auto def_balance = [&m, &d, options](const char* name, auto solve, const char* doc) {
    m.def(
        name,
        [options, solve](const DrivingGear& gear, std::optional<double> speed, const std::string& rule,
                         double fraction, double alpha, bool driving, int steps, const std::vector<double>& fractions) {
          const BalanceOptions o = options(rule, fraction, alpha, driving, steps, fractions);
          const double v = balance_speed(gear, speed);
          py::gil_scoped_release release;
          return solve(gear, v, o);
        },
        py::arg("gear"), py::arg("speed_m_s") = py::none(), py::kw_only(), py::arg("rule") = to_string(d.rule),
        py::arg("reciprocating_fraction") = d.reciprocating_fraction, py::arg("allowed_alpha") = d.allowed_alpha,
        py::arg("overbalance_driving_axles") = d.overbalance_driving_axles, py::arg("steps") = d.steps,
        py::arg("trade_off_fractions") = d.trade_off_fractions, doc);
  };
  def_balance(
      "balance",
      [](const DrivingGear& gear, double speed, const BalanceOptions& o) { return balance_driving_gear(gear, speed, o); },
      "The counterweights of `gear` at speed_m_s (default: its design speed) by one vertical rule "
      "(balance_driving_gear).");
  def_balance(
      "balance_study", [](const DrivingGear& gear, double speed, const BalanceOptions& o) { return study_balance(gear, speed, o); },
      "The gear's forces and its balancing by each of the three vertical rules (what 'railmodal balance' prints; "
      "only `rule`'s result has a trade-off).");
}

// The gear as an excitation source (GearExcitation, make_source): for find_critical_speeds and
// amplitude_curves, like rail_joints(). `axles` are (x_m, body) pairs in the gear's axle order.
void bind_gear_excitation(py::module_& m) {
  m.def(
      "gear_excitation",
      [](const DrivingGear& gear, const std::string& body, const std::vector<std::pair<double, std::string>>& axles,
         double crank_angle, int harmonics) {
        GearExcitation e;
        e.gear = gear;
        e.body = body;
        for (const auto& [x, on] : axles) e.axles.push_back({x, on});
        e.crank_angle = crank_angle;
        e.harmonics = harmonics;
        return std::shared_ptr<ExcitationSource>(make_source(e));
      },
      py::arg("gear"), py::kw_only(), py::arg("body") = GearExcitation{}.body,
      py::arg("axles") = std::vector<std::pair<double, std::string>>{},
      py::arg("crank_angle_rad") = GearExcitation{}.crank_angle, py::arg("harmonics") = GearExcitation{}.harmonics,
      "The driving gear as the unbalance excitation (GearExcitation, make_source; scene kind 'driving_gear'): "
      "harmonics 1..harmonics of its exact forces at k times the wheels' turning frequency, on `body` (the "
      "frame); `axles`, one (x_m, body) per gear axle, places each axle and names the body its vertical forces "
      "act on ('' for `body`); empty: the gear's own axle positions. ValueError for an invalid gear.");
}

}  // namespace

void bind_balance(py::module_& m) {
  bind_gear(m);
  bind_gear_result(m);
  bind_balance_result(m);
  bind_gear_excitation(m);
}

}  // namespace railmodal::python
