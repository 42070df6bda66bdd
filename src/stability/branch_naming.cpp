// Root names for the hunting branches (see branch_naming.hpp).
#include "stability/branch_naming.hpp"

#include <algorithm>
#include <complex>
#include <map>
#include <vector>

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

// The DOF of `body`'s lateral motion in the system, −1 when it has none.
int lateral_dof_of(const LinearSystem& system, int body) {
  for (int i = 0; i < system.size(); ++i)
    if (system.dofs[i].body == body && system.dofs[i].motion == Motion::lateral) return i;
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
      const int dof = lateral_dof_of(system, w);
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

std::string root_name(const LinearSystem& system, const Eigen::VectorXcd& weighted_shape, bool oscillatory) {
  const int n = system.size();
  const Eigen::VectorXd energy = weighted_shape.cwiseAbs2();
  if (energy.sum() == 0.0) return "series damper relaxation";
  const int bodies = static_cast<int>(system.vehicle.bodies.size());
  std::map<int, double> per_mass;
  for (int i = 0; i < n; ++i) {
    const int b = system.dofs[i].body;
    if (b < 0 || b >= bodies) {  // matrices without bodies: the DOF with the most energy
      Eigen::Index most = 0;
      energy.maxCoeff(&most);
      return system.dofs[most].label;
    }
    const double mass = system.vehicle.bodies[b].mass;
    per_mass[b] += mass > 0.0 ? energy(i) / mass : energy(i);
  }
  // What moves most: the largest energy per unit of the body's mass, y² + k_roll²φ² + k_yaw²ψ²
  // with k the radii of gyration (by energy alone, a car body that follows its bogies would
  // name every low-speed mode of a bogie vehicle: it is ten times their mass).
  int lead = per_mass.begin()->first;
  for (const auto& [b, e] : per_mass)
    if (e > per_mass[lead]) lead = b;
  int key = -1;
  const std::string words = words_of(system, energy, lead, oscillatory, &key);
  const std::string& name = system.vehicle.bodies[lead].name;
  if (words == "hunting")
    if (std::string by_bogie = bogie_hunting_name(system, weighted_shape, per_mass, lead); !by_bogie.empty())
      return by_bogie;
  // Twin bodies (bogie1/bogie2, wheelset1…wheelset4) that move at least half as much as the
  // leading one share the mode: name the family and the phase of the key motion, "in phase"
  // when every such twin's is within 90° of the leading body's. Which of two nearly equal
  // bogies leads is otherwise decided by round-off (0.71 of one bogie's yaw, 0.70 of the other's).
  // The twins are listed by their names as written, in the vehicle's order, joined by "+"
  // ("bogie1+bogie2 yaw, antiphase"): a plural made from the family ("wss" from ws1, ws2)
  // would mangle names that are not English words.
  const std::string family = solve::family_of(name);
  bool in_phase = true;
  std::string twins;
  if (!family.empty() && family != name)
    for (const auto& [b, e] : per_mass) {
      const std::string& other = system.vehicle.bodies[b].name;
      int twin_key = key;
      if (b != lead && (e < 0.5 * per_mass[lead] || solve::family_of(other) != family ||
                        words_of(system, energy, b, oscillatory, &twin_key) != words))
        continue;
      twins += (twins.empty() ? "" : "+") + other;
      in_phase = in_phase && std::real(weighted_shape(key) * std::conj(weighted_shape(twin_key))) >= 0.0;
    }
  if (twins != name && !twins.empty()) return twins + " " + words + ", " + (in_phase ? "in phase" : "antiphase");
  return name + " " + words;
}

}  // namespace railmodal::stability
