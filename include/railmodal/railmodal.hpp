// railmodal — modal analysis of railway wagons. Include this one header.
//
//   #include <railmodal/railmodal.hpp>
//   #include <iostream>
//
//   int main() {
//     railmodal::Vehicle vehicle = railmodal::load_vehicle("data/vehicles/resort_car.toml");
//     railmodal::LinearSystem system = railmodal::assemble(vehicle, railmodal::DofSet::all);
//     railmodal::ModalResult result = railmodal::solve_modes(system);
//     for (const railmodal::Mode& mode : result.modes)
//       std::cout << mode.name << ": " << mode.frequency_hz << " Hz, " << mode.period_s << " s\n";
//   }
#pragma once

#include "railmodal/balance.hpp"
#include "railmodal/balance_report.hpp"
#include "railmodal/comfort_weighting.hpp"
#include "railmodal/comparison_report.hpp"
#include "railmodal/critical_speed.hpp"
#include "railmodal/critical_speed_report.hpp"
#include "railmodal/damped_modal.hpp"
#include "railmodal/driving_gear.hpp"
#include "railmodal/errors.hpp"
#include "railmodal/excitation.hpp"
#include "railmodal/fft_check_report.hpp"
#include "railmodal/hunting.hpp"
#include "railmodal/hunting_report.hpp"
#include "railmodal/input.hpp"
#include "railmodal/limit_cycles.hpp"
#include "railmodal/linear_system.hpp"
#include "railmodal/matrix_market.hpp"
#include "railmodal/modal.hpp"
#include "railmodal/nonlinear_hunting.hpp"
#include "railmodal/nonlinear_hunting_report.hpp"
#include "railmodal/output_format.hpp"
#include "railmodal/provenance.hpp"
#include "railmodal/report.hpp"
#include "railmodal/response.hpp"
#include "railmodal/ride.hpp"
#include "railmodal/ride_report.hpp"
#include "railmodal/ride_simulation.hpp"
#include "railmodal/scene.hpp"
#include "railmodal/scene_simulation.hpp"
#include "railmodal/simulation.hpp"
#include "railmodal/simulation_report.hpp"
#include "railmodal/sparse_system.hpp"
#include "railmodal/spectrum.hpp"
#include "railmodal/stability.hpp"
#include "railmodal/study.hpp"
#include "railmodal/summary.hpp"
#include "railmodal/track_spectrum.hpp"
#include "railmodal/vehicle.hpp"
#include "railmodal/version.hpp"
#include "railmodal/wheel_rail.hpp"
