// The C++ side of compare_fft.py: times railmodal's amplitude spectrum of the samples in
// IN (raw float64, native byte order) in the same run as numpy, and writes the amplitudes to
// OUT for the script to compare with its own.
//
//   spectrum_timing IN OUT REPEATS    prints "new_plan_s T" and "reused_plan_s T" (medians)
#include <algorithm>
#include <chrono>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include <railmodal/spectrum.hpp>

namespace {

template <typename F>
double median_seconds(int repeats, F f) {
  std::vector<double> times;
  for (int i = 0; i < repeats; ++i) {
    const auto start = std::chrono::steady_clock::now();
    f();
    times.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  std::sort(times.begin(), times.end());
  return times[times.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 4) {
    std::cerr << "usage: spectrum_timing IN.f64 OUT.f64 REPEATS\n";
    return 2;
  }
  std::ifstream in(argv[1], std::ios::binary | std::ios::ate);
  if (!in) {
    std::cerr << argv[1] << ": error: cannot open\n";
    return 3;
  }
  Eigen::VectorXd x(static_cast<Eigen::Index>(in.tellg()) / static_cast<Eigen::Index>(sizeof(double)));
  in.seekg(0);
  in.read(reinterpret_cast<char*>(x.data()), static_cast<std::streamsize>(x.size() * sizeof(double)));
  const int repeats = std::max(1, std::stoi(argv[3]));
  const double fs = 1.0;  // Hz; the scaling does not depend on it

  // Hann, weighted mean removed, no padding: what compare_fft.py computes with numpy. Median
  // times over `repeats` runs: a fresh plan each time, as numpy.fft plans inside every call,
  // then one plan reused.
  railmodal::Spectrum s;
  const double fresh = median_seconds(repeats, [&] { s = railmodal::amplitude_spectrum(x, fs); });
  railmodal::SpectrumAnalyzer analyzer(x.size());
  const double reused = median_seconds(repeats, [&] { analyzer.compute(x, fs, &s); });
  std::cout << "new_plan_s " << fresh << "\nreused_plan_s " << reused << "\n";

  std::ofstream out(argv[2], std::ios::binary);
  out.write(reinterpret_cast<const char*>(s.amplitude.data()),
            static_cast<std::streamsize>(s.amplitude.size() * sizeof(double)));
  if (!out) {
    std::cerr << argv[2] << ": error: cannot write\n";
    return 5;
  }
}
