#include "railmodal/version.hpp"

namespace railmodal {

// RAILMODAL_VERSION is set on this file only (CMakeLists.txt), from project(... VERSION ...), so a
// release changes one line and no other file recompiles.
std::string_view version() { return RAILMODAL_VERSION; }

}  // namespace railmodal
