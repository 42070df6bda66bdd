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
                                "' has a series damper, which only `railmodal stability` represents");
  }
}

std::vector<std::string> undamped_mode_notes(const LinearSystem& system) {
  std::vector<std::string> notes;
  if (!system.vehicle.wheelsets.empty())
    notes.push_back(
        "wheelsets: suspension modes only, without the wheel–rail contact terms (see `railmodal stability`)");
  const auto& elements = system.vehicle.elements;
  if (std::any_of(elements.begin(), elements.end(), [](const Element& e) { return !e.series_dampers.empty(); }))
    notes.push_back(
        "series dampers: left out of these modes, since they carry no static force (`railmodal stability` "
        "represents them)");
  return notes;
}

bool stands_on_wheelset(const Vehicle& vehicle, const Element& element) {
  return !element.lower.empty() && wheelset_of(vehicle, element.lower) != nullptr;
}

}  // namespace railmodal::model
