// libFuzzer target for the input parsers: vehicle files, scene files, Matrix Market files,
// study files. The first byte picks the parser; the rest is the file. Each stage may throw
// only what the command line turns into its documented exit code:
//   parsers (load_vehicle, load_scene, load_matrix_model,
//            load_study)                                   InputError           exit 3
//   assemble                                                std::invalid_argument, which the
//                                                           CLI rethrows as InputError: exit 3
//   solve_modes (default options, at least one DOF)         NumericalError       exit 4
// A parser leaking std::invalid_argument (the unit and key-path helpers throw it) would reach
// the CLI as a usage error (exit 2) or an internal one (exit 1), so it is not caught here: a
// crash, a sanitizer report or any exception outside that table is a bug.
//
//   build-asan/tools/fuzz/fuzz_inputs -max_total_time=60 build-asan/corpus
// (tools/sanitize.sh builds it with clang, -fsanitize=fuzzer,address,undefined, with the
// sanitised test suite, and runs it briefly.)
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <system_error>
#include <stdexcept>
#include <string>

#include "load_study.hpp"
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

// A study's path: <scratch>/studies/study.toml, beside links to the bundled vehicles and
// scenes, so that the bundled studies' "../vehicles/…" and "../scenes/…" resolve.
const std::string& study_path() {
  static const std::string path = [] {
    const std::string root = scratch("studies");
    std::error_code ignored;
    std::filesystem::create_directories(root, ignored);
    const std::filesystem::path parent = std::filesystem::path(root).parent_path();
    for (const char* folder : {"vehicles", "scenes"})
      std::filesystem::create_directory_symlink(std::string(RAILMODAL_DATA_DIR) + "/" + folder, parent / folder, ignored);
    return root + "/study.toml";
  }();
  return path;
}

void write(const std::string& path, const uint8_t* data, size_t size) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 1) return 0;
  const int which = data[0] % 4;
  try {
    if (which == 0) {
      const std::string path = scratch("vehicle.toml");
      write(path, data + 1, size - 1);
      const railmodal::Vehicle v = railmodal::load_vehicle(path);
      railmodal::LinearSystem s;
      try {
        s = railmodal::assemble(v, railmodal::DofSet::all);
      } catch (const std::invalid_argument&) {
        return 0;  // a vehicle that cannot be assembled: the CLI reports it as an InputError
      }
      if (s.size() > 0 && s.size() < 200) railmodal::solve_modes(s);
    } else if (which == 1) {
      const std::string path = scratch("scene.toml");
      write(path, data + 1, size - 1);
      railmodal::load_scene(path);
    } else if (which == 3) {
      // The reader's paths, not a study's size: at most 64 variants listed and 2 read (a
      // million listed take 2.7 GB, over the fuzzer's memory limit).
      const std::string& path = study_path();
      write(path, data + 1, size - 1);
      railmodal::load_study(path, [](int index) { return index < 2; }, 64);
    } else {
      const std::string mass = scratch("M.mtx");
      write(mass, data + 1, size - 1);
      const std::string stiffness = scratch("K.mtx");
      write(stiffness, data + 1, size - 1);
      const railmodal::MatrixModel m = railmodal::load_matrix_model(mass, stiffness, "");
      // The reader rejects a 0 × 0 matrix, so solve_modes has no invalid_argument to throw.
      if (m.labels.size() < 200) railmodal::solve_modes(railmodal::to_linear_system(m));
    }
  } catch (const railmodal::InputError&) {
  } catch (const railmodal::NumericalError&) {
  }
  return 0;
}
