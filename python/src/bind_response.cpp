// Harmonic response and critical speeds: the response over a numpy array of frequencies (one
// solve per frequency, looped in C++ without the GIL), frequency response functions between a
// unit force and chosen outputs, scenes and their excitation sources, critical speeds, and
// amplitude curves against a numpy array of speeds; the study of a scene as the command line
// runs it. Arrays a result owns are views with the result as base (docs/python.md).
#include <pybind11/complex.h>
#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <memory>
#include <string>
#include <vector>

#include "arrays.hpp"
#include "bindings.hpp"
#include "dofs.hpp"
#include "number_text.hpp"
#include "options.hpp"
#include "railmodal/critical_speed.hpp"
#include "railmodal/excitation.hpp"
#include "railmodal/input.hpp"
#include "railmodal/modal.hpp"
#include "railmodal/response.hpp"
#include "railmodal/scene.hpp"

namespace py = pybind11;

namespace railmodal::python {

namespace {

constexpr double kPi = 3.14159265358979323846;

// The steady response at each of several frequencies, for some outputs.
struct FrequencyResponse {
  std::vector<double> frequencies_hz;
  std::vector<std::string> outputs;
  std::string quantity;
  std::vector<std::complex<double>> values;  // frequency-major: values[f · outputs + o]
  std::vector<bool> unbounded;               // the same layout
};

// Solves at every frequency (direct or modal) and keeps `dofs`, × (iω)^k for the quantity.
FrequencyResponse sweep(const LinearSystem& system, const ModalResult& modes, const Eigen::VectorXcd& load,
                        const std::vector<double>& frequencies, const std::vector<int>& dofs, ResponseQuantity quantity,
                        bool modal, int mode_count) {
  if (load.size() != system.size())
    throw py::value_error("the load has " + std::to_string(load.size()) + " entries for " +
                          std::to_string(system.size()) + " degrees of freedom");
  if (static_cast<int>(modes.dofs.size()) != system.size())
    throw py::value_error("the modes are of another system (" + std::to_string(modes.dofs.size()) + " DOFs, not " +
                          std::to_string(system.size()) + ")");
  FrequencyResponse out;
  out.frequencies_hz = frequencies;
  out.quantity = to_string(quantity);
  for (int d : dofs) out.outputs.push_back(system.dofs[static_cast<std::size_t>(d)].label);
  out.values.resize(frequencies.size() * dofs.size());
  out.unbounded.resize(out.values.size());
  py::gil_scoped_release release;
  for (std::size_t f = 0; f < frequencies.size(); ++f) {
    if (!std::isfinite(frequencies[f]) || frequencies[f] < 0.0)
      throw std::invalid_argument("frequency " + number_text(frequencies[f]) + " Hz: expected finite and >= 0");
    const HarmonicResponse r = modal ? modal_harmonic_response(system, modes, load, frequencies[f], mode_count)
                                     : harmonic_response(system, modes, load, frequencies[f]);
    const std::complex<double> iw(0.0, 2.0 * kPi * frequencies[f]);
    const std::complex<double> factor = quantity == ResponseQuantity::displacement ? 1.0
                                        : quantity == ResponseQuantity::velocity   ? iw
                                                                                   : iw * iw;
    for (std::size_t o = 0; o < dofs.size(); ++o) {
      const std::size_t k = f * dofs.size() + o;
      out.unbounded[k] = r.unbounded && unbounded_at(r, modes, dofs[o]);
      out.values[k] = out.unbounded[k] ? 0.0 : factor * r.displacement[dofs[o]];
    }
  }
  return out;
}

std::vector<int> all_dofs(const LinearSystem& system) {
  std::vector<int> dofs(static_cast<std::size_t>(system.size()));
  for (int i = 0; i < system.size(); ++i) dofs[static_cast<std::size_t>(i)] = i;
  return dofs;
}

struct CriticalSpeedList {
  std::vector<CriticalSpeed> rows;
  AnalysisSummary summary;
};

// The keys of `railmodal critical-speed --format json`: a source by its number from 1
// (`source_index`, as the JSON and the tables' "[1]" number it) and its kind (`source_kind`).
py::dict critical_speed_record(const CriticalSpeed& c) {
  py::dict r;
  r["speed_m_s"] = c.speed;
  r["speed_kmh"] = 3.6 * c.speed;
  r["source_index"] = c.source + 1;
  r["source_kind"] = c.source_kind;
  r["harmonic"] = c.harmonic;
  r["mode"] = c.mode;
  r["mode_name"] = c.mode_name;
  r["frequency_hz"] = c.frequency_hz;
  r["output"] = c.output;
  r["unbounded"] = c.unbounded;
  r["amplitude"] = c.amplitude;
  r["growth_per_half_period"] = c.growth_per_half_period;
  r["friction_decrement_per_half_period"] = c.friction_decrement_per_half_period;
  r["friction_stops"] = c.friction_stops;
  r["friction_threshold_scale"] = c.friction_threshold_scale;
  return r;
}

py::dict curve_dict(const AmplitudeCurve& c) {
  py::dict d;
  d["speed_m_s"] = py::array_t<double>(static_cast<py::ssize_t>(c.speeds.size()), c.speeds.values().data());
  d["amplitude"] = py::array_t<double>(static_cast<py::ssize_t>(c.amplitudes.size()), c.amplitudes.data());
  d["unbounded"] = bool_array(c.unbounded);
  if (!c.phases_deg.empty())
    d["phase_deg"] = py::array_t<double>(static_cast<py::ssize_t>(c.phases_deg.size()), c.phases_deg.data());
  return d;
}

// The speeds to sweep: as given, or (as railmodal critical-speed sweeps) with the source's
// critical speeds between the lowest and the highest put in their places, so that an undamped
// resonance is a point of the curve, flagged unbounded, and not a finite peak between two
// speeds whose height depends on the grid (user audit 2026-11-28b, F7). Speeds the sweep would
// refuse (not positive and finite) are left for amplitude_curves to refuse in its own words.
std::vector<double> sweep_speeds(const LinearSystem& system, const ModalResult& modes, const ExcitationSource& source,
                                 std::vector<double> given, double friction_reference_amplitude,
                                 bool with_critical_speeds) {
  if (!with_critical_speeds || given.empty()) return given;
  CriticalSpeedOptions options;
  options.min_speed = *std::min_element(given.begin(), given.end());
  options.max_speed = *std::max_element(given.begin(), given.end());
  options.friction_reference_amplitude = friction_reference_amplitude;
  std::string why;
  if (!options.is_valid(&why)) return given;
  return grid_with_critical_speeds(given, find_critical_speeds(system, modes, {&source}, options));
}

std::vector<std::shared_ptr<ExcitationSource>> scene_sources(const Scene& s) {
  std::vector<std::shared_ptr<ExcitationSource>> out;
  for (const auto& source : s.sources) out.push_back(std::const_pointer_cast<ExcitationSource>(source));
  return out;
}

void bind_sources_and_scenes(py::module_& m) {
  py::class_<ExcitationSource, std::shared_ptr<ExcitationSource>>(m, "ExcitationSource",
                                                                  "A periodic excitation: rail joints, wheel defects, ...")
      .def_property_readonly("kind", &ExcitationSource::kind)
      .def_property_readonly("description", &ExcitationSource::description)
      .def_property_readonly("wavelength_m", &ExcitationSource::wavelength)
      .def_property_readonly("harmonic_count", &ExcitationSource::harmonic_count)
      .def("frequency_hz", &ExcitationSource::frequency_hz, py::arg("speed_m_s"), py::arg("harmonic") = 1)
      .def("speed_for", &ExcitationSource::speed_for, py::arg("frequency_hz"), py::arg("harmonic") = 1,
           "the speed (m/s) at which the harmonic runs at this frequency")
      .def("__repr__", [](const ExcitationSource& s) { return "ExcitationSource(" + s.description() + ")"; });

  m.def(
      "rail_joints",
      [](py::kwargs options) {
        OptionReader reader(options, "rail_joints()");
        RailJoints j;
        reader.read("rail_length", &j.rail_length);
        reader.read("staggered", &j.staggered);
        reader.read("dip_depth", &j.dip_depth);
        reader.read_enum("shape", &j.shape, dip_shape_from_string, "cosine, triangular, parabolic");
        reader.read("dip_length", &j.dip_length);
        reader.read("harmonics", &j.harmonics);
        reader.read("track_stiffness", &j.track_stiffness);
        reader.read("half_wheelset_mass", &j.half_wheelset_mass);
        reader.read("first_joint_at", &j.first_joint_at);
        reader.finish();
        return std::shared_ptr<ExcitationSource>(make_source(j));
      },
      "Rail joints as a source; keywords as the fields of RailJoints (SI: m, N/m, kg).");
  m.def(
      "wheel_eccentricity",
      [](py::kwargs options) {
        OptionReader reader(options, "wheel_eccentricity()");
        WheelEccentricity w;
        reader.read("wheel_diameter", &w.wheel_diameter);
        reader.read("eccentricity", &w.eccentricity);
        reader.read("phases", &w.phases);
        reader.read("lobes", &w.lobes);
        reader.finish();
        return std::shared_ptr<ExcitationSource>(make_source(w));
      },
      "Eccentric (lobes=1) or out-of-round wheels as a source; keywords as the fields of WheelEccentricity (SI: m, "
      "rad).");
  m.def(
      "wheel_flat",
      [](py::kwargs options) {
        OptionReader reader(options, "wheel_flat()");
        WheelFlat f;
        reader.read("wheel_diameter", &f.wheel_diameter);
        reader.read("depth", &f.depth);
        reader.read("length", &f.length);
        reader.read_enum("shape", &f.shape, dip_shape_from_string, "cosine, triangular, parabolic");
        reader.read("harmonics", &f.harmonics);
        reader.read("flat_angle", &f.flat_angle);
        reader.finish();
        return std::shared_ptr<ExcitationSource>(make_source(f));
      },
      "A wheel flat as a source; keywords as the fields of WheelFlat (SI: m, rad).");

  py::class_<Scene>(m, "Scene", "A vehicle on a track at a range of speeds, with its sources and outputs.")
      .def_readonly("name", &Scene::name)
      .def_readonly("source", &Scene::source, "the scene file")
      .def_readonly("vehicle_file", &Scene::vehicle_file)
      .def_property_readonly("dofs", [](const Scene& s) { return std::string(to_string(s.dofs)); })
      .def_readonly("min_speed_m_s", &Scene::min_speed)
      .def_readonly("max_speed_m_s", &Scene::max_speed)
      .def_readonly("speed_step_m_s", &Scene::speed_step)
      .def_property_readonly("sources", &scene_sources)
      .def_property_readonly("outputs",
                             [](const Scene& s) {
                               std::vector<std::pair<std::string, std::string>> out;
                               for (const SceneOutput& o : s.outputs) out.emplace_back(o.dof, to_string(o.quantity));
                               return out;
                             },
                             "(DOF label, quantity) pairs")
      .def_readonly("friction_reference_amplitude", &Scene::friction_reference_amplitude)
      .def("__repr__", [](const Scene& s) { return "Scene('" + s.name + "')"; });
  m.def("load_scene", &load_scene, py::arg("path"), py::call_guard<py::gil_scoped_release>(),
        "Reads a scene file. InputError names file, line, column and key.");
}

void bind_frequency_response(py::module_& m) {
  py::class_<FrequencyResponse>(m, "FrequencyResponse",
                                "The steady response at each frequency: values (n_frequencies, n_outputs) complex "
                                "and unbounded (the same shape, bool), values 0 where unbounded.")
      .def_property_readonly("frequencies_hz",
                             [](py::object self) { return vector_view(self.cast<const FrequencyResponse&>().frequencies_hz, self); })
      .def_readonly("outputs", &FrequencyResponse::outputs)
      .def_readonly("quantity", &FrequencyResponse::quantity)
      .def_property_readonly("values",
                             [](py::object self) {
                               const auto& r = self.cast<const FrequencyResponse&>();
                               const auto s = static_cast<py::ssize_t>(sizeof(std::complex<double>));
                               const auto cols = static_cast<py::ssize_t>(r.outputs.size());
                               return read_only(py::array_t<std::complex<double>>(
                                   {static_cast<py::ssize_t>(r.frequencies_hz.size()), cols}, {s * cols, s},
                                   r.values.data(), self));
                             })
      .def_property_readonly("unbounded",
                             [](const FrequencyResponse& r) {
                               return bool_array(r.unbounded).reshape(
                                   {static_cast<py::ssize_t>(r.frequencies_hz.size()), static_cast<py::ssize_t>(r.outputs.size())});
                             })
      .def("as_dict",
           [](const FrequencyResponse& r) {
             py::dict d;
             const std::size_t n = r.outputs.size();
             d["frequency_hz"] = py::array_t<double>(static_cast<py::ssize_t>(r.frequencies_hz.size()), r.frequencies_hz.data());
             for (std::size_t o = 0; o < n; ++o) {
               std::vector<double> amplitude, phase;
               std::vector<bool> unbounded;
               for (std::size_t f = 0; f < r.frequencies_hz.size(); ++f) {
                 const std::complex<double> v = r.values[f * n + o];
                 amplitude.push_back(std::abs(v));
                 phase.push_back(std::arg(v) * 180.0 / kPi);
                 unbounded.push_back(r.unbounded[f * n + o]);
               }
               d[py::str(r.outputs[o] + " amplitude")] = take(std::move(amplitude));
               d[py::str(r.outputs[o] + " phase_deg")] = take(std::move(phase));
               d[py::str(r.outputs[o] + " unbounded")] = bool_array(unbounded);
             }
             return d;
           },
           "frequency_hz (Hz) and, per output, '<label> amplitude' (the FRF's unit: m/N for a receptance, "
           "(m/s)/N, (m/s²)/N; rad for a rotation), '<label> phase_deg' (degrees), '<label> unbounded'")
      .def("__repr__", [](const FrequencyResponse& r) {
        return "FrequencyResponse(" + std::to_string(r.frequencies_hz.size()) + " frequencies, " +
               std::to_string(r.outputs.size()) + " outputs, " + r.quantity + ")";
      });

  m.def(
      "harmonic_response",
      [](const LinearSystem& system, const ModalResult& modes, const Eigen::VectorXcd& load,
         const DoubleArray& frequencies_hz, const std::string& method, int mode_count) {
        if (method != "direct" && method != "modal") throw py::value_error("method is '" + method + "'; expected direct or modal");
        return sweep(system, modes, load, to_vector(frequencies_hz, "frequencies_hz"), all_dofs(system), ResponseQuantity::displacement,
                     method == "modal", mode_count);
      },
      py::arg("system"), py::arg("modes"), py::arg("load"), py::arg("frequencies_hz"), py::arg("method") = "direct",
      py::arg("mode_count") = 0,
      "Steady displacement of every DOF under the complex load Q at each frequency: (K − ω²M + iωC) X = Q "
      "(method 'direct'), or modal superposition over mode_count modes ('modal').");

  m.def(
      "frf",
      [](const LinearSystem& system, const ModalResult& modes, py::handle input, const DoubleArray& frequencies_hz,
         py::object outputs, const std::string& quantity, const std::string& method, int mode_count) {
        if (method != "direct" && method != "modal") throw py::value_error("method is '" + method + "'; expected direct or modal");
        Eigen::VectorXcd load = Eigen::VectorXcd::Zero(system.size());
        load[dof_index(system, input)] = 1.0;
        std::vector<int> dofs;
        if (outputs.is_none()) {
          dofs = all_dofs(system);
        } else {
          for (py::handle o : outputs) dofs.push_back(dof_index(system, o));
        }
        return sweep(system, modes, load, to_vector(frequencies_hz, "frequencies_hz"), dofs, quantity_of(quantity),
                     method == "modal", mode_count);
      },
      py::arg("system"), py::arg("modes"), py::arg("input"), py::arg("frequencies_hz"), py::arg("outputs") = py::none(),
      py::arg("quantity") = "displacement", py::arg("method") = "direct", py::arg("mode_count") = 0,
      "Frequency response functions from a unit force (moment) at `input` to `outputs` (all DOFs when None): "
      "receptance, mobility (quantity='velocity') or accelerance ('acceleration').");
}

void bind_critical_speeds(py::module_& m) {
  py::class_<CriticalSpeedList>(m, "CriticalSpeeds", "Critical speeds sorted by speed; records() for pandas.")
      .def("records",
           [](const CriticalSpeedList& l) {
             py::list out;
             for (const CriticalSpeed& c : l.rows) out.append(critical_speed_record(c));
             return out;
           },
           "One dict per critical speed: speed_m_s (m/s), speed_kmh (km/h), source_index (the scene's source, "
           "from 1), source_kind, harmonic, mode, "
           "mode_name, frequency_hz (Hz), output, unbounded, amplitude (the output's: m or rad), "
           "growth_per_half_period and friction_decrement_per_half_period (m or rad per half period), "
           "friction_stops, friction_threshold_scale (a factor on the source amplitude)")
      .def("output_records",
           [](const CriticalSpeedList& l) {
             py::list out;
             for (std::size_t i = 0; i < l.rows.size(); ++i)
               for (const ResonanceAtOutput& o : l.rows[i].outputs) {
                 py::dict r;
                 r["critical_speed"] = i;
                 r["speed_m_s"] = l.rows[i].speed;
                 r["output"] = o.output;
                 r["quantity"] = to_string(o.quantity);
                 r["unbounded"] = o.unbounded;
                 r["amplitude"] = o.amplitude;
                 r["growth_per_half_period"] = o.growth_per_half_period;
                 out.append(r);
               }
             return out;
           },
           "One dict per critical speed and requested output (CriticalSpeed::outputs): critical_speed (its index), "
           "speed_m_s (m/s), output, quantity, unbounded, amplitude and growth_per_half_period (the quantity's unit: "
           "m, m/s or m/s²; rad, rad/s or rad/s² for a rotation)")
      .def_property_readonly("speeds_m_s",
                             [](const CriticalSpeedList& l) {
                               std::vector<double> v;
                               for (const CriticalSpeed& c : l.rows) v.push_back(c.speed);
                               return take(std::move(v));
                             })
      .def_readonly("summary", &CriticalSpeedList::summary)
      .def("__len__", [](const CriticalSpeedList& l) { return l.rows.size(); })
      .def("__repr__", [](const CriticalSpeedList& l) { return "CriticalSpeeds(" + std::to_string(l.rows.size()) + ")"; });

  py::class_<AmplitudeCurve>(m, "AmplitudeCurve",
                             "Amplitude of one output against speed; speeds_m_s, amplitudes and phases_deg are "
                             "read-only views (no copy).")
      .def_property_readonly("source_index", [](const AmplitudeCurve& c) { return c.source + 1; },
                             "the source's number from 1, as the JSON's curves write it")
      .def_readonly("output", &AmplitudeCurve::output)
      .def_property_readonly("quantity", [](const AmplitudeCurve& c) { return std::string(to_string(c.quantity)); })
      .def_property_readonly("speeds_m_s",
                             [](py::object self) { return vector_view(self.cast<const AmplitudeCurve&>().speeds.values(), self); })
      .def_property_readonly("amplitudes",
                             [](py::object self) { return vector_view(self.cast<const AmplitudeCurve&>().amplitudes, self); })
      .def_property_readonly("phases_deg",
                             [](py::object self) { return vector_view(self.cast<const AmplitudeCurve&>().phases_deg, self); })
      .def_property_readonly("unbounded", [](const AmplitudeCurve& c) { return bool_array(c.unbounded); })
      .def("as_dict", &curve_dict,
           "speed_m_s (m/s), amplitude (the quantity's unit: m, m/s or m/s²; rad... for a rotation), unbounded "
           "(and phase_deg, degrees): pandas.DataFrame(c.as_dict())")
      .def("__repr__", [](const AmplitudeCurve& c) {
        return "AmplitudeCurve('" + c.output + "', " + to_string(c.quantity) + ", " + std::to_string(c.speeds.size()) + " speeds)";
      });

  m.def(
      "find_critical_speeds",
      [](const LinearSystem& system, const ModalResult& modes, py::object sources, double min_speed, double max_speed,
         double friction_reference_amplitude, py::object outputs) {
        std::vector<std::shared_ptr<ExcitationSource>> held;
        if (py::isinstance<ExcitationSource>(sources))
          held.push_back(sources.cast<std::shared_ptr<ExcitationSource>>());
        else
          held = sources.cast<std::vector<std::shared_ptr<ExcitationSource>>>();
        CriticalSpeedOptions options;
        options.min_speed = min_speed;
        options.max_speed = max_speed;
        options.friction_reference_amplitude = friction_reference_amplitude;
        if (!outputs.is_none()) options.outputs = output_requests(system, outputs);
        std::vector<const ExcitationSource*> pointers;
        for (const auto& s : held) pointers.push_back(s.get());
        CriticalSpeedList out;
        py::gil_scoped_release release;
        out.rows = find_critical_speeds(system, modes, pointers, options, &out.summary);
        return out;
      },
      py::arg("system"), py::arg("modes"), py::arg("sources"), py::arg("min_speed"), py::arg("max_speed"),
      py::arg("friction_reference_amplitude") = 0.0, py::arg("outputs") = py::none(),
      "Every resonance of the sources' harmonics with the modes between min_speed and max_speed (m/s).");

  m.def(
      "amplitude_curves",
      [](const LinearSystem& system, const ModalResult& modes, std::shared_ptr<ExcitationSource> source,
         const py::iterable& outputs, const DoubleArray& speeds, int source_index, double friction_reference_amplitude,
         bool with_critical_speeds) {
        if (source_index < 1) throw py::value_error("source_index counts from 1, not " + std::to_string(source_index));
        const std::vector<OutputRequest> requests = output_requests(system, outputs);
        std::vector<double> given = to_vector(speeds, "speeds");
        py::gil_scoped_release release;
        const SpeedGrid grid(sweep_speeds(system, modes, *source, std::move(given), friction_reference_amplitude,
                                          with_critical_speeds));
        return amplitude_curves(system, modes, *source, source_index - 1, requests, grid,
                                friction_reference_amplitude);
      },
      py::arg("system"), py::arg("modes"), py::arg("source"), py::arg("outputs"), py::arg("speeds"),
      py::arg("source_index") = 1, py::arg("friction_reference_amplitude") = 0.0, py::kw_only(),
      py::arg("with_critical_speeds") = true,
      "One AmplitudeCurve per output (a label, an index or a (label, quantity) pair) against speed, computed in "
      "C++ in one call; source_index (from 1) is the number the curves give their source. The speeds (m/s, a "
      "numpy array) are swept as railmodal critical-speed sweeps its grid: sorted, with every critical speed of "
      "the source between the lowest and the highest put in its place, so that an undamped resonance is a point "
      "of the curve flagged in `unbounded` (amplitude 0 there); read the speeds from the curve's speeds_m_s, "
      "which may be longer than the array given. with_critical_speeds=False sweeps the speeds exactly as "
      "given: an undamped resonance between two of them then shows as a finite peak whose height depends on "
      "the grid, and is not flagged.");

  py::class_<CriticalSpeedStudy>(m, "CriticalSpeedStudy", "A scene's critical speeds, curves and peaks (railmodal critical-speed).")
      .def_readonly("scene", &CriticalSpeedStudy::scene)
      .def_readonly("system", &CriticalSpeedStudy::system)
      .def_readonly("modes", &CriticalSpeedStudy::modes)
      .def_property_readonly("critical_speeds",
                             [](const CriticalSpeedStudy& s) { return CriticalSpeedList{s.critical_speeds, {}}; })
      .def_readonly("curves", &CriticalSpeedStudy::curves)
      .def("peak_records",
           [](const CriticalSpeedStudy& s) {
             py::list out;
             for (const auto& p : s.peaks) {
               py::dict r;
               r["curve"] = p.curve;
               r["output"] = s.curves[static_cast<std::size_t>(p.curve)].output;
               r["speed_m_s"] = p.peak.speed;
               r["amplitude"] = p.peak.amplitude;
               r["evaluations"] = p.peak.evaluations;
               r["unbounded"] = p.peak.unbounded;
               out.append(r);
             }
             return out;
           })
      .def_readonly("summary", &CriticalSpeedStudy::summary);

  m.def(
      "study_critical_speeds",
      [](const Scene& scene, const Vehicle* vehicle) {  // a pointer: the vehicle is not copied
        if (vehicle) {
          py::gil_scoped_release release;
          return study_critical_speeds(scene, *vehicle);
        }
        std::vector<std::string> warnings;
        Vehicle own;
        {
          py::gil_scoped_release release;
          own = load_vehicle(scene.vehicle_file, &warnings);
        }
        warn_input(warnings);  // as load_vehicle's binding does: InputWarning, with the GIL held
        py::gil_scoped_release release;
        return study_critical_speeds(scene, own);
      },
      py::arg("scene"), py::arg("vehicle") = py::none(),
      "The critical-speed study of a scene (its own vehicle unless one is given), as `railmodal critical-speed`.");
}

}  // namespace

void bind_response(py::module_& m) {
  bind_sources_and_scenes(m);
  bind_frequency_response(m);
  bind_critical_speeds(m);
}

}  // namespace railmodal::python
