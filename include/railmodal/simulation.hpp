// Time-domain simulation of an assembled vehicle running over its excitation sources.
//
//   #include <railmodal/railmodal.hpp>
//   #include <iostream>
//
//   int main() {
//     auto vehicle = railmodal::load_vehicle("data/vehicles/two_axle_freight_wagon.toml");
//     auto system = railmodal::assemble(vehicle, railmodal::DofSet::vertical);
//     railmodal::RailJoints joints;  // 12.5 m rails with 5 mm dips at 60 km/h
//     joints.rail_length = 12.5;
//     joints.dip_depth = 0.005;
//     auto source = railmodal::make_source(joints);
//     railmodal::SimulationOptions options;
//     options.speed = 60.0 / 3.6;
//     options.duration = 5.0;
//     options.time_step = 0.005;
//     railmodal::TimeHistory h = railmodal::simulate_linear(system, {source.get()}, options);
//     std::cout << h.time.size() << " samples; body bounce at 5 s: " << h.displacement(h.time.size() - 1, 0) << " m\n";
//   }
//
// The linear path integrates M ẍ + C ẋ + K x = F(t) exactly for a load that is linear over
// each step (the state transition e^{AΔt} and its first-order-hold input integrals, from one
// matrix exponential; Van Loan 1978), so the only error is that of sampling F(t) at the step:
// O(Δt²) for smooth forcing, none for free motion. Massless DOFs follow statically.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "railmodal/excitation.hpp"
#include "railmodal/linear_system.hpp"
#include "railmodal/summary.hpp"

