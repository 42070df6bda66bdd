// Root names for the hunting branches (see branch_naming.hpp).
#include "stability/branch_naming.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <map>
#include <vector>

#include "model/rigid_body.hpp"
#include "model/wheelset_dofs.hpp"
#include "solve/mode_naming.hpp"

namespace railmodal::stability {

namespace {

// The words for what one body does in the shape: "hunting" for an oscillating wheelset whose
// lateral and yaw both carry at least 1 % of its energy, else its motions carrying at least a
// quarter of its energy, the larger first, joined by "/". `key` is the DOF whose phase twins
// compare (the largest motion; for hunting the lateral one).
std::string words_of(const LinearSystem& system, const Eigen::VectorXd& energy, int body, bool oscillatory, int* key) {
  const int n = system.size();
  double total = 0.0;
  std::vector<std::pair<double, int>> motions;
  for (int i = 0; i < n; ++i)
    if (system.dofs[i].body == body) motions.push_back({energy(i), i}), total += energy(i);
  std::stable_sort(motions.begin(), motions.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  *key = motions.front().second;
  if (oscillatory && model::wheelset_of(system.vehicle, system.vehicle.bodies[body].name) != nullptr) {
    double lateral = 0.0, yaw = 0.0;
    int lateral_dof = -1;
    for (const auto& [e, i] : motions) {
      if (system.dofs[i].motion == Motion::lateral) lateral += e, lateral_dof = i;
      if (system.dofs[i].motion == Motion::yaw) yaw += e;
    }
    if (lateral >= 0.01 * total && yaw >= 0.01 * total) {
      *key = lateral_dof;
      return "hunting";
    }
  }
  std::string words;
  for (const auto& [e, i] : motions)
    if (e >= 0.25 * total) words += (words.empty() ? "" : "/") + std::string(to_string(system.dofs[i].motion));
  return words;
}

// The DOF of `body`'s `motion` in the system, −1 when it has none.
int dof_of(const LinearSystem& system, int body, Motion motion) {
  for (int i = 0; i < system.size(); ++i)
    if (system.dofs[i].body == body && system.dofs[i].motion == motion) return i;
  return -1;
}

// Hunting wheelsets named by their bogies (branch_naming.hpp), or "" when the leading bogie's
// wheelsets do not move together (or the leading body is in no bogie). `per_mass` is each
// body's energy per unit mass.
std::string bogie_hunting_name(const LinearSystem& system, const Eigen::VectorXcd& shape,
                               const std::map<int, double>& per_mass, int lead) {
  const std::vector<WheelsetBogie> bogies = wheelset_bogies(system.vehicle);
  const auto energy_of = [&](int body) {
    const auto e = per_mass.find(body);
    return e == per_mass.end() ? 0.0 : e->second;
  };
  // Each bogie's lateral amplitude (the sum of its wheelsets'), its energy per unit mass (the
  // sum of theirs), and whether its wheelsets move together.
  struct Moving {
    std::complex<double> lateral;
    double energy = 0.0;
    bool together = true;
  };
  std::vector<Moving> moving(bogies.size());
  int lead_bogie = -1;
  for (size_t g = 0; g < bogies.size(); ++g) {
    std::vector<std::complex<double>> y;
    for (int w : bogies[g].wheelsets) {
      const int dof = dof_of(system, w, Motion::lateral);
      y.push_back(dof >= 0 ? shape(dof) : 0.0);
      moving[g].lateral += y.back();
      moving[g].energy += energy_of(w);
      if (w == lead) lead_bogie = static_cast<int>(g);
    }
    double largest = 0.0;
    for (const auto& a : y) largest = std::max(largest, std::norm(a));
    for (size_t i = 0; i < y.size(); ++i)
      for (size_t j = 0; j < y.size(); ++j)
        moving[g].together = moving[g].together && std::real(y[i] * std::conj(y[j])) >= 0.0 &&
                             std::norm(y[i]) >= 0.25 * largest && largest > 0.0;
  }
  if (lead_bogie < 0 || !moving[lead_bogie].together) return "";
  // The bogie that moves most leads (its wheelsets' energy, not one wheelset's).
  for (size_t g = 0; g < bogies.size(); ++g)
    if (moving[g].together && moving[g].energy > moving[lead_bogie].energy) lead_bogie = static_cast<int>(g);
  std::string names;
  bool in_phase = true;
  int count = 0;
  for (size_t g = 0; g < bogies.size(); ++g) {
    if (!moving[g].together || moving[g].energy < 0.5 * moving[lead_bogie].energy) continue;
    names += (names.empty() ? "" : "+") + system.vehicle.bodies[bogies[g].body].name;
    in_phase = in_phase && std::real(moving[g].lateral * std::conj(moving[lead_bogie].lateral)) >= 0.0;
    ++count;
  }
  return count == 1 ? names + " hunting" : names + " hunting, " + (in_phase ? "in phase" : "antiphase");
}

// Each body's energy per unit of its mass (root_name), from the energy of each DOF.
std::map<int, double> energy_per_mass(const LinearSystem& system, const Eigen::VectorXd& energy) {
  std::map<int, double> per_mass;
  for (int i = 0; i < system.size(); ++i) {
    const int b = system.dofs[i].body;
    const double mass = system.vehicle.bodies[b].mass;
    per_mass[b] += mass > 0.0 ? energy(i) / mass : energy(i);
  }
  return per_mass;
}

int most_moving(const std::map<int, double>& per_mass) {
  int lead = per_mass.begin()->first;
  for (const auto& [b, e] : per_mass)
    if (e > per_mass.at(lead)) lead = b;
  return lead;
}

// The energies of `energy` (each DOF's |√M_ii u_i|², u the displacement) with each carried
// wheelset's carried motion credited to its carrier (model::wheelset_carrier), as the undamped
// modes' names credit it (solve::ModeNamer): the wheelset keeps the energy of its motion
// relative to the carrier, u − α c (c the motion the carrier's rigid motion gives it, α =
// solve::carried_share), and the carrier gains that of α c, shared among its DOFs in proportion
// to what each alone gives the wheelset.
Eigen::VectorXd carried_split(const LinearSystem& system, const Eigen::VectorXcd& weighted_shape, Eigen::VectorXd energy) {
  using Complex = std::complex<double>;
  using Motions = Eigen::Matrix<Complex, model::kMotionsPerBody, 1>;
  const auto& bodies = system.vehicle.bodies;
  const solve::ModeNamer namer(system);
  // Each body's DOF of each motion (−1: none) and its motions, the shape unweighted.
  std::vector<std::array<int, model::kMotionsPerBody>> dof(bodies.size());
  for (auto& d : dof) d.fill(-1);
  std::vector<Motions> u(bodies.size(), Motions::Zero());
  for (int i = 0; i < system.size(); ++i) {
    const Dof& d = system.dofs[i];
    if (d.motion == Motion::bending || !(system.mass(i, i) > 0.0)) continue;
    dof[d.body][static_cast<int>(d.motion)] = i;
    u[d.body](static_cast<int>(d.motion)) = weighted_shape(i) / std::sqrt(system.mass(i, i));
  }
  for (size_t w = 0; w < bodies.size(); ++w) {
    const solve::ModeNamer::BodyFacts& f = namer.facts(static_cast<int>(w));
    if (f.carrier < 0) continue;
    const model::BodyMatrix per_motion = namer.carried_per_carrier_motion(static_cast<int>(w));
    const Motions c = per_motion.cast<Complex>() * u[f.carrier];
    const double alpha = solve::carried_share(f.mass, c, u[w]);
    if (alpha == 0.0) continue;
    const Motions relative = u[w] - alpha * c;
    for (int m = 0; m < model::kMotionsPerBody; ++m)
      if (dof[w][m] >= 0) energy(dof[w][m]) = std::norm(relative(m)) * system.mass(dof[w][m], dof[w][m]);
    const auto kinetic = [&](const Motions& v) { return std::real((f.mass.cast<Complex>() * v).dot(v)); };
    std::array<double, model::kMotionsPerBody> alone{};
    double sum = 0.0;
    for (int m = 0; m < model::kMotionsPerBody; ++m)
      if (dof[f.carrier][m] >= 0) sum += alone[m] = kinetic(per_motion.col(m).cast<Complex>() * u[f.carrier](m));
    if (!(sum > 0.0)) continue;
    const double carried = alpha * alpha * kinetic(c);
    for (int m = 0; m < model::kMotionsPerBody; ++m)
      if (dof[f.carrier][m] >= 0) energy(dof[f.carrier][m]) += carried * alone[m] / sum;
  }
  return energy;
}

// Having taken its wheelsets' carried energy, a leading carrier leads only if it also moves more
// per unit mass than they do together relative to it, else its wheelset that moves most does
// (solve::ModeNamer's rule, per unit mass as root_name weighs bodies).
int wheelsets_together(const LinearSystem& system, const std::map<int, double>& per_mass, int lead) {
  double relative = 0.0, mass = 0.0;
  int wheelset = -1;
  for (const WheelsetBogie& carrier : wheelset_carriers(system.vehicle)) {
    if (carrier.body != lead) continue;
    for (int w : carrier.wheelsets) {
      const auto e = per_mass.find(w);
      if (e == per_mass.end()) continue;
      relative += e->second * system.vehicle.bodies[w].mass;
      mass += system.vehicle.bodies[w].mass;
      if (wheelset < 0 || e->second > per_mass.at(wheelset)) wheelset = w;
    }
  }
  return wheelset >= 0 && mass > 0.0 && relative / mass > per_mass.at(lead) ? wheelset : lead;
}

// The name of the leading body, or of its twins that do the same (root_name).
std::string with_twins(const LinearSystem& system, const Eigen::VectorXcd& weighted_shape, const Eigen::VectorXd& energy,
                       const std::map<int, double>& per_mass, int lead, int key, const std::string& words,
                       bool oscillatory, bool twin) {
  // Twin bodies (bogie1/bogie2, wheelset1…wheelset4) that move at least half as much as the
  // leading one share the mode: name the family and the phase of the key motion, "in phase"
  // when every such twin's is within 90° of the leading body's. Which of two nearly equal
  // bogies leads is otherwise decided by round-off (0.71 of one bogie's yaw, 0.70 of the other's).
  // The twins are listed by their names as written, in the vehicle's order, joined by "+"
  // ("bogie1+bogie2 yaw, antiphase"): a plural made from the family ("wss" from ws1, ws2)
  // would mangle names that are not English words. Twins under two or more carriers (four
  // wheelsets under two bogies) take the undamped modes' phase words (solve::carried_twins_phase).
  const auto& bodies = system.vehicle.bodies;
  const std::string& name = bodies[lead].name;
  const std::string family = solve::family_of(name);
  bool in_phase = true;
  std::string twins;
  std::vector<solve::TwinMotion> motions;
  int lead_twin = -1;
  if (!family.empty() && family != name)
    for (const auto& [b, e] : per_mass) {
      const std::string& other = bodies[b].name;
      if (solve::family_of(other) != family) continue;
      int twin_key = key;
      const bool shares = b == lead || (e >= 0.5 * per_mass.at(lead) && words_of(system, energy, b, oscillatory, &twin_key) == words);
      if (b == lead) lead_twin = static_cast<int>(motions.size());
      const int same_motion = dof_of(system, b, system.dofs[key].motion);
      motions.push_back({model::wheelset_of(system.vehicle, other) != nullptr ? model::wheelset_carrier(system.vehicle, other) : -1,
                         bodies[b].reference_point.x(), same_motion >= 0 ? weighted_shape(same_motion) : 0.0, e, shares});
      if (!shares) continue;
      twins += (twins.empty() ? "" : "+") + other;
      in_phase = in_phase && std::real(weighted_shape(key) * std::conj(weighted_shape(twin_key))) >= 0.0;
    }
  if (twins == name || twins.empty()) return name + " " + words;
  const std::string grouped = solve::carried_twins_phase(motions, lead_twin, bodies, family, twin);
  return twins + " " + words + ", " + (!grouped.empty() ? grouped : in_phase ? "in phase" : "antiphase");
}
}  // namespace

std::vector<WheelsetBogie> wheelset_carriers(const Vehicle& vehicle) {
  const auto index_of = [&](const std::string& name) {
    for (size_t b = 0; b < vehicle.bodies.size(); ++b)
      if (vehicle.bodies[b].name == name) return static_cast<int>(b);
    return -1;
  };
  std::vector<WheelsetBogie> bogies(vehicle.bodies.size());
  for (const Wheelset& w : vehicle.wheelsets) {
    const int ws = index_of(w.body);
    const int carrier = model::wheelset_carrier(vehicle, w.body);
    if (ws >= 0 && carrier >= 0) bogies[carrier].wheelsets.push_back(ws);
  }
  std::vector<WheelsetBogie> out;
  for (size_t b = 0; b < bogies.size(); ++b) {
    if (bogies[b].wheelsets.size() < 2) continue;
    WheelsetBogie g = bogies[b];
    g.body = static_cast<int>(b);
    const double count = static_cast<double>(g.wheelsets.size());
    double mean = 0.0, square = 0.0;
    for (int w : g.wheelsets) mean += vehicle.bodies[w].centre_of_gravity.x() / count;
    for (int w : g.wheelsets) square += std::pow(vehicle.bodies[w].centre_of_gravity.x() - mean, 2) / count;
    g.axle_spread = std::sqrt(square);
    out.push_back(g);
  }
  return out;
}

std::vector<WheelsetBogie> wheelset_bogies(const Vehicle& vehicle) {
  std::vector<WheelsetBogie> out = wheelset_carriers(vehicle);
  if (out.size() < 2) out.clear();
  return out;
}

std::string root_name(const LinearSystem& system, const Eigen::VectorXcd& weighted_shape, bool oscillatory, bool twin) {
  const Eigen::VectorXd raw = weighted_shape.cwiseAbs2();
  if (raw.sum() == 0.0) return "series damper relaxation";
  const int bodies = static_cast<int>(system.vehicle.bodies.size());
  for (const Dof& d : system.dofs)
    if (d.body < 0 || d.body >= bodies) {  // matrices without bodies: the DOF with the most energy
      Eigen::Index most = 0;
      raw.maxCoeff(&most);
      return system.dofs[most].label;
    }
  // What moves most: the largest energy per unit of the body's mass, y² + k_roll²φ² + k_yaw²ψ²
  // with k the radii of gyration (by energy alone, a car body that follows its bogies would
  // name every low-speed mode of a bogie vehicle: it is ten times their mass).
  std::map<int, double> per_mass = energy_per_mass(system, raw);
  int lead = most_moving(per_mass);
  int key = -1;
  std::string words = words_of(system, raw, lead, oscillatory, &key);
  Eigen::VectorXd energy = raw;
  if (words == "hunting") {
    if (std::string by_bogie = bogie_hunting_name(system, weighted_shape, per_mass, lead); !by_bogie.empty())
      return by_bogie;
  } else {
    // A root that does not hunt is named as the undamped modes are: a wheelset's motion that its
    // carrier's rigid motion gives it counts for the carrier. Hunting is the exception: there
    // the carried wheelsets' lateral motion and yaw at the kinematic ratio are the creep forces'
    // oscillation itself, named "hunting" by the wheelsets or their bogies however rigidly
    // their frames carry them (a bogie hunting as a rigid bogie would be "bogie1 lateral/yaw").
    energy = carried_split(system, weighted_shape, raw);
    per_mass = energy_per_mass(system, energy);
    lead = most_moving(per_mass);
    lead = wheelsets_together(system, per_mass, lead);
    words = words_of(system, energy, lead, oscillatory, &key);
  }
  return with_twins(system, weighted_shape, energy, per_mass, lead, key, words, oscillatory, twin);
}

}  // namespace railmodal::stability
