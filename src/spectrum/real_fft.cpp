#include "spectrum/real_fft.hpp"

#include <fftw3.h>

#include <climits>
#include <mutex>
#include <new>
#include <stdexcept>
#include <string>

namespace railmodal::spectrum {
namespace {

std::mutex& planner_lock() {
  static std::mutex lock;
  return lock;
}

}  // namespace

RealFft::RealFft(Eigen::Index length) : length_(length) {
  if (length < 1 || length > INT_MAX)
    throw std::invalid_argument("transform length must be in [1, " + std::to_string(INT_MAX) + "], got " +
                                std::to_string(length));
  const auto n = static_cast<size_t>(length);
  input_ = fftw_alloc_real(n);
  // fftw_complex is double[2], laid out as std::complex<double> (C++ [complex.numbers]).
  output_ = reinterpret_cast<std::complex<double>*>(fftw_alloc_complex(n / 2 + 1));
  if (input_ && output_) {
    std::lock_guard<std::mutex> guard(planner_lock());
    plan_ = fftw_plan_dft_r2c_1d(static_cast<int>(length), input_, reinterpret_cast<fftw_complex*>(output_),
                                 FFTW_ESTIMATE);
  }
  if (!plan_) {
    fftw_free(input_);
    fftw_free(output_);
    throw std::bad_alloc();
  }
}

RealFft::~RealFft() {
  {
    std::lock_guard<std::mutex> guard(planner_lock());
    fftw_destroy_plan(plan_);
  }
  fftw_free(input_);
  fftw_free(output_);
}

void RealFft::execute() { fftw_execute(plan_); }

InverseRealFft::InverseRealFft(Eigen::Index length) : length_(length) {
  if (length < 1 || length > INT_MAX)
    throw std::invalid_argument("transform length must be in [1, " + std::to_string(INT_MAX) + "], got " +
                                std::to_string(length));
  const auto n = static_cast<size_t>(length);
  input_ = reinterpret_cast<std::complex<double>*>(fftw_alloc_complex(n / 2 + 1));
  output_ = fftw_alloc_real(n);
  if (input_ && output_) {
    std::lock_guard<std::mutex> guard(planner_lock());
    plan_ = fftw_plan_dft_c2r_1d(static_cast<int>(length), reinterpret_cast<fftw_complex*>(input_), output_,
                                 FFTW_ESTIMATE);
  }
  if (!plan_) {
    fftw_free(input_);
    fftw_free(output_);
    throw std::bad_alloc();
  }
}

InverseRealFft::~InverseRealFft() {
  {
    std::lock_guard<std::mutex> guard(planner_lock());
    fftw_destroy_plan(plan_);
  }
  fftw_free(input_);
  fftw_free(output_);
}

void InverseRealFft::execute() { fftw_execute(plan_); }

void InverseRealFft::execute(Eigen::VectorXd* out) {
  out->resize(length_);
  if (fftw_alignment_of(out->data()) != fftw_alignment_of(output_)) {
    execute();
    *out = output();
    return;
  }
  fftw_execute_dft_c2r(plan_, reinterpret_cast<fftw_complex*>(input_), out->data());
}

}  // namespace railmodal::spectrum
