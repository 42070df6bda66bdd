// The up-front refusal of a record that would not fit: what fft_check and a scene's output
// record check before a sample is computed.
#pragma once

#include <cstdio>
#include <stdexcept>
#include <string>

namespace railmodal::simulate {

/// Throws std::invalid_argument, with the estimate, when `samples` × `bytes_per_sample` exceeds
/// `limit` (bytes). `what` says what needs the record and why it must be held whole.
inline void require_record_fits(const std::string& what, double samples, int columns, double bytes_per_sample,
                                double limit) {
  const double bytes = samples * bytes_per_sample;
  if (bytes <= limit) return;
  char estimate[200];
  std::snprintf(estimate, sizeof estimate,
                " would need about %.3g GB for %.3g samples x %d columns; the limit is %.3g GB", bytes / 1e9, samples,
                columns, limit / 1e9);
  throw std::invalid_argument(what + estimate +
                              ": take a longer time_step, a shorter duration or fewer outputs, or raise the limit "
                              "(--memory-limit)");
}

}  // namespace railmodal::simulate
