// railmodal — the steam locomotive's driving gear as a mechanism: the exact inertia forces of
// crank, connecting rod and crosshead at any crank angle, their harmonics, the dynamic wheel
// loads ("hammer blow") with the overload coefficient α, and the engine's surging force and
// nosing moment. Sources: Zhdanov, «Уравновешивание движущего механизма паровоза», 1937;
// Kvasnikov, «Определение неуравновешенности поршневых машин», 1920 (digest
// shared/reference/unbalance-excitation.md). docs/driving_gear.md states the conventions with a
// figure and every equation.
//
//   #include <railmodal/railmodal.hpp>
//   #include <cmath>
//   #include <iostream>
//
//   int main() {
//     // One side of the Су (Zhdanov, Table 4): r = 0.35 m, L = 2.35 m, rod 225.28 kg with its
//     // centre of mass 1.5575 m from the crosshead pin and J = 71.665 kgf·m·s² about that pin.
//     railmodal::GearCylinder right;
//     right.name = "right";
//     right.lateral = 1.14;
//     right.crank_radius = 0.35;
//     right.rod_length = 2.35;
//     right.rod_mass = 225.28;
//     right.rod_centre_of_mass = 1.5575;
//     right.rod_inertia = railmodal::rod_inertia_about_centre(71.665 * 9.81, 225.28, 1.5575);
//     right.reciprocating_mass = 365.75;
//     railmodal::GearCylinder left = right;
//     left.name = "left";
//     left.lateral = -1.14;
//     left.crank_offset = -M_PI / 2;  // the left crank lags the right by 90°
//     railmodal::DrivingGear gear;
//     gear.wheel_diameter = 1.85;
//     gear.wheel_plane_half_spacing = 0.795;
//     gear.cylinders = {right, left};
//     gear.axles.resize(1);
//     gear.axles[0].name = "driving";
//     gear.axles[0].crank_radius = 0.35;
//     gear.axles[0].right.static_load = gear.axles[0].left.static_load = 9000 * 9.81;
//     gear.axles[0].left.crank_offset = -M_PI / 2;
//     railmodal::GearResult r = railmodal::solve_driving_gear(gear, 100 / 3.6);
//     // the crank-pin force of the right rod at 90°, in kgf: Y = 4402 (the exact solution)
//     std::cout << r.states[90].cylinders[0].vertical / 9.81 << " kgf; alpha "
//               << r.wheels[0].alpha << (r.wheels[0].wheel_lift ? " (wheel lift)" : "") << "\n";
//     return r.summary.passed() ? 0 : 1;
//   }
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "railmodal/summary.hpp"

