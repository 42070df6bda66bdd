// The ranked comparison as rows of text for people, shared by the table and the Markdown/HTML report.
#pragma once

#include <string>
#include <vector>

#include "railmodal/study.hpp"

namespace railmodal::report {

/// The table's header then one row per variant in rank order, for people: rank, variant,
/// feasible, each criterion, lowest critical speed, static deflection, the largest dynamic
/// deflection (with a deflection rule), periods. (The CSV's rows, for programs, are written
/// straight into its text: comparison_report.cpp.)
std::vector<std::vector<std::string>> comparison_rows(const Comparison& comparison);

}  // namespace railmodal::report
