// railmodal — the nonlinear-hunting report: the nonlinear critical speed (the lowest speed at
// which a hunting limit cycle survives) and its amplitude, the ramps at the stated and the halved
// rate with their convergence check, the confirmation by holding the speed, and the bifurcation
// plot (limit-cycle amplitude against speed) with the linear critical speed marked.
//
//   #include <railmodal/railmodal.hpp>
//   #include <iostream>
//
//   int main() {
//     railmodal::Scene scene = railmodal::load_scene("data/scenes/wheelset_on_springs_nonlinear_hunting.toml");
//     railmodal::Vehicle vehicle = railmodal::load_vehicle(scene.vehicle_file);
//     railmodal::LinearSystem system = railmodal::assemble(vehicle, railmodal::DofSet::lateral);
//     railmodal::NonlinearHuntingResult result = railmodal::solve_nonlinear_hunting(system, *scene.nonlinear_hunting);
//     railmodal::write_nonlinear_hunting(std::cout, result, *scene.nonlinear_hunting, railmodal::OutputFormat::table,
//                                        vehicle.name, railmodal::provenance_of({scene.source}));
//   }
#pragma once

#include <optional>
#include <ostream>
#include <string>

#include "railmodal/nonlinear_hunting.hpp"
#include "railmodal/output_format.hpp"
#include "railmodal/provenance.hpp"

namespace railmodal {

struct LimitCycleBranch;  // railmodal/limit_cycles.hpp

/// Writes `result` of solve_nonlinear_hunting run with `options` as a table (text), CSV (one row
/// per half cycle of each ramp: the bifurcation data), JSON (SI, km/h beside; a quantity the
/// result does not have is null), Markdown or HTML (with the bifurcation plot). `vehicle` names
/// the vehicle ("" writes "vehicle"); `provenance` lists the input files for the footer of the
/// Markdown and HTML pages; `linear_critical_speed` (m/s, from solve_hunting_stability), when
/// given, is printed beside the nonlinear one and marked on the plot at zero amplitude (the Hopf
/// point). `continuation`, when given (continue_limit_cycles, `railmodal hunting --continuation`),
/// adds the branch of limit cycles: a section with its points and fold in the formats for people,
/// the branch on the bifurcation plot (stable solid, unstable dashed), its points as rows of the
/// CSV (ramp "continuation", with four more columns) and a "continuation" object in the JSON;
/// without it the output is what it was. Throws std::invalid_argument for a format it does not write.
/// Why `result` is not_converged and what to change in `options` (the ramp rate, the end speed,
/// the holds), speeds in km/h, as one paragraph; "" when it is converged or not_applicable. The
/// reports put it under the verdict; `railmodal hunting` also writes it on stderr and exits 6.
std::string nonlinear_hunting_warning(const NonlinearHuntingResult& result, const NonlinearHuntingOptions& options);

void write_nonlinear_hunting(std::ostream& out, const NonlinearHuntingResult& result,
                             const NonlinearHuntingOptions& options, OutputFormat format, const std::string& vehicle,
                             const Provenance& provenance, std::optional<double> linear_critical_speed = std::nullopt,
                             const LimitCycleBranch* continuation = nullptr);

}  // namespace railmodal
