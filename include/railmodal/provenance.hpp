// railmodal — what a report was made from: the input files, each with a hash of its content,
// for the footer of every page (beside railmodal::version()), so that a page can be traced to
// the exact files that produced it and reproduced.
//
//   #include <railmodal/railmodal.hpp>
//   #include <iostream>
//
//   int main() {
//     railmodal::Provenance inputs = railmodal::provenance_of({"data/scenes/resort_car_10m_rails.toml"});
//     for (const railmodal::InputFile& f : inputs.files) std::cout << f.path << " " << f.digest << "\n";
//     std::cout << railmodal::content_digest("") << "\n";  // cbf29ce484222325, FNV-1a 64 of no bytes
//   }
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace railmodal {

/// One input file of a run.
struct InputFile {
  std::string path;  ///< as the user gave it: a relative path stays relative, so a page does not depend on where it ran
  /// content_digest of the file's bytes as provenance_of read them (when the report was
  /// written, after the run had read it: a file changed in between shows its new bytes); empty
  /// for a path that is not a regular file (a pipe, `<(cat scene.toml)`), which is not hashed.
  std::string digest;
};

/// The input files of a run, in the order the run read them. Reports print them in their
/// footer; empty: the footer says the inputs were not recorded (a vehicle built in code).
struct Provenance {
  std::vector<InputFile> files;
};

/// FNV-1a 64 (Fowler, Noll and Vo; offset basis 14695981039346656037, prime 1099511628211) of
/// `bytes`, as 16 lower-case hex digits. It tells files apart and shows a change; it is no
/// protection against a file made to collide on purpose.
std::string content_digest(std::string_view bytes);

/// Each file with the digest of its content; the empty path is skipped and a path given twice is
/// listed once, and one that is not a regular file is listed with an empty digest (its bytes
/// were consumed by the run). Throws InputError (file, "cannot be read") for a file that cannot
/// be read.
Provenance provenance_of(const std::vector<std::string>& paths);

}  // namespace railmodal
