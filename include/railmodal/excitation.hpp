// Excitation sources: what the track and the running gear feed into a wagon at a speed.
//
//   #include <railmodal/railmodal.hpp>
//   #include <iostream>
//
//   int main() {
//     railmodal::WheelFlat flat;  // a 60 mm flat, 0.6 mm deep, on a 950 mm wheel
//     flat.wheel_diameter = 0.95;
//     flat.depth = 0.0006;
//     flat.length = 0.06;
//     flat.harmonics = 4;
//     auto source = railmodal::make_source(flat);
//     // harmonic k runs at k·V/(πD): the speed at which harmonic 2 meets a 4.38 Hz mode
//     std::cout << source->description() << ": " << source->speed_for(4.38, 2) * 3.6 << " km/h\n";
//   }
//
// Every source here is periodic along the track with a fundamental wavelength Λ (the rail
// length for joints, the wheel circumference πD for wheel defects and unbalance, the hunting
// wavelength for conicity), so harmonic k of a source runs at f = k·V/Λ and a mode of
// frequency f is excited at the critical speed V = Λ·f/k (V = L·f/k for joints, V = πD·f/k
// for wheel sources, V = λ·f for hunting). A source gives, for a speed and a harmonic, the
// input at every wheel with its time delay (displacement sources) or the forces on a body
// (unbalance), as complex amplitudes: a real signal is Re(A·e^{iωt}).
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <complex>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "railmodal/linear_system.hpp"

namespace railmodal {

/// Harmonic track displacement under one wheel: u(t) = Re(amplitude · e^{iω(t − delay_s)}).
struct WheelInput {
  int track_input = 0;  ///< index into LinearSystem::track_inputs
  /// (longitudinal, lateral, vertical) displacement, m; vertical positive up.
  Eigen::Vector3cd amplitude = Eigen::Vector3cd::Zero();
  /// Time after the leading wheel that this wheel meets the same point of the track, s.
  double delay_s = 0.0;
};

/// Harmonic force on a body at a point: F(t) = Re(amplitude · e^{iωt}), N.
struct PointForce {
  int body = 0;  ///< index into Vehicle::bodies
  Eigen::Vector3d point = Eigen::Vector3d::Zero();       ///< m, vehicle frame
  Eigen::Vector3cd amplitude = Eigen::Vector3cd::Zero();  ///< (longitudinal, lateral, vertical), N
};

/// One harmonic of one source at one speed.
struct HarmonicLoad {
  double frequency_hz = 0.0;
  std::vector<WheelInput> wheels;
  std::vector<PointForce> forces;
};

/// Complex generalised load Q over the system's degrees of freedom:
/// Q = Σ_wheels (K_u + iω C_u) u e^{−iωτ} + Σ_forces Gᵀ F.
Eigen::VectorXcd generalized_load(const LinearSystem& system, const HarmonicLoad& load);

/// A source harmonic's generalised load at any circular frequency ω of that harmonic:
/// Q(ω) = s(ω)·(stiffness_part + iω·damping_part), s = ExcitationSource::load_scale. Exact
/// for every source here: the phase between wheels, ω·τ = 2πk·(distance)/Λ, does not depend
/// on the speed, and the input amplitude depends on it only through s.
struct SeparableLoad {
  Eigen::VectorXcd stiffness_part;  ///< through the track elements' springs, plus point forces
  Eigen::VectorXcd damping_part;    ///< through the track elements' dampers
  double reference_omega = 0.0;     ///< ω at which the parts were taken
};

/// One excitation source (rail joints, wheel defects, hunting, unbalance).
class ExcitationSource {
 public:
  virtual ~ExcitationSource() = default;
  virtual std::string kind() const = 0;         ///< "rail_joints", "wheel_eccentricity", ...
  virtual std::string description() const = 0;  ///< one line with the parameters, for reports
  /// Fundamental wavelength along the track, m.
  virtual double wavelength() const = 0;
  /// Harmonics evaluated: 1 … harmonic_count().
  virtual int harmonic_count() const = 0;
  /// The input at `speed` (m/s, > 0 and finite) for `harmonic` (1-based); throws
  /// std::invalid_argument otherwise, and for a lateral input on a vehicle with wheelsets (it acts
  /// through the wheel–rail contact, which only the stability analysis models).
  HarmonicLoad load(const LinearSystem& system, double speed, int harmonic) const;

