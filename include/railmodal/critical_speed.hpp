// railmodal — the critical-speed study of one vehicle in one scene: its modes, the speeds at
// which the scene's sources excite them, and the amplitude of its outputs against speed.
//
//   #include <railmodal/railmodal.hpp>
//   #include <iostream>
//
//   int main() {
//     railmodal::Scene scene = railmodal::load_scene("data/scenes/resort_car_10m_rails.toml");
//     railmodal::CriticalSpeedStudy study =
//         railmodal::study_critical_speeds(scene, railmodal::load_vehicle(scene.vehicle_file));
//     for (const railmodal::CriticalSpeed& c : study.critical_speeds)
//       std::cout << c.mode_name << ": " << 3.6 * c.speed << " km/h\n";
//   }
#pragma once

#include <functional>
#include <vector>

#include "railmodal/linear_system.hpp"
#include "railmodal/modal.hpp"
#include "railmodal/response.hpp"
#include "railmodal/scene.hpp"
#include "railmodal/summary.hpp"
#include "railmodal/vehicle.hpp"

namespace railmodal {

struct CriticalSpeedStudy {
  Scene scene;
  LinearSystem system;
  ModalResult modes;
  std::vector<CriticalSpeed> critical_speeds;  ///< sorted by speed
  std::vector<AmplitudeCurve> curves;          ///< per source and output, on the scene's grid
  /// Damped resonance peaks of the curves: every local maximum of the grid above 1 % of the
  /// curve's largest value, refined by golden-section search to 1e-6 of its speed.
  struct CurvePeak {
    int curve = 0;  ///< index into curves
    Peak peak;
  };
  std::vector<CurvePeak> peaks;
  /// What was computed and how, the modes' residual and the unbounded curve points, and the
  /// wall time of each stage (assembly and modes, critical speeds, amplitude curves, peak
  /// refinement). No report writes it.
  AnalysisSummary summary;
};

/// `grid` (m/s; sorted if it is not ascending) with the speed of every row put in its place,
/// without repeats: the grid study_critical_speeds sweeps (its scene's step and every critical
/// speed). An undamped resonance is then a point of the sweep, where amplitude_curves flags it
/// unbounded; on a grid without it the resonance falls between two speeds and shows as a
/// finite peak whose height depends on how near they fall (6.35 m on one grid, 9.96 m on one a
/// point coarser: user audit 2026-11-28b, F7).
std::vector<double> grid_with_critical_speeds(const std::vector<double>& grid, const std::vector<CriticalSpeed>& rows);

/// Assembles the vehicle in the scene's DOF set, solves its modes, finds the critical speeds
/// of the scene's sources in its speed range and the amplitude curves of its outputs (or, if
/// it names none, of the most energetic DOF of each excited mode). The speed grid holds the
/// scene's step and every critical speed.
/// `progress`, if given, is called with the fraction done (0…1) as the sweep advances (the
/// command line shows it on a terminal when a study takes over a second). Throws
/// NumericalError for a vehicle with an unstable mode: it has no steady response, and
/// std::invalid_argument, before the sweep and with the estimate, for curves of more than 10⁷
/// points (sources × outputs × speeds of the grid; docs/input.md, "Resource limits").
CriticalSpeedStudy study_critical_speeds(const Scene& scene, const Vehicle& vehicle,
                                         const std::function<void(double)>& progress = {});

}  // namespace railmodal
