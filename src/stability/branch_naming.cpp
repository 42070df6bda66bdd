// Root names for the hunting branches (see branch_naming.hpp).
#include "stability/branch_naming.hpp"

#include <algorithm>
#include <cctype>
#include <map>
#include <vector>

namespace railmodal::stability {

namespace {

// "bogie1" → "bogie 1"; "wheelset_2" and "body" stay as they are.
std::string spoken(const std::string& name) {
  size_t digits = name.size();
  while (digits > 0 && std::isdigit(static_cast<unsigned char>(name[digits - 1]))) --digits;
  if (digits == 0 || digits == name.size() || !std::isalpha(static_cast<unsigned char>(name[digits - 1]))) return name;
  return name.substr(0, digits) + " " + name.substr(digits);
}

bool is_wheelset(const LinearSystem& system, const std::string& body) {
  return std::any_of(system.vehicle.wheelsets.begin(), system.vehicle.wheelsets.end(),
                     [&](const Wheelset& w) { return w.body == body; });
}

}  // namespace

std::string root_name(const LinearSystem& system, const Eigen::VectorXcd& weighted_shape) {
  const int n = system.size();
  const Eigen::VectorXd energy = weighted_shape.cwiseAbs2();
  if (energy.sum() == 0.0) return "series damper";
  const int bodies = static_cast<int>(system.vehicle.bodies.size());
  std::map<int, double> body_energy;
  for (int i = 0; i < n; ++i) {
    const int b = system.dofs[i].body;
    if (b < 0 || b >= bodies) {  // matrices without bodies: the DOF with the most energy
      Eigen::Index most = 0;
      energy.maxCoeff(&most);
      return system.dofs[most].label;
    }
    body_energy[b] += energy(i);
  }
  // What moves most: the largest energy per unit of the body's mass, y² + k_roll²φ² + k_yaw²ψ²
  // with k the radii of gyration (by energy alone, a car body that follows its bogies would
  // name every low-speed mode of a bogie vehicle: it is ten times their mass).
  int body = body_energy.begin()->first;
  double most = -1.0;
  for (const auto& [b, e] : body_energy) {
    const double mass = system.vehicle.bodies[b].mass;
    const double per_mass = mass > 0.0 ? e / mass : e;
    if (per_mass > most) most = per_mass, body = b;
  }
  const double total = body_energy[body];
  std::vector<std::pair<double, Motion>> motions;
  for (int i = 0; i < n; ++i)
    if (system.dofs[i].body == body) motions.push_back({energy(i), system.dofs[i].motion});
  std::stable_sort(motions.begin(), motions.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  const std::string& name = system.vehicle.bodies[body].name;
  if (is_wheelset(system, name)) {
    double lateral = 0.0, yaw = 0.0;
    for (const auto& m : motions) {
      if (m.second == Motion::lateral) lateral += m.first;
      if (m.second == Motion::yaw) yaw += m.first;
    }
    if (lateral >= 0.01 * total && yaw >= 0.01 * total) return spoken(name) + " hunting";
  }
  std::string words;
  for (const auto& m : motions)
    if (m.first >= 0.25 * total) words += (words.empty() ? "" : "/") + std::string(to_string(m.second));
  return spoken(name) + " " + words;
}

}  // namespace railmodal::stability