  /// Why the source cannot act on `system`: the key of its scene table to blame ("body",
  /// "phases") and the reason ("the vehicle has no body 'frame'"). load() throws
  /// std::invalid_argument then; check_scene_fits (scene.hpp) asks first, so that a scene's
  /// error names the key and its line.
  struct Misfit {
    std::string key;
    std::string reason;
  };
  virtual std::optional<Misfit> misfit(const LinearSystem& system) const {
    (void)system;
    return std::nullopt;
  }

  /// The load's split for fast sweeps over speed (see SeparableLoad).
  SeparableLoad separable_load(const LinearSystem& system, int harmonic) const;
  /// s(ω)/s(ω_ref): how the input amplitude scales with frequency (1 for a fixed profile,
  /// (ω/ω_ref)² for an unbalance, the track's ρ²/(ρ² − ω²) ratio for joints on elastic track).
  double load_scale(double omega, double reference_omega) const {
    double scale = 1.0;
    load_scales(&omega, 1, reference_omega, &scale);
    return scale;
  }
  /// load_scale at `count` frequencies `omega` into `out`: one call per block of a sweep
  /// rather than a virtual call per speed. The default is a fixed profile, s = 1.
  virtual void load_scales(const double* omega, int count, double reference_omega, double* out) const {
    (void)omega, (void)reference_omega;
    std::fill_n(out, count, 1.0);
  }

  double frequency_hz(double speed, int harmonic) const { return harmonic * speed / wavelength(); }
  /// The speed at which `harmonic` runs at `frequency_hz`: V = Λ·f/k.
  double speed_for(double frequency_hz, int harmonic) const {
    return frequency_hz * wavelength() / harmonic;
  }

