// Names a mode from where its kinetic energy sits, and finds its centre of oscillation.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>

#include "railmodal/linear_system.hpp"
#include "railmodal/modal.hpp"

namespace railmodal::solve {

struct ModeDescription {
  std::string name;
  std::optional<CentreOfOscillation> centre;
};

/// Describes a mode shape over system.dofs (all entries, condensed ones recovered).
///
/// The kinetic energy of each body is split at its centre of gravity into translation
/// (lateral, vertical, longitudinal) and rotation (roll, pitch, yaw), terms that cannot be
/// negative. The body with the most energy names the mode; its leading motion gives the
/// word: bounce, pitch (longitudinal CG motion comes from pitching about a point below the
/// CG), roll, lateral, yaw, and "lower sway" / "upper sway" when the body's lateral motion is
/// free, lateral and roll both carry at least 10 % of its energy and the centre of
/// oscillation lies below / above the CG.
/// Bodies named alike but for a trailing number (bogie1, bogie2) that share the energy
/// (the second at least half the first) are named together: "bogies bounce, antiphase".
/// A system without bodies (matrices read from files) is named after the DOF with the most
/// kinetic energy φᵢ (Mφ)ᵢ, e.g. "dof3" or "body.bounce", with no centre of oscillation.
ModeDescription describe_mode(const LinearSystem& system, const Eigen::VectorXd& shape);

}  // namespace railmodal::solve
