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
#include "model/wheelset_dofs.hpp"

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

// A body's rigid motion as the motion of its CG and its rotation, one entry per rigid Term
// (lateral, vertical, longitudinal, roll, pitch, yaw): its energy terms are these squared.
using CgMotion = Eigen::Matrix<double, kMotionsPerBody, 1>;

// `map` is the body's point map of its CG (ModeNamer::BodyFacts).
CgMotion cg_motion_of(const model::PointMap& map, const BodyVector& q) {
  // The five motions before longitudinal as a 3 × 5 product (the same sums as before it
  // existed), then the longitudinal one, +0 where it is held.
  constexpr int kFive = kMotionsPerBody - 1;
  const Eigen::Matrix<double, 3, kFive> five = map.leftCols<kFive>();
  const Eigen::Vector3d cg = five * q.head<kFive>() + map.col(kFive) * q(kFive);
  CgMotion s;
  s << cg.y(), cg.z(), cg.x(), q(2), q(3), q(4);
  return s;
}

// `map` is the body's point map of its CG, `bending_mass` its bending mode's modal mass (0
// without one): ModeNamer::BodyFacts.
BodyEnergy energy_of(const Body& body, const model::PointMap& map, double bending_mass, const BodyVector& q,
                     double bending) {
  BodyEnergy e;
  e.motion = q;
  e.bending = bending;
  const CgMotion s = cg_motion_of(map, q);
  const std::array<double, kMotionsPerBody> inertia{body.mass, body.mass, body.mass,
                                                    body.inertia.x(), body.inertia.y(), body.inertia.z()};
  for (int t = 0; t < kMotionsPerBody; ++t) e.term[t] = 0.5 * inertia[t] * s(t) * s(t);
  if (body.bending) e.term[kBending] = 0.5 * bending_mass * bending * bending;
  for (double t : e.term) e.total += t;
  return e;
}

// A wheelset's motions (its reference point's, in the order of Motion) per unit of each term of
// its carrier's CG motion (CgMotion): its reference point moves as a point of the carrier,
// u = v_cg + θ × d with d from the carrier's CG to the point (model::point_map's convention), and
// turns with it. A motion the wheelset does not have (its bounce, roll and spin follow the
// rails: `free`) is not carried: the primary suspension takes the carrier's motion there.
model::BodyMatrix carried_per_term(const Body& carrier, const Body& carried, const std::array<bool, kMotionsPerBody>& free) {
  const Eigen::Vector3d d = carried.reference_point - carrier.centre_of_gravity;
  const int lateral = static_cast<int>(Motion::lateral), bounce = static_cast<int>(Motion::bounce),
            roll = static_cast<int>(Motion::roll), pitch = static_cast<int>(Motion::pitch),
            yaw = static_cast<int>(Motion::yaw), longitudinal = static_cast<int>(Motion::longitudinal);
  model::BodyMatrix c = model::BodyMatrix::Zero();
  // θ × d = (θy dz − θz dy, θz dx − θx dz, θx dy − θy dx)
  c(lateral, kLateral) = 1.0, c(lateral, kYaw) = d.x(), c(lateral, kRoll) = -d.z();
  c(bounce, kVertical) = 1.0, c(bounce, kRoll) = d.y(), c(bounce, kPitch) = -d.x();
  c(longitudinal, kLongitudinal) = 1.0, c(longitudinal, kPitch) = d.z(), c(longitudinal, kYaw) = -d.y();
  c(roll, kRoll) = 1.0, c(pitch, kPitch) = 1.0, c(yaw, kYaw) = 1.0;
  for (int m = 0; m < kMotionsPerBody; ++m)
    if (!free[m]) c.row(m).setZero();
  return c;
}

