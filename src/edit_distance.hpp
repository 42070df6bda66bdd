// How far apart two names are, to point at the one a misspelt name meant (a key of an input
// table, a ride output named by a study's metric). A foundation: any stage may include it.
#pragma once

#include <algorithm>
#include <string_view>
#include <vector>

namespace railmodal {

/// The Levenshtein distance: the fewest single-character insertions, deletions and
/// substitutions that turn `a` into `b` (one row of the dynamic-programming table at a time).
inline size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diagonal = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

}  // namespace railmodal
