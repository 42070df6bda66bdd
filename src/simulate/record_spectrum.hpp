// How the spectra of a simulated record are taken, by fft_check and for a scene's outputs.
#pragma once

#include "railmodal/spectrum.hpp"

namespace railmodal {

/// Hann (the window for frequencies) with ×4 zero padding: interpolation error far below a bin.
inline SpectrumOptions record_spectrum_options(Eigen::Index samples) {
  SpectrumOptions options;
  options.window = Window::hann;
  options.padding = Padding::to_length;
  options.padded_length = 4 * samples;
  return options;
}

}  // namespace railmodal
