// simulate_ride: the linear vehicle over a sampled track, exact for the linearly interpolated
// track (ride_march.hpp), and the EN 12299 and Sperling indices of its histories. Method and
// conventions: docs/ride.md, "Realisations" and "Ride indices in time".
#include <Eigen/Dense>
#include <cmath>
#include <array>
#include <cstdio>
#include <iomanip>
#include <map>
#include <optional>
#include <utility>
#include <sstream>
#include <stdexcept>
#include <tuple>

#include "railmodal/ride_simulation.hpp"
#include "require_valid.hpp"
#include "ride/default_ride_outputs.hpp"
#include "ride/window_indices.hpp"
#include "ride/ride_friction_march.hpp"
#include "ride/ride_march.hpp"
#include "ride/ride_modal_march.hpp"
#include "ride/ride_state_space.hpp"
#include "ride/ride_transfer.hpp"
#include "ride/time_weighting.hpp"
#include "ride/track_under_wheels.hpp"
#include "summary/stage_clock.hpp"

namespace railmodal {
namespace {

// EN 12299: a zone of five minutes holds 60 five-second windows.
constexpr Eigen::Index kWindowsPerZone = 60;
// The step when none is given, s: 1 kHz sampling holds the digital weightings' bilinear error,
// about 3.5 (f/f_s)² (docs/ride.md, "Digital weightings"), below 1e-3 up to 16 Hz, where a
// floor's weighted acceleration has its energy (Wb peaks at 4–12 Hz).
constexpr double kDefaultTimeStep = 1e-3;
// A coarser step is noted with its weighting error at this frequency, the upper end of the band
// where Wb and Wd carry a floor's weighted energy.
constexpr double kWeightedBandTop = 16.0;

bool finite_at_least(double value, double least) { return std::isfinite(value) && value >= least; }

Eigen::Index geometry_samples(const TrackGeometry& geometry) {
  if (!(std::isfinite(geometry.step) && geometry.step > 0.0))
    throw std::invalid_argument("simulate_ride: the geometry's step must be positive and finite");
  Eigen::Index n = 0;
  for (const Eigen::VectorXd* profile : {&geometry.vertical_level, &geometry.alignment, &geometry.cross_level}) {
    if (profile->size() == 0) continue;
    if (n != 0 && profile->size() != n)
      throw std::invalid_argument("simulate_ride: the geometry's components have different sample counts");
    if (!profile->allFinite()) throw std::invalid_argument("simulate_ride: the geometry has a non-finite sample");
    n = profile->size();
  }
  if (n < 2) throw std::invalid_argument("simulate_ride: the geometry has no component of at least two samples");
  return n;
}

// The run: `settle` steps, then `evaluated` samples; a periodic geometry is evaluated over
// exactly one period (N·m steps), so its samples' DFT has the track's bins (the FFT checks).
struct RunPlan {
  double step = 0.0;
  long settle = 0, evaluated = 0;
};

RunPlan plan_run(const TrackGeometry& geometry, Eigen::Index samples, const ride::TrackUnderWheels& track,
                 const RideSimulationOptions& options, std::vector<std::string>* notes) {
  const double sample_time = geometry.step / options.speed;
  if (options.time_step > sample_time * (1.0 + 1e-12)) {
    std::ostringstream why;
    why << "simulate_ride: time_step " << options.time_step << " s is longer than the geometry's step over the speed, "
        << sample_time << " s";
    throw std::invalid_argument(why.str());
  }
  const double asked = options.time_step > 0.0 ? options.time_step : std::min(kDefaultTimeStep, sample_time);
  RunPlan plan;
  const long m = std::max(1L, static_cast<long>(std::ceil(sample_time / asked - 1e-9)));
  plan.step = sample_time / static_cast<double>(m);
  if (plan.step < asked * (1.0 - 1e-12)) {
    std::ostringstream note;
    note << "time step " << plan.step << " s: the geometry's step over the speed divided by " << m
         << ", so that the track samples meet every wheel on a fixed phase of the steps";
    notes->push_back(note.str());
  }
  if (plan.step > kDefaultTimeStep * (1.0 + 1e-9)) {
    const double rate = 1.0 / plan.step;
    char error[32];
    std::snprintf(error, sizeof error, "%.2g", 100.0 * 3.5 * std::pow(kWeightedBandTop / rate, 2));
    std::ostringstream note;
    note << "sampling at " << std::lround(rate) << " Hz: the digital weightings are off by about " << error << " % at "
         << kWeightedBandTop << " Hz (3.5 (f/f_s)²); a time_step of 1 ms or less (the default) holds that below 0.1 %";
    notes->push_back(note.str());
  }
  plan.settle = std::lround(options.settle_time / plan.step);
  if (geometry.periodic) {
    plan.evaluated = static_cast<long>(samples) * m;
  } else {
    const double travel = track.end() - track.span();
    const long steps = travel > 0.0 ? static_cast<long>(std::floor(travel / (options.speed * plan.step) + 1e-9)) : -1;
    plan.evaluated = steps + 1 - plan.settle;
    if (plan.evaluated < 2) {
      std::ostringstream why;
      why << "simulate_ride: the geometry (" << track.end() << " m) is too short for the run: the wheels span "
          << track.span() << " m and settle_time takes " << options.speed * options.settle_time << " m";
      throw std::invalid_argument(why.str());
    }
  }
  if (static_cast<double>(plan.settle + plan.evaluated) > 1e9)
    throw std::invalid_argument("simulate_ride: more than 1e9 steps; take a longer time step or a shorter record");
  return plan;
}

// What was run, for the report's first line: "ORE B176 low, vertical level; 8192 m every 0.25 m;
// seed 7 at 160 km/h: 184.3 s evaluated after 0 s of settling, 196608 steps of 0.9375 ms (1067 Hz)".
std::string run_text(const TrackGeometry& geometry, const RideSimulationOptions& options, const RunPlan& plan) {
  std::ostringstream text;
  text << std::setprecision(4) << (geometry.source.empty() ? std::string("the track") : geometry.source) << " at " << options.speed * 3.6
       << " km/h: " << static_cast<double>(plan.evaluated) * plan.step << " s evaluated after "
       << static_cast<double>(plan.settle) * plan.step << " s of settling, " << plan.evaluated << " steps of "
       << plan.step * 1e3 << " ms (" << std::lround(1.0 / plan.step) << " Hz)";
  return text.str();
}

std::string periodic_start_note(bool steady) {
  return steady ? "started in the periodic steady state of the periodic track (no start-up transient)"
                : "started from rest: the vehicle has an (almost) undamped motion, so no periodic steady state";
}

// The periodic steady state: from rest, one period of N·m steps gives s_P; the state then
// obeys s_{k+Nm} = Φ^{Nm} s_k + s_P, whose fixed point s* = (I − Φ^{Nm})⁻¹ s_P starts the run
// on its periodic orbit (no start-up transient at all). An undamped mode makes I − Φ^{Nm}
// singular: then the run starts from rest and settle_time is all there is.
Eigen::VectorXd periodic_start(ride::RideMarch* march, long period, int states, std::vector<std::string>* notes) {
  Eigen::VectorXd s = Eigen::VectorXd::Zero(states);
  for (long k = 0; k < period; ++k) march->advance(k, &s);
  const Eigen::MatrixXd I = Eigen::MatrixXd::Identity(states, states);
  const Eigen::FullPivLU<Eigen::MatrixXd> lu(I - march->transition_power(period));
  constexpr double kSingular = 1e-10;  // reciprocal condition below which the fixed point is not trusted
  const bool steady = lu.isInvertible() && lu.rcond() >= kSingular;  // rcond is NaN for an exactly zero pivot
  notes->push_back(periodic_start_note(steady));
  return steady ? Eigen::VectorXd(lu.solve(s)) : Eigen::VectorXd::Zero(states);
}

// The samples of every output over the run, one vector each.
std::vector<Eigen::VectorXd> march_outputs(ride::RideMarch* march, const ride::TrackUnderWheels& track,
                                           const std::vector<ride::OutputRow>& rows, Eigen::VectorXd s, long count,
                                           double speed) {
  std::vector<Eigen::VectorXd> y(rows.size());
  for (Eigen::VectorXd& run : y) run.resize(count);
  Eigen::VectorXd w, dw;
  for (long k = 0; k < count; ++k) {
    track.displacement(march->leading(k), &w);
    track.slope(march->leading(k), &dw);
    dw *= speed;  // ẇ = V ∂w/∂ξ
    for (size_t j = 0; j < rows.size(); ++j) y[j](k) = rows[j].Ls.dot(s) + rows[j].Lw.dot(w) + rows[j].Ld.dot(dw);
    if (k + 1 < count) march->advance(k, &s);
  }
  return y;
}

// The linear vehicle's outputs over the run, one vector each: in modal coordinates when A's
// eigenvectors are well conditioned (ride_modal_march.hpp), else by the dense march; the same
// discretisation, so the same histories to round-off (tests/ride/ride_modal_march_test.cpp).
std::vector<Eigen::VectorXd> linear_march(const ride::RideStateSpace& model, const ride::TrackUnderWheels& track,
                                          const std::vector<ride::OutputRow>& rows, bool periodic, const RunPlan& plan,
                                          double speed, std::vector<std::string>* notes, StageClock* clock) {
  const long count = plan.settle + plan.evaluated;
  if (const auto modal = ride::ModalRideMarch::make(model, track, rows, speed, plan.step, track.span())) {
    clock->lap("state transition");
    ride::ModalRideMarch::State start = modal->rest();
    if (periodic) notes->push_back(periodic_start_note(modal->periodic_start(plan.evaluated, &start)));
    std::vector<Eigen::VectorXd> y = modal->outputs(std::move(start), count);
    clock->lap("march");
    return y;
  }
  ride::RideMarch march(model, track, speed, plan.step, track.span());
  clock->lap("state transition");
  const Eigen::VectorXd start =
      periodic ? periodic_start(&march, plan.evaluated, model.states(), notes) : Eigen::VectorXd::Zero(model.states());
  std::vector<Eigen::VectorXd> y = march_outputs(&march, track, rows, start, count, speed);
  clock->lap("march");
  return y;
}

// A weighting run over the evaluated samples, into *out: a periodic history (`evaluated`, the
// run's tail) is filtered over two periods and the second kept (the filter then in its own
// periodic steady state); another over the whole run, settling included, and the evaluated
// tail kept. The histories are read in place (Eigen::Ref), not copied.
void weighted(const ride::DigitalFilter& filter, Eigen::Ref<const Eigen::VectorXd> run,
              Eigen::Ref<const Eigen::VectorXd> evaluated, bool periodic, Eigen::VectorXd* out) {
  *out = periodic ? filter.apply_second_pass(evaluated) : filter.apply_from(run, run.size() - evaluated.size());
}

// Two weightings of the same run side by side (DigitalFilter's pair: the same samples as
// weighted() of each, bit for bit), into the caller's vectors.
void weighted(const ride::DigitalFilter& first, const ride::DigitalFilter& second, Eigen::Ref<const Eigen::VectorXd> run,
              Eigen::Ref<const Eigen::VectorXd> evaluated, bool periodic, Eigen::VectorXd* first_out,
              Eigen::VectorXd* second_out) {
  if (periodic)
    ride::DigitalFilter::apply_second_pass(first, second, evaluated, first_out, second_out);
  else
    ride::DigitalFilter::apply_from(first, second, run, run.size() - evaluated.size(), first_out, second_out);
}

// The same two weightings of two runs at once (DigitalFilter's two-history form: each output
// the same samples as the pair's, bit for bit).
void weighted(const ride::DigitalFilter& first, const ride::DigitalFilter& second, Eigen::Ref<const Eigen::VectorXd> run_a,
              Eigen::Ref<const Eigen::VectorXd> evaluated_a, Eigen::Ref<const Eigen::VectorXd> run_b,
              Eigen::Ref<const Eigen::VectorXd> evaluated_b, bool periodic, Eigen::VectorXd* first_a,
              Eigen::VectorXd* second_a, Eigen::VectorXd* first_b, Eigen::VectorXd* second_b) {
  if (periodic)
    ride::DigitalFilter::apply_second_pass(first, second, evaluated_a, evaluated_b, first_a, second_a, first_b, second_b);
  else
    ride::DigitalFilter::apply_from(first, second, run_a, run_b, run_a.size() - evaluated_a.size(), first_a, second_a,
                                    first_b, second_b);
}

double rms(const Eigen::VectorXd& values) { return std::sqrt(values.squaredNorm() / static_cast<double>(values.size())); }

// An output's history before its weightings: its samples over the run, `*run`, and their RMS.
// With no settling the run is the history and moves into it (no copy); else its evaluated
// tail is copied into the history's values.
RideHistory history_values(Eigen::VectorXd* run, const RunPlan& plan) {
  RideHistory h;
  if (plan.settle == 0)
    h.values = std::move(*run);
  else
    h.values = run->tail(plan.evaluated);
  h.rms = rms(h.values);
  return h;
}

bool weighted_output(const RideOutput& output) {
  return output.kind == RideOutput::Kind::point && output.quantity == ResponseQuantity::acceleration;
}

// A weighted output's filters: EN 12299's W of its axis, and beside it (lateral and vertical)
// Sperling's B of its direction.
ride::DigitalFilter comfort_filter(const RideOutput& output, double step) {
  return ride::digital_weighting(output.axis == RideAxis::vertical ? en12299_wb() : en12299_wd(), step);
}
bool has_sperling(const RideOutput& output) { return output.axis != RideAxis::longitudinal; }
ride::DigitalFilter sperling_filter(const RideOutput& output, double step) {
  return ride::digital_sperling(output.axis == RideAxis::vertical ? SperlingDirection::vertical : SperlingDirection::lateral,
                                step);
}

// The weighted samples of every weighted output: W into RideHistory::weighted, Sperling's B
// (of which only the RMS is kept, by history_indices()) into the storage of the history's
// Cc(t), written after it. Two outputs of one axis (the same two filters) go through them at once.
// runs[j]: output j's samples over the run, settling included.
void weigh_outputs(const std::vector<RideOutput>& outputs, const std::vector<Eigen::VectorXd*>& runs,
                   const RunPlan& plan, bool periodic, std::vector<RideHistory>* histories) {
  std::vector<char> done(outputs.size(), 0);
  for (size_t j = 0; j < outputs.size(); ++j) {
    if (done[j] || !weighted_output(outputs[j])) continue;
    RideHistory& h = (*histories)[j];
    const ride::DigitalFilter comfort = comfort_filter(outputs[j], plan.step);
    if (!has_sperling(outputs[j])) {
      weighted(comfort, *runs[j], h.values, periodic, &h.weighted);
      continue;
    }
    const ride::DigitalFilter sperling = sperling_filter(outputs[j], plan.step);
    size_t partner = j + 1;
    while (partner < outputs.size() &&
           (done[partner] || !weighted_output(outputs[partner]) || outputs[partner].axis != outputs[j].axis))
      ++partner;
    if (partner == outputs.size()) {
      weighted(comfort, sperling, *runs[j], h.values, periodic, &h.weighted, &h.continuous_comfort);
      continue;
    }
    RideHistory& g = (*histories)[partner];
    weighted(comfort, sperling, *runs[j], h.values, *runs[partner], g.values, periodic, &h.weighted,
             &h.continuous_comfort, &g.weighted, &g.continuous_comfort);
    done[partner] = 1;
  }
}

// A weighted output's indices from its weighted samples (weigh_outputs()).
void history_indices(const RideOutput& output, const RunPlan& plan, const RideSimulationOptions& options,
                     std::vector<std::string>* notes, RideHistory* h) {
  if (has_sperling(output)) h->sperling_wz = sperling_wz_from_weighted_rms(rms(h->continuous_comfort));
  h->weighted_rms = rms(h->weighted);
  const Eigen::Index window = std::max<Eigen::Index>(1, std::lround(options.window / plan.step));
  h->window_rms = ride::window_rms(h->weighted, window);
  ride::running_rms(h->weighted, window, &h->continuous_comfort);
  if (h->window_rms.size() == 0) {
    notes->push_back(output.name + ": the run is shorter than one window; no P95");
    return;
  }
  std::string note;
  h->p95 = ride::zone_p95(h->window_rms, kWindowsPerZone, &note);
  notes->push_back(output.name + ": " + note);
}

// N_MV per floor point: EN 12299 combines the three axes' P95 of the same 5-minute zone, and
// the point's figure is the largest over the zones (not the axes' worst zones combined).
std::vector<RideComfortAtPoint> comfort(const std::vector<RideOutput>& outputs, const std::vector<RideHistory>& histories) {
  using Key = std::tuple<std::string, double, double, double>;
  std::map<Key, std::array<std::optional<Eigen::VectorXd>, 3>> points;  // per axis: its zones' P95
  std::vector<Key> order;
  for (size_t j = 0; j < outputs.size(); ++j) {
    const RideOutput& o = outputs[j];
    if (o.kind != RideOutput::Kind::point || o.quantity != ResponseQuantity::acceleration || !histories[j].p95) continue;
    const Key key = std::make_tuple(o.body, o.point.x(), o.point.y(), o.point.z());
    if (!points.count(key)) order.push_back(key);
    points[key][static_cast<int>(o.axis)] = ride::zone_p95s(histories[j].window_rms, kWindowsPerZone);
  }
  std::vector<RideComfortAtPoint> out;
  for (const Key& key : order) {
    RideComfortAtPoint c;
    c.body = std::get<0>(key);
    c.point = {std::get<1>(key), std::get<2>(key), std::get<3>(key)};
    const auto& p95 = points[key];
    for (RideAxis axis : {RideAxis::longitudinal, RideAxis::lateral, RideAxis::vertical})
      if (!p95[static_cast<int>(axis)]) c.missing_axes.push_back(axis);
    auto axis = [&](int k) { return p95[k] ? &*p95[k] : nullptr; };
    c.nmv_estimate = ride::zone_nmv(axis(0), axis(1), axis(2));
    out.push_back(c);
  }
  return out;
}

}  // namespace

bool RideSimulationOptions::is_valid(std::string* why) const {
  if (!(std::isfinite(speed) && speed > 0.0)) return invalid(why, "speed must be positive and finite");
  if (!finite_at_least(time_step, 0.0)) return invalid(why, "time_step must be finite and >= 0 (0: the default)");
  if (!finite_at_least(settle_time, 0.0)) return invalid(why, "settle_time must be finite and >= 0");
  if (!(std::isfinite(window) && window > 0.0)) return invalid(why, "window must be positive and finite");
  if (!finite_at_least(contact_half_spacing, 0.0)) return invalid(why, "contact_half_spacing must be finite and >= 0");
  if (!finite_at_least(rolling_radius, 0.0)) return invalid(why, "rolling_radius must be finite and >= 0");
  return true;
}

RideSimulationResult simulate_ride(const LinearSystem& system, const TrackGeometry& geometry,
                                   const std::vector<RideOutput>& outputs, const RideSimulationOptions& options) {
  require_valid(options, "RideSimulationOptions: ");
  const Eigen::Index samples = geometry_samples(geometry);
  if (system.track_inputs.empty()) throw std::invalid_argument("simulate_ride: the system has no track inputs");
  if (outputs.empty()) throw std::invalid_argument("simulate_ride: no outputs requested");
  RideSimulationResult result;
  StageClock clock(&result.summary);
  const ride::RideStateSpace model = ride::ride_state_space(system);
  const std::vector<ride::OutputRow> rows = ride::output_rows(system, model, outputs);
  const ride::TrackUnderWheels track(
      system, geometry, ride::cross_level_directions(system, options.contact_half_spacing, options.rolling_radius));
  const RunPlan plan = plan_run(geometry, samples, track, options, &result.notes);
  std::vector<Eigen::VectorXd> y;  // every output's samples over the run
  if (options.effects.any()) {
    // The nonlinear effects simulated, not linearised (docs/ride.md, "Friction in time"): from
    // rest, also on a periodic track (a nonlinear orbit has no closed-form start).
    if (geometry.periodic)
      result.notes.push_back("nonlinear effects: started from rest (settle_time is all the settling there is)");
    ride::FrictionMarch march = ride::march_with_effects(system, model, track, rows, plan.settle + plan.evaluated,
                                                         plan.step, options.speed, options.effects);
    for (Eigen::Index j = 0; j < march.y.cols(); ++j) y.emplace_back(march.y.col(j));
    int sticks = 0, slips = 0;
    for (const SimulationEvent& e : march.history.events)
      sticks += e.kind == SimulationEvent::Kind::stick, slips += e.kind == SimulationEvent::Kind::slip;
    result.summary.checks.push_back({"integrator steps", static_cast<double>(march.history.steps_taken), INFINITY, true});
    result.summary.checks.push_back({"stick events", static_cast<double>(sticks), INFINITY, true});
    result.summary.checks.push_back({"slip events", static_cast<double>(slips), INFINITY, true});
    clock.lap("nonlinear march");
  } else {
    y = linear_march(model, track, rows, geometry.periodic, plan, options.speed, &result.notes, &clock);
  }

  result.outputs = outputs;
  result.time_step = plan.step;
  result.window = options.window;
  result.notes.insert(result.notes.begin(), run_text(geometry, options, plan));
  result.time = Eigen::VectorXd::LinSpaced(plan.evaluated, static_cast<double>(plan.settle) * plan.step,
                                           static_cast<double>(plan.settle + plan.evaluated - 1) * plan.step);
  double non_finite = 0.0;  // over the whole run, settling included
  for (const Eigen::VectorXd& run : y) non_finite += static_cast<double>((!run.array().isFinite()).count());
  result.histories.reserve(outputs.size());  // no reallocation: `runs` points into the histories
  std::vector<Eigen::VectorXd*> runs;         // each output's whole run, where it is now
  for (size_t j = 0; j < outputs.size(); ++j) {
    result.histories.push_back(history_values(&y[j], plan));
    runs.push_back(plan.settle == 0 ? &result.histories.back().values : &y[j]);
  }
  weigh_outputs(outputs, runs, plan, geometry.periodic, &result.histories);
  for (size_t j = 0; j < outputs.size(); ++j)
    if (weighted_output(outputs[j])) history_indices(outputs[j], plan, options, &result.notes, &result.histories[j]);
  result.comfort = comfort(outputs, result.histories);
  clock.lap("indices");

  result.summary.analysis = options.effects.any() ? "ride on a track realisation (time domain, nonlinear effects)"
                                                   : "ride on a track realisation (time domain)";
  result.summary.method =
      options.effects.any()
          ? "adaptive Dormand–Prince 5(4) with stick/slip events, steps ending where a wheel passes a track sample "
            "(simulate/sampled_track.hpp); EN 12299 Wb/Wd and Sperling B by the prewarped bilinear transform"
          : "exact state transition with a first-order hold on each wheel's linearly interpolated track (Van Loan), "
            "step = track step / (m·speed); EN 12299 Wb/Wd and Sperling B by the prewarped bilinear transform";
  result.summary.checks.push_back({"non-finite output samples", non_finite, 0.0, non_finite == 0.0});
  if (auto note = ride::default_floor_note(system, outputs)) result.notes.push_back(std::move(*note));
  for (const std::string& note : ride::frame_notes(system, outputs)) result.notes.push_back(note);
  return result;
}

}  // namespace railmodal
