#include "model/analysis_limits.hpp"

#include <algorithm>
#include <stdexcept>

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

}  // namespace

std::vector<std::string> undamped_mode_notes(const LinearSystem& system) {
  std::vector<std::string> notes = wheelset_notes(system);
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
  return notes;
}

bool stands_on_wheelset(const Vehicle& vehicle, const Element& element) {
  return !element.lower.empty() && wheelset_of(vehicle, element.lower) != nullptr;
}

}  // namespace railmodal::model
