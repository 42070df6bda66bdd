#include "model/analysis_limits.hpp"

#include <algorithm>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "model/wheelset_dofs.hpp"

namespace railmodal::model {

void refuse_series_dampers(const LinearSystem& system, const char* analysis) {
  // The rows, not the elements: a damper no kept motion stretches (a lateral one among the
  // vertical motions) changes nothing this system describes.
  for (const SeriesDamperRow& row : system.series_dampers) {
    const auto& elements = system.vehicle.elements;
    const std::string name = row.element >= 0 && row.element < static_cast<int>(elements.size())
                                 ? elements[static_cast<size_t>(row.element)].name
                                 : std::to_string(row.element);
    throw std::invalid_argument(std::string(analysis) + ": element '" + name +
                                "' has a series damper, which this analysis does not represent (the hunting "
                                "stability, the damped modes and the linear ride do)");
  }
}

namespace {

bool has_series_dampers(const Vehicle& vehicle) {
  return std::any_of(vehicle.elements.begin(), vehicle.elements.end(),
                     [](const Element& e) { return !e.series_dampers.empty(); });
}

std::vector<std::string> wheelset_notes(const LinearSystem& system) {
  if (system.vehicle.wheelsets.empty()) return {};
  return {"wheelsets: suspension modes only, without the wheel–rail contact terms (see `railmodal stability`)"};
}

// The friction of the vehicle's spring stages, named for their kind: "leaf friction φ = 0.075
// in 4 elements", "friction φ = 0.1 on the coil springs of 4 elements" (a three-piece bogie's
// wedges given as a coil stage's relative_friction, the user audit of 2026-11-28b); "" for none.
std::string friction_text(const Vehicle& vehicle) {
  struct Group {
    std::string kind;
    double phi;
    int elements;
  };
  std::vector<Group> groups;
  for (const Element& e : vehicle.elements)
    for (const SpringStage& s : e.vertical_stages) {
      if (!(s.relative_friction > 0.0)) continue;
      const bool leaf = s.kind == "leaf" || s.kind == "elliptic";  // friction between leaves
      const std::string kind = leaf ? "leaf" : s.kind;
      auto g = std::find_if(groups.begin(), groups.end(),
                            [&](const Group& x) { return x.kind == kind && x.phi == s.relative_friction; });
      if (g == groups.end()) g = groups.insert(groups.end(), {kind, s.relative_friction, 0});
      ++g->elements;  // the reader allows one friction stage per element
    }
  std::string text;
  for (const Group& g : groups) {
    std::ostringstream phi;
    phi << g.phi;
    const std::string elements = std::to_string(g.elements) + (g.elements == 1 ? " element" : " elements");
    text += (text.empty() ? "" : ", ") + (g.kind == "leaf" ? "leaf friction φ = " + phi.str() + " in " + elements
                                                           : "friction φ = " + phi.str() + " on the " + g.kind +
                                                                 " springs of " + elements);
  }
  return text;
}

// A vehicle's motions no stiffness holds (their rows of K, gravity's included, are exactly zero:
// no element reaches them), each a rigid-body mode: the lateral and yaw of a wagon without lateral
// springs, which the user audit of 2026-11-28b met without a word on why. "" for none.
std::string unheld_motions(const LinearSystem& system) {
  std::string labels;
  for (size_t i = 0; i < system.dofs.size(); ++i)
    if (system.dofs[i].body >= 0 && system.stiffness.row(static_cast<Eigen::Index>(i)).isZero(0.0))
      labels += (labels.empty() ? "" : ", ") + system.dofs[i].label;
  if (labels.empty()) return "";
  return "nothing holds " + labels +
         " (no element's spring reaches it): each is a rigid-body mode (λ = 0); a body without lateral stages "
         "or a hanger has a rigid-body lateral and yaw; give them for their frequencies, or ask for --dofs "
         "vertical";
}

}  // namespace

std::vector<std::string> undamped_mode_notes(const LinearSystem& system) {
  std::vector<std::string> notes = wheelset_notes(system);
  if (const std::string unheld = unheld_motions(system); !unheld.empty()) notes.push_back(unheld);
  if (has_series_dampers(system.vehicle))
    notes.push_back(
        "series dampers: left out of these modes, since they carry no static force (`railmodal modes --damped`, "
        "`railmodal stability` and `railmodal ride` represent them)");
  return notes;
}

std::vector<std::string> damped_mode_notes(const LinearSystem& system) {
  std::vector<std::string> notes = wheelset_notes(system);
  if (!system.series_dampers.empty())
    notes.push_back(
        "series dampers: in, each through the stroke of its dashpot, a first-order state whose root (near −k/c, "
        "τ = c/k for a damper on its own) is the mode 'series damper relaxation (element)'");
  // Friction is no viscous damping: a wagon damped by friction alone shows ζ = 0 here, which
  // without this note reads as an undamped wagon (the user audit of 2026-11-28b).
  if (const std::string friction = friction_text(system.vehicle); !friction.empty())
    notes.push_back("friction: not in C, so ζ is that of the viscous dampers alone (0 without any); the vehicle's "
                    "friction (" + friction +
                    ") acts in `critical-speed` (whether it stops a resonance), `simulate` and `ride` (docs/input.md, "
                    "\"Friction dampers\")");
  return notes;
}

bool stands_on_wheelset(const Vehicle& vehicle, const Element& element) {
  return !element.lower.empty() && wheelset_of(vehicle, element.lower) != nullptr;
}

}  // namespace railmodal::model
