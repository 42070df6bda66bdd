// A consumer of the spectra: it links FFTW through railmodal's package config alone.
#include <railmodal/spectrum.hpp>

#include <cmath>
#include <iostream>

int main() {
  const double fs = 100.0, pi = 3.14159265358979323846;
  Eigen::VectorXd x(6000);  // 60 s of a 1.0586 Hz line (the resort car's body bounce)
  for (Eigen::Index n = 0; n < x.size(); ++n) x(n) = 0.01 * std::cos(2 * pi * 1.0586 * n / fs);
  for (const railmodal::SpectralPeak& p : railmodal::find_peaks(railmodal::amplitude_spectrum(x, fs)))
    std::cout << "spectral peak " << p.frequency << " Hz, " << p.amplitude << " m\n";
}
