// The study's periods' notes, said once by compare (Study::notes).
#include "study/period_notes.hpp"

#include <algorithm>
#include <exception>

#include "model/analysis_limits.hpp"

namespace railmodal::study {

std::vector<std::string> period_notes(const std::vector<const Vehicle*>& vehicles, DofSet dofs) {
  std::vector<std::string> notes;
  for (const Vehicle* vehicle : vehicles) {
    std::vector<std::string> of_vehicle;
    try {
      of_vehicle = model::undamped_mode_notes(assemble(*vehicle, dofs));
    } catch (const std::exception&) {
      continue;  // its variants report what is wrong
    }
    for (const std::string& n : of_vehicle) {
      const std::string note = "periods [s], as `railmodal modes` notes them: " + n;
      if (std::find(notes.begin(), notes.end(), note) == notes.end()) notes.push_back(note);
    }
  }
  return notes;
}

}  // namespace railmodal::study
