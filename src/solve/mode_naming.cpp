#include "solve/mode_naming.hpp"

#include <Eigen/Dense>
#include <array>
#include <cctype>
#include <cmath>
#include <map>

#include "model/rigid_body.hpp"

namespace railmodal::solve {
namespace {

using model::BodyVector;
using model::kMotionsPerBody;

// Word for each energy term at the CG; longitudinal CG motion belongs to pitch unless the
// body's longitudinal motion is a degree of freedom.
enum Term { kLateral, kVertical, kLongitudinal, kRoll, kPitch, kYaw, kTerms };

struct BodyEnergy {
  double total = 0.0;
  std::array<double, kTerms> term{};
  BodyVector motion = BodyVector::Zero();  // the body's motions in this mode
};

BodyEnergy energy_of(const Body& body, const BodyVector& q) {
  BodyEnergy e;
  e.motion = q;
  // The five motions before longitudinal as a 3 × 5 product (the same sums as before it
  // existed), then the longitudinal one, +0 where it is held.
  constexpr int kFive = kMotionsPerBody - 1;
  const model::PointMap map = model::point_map(body, body.centre_of_gravity);
  const Eigen::Matrix<double, 3, kFive> five = map.leftCols<kFive>();
  const Eigen::Vector3d cg = five * q.head<kFive>() + map.col(kFive) * q(kFive);
  const Eigen::Vector3d rotation(q(2), q(3), q(4));
  e.term[kLongitudinal] = 0.5 * body.mass * cg.x() * cg.x();
  e.term[kLateral] = 0.5 * body.mass * cg.y() * cg.y();
  e.term[kVertical] = 0.5 * body.mass * cg.z() * cg.z();
  e.term[kRoll] = 0.5 * body.inertia.x() * rotation.x() * rotation.x();
  e.term[kPitch] = 0.5 * body.inertia.y() * rotation.y() * rotation.y();
  e.term[kYaw] = 0.5 * body.inertia.z() * rotation.z() * rotation.z();
  for (double t : e.term) e.total += t;
  return e;
}

std::string family_of(const std::string& name) {
  size_t end = name.size();
  while (end > 0 && (std::isdigit(static_cast<unsigned char>(name[end - 1])) || name[end - 1] == '_'))
    --end;
  return name.substr(0, end);
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
ModeDescription describe_by_dof(const LinearSystem& system, const Eigen::VectorXd& shape) {
  const Eigen::VectorXd energy = shape.cwiseProduct(system.mass * shape);
  Eigen::Index lead = 0;
  energy.maxCoeff(&lead);
  ModeDescription d;
  d.name = system.dofs[lead].label;
  return d;
}

// How the leading body moves: its word, the motion whose phase twins compare, and the
// centre of roll or pitch where the word has one.
struct LeadingMotion {
  std::string word;
  Motion key = Motion::bounce;
  std::optional<CentreOfOscillation> centre;
};

LeadingMotion leading_motion(const LinearSystem& system, const Body& body, const BodyEnergy& e) {
  std::array<double, kTerms> t = e.term;
  if (system.index_of(body.name + ".longitudinal") < 0) {
    t[kPitch] += t[kLongitudinal];
    t[kLongitudinal] = 0.0;
  }
  int word = 0;
  for (int k = 1; k < kTerms; ++k)
    if (t[k] > t[word]) word = k;

  LeadingMotion m;
  const double share_lateral = e.total > 0 ? t[kLateral] / e.total : 0.0;
  const double share_roll = e.total > 0 ? t[kRoll] / e.total : 0.0;
  // Sway needs a free lateral motion; a body held laterally (two-axle wagon, bogie frame)
  // simply rolls about its fixed axis, the book's "side rocking".
  const bool lateral_free = system.index_of(body.name + ".lateral") >= 0;
  if (lateral_free && (word == kLateral || word == kRoll) && share_lateral >= 0.1 && share_roll >= 0.1) {
    m.centre = centre_of(body, e.motion, true);
    const bool lower = !m.centre->at_infinity && m.centre->position < body.centre_of_gravity.z();
    m.word = lower ? "lower sway" : "upper sway";
    m.key = Motion::roll;
    return m;
  }
  switch (word) {
    case kLateral: m.word = "lateral"; m.key = Motion::lateral; break;
    case kVertical: m.word = "bounce"; m.key = Motion::bounce; break;
    case kRoll: m.word = "roll"; m.key = Motion::roll; break;
    case kPitch: m.word = "pitch"; m.key = Motion::pitch; break;
    case kLongitudinal:
      m.word = "longitudinal";
      m.key = Motion::longitudinal;
      break;
    default: m.word = "yaw"; m.key = Motion::yaw; break;
  }
  if (word == kRoll) m.centre = centre_of(body, e.motion, true);
  if (word == kPitch) m.centre = centre_of(body, e.motion, false);
  return m;
}

}  // namespace

ModeDescription describe_mode(const LinearSystem& system, const Eigen::VectorXd& shape) {
  const auto& bodies = system.vehicle.bodies;
  if (bodies.empty()) return describe_by_dof(system, shape);
  std::vector<BodyVector> motion(bodies.size(), BodyVector::Zero());
  for (size_t i = 0; i < system.dofs.size(); ++i)
    motion[system.dofs[i].body](static_cast<int>(system.dofs[i].motion)) = shape(static_cast<int>(i));

  std::vector<BodyEnergy> energy;
  int lead = 0;
  for (size_t b = 0; b < bodies.size(); ++b) {
    energy.push_back(energy_of(bodies[b], motion[b]));
    if (energy[b].total > energy[lead].total) lead = static_cast<int>(b);
  }
  const BodyEnergy& e = energy[lead];
  const Body& body = bodies[lead];
  const LeadingMotion leading = leading_motion(system, body, e);
  ModeDescription d;
  d.centre = leading.centre;

  // A twin body (bogie1/bogie2) sharing the energy: name the pair and their phase.
  const std::string family = family_of(body.name);
  for (size_t b = 0; b < bodies.size(); ++b) {
    if (static_cast<int>(b) == lead || family.empty() || family == body.name) continue;
    if (family_of(bodies[b].name) != family || energy[b].total < 0.5 * e.total) continue;
    const int m = static_cast<int>(leading.key);
    const double a = e.motion(m), other = energy[b].motion(m);
    const std::string phase = a * other >= 0.0 ? "in phase" : "antiphase";
    d.name = family + "s " + leading.word + ", " + phase;
    return d;
  }
  d.name = body.name + " " + leading.word;
  return d;
}

}  // namespace railmodal::solve
