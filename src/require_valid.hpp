// The one rule of an options struct, checked where an analysis starts.
#pragma once

#include <stdexcept>
#include <string>

namespace railmodal {

/// Throws std::invalid_argument(prefix + why) when options.is_valid(&why) is false.
template <class Options>
void require_valid(const Options& options, const std::string& prefix) {
  std::string why;
  if (!options.is_valid(&why)) throw std::invalid_argument(prefix + why);
}

}  // namespace railmodal
