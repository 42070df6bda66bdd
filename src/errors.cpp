#include "railmodal/errors.hpp"

namespace railmodal {

InputError::InputError(std::string file, int line, int column, std::string message)
    : std::runtime_error(file + (line > 0 ? ":" + std::to_string(line) + (column > 0 ? ":" + std::to_string(column) : "") : "") +
                         ": error: " + message),
      file_(std::move(file)),
      line_(line),
      column_(column),
      message_(std::move(message)) {}

}  // namespace railmodal
