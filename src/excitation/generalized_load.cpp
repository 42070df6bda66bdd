// From wheel inputs and point forces to the generalised load on the degrees of freedom.
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>

#include "excitation/generalized_load.hpp"
#include "model/analysis_limits.hpp"
#include "model/point_motion.hpp"
#include "railmodal/excitation.hpp"

namespace railmodal {

HarmonicLoad ExcitationSource::load(const LinearSystem& system, double speed, int harmonic) const {
  if (!(speed > 0.0) || !std::isfinite(speed))
    throw std::invalid_argument(kind() + ": the speed must be positive and finite");
  if (harmonic < 1) throw std::invalid_argument(kind() + ": harmonics count from 1");
  HarmonicLoad load = load_at(system, speed, harmonic);
  // On wheelsets the rail's lateral displacement acts through the wheel–rail contact, which M, C
  // and K do not hold (an element on a wheelset has no lateral column): refused rather than
  // dropped, whatever element the input was given to.
  if (!system.vehicle.wheelsets.empty())
    for (const WheelInput& w : load.wheels) {
      if (w.amplitude(1) == 0.0) continue;
      std::string where = "on a vehicle with wheelsets";
      if (w.track_input >= 0 && w.track_input < static_cast<int>(system.track_inputs.size())) {
        const Element& e = system.vehicle.elements[system.track_inputs[w.track_input].element];
        if (model::stands_on_wheelset(system.vehicle, e)) where = "under wheelset '" + e.lower + "'";
      }
      throw std::invalid_argument(kind() + ": a lateral track input " + where +
                                  " acts through the wheel–rail contact, which this analysis does not model; "
                                  "`railmodal stability` models the contact");
    }
  return load;
}

namespace {

// QK += column d of `stiffness` × u and QC += column d of `damping` × u, entry by entry as
// `QK += stiffness.col(d) * u` (and QC's) sums them: the same products and sums, the same bits
// (QK's entries take only stiffness terms and QC's only damping terms, so one pass over the
// rows does both in the order two would). A track element's column is nonzero only at the DOFs
// its spring moves; a zero entry is skipped where u is finite, since its product is ±0 and
// adding ±0 leaves every entry as it was (Q starts at +0, and a sum is −0 only when both terms
// are, so no entry is ever −0). One call a wheel and direction: u's finiteness is tested once.
void add_columns(const TrackInput& t, int d, std::complex<double> u, Eigen::VectorXcd* QK, Eigen::VectorXcd* QC) {
  const double* stiffness = t.load_per_displacement.col(d).data();
  const double* damping = t.load_per_velocity.col(d).data();
  std::complex<double>* qk = QK->data();
  std::complex<double>* qc = QC->data();
  const Eigen::Index n = QK->size();
  if (std::isfinite(u.real()) && std::isfinite(u.imag())) {
    for (Eigen::Index r = 0; r < n; ++r) {
      if (stiffness[r] != 0.0) qk[r] += stiffness[r] * u;
      if (damping[r] != 0.0) qc[r] += damping[r] * u;
    }
  } else {
    for (Eigen::Index r = 0; r < n; ++r) {
      qk[r] += stiffness[r] * u;
      qc[r] += damping[r] * u;
    }
  }
}

// Q = Q_K + iω Q_C: the wheel inputs through the track elements' stiffness (and the point
// forces) in Q_K, through their dampers in Q_C.
void load_parts(const LinearSystem& system, const HarmonicLoad& load, Eigen::VectorXcd* QK, Eigen::VectorXcd* QC) {
  constexpr double kTwoPi = 6.28318530717958647692;
  const int n = system.size();
  const double omega = kTwoPi * load.frequency_hz;
  const std::complex<double> i(0.0, 1.0);
  QK->setZero(n);
  QC->setZero(n);
  // The wheels of a wheelset share their delay, and the sources list them together: the phase
  // e^{−iωτ} is found once per run of equal delays (equal bits, so the same value each wheel's
  // own exp would give), half the complex exponentials of a rail-joint load.
  double phase_delay = 0.0;
  std::complex<double> phase;
  bool have_phase = false;
  for (const WheelInput& w : load.wheels) {
    if (w.track_input < 0 || w.track_input >= static_cast<int>(system.track_inputs.size()))
      throw std::invalid_argument("generalized_load: no such track input");
    const TrackInput& t = system.track_inputs[w.track_input];
    if (!have_phase || std::memcmp(&w.delay_s, &phase_delay, sizeof phase_delay) != 0) {
      phase = std::exp(-i * omega * w.delay_s);
      phase_delay = w.delay_s;
      have_phase = true;
    }
    const Eigen::Vector3cd u = w.amplitude * phase;
    for (int d = 0; d < 3; ++d) {
      if (u(d) == 0.0) continue;
      add_columns(t, d, u(d), QK, QC);
    }
  }
  for (const PointForce& f : load.forces) {
    if (f.body < 0 || f.body >= static_cast<int>(system.vehicle.bodies.size()))
      throw std::invalid_argument("generalized_load: no such body");
    // The point's displacement per DOF, its bending included where the body has a mode: the
    // force's virtual work, per DOF of that body (the others' columns are zero).
    const Eigen::MatrixXd G = model::point_displacement_map(system, f.body, f.point);
    for (int d = 0; d < n; ++d)
      if (system.dofs[d].body == f.body) (*QK)(d) += G.col(d).cast<std::complex<double>>().dot(f.amplitude);
  }
}

}  // namespace

Eigen::VectorXcd generalized_load(const LinearSystem& system, const HarmonicLoad& load) {
  Eigen::VectorXcd Q;
  excitation::generalized_load_into(system, load, &Q);
  return Q;
}

void excitation::generalized_load_into(const LinearSystem& system, const HarmonicLoad& load, Eigen::VectorXcd* Q) {
  constexpr double kTwoPi = 6.28318530717958647692;
  thread_local Eigen::VectorXcd QC;  // the damper part, kept: its storage serves this thread's next load
  load_parts(system, load, Q, &QC);
  *Q += std::complex<double>(0.0, kTwoPi * load.frequency_hz) * QC;  // the sum QK + iωQC, in QK's storage
}

SeparableLoad ExcitationSource::separable_load(const LinearSystem& system, int harmonic) const {
  constexpr double kTwoPi = 6.28318530717958647692;
  // A slow reference speed: far below any track resonance, so the source's speed law is
  // regular there.
  const double reference_speed = 1e-3 * wavelength();
  const HarmonicLoad load = this->load(system, reference_speed, harmonic);
  SeparableLoad out;
  out.reference_omega = kTwoPi * load.frequency_hz;
  load_parts(system, load, &out.stiffness_part, &out.damping_part);
  return out;
}

}  // namespace railmodal
