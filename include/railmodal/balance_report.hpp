// railmodal — the report of `railmodal balance`: the driving gear's forces every 15° like
// Zhdanov's tables, their harmonics, the counterweights by each vertical rule with α, surging and
// nosing after balancing, the speeds at which α reaches the book's limits, and the trade-off of α
// against the fraction of reciprocating mass balanced (docs/driving_gear.md, "The report").
//
//   #include <railmodal/railmodal.hpp>
//   #include <iostream>
//
//   int main() {
//     railmodal::DrivingGear gear = railmodal::load_driving_gear("data/locomotives/su.toml");
//     railmodal::BalanceOptions options;
//     options.allowed_alpha = 0.3;
//     railmodal::BalanceStudy study = railmodal::study_balance(gear, gear.design_speed, options);
//     railmodal::write_balance(std::cout, study, railmodal::OutputFormat::markdown);
//   }
#pragma once

#include <ostream>

#include "railmodal/balance.hpp"
#include "railmodal/output_format.hpp"
#include "railmodal/provenance.hpp"

namespace railmodal {

/// Writes `study` in any OutputFormat: table (aligned text), markdown and html (the tables, and in
/// html the plots of the wheel loads and of surging and nosing against crank angle), in kN, kN·m,
/// kg on the crank radius and degrees ahead of the wheel's crank; csv (one long table, a row per
/// number with its section, rule, item, quantity and SI unit) and json (a tree whose keys carry
/// their SI units), both at full precision with harmonics as amplitude and phase
/// (docs/driving_gear.md, "The report"). `inputs`: the files read, for the HTML footer ({}: not
/// recorded).
void write_balance(std::ostream& out, const BalanceStudy& study, OutputFormat format, const Provenance& inputs = {});

}  // namespace railmodal
