// The critical-speed study of a system assembled by the caller (a study's variant assembles its
// vertical system and the lateral stiffness of its metacentric height together).
#pragma once

#include <functional>
#include <vector>

#include "railmodal/critical_speed.hpp"
#include "solve/modal_solver.hpp"

namespace railmodal::response {

/// What a caller reads of each critical speed. `full`: everything find_critical_speeds gives.
/// `without_response`: the row without its steady response at the resonance (the direct
/// harmonic solve: `unbounded`, `amplitude` and `outputs` are left at their defaults), for a
/// caller that reads only the speeds, modes and friction criterion (a design variant's summary,
/// VariantResult::CriticalSpeedSummary). Every other field is the same bits as `full`'s. In exact
/// arithmetic the solve it leaves out cannot fail for a system that has modes: at ω > 0 the
/// dynamic stiffness bordered by the undamped modes at ω is regular (a null vector x would have
/// Cx = 0 and (K − ω²M)x = 0, an undamped mode at ω, which the border excludes). In floating
/// point its residual check could still refuse a nearly singular system; such a variant now
/// keeps its rows, which do not depend on that solve (deliberate: docs/studies.md, "What is
/// computed for each variant").
enum class ResonanceDetail { full, without_response };

/// find_critical_speeds with the rows' detail chosen.
std::vector<CriticalSpeed> find_critical_speeds_in(const LinearSystem& system, const ModalResult& modes,
                                                   const std::vector<const ExcitationSource*>& sources,
                                                   const CriticalSpeedOptions& options, ResonanceDetail detail,
                                                   AnalysisSummary* summary = nullptr);

/// study_critical_speeds(scene, vehicle, progress) with the vehicle's system in the scene's
/// dofs given by `assembled` (called where study_critical_speeds assembles, so that errors
/// come in the same order); the results are the same bit for bit.
CriticalSpeedStudy study_critical_speeds_of(const Scene& scene, const std::function<LinearSystem()>& assembled,
                                            const std::function<void(double)>& progress = {});

/// Whether the amplitude curves carry their phases (AmplitudeCurve::phases_deg). A design
/// study's variant reads only their amplitudes and leaves the phases out: an arg x and a
/// phase per speed and output, and an array per curve, fewer (issue 19, item 2).
enum class CurvePhases { kept, left_out };

/// What a caller reads of a critical-speed study. With `rows` without_response its critical
/// speeds are find_critical_speeds_in's rows without their response, found once, and the
/// study's own `summary` (stage times, method, checks) is left empty: a design variant's result
/// has a summary of its own and reads none of the study's. With `phases` left_out every curve's
/// phases_deg is empty. With `naming` deferred the modes are not named (solve::ModeNaming: every
/// Mode::name and CriticalSpeed::mode_name empty, but an unstable mode's in the error it throws):
/// the caller names what it reads (solve::name_mode, name_eigenspace).
/// Everything else is the same bits as the full study's.
struct StudyDetail {
  ResonanceDetail rows = ResonanceDetail::full;
  CurvePhases phases = CurvePhases::kept;
  solve::ModeNaming naming = solve::ModeNaming::now;
};

/// The same into `study` (default-constructed), taking the scene as given: a caller that owns
/// it moves it in instead of copying it. Where it throws, what `study` was given so far stays
/// there: its scene, and its system once `assembled` returned (a study's variant then
/// describes its failure from them, the vehicle having moved into the system). `detail` says
/// what the caller reads (StudyDetail); the default is everything.
void study_critical_speeds_into(Scene scene, const std::function<LinearSystem()>& assembled, CriticalSpeedStudy* study,
                                const std::function<void(double)>& progress = {}, StudyDetail detail = {});

}  // namespace railmodal::response
