// Names a mode from where its kinetic energy sits, and finds its centre of oscillation.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <complex>
#include <optional>
#include <string>
#include <vector>

#include "railmodal/linear_system.hpp"
#include "railmodal/modal.hpp"
#include "model/rigid_body.hpp"

namespace railmodal::solve {

/// Names the modes of one system. What the names need of the system alone (each body's family
/// and whether it has a twin, its CG's point map, which of its motions are DOFs) is worked out
/// once, not per mode and body (a study names six modes of each of its 10⁵ variants). The
/// system must outlive the namer.
///
/// describe() describes a mode shape over system.dofs (all entries, condensed ones
/// recovered); `repeated`: the mode shares its eigenvalue with another (Mode::repeated). It
/// writes the name into `name` (its storage reused: a study's worker names its modes into the
/// previous variant's) and sets or clears `centre`.
///
/// The kinetic energy of each body is split at its centre of gravity into translation
/// (lateral, vertical, longitudinal) and rotation (roll, pitch, yaw), terms that cannot be
/// negative. The body with the most energy names the mode; its leading motion gives the
/// word: bounce, pitch (longitudinal CG motion comes from pitching about a point off the CG),
/// yaw, "first vertical bending" (a body with a bending mode, Body::bending, whose kinetic
/// energy ½ m_b q_b² leads: "body first vertical bending"), or, for lateral CG motion and roll
/// taken together:
///  - "roll" (about the fixed axis: side rocking) when the body is held laterally, or about
///    the CG when the lateral share is round-off (an uncoupled body);
///  - "lateral" when the body is held in roll, or the roll share is round-off;
///  - otherwise "lower sway" / "upper sway" as the centre of oscillation lies below / above
///    the CG, however small either share (README, "Mode names").
/// A wheelset carried by a body through its suspension (a bogie frame, a two-axle wagon's body:
/// model::wheelset_carrier) is credited with its motion relative to that body only: its
/// displacement less the one its reference point and its rotation would have as a point of the
/// carrier (lateral = the carrier's lateral + yaw × x-offset − roll × height, yaw = the
/// carrier's yaw; its bounce, roll and spin follow the rails and are not carried). The carrier
/// takes the kinetic energy of the carried part, shared among its own terms in proportion to
/// what each alone gives the wheelset, so that a bogie yawing with its wheelsets is "bogies yaw"
/// however far they move laterally, and wheelsets yawing in a frame held still stay "wheelsets
/// yaw". The cross term between the carried and the relative motion belongs to neither and
/// counts for neither. Having taken all its wheelsets' carried energy, the carrier leads only if
/// it also has more than their relative energies together; else its wheelset with the most does.
/// Bodies named alike but for a trailing number (bogie1, bogie2): a repeated mode led by one of
/// them names the subspace, "bogies pitch (repeated)"; a repeated mode has no centre of
/// oscillation (its shape is an arbitrary member of the subspace); otherwise a twin with at least half the
/// leader's energy names the pair and their phase: "bogies bounce, antiphase". Twins hung from
/// more than one carrier (four wheelsets under two bogies) are named with their phase within
/// each carrier and between the carriers (carried_twins_phase): "wheelsets lateral, each bogie's
/// pair in antiphase, bogies in phase", "wheelsets yaw, each bogie's pair in phase (repeated)".
/// A system without bodies (matrices read from files) is named after the DOF with the most
/// kinetic energy φᵢ (Mφ)ᵢ, e.g. "dof3" or "body.bounce", with no centre of oscillation.
class ModeNamer {
 public:
  explicit ModeNamer(const LinearSystem& system);
  void describe(const Eigen::VectorXd& shape, bool repeated, std::string* name,
                std::optional<CentreOfOscillation>* centre) const;

