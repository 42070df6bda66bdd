// Undamped and damped modes: modes(system, **ModalOptions), damped_modes(system,
// **DampedModalOptions), modes_batch over a stack of M, K; the results as numpy arrays (one
// entry per mode), shapes (n_dofs × n_modes, like Φ) and records for pandas. Also the analysis
// summary every result carries (AnalysisSummary, bound here once for every area).
#include <pybind11/complex.h>
#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "arrays.hpp"
#include "bindings.hpp"
#include "dofs.hpp"
#include "number_text.hpp"
#include "options.hpp"
#include "railmodal/damped_modal.hpp"
#include "railmodal/linear_system.hpp"
#include "railmodal/modal.hpp"
#include "railmodal/summary.hpp"

namespace py = pybind11;

namespace railmodal::python {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

ModalOptions read_modal_options(py::dict options, const std::string& what) {
  if (options.empty()) return {};  // the common call: no reader, no allocations
  OptionReader reader(std::move(options), what);
  ModalOptions o;
  reader.read("zero_tolerance", &o.zero_tolerance);
  reader.read("max_residual", &o.max_residual);
  reader.read_enum("solver", &o.solver, modal_solver_from_string, "dense, arpack, auto");
  reader.read("mode_count", &o.mode_count);
  OptionReader arpack(reader.nested("arpack"), what + ", arpack");
  arpack.read("shift", &o.arpack.shift);
  arpack.read("tolerance", &o.arpack.tolerance);
  arpack.read("subspace_size", &o.arpack.subspace_size);
  arpack.read("max_iterations", &o.arpack.max_iterations);
  arpack.finish();
  reader.finish();
  return o;
}

DampedModalOptions read_damped_options(py::dict options) {
  OptionReader reader(std::move(options), "damped_modes()");
  DampedModalOptions o;
  o.undamped = read_modal_options(reader.nested("undamped"), "damped_modes(), undamped");
  reader.read("critical_gap", &o.critical_gap);
  reader.finish();
  return o;
}

// One double per mode, gathered into a new array.
template <typename Modes, typename Field>
py::array per_mode(const Modes& modes, Field field) {
  std::vector<double> values;
  values.reserve(modes.size());
  for (const auto& mode : modes) values.push_back(field(mode));
  return take(std::move(values));
}

// One word per mode (its name, its kind): a list of str in Python.
template <typename Modes, typename Field>
std::vector<std::string> words_per_mode(const Modes& modes, Field field) {
  std::vector<std::string> words;
  words.reserve(modes.size());
  for (const auto& mode : modes) words.emplace_back(field(mode));
  return words;
}

template <typename Scalar, typename Modes, typename Field>
py::array columns(const Modes& modes, std::size_t dofs, Field field) {
  Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic> out(dofs, modes.size());
  for (std::size_t j = 0; j < modes.size(); ++j) out.col(static_cast<Eigen::Index>(j)) = field(modes[j]);
  return take(std::move(out));
}

py::object optional_value(const std::optional<double>& v) {
  return v ? py::object(py::float_(*v)) : py::object(py::none());
}

py::dict mode_record(const Mode& mode) {
  py::dict r;
  r["index"] = mode.index;
  r["name"] = mode.name;
  r["kind"] = to_string(mode.kind);
  r["frequency_hz"] = mode.frequency_hz;
  r["period_s"] = mode.period_s;
  r["omega_rad_s"] = mode.omega_rad_s;
  r["eigenvalue"] = mode.eigenvalue;
  r["divergence_rate_per_s"] = mode.divergence_rate;
  r["repeated"] = mode.repeated;
  r["residual"] = mode.residual;
  r["eigenvalue_error"] = mode.eigenvalue_error;
  r["centre_body"] = mode.centre ? py::object(py::str(mode.centre->body)) : py::object(py::none());
  r["centre_about"] = mode.centre ? py::object(py::str(mode.centre->about)) : py::object(py::none());
  r["centre_position_m"] =
      mode.centre && !mode.centre->at_infinity ? py::object(py::float_(mode.centre->position)) : py::object(py::none());
  return r;
}

py::list summary_checks(const AnalysisSummary& s) {
  py::list out;
  for (const Check& c : s.checks) {
    py::dict r;
    r["name"] = c.name;
    r["value"] = c.value;
    r["limit"] = c.limit;
    r["passed"] = c.passed;
    out.append(r);
  }
  return out;
}

py::list summary_stages(const AnalysisSummary& s) {
  py::list out;
  for (const StageTiming& t : s.stages) {
    py::dict r;
    r["stage"] = t.stage;
    r["seconds"] = t.seconds;
    out.append(r);
  }
  return out;
}

void bind_summary(py::module_& m) {
  py::class_<AnalysisSummary>(m, "AnalysisSummary",
                              "What an analysis did: method, checks (records: name, value and limit in the unit the "
                              "name says, passed) and stage times (records: stage, seconds, s).")
      .def_readonly("analysis", &AnalysisSummary::analysis)
      .def_readonly("method", &AnalysisSummary::method)
      .def_property_readonly("checks", &summary_checks)
      .def_property_readonly("stages", &summary_stages)
      .def_property_readonly("total_seconds", &AnalysisSummary::total_seconds)
      .def_property_readonly("passed", &AnalysisSummary::passed)
      .def("brief", &AnalysisSummary::brief)
      .def("__repr__", &AnalysisSummary::brief);
  py::class_<SolverSummary, AnalysisSummary>(m, "SolverSummary", "AnalysisSummary with the ARPACK figures.")
      .def_property_readonly("solver", [](const SolverSummary& s) { return std::string(to_string(s.solver)); })
      .def_readonly("shift", &SolverSummary::shift)
      .def_readonly("factorisation", &SolverSummary::factorisation)
      .def_readonly("requested", &SolverSummary::requested)
      .def_readonly("subspace_size", &SolverSummary::subspace_size)
      .def_readonly("restarts", &SolverSummary::restarts)
      .def_readonly("operator_applications", &SolverSummary::operator_applications)
      .def_readonly("runs", &SolverSummary::runs)
      .def_readonly("count_checked", &SolverSummary::count_checked);
}

void bind_modal_result(py::module_& m) {
  py::class_<Mode>(m, "Mode", "One undamped mode; shape is a read-only view (mass-normalised).")
      .def_readonly("index", &Mode::index)
      .def_property_readonly("kind", [](const Mode& x) { return std::string(to_string(x.kind)); })
      .def_readonly("eigenvalue", &Mode::eigenvalue, "λ = ω², 1/s²")
      .def_readonly("omega_rad_s", &Mode::omega_rad_s)
      .def_readonly("frequency_hz", &Mode::frequency_hz)
      .def_readonly("period_s", &Mode::period_s)
      .def_readonly("divergence_rate_per_s", &Mode::divergence_rate)
      .def_readonly("name", &Mode::name)
      .def_property_readonly("shape", [](py::object self) { return vector_view(self.cast<const Mode&>().shape, self); })
      .def_property_readonly("kinetic_energy_share",
                             [](py::object self) { return vector_view(self.cast<const Mode&>().kinetic_energy_share, self); })
      .def_readonly("repeated", &Mode::repeated)
      .def_readonly("residual", &Mode::residual)
      .def_readonly("eigenvalue_error", &Mode::eigenvalue_error)
      .def("to_dict", &mode_record)
      .def("__repr__", [](const Mode& x) {
        return "Mode(" + std::to_string(x.index) + ", '" + x.name + "', " + number_text(x.frequency_hz, 6) + " Hz)";
      });

  py::class_<ModalResult>(m, "ModalResult",
                          "Undamped modes. Per-mode arrays (frequencies_hz, ...) are new arrays, shapes is "
                          "(n_dofs, n_modes) like Φ; records() for pandas.DataFrame.")
      .def_property_readonly("dof_labels", [](const ModalResult& r) { return dof_labels(r.dofs); })
      .def_property_readonly("modes", [](const ModalResult& r) { return r.modes; }, "a list of Mode (copies)")
      .def_property_readonly("frequencies_hz", [](const ModalResult& r) { return per_mode(r.modes, [](const Mode& x) { return x.frequency_hz; }); })
      .def_property_readonly("periods_s", [](const ModalResult& r) { return per_mode(r.modes, [](const Mode& x) { return x.period_s; }); })
      .def_property_readonly("omega_rad_s", [](const ModalResult& r) { return per_mode(r.modes, [](const Mode& x) { return x.omega_rad_s; }); })
      .def_property_readonly("eigenvalues", [](const ModalResult& r) { return per_mode(r.modes, [](const Mode& x) { return x.eigenvalue; }); })
      .def_property_readonly("names", [](const ModalResult& r) { return words_per_mode(r.modes, [](const Mode& x) { return x.name; }); })
      .def_property_readonly("kinds", [](const ModalResult& r) { return words_per_mode(r.modes, [](const Mode& x) { return to_string(x.kind); }); })
      .def_property_readonly("shapes", [](const ModalResult& r) {
        return columns<double>(r.modes, r.dofs.size(), [](const Mode& x) -> const Eigen::VectorXd& { return x.shape; });
      }, "(n_dofs, n_modes), mass-normalised: shapes.T @ M @ shapes = I")
      .def_property_readonly("kinetic_energy_shares", [](const ModalResult& r) {
        return columns<double>(r.modes, r.dofs.size(), [](const Mode& x) -> const Eigen::VectorXd& { return x.kinetic_energy_share; });
      })
      .def_readonly("condensed", &ModalResult::condensed)
      .def_readonly("max_residual", &ModalResult::max_residual)
      .def_readonly("orthonormality_error", &ModalResult::orthonormality_error)
      .def_readonly("solver", &ModalResult::solver)
      .def_readonly("notes", &ModalResult::notes)
      .def("records", [](const ModalResult& r) {
        py::list out;
        for (const Mode& x : r.modes) out.append(mode_record(x));
        return out;
      }, "One dict per mode: index, name, kind, frequency_hz (Hz), period_s (s), omega_rad_s (rad/s), "
         "eigenvalue (λ = ω², 1/s²), divergence_rate_per_s (1/s), repeated, residual (relative), "
         "eigenvalue_error (1/s²), centre_body, centre_about, centre_position_m (m)")
      .def("__len__", [](const ModalResult& r) { return r.modes.size(); })
      .def("__getitem__", [](const ModalResult& r, py::ssize_t i) {
        const auto n = static_cast<py::ssize_t>(r.modes.size());
        if (i < 0) i += n;
        if (i < 0 || i >= n) throw py::index_error("mode index out of range");
        return r.modes[static_cast<std::size_t>(i)];
      })
      .def("__repr__", [](const ModalResult& r) {
        return "ModalResult(" + std::to_string(r.modes.size()) + " modes, " + std::to_string(r.dofs.size()) + " DOFs, " +
               to_string(r.solver.solver) + ")";
      });
}

py::dict damped_record(const DampedMode& mode) {
  py::dict r;
  r["index"] = mode.index;
  r["name"] = mode.name;
  r["kind"] = to_string(mode.kind);
  r["stable"] = mode.stable;
  r["damped_frequency_hz"] = optional_value(mode.damped_frequency_hz);
  r["damping_ratio"] = optional_value(mode.damping_ratio);
  r["natural_frequency_hz"] = optional_value(mode.natural_frequency_hz);
  r["decay_rate_per_s"] = mode.decay_rate;
  r["undamped_mode"] = mode.undamped_mode;
  r["eigenvalue"] = mode.eigenvalues.empty() ? std::complex<double>(kNaN, kNaN) : mode.eigenvalues.front();
  r["residual"] = mode.residual;
  return r;
}

void bind_damped_result(py::module_& m) {
  py::class_<DampedModalResult>(m, "DampedModalResult",
                                "Damped modes. Per-mode arrays (NaN where the C++ value is empty), complex shapes "
                                "(n_dofs, n_modes); records() for pandas.DataFrame.")
      .def_property_readonly("dof_labels", [](const DampedModalResult& r) { return dof_labels(r.dofs); })
      .def_property_readonly("eigenvalues", [](const DampedModalResult& r) {
        std::vector<std::complex<double>> values;
        for (const DampedMode& x : r.modes) values.push_back(x.eigenvalues.empty() ? std::complex<double>(kNaN, kNaN) : x.eigenvalues.front());
        return take(std::move(values));
      }, "the first eigenvalue of each mode (Im > 0 for a pair), 1/s")
      .def_property_readonly("damped_frequencies_hz", [](const DampedModalResult& r) {
        return per_mode(r.modes, [](const DampedMode& x) { return x.damped_frequency_hz.value_or(kNaN); });
      })
      .def_property_readonly("damping_ratios", [](const DampedModalResult& r) {
        return per_mode(r.modes, [](const DampedMode& x) { return x.damping_ratio.value_or(kNaN); });
      })
      .def_property_readonly("natural_frequencies_hz", [](const DampedModalResult& r) {
        return per_mode(r.modes, [](const DampedMode& x) { return x.natural_frequency_hz.value_or(kNaN); });
      })
      .def_property_readonly("decay_rates_per_s", [](const DampedModalResult& r) {
        return per_mode(r.modes, [](const DampedMode& x) { return x.decay_rate; });
      })
      .def_property_readonly("names", [](const DampedModalResult& r) { return words_per_mode(r.modes, [](const DampedMode& x) { return x.name; }); })
      .def_property_readonly("kinds", [](const DampedModalResult& r) { return words_per_mode(r.modes, [](const DampedMode& x) { return to_string(x.kind); }); })
      .def_property_readonly("shapes", [](const DampedModalResult& r) {
        return columns<std::complex<double>>(r.modes, r.dofs.size(), [](const DampedMode& x) -> const Eigen::VectorXcd& { return x.shape; });
      }, "(n_dofs, n_modes) complex, φᴴMφ = 1")
      .def_property_readonly("undamped", [](py::object self) { return py::cast(self.cast<const DampedModalResult&>().undamped, py::return_value_policy::reference_internal, self); })
      .def_readonly("condensed", &DampedModalResult::condensed)
      .def_readonly("first_order", &DampedModalResult::first_order)
      .def_readonly("notes", &DampedModalResult::notes, "what these damped modes leave out or add, a sentence each")
      .def_readonly("stable", &DampedModalResult::stable)
      .def_readonly("max_residual", &DampedModalResult::max_residual)
      .def_readonly("summary", &DampedModalResult::summary)
      .def("records", [](const DampedModalResult& r) {
        py::list out;
        for (const DampedMode& x : r.modes) out.append(damped_record(x));
        return out;
      }, "One dict per mode: index, name, kind, stable, damped_frequency_hz (Hz), damping_ratio (a fraction), "
         "natural_frequency_hz (Hz), decay_rate_per_s (1/s), undamped_mode, eigenvalue (complex, 1/s), "
         "residual (relative)")
      .def("__len__", [](const DampedModalResult& r) { return r.modes.size(); })
      .def("__repr__", [](const DampedModalResult& r) {
        return "DampedModalResult(" + std::to_string(r.modes.size()) + " modes, " + (r.stable ? "stable" : "unstable") + ")";
      });
}

}  // namespace