 protected:
  /// load() after its checks.
  virtual HarmonicLoad load_at(const LinearSystem& system, double speed, int harmonic) const = 0;
};

/// Shape of a local dip (rail joint, wheel flat) of depth h and length l, centred on its
/// deepest point: cosine η = (h/2)(1 + cos 2πs/l) (the book's joint, eq. (163), when l is the
/// rail length; the sinusoidal flat, eq. (280)); triangular η = h(1 − 2|s|/l); parabolic
/// η = h(1 − 4s²/l²) (the parabolic flat, §2.10).
enum class DipShape { cosine, triangular, parabolic };
const char* to_string(DipShape shape);  ///< "cosine", "triangular", "parabolic"
/// Inverse of to_string; std::nullopt for an unknown word.
std::optional<DipShape> dip_shape_from_string(const std::string& word);

/// Complex amplitude of harmonic k (≥ 1) of a train of dips −η repeating every `period`,
/// the dip centred at s = 0: the profile is Σ_k Re(A_k e^{i2πks/period}). A_k is real.
double dip_harmonic(DipShape shape, double depth, double length, double period, int k);

/// Rail joints: a dip of depth 2a (the loaded dip at the joint relative to mid-rail, two-axle
/// digest §2.5) at every joint, on both rails; joints opposite (square) or staggered by half a
/// rail. Excites through the vertical stiffness of every track element.
struct RailJoints {
  double rail_length = 0.0;  ///< L, m
  bool staggered = false;
  double dip_depth = 0.0;    ///< 2a, m
  DipShape shape = DipShape::cosine;
  double dip_length = 0.0;   ///< m; 0: the whole rail (the book's cosine, eq. (163))
  int harmonics = 1;
  /// Optional track data (two-axle digest §2.5): K, the load per unit settlement under a
  /// wheel (N/m; the book's 22 000–57 000 kgf/cm), and m, the mass of half a wheelset (kg).
  /// With both the wheel follows the dip amplified by ρ²/(ρ² − n²), ρ = √(K/m), n = 2πkV/L
  /// (eq. (162) without its free term); without them, by 1 (the book's n² ≪ ρ², eq. (163)).
  double track_stiffness = 0.0;
  double half_wheelset_mass = 0.0;
  /// Where the track starts: the deepest point of the first joint (of the left rail when
  /// staggered) lies this far ahead of the leading wheelset at t = 0, m, in [0, L). 0: the
  /// leading wheelset stands on a joint; the joint reaches it at t = first_joint_at/V.
  double first_joint_at = 0.0;
  /// The rules make_source checks: L positive and finite, 2a finite and ≥ 0, the dip length
  /// from 0 to L, at least one harmonic, K and m both given (> 0) or neither, first_joint_at in
  /// [0, L). *why names the first field that breaks its rule and begins with the field's name
  /// (the scene file's key), as "dip_length cannot exceed the rail length".
  bool is_valid(std::string* why) const;
};

/// Wheelset eccentricity e: each wheelset's axle rises and falls e·sin(2πs/πD + ψᵢ)
/// (bogie-wagons-forced digest §2.9; the book's worst case has all ψᵢ = 0). An out-of-round
/// (polygonal) wheel with n lobes, radius R + e·sin(nθ + ψᵢ), is the same sinusoid at the
/// wavelength πD/n: n times the frequency of the wheel's turn.
struct WheelEccentricity {
  double wheel_diameter = 0.0;  ///< D, m
  double eccentricity = 0.0;    ///< e, m
  std::vector<double> phases;   ///< ψᵢ per wheelset from the front, rad (empty: all 0)
  int lobes = 1;                ///< n: 1 an eccentric wheel, 2 an oval, 3 a triangular one, …
  /// The rules make_source checks: D positive and finite, e finite and ≥ 0, finite phases, at
  /// least one lobe; *why begins with the name of the first field that breaks its rule.
  bool is_valid(std::string* why) const;
};

/// Wheel flats (or out-of-round) of depth a₁ and length l on every wheel, in phase, repeating
/// every revolution πD (bogie-wagons-forced digest §2.10, eqs. (280)–(283)).
struct WheelFlat {
  double wheel_diameter = 0.0;  ///< D, m
  double depth = 0.0;           ///< a₁, m
  double length = 0.0;          ///< l, m (≤ πD; πD is the book's whole-revolution case)
  DipShape shape = DipShape::cosine;
  int harmonics = 1;
  /// Where the flats are at t = 0: the angle every wheel turns before the middle of its flat
  /// meets the rail, rad, in [0, 2π); the flat arrives at t = flat_angle·D/(2V). 0: every flat
  /// on the rail at t = 0.
  double flat_angle = 0.0;
  /// The rules make_source checks: D positive and finite, a₁ finite and ≥ 0, l positive and at
  /// most πD, at least one harmonic, flat_angle in [0, 2π); *why begins with the name of the
  /// first field that breaks its rule.
  bool is_valid(std::string* why) const;
};

/// Kinematic hunting of conical treads: each wheelset moves laterally y₀ sin(2πs/λ), with
/// λ from Klingel's free wheelset, eq. (264b), λ = 2π√(s r/(2n)), or a rigid bogie of
/// wheelbase a, λ·√(1 + (a/s)²) (Rocard), or given (bogie-wagons-forced digest §2.1).
struct Hunting {
  enum class Model { free_wheelset, rigid_bogie, given } model = Model::free_wheelset;
  double conicity = 0.0;                ///< n, tread taper (1/20 = 0.05)
  double rolling_circle_spacing = 0.0;  ///< s, m
  double rolling_radius = 0.0;          ///< r, m
  double bogie_wheelbase = 0.0;         ///< the whole wheelbase 2a, m (rigid bogie; axles at ±a)
  double given_wavelength = 0.0;        ///< m (given)
  double amplitude = 0.0;               ///< y₀, m
  /// φ, rad, in [0, 2π): the leading wheelset's path is y₀ sin(2πs/λ + φ), s = V·t the
  /// distance run since t = 0 (0: on the track's centre line, moving left).
  double phase = 0.0;
  /// Optional data for Meineke's hunting-limit speed (267), reported beside the source.
  struct Meineke {
    double wheelbase = 0.0, diagonal = 0.0, clearance = 0.0, k = 0.0;  ///< a, d, 2σ (m); k
    int wheels = 0;                                                    ///< i
  };
  std::optional<Meineke> meineke;
};
const char* to_string(Hunting::Model model);  ///< "free_wheelset", "rigid_bogie", "given" (as in scene files)
/// Inverse of to_string; std::nullopt for an unknown word.
std::optional<Hunting::Model> hunting_model_from_string(const std::string& word);

/// Klingel's wavelength of a free wheelset, eq. (264b): λ = 2π√(s r / (2n)).
double klingel_wavelength(double conicity, double rolling_circle_spacing, double rolling_radius);
/// Rocard's wavelength of a rigid bogie of wheelbase a: λ_Klingel · √(1 + (a/s)²).
double rigid_bogie_wavelength(double conicity, double rolling_circle_spacing, double rolling_radius,
                              double wheelbase);
/// Meineke's hunting-limit speed, eq. (267), km/h: (1.33 a/d + 0.67)·a·k / (2σ √i) with the
/// wheelbase a and diagonal d (m), clearance 2σ (m), i wheels and k the empirical constant
/// (0.5 wagons, 0.63 locomotives, 1.0 bogies).
double meineke_hunting_speed_kmh(double wheelbase, double diagonal, double clearance, int wheels,
                                 double k);

/// Unbalanced running gear: rotating unbalances m·ρ on wheels and, for a locomotive, the
/// reciprocating masses of its cranks (unbalance-excitation digest §2.2, §3). Forces act on
/// the named body at the wheel positions and grow with ω² = (2V/D)².
struct Unbalance {
  struct Rotating {
    double x = 0.0, y = 0.0, z = 0.0;  ///< where the force acts, m (vehicle frame)
    double mass_radius = 0.0;          ///< m·ρ, kg·m
    double phase = 0.0;                ///< rad; the force is vertical m ρ ω² sin(ωt + φ),
                                       ///< longitudinal m ρ ω² cos(ωt + φ)
  };
  struct Reciprocating {
    double x = 0.0, y = 0.0, z = 0.0;  ///< crosshead guide, m
    double mass = 0.0;                 ///< reciprocating mass, kg
    double crank_radius = 0.0;         ///< r, m
    double rod_ratio = 0.0;            ///< λ = r/L
    double phase = 0.0;                ///< crank angle at t = 0, rad (90° between sides)
  };
  std::string body;
  double wheel_diameter = 0.0;  ///< D, m
  std::vector<Rotating> rotating;
  std::vector<Reciprocating> reciprocating;
  int harmonics = 2;
};

/// Coefficient Aₙ of the reciprocating inertia force X = m r ω² Σ Aₙ cos nθ of a crank of
/// rod ratio λ = r/L, from the exact crank–rod kinematics (unbalance digest §2.2): A₁ = 1,
/// A₂ ≈ λ + λ³/4 + 15λ⁵/128 (Kvasnikov's series), A₄ ≈ −(λ³/4 + 3λ⁵/16), odd n > 1 zero.
double reciprocating_coefficient(double rod_ratio, int order);

/// The track and wheel sources; each throws std::invalid_argument ("rail joints: " + why, and so
/// on) when its description breaks the rules of its is_valid.
std::unique_ptr<ExcitationSource> make_source(const RailJoints& joints);
std::unique_ptr<ExcitationSource> make_source(const WheelEccentricity& eccentricity);
std::unique_ptr<ExcitationSource> make_source(const WheelFlat& flat);
std::unique_ptr<ExcitationSource> make_source(const Hunting& hunting);
/// The body is looked up by name when loads are made (std::invalid_argument if absent).
std::unique_ptr<ExcitationSource> make_source(const Unbalance& unbalance);

}  // namespace railmodal
