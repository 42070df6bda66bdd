// railmodal — the report of a critical-speed study: Markdown, a self-contained HTML page with
// inline SVG plots, CSV and JSON.
//
//   #include <railmodal/railmodal.hpp>
//   #include <iostream>
//
//   int main() {
//     railmodal::Scene scene = railmodal::load_scene("data/scenes/resort_car_10m_rails.toml");
//     railmodal::Vehicle vehicle = railmodal::load_vehicle(scene.vehicle_file);
//     railmodal::CriticalSpeedStudy study = railmodal::study_critical_speeds(scene, vehicle);
//     railmodal::write_critical_speed_report(std::cout, study, railmodal::OutputFormat::markdown);
//   }
#pragma once

#include <ostream>

#include "railmodal/critical_speed.hpp"
#include "railmodal/output_format.hpp"
#include "railmodal/provenance.hpp"

namespace railmodal {

/// Writes markdown, html, csv or json (std::invalid_argument for table). The markdown and html
/// documents end with the railmodal version and `provenance`'s input files and their digests
/// (provenance_of({scene file, vehicle file})); {}: "input files not recorded". Every format
/// writes the notes (markdown and html "Note: …", csv "# note: …" lines, json "notes", absent
/// when there is none): what the modes leave out (ModalResult::notes) and, for a scene with a
/// kinematic-hunting source, that its critical speeds are resonances to a kinematic input and
/// that the stability critical speed (the onset of hunting) is `railmodal stability`'s; for a
/// scene with random track irregularity too, that `ride` takes it (it has no critical speeds).
void write_critical_speed_report(std::ostream& out, const CriticalSpeedStudy& study, OutputFormat format,
                                 const Provenance& provenance = {});

}  // namespace railmodal
