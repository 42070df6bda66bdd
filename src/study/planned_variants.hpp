// The variants a study plan defines, in study order: its variants as written, then each
// sweep's points (the full grid, or the seeded sample). Each is made when asked for, from its
// index (issue 19, item 2: a study of 10^6 variants holds no list of them).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "study/study_plan.hpp"
#include "xoshiro256.hpp"

namespace railmodal::study {

class PlannedVariants {
 public:
  explicit PlannedVariants(StudyPlan plan);

  size_t size() const { return size_; }
  /// Variant `index` (0 ... size() − 1): the same whenever it is asked for.
  VariantSpec at(size_t index) const;
  /// at(index) written into `into`, whose strings and lists serve again where they can (a
  /// study's worker reads each of its variants into one spec).
  void at_into(size_t index, VariantSpec* into) const;
  /// Its name alone, without drawing or writing its values.
  std::string name(size_t index) const;
  /// The first variant, in study order, whose name an earlier one has; none when the names
  /// are all different.
  std::optional<size_t> first_repeated_name() const;

  const StudyPlan& plan() const { return plan_; }

 private:
  // A sweep's points: where they start in the study, and for a sample the generator's state
  // every kCheckpoint points, so that a point is drawn from its checkpoint rather than from
  // the first point.
  struct Points {
    size_t sweep = 0;  ///< in plan_.sweeps (an index: a copy of the plan keeps it)
    size_t first = 0, count = 0;
    std::vector<Xoshiro256> checkpoints;
  };
  // 32 points: a point asked for draws on average 15.5 · P numbers to reach its own (256 made
  // every variant of a study cost about 4 k instructions for it), and the 32-byte states take
  // one byte a point: 1 MB at the limit of 10^6 variants.
  static constexpr size_t kCheckpoint = 32;
  const Points& points_of(size_t index) const;

  StudyPlan plan_;
  std::vector<Points> points_;
  size_t size_ = 0;
};

}  // namespace railmodal::study
