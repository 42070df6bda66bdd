// The input files of a run with the hash of their content, for the footers of the reports
// (include/railmodal/provenance.hpp). Here, in the input layer: the reports read no file.
#include "railmodal/provenance.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "input/input_file.hpp"
#include "railmodal/errors.hpp"

namespace railmodal {

std::string content_digest(std::string_view bytes) {
  std::uint64_t hash = 14695981039346656037ULL;  // FNV-1a 64 offset basis
  for (unsigned char byte : bytes) {
    hash ^= byte;
    hash *= 1099511628211ULL;  // FNV 64 prime
  }
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(hash));
  return text;
}

Provenance provenance_of(const std::vector<std::string>& paths) {
  Provenance provenance;
  for (const std::string& path : paths) {
    if (path.empty()) continue;
    const auto listed = [&](const InputFile& f) { return f.path == path; };
    if (std::any_of(provenance.files.begin(), provenance.files.end(), listed)) continue;
    // A pipe or a device (`<(cat scene.toml)`) was drained when the run read it: reading it
    // again would hash nothing, or other bytes, so it is listed unhashed.
    std::error_code ignored;
    if (std::filesystem::exists(path, ignored) && !std::filesystem::is_regular_file(path, ignored)) {
      provenance.files.push_back({path, ""});
      continue;
    }
    errno = 0;
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path, 0, 0, "cannot be read" + input::system_reason(errno));
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    provenance.files.push_back({path, content_digest(bytes)});
  }
  return provenance;
}

}  // namespace railmodal
