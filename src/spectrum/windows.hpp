// The window's line shape, shared by the spectrum's scaling and the peak interpolation.
#pragma once

#include "railmodal/spectrum.hpp"

namespace railmodal::spectrum {

/// |W(ν)|/W(0): the amplitude a tone ν bins of fs/N off a bin centre shows, relative to a
/// centred one, for N ≫ 1 (the window's continuous transform, a sum of shifted sincs).
double window_response(Window window, double offset);

}  // namespace railmodal::spectrum
