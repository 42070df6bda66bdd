// libFuzzer target for the input parsers: vehicle files, scene files, Matrix Market files.
// The first byte picks the parser; the rest is the file. Every input must either load or
// throw railmodal::InputError (or std::invalid_argument/NumericalError from the model built
// from it) — a crash, a sanitizer report or any other exception is a bug.
//
//   build-fuzz/tools/fuzz/fuzz_inputs -max_total_time=60 build-fuzz/corpus
// (.ci/run builds it with clang, -fsanitize=fuzzer,address,undefined, and runs it briefly.)
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <stdexcept>
#include <string>

#include "railmodal/railmodal.hpp"
#include "railmodal/matrix_market.hpp"

namespace {

// The parsers read files; one per process in the fast tmpfs.
const std::string& scratch(const char* name) {
  static const std::string dir = [] {
    std::string d = "/dev/shm/railmodal_fuzz_" + std::to_string(getpid());
    std::string cmd = "mkdir -p " + d;
    if (std::system(cmd.c_str()) != 0) d = "/tmp";
    return d;
  }();
  static std::string path;
  path = dir + "/" + name;
  return path;
}

void write(const std::string& path, const uint8_t* data, size_t size) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 1) return 0;
  const int which = data[0] % 3;
  try {
    if (which == 0) {
      const std::string path = scratch("vehicle.toml");
      write(path, data + 1, size - 1);
      const railmodal::Vehicle v = railmodal::load_vehicle(path);
      const railmodal::LinearSystem s = railmodal::assemble(v, railmodal::DofSet::all);
      if (s.size() > 0 && s.size() < 200) railmodal::solve_modes(s);
    } else if (which == 1) {
      const std::string path = scratch("scene.toml");
      write(path, data + 1, size - 1);
      railmodal::load_scene(path);
    } else {
      const std::string mass = scratch("M.mtx");
      write(mass, data + 1, size - 1);
      const std::string stiffness = scratch("K.mtx");
      write(stiffness, data + 1, size - 1);
      const railmodal::MatrixModel m = railmodal::load_matrix_model(mass, stiffness, "");
      if (m.labels.size() < 200) railmodal::solve_modes(railmodal::to_linear_system(m));
    }
  } catch (const railmodal::InputError&) {
  } catch (const railmodal::NumericalError&) {
  } catch (const std::invalid_argument&) {
  }
  return 0;
}
