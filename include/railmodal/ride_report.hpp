// railmodal — the ride report: per output and speed the RMS, the EN 12299 weighted RMS and its
// estimated 95th percentile, Sperling's Wz, N_MV per floor point and the dominant modes; the
// HTML page plots the input and output PSDs (log–log, natural frequencies marked) and the
// indices against speed, and for a time-domain run the weighted acceleration with its 5 s
// windows.
//
//   #include <railmodal/railmodal.hpp>
//   #include <iostream>
//
//   int main() {
//     using namespace railmodal;
//     const LinearSystem system =
//         assemble(load_vehicle("data/vehicles/manchester_benchmark_coach.toml"), DofSet::vertical);
//     TrackIrregularitySpectra track;
//     track.vertical_level = TrackSpectrum::ore_b176(OreLevel::low, TrackIrregularity::vertical_level,
//                                                    {2 * 3.14159265358979 / 100, 2 * 3.14159265358979 / 3});
//     RideOptions options;
//     options.speeds = {160 / 3.6};
//     write_ride(std::cout, solve_ride(system, track, default_ride_outputs(system), options),
//                OutputFormat::markdown);
//   }
#pragma once

#include <ostream>
#include <string>

#include "railmodal/output_format.hpp"
#include "railmodal/provenance.hpp"
#include "railmodal/ride.hpp"
#include "railmodal/ride_simulation.hpp"

namespace railmodal {

/// Writes the frequency-domain ride (and, when `simulated` is given, the time-domain run and its
/// FFT checks) as a table, CSV, JSON, Markdown or HTML. Throws std::invalid_argument for another
/// format.
void write_ride(std::ostream& out, const RideResult& result, OutputFormat format,
                const RideSimulationResult* simulated = nullptr, const RideFftChecks* checks = nullptr);
/// The same with the report's title and input files for the footer (as write_hunting_stability).
void write_ride(std::ostream& out, const RideResult& result, OutputFormat format, const std::string& title,
                const Provenance& provenance, const RideSimulationResult* simulated = nullptr,
                const RideFftChecks* checks = nullptr);

/// Writes the spectra behind the RMS as CSV (`railmodal ride --spectra FILE`), for plotting in
/// another tool: one row per speed and frequency of RideResult::frequencies, the columns
/// "speed [km/h]", "frequency [Hz]", each track input's PSD ("<input> input psd [m²/Hz]", in
/// RideResult::inputs order) and each output's ("<output> psd [(m/s²)²/Hz]", its unit squared
/// per Hz), one-sided, numbers in full precision. A value the result does not hold (an unbounded
/// output's, spectra not kept: RideOptions::keep_spectra) is a blank field.
void write_ride_spectra(std::ostream& out, const RideResult& result);

}  // namespace railmodal
