// railmodal — vehicle description: rigid bodies joined by suspension elements.
//
// Everything here is SI (kg, m, s, N, rad); units are converted when a file is read.
// Vehicle frame: x forward, y to the left, z up, origin on the track centre line in the
// plane of the wheelset axles.
//
// Example (a single body on four springs, the book's two-axle wagon reduced to essentials):
//
//   #include <railmodal/railmodal.hpp>
//   #include <iostream>
//
//   int main() {
//     railmodal::Vehicle v;
//     railmodal::Body body;
//     body.name = "body";
//     body.mass = 20000.0;
//     body.inertia = {3.0e4, 1.2e5, 1.2e5};
//     body.centre_of_gravity = {0.0, 0.0, 1.0};
//     body.reference_point = {0.0, 0.0, 0.0};  // pitch and roll about the axle plane
//     body.held = {railmodal::Motion::lateral, railmodal::Motion::yaw};
//     body.longitudinal_free = false;  // the default: surge held, pitch about the reference point
//     v.bodies.push_back(body);
//     for (double x : {-1.9, 1.9})
//       for (double y : {-0.8, 0.8}) {
//         railmodal::Element e;
//         e.name = "spring";
//         e.upper = "body";  // lower = "" : the track / wheelsets
//         e.point = {x, y, 0.0};
//         e.vertical_stages = {{"leaf", 9.0e5, 1}};
//         v.elements.push_back(e);
//       }
//     auto system = railmodal::assemble(v, railmodal::DofSet::all);
//     for (const auto& mode : railmodal::solve_modes(system).modes)
//       std::cout << mode.name << "  " << mode.frequency_hz << " Hz\n";
//   }
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

