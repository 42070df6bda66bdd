// Opening an input file (vehicle, scene, study, Matrix Market, shard) for reading.
#pragma once

#include <cstddef>
#include <fstream>
#include <string>

namespace railmodal::input {

/// The file open for binary reading. Throws InputError naming it when it cannot be opened (with
/// the system's reason: "cannot open the file: Permission denied"), or
/// when it is a directory (which opens on Linux and reads as empty: a misleading "missing
/// table" later) or a device (/dev/zero never ends). Pipes are kept: `<(command)` works.
std::ifstream open_input(const std::string& path);

/// ": No such file or directory" for errno `error` (the system's reason, to follow "cannot open
/// the file"); "" for 0.
std::string system_reason(int error);

/// The whole file, read with open_input. A file of more than `limit` bytes is refused (an
/// InputError naming it, `limit`, and `why` the limit exists) once limit + 1 bytes are read:
/// memory stays bounded for a pipe or a file that grows.
std::string read_input_text(const std::string& path, size_t limit, const std::string& why);

}  // namespace railmodal::input
