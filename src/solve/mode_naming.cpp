#include "solve/mode_naming.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstring>
#include <map>

#include "model/body_bending.hpp"
#include "model/rigid_body.hpp"

namespace railmodal::solve {
namespace {

using model::BodyVector;
using model::kMotionsPerBody;

// Word for each energy term at the CG; longitudinal CG motion belongs to pitch unless the
// body's longitudinal motion is a degree of freedom. The bending mode's kinetic energy
// ½ m_b q_b² adds to the rigid terms (the mode is mass-orthogonal to the rigid motions).
enum Term { kLateral, kVertical, kLongitudinal, kRoll, kPitch, kYaw, kBending, kTerms };

struct BodyEnergy {
  double total = 0.0;
  std::array<double, kTerms> term{};
  BodyVector motion = BodyVector::Zero();  // the body's motions in this mode
  double bending = 0.0;                    // and its bending amplitude (0: rigid body)

  // The body's coordinate `m` in this mode (the twins' phase test compares them).
  double amplitude(Motion m) const { return m == Motion::bending ? bending : motion(static_cast<int>(m)); }
};

// `map` is the body's point map of its CG, `bending_mass` its bending mode's modal mass (0
// without one): ModeNamer::BodyFacts.
BodyEnergy energy_of(const Body& body, const model::PointMap& map, double bending_mass, const BodyVector& q,
                     double bending) {
  BodyEnergy e;
  e.motion = q;
  e.bending = bending;
  // The five motions before longitudinal as a 3 × 5 product (the same sums as before it
  // existed), then the longitudinal one, +0 where it is held.
  constexpr int kFive = kMotionsPerBody - 1;
  const Eigen::Matrix<double, 3, kFive> five = map.leftCols<kFive>();
  const Eigen::Vector3d cg = five * q.head<kFive>() + map.col(kFive) * q(kFive);
  const Eigen::Vector3d rotation(q(2), q(3), q(4));
  e.term[kLongitudinal] = 0.5 * body.mass * cg.x() * cg.x();
  e.term[kLateral] = 0.5 * body.mass * cg.y() * cg.y();
  e.term[kVertical] = 0.5 * body.mass * cg.z() * cg.z();
  e.term[kRoll] = 0.5 * body.inertia.x() * rotation.x() * rotation.x();
  e.term[kPitch] = 0.5 * body.inertia.y() * rotation.y() * rotation.y();
  e.term[kYaw] = 0.5 * body.inertia.z() * rotation.z() * rotation.z();
  if (body.bending) e.term[kBending] = 0.5 * bending_mass * bending * bending;
  for (double t : e.term) e.total += t;
  return e;
}

// Height of the line with no lateral motion (roll) or x of the point with no vertical
// motion (pitch), from the motions of the reference point.
std::optional<CentreOfOscillation> centre_of(const Body& body, const BodyVector& q, bool roll) {
  CentreOfOscillation c;
  c.body = body.name;
  c.about = roll ? "roll" : "pitch";
  const double rotation = roll ? q(2) : q(3);
  const double translation = roll ? q(0) : q(1);
  // y(z) = y_ref − θx (z − z_ref); z(x) = z_ref − θy (x − x_ref)
  if (std::abs(rotation) * 1e6 <= std::abs(translation) || rotation == 0.0) {
    c.at_infinity = true;
    return c;
  }
  c.position = (roll ? body.reference_point.z() : body.reference_point.x()) + translation / rotation;
  return c;
}

// Matrices read from files have no bodies: the DOF with the most kinetic energy,
// φᵢ (Mφ)ᵢ, names the mode.
void describe_by_dof(const LinearSystem& system, const Eigen::VectorXd& shape, std::string* name) {
  const Eigen::VectorXd energy = shape.cwiseProduct(system.mass * shape);
  Eigen::Index lead = 0;
  energy.maxCoeff(&lead);
  *name = system.dofs[lead].label;
}

// How the leading body moves: its word, the motion whose phase twins compare, and the
// centre of roll or pitch where the word has one.
struct LeadingMotion {
  const char* word = "";
  Motion key = Motion::bounce;
  std::optional<CentreOfOscillation> centre;
};

// Roll and lateral motion of a body free in both are one coupled motion, sway, named by the
// side of the CG its centre of rotation lies on: the pair's centres are always on opposite
// sides (their M-orthogonality gives (z₁ − z_cg)(z₂ − z_cg) = −J/m), so the name follows the
// shape continuously and a small change of the design cannot swap it. Only an uncoupled body
// (spring plane through the CG, or no lateral stiffness) has a pure lateral or a pure roll
// mode about the CG; a share below 1e-6 of the sway energy is round-off of such a mode.
const char* sway_word(const Body& body, const BodyEnergy& e, std::optional<CentreOfOscillation>* centre) {
  const double sway = e.term[kLateral] + e.term[kRoll];
  if (e.term[kLateral] <= 1e-6 * sway) {
    *centre = centre_of(body, e.motion, true);
    return "roll";
  }
  if (e.term[kRoll] <= 1e-6 * sway) return "lateral";
  *centre = centre_of(body, e.motion, true);
  const bool lower = !(*centre)->at_infinity && (*centre)->position < body.centre_of_gravity.z();
  return lower ? "lower sway" : "upper sway";
}

// Whether the system has the DOF "<body>.<motion>": LinearSystem::index_of(label) ≥ 0 without
// the label built (a long one is an allocation).
bool has_dof(const LinearSystem& system, const std::string& body, const char* motion) {
  const size_t n = body.size(), m = std::strlen(motion);
  for (const Dof& d : system.dofs)
    if (d.label.size() == n + 1 + m && d.label.compare(0, n, body) == 0 && d.label[n] == '.' &&
        d.label.compare(n + 1, m, motion) == 0)
      return true;
  return false;
}

LeadingMotion leading_motion(const ModeNamer::BodyFacts& facts, const Body& body, const BodyEnergy& e) {
  // Longitudinal CG motion of a body whose surge is held comes from pitching about a point off
  // the CG; lateral CG motion and roll are one sway, whichever of the two is larger.
  std::array<double, kTerms> t = e.term;
  if (!facts.free_longitudinal) {  // held surge: the CG's longitudinal motion is pitch
    t[kPitch] += t[kLongitudinal];
    t[kLongitudinal] = 0.0;
  }
  t[kRoll] += t[kLateral];
  t[kLateral] = 0.0;
  int word = 0;
  for (int k = 1; k < kTerms; ++k)
    if (t[k] > t[word]) word = k;

  LeadingMotion m;
  switch (word) {
    case kVertical: m.word = "bounce"; m.key = Motion::bounce; break;
    case kPitch:
      m.word = "pitch", m.key = Motion::pitch;
      m.centre = centre_of(body, e.motion, false);
      break;
    case kYaw:
      m.word = "yaw";
      m.key = Motion::yaw;
      break;
    case kLongitudinal:
      m.word = "longitudinal";
      m.key = Motion::longitudinal;
      break;
    case kBending:
      m.word = "first vertical bending";
      m.key = Motion::bending;
      break;
    default: {
      // A body held laterally rolls about its fixed axis (the book's side rocking) even when
      // its CG moves more than it turns; one held in roll only translates.
      const bool lateral_free = facts.free_lateral;
      const bool roll_free = facts.free_roll;
      if (roll_free && !lateral_free) {
        m.word = "roll";
        m.centre = centre_of(body, e.motion, true);
      } else {
        m.word = lateral_free && !roll_free ? "lateral" : sway_word(body, e, &m.centre);
      }
      m.key = std::strcmp(m.word, "lateral") == 0 ? Motion::lateral : Motion::roll;
    }
  }
  return m;
}

}  // namespace

ModeNamer::ModeNamer(const LinearSystem& system) : system_(system) {
  const auto& bodies = system.vehicle.bodies;
  bodies_.resize(bodies.size());
  for (size_t b = 0; b < bodies.size(); ++b) {
    BodyFacts& f = bodies_[b];
    f.family = family_of(bodies[b].name);
    f.free_longitudinal = has_dof(system, bodies[b].name, "longitudinal");
    f.free_lateral = has_dof(system, bodies[b].name, "lateral");
    f.free_roll = has_dof(system, bodies[b].name, "roll");
    f.cg_map = model::point_map(bodies[b], bodies[b].centre_of_gravity);
    if (bodies[b].bending) f.bending_mass = model::bending_mode(bodies[b]).modal_mass;
  }
  for (size_t b = 0; b < bodies.size(); ++b) {
    BodyFacts& f = bodies_[b];
    for (size_t o = 0; o < bodies.size() && !f.has_twin; ++o)
      f.has_twin = !f.family.empty() && f.family != bodies[b].name && bodies[o].name != bodies[b].name &&
                   bodies_[o].family == f.family;
  }
}

void ModeNamer::describe(const Eigen::VectorXd& shape, bool repeated, std::string* name,
                         std::optional<CentreOfOscillation>* centre) const {
  const LinearSystem& system = system_;
  const auto& bodies = system.vehicle.bodies;
  centre->reset();
  if (bodies.empty()) return describe_by_dof(system, shape, name);
  // This thread's lists, kept between modes: every mode of every variant of a study is named.
  thread_local std::vector<BodyVector> motion;
  thread_local std::vector<double> bending;
  thread_local std::vector<BodyEnergy> energy;
  motion.assign(bodies.size(), BodyVector::Zero());
  bending.assign(bodies.size(), 0.0);
  energy.clear();
  for (size_t i = 0; i < system.dofs.size(); ++i) {
    const Dof& dof = system.dofs[i];
    if (dof.motion == Motion::bending)
      bending[dof.body] = shape(static_cast<int>(i));
    else
      motion[dof.body](static_cast<int>(dof.motion)) = shape(static_cast<int>(i));
  }

  int lead = 0;
  for (size_t b = 0; b < bodies.size(); ++b) {
    energy.push_back(energy_of(bodies[b], bodies_[b].cg_map, bodies_[b].bending_mass, motion[b], bending[b]));
    if (energy[b].total > energy[lead].total) lead = static_cast<int>(b);
  }
  const BodyEnergy& e = energy[lead];
  const Body& body = bodies[lead];
  const BodyFacts& facts = bodies_[lead];
  const LeadingMotion leading = leading_motion(facts, body, e);
  // A repeated mode's shape is one arbitrary member of its subspace, and so is its centre of
  // oscillation (bogies pitch: either bogie's pivot): only a mode of its own has one.
  if (!repeated) *centre = leading.centre;

  const std::string& family = facts.family;
  const bool has_twin = facts.has_twin;
  // A repeated mode of twin bodies is any combination of the twins' motions (the solver's
  // basis is arbitrary, its members unequal mixtures): only the shared subspace has a name.
  if (repeated && has_twin) {
    name->assign(family).append("s ").append(leading.word).append(" (repeated)");
    return;
  }
  // Twin bodies (bogie1/bogie2, wheelset1…wheelset4) sharing the energy: name the family and
  // their phase, "in phase" when every twin that shares it moves with the leading body. With
  // more than two twins the test is over all of them, not the leading body and the first other:
  // which of four nearly equal wheelsets leads changes with a 1 % change of any parameter.
  bool shared = false, in_phase = true;
  for (size_t b = 0; b < bodies.size() && has_twin; ++b) {
    if (static_cast<int>(b) == lead || bodies_[b].family != family || energy[b].total < 0.5 * e.total) continue;
    shared = true;
    in_phase = in_phase && e.amplitude(leading.key) * energy[b].amplitude(leading.key) >= 0.0;
  }
  if (shared) {
    name->assign(family).append("s ").append(leading.word).append(", ").append(in_phase ? "in phase" : "antiphase");
    return;
  }
  name->reserve(body.name.size() + 1 + std::strlen(leading.word));  // one allocation at most, none in kept storage
  name->assign(body.name).append(1, ' ').append(leading.word);
}

std::string family_of(const std::string& name) {
  size_t end = name.size();
  while (end > 0 && (std::isdigit(static_cast<unsigned char>(name[end - 1])) || name[end - 1] == '_'))
    --end;
  return name.substr(0, end);
}

}  // namespace railmodal::solve