void bind_modes(py::module_& m) {
  bind_summary(m);
  bind_modal_result(m);
  bind_damped_result(m);

  m.def(
      "modes",
      [](const LinearSystem& system, py::kwargs options) {
        const ModalOptions o = read_modal_options(options, "modes()");
        py::gil_scoped_release release;
        return solve_modes(system, o);
      },
      py::arg("system"),
      "Undamped modes of a LinearSystem. Keywords as ModalOptions: zero_tolerance, max_residual, "
      "solver ('dense', 'arpack', 'auto'), mode_count, arpack={'shift', 'tolerance', 'subspace_size', "
      "'max_iterations'}.");
  m.def(
      "modes",
      [](const SparseSystem& system, py::kwargs options) {
        const ModalOptions o = read_modal_options(options, "modes()");
        py::gil_scoped_release release;
        return solve_modes(system, o);
      },
      py::arg("system"), "Undamped modes of a SparseSystem (ARPACK works on it directly).");

  m.def(
      "damped_modes",
      [](const LinearSystem& system, py::kwargs options) {
        const DampedModalOptions o = read_damped_options(options);
        py::gil_scoped_release release;
        return solve_damped_modes(system, o);
      },
      py::arg("system"),
      "Damped modes. Keywords as DampedModalOptions: undamped={ModalOptions keywords}, critical_gap.");

  m.def(
      "modes_of_vehicles",
      [](const std::vector<const Vehicle*>& vehicles, const std::string& dofs, py::kwargs options) {
        const std::optional<DofSet> set = dof_set_from_string(dofs);
        if (!set) throw py::value_error("dofs is '" + dofs + "'; expected one of vertical, lateral, all");
        const ModalOptions o = read_modal_options(options, "modes_of_vehicles()");
        std::vector<ModalResult> results;
        results.reserve(vehicles.size());
        py::gil_scoped_release release;
        for (const Vehicle* vehicle : vehicles) results.push_back(solve_modes(assemble(*vehicle, *set), o));
        return results;
      },
      py::arg("vehicles"), py::arg("dofs") = "all",
      "Assembles and solves each vehicle of a list (design variants) in C++ without the GIL: a list of "
      "ModalResult. Keywords as modes().");

  m.def(
      "modes_batch",
      [](py::array_t<double, py::array::c_style | py::array::forcecast> mass,
         py::array_t<double, py::array::c_style | py::array::forcecast> stiffness, py::kwargs options) {
        if (mass.ndim() != 3 || stiffness.ndim() != 3 || mass.shape(0) != stiffness.shape(0) ||
            mass.shape(1) != mass.shape(2) || stiffness.shape(1) != mass.shape(1) || stiffness.shape(2) != mass.shape(1))
          throw py::value_error("modes_batch: M and K must be stacks of the same shape (batch, n, n)");
        const ModalOptions o = read_modal_options(options, "modes_batch()");
        const py::ssize_t count = mass.shape(0), n = mass.shape(1);
        std::vector<ModalResult> results(static_cast<std::size_t>(count));
        const double* pm = mass.data();
        const double* pk = stiffness.data();
        {
          py::gil_scoped_release release;
          using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
          for (py::ssize_t b = 0; b < count; ++b) {
            const Eigen::MatrixXd mb = Eigen::Map<const RowMajor>(pm + b * n * n, n, n);
            const Eigen::MatrixXd kb = Eigen::Map<const RowMajor>(pk + b * n * n, n, n);
            results[static_cast<std::size_t>(b)] = solve_modes(system_from_arrays(mb, kb, std::nullopt, {}), o);
          }
        }
        return results;
      },
      py::arg("M"), py::arg("K"),
      "Modes of each system of a stack M[b], K[b] (arrays (batch, n, n)), looped in C++ without the "
      "GIL: a list of ModalResult. Keywords as modes().");
}

}  // namespace railmodal::python
