// Opening an input file (vehicle, scene, study, Matrix Market, shard) for reading.
#pragma once

#include <fstream>
#include <string>

namespace railmodal::input {

/// The file open for binary reading. Throws InputError naming it when it cannot be opened, or
/// when it is a directory (which opens on Linux and reads as empty: a misleading "missing
/// table" later) or a device (/dev/zero never ends). Pipes are kept: `<(command)` works.
std::ifstream open_input(const std::string& path);

}  // namespace railmodal::input
