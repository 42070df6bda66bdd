// Warnings of the readers: inputs that can be meant but are unusual (docs/input.md,
// "Implausible inputs"), accepted, and said on stderr by the command line. Errors are for
// inputs that cannot be meant; a warning changes no result and no output file.
#pragma once

#include <string>
#include <vector>

namespace railmodal::input {

class TableReader;

/// While alive, the warnings of the reader run on this thread go to `*into` (a study reads its
/// variants on several threads). Nested collectors stack; without one, or with `into` null,
/// warnings are not made.
class WarningCollector {
 public:
  explicit WarningCollector(std::vector<std::string>* into);
  ~WarningCollector();
  WarningCollector(const WarningCollector&) = delete;
  WarningCollector& operator=(const WarningCollector&) = delete;

 private:
  std::vector<std::string>* previous_;
};

/// "file:line:col: warning: key 'a.b': message", at `key` of `t`, to this thread's collector.
void warn_at(TableReader& t, const std::string& key, const std::string& message);
/// "file:line:col: warning: message" to this thread's collector.
void warn(const std::string& file, int line, int column, const std::string& message);

/// The bands of lengths a reader accepts without a warning, m (docs/input.md, "Implausible
/// inputs", where each is justified from the book digests).
struct LengthBand {
  double low;
  double high;
  const char* what;  ///< "a swing hanger's length (the book's 230–650 mm)"
};
/// A swing hanger: the book's 230–650 mm "and more" (two-axle digest, bogie digest §Table 8).
inline constexpr LengthBand kHangerLength{0.01, 5.0, "a swing hanger's length (the book's 230–650 mm)"};
/// A spring's geometry and static deflection: wire and leaves of millimetres, leaf springs and
/// static deflections up to 2 m and 350 mm (springs digest; Table 9's quiet-riding cars).
inline constexpr LengthBand kSpringLength{0.001, 5.0, "a spring's dimension (millimetres to a 2 m leaf spring)"};
/// A body's dimensions: spacings, wheelbases, heights and radii of gyration of a wagon, whose
/// bodies are at most about 27 m long (bogie centres 2l3 = 13.8–19 m).
inline constexpr LengthBand kBodyLength{0.001, 50.0, "a wagon's dimension (a body is at most about 27 m long)"};

/// Warns when the length `si` read at `key` of `t` is non-zero and outside `band`: the value as
/// written, the unit it was read in, and the unit that puts it inside the band (a bare 734 for
/// a hanger: "734 mm"?).
void warn_implausible_length(TableReader& t, const std::string& key, double si, const LengthBand& band);

}  // namespace railmodal::input
