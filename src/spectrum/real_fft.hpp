// The FFTW back-end: real-to-complex and complex-to-real transforms of one length, planned once.
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

/// The inverse: a complex-to-real transform of one length, planned once (FFTW_ESTIMATE, for
/// the same reason). FFTW's c2r overwrites its input, so the spectrum is to be filled before
/// every execute().
class InverseRealFft {
 public:
  explicit InverseRealFft(Eigen::Index length);
  ~InverseRealFft();
  InverseRealFft(const InverseRealFft&) = delete;
  InverseRealFft& operator=(const InverseRealFft&) = delete;

  Eigen::Index length() const { return length_; }
  /// Y[k] for k = 0 … length/2 (the other half is the conjugate mirror), to be filled before
  /// execute(); the imaginary parts of Y[0] and, for an even length, Y[length/2] are ignored.
  Eigen::Map<Eigen::VectorXcd> input() { return {input_, length_ / 2 + 1}; }
  /// y[n] = Σ_{k=0}^{length−1} Y[k] e^{+2πikn/length} (unnormalised), valid after execute().
  Eigen::Map<const Eigen::VectorXd> output() const { return {output_, length_}; }
  void execute();
  /// execute() with y written into *out (resized to `length`) instead of output(): the same
  /// plan, so the same doubles; straight into out's storage when FFTW's alignment of it is
  /// the planned buffer's (fftw_execute_dft_c2r's condition), else through output() and copied.
  void execute(Eigen::VectorXd* out);

 private:
  Eigen::Index length_;
  std::complex<double>* input_ = nullptr;
  double* output_ = nullptr;
  fftw_plan_s* plan_ = nullptr;
};

}  // namespace railmodal::spectrum
