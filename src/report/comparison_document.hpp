// The design comparison as a document (comparison_document.cpp) written from what it needs of
// every variant, not from every variant whole: the best few and the base whole, counts, and a
// small sweep point per evaluated variant that may wait in a file (issue 19, item 2). A study of
// 10^6 variants is reported in the memory of its ranking keys.
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "railmodal/output_format.hpp"
#include "railmodal/provenance.hpp"
#include "railmodal/study.hpp"

namespace railmodal::report {

/// What the swept-parameter charts and tables take of one evaluated variant.
struct SweepPoint {
  bool feasible = false;
  std::optional<double> ranked;  ///< the value ranked first: the weighted sum or the first criterion, SI
  std::vector<std::pair<std::string, std::string>> parameters;  ///< key and value as the variant writes them
  std::vector<std::pair<std::string, double>> periods;  ///< each oscillatory mode's name and period [s], in order
};

/// The sweep point of an evaluated variant (v.result.ok()).
SweepPoint sweep_point(const RankedVariant& v, const Ranking& ranking);
/// A sweep point as bytes, and back: the same numbers bit for bit.
std::string to_bytes(const SweepPoint& point);
SweepPoint sweep_point_from_bytes(const std::string& bytes);

/// What the document counts over every variant.
struct DocumentTally {
  size_t variants = 0, feasible = 0, failed = 0;
  std::vector<size_t> violating;  ///< per constraint of the ranking: evaluated variants outside it
  /// The first failed variant in rank order (failed variants rank in study order: the lowest
  /// index): its index, name and failure.
  std::optional<int> failed_index;
  std::string failed_name, failure;
  /// Counts `v` (in any order; not thread-safe).
  void add(const RankedVariant& v, const Ranking& ranking);
};

/// Calls its argument with the sweep point of each evaluated variant, in study order; the
/// document calls it twice.
using SweepPoints = std::function<void(const std::function<void(const SweepPoint&)>& visit)>;

/// Writes the Markdown or HTML document of a study whose ranking `best` holds only its best
/// variants (at least kReportRows of them, or all) in rank order, with the base design after
/// them if it ranks lower; `tally` and `points` speak for every variant. The bytes are those
/// write_comparison_report writes of the whole comparison.
void write_comparison_document(std::ostream& out, const Study& study, const Comparison& best,
                               const DocumentTally& tally, const SweepPoints& points, const ComparisonCurves& curves,
                               OutputFormat format, const Provenance& provenance);

}  // namespace railmodal::report
