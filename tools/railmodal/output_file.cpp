// Output files written whole or not at all: what every railmodal program that writes a file
// (railmodal, railmodal-mpi) does with -o.
#include <filesystem>
#include <fstream>
#include <iostream>

#include "commands.hpp"

namespace railmodal::cli {

int write_output(const std::string& path, const std::string& text) {
  return write_output(path, [&text](std::ostream& out) {
    out << text;
    return kSuccess;
  });
}

int write_output(const std::string& path, const std::function<int(std::ostream&)>& write) {
  if (path.empty() || path == "-") {
    const int code = write(std::cout);
    std::cout << std::flush;
    return code != kSuccess ? code : std::cout ? kSuccess : kOutput;
  }
  namespace fs = std::filesystem;
  const fs::path target(path);
  std::error_code status_error;
  const fs::file_status status = fs::status(target, status_error);
  if (fs::exists(status) && !fs::is_regular_file(status)) {
    // A device or pipe (/dev/null, a FIFO): write into it; renaming over it would replace it.
    std::ofstream out(target, std::ios::binary);
    const int code = write(out);
    out.close();
    if (code != kSuccess) return code;
    if (out) return kSuccess;
    std::cerr << path << ": error: cannot write the output file\n";
    return kOutput;
  }
  const fs::path temporary = target.parent_path() / ("." + target.filename().string() + ".tmp");
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    int code = kSuccess;
    try {
      code = write(out);
    } catch (...) {
      out.close();
      std::error_code ignored;
      fs::remove(temporary, ignored);
      throw;
    }
    out.close();
    if (code != kSuccess || !out) {
      std::error_code ignored;
      fs::remove(temporary, ignored);
      if (code != kSuccess) return code;
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
