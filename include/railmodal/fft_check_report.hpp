// The fft-check as a page: time histories, spectra with the modal frequencies marked, the
// checks and (nonlinear scenes) the half periods, in one self-contained HTML file.
//
//   #include <railmodal/railmodal.hpp>
//   #include <fstream>
//
//   int main() {
//     railmodal::Scene scene = railmodal::load_scene("data/scenes/resort_car_free_response.toml");
//     railmodal::Vehicle vehicle = railmodal::load_vehicle(scene.vehicle_file);
//     std::ofstream page("/dev/null");  // a file name such as fft_check.html
//     railmodal::write_fft_check_html(page, railmodal::fft_check(scene, vehicle), scene, vehicle);
//   }
#pragma once

#include <ostream>

#include "railmodal/scene_simulation.hpp"
#include "railmodal/vehicle.hpp"

namespace railmodal {

/// Writes a self-contained HTML page (inline SVG, no scripts): the displacement histories of
/// the DOFs whose spectra were taken (with the stick/slip/kink events marked when there are
/// few enough to see), each spectrum up to 1.5× the highest checked mode with every modal
/// frequency as a vertical line, the check table and the half-period table.
void write_fft_check_html(std::ostream& out, const FftCheckResult& result, const Scene& scene, const Vehicle& vehicle);

}  // namespace railmodal
