#include "input/input_file.hpp"

#include <filesystem>
#include <system_error>

#include "railmodal/errors.hpp"

namespace railmodal::input {

std::ifstream open_input(const std::string& path) {
  std::error_code error;
  const std::filesystem::file_status status = std::filesystem::status(path, error);
  if (!error) {
    if (std::filesystem::is_directory(status)) throw InputError(path, 0, 0, "is a directory, not a file");
    if (std::filesystem::is_character_file(status) || std::filesystem::is_block_file(status))
      throw InputError(path, 0, 0, "is a device, not a file");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, 0, 0, "cannot open the file");
  return in;
}

}  // namespace railmodal::input
