// Dynamic deflection of suspension elements against speed: what the book's permissible
// dynamic deflections (springs digest §5) are checked against.
//
// A direct solve per speed and harmonic, because the element's stretch needs the track's own
// displacement under a track element as well as the body motion, and because leaf friction,
// when it is linearised, is a damper whose size depends on ω (so no modal basis serves every
// speed). The systems are small: a complex LU of ten to thirty DOFs per speed.
#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <stdexcept>

#include "railmodal/response.hpp"
#include "response/friction_damping.hpp"
#include "response/modal_checks.hpp"
#include "summary/stage_clock.hpp"

namespace railmodal {

namespace {

constexpr double kTwoPi = 6.28318530717958647692;

// The vertical displacement of the track under element `element` in this harmonic, with its
// delay: the wheels' inputs as generalized_load applies them (u e^{−iωτ}).
std::complex<double> track_under(const LinearSystem& system, const HarmonicLoad& load, int element) {
  const double omega = kTwoPi * load.frequency_hz;
  std::complex<double> u = 0.0;
  for (const WheelInput& w : load.wheels)
    if (system.track_inputs[w.track_input].element == element)
      u += w.amplitude(2) * std::exp(std::complex<double>(0.0, -omega * w.delay_s));
  return u;
}

// Whether an undamped mode that the response found resonant stretches the element.
bool stretched_by_resonance(const HarmonicResponse& r, const ModalResult& modes, const Eigen::RowVectorXd& row) {
  for (int index : r.resonant_modes)
    if (response::moves(row, modes.modes[index - 1].shape)) return true;
  return false;
}

}  // namespace

std::vector<DeflectionCurve> element_deflection_curves(const LinearSystem& system, const ModalResult& modes,
                                                       const ExcitationSource& source, int source_index,
                                                       const std::vector<int>& elements,
                                                       const std::vector<double>& speeds,
                                                       const std::vector<double>& friction_reference_stretch,
                                                       AnalysisSummary* summary) {
  if (summary) *summary = AnalysisSummary{};
  StageClock clock(summary);  // no clock, no strings without a summary
  const int element_count = static_cast<int>(system.vehicle.elements.size());
  std::vector<DeflectionCurve> curves;
  std::vector<Eigen::RowVectorXd> rows;  // each element's stretch per unit of each DOF
  std::vector<double> stiffness;         // its spring stages in series
  const SpeedGrid grid(speeds);
  for (int e : elements) {
    if (e < 0 || e >= element_count) throw std::invalid_argument("deflection curve: no such element");
    rows.push_back(system.element_vertical_map.row(e));
    stiffness.push_back(series_stiffness(system.vehicle.elements[e].vertical_stages));
    DeflectionCurve c;
    c.source = source_index;
    c.element = e;
    c.speeds = grid;
    c.amplitudes.assign(speeds.size(), 0.0);
    c.spring_forces.assign(speeds.size(), 0.0);
    c.unbounded.assign(speeds.size(), false);
    curves.push_back(c);
  }
  bool friction_linearised = false;
  for (double x : friction_reference_stretch) friction_linearised = friction_linearised || x > 0.0;
  friction_linearised = friction_linearised && has_leaf_friction(system);

  for (size_t v = 0; v < speeds.size(); ++v) {
    if (!(speeds[v] > 0.0) || !std::isfinite(speeds[v]))
      throw std::invalid_argument("deflection curve: speeds must be positive");
    const double source_load = response::source_load_norm(system, source, speeds[v]);
    for (int k = 1; k <= source.harmonic_count(); ++k) {
      const double omega = kTwoPi * source.frequency_hz(speeds[v], k);
      // The friction damper also acts on the track's velocity: the load is built on the
      // linearised system.
      const LinearSystem linearised =
          friction_linearised ? with_equivalent_friction_damping(system, omega, friction_reference_stretch) : LinearSystem{};
      const LinearSystem& s = friction_linearised ? linearised : system;
      const HarmonicLoad load = source.load(s, speeds[v], k);
      const HarmonicResponse r = harmonic_response(s, modes, generalized_load(s, load), load.frequency_hz, source_load);
      for (size_t i = 0; i < curves.size(); ++i) {
        DeflectionCurve& c = curves[i];
        if (c.unbounded[v]) continue;
        if (r.unbounded && stretched_by_resonance(r, modes, rows[i])) {
          c.unbounded[v] = true;
          c.amplitudes[v] = 0.0;
          c.spring_forces[v] = 0.0;
          continue;
        }
        const std::complex<double> stretch =
            (rows[i].cast<std::complex<double>>() * r.displacement).value() - track_under(system, load, c.element);
        c.amplitudes[v] += std::abs(stretch);
        const double friction = friction_linearised && static_cast<size_t>(c.element) < friction_reference_stretch.size()
                                    ? response::equivalent_friction_damping(system, c.element, omega,
                                                                            friction_reference_stretch[c.element])
                                    : 0.0;
        c.spring_forces[v] += std::abs(std::complex<double>(stiffness[i], omega * friction) * stretch);
      }
    }
  }
  clock.lap("sweep");
  if (summary) {
    summary->analysis = "element deflection against speed";
    summary->method = friction_linearised
                          ? "direct solve per speed and harmonic, leaf friction as equivalent viscous damping"
                          : "direct solve per speed and harmonic";
    size_t unbounded = 0;
    for (const DeflectionCurve& c : curves) unbounded += std::count(c.unbounded.begin(), c.unbounded.end(), true);
    summary->checks.push_back({"points where an undamped resonance stretches an element without limit",
                               static_cast<double>(unbounded), std::numeric_limits<double>::infinity(), true});
  }
  return curves;
}

}  // namespace railmodal
