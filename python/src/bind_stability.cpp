// Hunting stability (root locus against speed, the linear critical speed, the critical speed
// against conicity), the nonlinear critical speed, and the static lateral stability of a body
// (docs/python.md, "Hunting stability").
#include <complex>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "analysis_values.hpp"
#include "bindings.hpp"
#include "railmodal/hunting.hpp"
#include "railmodal/limit_cycles.hpp"
#include "railmodal/nonlinear_hunting.hpp"
#include "railmodal/nonlinear_hunting_report.hpp"
#include "railmodal/output_format.hpp"
#include "railmodal/provenance.hpp"
#include "railmodal/scene.hpp"
#include "railmodal/stability.hpp"

namespace railmodal::python {
namespace {

py::object critical_dict(const std::optional<HuntingCriticalSpeed>& c) {
  if (!c) return py::none();
  return py::dict(py::arg("speed_m_s") = c->speed, py::arg("branch") = c->branch, py::arg("motion") = c->motion,
                  py::arg("frequency_hz") = c->frequency_hz, py::arg("klingel_frequency_hz") = c->klingel_frequency_hz,
                  py::arg("bogie_frequency_hz") =
                      c->bogie_frequency_hz > 0.0 ? py::object(py::float_(c->bogie_frequency_hz)) : py::none(),
                  py::arg("bogie") = c->bogie_frequency_hz > 0.0 ? py::object(py::str(c->bogie)) : py::none(),
                  py::arg("evaluations") = c->evaluations);
}

// The place of the branch named `name` in HuntingResult::branches from 1, as the reports number
// them; None for a name no branch has (a real root's group).
py::object branch_number(const HuntingResult& r, const std::string& name) {
  for (size_t k = 0; k < r.branches.size(); ++k)
    if (r.branches[k].name == name) return py::int_(k + 1);
  return py::none();
}

// The root locus as one array per quantity, speeds × branches (the branches in HuntingResult order).
template <class Value>
py::array locus(const HuntingResult& r, const Value& value) {
  return table(r.speeds.size(), r.branches.size(), [&](size_t i, size_t j) { return value(r.branches[j], i); });
}

py::list conicity_records(const HuntingResult& r) {
  py::list out;
  for (const ConicityPoint& p : r.conicity_curve)
    out.append(py::dict(py::arg("conicity") = p.conicity, py::arg("verdict") = std::string(to_string(p.verdict)),
                        py::arg("critical_speed_m_s") = p.critical ? py::object(py::float_(p.critical->speed)) : py::none(),
                        py::arg("branch") = p.critical ? py::object(py::str(p.critical->branch)) : py::none(),
                        py::arg("motion") = p.critical ? py::object(py::str(p.critical->motion)) : py::none(),
                        py::arg("frequency_hz") =
                            p.critical ? py::object(py::float_(p.critical->frequency_hz)) : py::none()));
  return out;
}

py::list contact_records(const std::vector<ResolvedContact>& contacts) {
  py::list out;
  for (const ResolvedContact& c : contacts)
    out.append(py::dict(py::arg("body") = c.body, py::arg("axle_load_n") = c.axle_load,
                        py::arg("axle_load_source") = c.axle_load_source, py::arg("conicity") = c.conicity,
                        py::arg("contact_angle_parameter") = c.contact_angle_parameter,
                        py::arg("roll_parameter") = c.roll_parameter, py::arg("rolling_radius_m") = c.rolling_radius,
                        py::arg("contact_half_spacing_m") = c.contact_half_spacing, py::arg("f11_n") = c.creep.f11,
                        py::arg("f22_n") = c.creep.f22, py::arg("f23_n_m") = c.creep.f23,
                        py::arg("f33_n_m2") = c.creep.f33, py::arg("klingel_wavelength_m") = c.klingel_wavelength));
  return out;
}

// One row per speed and branch: what pandas.DataFrame takes as the long table of the locus.
py::dict locus_columns(const HuntingResult& r) {
  const size_t n = r.speeds.size() * r.branches.size();
  std::vector<std::string> branch(n);
  for (size_t j = 0, k = 0; j < r.branches.size(); ++j)
    for (size_t i = 0; i < r.speeds.size(); ++i, ++k) branch[k] = r.branches[j].name;
  const size_t speeds = r.speeds.size();
  const auto at = [&](auto value) {
    return column(n, [&](size_t k) { return value(r.branches[k / speeds], k % speeds); });
  };
  return py::dict(
      py::arg("speed_m_s") = at([&](const HuntingBranch&, size_t i) { return r.speeds[i]; }),
      py::arg("branch") = branch,
      py::arg("eigenvalue_re") = at([](const HuntingBranch& b, size_t i) { return b.eigenvalues[i].real(); }),
      py::arg("eigenvalue_im") = at([](const HuntingBranch& b, size_t i) { return b.eigenvalues[i].imag(); }),
      py::arg("damping_ratio") = at([](const HuntingBranch& b, size_t i) { return b.damping_ratio[i]; }),
      py::arg("frequency_hz") = at([](const HuntingBranch& b, size_t i) { return b.frequency_hz[i]; }),
      py::arg("continuity") = at([](const HuntingBranch& b, size_t i) { return b.continuity[i]; }));
}

void bind_hunting(py::module_& m) {
  py::class_<HuntingResult>(m, "HuntingResult",
                            "The root locus against speed (arrays speeds × branches), the critical speed, the "
                            "unstable intervals and the critical speed against conicity")
      .def_property_readonly(
          "speeds_m_s", [](py::object self) { return vector_view(self.cast<const HuntingResult&>().speeds, self); },
          "the speed grid, m/s (a view)")
      .def_readonly("dofs", &HuntingResult::dofs)
      .def_property_readonly("branches",
                             [](const HuntingResult& r) {
                               std::vector<std::string> names;
                               for (const HuntingBranch& b : r.branches) names.push_back(b.name);
                               return names;
                             },
                             "branch names, the columns of the locus arrays, least damped first at the top speed")
      .def_property_readonly("eigenvalues",
                             [](const HuntingResult& r) {
                               py::array_t<std::complex<double>> out({r.speeds.size(), r.branches.size()});
                               auto view = out.mutable_unchecked<2>();
                               for (size_t j = 0; j < r.branches.size(); ++j)
                                 for (size_t i = 0; i < r.speeds.size(); ++i) view(i, j) = r.branches[j].eigenvalues[i];
                               return out;
                             },
                             "λ, 1/s, speeds × branches, Im λ ≥ 0 (a new array)")
      .def_property_readonly("damping_ratio",
                             [](const HuntingResult& r) {
                               return locus(r, [](const HuntingBranch& b, size_t i) { return b.damping_ratio[i]; });
                             },
                             "ζ = −Re λ/|λ|, speeds × branches")
      .def_property_readonly("frequency_hz",
                             [](const HuntingResult& r) {
                               return locus(r, [](const HuntingBranch& b, size_t i) { return b.frequency_hz[i]; });
                             },
                             "Im λ/2π, speeds × branches")
      .def_property_readonly("continuity",
                             [](const HuntingResult& r) {
                               return locus(r, [](const HuntingBranch& b, size_t i) { return b.continuity[i]; });
                             },
                             "MAC with the previous speed, speeds × branches")
      .def_property_readonly("veers",
                             [](const HuntingResult& r) {
                               std::vector<bool> out;
                               for (const HuntingBranch& b : r.branches) out.push_back(b.veers);
                               return out;
                             },
                             "per branch: some continuity fell below the threshold")
      .def_property_readonly("verdict", [](const HuntingResult& r) { return std::string(to_string(r.verdict)); })
      .def_property_readonly("critical", [](const HuntingResult& r) { return critical_dict(r.critical); },
                             "the linear critical speed as a dict (speed_m_s, m/s; branch, motion and bogie, names; "
                             "frequency_hz, klingel_frequency_hz and bogie_frequency_hz, Hz; evaluations, a count), or None")
      .def_property_readonly("unstable_intervals",
                             [](const HuntingResult& r) {
                               py::list out;
                               for (const UnstableInterval& u : r.unstable_intervals)
                                 out.append(py::dict(py::arg("from_m_s") = u.from, py::arg("to_m_s") = u.to,
                                                     py::arg("from_lowest_speed") = u.from_lowest_speed,
                                                     py::arg("to_highest_speed") = u.to_highest_speed,
                                                     py::arg("branch") = u.branch,
                                                     py::arg("branch_number") = branch_number(r, u.branch),
                                                     py::arg("divergence") = u.divergence));
                               return out;
                             },
                             "records, one per branch and interval, in order of their lower ends; branch_number "
                             "is the branch's place in `branches` from 1 (None for a real root)")
      .def_property_readonly("damping_threshold",
                             [](const HuntingResult& r) { return optional_value(r.damping_threshold); })
      .def_property_readonly("threshold_speed_m_s",
                             [](const HuntingResult& r) { return optional_value(r.threshold_speed); })
      .def_readonly("threshold_branch", &HuntingResult::threshold_branch)
      .def_readonly("below_threshold_at_lowest_speed", &HuntingResult::below_threshold_at_lowest_speed)
      .def_readonly("neutral_roots", &HuntingResult::neutral_roots)
      .def_property_readonly("conicity_curve", [](const HuntingResult& r) { return conicity_records(r); },
                             "records, one per conicity asked: conicity (λ, dimensionless), verdict, "
                             "critical_speed_m_s (m/s), branch, motion, frequency_hz (Hz)")
      .def_property_readonly("contacts", [](const HuntingResult& r) { return contact_records(r.contacts); },
                             "records of the wheelsets' contact as used: each key with its unit (axle_load_n, "
                             "rolling_radius_m, f11_n, f23_n_m, f33_n_m2, ...); conicity, contact_angle_parameter and "
                             "roll_parameter dimensionless")
      .def_readonly("summary", &HuntingResult::summary)
      .def("as_dict", [](const HuntingResult& r) { return locus_columns(r); },
           "The locus as a long table, one row per speed and branch: speed_m_s (m/s), branch, eigenvalue_re and "
           "eigenvalue_im (1/s), damping_ratio (a fraction), frequency_hz (Hz), continuity (MAC, 0 to 1) "
           "(equal-length arrays)")
      .def(
          "records",
          [](const HuntingResult& r) {
            py::list out;
            for (const HuntingBranch& b : r.branches)
              for (size_t i = 0; i < r.speeds.size(); ++i)
                out.append(py::dict(py::arg("speed_m_s") = r.speeds[i], py::arg("branch") = b.name,
                                    py::arg("eigenvalue_re") = b.eigenvalues[i].real(),
                                    py::arg("eigenvalue_im") = b.eigenvalues[i].imag(),
                                    py::arg("damping_ratio") = b.damping_ratio[i],
                                    py::arg("frequency_hz") = b.frequency_hz[i], py::arg("continuity") = b.continuity[i]));
            return out;
          },
          "The locus as records, one per speed and branch (the rows of as_dict(): speed_m_s in m/s, "
          "eigenvalue_re and eigenvalue_im in 1/s, damping_ratio a fraction, frequency_hz in Hz, continuity "
          "0 … 1: how closely the branch's eigenvector follows on from the previous speed's)");

  m.def(
      "hunting_stability",
      [](const py::object& system, double min_speed, double max_speed, int speed_count,
         const std::vector<double>& conicities, std::optional<double> damping_threshold, double relative_tolerance,
         double continuity_threshold, int threads) {
        HuntingOptions options;
        options.min_speed = min_speed;
        options.max_speed = max_speed;
        options.speed_count = speed_count;
        options.conicities = conicities;
        options.damping_threshold = damping_threshold;
        options.relative_tolerance = relative_tolerance;
        options.continuity_threshold = continuity_threshold;
        options.threads = threads;
        // As `railmodal stability`: the lateral motions, where the hunting lives (the vertical
        // decouples in the linear model of a vehicle symmetric about its centre line).
        const SystemArgument s(system, DofSet::lateral);
        py::gil_scoped_release release;
        return solve_hunting_stability(*s, options);
      },
      py::arg("system"), py::kw_only(), py::arg("min_speed_m_s") = HuntingOptions{}.min_speed,
      py::arg("max_speed_m_s") = HuntingOptions{}.max_speed, py::arg("speed_count") = HuntingOptions{}.speed_count,
      py::arg("conicities") = std::vector<double>{}, py::arg("damping_threshold") = py::none(),
      py::arg("relative_tolerance") = HuntingOptions{}.relative_tolerance,
      py::arg("continuity_threshold") = HuntingOptions{}.continuity_threshold,
      py::arg("threads") = HuntingOptions{}.threads,
      "Hunting stability (solve_hunting_stability): `system` is a LinearSystem, or a vehicle (a file or a "
      "Vehicle) assembled in its lateral motions as 'railmodal stability' does. ValueError for bad options or "
      "a vehicle without wheelsets; NumericalError when an eigen-solve fails.");
}

py::dict curve_columns(const std::vector<LimitCyclePoint>& curve) {
  return py::dict(py::arg("speed_m_s") = column(curve.size(), [&](size_t i) { return curve[i].speed; }),
                  py::arg("amplitude_m") = column(curve.size(), [&](size_t i) { return curve[i].amplitude; }));
}

py::dict ramp_dict(const RampDown& r) {
  return py::dict(py::arg("ramp_rate_m_s2") = r.ramp_rate, py::arg("verdict") = std::string(to_string(r.verdict)),
                  py::arg("critical_speed_m_s") = optional_value(r.critical_speed), py::arg("amplitude_m") = r.amplitude,
                  py::arg("curve") = curve_columns(r.curve), py::arg("steps") = r.steps,
                  py::arg("watched_wheelset") = r.watched_wheelset);
}

py::dict hold_dict(const HeldCriticalSpeed& h) {
  py::list holds;
  for (const SpeedHold& s : h.holds)
    holds.append(py::dict(py::arg("speed_m_s") = s.speed, py::arg("survives") = s.survives,
                          py::arg("start_amplitude_m") = s.start_amplitude, py::arg("end_amplitude_m") = s.end_amplitude,
                          py::arg("periods") = s.periods, py::arg("steps") = s.steps,
                          py::arg("undecided") = s.undecided, py::arg("rate_per_period") = s.rate_per_period,
                          py::arg("rate_error") = s.rate_error,
                          py::arg("rate_change_per_period") = s.rate_change_per_period,
                          py::arg("rate_change_error") = s.rate_change_error));
  return py::dict(py::arg("lowest_surviving_m_s") = optional_value(h.lowest_surviving),
                  py::arg("highest_dying_m_s") = optional_value(h.highest_dying),
                  py::arg("doubled_hold_survives") = h.doubled_hold_survives, py::arg("holds") = holds,
                  py::arg("steps") = h.steps);
}

// The result with its not_converged_reason: why it did not converge, as the reports say it (JSON
// "not_converged_reason"), or None. The words need the options, which the result does not hold, so
// the functions that solve set it on the instance (the class has a __dict__ for it).
py::object with_reason(NonlinearHuntingResult result, const NonlinearHuntingOptions& options) {
  const std::string why = nonlinear_hunting_warning(result, options);
  py::object out = py::cast(std::move(result));
  out.attr("not_converged_reason") = why.empty() ? py::object(py::none()) : py::object(py::str(why));
  return out;
}

void bind_nonlinear_hunting(py::module_& m) {
  py::class_<NonlinearHuntingResult>(m, "NonlinearHuntingResult",
                                     "The nonlinear critical speed from a ramp-down, its check at half the rate and "
                                     "its confirmation by held speeds; not_converged_reason: why it did not "
                                     "converge (as the reports say), or None",
                                     py::dynamic_attr())
      .def_property_readonly("verdict", [](const NonlinearHuntingResult& r) { return std::string(to_string(r.verdict)); })
      .def_property_readonly("critical_speed_m_s",
                             [](const NonlinearHuntingResult& r) { return optional_value(r.critical_speed); })
      .def_readonly("amplitude_m", &NonlinearHuntingResult::amplitude)
      .def_property_readonly("curve", [](const NonlinearHuntingResult& r) { return curve_columns(r.curve); },
                             "the bifurcation plot: speed_m_s, amplitude_m, one point a half cycle (arrays)")
      .def_property_readonly("stated_rate", [](const NonlinearHuntingResult& r) { return ramp_dict(r.stated_rate); })
      .def_property_readonly("halved_rate", [](const NonlinearHuntingResult& r) { return ramp_dict(r.halved_rate); })
      .def_readonly("convergence_difference_m_s", &NonlinearHuntingResult::convergence_difference)
      .def_property_readonly("richardson_critical_speed_m_s",
                             [](const NonlinearHuntingResult& r) { return optional_value(r.richardson_critical_speed); })
      .def_property_readonly("hold", [](const NonlinearHuntingResult& r) { return hold_dict(r.hold); })
      .def_property_readonly("convergence",
                             [](const NonlinearHuntingResult& r) { return std::string(to_string(r.convergence)); })
      .def_readonly("converged", &NonlinearHuntingResult::converged)
      .def_readonly("ramp_too_fast", &NonlinearHuntingResult::ramp_too_fast,
                    "the stated ramp lost the cycle more than hold_margin above a held speed whose cycle survives")
      .def_readonly("collapsing_at_end_speed", &NonlinearHuntingResult::collapsing_at_end_speed,
                    "the stated ramp survived to end_speed, its cycle still collapsing there")
      .def_readonly("summary", &NonlinearHuntingResult::summary);

  m.def(
      "nonlinear_hunting",
      [](const py::object& system, const std::vector<std::string>& effects, double friction_coefficient,
         std::optional<double> wheel_load, double contact_angle, double flange_clearance, double flange_stiffness,
         double start_speed, double end_speed, double ramp_rate, double disturbance, double extinction_amplitude,
         double amplitude_bound, double tolerance, int hold_periods, double hold_margin) {
        NonlinearHuntingOptions o;
        o.effects.clear();
        for (const std::string& word : effects)
          o.effects.push_back(enum_argument(word, nonlinear_effect_from_string, "effects",
                                            "'creep_saturation', 'flange_contact'"));
        o.friction_coefficient = friction_coefficient;
        o.wheel_load = wheel_load;
        o.contact_angle = contact_angle;
        o.flange_clearance = flange_clearance;
        o.flange_stiffness = flange_stiffness;
        o.start_speed = start_speed;
        o.end_speed = end_speed;
        o.ramp_rate = ramp_rate;
        o.disturbance = disturbance;
        o.extinction_amplitude = extinction_amplitude;
        o.amplitude_bound = amplitude_bound;
        o.tolerance = tolerance;
        o.hold_periods = hold_periods;
        o.hold_margin = hold_margin;
        const SystemArgument s(system, DofSet::lateral);
        NonlinearHuntingResult result;
        {
          py::gil_scoped_release release;
          result = solve_nonlinear_hunting(*s, o);
        }
        return with_reason(std::move(result), o);
      },
      py::arg("system"), py::kw_only(),
      py::arg("effects") = std::vector<std::string>{"creep_saturation", "flange_contact"},
      py::arg("friction_coefficient") = NonlinearHuntingOptions{}.friction_coefficient,
      py::arg("wheel_load_n") = py::none(), py::arg("contact_angle_rad") = NonlinearHuntingOptions{}.contact_angle,
      py::arg("flange_clearance_m") = NonlinearHuntingOptions{}.flange_clearance,
      py::arg("flange_stiffness_n_per_m") = NonlinearHuntingOptions{}.flange_stiffness,
      py::arg("start_speed_m_s") = NonlinearHuntingOptions{}.start_speed,
      py::arg("end_speed_m_s") = NonlinearHuntingOptions{}.end_speed,
      py::arg("ramp_rate_m_s2") = NonlinearHuntingOptions{}.ramp_rate,
      py::arg("disturbance_m") = NonlinearHuntingOptions{}.disturbance,
      py::arg("extinction_amplitude_m") = NonlinearHuntingOptions{}.extinction_amplitude,
      py::arg("amplitude_bound_m") = NonlinearHuntingOptions{}.amplitude_bound,
      py::arg("tolerance_m_s") = NonlinearHuntingOptions{}.tolerance,
      py::arg("hold_periods") = NonlinearHuntingOptions{}.hold_periods,
      py::arg("hold_margin_m_s") = NonlinearHuntingOptions{}.hold_margin,
      "The nonlinear critical speed (solve_nonlinear_hunting): `system` a LinearSystem of the lateral motions or "
      "a vehicle (file or Vehicle), assembled so. ValueError for bad options; NumericalError when the integration "
      "fails.");
}

// A scene's [nonlinear_hunting] run as `railmodal hunting` runs it: the vehicle (the scene's, or
// `vehicle`) in its lateral motions, the linear critical speed over the ramp for the report's
// Hopf point, and the ramp-down.
struct SceneHunting {
  Vehicle vehicle;
  NonlinearHuntingResult result;
  std::optional<double> linear;
};
SceneHunting scene_hunting(const Scene& scene, const py::object& vehicle) {
  if (!scene.nonlinear_hunting)
    throw InputError(scene.source, 0, 0, "the scene has no [nonlinear_hunting] table (docs/stability.md)");
  SceneHunting out;
  if (!vehicle.is_none()) {
    out.vehicle = vehicle_argument(vehicle);
  } else if (scene.vehicle_file.empty()) {
    throw py::value_error("no vehicle: give vehicle=... or a 'vehicle' key in " + scene.source);
  } else {
    out.vehicle = vehicle_argument(py::str(scene.vehicle_file));
  }
  if (out.vehicle.wheelsets.empty())
    throw py::value_error("the vehicle has no [wheelset] data: hunting needs wheelsets on rails (docs/stability.md)");
  const NonlinearHuntingOptions& o = *scene.nonlinear_hunting;
  py::gil_scoped_release release;
  const LinearSystem system = assemble(out.vehicle, DofSet::lateral);
  HuntingOptions h;  // as the command: the ramp's speeds, one thread
  h.min_speed = o.end_speed;
  h.max_speed = o.start_speed;
  h.threads = 1;
  const HuntingResult linear = solve_hunting_stability(system, h);
  if (linear.critical) out.linear = linear.critical->speed;
  out.result = solve_nonlinear_hunting(system, o);
  return out;
}

void bind_scene_hunting(py::module_& m) {
  m.def(
      "hunting_scene",
      [](const Scene& scene, const py::object& vehicle) {
        return with_reason(scene_hunting(scene, vehicle).result, *scene.nonlinear_hunting);
      },
      py::arg("scene"), py::arg("vehicle") = py::none(),
      "The scene's [nonlinear_hunting] ramp-down ('railmodal hunting'): a NonlinearHuntingResult. `vehicle` (a file "
      "or Vehicle) replaces the scene's. InputError without the table; ValueError without wheelsets.");
  m.def(
      "hunting_report",
      [](const Scene& scene, const py::object& vehicle, const std::string& format) {
        const std::optional<OutputFormat> f = output_format_from_string(format);
        if (!f) throw py::value_error("format is '" + format + "'; expected one of table, csv, json, markdown, html");
        const SceneHunting run = scene_hunting(scene, vehicle);
        std::vector<std::string> files{scene.source};
        if (!run.vehicle.source.empty()) files.push_back(run.vehicle.source);  // the file it was read from
        std::ostringstream out;
        write_nonlinear_hunting(out, run.result, *scene.nonlinear_hunting, *f, run.vehicle.name, provenance_of(files),
                                run.linear);
        return out.str();
      },
      py::arg("scene"), py::arg("vehicle") = py::none(), py::arg("format") = "json",
      "The report 'railmodal hunting SCENE --format FORMAT' writes (write_nonlinear_hunting), as a string.");
}

py::dict branch_point_dict(const LimitCycleBranchPoint& q) {
  return py::dict(py::arg("speed_m_s") = q.speed, py::arg("amplitude_m") = q.amplitude, py::arg("period_s") = q.period,
                  py::arg("stable") = q.stable, py::arg("largest_multiplier") = q.largest_multiplier,
                  py::arg("newton_residual") = q.residual);
}

// The branch as a dict: its points as columns (lists), the fold a dict or None.
py::dict branch_dict(const LimitCycleBranch& b) {
  const auto& p = b.points;
  py::dict points(py::arg("speed_m_s") = column(p.size(), [&](size_t i) { return p[i].speed; }),
                  py::arg("amplitude_m") = column(p.size(), [&](size_t i) { return p[i].amplitude; }),
                  py::arg("period_s") = column(p.size(), [&](size_t i) { return p[i].period; }),
                  py::arg("largest_multiplier") = column(p.size(), [&](size_t i) { return p[i].largest_multiplier; }),
                  py::arg("newton_residual") = column(p.size(), [&](size_t i) { return p[i].residual; }));
  py::list stable;
  for (const LimitCycleBranchPoint& q : p) stable.append(q.stable);
  points["stable"] = stable;
  py::list folds;
  for (const LimitCycleBranchPoint& q : b.folds) folds.append(branch_point_dict(q));
  return py::dict(py::arg("kind") = std::string(to_string(b.kind)),
                  py::arg("hopf_speed_m_s") = optional_value(b.hopf_speed),
                  py::arg("hopf_frequency_hz") = b.hopf_frequency, py::arg("watched_wheelset") = b.watched_wheelset,
                  py::arg("points") = points, py::arg("folds") = folds,
                  py::arg("fold") = b.fold ? py::object(branch_point_dict(*b.fold)) : py::object(py::none()),
                  py::arg("end") = std::string(to_string(b.end)), py::arg("failure") = b.failure,
                  py::arg("one_period_integrations") = b.flows);
}

void bind_limit_cycles(py::module_& m) {
  m.def(
      "limit_cycles_scene",
      [](const Scene& scene, const py::object& vehicle, double start_amplitude, double max_amplitude,
         int steps_per_period, double newton_tolerance) {
        if (!scene.nonlinear_hunting)
          throw InputError(scene.source, 0, 0, "the scene has no [nonlinear_hunting] table (docs/stability.md)");
        const Vehicle v = vehicle.is_none() ? vehicle_argument(py::str(scene.vehicle_file)) : vehicle_argument(vehicle);
        LimitCycleOptions o;
        o.start_amplitude = start_amplitude;
        o.max_amplitude = max_amplitude;
        o.steps_per_period = steps_per_period;
        o.newton_tolerance = newton_tolerance;
        LimitCycleBranch b;
        {
          py::gil_scoped_release release;
          b = continue_limit_cycles(assemble(v, DofSet::lateral), *scene.nonlinear_hunting, o);
        }
        return branch_dict(b);
      },
      py::arg("scene"), py::arg("vehicle") = py::none(), py::kw_only(),
      py::arg("start_amplitude_m") = LimitCycleOptions{}.start_amplitude,
      py::arg("max_amplitude_m") = LimitCycleOptions{}.max_amplitude,
      py::arg("steps_per_period") = LimitCycleOptions{}.steps_per_period,
      py::arg("newton_tolerance") = LimitCycleOptions{}.newton_tolerance,
      "The branch of hunting limit cycles of the scene's [nonlinear_hunting] model by continuation from the Hopf "
      "point (continue_limit_cycles; 'railmodal hunting --continuation'), as a dict: kind, hopf_speed_m_s, "
      "hopf_frequency_hz, points (columns), fold (the nonlinear critical speed of a subcritical branch), folds, end, "
      "failure. ValueError for bad options or a vehicle without wheelsets.");
}

void bind_lateral_stability(py::module_& m) {
  py::class_<LateralStability>(m, "LateralStability", "Static lateral stability of a body on its springs (eq. (235b))")
      .def_readonly("body", &LateralStability::body)
      .def_readonly("roll_stiffness_n_m_rad", &LateralStability::roll_stiffness)
      .def_readonly("metacentric_height_m", &LateralStability::metacentric_height)
      .def_readonly("cg_height_m", &LateralStability::cg_height)
      .def_readonly("margin_m", &LateralStability::margin, "h − d0: the body returns when positive")
      .def("nolltein_measure", &LateralStability::nolltein_measure, py::arg("b2_m"),
           "h / (b2 d0), 1/m, eq. (242c), for the half spacing b2 of the springs nearest the track")
      .def_readonly("summary", &LateralStability::summary);
  m.def(
      "lateral_stability",
      [](const py::object& vehicle, const std::string& body) {
        const Vehicle v = vehicle_argument(vehicle);
        py::gil_scoped_release release;
        return lateral_stability(v, body);
      },
      py::arg("vehicle"), py::arg("body") = "body",
      "The metacentric height and Nolltein's measure of `body` (a vehicle file or Vehicle).");
}

}  // namespace

void bind_stability(py::module_& m) {
  bind_hunting(m);
  bind_nonlinear_hunting(m);
  bind_scene_hunting(m);
  bind_limit_cycles(m);
  bind_lateral_stability(m);
}

}  // namespace railmodal::python
