// Names a mode from where its kinetic energy sits, and finds its centre of oscillation.
#pragma once

#include <Eigen/Core>
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
/// leader's energy names the pair and their phase: "bogies bounce, antiphase".
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

 private:
  const LinearSystem& system_;
  std::vector<BodyFacts> bodies_;
};

/// What twin bodies share: "bogie1" → "bogie", "wheelset_2" → "wheelset"; a name without a
/// trailing number is its own family.
std::string family_of(const std::string& name);

}  // namespace railmodal::solve
