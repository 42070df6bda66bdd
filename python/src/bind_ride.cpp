// Ride on random track: track spectra, the frequency-domain ride (PSDs, RMS, EN 12299 indices,
// Sperling's Wz, N_MV), realisations of the track and the time-domain ride with its FFT checks,
// and the comfort weightings (docs/python.md, "Ride").
#include <pybind11/complex.h>
#include <pybind11/eigen.h>

#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "analysis_values.hpp"
#include "bindings.hpp"
#include "railmodal/comfort_weighting.hpp"
#include "railmodal/ride.hpp"
#include "railmodal/ride_simulation.hpp"
#include "railmodal/scene.hpp"
#include "railmodal/track_spectrum.hpp"

namespace railmodal::python {
namespace {

constexpr double kMissing = std::numeric_limits<double>::quiet_NaN();  // an absent value in an array

TrackIrregularity irregularity_argument(const std::string& word) {
  return enum_argument(word, track_irregularity_from_string, "irregularity",
                       "'vertical_level', 'alignment', 'cross_level'");
}

void bind_track_spectrum(py::module_& m) {
  py::class_<TrackSpectrum>(m, "TrackSpectrum",
                            "A one-sided spatial PSD of one track irregularity, m²/(rad/m), zero outside its band")
      .def_static(
          "ore_b176",
          [](const std::string& level, const std::string& irregularity, std::pair<double, double> band) {
            return TrackSpectrum::ore_b176(enum_argument(level, ore_level_from_string, "level", "'low', 'high'"),
                                           irregularity_argument(irregularity), {band.first, band.second});
          },
          py::arg("level"), py::arg("irregularity"), py::arg("band_rad_m"),
          "ORE B176 low or high level over band_rad_m = (low, high) wavenumbers, rad/m")
      .def_static(
          "fra_class",
          [](int track_class, const std::string& irregularity, std::optional<std::pair<double, double>> band) {
            return band ? TrackSpectrum::fra_class(track_class, irregularity_argument(irregularity),
                                                   {band->first, band->second})
                        : TrackSpectrum::fra_class(track_class, irregularity_argument(irregularity));
          },
          py::arg("track_class"), py::arg("irregularity"), py::arg("band_rad_m") = py::none(),
          "FRA track class 1 … 6; the band defaults to wavelengths 1.524 … 304.8 m")
      .def_static(
          "table",
          [](const std::string& irregularity, const std::string& abscissa, const std::vector<double>& abscissae,
             const std::vector<double>& densities) {
            return TrackSpectrum::table(irregularity_argument(irregularity),
                                        enum_argument(abscissa, spectrum_abscissa_from_string, "abscissa",
                                                      "'wavenumber', 'spatial_frequency', 'wavelength'"),
                                        abscissae, densities);
          },
          py::arg("irregularity"), py::arg("abscissa"), py::arg("abscissae"), py::arg("densities"),
          "A user table (SI), log-log interpolated, zero outside its range")
      .def_property_readonly("irregularity", [](const TrackSpectrum& s) { return std::string(to_string(s.irregularity())); })
      .def_property_readonly("name", &TrackSpectrum::name)
      .def_property_readonly("band_rad_m", [](const TrackSpectrum& s) { return std::make_pair(s.band().low, s.band().high); })
      .def("density",
           [](const TrackSpectrum& s, const py::array_t<double>& wavenumber) {
             return elementwise(wavenumber, [&s](double w) { return s.density(w); });
           },
           py::arg("wavenumber_rad_m"), "S(Ω), m²/(rad/m), over an array of wavenumbers")
      .def("density_per_cycle",
           [](const TrackSpectrum& s, const py::array_t<double>& n) {
             return elementwise(n, [&s](double x) { return s.density_per_cycle(x); });
           },
           py::arg("spatial_frequency_cycle_m"), "S_n(n) = 2π S(2πn), m²/(cycle/m)")
      .def("temporal_density",
           [](const TrackSpectrum& s, const py::array_t<double>& frequency, double speed) {
             return elementwise(frequency, [&](double f) { return s.temporal_density(f, speed); });
           },
           py::arg("frequency_hz"), py::arg("speed_m_s"), "G(f) = (2π/V) S(2πf/V), m²/Hz")
      .def(
          "variance",
          [](const TrackSpectrum& s, std::optional<std::pair<double, double>> band) {
            return band ? s.variance({band->first, band->second}) : s.variance();
          },
          py::arg("band_rad_m") = py::none(), "σ², m², over the band (default: the spectrum's own)")
      .def(
          "rms",
          [](const TrackSpectrum& s, std::optional<std::pair<double, double>> band) {
            return band ? s.rms({band->first, band->second}) : s.rms();
          },
          py::arg("band_rad_m") = py::none(), "σ, m")
      .def("__repr__", [](const TrackSpectrum& s) { return "<railmodal.TrackSpectrum '" + s.name() + "'>"; });
}

// A track: a dict of TrackSpectrum by component ("vertical_level", "alignment", "cross_level"),
// or a Scene (its irregularity source).
const TrackIrregularitySpectra& scene_track(const Scene& scene) {
  if (!scene.irregularity)
    throw InputError(scene.source, 0, 0,
                     "the scene has no [[source]] with kind = \"irregularity\": the ride is the response to random "
                     "track (docs/scenes.md, \"Ride scenes\")");
  return *scene.irregularity;
}

TrackIrregularitySpectra track_argument(const py::handle& track) {
  if (!py::isinstance<py::dict>(track))
    return scene_track(typed_argument<Scene>(track, "a dict of TrackSpectrum by component or a Scene"));
  TrackIrregularitySpectra out;
  for (const auto& item : track.cast<py::dict>()) {
    const std::string key = py::str(item.first);
    std::optional<TrackSpectrum>* slot = key == "vertical_level" ? &out.vertical_level
                                         : key == "alignment"    ? &out.alignment
                                         : key == "cross_level"  ? &out.cross_level
                                                                 : nullptr;
    if (!slot)
      throw py::value_error("track: '" + key + "' is not one of 'vertical_level', 'alignment', 'cross_level'");
    if (!item.second.is_none()) *slot = typed_argument<TrackSpectrum>(item.second, "a TrackSpectrum");
  }
  return out;
}

void bind_ride_output(py::module_& m) {
  py::class_<RideOutput>(m, "RideOutput", "One quantity the ride reports (a point's motion, an element's deflection or force, a wheel–rail force)")
      .def(py::init([](const std::string& name, const std::string& kind, const std::string& body,
                       const Eigen::Vector3d& point, const std::string& element, const std::string& axis,
                       const std::string& quantity, const std::string& frame) {
             RideOutput o;
             o.name = name;
             o.kind = enum_argument(kind, ride_output_kind_from_string, "kind",
                                    "'point', 'element_deflection', 'element_force', 'wheel_rail_force'");
             o.body = body;
             o.point = point;
             o.element = element;
             o.axis = enum_argument(axis, ride_axis_from_string, "axis", "'longitudinal', 'lateral', 'vertical'");
             o.quantity = enum_argument(quantity, response_quantity_from_string, "quantity",
                                        "'displacement', 'velocity', 'acceleration'");
             o.frame = enum_argument(frame, ride_frame_from_string, "frame", "'body', 'track'");
             return o;
           }),
           py::arg("name"), py::kw_only(), py::arg("kind") = "point", py::arg("body") = "",
           py::arg("point_m") = Eigen::Vector3d::Zero().eval(), py::arg("element") = "", py::arg("axis") = "vertical",
           py::arg("quantity") = "acceleration", py::arg("frame") = "body")
      .def_readonly("name", &RideOutput::name)
      .def_property_readonly("kind", [](const RideOutput& o) { return std::string(to_string(o.kind)); })
      .def_readonly("body", &RideOutput::body)
      .def_readonly("point_m", &RideOutput::point)
      .def_readonly("element", &RideOutput::element)
      .def_property_readonly("axis", [](const RideOutput& o) { return std::string(to_string(o.axis)); })
      .def_property_readonly("quantity", [](const RideOutput& o) { return std::string(to_string(o.quantity)); })
      .def_property_readonly("unit", [](const RideOutput& o) { return unit_of(o); })
      .def_property_readonly("frame", [](const RideOutput& o) { return std::string(to_string(o.frame)); },
                             "'body': a point acceleration as an accelerometer fixed to the floor reads it "
                             "(lateral ÿ + g·φ, longitudinal ẍ − g·θ); 'track': inertial")
      .def("__repr__", [](const RideOutput& o) { return "<railmodal.RideOutput '" + o.name + "'>"; });

  m.def("default_ride_outputs", &default_ride_outputs, py::arg("system"),
        "The floor points a ride looks at when none are named (body over each bogie, mid-car, 1 m from each end), "
        "at the body's floor_height (None: at its reference point, which the ride's notes then say)");
}

// One row per speed and output, under the keys of the ride JSON's outputs (the weighted RMS and
// the P95 estimate with their unit, m/s²); an index an RMS-only result skipped
// (RideResult::rms_only) is None.
py::list ride_records(const RideResult& r) {
  py::list out;
  const bool every_index = !r.rms_only;
  const auto computed = [every_index](double v) { return every_index ? py::object(py::float_(v)) : py::none(); };
  for (const RideAtSpeed& at : r.speeds)
    for (size_t i = 0; i < r.outputs.size(); ++i) {
      const RideOutputAtSpeed& o = at.outputs[i];
      out.append(py::dict(py::arg("speed_m_s") = at.speed, py::arg("output") = r.outputs[i].name,
                          py::arg("unit") = unit_of(r.outputs[i]), py::arg("unbounded") = o.unbounded,
                          py::arg("rms") = o.unbounded ? py::none() : py::object(py::float_(o.rms)),
                          py::arg("weighted_rms_m_s2") = optional_value(o.weighted_rms),
                          py::arg("sperling_wz") = optional_value(o.sperling_wz),
                          py::arg("p95_estimate_m_s2") = optional_value(o.p95_estimate),
                          py::arg("cross_term_variance") = computed(o.cross_term_variance),
                          py::arg("direct_variance") = computed(o.direct_variance)));
    }
  return out;
}

std::string axes_text(const std::vector<RideAxis>& axes) {
  std::string out;
  for (RideAxis a : axes) out += (out.empty() ? "" : ", ") + std::string(to_string(a));
  return out;
}

py::list comfort_records(double speed, const std::vector<RideComfortAtPoint>& comfort, const char* value_key) {
  py::list out;
  for (const RideComfortAtPoint& c : comfort)
    out.append(py::dict(py::arg("speed_m_s") = speed, py::arg("body") = c.body, py::arg("x_m") = c.point.x(),
                        py::arg("y_m") = c.point.y(), py::arg("z_m") = c.point.z(),
                        py::arg(value_key) = c.nmv_estimate, py::arg("missing_axes") = axes_text(c.missing_axes)));
  return out;
}

// speeds × outputs × frequencies of the output PSDs (NaN where an output is unbounded or the
// spectra were not kept), or speeds × inputs × frequencies of the input PSDs: a new array.
template <class Spectra>
py::array psd_cube(const RideResult& r, size_t count, const Spectra& spectra) {
  const size_t speeds = r.speeds.size(), bins = static_cast<size_t>(r.frequencies.size());
  py::array_t<double> cube({speeds, count, bins});
  auto out = cube.mutable_unchecked<3>();
  for (size_t s = 0; s < speeds; ++s)
    for (size_t i = 0; i < count; ++i) {
      const Eigen::VectorXd* psd = spectra(r.speeds[s], i);
      const bool kept = psd && static_cast<size_t>(psd->size()) == bins;
      for (size_t k = 0; k < bins; ++k)
        out(s, i, k) = kept ? (*psd)(static_cast<Eigen::Index>(k)) : kMissing;
    }
  return cube;
}

void bind_ride_result(py::module_& m) {
  py::class_<RideResult>(m, "RideResult", "The ride on random track at each speed: PSDs, RMS and comfort indices")
      .def_readonly("outputs", &RideResult::outputs)
      .def_property_readonly("output_names",
                             [](const RideResult& r) {
                               std::vector<std::string> names;
                               for (const RideOutput& o : r.outputs) names.push_back(o.name);
                               return names;
                             })
      .def_property_readonly(
          "frequencies_hz", [](const RideResult& r) -> const Eigen::VectorXd& { return r.frequencies; }, kView,
          "the frequency grid (a view)")
      .def_property_readonly("speeds_m_s",
                             [](const RideResult& r) { return column(r.speeds.size(), [&](size_t i) { return r.speeds[i].speed; }); })
      .def_property_readonly(
          "psd",
          [](const RideResult& r) {
            return psd_cube(r, r.outputs.size(), [](const RideAtSpeed& at, size_t i) -> const Eigen::VectorXd* {
              return at.outputs[i].unbounded ? nullptr : &at.outputs[i].psd;
            });
          },
          "output PSDs, unit²/Hz, speeds × outputs × frequencies (a new array; NaN where unbounded)")
      .def_readonly("inputs", &RideResult::inputs, "the track spectra's names, the input_psd order")
      .def_property_readonly(
          "input_rms", [](py::object self) { return vector_view(self.cast<const RideResult&>().input_rms, self); },
          "the RMS of each track component over its own band, m, in `inputs` order (a view)")
      .def_property_readonly(
          "input_psd",
          [](const RideResult& r) {
            const size_t inputs = r.speeds.empty() ? 0 : r.speeds.front().input_psd.size();
            return psd_cube(r, inputs, [](const RideAtSpeed& at, size_t i) { return &at.input_psd[i]; });
          },
          "input PSDs G(f), m²/Hz, speeds × inputs × frequencies")
      .def_property_readonly("modes",
                             [](const RideResult& r) {
                               py::list out;
                               for (const RideMode& mode : r.modes)
                                 out.append(py::dict(py::arg("name") = mode.name, py::arg("frequency_hz") = mode.frequency_hz));
                               return out;
                             },
                             "records of the undamped modes: name, frequency_hz")
      .def("records", &ride_records,
           "One row per speed and output: speed_m_s (m/s), output, unit (the output's: m, m/s, m/s² or N), "
           "unbounded, rms (unit), weighted_rms_m_s2 (m/s², EN 12299), sperling_wz (dimensionless), "
           "p95_estimate_m_s2 (m/s²), cross_term_variance and direct_variance (unit², the direct track term alone); "
           "with rms_only, sperling_wz, p95_estimate_m_s2 and the variances are None")
      .def(
          "comfort",
          [](const RideResult& r) {
            py::list out;
            for (const RideAtSpeed& at : r.speeds) out.attr("extend")(comfort_records(at.speed, at.comfort, "nmv_estimate"));
            return out;
          },
          "One row per speed and floor point: speed_m_s (m/s), body, x_m, y_m, z_m (m, vehicle frame), "
          "nmv_estimate (EN 12299 N_MV, dimensionless), missing_axes")
      .def(
          "contributions",
          [](const RideResult& r) {
            py::list out;
            for (const RideAtSpeed& at : r.speeds)
              for (size_t i = 0; i < r.outputs.size(); ++i)
                for (const ModalContribution& c : at.outputs[i].modes)
                  out.append(py::dict(py::arg("speed_m_s") = at.speed, py::arg("output") = r.outputs[i].name,
                                      py::arg("mode") = c.mode, py::arg("mode_name") = r.modes[static_cast<size_t>(c.mode)].name,
                                      py::arg("variance") = c.variance, py::arg("share") = c.share));
            return out;
          },
          "One row per speed, output and mode: speed_m_s (m/s), output, mode, mode_name, variance (the output's "
          "unit²) and share (a fraction of the output's variance; largest first)")
      .def_readonly("rms_only", &RideResult::rms_only,
                             "True when solved with rms_only=True: records() has the RMS and weighted RMS only")
      .def_readonly("friction_treatment", &RideResult::friction_treatment)
      .def_property_readonly(
          "grid_error_estimate",
          [](const RideResult& r) {
            return has_grid_error_estimate(r) ? py::object(py::float_(r.grid_error_estimate)) : py::none();
          },
          "the largest relative RMS change on halving the grid; None with rms_only or when no output has a "
          "bounded RMS")
      .def_readonly("notes", &RideResult::notes)
      .def_readonly("summary", &RideResult::summary);
}

RideOptions ride_options(std::vector<double> speeds, double min_frequency, double max_frequency, int points_per_decade,
                         int points_per_bandwidth, int modes, double contact_half_spacing, double percentile_window,
                         double friction_tolerance, int friction_iterations, int threads, bool keep_spectra,
                         double rolling_radius, bool rms_only) {
  RideOptions o;
  o.speeds = std::move(speeds);
  o.min_frequency = min_frequency;
  o.max_frequency = max_frequency;
  o.points_per_decade = points_per_decade;
  o.points_per_bandwidth = points_per_bandwidth;
  o.modes = modes;
  o.contact_half_spacing = contact_half_spacing;
  o.percentile_window = percentile_window;
  o.friction_tolerance = friction_tolerance;
  o.friction_iterations = friction_iterations;
  o.threads = threads;
  o.keep_spectra = keep_spectra;
  o.rolling_radius = rolling_radius;
  o.rms_only = rms_only;
  return o;
}

// The scene's system and outputs, as `railmodal ride` assembles them.
struct SceneRide {
  LinearSystem system;
  std::vector<RideOutput> outputs;
};
SceneRide scene_ride(const Scene& scene, const py::object& vehicle) {
  scene_track(scene);  // a ride scene, or its error
  Vehicle v;
  if (!vehicle.is_none()) {
    v = vehicle_argument(vehicle);
  } else if (scene.vehicle_file.empty()) {
    throw py::value_error("no vehicle: give vehicle=... or a 'vehicle' key in " + scene.source);
  } else {
    v = vehicle_argument(py::str(scene.vehicle_file));
  }
  py::gil_scoped_release release;
  SceneRide out{assemble(v, scene.dofs), {}};
  check_scene_fits(scene, out.system);
  out.outputs = scene.ride && !scene.ride->outputs.empty() ? scene.ride->outputs : default_ride_outputs(out.system);
  return out;
}

void bind_ride_functions(py::module_& m) {
  const RideOptions d;
  m.def(
      "ride",
      [](const LinearSystem& system, const py::object& track, const std::optional<std::vector<RideOutput>>& outputs,
         const std::vector<double>& speeds, double min_frequency, double max_frequency, int points_per_decade,
         int points_per_bandwidth, int modes, double contact_half_spacing, double percentile_window,
         double friction_tolerance, int friction_iterations, int threads, bool keep_spectra, double rolling_radius,
         bool rms_only) {
        const TrackIrregularitySpectra t = track_argument(track);
        const RideOptions o = ride_options(speeds, min_frequency, max_frequency, points_per_decade,
                                           points_per_bandwidth, modes, contact_half_spacing, percentile_window,
                                           friction_tolerance, friction_iterations, threads, keep_spectra,
                                           rolling_radius, rms_only);
        py::gil_scoped_release release;
        return solve_ride(system, t, outputs ? *outputs : default_ride_outputs(system), o);
      },
      py::arg("system"), py::arg("track"), py::arg("outputs") = py::none(), py::kw_only(), py::arg("speeds_m_s"),
      py::arg("min_frequency_hz") = d.min_frequency, py::arg("max_frequency_hz") = d.max_frequency,
      py::arg("points_per_decade") = d.points_per_decade, py::arg("points_per_bandwidth") = d.points_per_bandwidth,
      py::arg("modes") = d.modes, py::arg("contact_half_spacing_m") = d.contact_half_spacing,
      py::arg("percentile_window_s") = d.percentile_window, py::arg("friction_tolerance") = d.friction_tolerance,
      py::arg("friction_iterations") = d.friction_iterations, py::arg("threads") = d.threads,
      py::arg("keep_spectra") = d.keep_spectra, py::arg("rolling_radius_m") = d.rolling_radius,
      py::arg("rms_only") = d.rms_only,
      "The ride of `system` on `track` (a dict of TrackSpectrum by component, or a Scene) at every speed "
      "(solve_ride); outputs default to default_ride_outputs(system). rms_only=True: each output's RMS and "
      "weighted RMS only, bit for bit the same, at about 55 % of the CPU; Sperling's Wz, the P95 estimate, "
      "N_MV (comfort()), the modal shares (contributions()), the variances of records() and the grid error "
      "estimate are skipped (None or empty).");
  m.def(
      "ride_scene",
      [](const Scene& scene, const py::object& vehicle, const std::optional<std::vector<double>>& speeds, int threads,
         bool rms_only) {
        const SceneRide run = scene_ride(scene, vehicle);
        RideOptions options = scene.ride ? scene.ride->options : RideOptions{};
        if (speeds) options.speeds = *speeds;
        if (options.speeds.empty() && scene.ride && scene.ride->simulation) options.speeds = {scene.ride->simulation->speed};
        if (options.speeds.empty()) {
          // At the [ride] table (its speeds key) as `railmodal ride` places it, else at the
          // irregularity source of a scene without [ride].
          const std::string message = "no speeds: give them in [ride] (speeds = \"100 km/h:200 km/h:20 km/h\") or as speeds_m_s";
          const auto ride = scene.name_places.find("ride.speeds");
          if (ride != scene.name_places.end())
            throw InputError(scene.source, ride->second.line, ride->second.column, "key 'ride.speeds': " + message);
          const auto source = scene.name_places.find("irregularity");
          const KeyPlace at = source != scene.name_places.end() ? source->second : KeyPlace{};
          throw InputError(scene.source, at.line, at.column, message);
        }
        options.threads = threads;
        options.rms_only = rms_only;
        py::gil_scoped_release release;
        return as_input_error(scene.source, [&] { return solve_ride(run.system, *scene.irregularity, run.outputs, options); });
      },
      py::arg("scene"), py::arg("vehicle") = py::none(), py::kw_only(), py::arg("speeds_m_s") = py::none(),
      py::arg("threads") = 1, py::arg("rms_only") = false,
      "The ride of a scene ('railmodal ride' without the time domain): its vehicle in its DOF set, its track, its "
      "[ride] options and outputs; speeds_m_s in place of the scene's. rms_only=True is 'railmodal ride "
      "--rms-only': each output's RMS and weighted RMS only (Wz, P95, N_MV, modal shares, variances and grid "
      "error estimate skipped).");
}

void bind_geometry(py::module_& m) {
  py::class_<TrackGeometry>(m, "TrackGeometry", "Track geometry sampled every step_m from distance 0 (views)")
      .def_readonly("step_m", &TrackGeometry::step)
      .def_property_readonly(
          "vertical_level", [](const TrackGeometry& g) -> const Eigen::VectorXd& { return g.vertical_level; }, kView, "m")
      .def_property_readonly(
          "alignment", [](const TrackGeometry& g) -> const Eigen::VectorXd& { return g.alignment; }, kView, "m")
      .def_property_readonly(
          "cross_level", [](const TrackGeometry& g) -> const Eigen::VectorXd& { return g.cross_level; }, kView, "m")
      .def_property_readonly("distance_m",
                             [](const TrackGeometry& g) {
                               const Eigen::Index n = std::max({g.vertical_level.size(), g.alignment.size(), g.cross_level.size()});
                               return column(static_cast<size_t>(n), [&](size_t i) { return static_cast<double>(i) * g.step; });
                             },
                             "the samples' distances, m (a new array)")
      .def_readonly("periodic", &TrackGeometry::periodic)
      .def_readonly("source", &TrackGeometry::source)
      .def_property_readonly("length_m", &TrackGeometry::length);

  m.def(
      "synthesise_track",
      [](const py::object& track, double length, double step, std::uint64_t seed) {
        const TrackIrregularitySpectra t = track_argument(track);
        TrackSynthesisOptions o;
        o.length = length;
        o.step = step;
        o.seed = seed;
        py::gil_scoped_release release;
        return synthesise_track(t, o);
      },
      py::arg("track"), py::kw_only(), py::arg("length_m"), py::arg("step_m"), py::arg("seed") = TrackSynthesisOptions{}.seed,
      "A realisation of the track (a dict of TrackSpectrum or a Scene) by inverse real FFT; the same seed gives "
      "the same profile on every machine.");
  m.def(
      "load_track_geometry", path_reader([](const std::string& file) { return load_track_geometry(file); }),
      py::arg("path"), "Measured track geometry from a CSV file; InputError with file, line and column.");
}

py::dict history_dict(const RideHistory& h, py::handle owner) {
  return py::dict(py::arg("values") = vector_view(h.values, owner), py::arg("weighted") = vector_view(h.weighted, owner),
                  py::arg("window_rms") = vector_view(h.window_rms, owner),
                  py::arg("continuous_comfort") = vector_view(h.continuous_comfort, owner));
}

RideSimulationOptions simulation_options(double speed, double time_step, double settle_time, double window,
                                         double contact_half_spacing, double rolling_radius) {
  RideSimulationOptions o;
  o.speed = speed;
  o.time_step = time_step;
  o.settle_time = settle_time;
  o.window = window;
  o.contact_half_spacing = contact_half_spacing;
  o.rolling_radius = rolling_radius;
  return o;
}

// A scene's [ride.simulation]: on its synthesised realisation (then with the FFT checks) or its
// measured geometry, as 'railmodal ride' runs it.
std::pair<RideSimulationResult, std::optional<RideFftChecks>> scene_ride_simulation(const Scene& scene,
                                                                                   const py::object& vehicle) {
  if (!scene.ride || !scene.ride->simulation)
    throw InputError(scene.source, 0, 0, "the scene has no [ride.simulation] table");
  const SceneRide run = scene_ride(scene, vehicle);
  py::gil_scoped_release release;
  return as_input_error(scene.source, [&] {
    const RideSpec& spec = *scene.ride;
    const TrackGeometry geometry = spec.realisation ? synthesise_track(*scene.irregularity, *spec.realisation)
                                                    : load_track_geometry(spec.geometry_file);
    std::pair<RideSimulationResult, std::optional<RideFftChecks>> out;
    out.first = simulate_ride(run.system, geometry, run.outputs, *spec.simulation);
    if (spec.realisation)
      out.second = check_ride_realisation(run.system, *scene.irregularity, geometry, out.first, *spec.simulation);
    return out;
  });
}

void bind_ride_simulation(py::module_& m) {
  py::class_<RideFftChecks>(m, "RideFftChecks", "The FFT checks of a simulated realisation against the frequency-domain ride")
      .def_property_readonly("exact_bin_error", [](const RideFftChecks& c) { return optional_value(c.exact_bin_error); })
      .def_readonly("fraction_outside_band", &RideFftChecks::fraction_outside_band)
      .def_readonly("rms_difference", &RideFftChecks::rms_difference, "per output, relative")
      .def_readonly("summary", &RideFftChecks::summary);

  py::class_<RideSimulationResult>(m, "RideSimulationResult", "The time-domain ride over a track realisation or measured geometry")
      .def_readonly("outputs", &RideSimulationResult::outputs)
      .def_readonly("time_step_s", &RideSimulationResult::time_step)
      .def_property_readonly(
          "time_s", [](const RideSimulationResult& r) -> const Eigen::VectorXd& { return r.time; }, kView)
      .def(
          "history",
          [](py::object self, const std::string& output) {
            const RideSimulationResult& r = self.cast<const RideSimulationResult&>();
            for (size_t i = 0; i < r.outputs.size(); ++i)
              if (r.outputs[i].name == output) return history_dict(r.histories[i], self);
            throw py::key_error("no ride output '" + output + "'");
          },
          py::arg("output"),
          "One output's samples as views: values, weighted (EN 12299, m/s²), window_rms, continuous_comfort")
      .def(
          "records",
          [](const RideSimulationResult& r) {
            py::list out;
            for (size_t i = 0; i < r.outputs.size(); ++i) {
              const RideHistory& h = r.histories[i];
              out.append(py::dict(py::arg("output") = r.outputs[i].name, py::arg("unit") = unit_of(r.outputs[i]),
                                  py::arg("rms") = h.rms, py::arg("weighted_rms_m_s2") = optional_value(h.weighted_rms),
                                  py::arg("sperling_wz") = optional_value(h.sperling_wz),
                                  py::arg("p95_m_s2") = optional_value(h.p95)));
            }
            return out;
          },
          "One row per output, under the keys of the ride JSON's time_domain outputs: output, unit (the "
          "output's: m, m/s, m/s² or N), rms (unit), weighted_rms_m_s2 (m/s², EN 12299), sperling_wz "
          "(dimensionless), p95_m_s2 (m/s², of the 5 s windows)")
      .def("comfort", [](const RideSimulationResult& r) { return comfort_records(0.0, r.comfort, "nmv"); },
           "One row per floor point: body, x_m, y_m, z_m (m), nmv (EN 12299 N_MV, dimensionless), missing_axes "
           "(speed_m_s is 0: one run)")
      .def_readonly("window_s", &RideSimulationResult::window)
      .def_readonly("notes", &RideSimulationResult::notes)
      .def_readonly("summary", &RideSimulationResult::summary);

  const RideSimulationOptions d;
  m.def(
      "simulate_ride",
      [](const LinearSystem& system, const TrackGeometry& geometry, const std::vector<RideOutput>& outputs,
         double speed, double time_step, double settle_time, double window, double contact_half_spacing,
         double rolling_radius) {
        const RideSimulationOptions o =
            simulation_options(speed, time_step, settle_time, window, contact_half_spacing, rolling_radius);
        py::gil_scoped_release release;
        return simulate_ride(system, geometry, outputs, o);
      },
      py::arg("system"), py::arg("geometry"), py::arg("outputs"), py::kw_only(), py::arg("speed_m_s"),
      py::arg("time_step_s") = d.time_step, py::arg("settle_time_s") = d.settle_time, py::arg("window_s") = d.window,
      py::arg("contact_half_spacing_m") = d.contact_half_spacing, py::arg("rolling_radius_m") = d.rolling_radius,
      "The time-domain ride of `system` over `geometry` at one speed (simulate_ride).");
  m.def(
      "check_ride_realisation",
      [](const LinearSystem& system, const py::object& track, const TrackGeometry& geometry,
         const RideSimulationResult& simulated, double speed, double time_step, double settle_time, double window,
         double contact_half_spacing, double rolling_radius) {
        const TrackIrregularitySpectra t = track_argument(track);
        const RideSimulationOptions o =
            simulation_options(speed, time_step, settle_time, window, contact_half_spacing, rolling_radius);
        py::gil_scoped_release release;
        return check_ride_realisation(system, t, geometry, simulated, o);
      },
      py::arg("system"), py::arg("track"), py::arg("geometry"), py::arg("simulated"), py::kw_only(),
      py::arg("speed_m_s"), py::arg("time_step_s") = d.time_step, py::arg("settle_time_s") = d.settle_time,
      py::arg("window_s") = d.window, py::arg("contact_half_spacing_m") = d.contact_half_spacing,
      py::arg("rolling_radius_m") = d.rolling_radius,
      "The FFT checks of a simulated realisation (the options simulate_ride was given).");
  m.def("ride_scene_simulation", &scene_ride_simulation, py::arg("scene"), py::arg("vehicle") = py::none(),
        "The scene's time-domain ride ('railmodal ride' with [ride.simulation]): (RideSimulationResult, "
        "RideFftChecks or None; the checks run on a synthesised realisation only).");
}

void bind_comfort(py::module_& m) {
  const auto weighting = [](const std::string& name) {
    if (name == "wb") return en12299_wb();
    if (name == "wd") return en12299_wd();
    if (name == "bs6841_wb") return bs6841_wb();
    throw py::value_error("weighting: '" + name + "' is not one of 'wb', 'wd', 'bs6841_wb'");
  };
  m.def(
      "comfort_weighting",
      [weighting](const std::string& name, const py::array_t<double>& frequency) {
        const FrequencyWeighting w = weighting(name);
        return elementwise<std::complex<double>>(frequency, [&w](double f) { return w.response(f); });
      },
      py::arg("name"), py::arg("frequency_hz"),
      "W(j2πf) of EN 12299's Wb ('wb', vertical), Wd ('wd') or BS 6841's Wb ('bs6841_wb'), complex, over an array");
  m.def(
      "sperling_weighting",
      [](const py::array_t<double>& frequency, const std::string& direction) {
        const SperlingDirection d =
            enum_argument(direction, sperling_direction_from_string, "direction", "'vertical', 'lateral'");
        return elementwise(frequency, [d](double f) { return sperling_weighting(f, d); });
      },
      py::arg("frequency_hz"), py::arg("direction") = "vertical", "Sperling's B(f) over an array of frequencies");
  m.def("sperling_wz_from_weighted_rms", py::vectorize(&sperling_wz_from_weighted_rms), py::arg("weighted_rms"),
        "Wz = 4.4173·a_w^0.3 for the B-weighted RMS a_w, m/s²");
  m.def("en12299_nmv", py::vectorize(&en12299_nmv), py::arg("p95_longitudinal"), py::arg("p95_lateral"),
        py::arg("p95_vertical"), "N_MV = 6 √(a_XP95² + a_YP95² + a_ZP95²)");
}

}  // namespace

void bind_ride(py::module_& m) {
  bind_track_spectrum(m);
  bind_ride_output(m);
  bind_ride_result(m);
  bind_ride_functions(m);
  bind_geometry(m);
  bind_ride_simulation(m);
  bind_comfort(m);
}

}  // namespace railmodal::python
