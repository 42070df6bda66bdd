// Warnings of the readers: inputs that can be meant but are unusual (docs/input.md,
// "Implausible inputs"), accepted, and said on stderr by the command line. Errors are for
// inputs that cannot be meant; a warning changes no result and no output file.
#pragma once

#include <array>
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

/// A lateral spacing (of springs, hangers or dampers across the track): the track gauge is
/// 1.435 m (1.52–1.676 m on broad gauges) and the widest bodies about 3.5 m (the 1520 mm
/// network's gauge T allows 3.75 m), so a spacing beyond 5 m is no lateral spacing (a "20 m" the
/// user audit of 2026-11-28b met passed the wagon band).
inline constexpr LengthBand kLateralSpacing{0.001, 5.0,
                                            "a lateral spacing (the gauge is 1.435 m, the widest bodies about 3.5 m)"};
/// A point's lateral coordinate y: half the lateral spacing's band.
inline constexpr LengthBand kLateralOffset{0.001, 2.5, "a point's distance from the track's centre line "
                                                       "(half the widest body, about 1.75 m)"};

/// The band of a body's mass accepted without a warning, kg: from an axlebox or a bogie frame of
/// the general form (about 100 kg to 3 t) to a loaded wagon (the bogie digest's up to 90 t) or a
/// locomotive's body (about 130 t), with margin either way. A wagon body of 42 kg is a mass meant in
/// tonnes (the user audit of 2026-11-28b: "mass = 42.2", a 54 Hz bounce).
struct MassBand {
  double low;
  double high;
  const char* what;
};
inline constexpr MassBand kBodyMass{50.0, 1.0e6, "a body's mass (an axlebox of about 100 kg to a locomotive's 130 t)"};

/// Warns when the length `si` read at `key` of `t` is non-zero and outside `band`: the value as
/// written, the unit it was read in, and the unit that puts it inside the band (a bare 734 for
/// a hanger: "734 mm"?).
void warn_implausible_length(TableReader& t, const std::string& key, double si, const LengthBand& band);
/// The same for a body's mass read at `key` (kBodyMass; "did you mean \"42.2 t\"?").
void warn_implausible_mass(TableReader& t, const std::string& key, double si);
/// The same for each coordinate of the point read at `key`: x and z beyond kBodyLength's 50 m,
/// y beyond kLateralOffset's 2.5 m ("x read as -4000 m … did you mean \"-4000 mm\"?"). A
/// coordinate may be small or zero, so only the upper bound is warned.
void warn_implausible_point(TableReader& t, const std::string& key, const std::array<double, 3>& point);

}  // namespace railmodal::input
