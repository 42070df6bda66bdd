// Scenes, time-domain simulation, amplitude spectra and the fft-check (docs/python.md, "Scenes
// and simulation"). Time histories and spectra come back as numpy views of the result's own
// memory (read-only; the result object is kept alive as their base).
#include <pybind11/eigen.h>

#include <optional>
#include <string>
#include <vector>

#include "analysis_values.hpp"
#include "bindings.hpp"
#include "railmodal/fft_check_report.hpp"
#include "railmodal/scene.hpp"
#include "railmodal/scene_simulation.hpp"
#include "railmodal/simulation.hpp"
#include "railmodal/spectrum.hpp"

namespace railmodal::python {
namespace {

// The scene's vehicle: `vehicle` when given (a file or a Vehicle), else the scene's own file, as
// the command line's --vehicle wins over the scene's key.
Vehicle scene_vehicle(const Scene& scene, const py::object& vehicle) {
  if (!vehicle.is_none()) return vehicle_argument(vehicle);
  if (scene.vehicle_file.empty())
    throw py::value_error("no vehicle: give vehicle=... or a 'vehicle' key in " + scene.source);
  return vehicle_argument(py::str(scene.vehicle_file));
}

py::dict simulation_spec(const SimulationSpec& s) {
  py::list initial;
  for (const InitialCondition& c : s.initial)
    initial.append(py::dict(py::arg("dof") = c.dof, py::arg("displacement") = c.displacement,
                            py::arg("velocity") = c.velocity));
  return py::dict(py::arg("speed_m_s") = s.speed, py::arg("final_speed_m_s") = s.final_speed,
                  py::arg("friction_law") = s.friction_law, py::arg("duration_s") = s.duration,
                  py::arg("time_step_s") = s.time_step, py::arg("effects") = s.effects,
                  py::arg("tolerance") = s.tolerance, py::arg("event_tolerance_s") = s.event_tolerance,
                  py::arg("initial") = initial, py::arg("outputs") = s.outputs);
}

// What the analyses of this file read of a scene (py-core's bind_response binds Scene itself).
void bind_scene_simulation(py::module_& m) {
  m.def(
      "simulation_spec",
      [](const Scene& s) { return s.simulation ? py::object(simulation_spec(*s.simulation)) : py::none(); },
      py::arg("scene"), "The scene's [simulation] table as a dict (SI, units in the keys), or None");
}

py::list event_records(const std::vector<SimulationEvent>& events) {
  py::list out;
  for (const SimulationEvent& e : events)
    out.append(py::dict(py::arg("time_s") = e.time, py::arg("element") = e.element,
                        py::arg("kind") = std::string(to_string(e.kind))));
  return out;
}

void bind_history(py::module_& m) {
  py::class_<TimeHistory>(m, "TimeHistory",
                          "Sampled response: time (s), displacement and velocity (samples × DOFs), read-only views")
      .def_readonly("labels", &TimeHistory::labels, "the DOF labels, the columns")
      .def_property_readonly(
          "time", [](const TimeHistory& h) -> const Eigen::VectorXd& { return h.time; }, kView, "s")
      .def_property_readonly(
          "displacement", [](const TimeHistory& h) -> const Eigen::MatrixXd& { return h.displacement; }, kView,
          "m or rad, samples × DOFs (a view, Fortran order)")
      .def_property_readonly(
          "velocity", [](const TimeHistory& h) -> const Eigen::MatrixXd& { return h.velocity; }, kView,
          "m/s or rad/s, samples × DOFs (empty when only the outputs were kept)")
      .def_property_readonly("events", [](const TimeHistory& h) { return event_records(h.events); },
                             "records of the nonlinear path's regime changes: time_s, element, kind")
      .def_readonly("steps_taken", &TimeHistory::steps_taken)
      .def_readonly("summary", &TimeHistory::summary)
      .def(
          "column",
          [](py::object self, const std::string& label) {
            const TimeHistory& h = self.cast<const TimeHistory&>();
            for (size_t j = 0; j < h.labels.size(); ++j)
              if (h.labels[j] == label)
                return vector_view(h.displacement.col(static_cast<Eigen::Index>(j)).data(),
                                   static_cast<size_t>(h.displacement.rows()), self);
            throw py::key_error("no DOF '" + label + "' in the history; it has: " + py::str(py::cast(h.labels)).cast<std::string>());
          },
          py::arg("label"), "The displacement of one DOF by its label (a view)")
      .def(
          "columns",
          [](py::object self) {
            const TimeHistory& h = self.cast<const TimeHistory&>();
            py::dict out;
            out["time_s"] = vector_view(h.time, self);
            for (size_t j = 0; j < h.labels.size(); ++j)
              out[py::str(h.labels[j])] = vector_view(h.displacement.col(static_cast<Eigen::Index>(j)).data(),
                                                      static_cast<size_t>(h.displacement.rows()), self);
            return out;
          },
          "time_s and each DOF's displacement by label, as views: pandas.DataFrame(h.columns())");
}

void bind_spectrum(py::module_& m) {
  py::class_<Spectrum>(m, "Spectrum", "A one-sided amplitude spectrum (peak amplitudes, the signal's unit)")
      .def_property_readonly(
          "amplitude", [](const Spectrum& s) -> const Eigen::VectorXd& { return s.amplitude; }, kView,
          "bins 0 … M/2, a view")
      .def_property_readonly("frequencies", [](const Spectrum& s) { return Eigen::VectorXd(s.frequencies()); },
                             "Hz, every bin")
      .def_readonly("sampling_rate_hz", &Spectrum::sampling_rate)
      .def_readonly("signal_length", &Spectrum::signal_length)
      .def_readonly("transform_length", &Spectrum::transform_length)
      .def_readonly("resolution_hz", &Spectrum::resolution, "fs/N")
      .def_readonly("bin_spacing_hz", &Spectrum::bin_spacing, "fs/M")
      .def_property_readonly("window", [](const Spectrum& s) { return std::string(to_string(s.window)); })
      .def_readonly("coherent_gain", &Spectrum::coherent_gain)
      .def_readonly("summary", &Spectrum::summary)
      .def(
          "peaks",
          [](const Spectrum& s, double threshold, double min_dip) {
            PeakOptions options;
            options.threshold = threshold;
            options.min_dip = min_dip;
            py::list out;
            for (const SpectralPeak& p : find_peaks(s, options))
              out.append(py::dict(py::arg("frequency_hz") = p.frequency, py::arg("amplitude") = p.amplitude,
                                  py::arg("bin") = p.bin, py::arg("resolution_hz") = p.resolution));
            return out;
          },
          py::arg("threshold") = PeakOptions{}.threshold, py::arg("min_dip") = PeakOptions{}.min_dip,
          "Spectral peaks (find_peaks) as records: frequency_hz (Hz), amplitude (the signal's unit, a peak "
          "amplitude), bin, resolution_hz (Hz)");

  const auto spectrum_options = [](const std::string& window, bool remove_mean, const std::string& padding,
                                   Eigen::Index padded_length) {
    SpectrumOptions o;
    o.window = enum_argument(window, window_from_string, "window", "'rectangular', 'hann', 'flat-top'");
    o.remove_mean = remove_mean;
    o.padding =
        enum_argument(padding, padding_from_string, "padding", "'none', 'to-length', 'next-power-of-two'");
    o.padded_length = padded_length;
    return o;
  };
  m.def(
      "amplitude_spectrum",
      [spectrum_options](const Eigen::Ref<const Eigen::VectorXd>& signal, double sampling_rate_hz,
                         const std::string& window, bool remove_mean, const std::string& padding,
                         Eigen::Index padded_length) {
        const SpectrumOptions options = spectrum_options(window, remove_mean, padding, padded_length);
        py::gil_scoped_release release;
        return amplitude_spectrum(signal, sampling_rate_hz, options);
      },
      py::arg("signal"), py::arg("sampling_rate_hz"), py::kw_only(), py::arg("window") = "hann",
      py::arg("remove_mean") = true, py::arg("padding") = "none", py::arg("padded_length") = 0,
      "The amplitude spectrum of a uniformly sampled real signal (FFTW).");
  m.def(
      "amplitude_spectra",
      [spectrum_options](const Eigen::Ref<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>& signals,
                         double sampling_rate_hz, const std::string& window, bool remove_mean,
                         const std::string& padding, Eigen::Index padded_length) {
        const SpectrumOptions options = spectrum_options(window, remove_mean, padding, padded_length);
        std::vector<Spectrum> out(static_cast<size_t>(signals.rows()));
        py::gil_scoped_release release;
        SpectrumAnalyzer analyzer(signals.cols(), options);  // planned once for every row
        for (Eigen::Index i = 0; i < signals.rows(); ++i)
          analyzer.compute(signals.row(i).transpose(), sampling_rate_hz, &out[static_cast<size_t>(i)]);
        return out;
      },
      py::arg("signals"), py::arg("sampling_rate_hz"), py::kw_only(), py::arg("window") = "hann",
      py::arg("remove_mean") = true, py::arg("padding") = "none", py::arg("padded_length") = 0,
      "The spectra of the rows of a 2-D array (signals × samples), with one transform plan.");
}

py::list fft_check_records(const std::vector<FftCheck>& checks) {
  py::list out;
  for (const FftCheck& c : checks)
    out.append(py::dict(py::arg("mode") = c.mode, py::arg("mode_name") = c.mode_name, py::arg("dof") = c.dof,
                        py::arg("undamped_frequency_hz") = c.modal_hz, py::arg("damped_frequency_hz") = c.damped_hz,
                        py::arg("damping_ratio") = c.damping_ratio, py::arg("peak_frequency_hz") = optional_value(c.peak_hz),
                        py::arg("rel_error") = c.rel_error, py::arg("resolution_hz") = c.resolution_hz,
                        py::arg("within_resolution") = c.within_resolution,
                        py::arg("modal_amplitude_ratio") = c.modal_amplitude_ratio, py::arg("excited") = c.excited,
                        py::arg("tolerance") = c.tolerance,
                        py::arg("outcome") = to_string(c.outcome),  // the reports' words
                        py::arg("needed_duration_s") = c.needed_duration_s,
                        // The JSON's why_not_applicable: the words, where the outcome is "not applicable".
                        py::arg("why_not_applicable") = c.outcome == FftCheck::Outcome::not_applicable
                                                            ? py::object(py::str(c.why_not_applicable))
                                                            : py::object(py::none()),
                        // The JSON's why_decayed, where the outcome is "decayed".
                        py::arg("why_decayed") = c.outcome == FftCheck::Outcome::decayed
                                                     ? py::object(py::str(c.why_decayed))
                                                     : py::object(py::none())));
  return out;
}

py::dict spectra_by_dof(const std::vector<std::string>& dofs, const std::vector<Spectrum>& spectra) {
  py::dict out;
  for (size_t i = 0; i < dofs.size(); ++i) out[py::str(dofs[i])] = spectra[i];
  return out;
}

py::dict swings_dict(const Swings& s) {
  return py::dict(py::arg("dof") = s.dof, py::arg("turning_times_s") = s.turning_times,
                  py::arg("turning_values") = s.turning_values, py::arg("crossing_times_s") = s.crossing_times,
                  py::arg("comes_to_rest") = s.comes_to_rest,
                  py::arg("half_periods_between_turns_s") = s.half_periods_between_turns(),
                  py::arg("half_periods_between_crossings_s") = s.half_periods_between_crossings());
}

void bind_fft_check(py::module_& m) {
  py::class_<FftCheckResult>(m, "FftCheckResult", "Spectral peaks of a simulated scene against its modes")
      .def_readonly("history", &FftCheckResult::history)
      .def_property_readonly("checks", [](const FftCheckResult& r) { return fft_check_records(r.checks); },
                             "records, one per mode")
      .def("records", [](const FftCheckResult& r) { return fft_check_records(r.checks); },
           "The checks, one row per mode (the same as `checks`): mode, mode_name, dof, undamped_frequency_hz, "
           "damped_frequency_hz (the frequency checked) and peak_frequency_hz (Hz), damping_ratio, "
           "rel_error (relative), resolution_hz (Hz), within_resolution, modal_amplitude_ratio (dimensionless), "
           "excited, tolerance (relative), outcome, needed_duration_s (s), why_not_applicable")
      .def_property_readonly("spectra", [](const FftCheckResult& r) { return spectra_by_dof(r.spectrum_dofs, r.spectra); },
                             "Spectrum by DOF label")
      .def_property_readonly("swings",
                             [](const FftCheckResult& r) { return r.swings ? py::object(swings_dict(*r.swings)) : py::none(); })
      .def_property_readonly(
          "half_period_check",
          [](const FftCheckResult& r) {
            if (!r.half_period_check) return py::object(py::none());
            const FftCheckResult::HalfPeriodCheck& h = *r.half_period_check;
            return py::object(py::dict(py::arg("count") = h.count, py::arg("passed") = h.passed,
                                       py::arg("tolerance") = h.tolerance, py::arg("worst_rel_error") = h.worst_rel_error));
          },
          "The check of a free friction decay by its half periods between turning points (JSON "
          "half_period_check: count, passed, tolerance, worst_rel_error), or None where it was not made")
      .def_readonly("linear_half_period_s", &FftCheckResult::linear_half_period_s)
      .def_readonly("nonlinear", &FftCheckResult::nonlinear)
      .def_readonly("checked", &FftCheckResult::checked)
      .def_readonly("failed", &FftCheckResult::failed)
      .def_readonly("passed", &FftCheckResult::passed)
      .def_property_readonly("verdict", &fft_check_verdict,
                             "The verdict in words, as the command line and the JSON's verdict_text give it: "
                             "'passed: …', 'FAILED: …' or 'NOT CHECKED: …' (not checked is not a pass)")
      .def_readonly("summary", &FftCheckResult::summary)
      .def("__repr__", [](const FftCheckResult& r) { return "FftCheckResult(" + fft_check_verdict(r) + ")"; });

  m.def(
      "fft_check",
      [](const Scene& scene, const py::object& vehicle, double memory_limit) {
        const Vehicle v = scene_vehicle(scene, vehicle);
        py::gil_scoped_release release;
        return as_input_error(scene.source, [&] { return fft_check(scene, v, memory_limit); });
      },
      py::arg("scene"), py::arg("vehicle") = py::none(), py::kw_only(), py::arg("memory_limit") = kDefaultMemoryLimit,
      "Simulates the scene and checks the spectral peaks against the modal frequencies (railmodal fft-check).");
}

void bind_simulate(py::module_& m) {
  m.def(
      "simulate",
      [](const Scene& scene, const py::object& vehicle, bool outputs_only, double memory_limit) {
        const Vehicle v = scene_vehicle(scene, vehicle);
        py::gil_scoped_release release;
        return as_input_error(scene.source, [&] {
          if (!outputs_only) return simulate_scene(scene, v);
          OutputRecord record(scene, false, memory_limit);
          std::vector<HistorySink*> sinks{&record};
          return record.history(simulate_scene(scene, v, sinks));
        });
      },
      py::arg("scene"), py::arg("vehicle") = py::none(), py::kw_only(), py::arg("outputs_only") = false,
      py::arg("memory_limit") = kDefaultMemoryLimit,
      "Runs the scene's [simulation]: every DOF's displacement and velocity, or with outputs_only the "
      "displacements of the DOFs the scene outputs (what 'railmodal simulate' writes), refused over "
      "memory_limit bytes.");
  m.def(
      "output_spectra",
      [](const TimeHistory& history, const Scene& scene) {
        OutputSpectra spectra;
        {
          py::gil_scoped_release release;
          spectra = as_input_error(scene.source, [&] { return output_spectra(history, scene); });
        }
        return spectra_by_dof(spectra.dofs, spectra.spectra);
      },
      py::arg("history"), py::arg("scene"),
      "The amplitude spectra of the scene's outputs (Hann, zero-padded ×4), Spectrum by DOF label "
      "('railmodal simulate --spectra').");
  m.def(
      "swings", [](const TimeHistory& history, const std::string& dof) {
        for (size_t j = 0; j < history.labels.size(); ++j)
          if (history.labels[j] == dof) return swings_dict(swings(history, static_cast<int>(j)));
        throw py::key_error("no DOF '" + dof + "' in the history");
      },
      py::arg("history"), py::arg("dof"), "Turning points and zero crossings of one DOF (Hermite interpolation).");
}

}  // namespace

void bind_simulation(py::module_& m) {
  bind_scene_simulation(m);
  bind_history(m);
  bind_spectrum(m);
  bind_fft_check(m);
  bind_simulate(m);
}

}  // namespace railmodal::python
