// The ranked comparison as rows of text, shared by the table, CSV and the Markdown/HTML report.
#pragma once

#include <string>
#include <vector>

#include "railmodal/study.hpp"

namespace railmodal::report {

/// Header then one row per variant in rank order: rank, variant, feasible, each criterion,
/// lowest critical speed, static deflection, periods (for_csv: exact numbers and the extra
/// columns objective, critical speeds, failure and violations).
std::vector<std::vector<std::string>> comparison_rows(const Comparison& comparison, bool for_csv);
/// One variant's row of comparison_rows (its rank is v.rank).
std::vector<std::string> comparison_row(const Ranking& ranking, const DeflectionRule& rule, const RankedVariant& v,
                                        bool for_csv);

}  // namespace railmodal::report
