// The critical-speed study of a system assembled by the caller (a study's variant assembles its
// vertical system and the lateral stiffness of its metacentric height together).
#pragma once

#include <functional>

#include "railmodal/critical_speed.hpp"

namespace railmodal::response {

/// study_critical_speeds(scene, vehicle, progress) with the vehicle's system in the scene's
/// dofs given by `assembled` (called where study_critical_speeds assembles, so that errors
/// come in the same order); the results are the same bit for bit.
CriticalSpeedStudy study_critical_speeds_of(const Scene& scene, const std::function<LinearSystem()>& assembled,
                                            const std::function<void(double)>& progress = {});

/// Whether the amplitude curves carry their phases (AmplitudeCurve::phases_deg). A design
/// study's variant reads only their amplitudes and leaves the phases out: an arg x and a
/// phase per speed and output, and an array per curve, fewer (issue 19, item 2).
enum class CurvePhases { kept, left_out };

/// The same into `study` (default-constructed), taking the scene as given: a caller that owns
/// it moves it in instead of copying it. Where it throws, what `study` was given so far stays
/// there: its scene, and its system once `assembled` returned (a study's variant then
/// describes its failure from them, the vehicle having moved into the system). With
/// CurvePhases::left_out every curve's phases_deg is empty; everything else is the same bits.
void study_critical_speeds_into(Scene scene, const std::function<LinearSystem()>& assembled, CriticalSpeedStudy* study,
                                const std::function<void(double)>& progress = {},
                                CurvePhases phases = CurvePhases::kept);

}  // namespace railmodal::response
