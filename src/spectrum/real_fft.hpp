// The FFTW back-end: a real-to-complex transform of one length, planned once.
#pragma once

#include <Eigen/Core>
#include <complex>

struct fftw_plan_s;

namespace railmodal::spectrum {

/// Owns FFTW's aligned buffers and an r2c plan for `length` samples. Planned by FFTW_ESTIMATE,
/// which always picks the same algorithm (FFTW_MEASURE times candidates, so two runs could
/// pick different algorithms and round differently). Planning is serialised by a lock, since
/// FFTW's planner is not thread-safe; executing is.
class RealFft {
 public:
  explicit RealFft(Eigen::Index length);
  ~RealFft();
  RealFft(const RealFft&) = delete;
  RealFft& operator=(const RealFft&) = delete;

  Eigen::Index length() const { return length_; }
  /// The `length` input samples, to be filled before execute().
  Eigen::Map<Eigen::VectorXd> input() { return {input_, length_}; }
  /// X[k] = Σ x[n] e^{−2πikn/length} for k = 0 … length/2, valid after execute().
  Eigen::Map<const Eigen::VectorXcd> output() const { return {output_, length_ / 2 + 1}; }
  void execute();

 private:
  Eigen::Index length_;
  double* input_ = nullptr;
  std::complex<double>* output_ = nullptr;
  fftw_plan_s* plan_ = nullptr;
};

}  // namespace railmodal::spectrum