namespace railmodal {

class ExcitationSource;  // excitation.hpp

/// Which way the wheels turn. Every force is a function of the mechanism's configuration
/// (steady rotation: the accelerations go with ω²), so the tables against crank angle, α,
/// surging and nosing are the same either way; the direction only sets how the crank angle
/// runs in time, φ(t) = φ₀ ± ωt, which the excitation (GearExcitation) uses.
enum class GearRotation { forward, backward };
const char* to_string(GearRotation rotation);  ///< "forward", "backward"
/// Inverse of to_string; std::nullopt for an unknown word.
std::optional<GearRotation> gear_rotation_from_string(const std::string& word);

/// One cylinder with its crank, connecting (main) rod and crosshead. Frame (docs/driving_gear.md):
/// x forward (toward the cylinder, which lies ahead of its driving axle), y up; the crank angle
/// φ is Zhdanov's, measured from the rear dead centre (crank pin behind the axle, on the
/// cylinder axis) in the direction of rotation when running forward, so at φ = 90° the crank
/// pin is at the top. The cylinder axis passes through the axle centre (no inclination).
struct GearCylinder {
  std::string name;
  double lateral = 0.0;  ///< m, the rod plane from the engine's centreline, + right
  /// rad, this crank's angle when the reference crank (φ) is at 0, running forward; + leads.
  /// Two cylinders at 90° with the right leading: right 0, left −π/2.
  double crank_offset = 0.0;
  int axle = 0;                   ///< index into DrivingGear::axles of the axle it drives
  double crank_radius = 0.0;      ///< r, m (half the stroke)
  double rod_length = 0.0;        ///< L, m, between crank-pin and crosshead-pin centres
  double rod_mass = 0.0;          ///< kg
  double rod_centre_of_mass = 0.0;  ///< d, m, from the crosshead pin along the rod (0 ≤ d ≤ L)
  double rod_inertia = 0.0;       ///< J_G, kg·m², about the rod's centre of mass (≥ 0)
  double reciprocating_mass = 0.0;  ///< piston, piston rod and crosshead, kg
};

/// J_G = J_P − m·e²: the moment of inertia about the centre of mass from the one about a
/// point P at distance e from it (parallel axes; Zhdanov gives J about the crosshead pin).
double rod_inertia_about_centre(double inertia_about_point, double mass, double distance);
/// Kvasnikov's H = m·s_a·s_b − J_G (eq. (24)–(26)): zero for a rod that is dynamically two
/// masses at its pins, J_G = m·d·(L − d).
double rod_dynamic_defect(const GearCylinder& cylinder);

/// A mass turning with one wheel: crank-pin bosses, crank webs, coupling-rod shares, counter-
/// cranks, counterweights.
struct RotatingMass {
  std::string name;
  double mass = 0.0;    ///< kg (≥ 0)
  double radius = 0.0;  ///< m, of its centre of mass from the axle (≥ 0)
  /// rad, ahead of this wheel's crank in the direction of rotation (0 = on the crank, π = opposite).
  double angle = 0.0;
  /// m, its plane from the wheel's counterweight plane, + outward (a crank pin outside the wheel).
  double plane_offset = 0.0;
  /// True for the part of a counterweight that balances reciprocating mass (Zhdanov's
  /// overbalance Q_в): GearWheelLoad::alpha_89a adds its hammer blow as eq. (89a) does.
  bool overbalance = false;
};

/// One wheel (one side of one axle).
struct GearWheel {
  double static_load = 0.0;  ///< П, N: the static wheel load on the rail (> 0)
  /// rad, this wheel's crank when the reference crank is at 0, running forward (as
  /// GearCylinder::crank_offset; the left wheels of a two-cylinder engine −π/2).
  double crank_offset = 0.0;
  std::vector<RotatingMass> masses;
};

/// One axle: the driving axle or a coupled one.
struct GearAxle {
  std::string name;
  double position = 0.0;      ///< m, along the engine (reported, for pitch later)
  double crank_radius = 0.0;  ///< m, the radius masses are reduced to (G_r = G·ρ/r)
  GearWheel right, left;
};

/// The driving gear of an engine.
struct DrivingGear {
  std::string name;             ///< for reports
  std::string source;           ///< the file it was read from ("" when built in code)
  double design_speed = 0.0;    ///< m/s, the speed balancing is done for (0: not stated)
  double wheel_diameter = 0.0;  ///< D, m, of the coupled wheels on the rolling circle
  /// S, m: the wheels' counterweight planes at ±S from the centreline (Zhdanov 2S = 1.59 m).
  double wheel_plane_half_spacing = 0.0;
  GearRotation rotation = GearRotation::forward;
  std::vector<GearCylinder> cylinders;
  std::vector<GearAxle> axles;
  /// Names the first field that breaks its rule (positive lengths, d within the rod, r < L,
  /// a cylinder's axle in range, finite numbers, static loads > 0).
  bool is_valid(std::string* why) const;
};

/// Positions, velocities and accelerations of one crank mechanism at crank angle φ and steady
/// angular velocity ω (x forward, y up, crank centre at the origin), from the exact geometry.
struct CrankKinematics {
  double crank_angle = 0.0;                    ///< φ of this crank, rad
  double crank_pin_x = 0.0, crank_pin_y = 0.0;  ///< A = (−r cos φ, r sin φ), m
  double crosshead_x = 0.0;                    ///< x_B = −r cos φ + L cos β, m (y_B = 0)
  double crosshead_velocity = 0.0;             ///< dx_B/dt, m/s
  double crosshead_acceleration = 0.0;         ///< d²x_B/dt², m/s²
  double rod_angle = 0.0;                      ///< β, sin β = λ sin φ, rad
  double rod_angular_velocity = 0.0;           ///< dβ/dt, rad/s
  double rod_angular_acceleration = 0.0;       ///< d²β/dt², rad/s²
};
/// The exact kinematics (throws std::invalid_argument for r ≥ L or a non-positive length).
CrankKinematics crank_kinematics(const GearCylinder& cylinder, double crank_angle, double omega);

/// The inertia forces of one mechanism at one crank angle (Newton–Euler on rod and crosshead).
struct RodForces {
  double crank_angle = 0.0;  ///< φ of this crank, rad
  /// X, N: horizontal force of rod and reciprocating parts on the crank pin, + forward
  /// (Zhdanov's X, eq. (33)); inertia only.
  double horizontal = 0.0;
  /// Y, N: vertical force on the crank pin, + up (eq. (39)–(40)); inertia only: the rod's
  /// static weight share on the pin, m·g·d/L, is left out as the book leaves it out.
  double vertical = 0.0;
  /// Z, N: vertical force of the crosshead on the guide bars, + up (eq. (41)–(43)), with the
  /// weight of crosshead group and rod share, −(m_k + m(1 − d/L))·g, as the book gives it:
  /// Z < 0 presses the lower bar.
  double guide = 0.0;
};
/// g = 9.81 m/s² in `guide` (the digest's value).
RodForces rod_forces(const GearCylinder& cylinder, double crank_angle, double omega);

/// One harmonic k of a periodic quantity q(φ) = Σ_k (cosine_k cos kφ + sine_k sin kφ), φ the
/// reference crank angle.
struct GearHarmonic {
  int order = 0;        ///< k (0 = the mean)
  double cosine = 0.0;  ///< a_k, in the quantity's unit
  double sine = 0.0;    ///< b_k
  double amplitude() const;  ///< √(a_k² + b_k²)
};

/// The state of the whole gear at one reference crank angle.
struct GearState {
  double crank_angle = 0.0;             ///< φ of the reference crank, rad
  std::vector<RodForces> cylinders;     ///< per GearCylinder, at its own crank angle
  /// Per wheel (axle-major: axle i right at 2i, left at 2i+1): the dynamic wheel load ΔP, N,
  /// + pressing the rail: minus the vertical inertia forces the wheel carries (its cylinders'
  /// Y moved to the wheel planes, its masses' centrifugal forces).
  std::vector<double> wheel_loads;
  double surging = 0.0;  ///< ΣX, N, + forward (eq. (94)/(96)): every horizontal force
  double nosing = 0.0;   ///< ΣMX, N·m, + turning the engine to the right (eq. (95)/(97))
};

/// Per wheel over the revolution. Extremes are taken over the GearOptions::steps crank angles
/// (1° steps: within 1 − cos 0.5° = 3.8e-5 of a sine's continuous peak).
struct GearWheelLoad {
  int axle = 0;
  bool right = true;
  std::string wheel;  ///< as the reports name it: its axle's name and side, "coupled 1 R"
  double static_load = 0.0;        ///< П, N
  double max_dynamic_load = 0.0;   ///< max ΔP, N
  double min_dynamic_load = 0.0;   ///< min ΔP, N (the least wheel load is П + this)
  /// α = max|ΔP|/П (eq. (78) taken over every mass of the wheel): the overload coefficient.
  double alpha = 0.0;
  /// α as eq. (89a) writes it: (max|ΔP without the overbalance| + the overbalance's
  /// vertical amplitude)/П. The two peaks need not meet, so alpha_89a ≥ alpha.
  double alpha_89a = 0.0;
  bool wheel_lift = false;  ///< α ≥ 1: the book's flag (the least load П + min ΔP may still be > 0)
  std::vector<GearHarmonic> harmonics;  ///< of ΔP, N, orders 0 … GearOptions::harmonics
};

struct GearOptions {
  int steps = 360;      ///< crank angles per revolution, ≥ 8 (360: 1° steps, the tables' 15° among them)
  int harmonics = 6;    ///< highest order of the harmonics, 1 … steps/2 − 1
  bool is_valid(std::string* why) const;
};

struct GearResult {
  double speed = 0.0;         ///< m/s
  double omega = 0.0;         ///< ω = 2V/D, rad/s
  double frequency_hz = 0.0;  ///< f₁ = V/(πD)
  std::vector<GearState> states;  ///< steps states, φ = 2π·i/steps
  /// Per cylinder: harmonics of X, Y and Z in N, orders 0 … harmonics, in the reference angle.
  std::vector<std::vector<GearHarmonic>> horizontal_harmonics, vertical_harmonics, guide_harmonics;
  std::vector<GearWheelLoad> wheels;  ///< axle-major, right then left
  std::vector<GearHarmonic> surging_harmonics;  ///< of ΣX, N
  std::vector<GearHarmonic> nosing_harmonics;   ///< of ΣMX, N·m
  double max_surging = 0.0;  ///< max |ΣX|, N
  double max_nosing = 0.0;   ///< max |ΣMX|, N·m
  /// Harmonics by a discrete Fourier sum over the steps (each force is an analytic periodic
  /// function of φ, so the sum is exact to aliasing of order λ^(steps − k)); the checks: the
  /// largest error of the synthesis from the harmonics against the sampled forces, relative.
  AnalysisSummary summary;
};

/// The forces at `speed` (m/s, > 0) over one revolution. Throws std::invalid_argument for an
/// invalid gear (DrivingGear::is_valid) or options ("GearOptions: ...").
GearResult solve_driving_gear(const DrivingGear& gear, double speed, const GearOptions& options = {});

/// The [driving_gear] table of a TOML file (a vehicle file or a locomotive file such as
/// data/locomotives/su.toml; docs/driving_gear.md, "Input"), with units converted to SI. Other
/// tables of the file are not read here. Throws InputError naming file, line, column and key.
DrivingGear load_driving_gear(const std::string& path);

/// The speed at which an overload coefficient `alpha` found at `speed` reaches `limit`: every
/// force grows as V², so V·√(limit/α) (+∞ for α = 0).
double speed_at_alpha(double alpha, double speed, double limit);

/// The driving gear as the unbalance excitation of a vehicle (scene kind "driving_gear";
/// docs/driving_gear.md, "As an excitation"): harmonic k of the exact forces above at k times
/// the wheels' turning frequency V/(πD), growing as V². Vertical forces of an axle (its rods'
/// Y at the crank pins, its wheels' masses) act on the body named for that axle (a wheelset or
/// other unsprung body) or else on `body`; horizontal forces (X, the masses') and the guide-bar
/// force Z act on `body`, the frame that carries axleboxes and guides, so surging moves it
/// through its longitudinal degree of freedom where it frees one (Body::longitudinal_free).
/// Points in the vehicle frame (x forward, y left, z up from the axle plane): an axle's forces
/// at (x, ∓(lateral), 0) of its crank pins and wheels, Z at the middle of the crosshead's stroke,
/// L ahead of the axle. The more numerous `Unbalance` of excitation.hpp stays the simple form.
struct GearExcitation {
  DrivingGear gear;
  std::string body = "body";  ///< the frame
  struct AxlePlace {
    double x = 0.0;    ///< m, the axle's position along the vehicle frame
    std::string body;  ///< the body its vertical forces act on; "" = `body`
  };
  /// Per DrivingGear::axles, in order; empty: x = GearAxle::position, every force on `body`.
  std::vector<AxlePlace> axles;
  /// φ₀, rad: the reference crank's angle at t = 0 (Zhdanov's, docs/driving_gear.md); the
  /// crank angle runs as φ(t) = φ₀ + ωt forward, φ₀ − ωt backward (DrivingGear::rotation).
  double crank_angle = 0.0;
  /// Orders 1 … harmonics. 3, as a scene's `harmonics` defaults to: the second is what the
  /// counterweights cannot balance, and the third of the rods' Y and Z (about 1.5 kN each for
  /// the Су at 100 km/h) does not cancel between cranks at 90°, as the second does in surge and
  /// bounce.
  int harmonics = 3;
};
/// Throws std::invalid_argument for an invalid gear, harmonics < 1, or axles not matching the
/// gear's. The bodies are looked up when loads are made (ExcitationSource::misfit).
std::unique_ptr<ExcitationSource> make_source(const GearExcitation& excitation);

}  // namespace railmodal
