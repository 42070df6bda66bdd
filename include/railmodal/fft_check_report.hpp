// railmodal — the report of an fft-check: the spectral peaks of a scene's simulated response
// against the modal frequencies, as a table, CSV, JSON or a self-contained HTML page.
//
//   #include <railmodal/railmodal.hpp>
//   #include <iostream>
//
//   int main() {
//     railmodal::Scene scene = railmodal::load_scene("data/scenes/resort_car_free_response.toml");
//     railmodal::Vehicle vehicle = railmodal::load_vehicle(scene.vehicle_file);
//     railmodal::FftCheckResult result = railmodal::fft_check(scene, vehicle);
//     railmodal::write_fft_check(std::cout, result, scene, vehicle, railmodal::OutputFormat::table);
//   }
#pragma once

#include <ostream>
#include <string>

#include "railmodal/output_format.hpp"
#include "railmodal/provenance.hpp"
#include "railmodal/scene_simulation.hpp"
#include "railmodal/vehicle.hpp"

namespace railmodal {

/// Writes table, csv, json or html (std::invalid_argument for markdown).
///   table: the checks (mode, DOF, modal and peak frequency, relative error, resolution and
///   whether the peak lies within it, or why there is none), below a header that warns of each
///   part of the vehicle the scene's effects leave out (unsimulated_parts), and, for a nonlinear scene, the
///   half periods between the turning points and between passes through the static position.
///   csv: one row per check: mode, mode_name, dof, undamped_frequency [Hz],
///   damped_frequency [Hz] (the frequency checked), damping_ratio, peak_frequency [Hz], rel_error,
///   resolution [Hz], within_resolution, excited, modal_amplitude_ratio, tolerance, outcome
///   (passed, failed, not excited, not resolved, no line), checked, passed, and the whole
///   record's verdict (passed, FAILED, not checked) on every row (no peak: blank).
///   json: {"scene", "checks": [{the csv's columns, keyed mode_name, undamped_frequency_hz,
///   damped_frequency_hz, peak_frequency_hz,
///   resolution_hz, …; no peak: null}], "nonlinear", "compared", "checked" (false: nothing
///   could be checked), "checks_made", "checks_failed", "passed", "verdict" (as the csv's),
///   "verdict_text" (fft_check_verdict), "unsimulated_parts" (unsimulated_parts' sentences; [] when
///   the scene simulates every part), and for a nonlinear scene
///   "half_periods": {"dof", "linear_half_period_s", "between_turning_points_s",
///   "between_crossings_s", "turning_points": [{"time_s", "displacement"}], "comes_to_rest"}}.
///   html: a self-contained page (inline SVG, no scripts): the displacement histories of the
///   DOFs whose spectra were taken, translations (mm) and rotations (mrad) on charts of their
///   own (below the warnings of unsimulated_parts), with the stick/slip/kink events marked when there are few enough to see; each
///   spectrum up to 1.5× the highest checked mode with every modal frequency as a vertical
///   line; the check table and the half-period table. The page ends with the railmodal
///   version and `provenance`'s input files with their digests.
/// `vehicle` names the page's vehicle.
void write_fft_check(std::ostream& out, const FftCheckResult& result, const Scene& scene, const Vehicle& vehicle,
                     OutputFormat format, const Provenance& provenance = {});

/// The verdict of all the checks in words, as every report ends: "FAILED: 2 of 6 modes
/// checked, 1 outside its tolerance; …", "passed: 1 of 6 modes checked, within 5.0 %; 5 not
/// checked (5 no line)" or "NOT CHECKED: no mode's line could be checked (2 not resolved: a run
/// of at least 31 s)". "Not checked" is neither a pass nor a failure.
std::string fft_check_verdict(const FftCheckResult& result);

}  // namespace railmodal
