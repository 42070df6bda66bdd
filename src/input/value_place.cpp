#include "input/value_place.hpp"

#include <algorithm>
#include <memory>
#include <vector>

namespace railmodal::input {
namespace {

using Source = std::vector<char>;

// The offsets at which the lines of one file start.
struct LineIndex {
  std::weak_ptr<const Source> source;  // weak: the index must not keep a file's text alive
  const Source* key = nullptr;
  std::vector<size_t> starts;
};

std::vector<size_t> line_starts(const Source& text) {
  std::vector<size_t> starts{0};
  for (size_t i = 0; i < text.size(); ++i)
    if (text[i] == '\n') starts.push_back(i + 1);
  return starts;
}

// The index of `source`, built on first use. A study reads a few files at once (the study,
// its scene, its vehicles): the indices of those still alive are kept, the others dropped.
const std::vector<size_t>& index_of(const std::shared_ptr<const Source>& source) {
  thread_local std::vector<LineIndex> indices;
  for (const LineIndex& index : indices)
    if (index.key == source.get() && index.source.lock() == source) return index.starts;
  indices.erase(std::remove_if(indices.begin(), indices.end(), [](const LineIndex& i) { return i.source.expired(); }),
                indices.end());
  indices.push_back({source, source.get(), line_starts(*source)});
  return indices.back().starts;
}

}  // namespace

KeyPlace place_of(const toml::value& value) {
  const auto* region = dynamic_cast<const toml::detail::region*>(toml::detail::get_region(value));
  if (region == nullptr || !region->is_ok()) return {};
  const std::vector<size_t>& starts = index_of(region->source());
  const auto offset = static_cast<size_t>(region->first() - region->begin());
  // The last line start at or before the offset.
  const size_t line = static_cast<size_t>(std::upper_bound(starts.begin(), starts.end(), offset) - starts.begin());
  return {static_cast<int>(line), static_cast<int>(offset - starts[line - 1] + 1)};
}

}  // namespace railmodal::input
