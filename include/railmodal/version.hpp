// railmodal — the version of the library a program runs with, for reports and `--version`:
// a page or a file that says which version produced it can be reproduced.
//
//   #include <railmodal/railmodal.hpp>
//   #include <iostream>
//
//   int main() {
//     std::cout << "railmodal " << railmodal::version() << "\n";  // railmodal 0.1.0
//     return railmodal::version().empty() ? 1 : 0;
//   }
#pragma once

#include <string_view>

namespace railmodal {

/// The project version of the built library ("major.minor.patch", CMake's PROJECT_VERSION).
std::string_view version();

}  // namespace railmodal