// Credits the carrier with the kinetic energy ½ cᵀMc of the motion c = C s its rigid motion s
// gives a wheelset (M the wheelset's mass matrix), shared among the carrier's terms in proportion
// to what each alone gives it, ½ (C_j s_j)ᵀ M (C_j s_j): none negative, and the cross terms
// (the carrier's lateral and yaw at one axle) go with the terms that make them.
void credit_carried(const model::BodyMatrix& carried, const model::BodyMatrix& mass, const CgMotion& s,
                    BodyEnergy* carrier) {
  const BodyVector c = carried * s;
  const double total = 0.5 * c.dot(mass * c);
  std::array<double, kMotionsPerBody> alone{};
  double sum = 0.0;
  for (int t = 0; t < kMotionsPerBody; ++t) {
    const BodyVector ct = carried.col(t) * s(t);
    alone[t] = 0.5 * ct.dot(mass * ct);
    sum += alone[t];
  }
  if (sum <= 0.0) return;
  for (int t = 0; t < kMotionsPerBody; ++t) carrier->term[t] += total * alone[t] / sum;
  carrier->total += total;
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
    if (model::wheelset_of(system.vehicle, bodies[b].name) == nullptr) continue;
    f.carrier = model::wheelset_carrier(system.vehicle, bodies[b].name);
    if (f.carrier < 0) continue;
    std::array<bool, kMotionsPerBody> free{};
    for (int m = 0; m < kMotionsPerBody; ++m) free[m] = has_dof(system, bodies[b].name, to_string(static_cast<Motion>(m)));
    f.carried = carried_per_term(bodies[f.carrier], bodies[b], free);
    f.mass = model::body_mass(bodies[b]);
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
  thread_local std::vector<double> carried_share;  // α of each carried wheelset (below)
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

  // A wheelset is named for its motion relative to its carrier (bogie frame, or a two-axle
  // wagon's body) only; what the carrier's rigid motion gives it, the carrier takes credit for
  // (a bogie yawing with its wheelsets is "bogie yaw", however much they move laterally). The
  // carried part is the share α c of the motion c the carrier would give it that the wheelset's
  // motion u has, α = cᵀMu / cᵀMc (its M-orthogonal projection) kept within [0, 1]: the carried
  // and relative energies then add up to the wheelset's own, or to less, never more. A wheelset
  // moving against its frame (α < 0: the primary springs take both motions) keeps its whole
  // energy and the frame none of it; without the bound its motion relative to the frame would
  // count for more energy than the mode gives it.
  carried_share.assign(bodies.size(), 0.0);
  for (size_t b = 0; b < bodies.size(); ++b) {
    const BodyFacts& f = bodies_[b];
    BodyVector own = motion[b];
    if (f.carrier >= 0) {
      const BodyVector c = f.carried * cg_motion_of(bodies_[f.carrier].cg_map, motion[f.carrier]);
      const double cc = c.dot(f.mass * c);
      if (cc > 0.0) carried_share[b] = std::clamp(c.dot(f.mass * motion[b]) / cc, 0.0, 1.0);
      own -= carried_share[b] * c;
    }
    energy.push_back(energy_of(bodies[b], f.cg_map, f.bending_mass, own, bending[b]));
  }
  for (size_t b = 0; b < bodies.size(); ++b) {
    const BodyFacts& f = bodies_[b];
    if (f.carrier >= 0 && carried_share[b] > 0.0)
      credit_carried(f.carried, f.mass, carried_share[b] * cg_motion_of(bodies_[f.carrier].cg_map, motion[f.carrier]),
                     &energy[f.carrier]);
  }
  int lead = 0;
  for (size_t b = 0; b < bodies.size(); ++b)
    if (energy[b].total > energy[lead].total) lead = static_cast<int>(b);
  // The carrier took the carried energy of all its wheelsets: their relative motion counts
  // together against it too, or a bogie would name a mode in which both its wheelsets move
  // laterally in the frame twice as far as the frame's yaw carries them (each wheelset's share
  // alone is about the bogie's, and which leads would turn on round-off).
  double relative = 0.0;
  int wheelset = -1;
  for (size_t b = 0; b < bodies.size(); ++b) {
    if (bodies_[b].carrier != lead) continue;
    relative += energy[b].total;
    if (wheelset < 0 || energy[b].total > energy[wheelset].total) wheelset = static_cast<int>(b);
  }
  if (wheelset >= 0 && relative > energy[lead].total) lead = wheelset;
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
