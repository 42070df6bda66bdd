// The parts of rank_variants (ranking.cpp) that a streamed ranking (streamed_ranking.cpp) uses
// one variant at a time: the variant's place before its rank is known, the check that the
// metrics name modes the variants have, and which variant is the base.
#pragma once

#include <set>
#include <string>
#include <vector>

#include "railmodal/study.hpp"

namespace railmodal::study {

/// Sets v's feasible, violations, criteria and objective for result `r` (v->result and
/// v->rank are left as they are) and returns its sort key without the study order: the group
/// (0 feasible, 1 infeasible, 2 failed), then the weighted sum or each criterion, smaller
/// first (a failed variant's key is its group alone).
std::vector<double> rank_entry(const VariantResult& r, const Ranking& ranking, RankedVariant* v);

/// Throws InputError at the study's key when a metric names a mode (period:<mode>,
/// critical_speed:<mode>) that is not among `modes`, the names of the evaluated variants'
/// modes; nothing is checked when no variant was evaluated (`evaluated` false).
void check_mode_names(const Study& study, const std::set<std::string>& modes, bool evaluated);

/// Whether `r` is the study's base design (comparison_base picks it): variant 0, named "base",
/// overriding nothing.
bool is_base(const VariantResult& r);

}  // namespace railmodal::study
