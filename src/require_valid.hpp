// The one rule of an options struct, checked where an analysis starts.
#pragma once

#include <stdexcept>
#include <string>
#include <utility>

namespace railmodal {

/// For an is_valid: explains in *why (when the caller asked) and returns false.
inline bool invalid(std::string* why, std::string text) {
  if (why) *why = std::move(text);
  return false;
}

/// Throws std::invalid_argument(prefix + why) when options.is_valid(&why) is false.
template <class Options>
void require_valid(const Options& options, const std::string& prefix) {
  std::string why;
  if (!options.is_valid(&why)) throw std::invalid_argument(prefix + why);
}

}  // namespace railmodal
