// Wagon templates: a few keys in the book's terms generate bodies and elements.
#pragma once

#include "input/table_reader.hpp"
#include "railmodal/vehicle.hpp"

namespace railmodal::input {

/// Two-axle wagon (two-axle digest §2.0–2.4): one sprung body on four springs at
/// (±a1, ±b1) in the axle plane; its DOFs are taken at the centre of oscillation O, on the
/// vertical through the CG in the axle plane; the axlebox guides hold it laterally and in yaw.
void read_two_axle(TableReader& head, TableReader& root, Vehicle* v);

/// Bogie wagon with single, double or triple suspension and optional swing-hanger cradles
/// (bogie-wagons-natural digest §2.1–2.10).
void read_bogie(TableReader& head, TableReader& root, Vehicle* v);

}  // namespace railmodal::input
