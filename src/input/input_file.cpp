#include "input/input_file.hpp"

#include <cerrno>
#include <filesystem>
#include <string>
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
  errno = 0;
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, 0, 0, "cannot open the file" + system_reason(errno));
  return in;
}

std::string system_reason(int error) {
  // std::generic_category's message is strerror's text, and thread-safe (a study's workers open
  // files too); 0: the library failed without saying why (no reason is better than a wrong one).
  return error == 0 ? std::string() : ": " + std::error_code(error, std::generic_category()).message();
}

std::string read_input_text(const std::string& path, size_t limit, const std::string& why) {
  std::ifstream in = open_input(path);
  errno = 0;  // a reason left over from opening is not the read's
  std::string text;
  char buffer[1 << 16];
  while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
    text.append(buffer, static_cast<size_t>(in.gcount()));
    if (text.size() > limit)
      throw InputError(path, 0, 0, "the file is larger than " + std::to_string(limit) + " bytes, the limit for " + why);
  }
  if (in.bad()) throw InputError(path, 0, 0, "cannot read the file" + system_reason(errno));
  return text;
}

}  // namespace railmodal::input
