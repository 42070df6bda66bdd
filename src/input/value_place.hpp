// Where a TOML value was written, found in time logarithmic in the file's size.
//
// toml11 3.7 counts the newlines from the start of the file each time a value's location()
// is asked for, so a reader that asks once per table (a study's [[variant]] tables) takes
// time quadratic in the file: 20 000 variants took 29 s. Here each file's line starts are
// indexed once, and a value's line is a binary search in them.
#pragma once

#include <toml.hpp>

#include "railmodal/errors.hpp"

namespace railmodal::input {

/// Where `value` starts in the file it was parsed from, the column in bytes as toml11 counts
/// it; 0 and 0 for a value read from no file (one a study writes into a document). The index
/// of each file's lines is kept per thread for as long as the file's text lives.
KeyPlace place_of(const toml::value& value);

}  // namespace railmodal::input
