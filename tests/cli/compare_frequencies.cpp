// Compares the modes of two `railmodal modes --format json` outputs: same count, same
// kinds, frequencies equal to a relative tolerance. Exit 0 when they agree, 1 otherwise.
//   compare_frequencies a.json b.json 1e-12
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>

int main(int argc, char** argv) {
  if (argc != 4) {
    std::cerr << "usage: compare_frequencies A.json B.json RELATIVE_TOLERANCE\n";
    return 2;
  }
  nlohmann::json a, b;
  std::ifstream(argv[1]) >> a;
  std::ifstream(argv[2]) >> b;
  const double tolerance = std::atof(argv[3]);
  const auto& ma = a.at("modes");
  const auto& mb = b.at("modes");
  if (ma.size() != mb.size() || ma.empty()) {
    std::cerr << ma.size() << " modes against " << mb.size() << "\n";
    return 1;
  }
  int bad = 0;
  for (size_t k = 0; k < ma.size(); ++k) {
    const bool oscillatory = ma[k].at("kind") == "oscillatory";
    if (ma[k].at("kind") != mb[k].at("kind")) {
      std::cerr << "mode " << k + 1 << ": kind " << ma[k].at("kind") << " against " << mb[k].at("kind") << "\n";
      ++bad;
      continue;
    }
    if (!oscillatory) continue;
    const double fa = ma[k].at("frequency_hz"), fb = mb[k].at("frequency_hz");
    const double error = std::abs(fa - fb) / std::abs(fa);
    std::cout << "mode " << k + 1 << ": " << fa << " Hz, relative difference " << error << "\n";
    if (!(error <= tolerance)) {
      std::cerr << "mode " << k + 1 << ": " << fa << " Hz against " << fb << " Hz (relative " << error << ")\n";
      ++bad;
    }
  }
  return bad == 0 ? 0 : 1;
}
