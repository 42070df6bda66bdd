// The `[[source]] kind = "irregularity"` table of a scene: random track irregularity given per
// component by a standard spectrum, a user table, or (for a time-domain run) measured geometry.
#pragma once

#include <string>

#include "input/table_reader.hpp"
#include "railmodal/ride.hpp"

namespace railmodal::input {

struct IrregularitySource {
  TrackIrregularitySpectra spectra;  ///< the components the table gives; may be none with geometry
  std::string geometry_file;         ///< measured geometry (`geometry`), resolved; "" if not given
};

/// Reads the source table `t` (its `kind` already read). Every key is checked; a component's
/// spectrum that TrackSpectrum refuses is an InputError at the key that gave it.
IrregularitySource read_irregularity(TableReader& t);

}  // namespace railmodal::input
