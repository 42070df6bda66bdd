// What a study varies (docs/studies.md): its variants as written, its sweeps and samples, and
// how it ranks them, before any variant is listed or read. The study reader
// (src/input/study_reader.cpp) fills it from the study file; planned_variants
// (study/planned_variants.hpp) lists the variants it defines. Types only: the reader includes
// this header and nothing else of the study layer.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "railmodal/study.hpp"

namespace railmodal::study {

/// Where the study file writes something, for messages.
struct Place {
  int line = 0, column = 0;
};

/// A number as the study writes it: 40, 40.0 or "40 mm". A value drawn from a sample's
/// interval is written like the interval's lower end.
struct WrittenNumber {
  double number = 0.0;
  std::string unit;  ///< "" for a bare number
  bool integer = false;
  /// As shown in names and reports: "40 mm", "40", "0.25" (the shortest text that reads back).
  std::string text() const;
  /// text() written into `text` (its storage reused).
  void write_text(std::string* text) const;
};

/// A value written in the study file (an override's or a swept value): its text, and its
/// index among the values the reader keeps as written.
struct WrittenValue {
  std::string text;
  int index = 0;
};

/// One key a variant sets: to a value the study writes, or to one drawn from an interval.
struct Assignment {
  std::string key;      ///< key path in the vehicle file (or the scene file)
  bool scene = false;   ///< a key of the scene file
  Place place;          ///< where the study writes the key (or the sweep its parameter)
  std::string text;     ///< the value as shown in names and reports
  int written = -1;     ///< WrittenValue::index; -1: the value is `drawn`
  WrittenNumber drawn;
};

/// One variant: a vehicle file and the keys it sets in it and in the scene.
struct VariantSpec {
  std::string name;
  Place place;
  std::string vehicle_file;
  std::vector<StudyParameter> parameters;  ///< what sets it apart, as Study lists it
  std::vector<Assignment> assignments;     ///< in the order they are written into the files
};

/// One parameter of a sweep: the values of a grid (a list, or a range stepped through) or the
/// interval a sample draws from.
struct SweepParameter {
  std::string key;
  bool scene = false;
  std::string label;  ///< in grid variant names: "f = 40 mm"
  Place place;
  std::vector<WrittenValue> values;  ///< grid
  WrittenNumber from, to;           ///< sample
};

struct Sweep {
  std::string name;
  int line = 0;  ///< of its parameters
  std::vector<SweepParameter> parameters;
  int samples = 0;  ///< > 0: that many points drawn from the parameters' intervals; 0: the full grid
  uint64_t seed = 0;
};

struct StudyPlan {
  std::string name;
  std::string vehicle_file;               ///< the base vehicle, which sweeps vary
  std::vector<VariantSpec> variants;      ///< the base (unless base = false) and each [[variant]]
  std::vector<Sweep> sweeps;
  Ranking ranking;
  DeflectionRule deflection_rule;
};

}  // namespace railmodal::study
