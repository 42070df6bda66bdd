// railmodal — the hunting-stability report: root locus, damping ratio against speed, the
// critical speed and its intervals, and the critical speed against conicity.
//
//   #include <railmodal/railmodal.hpp>
//   #include <iostream>
//
//   int main() {
//     auto vehicle = railmodal::load_vehicle("data/vehicles/wheelset_on_springs.toml");
//     auto system = railmodal::assemble(vehicle, railmodal::DofSet::lateral);
//     auto result = railmodal::solve_hunting_stability(system);
//     railmodal::write_hunting_stability(std::cout, result, railmodal::OutputFormat::markdown);
//   }
#pragma once

#include <ostream>
#include <string>

#include "railmodal/hunting.hpp"
#include "railmodal/output_format.hpp"
#include "railmodal/provenance.hpp"

namespace railmodal {

/// Writes the result as a table (text), CSV (one row per branch and speed), JSON, Markdown or
/// HTML (with SVG plots: root locus coloured by speed, ζ against speed with the critical speed
/// marked, critical speed against conicity). Throws std::invalid_argument for another format.
void write_hunting_stability(std::ostream& out, const HuntingResult& result, OutputFormat format);
/// The same with the report's title, `vehicle` (the vehicle's name; "" writes "vehicle"), and the
/// input files for the footer of the Markdown and HTML pages (empty: "input files not recorded").
void write_hunting_stability(std::ostream& out, const HuntingResult& result, OutputFormat format,
                             const std::string& vehicle, const Provenance& provenance);

}  // namespace railmodal