namespace railmodal {

/// The motions of a body's reference point. Longitudinal motion (surge) is held unless the
/// body frees it (Body::longitudinal_free): the book's wagons are held longitudinally by the
/// axlebox guides and draw gear, and their pitch is taken about the reference point.
/// `bending` is not a motion of the reference point but the amplitude of the body's first
/// vertical bending mode (Body::bending), a degree of freedom "<body>.bending" only of a body
/// that carries one; it cannot be held.
enum class Motion { lateral, bounce, roll, pitch, yaw, longitudinal, bending };

/// "lateral", "bounce", "roll", "pitch", "yaw", "longitudinal", "bending".
const char* to_string(Motion motion);
/// Inverse of to_string; returns std::nullopt for an unknown word.
std::optional<Motion> motion_from_string(const std::string& word);

/// The first vertical bending mode of a body: a free–free Euler–Bernoulli beam of length L lying
/// along x, centred at `centre`, whose deflection is w(x, t) = φ(x)·q(t). The mode shape is the
/// closed form of the free–free beam (β₁L = 4.730040745: Blevins 1979 Table 8-1; Thomson and
/// Dahleh 1998 Appendix D), normalised to φ = 1 at the beam's ends, so q is the ends' vertical
/// displacement (m) relative to the rigid motion, positive up; the centre then moves −0.6078·q,
/// and the nodes are 0.2242·L from each end. The mode is given by exactly one of `beam` (a
/// uniform beam: the frequency and modal mass follow) and `mode` (the frequency and modal mass
/// directly). docs/ride.md, "Car-body bending", says what the model takes in and leaves out.
struct BodyBending {
  /// A uniform beam: f = (β₁L)² / (2π L²) · √(EI / m'), modal mass m'·L/4 (for φ = 1 at the ends).
  struct Beam {
    double bending_stiffness = 0.0;  ///< EI, N·m², > 0
    double mass_per_length = 0.0;    ///< m', kg/m, > 0
  };
  /// The mode itself, as measured or computed elsewhere.
  struct Mode {
    double frequency = 0.0;   ///< f_b, Hz, > 0: the free–free body's first bending frequency
    double modal_mass = 0.0;  ///< m_b, kg, > 0: ∫ m(x) φ(x)² dx with φ = 1 at the beam's ends
  };
  double length = 0.0;  ///< L, m, > 0
  /// x of the beam's centre, m (vehicle frame); none: the body's centre of gravity.
  std::optional<double> centre;
  std::optional<Beam> beam;
  std::optional<Mode> mode;
  double damping_ratio = 0.0;  ///< ζ, modal: 0 ≤ ζ < 1 (C gains 2ζω_b·m_b)
};

/// A rigid body: car body, bogie frame, bolster, locomotive frame, ...
struct Body {
  std::string name;
  double mass = 0.0;                     ///< kg, > 0
  Eigen::Vector3d inertia{0.0, 0.0, 0.0};  ///< roll, pitch, yaw moments of inertia about the
                                           ///< centre of gravity, kg·m² (0 allowed: that
                                           ///< rotation is massless and condensed statically)
  Eigen::Vector3d centre_of_gravity{0.0, 0.0, 0.0};  ///< m, vehicle frame
  /// Point whose translation and rotation are the body's degrees of freedom: the book's
  /// centre of oscillation (two-axle wagon: axle plane below the CG; bogie wagon body: the
  /// plane of the bolster spring clamps). It does not change the physics, only the
  /// coordinates in which mode shapes are reported and which motions "held" restrains.
  Eigen::Vector3d reference_point{0.0, 0.0, 0.0};
  /// Motions of the reference point held rigidly against the track (axlebox guides,
  /// side bearers): those degrees of freedom are removed.
  std::vector<Motion> held;
  /// Whether the reference point moves longitudinally (a degree of freedom "<name>.longitudinal",
  /// resisted by the elements' longitudinal stages and damping: draw gear, traction rods,
  /// axlebox guides). Held by default: pitch is then about the reference point, with the
  /// inertia J + m·d² of a CG a height d above it; freed, the results do not depend on where
  /// the reference point is.
  bool longitudinal_free = false;
  /// The body's first vertical bending mode (a degree of freedom "<name>.bending"); none: the
  /// body is rigid, and nothing it takes part in changes.
  std::optional<BodyBending> bending;
  /// z of the body's floor, m (vehicle frame: above the plane of the axles, not the rail): where
  /// default_ride_outputs (ride.hpp) puts its floor points. None: the floor is not given, and
  /// those points lie at the reference point's height, which the ride's notes then say.
  std::optional<double> floor_height;
};

/// Load–deflection curve of one progressive spring (the Khanin conical spring, springs digest
/// Example 10): piecewise linear through the points, deflection from the unloaded spring.
struct LoadDeflectionCurve {
  std::vector<double> deflection;  ///< m, increasing from 0
  std::vector<double> load;        ///< N, increasing from 0
  /// Load at deflection d; beyond the last point the last segment continues.
  double load_at(double d) const;
  /// Deflection under load p (the inverse).
  double deflection_at(double p) const;
  /// Slope of the segment that carries load p (at a kink: the stiffer segment above it).
  double stiffness_at(double p) const;
};

/// One stage of springs in parallel: `count` identical springs of `stiffness` each. Different
/// springs side by side (a file's `parallel = [...]`, nested coils) are one spring whose
/// stiffness is their sum.
struct SpringStage {
  std::string kind;        ///< "leaf", "coil", "elliptic", "direct", ... (for reports)
  double stiffness = 0.0;  ///< N/m, of one spring (of one set of different springs)
  int count = 1;           ///< identical springs side by side in this stage
  /// Relative friction coefficient φ of a leaf spring (Marié): the friction force as a
  /// fraction of the load the spring carries, R = c(1 ± φ)(f ± z) (springs digest §2.3).
  /// Not in the linear matrices; it decides whether friction stops a resonance.
  double relative_friction = 0.0;
  /// A progressive spring's curve (empty: linear). `stiffness` is then its tangent at the
  /// carried load, used by every linear analysis; the scene effect "progressive_springs" makes
  /// the simulation follow the whole curve.
  std::optional<LoadDeflectionCurve> curve = std::nullopt;
};

/// Cradle swing hangers carrying the element's vertical load: a pendulum whose lateral
/// restoring stiffness is load / (length · cos inclination) (bogie-wagons-natural digest
/// §2.8, N = P3/(λ cos α); two-axle digest (189) for small x).
struct SwingHanger {
  double length = 0.0;       ///< λ, m
  double inclination = 0.0;  ///< α, rad, to the vertical in the mid position
};

/// A damper in series with a spring (a yaw damper and its rubber end bushes): it carries no
/// static load and gives no static stiffness; at low frequency it is a damper, at high frequency
/// the spring. Each one adds a first-order state (the damper force F) to the equations:
/// Ḟ = k·(ṡ − F/c) with s the stretch of the element along `direction`.
struct SeriesDamper {
  Motion direction = Motion::longitudinal;  ///< longitudinal, lateral or bounce (vertical)
  double damping = 0.0;                     ///< c, N·s/m, > 0
  double stiffness = 0.0;                   ///< k of the series spring, N/m, > 0
};

/// A suspension element acting at one point between two bodies, or between a body and the
/// track (lower = ""). Stages act in series (leaf spring in series with coil springs is the
/// book's "double suspension"). The element's static vertical load follows from the static
/// equilibrium of the assembled vehicle under gravity.
struct Element {
  std::string name;
  std::string lower;  ///< body name, or "" for the track / wheelsets (rigid ground)
  std::string upper;  ///< body name
  Eigen::Vector3d point{0.0, 0.0, 0.0};  ///< m, vehicle frame
  std::vector<SpringStage> vertical_stages;  ///< in series; empty: no vertical stiffness
  std::vector<SpringStage> lateral_stages;   ///< in series; empty: no lateral stiffness
  /// In series; resists the longitudinal motion of the point: what yaw and pitch give it, and
  /// the longitudinal motion of a body that frees it (a spring a height h below the reference
  /// point couples that body's surge and pitch).
  std::vector<SpringStage> longitudinal_stages;
  std::optional<SwingHanger> hanger;  ///< lateral pendulum stiffness, in series with the
                                      ///< lateral stages when both are given
  /// Roll, pitch and yaw stiffness against the relative rotation of the two bodies, N·m/rad
  /// (an anti-roll bar is a roll stiffness between body and bogie).
  Eigen::Vector3d rotational_stiffness{0.0, 0.0, 0.0};
  double vertical_damping = 0.0;      ///< N·s/m (viscous; carried in C)
  double lateral_damping = 0.0;       ///< N·s/m
  double longitudinal_damping = 0.0;  ///< N·s/m
  /// Dampers with a spring in series, acting on the same relative motion of the point. Only the
  /// hunting-stability analysis represents them; the undamped modes leave them out (they carry
  /// no static force), and the analyses that cannot represent them refuse the vehicle.
  std::vector<SeriesDamper> series_dampers;
};

/// Kalker's linear creep coefficients of one wheel–rail contact: the creep forces per unit
/// creepage, F_x = −f11·ξ_x, F_y = −f22·ξ_y − f23·ξ_sp, M_z = f23·ξ_y − f33·ξ_sp (ξ_sp the
/// spin creepage, 1/m). f11 = G·a·b·C11, f22 = G·a·b·C22, f23 = G·(ab)^{3/2}·C23,
/// f33 = G·(ab)²·C33 (Kalker 1967; Knothe and Stichel, Rail Vehicle Dynamics, 2017, §4.3).
struct CreepCoefficients {
  double f11 = 0.0;  ///< longitudinal, N
  double f22 = 0.0;  ///< lateral, N
  double f23 = 0.0;  ///< lateral–spin, N·m
  double f33 = 0.0;  ///< spin, N·m²
};

/// What Hertz's theory needs to size the contact ellipse of one wheel on its rail, and the
/// material for Kalker's coefficients.
struct HertzContactInput {
  /// Normal load on one wheel, N; none: half the wheelset's static axle load (its weight and
  /// the static loads of the elements it carries).
  std::optional<double> wheel_load;
  /// Transverse radius of the wheel tread profile at the contact, m: positive convex, negative
  /// concave (a worn, hollow tread); none: a straight (conical) tread. The wheel's radius in the
  /// rolling direction is the wheelset's rolling radius r0.
  std::optional<double> wheel_transverse_radius;
  double rail_head_radius = 0.0;  ///< transverse radius of the rail head, m, > 0
  double youngs_modulus = 2.1e11;  ///< E, Pa (wheel and rail of one steel)
  double poisson_ratio = 0.28;     ///< ν
};

/// The linearised wheel–rail contact of one wheelset (docs/stability.md derives its terms).
struct WheelRailContact {
  double rolling_radius = 0.0;        ///< r0, m: nominal rolling radius of the wheels
  double contact_half_spacing = 0.0;  ///< l0, m: half the lateral distance between the contact points
  double conicity = 0.0;              ///< λ: equivalent conicity (≥ 0)
  /// ε: contact-angle parameter (the gravitational stiffness is W·ε/l0); none: the value for
  /// conical wheels on knife-edge rails (docs/stability.md says which).
  std::optional<double> contact_angle_parameter;
  /// σ: roll parameter (its definition and the terms it enters are in docs/stability.md);
  /// none: the value for conical wheels on knife-edge rails.
  std::optional<double> roll_parameter;
  /// W, N: the load the rails carry under this wheelset (its weight and all it carries); it sets
  /// the gravitational stiffness W·ε/l0 and the Hertz wheel load's default W/2. None: the
  /// wheelset's weight plus the static loads of the system's elements standing on it (only the
  /// wheelset's own weight when nothing stands on it, e.g. springs to a fixed frame).
  std::optional<double> axle_load;
  /// Exactly one of the two: the creep coefficients given directly (per wheel), or the Hertz
  /// contact they are computed from.
  std::optional<CreepCoefficients> creep;
  std::optional<HertzContactInput> hertz;
};

/// A wheelset on the rails: a Body (mass, roll and yaw inertia, its lateral and yaw motions
/// free; its bounce, roll and pitch held, since in the linear model they follow the rails) with
/// the contact that ties it to the track and the spin inertia that gives the gyroscopic terms.
struct Wheelset {
  std::string body;           ///< name of the Body that is the wheelset
  double spin_inertia = 0.0;  ///< I_y about the axle, kg·m² (≥ 0)
  WheelRailContact contact;
};

/// A vehicle: bodies, elements and the gravity they stand in.
struct Vehicle {
  std::string name;
  std::string source;  ///< file it was read from, or "" when built in code
  double gravity = 9.81;  ///< m/s²; the book uses g = 981 cm/s²
  std::vector<Body> bodies;
  std::vector<Element> elements;
  /// The bodies that are wheelsets on the rails; empty for the book's wagons, whose axles are
  /// the track (elements with lower = "").
  std::vector<Wheelset> wheelsets;
};

/// Combined stiffness of stages in series (each stage = count springs in parallel), N/m.
/// Returns 0 for no stages.
double series_stiffness(const std::vector<SpringStage>& stages);

}  // namespace railmodal