namespace railmodal {

/// A DOF displaced and/or moving at t = 0 (the book's drop tests release a load from rest
/// at a displaced position).
struct InitialCondition {
  std::string dof;          ///< DOF label, e.g. "body.bounce"
  double displacement = 0.0;  ///< m or rad
  double velocity = 0.0;      ///< m/s or rad/s
};

struct SimulationOptions {
  double speed = 0.0;      ///< m/s, constant (> 0 when there are sources); the initial speed of a ramp
  /// m/s; > 0: the speed ramps linearly from `speed` to this over the duration (the adaptive
  /// path only: simulate_nonlinear, with or without nonlinear effects).
  double final_speed = 0.0;
  double duration = 0.0;   ///< s
  double time_step = 0.0;  ///< s, integration step of the linear path; output step of both
  std::vector<InitialCondition> initial;
  /// Nonlinear path only: local error tolerance of the adaptive Runge–Kutta (Dormand–Prince
  /// 5(4)) integrator, relative to the state's scale (plus the same absolute floor in m).
  double tolerance = 1e-10;
  /// Nonlinear path only: events (stick, slip, reversal, a kink of a progressive spring) are
  /// located to within this time, s. Below resolvable_event_tolerance(duration) the
  /// simulation uses that limit instead and says so in its summary.
  double event_tolerance = 1e-12;
  /// Nonlinear path only: the most events a run records before it stops with NumericalError.
  /// Each event is held with the state after it: 16 bytes a DOF, and up to about 180 more for
  /// the event, its two vectors' heap headers and the list's spare capacity. Their number
  /// follows the motion, not the step count: the default, 10⁷, bounds that list to about
  /// 2.7 GB for 6 DOFs (a friction run has a few events a second).
  std::size_t max_events = 10'000'000;
  /// Returns false and explains in *why when an option is out of range: duration and time step
  /// positive, tolerances positive, final_speed finite and ≥ 0. Both paths check every option,
  /// also those only the nonlinear path reads. The rules that depend on the path or the sources
  /// (a speed with sources, a ramp, the step count) are the simulation's own.
  bool is_valid(std::string* why) const;
};

/// The finest event tolerance a run of `duration` seconds can honour, s: events are located in
/// absolute time t ≤ duration, where neighbouring doubles lie up to ε·duration apart
/// (ε = 2⁻⁵² ≈ 2.2e-16), so a finer tolerance cannot be met and an event search held to it
/// would stall between two neighbouring doubles (0.67 fs for a 3 s run).
double resolvable_event_tolerance(double duration);

/// The suspension nonlinearities a simulation follows; an effect left out is not built (the
/// element keeps its linear stiffness and the linear path runs when nothing is named).
struct NonlinearEffects {
  /// Leaf-spring friction R = c(1 ± φ)(f ± z) (springs digest §2.3): a friction force of φ
  /// times the spring's current elastic reaction against the sliding, and sticking (a dead
  /// zone) when the other forces stay within that band.
  bool leaf_friction = false;
  /// Progressive springs follow their load–deflection curve (SpringStage::curve).
  bool progressive_springs = false;
  /// Leaf friction as a constant Coulomb force φ·P₀ (P₀ the static load) instead of φ·R: the
  /// book's simplification 1 ± φ ≈ 1 of Example 3 (two-axle digest), for comparison with it.
  bool constant_friction = false;
  bool any() const { return leaf_friction || progressive_springs; }
};

/// A regime change of the nonlinear path.
struct SimulationEvent {
  enum class Kind { stick, slip, reversal, kink };
  double time = 0.0;  ///< s
  int element = 0;    ///< index into Vehicle::elements
  Kind kind = Kind::stick;
  /// The state just after the event (m or rad, m/s or rad/s, per DOF): the motion is smooth
  /// between events, so these points and the regular samples interpolate it piece by piece.
  Eigen::VectorXd displacement, velocity;
};
const char* to_string(SimulationEvent::Kind kind);  ///< "stick", "slip", "reversal", "kink"
/// Inverse of to_string; std::nullopt for an unknown word.
std::optional<SimulationEvent::Kind> simulation_event_kind_from_string(const std::string& word);

/// Sampled response: one row per time, one column per DOF.
struct TimeHistory {
  std::vector<std::string> labels;  ///< DOF labels, the columns
  Eigen::VectorXd time;             ///< s
  Eigen::MatrixXd displacement;     ///< m or rad
  Eigen::MatrixXd velocity;         ///< m/s or rad/s
  std::vector<SimulationEvent> events;  ///< nonlinear path: every regime change, in time order
  int steps_taken = 0;                  ///< integrator steps (nonlinear path), for cost reports
  /// The path and its integrator, the check that the history is finite (and, nonlinear, the
  /// steps and events) and the stage times.
  AnalysisSummary summary;
};

/// Receives a history's samples in time order as a simulation produces them, a block of
/// consecutive samples at a time, so that a long record can be written as it goes instead of
/// held whole (simulate_linear and simulate_nonlinear given a sink keep no samples).
class HistorySink {
 public:
  virtual ~HistorySink() = default;
  /// Called once, before any work on the samples: the DOF labels (the columns) and how many
  /// samples will come. A sink that cannot hold what it would need throws
  /// std::invalid_argument here, with its estimate, and the simulation stops.
  virtual void begin(const std::vector<std::string>& labels, Eigen::Index samples) = 0;
  /// One row per sample: times (s) and, per DOF, displacements (m or rad) and velocities
  /// (m/s or rad/s).
  virtual void write(const Eigen::Ref<const Eigen::VectorXd>& time,
                     const Eigen::Ref<const Eigen::MatrixXd>& displacement,
                     const Eigen::Ref<const Eigen::MatrixXd>& velocity) = 0;
};

/// Linear scene: the sources enter through their harmonic loads Σ_k Re(Q_k e^{iω_k t}) (as in
/// the harmonic response), the vehicle's viscous dampers through C. Throws std::invalid_argument
/// for invalid options (SimulationOptions::is_valid), a speed ramp, more than 1e8 steps, sources
/// without a positive speed, or initial conditions on unknown or massless DOFs.
TimeHistory simulate_linear(const LinearSystem& system, const std::vector<const ExcitationSource*>& sources,
                            const SimulationOptions& options);
/// The same, its samples given to `sink` as they are produced: the history returned holds the
/// labels and the summary, and no samples.
TimeHistory simulate_linear(const LinearSystem& system, const std::vector<const ExcitationSource*>& sources,
                            const SimulationOptions& options, HistorySink& sink);

/// Nonlinear scene: the linear model plus the named suspension nonlinearities of its vertical
/// elements, integrated by an adaptive Dormand–Prince 5(4) method whose steps end on the output
/// times and on located events, so that between events the motion is smooth and the Coulomb
/// decay of a leaf spring comes out to the tolerance (2φf/(1 ± φ) per half period, then rest in
/// the dead band). Stuck springs are constraints (their relative velocity is zero; the friction
/// force is what holds them, checked against φ times the elastic reaction); a leaf in series with
/// elastic stages is one element whose state is the leaf's own deflection, held while the force
/// through the pair stays within (1 ± φ) times the leaf's reaction.
/// Throws std::invalid_argument for invalid options (SimulationOptions::is_valid), more than 1e8
/// output steps, sources without a positive speed, a ramp without sources, and for what it
/// cannot model: two friction stages in one element, a progressive stage in series with other
/// stages, or massless degrees of freedom.
TimeHistory simulate_nonlinear(const LinearSystem& system, const std::vector<const ExcitationSource*>& sources,
                               const SimulationOptions& options, const NonlinearEffects& effects);
/// The same, its samples given to `sink` as they are produced: the history returned holds the
/// labels, events, step count and summary, and no samples.
TimeHistory simulate_nonlinear(const LinearSystem& system, const std::vector<const ExcitationSource*>& sources,
                               const SimulationOptions& options, const NonlinearEffects& effects, HistorySink& sink);

}  // namespace railmodal
