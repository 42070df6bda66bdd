// Output files written whole or not at all: what every railmodal program that writes a file
// (railmodal, railmodal-mpi) does with -o.
#include <filesystem>
#include <fstream>
#include <iostream>

#include "commands.hpp"

namespace railmodal::cli {

int write_output(const std::string& path, const std::string& text) {
  if (path.empty() || path == "-") {
    std::cout << text << std::flush;
    return std::cout ? kSuccess : kOutput;
  }
  namespace fs = std::filesystem;
  const fs::path target(path);
  std::error_code status_error;
  const fs::file_status status = fs::status(target, status_error);
  if (fs::exists(status) && !fs::is_regular_file(status)) {
    // A device or pipe (/dev/null, a FIFO): write into it; renaming over it would replace it.
    std::ofstream out(target, std::ios::binary);
    out << text;
    out.close();
    if (out) return kSuccess;
    std::cerr << path << ": error: cannot write the output file\n";
    return kOutput;
  }
  const fs::path temporary = target.parent_path() / ("." + target.filename().string() + ".tmp");
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    out << text;
    out.close();
    if (!out) {
      std::error_code ignored;
      fs::remove(temporary, ignored);
      std::cerr << path << ": error: cannot write the output file\n";
      return kOutput;
    }
  }
  std::error_code error;
  fs::rename(temporary, target, error);
  if (error) {
    fs::remove(temporary, error);
    std::cerr << path << ": error: cannot write the output file\n";
    return kOutput;
  }
  return kSuccess;
}

}  // namespace railmodal::cli