  /// What a body's part in a name depends on, of the system alone.
  struct BodyFacts {
    std::string family;  ///< family_of(name)
    bool has_twin = false;  ///< another body of the same family, under another name
    bool free_longitudinal = false, free_lateral = false, free_roll = false;  ///< DOFs of the system
    model::PointMap cg_map;  ///< the CG's motion per unit motion of the reference point
    double bending_mass = 0.0;  ///< the bending mode's modal mass (a body with Body::bending)
    /// A wheelset's carrier (model::wheelset_carrier: its bogie frame, or a two-axle wagon's
    /// body), −1 for any other body and a wheelset held by the track alone.
    int carrier = -1;
    /// A carried wheelset's motions per unit of its carrier's CG motion and rotation (rows in the
    /// order of Motion, columns lateral, vertical, longitudinal, roll, pitch, yaw; the motions it
    /// does not have, 0), and its mass matrix at its reference point (model::body_mass).
    model::BodyMatrix carried = model::BodyMatrix::Zero(), mass = model::BodyMatrix::Zero();
  };
  const BodyFacts& facts(int body) const { return bodies_[body]; }
  /// A carried wheelset's motions per unit motion of its carrier's reference point (in the order
  /// of Motion both): BodyFacts::carried times the carrier's CG motion per unit of it.
  model::BodyMatrix carried_per_carrier_motion(int wheelset) const;

 private:
  const LinearSystem& system_;
  std::vector<BodyFacts> bodies_;
};

/// The share α of the motion c its carrier gives a wheelset that the wheelset's motion u has:
/// their projection in its mass matrix M, Re(cᴴMu) / cᴴMc, kept within [0, 1] (ModeNamer: the
/// carried part α c and the relative u − α c then never count for more energy than u has, and a
/// wheelset moving against its frame keeps all of its own); 0 when c is. Real or complex
/// vectors: an undamped mode's motions, or a root's.
template <class Vector>
double carried_share(const model::BodyMatrix& mass, const Vector& c, const Vector& u) {
  using Scalar = typename Vector::Scalar;
  const Vector Mc = mass.cast<Scalar>() * c;
  const double cc = std::real(Mc.dot(c));
  return cc > 0.0 ? std::clamp(std::real(Mc.dot(u)) / cc, 0.0, 1.0) : 0.0;
}

/// What twin bodies share: "bogie1" → "bogie", "wheelset_2" → "wheelset"; a name without a
/// trailing number is its own family.
std::string family_of(const std::string& name);

/// One of a family of twin bodies in a mode (or a hunting root), for carried_twins_phase.
struct TwinMotion {
  int carrier = -1;  ///< index into vehicle.bodies of the body carrying it (model::wheelset_carrier), −1: none
  double x = 0.0;    ///< its reference point's x, m: orders the twins of a carrier from the front
  std::complex<double> amplitude;  ///< its leading motion's coordinate (real in an undamped mode)
  double energy = 0.0;  ///< how much it moves: its energy in the mode, as the caller weighs the twins
  bool shares = false;  ///< it shares the mode: the leading twin, or one with at least half its energy
};

/// The phase of twins hung from two or more carriers, which "in phase" or "antiphase" alone
/// leaves open (do the two wheelsets of a bogie move against each other, or one bogie's pair
/// against the other's?). Two twins move in phase when their coordinates are within 90° (the
/// same sign in an undamped mode). Within a carrier: its sharing twins in phase with the one of
/// them that moves most, "each bogie's pair in phase", else "in antiphase" ("pair" for two twins
/// a carrier, else the twins' family, "each bogie's wheelsets"; a carrier named when the
/// carriers differ, "bogie1's pair in phase, bogie2's in antiphase", or when only one carrier's
/// twins share a mode of its own). Between the carriers, for a mode of its own (not `repeated`,
/// whose subspace holds every combination of the carriers' motions): each carrier's twins taken
/// in order from the front, their coordinates' sum of products with the leading carrier's, in
/// phase when not negative: ", bogies in phase". "" when the twins are not so grouped (all under
/// one carrier or none, or no carrier with two sharing twins): the plain phase then says all.
/// `lead` indexes the leading twin in `twins`; `bodies` are the vehicle's (they name the
/// carriers); `family` is the twins' (family_of).
std::string carried_twins_phase(const std::vector<TwinMotion>& twins, int lead, const std::vector<Body>& bodies,
                                 const std::string& family, bool repeated);

}  // namespace railmodal::solve
