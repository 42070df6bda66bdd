// The frequency-domain ride (ride.hpp, solve_ride): modes, grid, receptances once, then each
// speed by its delays and densities, with leaf friction linearised statistically per speed.
#include <algorithm>
#include <cmath>
#include <exception>
#include <complex>
#include <limits>
#include <map>
#include <optional>
#include <utility>
#include <thread>

#include "railmodal/hunting.hpp"
#include "railmodal/modal.hpp"
#include "railmodal/response.hpp"
#include "railmodal/ride.hpp"
#include "require_valid.hpp"
#include "response/friction_damping.hpp"
#include "response/modal_checks.hpp"
#include "ride/default_ride_outputs.hpp"
#include "ride/ride_contact.hpp"
#include "ride/ride_friction.hpp"
#include "ride/ride_grid.hpp"
#include "ride/ride_indices.hpp"
#include "ride/ride_speed.hpp"
#include "ride/ride_transfer.hpp"
#include "ride/ride_workspace.hpp"
#include "ride/track_under_wheels.hpp"
#include "shortest_text.hpp"
#include "stability/branch_naming.hpp"
#include "summary/stage_clock.hpp"

namespace railmodal {

namespace {

constexpr double kTwoPi = 6.28318530717958647692;
using Complex = std::complex<double>;

// What every speed shares: the request's components and modes, the grid and the weightings.
struct Problem {
  const LinearSystem* system = nullptr;
  const std::vector<RideOutput>* outputs = nullptr;
  const RideOptions* options = nullptr;
  std::vector<ride::Component> components;
  ModalResult modes;
  std::vector<const Mode*> oscillatory;  // RideResult::modes, in order
  ride::ModalBasis contributions;        // the oscillatory modes the outputs are split over
  Eigen::MatrixXd truncation;            // n × N when options.modes > 0
  Eigen::VectorXd grid;
  Eigen::VectorXd wb2, wd2, sperling_v2, sperling_l2;  // |W|² on the grid
  std::vector<ride::FrictionElement> friction;
  std::vector<std::string> notes;  // the grid's and the track's, for RideResult::notes
  // Without friction the system is the same at every speed: its output maps and receptances
  // are computed once (into the workspace's `shared`) and every speed reuses them.
  std::vector<ride::OutputMap> maps;
  const ride::Receptances* shared = nullptr;
  // With wheelsets moving laterally: the creep contact, whose terms depend on speed (so does
  // every speed's own receptances).
  std::optional<ride::CreepContact> contact;
  bool contact_forces = false;  // a lateral wheel–rail force among the outputs (its map depends on speed)
  std::string track_inputs;     // "12 track inputs (…)" for summary.method
};

// How many track inputs the solve takes, and of which kind when the contact adds its own (the
// wheelsets' alignment and the rails' roll, ride_contact.hpp).
std::string input_count_text(const LinearSystem& system) {
  int elements = 0, alignment = 0, roll = 0;
  for (const TrackInput& t : system.track_inputs)
    (t.element >= 0 ? elements : t.element == ride::kAlignmentInput ? alignment : roll) += 1;
  const std::string all = std::to_string(system.track_inputs.size()) + " track inputs";
  if (alignment + roll == 0) return all;
  return all + " (" + std::to_string(elements) + " under the elements, " + std::to_string(alignment) +
         " wheelsets' alignment through the contact" +
         (roll ? ", " + std::to_string(roll) + " wheelsets' roll with the rails through the contact" : std::string()) + ")";
}

// A mode no damper acts on (the series dampers included).
bool undamped(const LinearSystem& system, const Mode& mode) {
  if (!response::undamped(system, mode)) return false;
  for (const SeriesDamperRow& s : system.series_dampers)
    if (response::moves(s.stretch, mode.shape)) return false;
  return true;
}

double modal_damping_ratio(const LinearSystem& system, const Mode& mode) {
  return mode.shape.dot(system.damping * mode.shape) / (2.0 * mode.omega_rad_s);
}

// The outputs an undamped mode in the band drives at this speed (an answer, not a number):
// its modal force from component c, Σ_i φᵀQ_{c,i}(ω_j)·e^{−iω_jτ_i}, beyond round-off of the
// inputs' loads (response::kLoadRoundOff), with G_c(f_j) > 0, and the output moving with it.
std::vector<bool> unbounded_outputs(const Problem& p, const LinearSystem& system,
                                    const std::vector<ride::OutputMap>& maps, double speed,
                                    std::vector<std::string>* driven) {
  std::vector<bool> out(maps.size(), false);
  double front = system.track_inputs.front().point.x();
  for (const TrackInput& t : system.track_inputs) front = std::max(front, t.point.x());
  for (const Mode* mode : p.oscillatory) {
    if (mode->frequency_hz < p.grid(0) || mode->frequency_hz > p.grid(p.grid.size() - 1)) continue;
    if (!undamped(system, *mode)) continue;
    const double omega = mode->omega_rad_s;
    bool drives = false;
    for (const ride::Component& c : p.components) {
      if (!(c.spectrum.temporal_density(mode->frequency_hz, speed) > 0.0)) continue;
      Complex force = 0.0;
      double load_norm2 = 0.0;
      for (size_t i = 0; i < system.track_inputs.size(); ++i) {
        const TrackInput& t = system.track_inputs[i];
        const Eigen::VectorXcd q = (t.load_per_displacement.cast<Complex>() +
                                    Complex(0.0, omega) * t.load_per_velocity.cast<Complex>()) *
                                   c.displacement[i].cast<Complex>();
        load_norm2 += q.squaredNorm();
        force += mode->shape.cast<Complex>().dot(q) * std::exp(Complex(0.0, -omega * (front - t.point.x()) / speed));
      }
      drives = drives || std::abs(force) > response::kLoadRoundOff * mode->shape.norm() * std::sqrt(load_norm2);
    }
    if (!drives) continue;
    driven->push_back(mode->name + " (" + shortest_text(mode->frequency_hz, 4) + " Hz)");
    for (size_t o = 0; o < maps.size(); ++o) {
      const Eigen::RowVectorXcd row = maps[o].row(omega);
      const double scale = mode->shape.cwiseAbs().maxCoeff() * row.cwiseAbs().sum();
      if (std::abs((row * mode->shape.cast<Complex>())(0)) > 1e-9 * scale) out[o] = true;
    }
  }
  return out;
}

void receptances_of(const Problem& p, const LinearSystem& system, const std::vector<ride::OutputMap>& maps,
                    ride::Receptances* into) {
  ride::receptances(system, p.components, maps, p.grid, p.truncation.size() ? &p.truncation : nullptr,
                    p.contributions.shapes.cols() ? &p.contributions : nullptr, into);
}

struct SpeedOutcome {
  RideAtSpeed at;
  std::vector<std::string> notes;
  double grid_error = 0.0;
  ride::FrictionLinearisation friction;
  bool grows = false;  // above the linear critical speed (mark_growing)
};

// Above the linear critical speed a free motion grows: no stationary response exists for the
// outputs it moves (their RMS is unbounded). An output it does not move, the round-off rule of
// unbounded_outputs on the output's row at ω = |λ| (a vertical output of a vehicle whose
// vertical motions are decoupled from the lateral ones in the linear model), keeps its number:
// the growing motion adds nothing to it, and the rest of the response is the stable modes'.
void mark_growing(const LinearSystem& system, const std::vector<ride::OutputMap>& maps, double speed,
                  std::vector<bool>* unbounded, SpeedOutcome* s) {
  const std::vector<ride::GrowingMotion> growing = ride::growing_motions(system);
  if (growing.empty()) return;
  s->grows = true;
  std::string motions;
  int moved = 0;
  std::vector<bool> moves(maps.size(), false);
  for (const ride::GrowingMotion& g : growing) {
    const double omega = std::abs(g.root);
    for (size_t o = 0; o < maps.size(); ++o) {
      const Eigen::RowVectorXcd row = maps[o].row(omega);
      const double scale = g.shape.cwiseAbs().maxCoeff() * row.cwiseAbs().sum();
      moves[o] = moves[o] || std::abs((row * g.shape)(0)) > 1e-9 * scale;
    }
    const Eigen::VectorXcd weighted = system.mass.diagonal().cwiseSqrt().cast<Complex>().cwiseProduct(g.shape);
    const bool oscillates = !stability::overdamped_root(g.root);
    motions += (motions.empty() ? "'" : "; '") + stability::root_name(system, weighted, oscillates) + "' (" +
               (oscillates ? shortest_text(g.root.imag() / kTwoPi, 3) + " Hz, " : std::string("real root, ")) +
               "Re λ = +" + shortest_text(g.root.real(), 3) + " 1/s)";
  }
  for (size_t o = 0; o < maps.size(); ++o) {
    moved += moves[o];
    (*unbounded)[o] = (*unbounded)[o] || moves[o];
  }
  const int kept = static_cast<int>(maps.size()) - moved;
  s->notes.push_back("at " + shortest_text(speed * 3.6, 6) + " km/h the vehicle on its wheelsets is above its linear "
                     "critical speed: the free " + (growing.size() > 1 ? "motions " : "motion ") + motions +
                     (growing.size() > 1 ? " grow" : " grows") + ", so the " + std::to_string(moved) +
                     " outputs they move have no stationary response (unbounded)" +
                     (kept > 0 ? "; the other " + std::to_string(kept) +
                                     " do not move with them in the linear model and keep their numbers"
                               : std::string()));
}

// ∫|D_c|²G_c df summed over the components: D_c(ω) = Σ_terms (iω)^q t(ω)·u_{c,i}·e^{−iωτ_i}, the
// output's direct track terms with the inputs' delays (RideOutputAtSpeed::direct_variance).
// `system` is the speed's (with the contact's own inputs after the elements', at their axles).
double direct_variance(const Problem& p, const LinearSystem& system, const ride::OutputMap& map,
                       const ride::SpeedSpectra& sp, const std::vector<ride::BandWeights>& bands, double speed) {
  if (map.inputs.empty()) return 0.0;
  const std::vector<TrackInput>& inputs = system.track_inputs;
  double front = p.system->track_inputs.front().point.x();
  for (const TrackInput& t : p.system->track_inputs) front = std::max(front, t.point.x());
  double sum = 0.0;
  for (size_t c = 0; c < p.components.size(); ++c)
    for (Eigen::Index k = 0; k < p.grid.size(); ++k) {
      if (bands[c].weights(k) == 0.0) continue;
      const double omega = kTwoPi * p.grid(k);
      Complex d = 0.0;
      for (size_t term = 0; term < map.inputs.size(); ++term) {
        const int i = map.inputs[term];
        d += map.track(term, p.components[c].displacement[i], omega) *
             std::polar(1.0, -omega * (front - inputs[i].point.x()) / speed);
      }
      sum += bands[c].weights(k) * std::norm(d) * sp.input_psd[c](k);
    }
  return sum;
}

RideOutputAtSpeed output_at_speed(const Problem& p, const RideOutput& o, const ride::ComponentPower& power,
                                  const Eigen::VectorXd& psd, const std::vector<double>& modal,
                                  const std::vector<ride::BandWeights>& bands, double* grid_error) {
  RideOutputAtSpeed r;
  const bool rms_only = p.options->rms_only;
  const double variance = ride::integral(power, bands, Eigen::VectorXd());
  r.rms = std::sqrt(std::max(variance, 0.0));
  if (variance > 0.0 && !rms_only) {
    const double coarse = std::sqrt(std::max(ride::integral(power, bands, Eigen::VectorXd(), true), 0.0));
    *grid_error = std::max(*grid_error, std::abs(coarse - r.rms) / r.rms);
  }
  if (o.kind == RideOutput::Kind::point && o.quantity == ResponseQuantity::acceleration) {
    const Eigen::VectorXd& w = o.axis == RideAxis::vertical ? p.wb2 : p.wd2;
    const double weighted = ride::integral(power, bands, w);
    r.weighted_rms = std::sqrt(std::max(weighted, 0.0));
    if (!rms_only) {  // RideOptions::rms_only: no P95 and no Wz
      r.p95_estimate = ride::rms_quantile(weighted, ride::integral_of_square(power, bands, p.grid, w),
                                          p.options->percentile_window, 0.95);
      if (o.axis != RideAxis::longitudinal)
        r.sperling_wz = sperling_wz_from_weighted_rms(std::sqrt(std::max(
            ride::integral(power, bands, o.axis == RideAxis::vertical ? p.sperling_v2 : p.sperling_l2), 0.0)));
    }
  }
  double modal_sum = 0.0;
  for (size_t j = 0; j < modal.size(); ++j) {
    if (!(modal[j] > 0.0)) continue;
    r.modes.push_back({static_cast<int>(j), modal[j], variance > 0.0 ? modal[j] / variance : 0.0});
    modal_sum += modal[j];
  }
  std::sort(r.modes.begin(), r.modes.end(),
            [](const ModalContribution& a, const ModalContribution& b) { return a.variance > b.variance; });
  r.cross_term_variance = variance - modal_sum;
  if (p.options->keep_spectra) r.psd = psd;
  return r;
}

// N_MV at each distinct floor point with acceleration outputs (en12299_nmv of the P95s).
std::vector<RideComfortAtPoint> comfort(const std::vector<RideOutput>& outputs,
                                        const std::vector<RideOutputAtSpeed>& at, std::vector<std::string>* notes) {
  std::vector<RideComfortAtPoint> out;
  std::vector<bool> done(outputs.size(), false);
  for (size_t o = 0; o < outputs.size(); ++o) {
    const RideOutput& first = outputs[o];
    if (done[o] || first.kind != RideOutput::Kind::point || first.quantity != ResponseQuantity::acceleration) continue;
    std::map<RideAxis, std::optional<double>> p95;
    bool unbounded = false;
    for (size_t q = o; q < outputs.size(); ++q) {
      const RideOutput& other = outputs[q];
      if (other.kind != RideOutput::Kind::point || other.quantity != ResponseQuantity::acceleration ||
          other.body != first.body || (other.point - first.point).norm() > 1e-9)
        continue;
      done[q] = true;
      unbounded = unbounded || at[q].unbounded;
      if (!p95.count(other.axis)) p95[other.axis] = at[q].p95_estimate;
    }
    if (unbounded) {
      notes->push_back("no N_MV at '" + first.name + "': an axis there is unbounded");
      continue;
    }
    RideComfortAtPoint c;
    c.body = first.body;
    c.point = first.point;
    double axis_p95[3] = {0.0, 0.0, 0.0};
    for (RideAxis axis : {RideAxis::longitudinal, RideAxis::lateral, RideAxis::vertical}) {
      if (p95.count(axis) && p95[axis]) axis_p95[static_cast<int>(axis)] = *p95[axis];
      else c.missing_axes.push_back(axis);
    }
    c.nmv_estimate = en12299_nmv(axis_p95[0], axis_p95[1], axis_p95[2]);
    out.push_back(c);
  }
  return out;
}

// An output whose RMS is round-off (the symmetric car's lateral response to vertical level:
// 1e-17 of the others) is a zero response: its grid error and modal shares are noise, so it is
// left out of the grid error estimate, given no shares, and named in a note. Round-off is an
// RMS below kRoundOff of the largest of the outputs in the same unit at that speed: far below
// any response a track excites and far above double precision's 1e-16 relative noise.
constexpr double kRoundOff = 1e-9;

void set_round_off_apart(const std::vector<RideOutput>& outputs, const std::vector<double>& grid_error,
                         SpeedOutcome* s) {
  std::map<std::string, double> largest;  // per unit
  for (size_t o = 0; o < outputs.size(); ++o)
    if (!s->at.outputs[o].unbounded)
      largest[unit_of(outputs[o])] = std::max(largest[unit_of(outputs[o])], s->at.outputs[o].rms);
  for (size_t o = 0; o < outputs.size(); ++o) {
    RideOutputAtSpeed& r = s->at.outputs[o];
    if (r.unbounded) continue;
    if (r.rms > kRoundOff * largest[unit_of(outputs[o])]) {
      s->grid_error = std::max(s->grid_error, grid_error[o]);
      continue;
    }
    if (largest[unit_of(outputs[o])] > 0.0 && r.rms > 0.0) {
      r.modes.clear();
      r.cross_term_variance = r.rms * r.rms;
      s->notes.push_back("'" + outputs[o].name + "' is round-off (its RMS below " + shortest_text(kRoundOff) +
                         " of the largest " + unit_of(outputs[o]) +
                         " output's): the track does not move it; no modal shares, and it is left out of the grid "
                         "error estimate");
    }
  }
}

// One speed, its arrays in the worker's `kept`.
SpeedOutcome solve_speed(const Problem& p, double speed, ride::SpeedWorkspace* kept) {
  SpeedOutcome s;
  const LinearSystem base = p.contact ? ride::with_creep(*p.system, *p.contact, speed) : *p.system;
  const std::vector<ride::BandWeights> bands = ride::speed_bands(p.components, p.grid, speed);
  std::vector<double> friction_damping;
  if (!p.friction.empty()) {
    // σ_v of every friction element for given dampers: its stretch rate as an extra output.
    auto velocity_rms = [&](const std::vector<double>& damping) {
      const LinearSystem system = response::with_element_vertical_dampers(base, damping);
      std::vector<ride::OutputMap> maps;
      for (const ride::FrictionElement& f : p.friction) maps.push_back(ride::stretch_rate_map(system, f.element));
      ride::receptances(system, p.components, maps, p.grid, p.truncation.size() ? &p.truncation : nullptr, nullptr,
                        &kept->passes);
      ride::SpeedSpectra& sp = kept->pass_spectra;
      ride::speed_spectra(system, kept->passes, p.components, p.grid, speed, bands, false, &sp, &kept->scratch);
      std::vector<double> sigma;
      for (const ride::ComponentPower& power : sp.outputs)
        sigma.push_back(std::sqrt(std::max(ride::integral(power, bands, Eigen::VectorXd()), 0.0)));
      return sigma;
    };
    s.friction = ride::linearise_friction(base, p.friction, p.options->friction_tolerance,
                                          p.options->friction_iterations, velocity_rms);
    friction_damping = s.friction.damping;
  }
  const LinearSystem system =
      friction_damping.empty() ? base : response::with_element_vertical_dampers(base, friction_damping);
  // The contact's wheel–rail forces depend on speed (C_c/V, V·G): their maps are rebuilt here.
  const ride::CreepContact* contact = p.contact ? &*p.contact : nullptr;
  const std::vector<ride::OutputMap> maps = friction_damping.empty() && !p.contact_forces
                                                ? p.maps
                                                : ride::output_maps(system, *p.outputs, friction_damping, contact, speed);
  const bool shared = friction_damping.empty() && !p.contact;
  if (!shared) receptances_of(p, system, maps, &kept->own);
  const ride::SpeedSpectra& sp = kept->spectra;
  ride::speed_spectra(system, shared ? *p.shared : kept->own, p.components, p.grid, speed, bands,
                      p.options->keep_spectra, &kept->spectra, &kept->scratch);
  std::vector<std::string> driven;
  std::vector<bool> unbounded = unbounded_outputs(p, system, maps, speed, &driven);
  if (p.contact) mark_growing(system, maps, speed, &unbounded, &s);
  s.at.speed = speed;
  std::vector<double> grid_error(maps.size(), 0.0);
  for (size_t o = 0; o < maps.size(); ++o) {
    if (unbounded[o]) {
      RideOutputAtSpeed r;
      r.unbounded = true;
      s.at.outputs.push_back(r);
      continue;
    }
    s.at.outputs.push_back(output_at_speed(p, (*p.outputs)[o], sp.outputs[o], sp.psd[o], sp.modal_variance[o], bands,
                                           &grid_error[o]));
    if (!p.options->rms_only) s.at.outputs.back().direct_variance = direct_variance(p, system, maps[o], sp, bands, speed);
  }
  set_round_off_apart(*p.outputs, grid_error, &s);
  for (const std::string& d : driven)
    s.notes.push_back("at " + shortest_text(speed * 3.6, 6) + " km/h the track excites the undamped mode " + d +
                      ": the outputs it moves have an unbounded RMS");
  if (!p.options->rms_only) s.at.comfort = comfort(*p.outputs, s.at.outputs, &s.notes);
  if (p.options->keep_spectra) s.at.input_psd = sp.input_psd;
  return s;
}

Problem prepare(const LinearSystem& system, const TrackIrregularitySpectra& track,
                const std::vector<RideOutput>& outputs, const RideOptions& options, RideResult* result) {
  Problem p;
  p.system = &system;
  p.outputs = &outputs;
  p.options = &options;
  if (ride::acts_through_contact(system))
    p.contact = ride::creep_contact(system, options.contact_half_spacing, track.cross_level.has_value());
  // With the contact, the wheelsets' own track inputs follow the elements' (with_creep).
  const LinearSystem first = p.contact ? ride::with_creep(system, *p.contact, options.speeds.front()) : LinearSystem();
  const LinearSystem& at_first = p.contact ? first : system;
  p.components = ride::track_components(at_first, track, options.contact_half_spacing, options.rolling_radius);
  // Every output names something of the system, or throws.
  p.maps = ride::output_maps(at_first, outputs, {}, p.contact ? &*p.contact : nullptr, options.speeds.front());
  for (const RideOutput& o : outputs)
    p.contact_forces = p.contact_forces || (o.kind == RideOutput::Kind::wheel_rail_force && o.axis == RideAxis::lateral);
  p.track_inputs = input_count_text(at_first);
  ModalOptions modal;
  modal.solver = ModalSolver::dense;
  p.modes = solve_modes(system, modal);
  for (const Mode& m : p.modes.modes)
    if (m.kind == ModeKind::oscillatory) {
      p.oscillatory.push_back(&m);
      result->modes.push_back({m.name, m.frequency_hz});
    }
  const int n = system.size();
  const int truncated = std::min<int>(options.modes, static_cast<int>(p.modes.modes.size()));
  if (options.modes > 0) {
    p.truncation.resize(n, truncated);
    for (int j = 0; j < truncated; ++j) p.truncation.col(j) = p.modes.modes[j].shape;
  }
  // The modal terms: every oscillatory mode of the basis H is computed in.
  // With the contact the modes change with speed (and are complex): the shares over the modes
  // without it would name motions the vehicle does not have, so none are given.
  std::vector<const Mode*> split;
  for (const Mode* m : p.oscillatory)
    if ((options.modes == 0 || m->index <= truncated) && !p.contact && !options.rms_only) split.push_back(m);
  Eigen::MatrixXd shapes(n, static_cast<Eigen::Index>(split.size()));
  for (size_t j = 0; j < split.size(); ++j) shapes.col(j) = split[j]->shape;
  p.contributions.shapes = shapes;
  p.contributions.left = shapes.transpose() * system.mass;
  p.friction = ride::friction_elements(system);
  return p;
}

// Each component's temporal band V·Ω/2π against the grid: wholly outside at a speed, its answer
// would be a silent zero (an error); partly outside, the RMS covers the grid only (a note).
std::vector<std::string> band_notes(const Problem& p, const RideOptions& options) {
  std::vector<std::string> notes;
  for (const ride::Component& c : p.components)
    for (double v : options.speeds) {
      const double low = v * c.spectrum.band().low / kTwoPi, high = v * c.spectrum.band().high / kTwoPi;
      const std::string at = "at " + shortest_text(v * 3.6, 6) + " km/h the " + to_string(c.kind) + " band (" +
                             c.spectrum.name() + ") spans " + shortest_text(low, 4) + " … " + shortest_text(high, 4) +
                             " Hz";
      if (high <= options.min_frequency || low >= options.max_frequency)
        throw IrregularityComponentError(
            c.kind, "ride: " + at + ", wholly outside the grid " + shortest_text(options.min_frequency) + " … " +
                        shortest_text(options.max_frequency) +
                        " Hz: its answer would be zero; widen the grid (min_frequency, max_frequency) or "
                        "the band");
      if (low < options.min_frequency || high > options.max_frequency)
        notes.push_back(at + ", beyond the grid " + shortest_text(options.min_frequency) + " … " +
                        shortest_text(options.max_frequency) + " Hz: the RMS covers the part inside the grid only");
    }
  return notes;
}

void build_grid(Problem* p, const RideOptions& options) {
  const LinearSystem& system = *p->system;
  std::vector<ride::GridMode> grid_modes;
  std::vector<double> avoid, extra;
  for (const Mode* m : p->oscillatory) {
    grid_modes.push_back({m->frequency_hz, modal_damping_ratio(system, *m)});
    if (undamped(system, *m)) avoid.push_back(m->frequency_hz);
  }
  if (p->contact)  // the modes with the creep terms at each speed: their peaks are the response's
    for (double v : options.speeds) {
      const Eigen::VectorXcd roots = ride::first_order_roots(ride::with_creep(system, *p->contact, v));
      for (const std::complex<double>& r : roots)
        if (r.imag() > 0.0 && r.real() < 0.0) grid_modes.push_back({std::abs(r) / kTwoPi, -r.real() / std::abs(r)});
    }
  for (double v : options.speeds)
    for (const ride::Component& c : p->components) {
      extra.push_back(v * c.spectrum.band().low / kTwoPi);
      extra.push_back(v * c.spectrum.band().high / kTwoPi);
    }
  p->grid = ride::frequency_grid(options, grid_modes, extra, avoid);
  p->notes = band_notes(*p, options);
  // Each weighting only where an output reads it (output_at_speed): a vertical acceleration
  // Wb (and Sperling's vertical B unless rms_only), a lateral or longitudinal one Wd (and the
  // lateral B for a lateral one unless rms_only).
  bool vertical = false, horizontal = false, lateral = false;
  for (const RideOutput& o : *p->outputs)
    if (o.kind == RideOutput::Kind::point && o.quantity == ResponseQuantity::acceleration) {
      (o.axis == RideAxis::vertical ? vertical : horizontal) = true;
      lateral = lateral || o.axis == RideAxis::lateral;
    }
  const Eigen::Index K = p->grid.size();
  const FrequencyWeighting wb = en12299_wb(), wd = en12299_wd();
  auto fill = [&](bool wanted, Eigen::VectorXd* w2, auto weight) {
    if (!wanted) return;
    w2->resize(K);
    for (Eigen::Index k = 0; k < K; ++k) (*w2)(k) = weight(p->grid(k));
  };
  fill(vertical, &p->wb2, [&](double f) { return std::norm(wb.response(f)); });
  fill(horizontal, &p->wd2, [&](double f) { return std::norm(wd.response(f)); });
  fill(vertical && !options.rms_only, &p->sperling_v2,
       [](double f) { return std::pow(sperling_weighting(f, SperlingDirection::vertical), 2); });
  fill(lateral && !options.rms_only, &p->sperling_l2,
       [](double f) { return std::pow(sperling_weighting(f, SperlingDirection::lateral), 2); });
}

// Each speed on its own; `threads` workers take every threads-th speed, each with its own arrays
// in `workspace`, kept from one speed to the next.
std::vector<SpeedOutcome> solve_speeds(const Problem& p, const RideOptions& options, ride::Workspace* workspace) {
  const size_t count = options.speeds.size();
  std::vector<SpeedOutcome> out(count);
  std::vector<std::exception_ptr> errors(count);
  const size_t threads = std::min<size_t>(static_cast<size_t>(options.threads), count);
  if (workspace->workers.size() < std::max<size_t>(threads, 1)) workspace->workers.resize(std::max<size_t>(threads, 1));
  auto work = [&](size_t first, size_t step) {
    for (size_t v = first; v < count; v += step) try {
        out[v] = solve_speed(p, options.speeds[v], &workspace->workers[first]);
      } catch (...) {
        errors[v] = std::current_exception();
      }
  };
  std::vector<std::thread> pool;
  for (size_t t = 1; t < threads; ++t) pool.emplace_back(work, t, threads);
  work(0, std::max<size_t>(threads, 1));
  for (std::thread& t : pool) t.join();
  for (const std::exception_ptr& e : errors)
    if (e) std::rethrow_exception(e);
  return out;
}

std::string friction_text(const std::vector<SpeedOutcome>& speeds, const RideOptions& options) {
  int passes = 0;
  double change = 0.0;
  bool converged = true;
  for (const SpeedOutcome& s : speeds) {
    passes = std::max(passes, s.friction.passes);
    change = std::max(change, s.friction.change);
    converged = converged && s.friction.converged;
  }
  std::string text =
      "statistical linearisation: each leaf an equivalent viscous damper F·√(2/π)/σ_v from the RMS stretch "
      "rate σ_v across it (Gaussian), iterated to consistency per speed; ";
  if (converged) return text + "converged in " + std::to_string(passes) + " passes at most";
  return text + "NOT converged in " + std::to_string(options.friction_iterations) + " passes (last relative change " +
         shortest_text(change, 3) + ")";
}

// Whether the cross-level's sideways part (−θ(z + r0)) loads the model: only then does r0 matter.
bool reaches_laterally(const Problem& p) {
  for (const ride::Component& c : p.components)
    if (c.kind == TrackIrregularity::cross_level)
      for (size_t i = 0; i < p.system->track_inputs.size(); ++i) {
        const TrackInput& t = p.system->track_inputs[i];
        if (t.load_per_displacement.col(1).cwiseAbs().maxCoeff() > 0.0 ||
            t.load_per_velocity.col(1).cwiseAbs().maxCoeff() > 0.0)
          return true;
      }
  return false;
}

// Where the ride found a growing motion, the linear critical speed as `railmodal stability`
// finds it (solve_hunting_stability from 10 km/h, or half the speed, to the lowest speed at which
// a motion grows), so that the report says why the outputs the hunting moves have no number.
std::string critical_speed_note(const LinearSystem& system, const RideOptions& options,
                                const std::vector<SpeedOutcome>& speeds) {
  double lowest = std::numeric_limits<double>::infinity();
  for (size_t v = 0; v < speeds.size(); ++v)
    if (speeds[v].grows) lowest = std::min(lowest, options.speeds[v]);
  HuntingOptions hunting;
  hunting.max_speed = lowest;
  hunting.min_speed = std::min(hunting.min_speed, 0.5 * lowest);
  hunting.speed_count = 100;  // the crossing is refined to relative_tolerance whatever the grid
  hunting.threads = options.threads;
  // The note explains numbers already computed: a failure of the root locus (a numerical
  // failure at some speed of its grid) must not cost the ride, so it is said instead.
  HuntingResult r;
  try {
    r = solve_hunting_stability(system, hunting);
  } catch (const std::exception& e) {
    return "the vehicle on its wheelsets has a growing motion at " + shortest_text(lowest * 3.6, 6) +
           " km/h; its linear critical speed could not be found (" + e.what() +
           "): `railmodal stability` gives the root locus";
  }
  const std::string tail = ": above it a free motion grows and the outputs it moves have no stationary response; "
                           "`railmodal stability` gives the root locus";
  if (r.critical)
    return "the linear critical speed of the vehicle on its wheelsets is " + shortest_text(r.critical->speed * 3.6, 4) +
           " km/h ('" + r.critical->motion + "', " + shortest_text(r.critical->frequency_hz, 3) + " Hz)" + tail;
  if (r.verdict == HuntingVerdict::unstable_at_lowest_speed)
    return "the vehicle on its wheelsets is unstable already at " + shortest_text(hunting.min_speed * 3.6, 4) +
           " km/h" + tail;
  return "the vehicle on its wheelsets has a growing motion at " + shortest_text(lowest * 3.6, 6) +
         " km/h that the root locus below it does not resolve" + tail;
}

}  // namespace

RideResult solve_ride(const LinearSystem& system, const TrackIrregularitySpectra& track,
                      const std::vector<RideOutput>& outputs, const RideOptions& options) {
  return ride::solve_ride(system, track, outputs, options, nullptr);
}

RideResult ride::solve_ride(const LinearSystem& system, const TrackIrregularitySpectra& track,
                            const std::vector<RideOutput>& outputs, const RideOptions& options,
                            Workspace* kept) {
  Workspace own;  // without a caller's: kept across this solve's speeds only
  Workspace* workspace = kept ? kept : &own;
  require_valid(options, "RideOptions: ");
  RideResult result;
  result.summary.analysis = "ride on random track";
  StageClock clock(&result.summary);
  result.outputs = outputs;
  Problem p = prepare(system, track, outputs, options, &result);
  for (const ride::Component& c : p.components) {  // input_psd's order
    result.inputs.push_back(c.spectrum.name());
    result.input_rms.push_back(c.spectrum.rms());
  }
  clock.lap("modes");
  build_grid(&p, options);
  result.frequencies = p.grid;
  result.notes = p.notes;
  clock.lap("grid");
  if (p.friction.empty() && !p.contact) {
    receptances_of(p, system, p.maps, &workspace->shared);
    p.shared = &workspace->shared;
    clock.lap("receptances");
  }
  const std::vector<SpeedOutcome> speeds = solve_speeds(p, options, workspace);
  clock.lap("speeds");

  result.summary.method =
      (options.modes > 0 ? "modal superposition over the " + std::to_string(p.truncation.cols()) + " lowest modes"
                         : std::string("direct solve of K − ω²M + iωC")) +
      " at each of " + std::to_string(p.grid.size()) + " grid frequencies for all " +
      p.track_inputs + " at once; per speed the inputs' delays x/V" +
      (p.contact ? "; with the wheel–rail creep contact (linear, Kalker) assembled at each speed" : "");
  for (const SpeedOutcome& s : speeds) {
    result.speeds.push_back(s.at);
    result.grid_error_estimate = std::max(result.grid_error_estimate, s.grid_error);
    for (const std::string& note : s.notes)
      if (std::find(result.notes.begin(), result.notes.end(), note) == result.notes.end()) result.notes.push_back(note);
  }
  if (std::any_of(speeds.begin(), speeds.end(), [](const SpeedOutcome& s) { return s.grows; }))
    result.notes.push_back(critical_speed_note(system, options, speeds));
  // With no bounded RMS at any speed (an all-unbounded ride) nothing was estimated: no check,
  // rather than one that reads 0.
  const bool bounded = std::any_of(result.speeds.begin(), result.speeds.end(), [](const RideAtSpeed& at) {
    return std::any_of(at.outputs.begin(), at.outputs.end(),
                       [](const RideOutputAtSpeed& o) { return !o.unbounded && o.rms > 0.0; });
  });
  if (!options.rms_only && bounded)
    result.summary.checks.push_back({"grid error estimate (largest relative RMS change on halving the grid)",
                                     result.grid_error_estimate, std::numeric_limits<double>::infinity(), true});
  if (p.friction.empty()) {
    result.friction_treatment = "none in the vehicle";
  } else {
    result.friction_treatment = friction_text(speeds, options);
    double change = 0.0;
    for (const SpeedOutcome& s : speeds) change = std::max(change, s.friction.change);
    result.summary.checks.push_back({"friction linearisation: last relative change of σ_v", change,
                                     options.friction_tolerance, change <= options.friction_tolerance});
    if (change > options.friction_tolerance) result.notes.push_back("the friction linearisation did not converge");
  }
  if (track.cross_level && !ride::knows_rolling_radius(system, options.rolling_radius) && reaches_laterally(p))
    result.notes.push_back("cross-level rolls the rails about the axle plane: the vehicle has no wheelset to give "
                           "the rail top's depth r0 below it; give it as [ride] rolling_radius");
  if (p.contact && !p.contact->cross_level)
    result.notes.push_back("the wheelsets run on the linear creep contact at each speed (alignment acts through it, "
                           "docs/ride.md \"Lateral ride through the creep forces\"): no modal shares, since the modes "
                           "with the contact change with speed");
  if (p.contact && p.contact->cross_level)
    result.notes.push_back("the wheelsets run on the linear creep contact at each speed (alignment and cross-level act "
                           "through it, docs/ride.md \"Lateral ride through the creep forces\" and \"Cross-level through "
                           "the contact\"): no modal shares, since the modes with the contact change with speed");
  for (const RideOutput& o : outputs)
    if (o.kind == RideOutput::Kind::wheel_rail_force && o.axis == RideAxis::lateral) {
      result.notes.push_back("lateral wheel–rail forces are the rails' on the wheelset in the inertial frame (creep, "
                             "gravitational stiffness, the normal loads leaning with the rails' roll θ); across the "
                             "rolled track plane add W·θ (docs/ride.md, \"The wheel–rail force across the track\")");
      break;
    }
  if (options.modes > 0)
    result.notes.push_back("H(f) by modal superposition over the " + std::to_string(p.truncation.cols()) +
                           " lowest modes: the response misses the higher modes' share (docs/accuracy.md, "
                           "\"Ride: modal truncation\")");
  result.rms_only = options.rms_only;
  if (options.rms_only)
    result.notes.push_back("rms_only: each output's RMS and weighted RMS only (no modal shares, Sperling Wz, P95, N_MV "
                           "or grid error estimate)");
  else
    result.notes.push_back("P95 and N_MV are estimates for a stationary Gaussian process (chi-square with ν = "
                         "2T(∫S)²/∫S², T = " + shortest_text(options.percentile_window) + " s), not the statistic of "
                         "measured 5-s windows; that ν takes T long against the response's correlation time, so for a "
                         "narrow-band response the estimate reads high (+5.9 % for a 1 Hz mode at ζ = 0.05, +0.9 % at "
                         "ζ = 0.2; docs/ride.md)");
  if (auto note = ride::default_floor_note(system, outputs)) result.notes.push_back(std::move(*note));
  for (const std::string& note : ride::frame_notes(system, outputs)) result.notes.push_back(note);
  return result;
}

}  // namespace railmodal
