// Regenerates docs/accuracy.md: for each knob that trades accuracy for time, the error
// against a reference and the CPU time, measured side by side in one run.
//   railmodal_accuracy DATA_DIR > docs/accuracy.md      (tools/update_accuracy.sh does this)
#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <functional>
#include <iomanip>
#include <iostream>
#ifdef __GLIBC__
#include <malloc.h>
#endif
#include <sstream>
#include <stdexcept>

#include "railmodal/railmodal.hpp"
#include "stability/hunting_analysis.hpp"

using namespace railmodal;

namespace {

constexpr double kPi = 3.14159265358979323846;

// Seconds per call: repeats until 0.2 s have passed, the median of 5 such batches.
double seconds_per_call(const std::function<void()>& call) {
  using clock = std::chrono::steady_clock;
  std::vector<double> batches;
  for (int b = 0; b < 5; ++b) {
    int n = 0;
    const auto start = clock::now();
    double elapsed = 0.0;
    do {
      call();
      ++n;
      elapsed = std::chrono::duration<double>(clock::now() - start).count();
    } while (elapsed < 0.04);
    batches.push_back(elapsed / n);
  }
  std::sort(batches.begin(), batches.end());
  return batches[2];
}

std::string sci(double v, int digits = 2) {
  std::ostringstream s;
  s << std::scientific << std::setprecision(digits) << v;
  return s.str();
}

std::string fix(double v, int decimals) {
  std::ostringstream s;
  s << std::fixed << std::setprecision(decimals) << v;
  return s.str();
}

// Modal superposition over the m lowest modes against the direct solve, at every critical
// speed of the source: the largest relative error of the response vector, and time per speed.
void modal_truncation(const std::string& title, const LinearSystem& system, const ExcitationSource& source,
                      double vmin, double vmax) {
  const ModalResult modes = solve_modes(system);
  CriticalSpeedOptions range;
  range.min_speed = vmin;
  range.max_speed = vmax;
  const auto rows = find_critical_speeds(system, modes, {&source}, range);
  std::vector<std::pair<double, Eigen::VectorXcd>> loads;
  for (const auto& r : rows) {
    const HarmonicLoad load = source.load(system, r.speed, r.harmonic);
    loads.push_back({load.frequency_hz, generalized_load(system, load)});
  }
  std::cout << "### " << title << "\n\n" << system.size() << " DOFs, " << loads.size()
            << " critical speeds; error = max over them of ‖X_modal − X_direct‖/‖X_direct‖.\n\n"
            << "| method | modes used | max relative error | time per speed (µs) | time ratio to direct |\n"
            << "|---|---:|---:|---:|---:|\n";
  const double t_direct = seconds_per_call([&] {
    for (const auto& [f, Q] : loads) harmonic_response(system, modes, Q, f);
  }) / loads.size();
  std::cout << "| direct LU of K − ω²M + iωC | — | reference | " << fix(t_direct * 1e6, 2) << " | 1.00 |\n";
  const int n = static_cast<int>(modes.modes.size());
  for (int m = 1; m <= n; m = (m < 4 || m == n) ? m + 1 : std::min(n, m * 2)) {
    double error = 0.0;
    for (const auto& [f, Q] : loads) {
      const auto direct = harmonic_response(system, modes, Q, f);
      const auto modal = modal_harmonic_response(system, modes, Q, f, m);
      error = std::max(error, (modal.displacement - direct.displacement).norm() / direct.displacement.norm());
    }
    const double t = seconds_per_call([&] {
      for (const auto& [f, Q] : loads) modal_harmonic_response(system, modes, Q, f, m);
    }) / loads.size();
    std::cout << "| modal superposition | " << m << " of " << n << " | " << sci(error) << " | " << fix(t * 1e6, 2)
              << " | " << fix(t / t_direct, 2) << " |\n";
  }
  std::cout << "\n";
}

// Peak of an amplitude curve: a uniform speed grid against a coarse grid plus golden-section
// refinement around its maximum, both against a reference refined to 1e-13.
void peak_search(const std::string& title, const LinearSystem& system, const ExcitationSource& source,
                 const OutputRequest& output, double vmin, double vmax) {
  const ModalResult modes = solve_modes(system);
  auto grid = [&](int n) {
    std::vector<double> v;
    for (int i = 0; i < n; ++i) v.push_back(vmin + (vmax - vmin) * i / (n - 1));
    return v;
  };
  auto grid_peak = [&](int n) {
    const auto c = amplitude_curves(system, modes, source, 0, {output}, grid(n))[0];
    // The largest local maximum inside the range: the damped resonance, not the range end.
    size_t best = 0;
    for (size_t i = 1; i + 1 < c.speeds.size(); ++i)
      if (c.amplitudes[i] >= c.amplitudes[i - 1] && c.amplitudes[i] > c.amplitudes[i + 1] &&
          (best == 0 || c.amplitudes[i] > c.amplitudes[best]))
        best = i;
    if (best == 0) throw std::runtime_error("no interior peak on the grid");
    return std::make_tuple(c.speeds[best], c.amplitudes[best], c.speeds[best - 1], c.speeds[best + 1]);
  };
  const auto [v0, a0, lo0, hi0] = grid_peak(400);
  (void)v0, (void)a0;
  const Peak reference = refine_peak(system, modes, source, output, lo0, hi0, 1e-13);
  std::cout << "### " << title << "\n\nReference peak " << fix(reference.speed * 3.6, 4) << " km/h, amplitude "
            << sci(reference.amplitude, 6) << " (golden section to 1e-13).\n\n"
            << "| method | solves | speed error (km/h) | relative amplitude error | time (ms) |\n"
            << "|---|---:|---:|---:|---:|\n";
  for (int n : {25, 50, 100, 200, 400, 800, 1600}) {
    const auto [v, a, lo, hi] = grid_peak(n);
    (void)lo, (void)hi;
    const double t = seconds_per_call([&] { grid_peak(n); });
    std::cout << "| uniform grid | " << n << " | " << sci(std::abs(v - reference.speed) * 3.6) << " | "
              << sci(std::abs(a - reference.amplitude) / reference.amplitude) << " | " << fix(t * 1e3, 3) << " |\n";
  }
  for (double tol : {1e-2, 1e-4, 1e-6, 1e-8}) {
    Peak p;
    auto adaptive = [&] {
      const auto [v, a, lo, hi] = grid_peak(25);
      (void)v, (void)a;
      p = refine_peak(system, modes, source, output, lo, hi, tol);
    };
    adaptive();
    const double t = seconds_per_call(adaptive);
    std::cout << "| 25-point grid + golden section to " << sci(tol, 0) << " | " << 25 + p.evaluations << " | "
              << sci(std::abs(p.speed - reference.speed) * 3.6) << " | "
              << sci(std::abs(p.amplitude - reference.amplitude) / reference.amplitude) << " | " << fix(t * 1e3, 3)
              << " |\n";
  }
  std::cout << "\n";
}


// The linear simulation's time step, on two cases with known answers. Free decay of a damped
// single DOF (closed form): the state transition is exact, so the error is round-off at any
// step. The Manchester coach (all DOFs, its dampers) over whole-rail cosine joints, which give
// one harmonic: started on its steady motion (from the direct harmonic solve, exact to
// round-off), it must stay on it; the error is the first-order hold's sampling of the load,
// O((ωΔt)²).
void simulation_time_step(const std::string& data) {
  const std::vector<double> steps_ms = {20, 10, 5, 2, 1, 0.5, 0.2, 0.1};
  {
    LinearSystem sys;
    sys.dofs = {Dof{"m.bounce", 0, Motion::bounce}};
    const double m = 1000.0, k = 1e6, zeta = 0.05, w = std::sqrt(k / m);
    sys.mass = Eigen::MatrixXd::Constant(1, 1, m);
    sys.stiffness = Eigen::MatrixXd::Constant(1, 1, k);
    sys.damping = Eigen::MatrixXd::Constant(1, 1, 2 * zeta * std::sqrt(k * m));
    sys.gravity_stiffness = Eigen::MatrixXd::Zero(1, 1);
    const double x0 = 0.02, wd = w * std::sqrt(1 - zeta * zeta), duration = 2.0;
    std::cout << "### Free decay of one damped DOF (m = 1000 kg, k = 1 MN/m, ζ = 0.05, 5.03 Hz), 2 s from 20 mm\n\n"
                 "Error = max over the record of |x − x_exact|/x₀, x_exact = x₀e^{−ζωt}(cos ω_d t + ζω/ω_d sin ω_d t).\n\n"
                 "| step (ms) | steps per period | max relative error | time per simulated second (ms) |\n"
                 "|---:|---:|---:|---:|\n";
    for (double step : steps_ms) {
      SimulationOptions o;
      o.duration = duration;
      o.time_step = step * 1e-3;
      o.initial = {{"m.bounce", x0, 0.0}};
      const TimeHistory h = simulate_linear(sys, {}, o);
      double error = 0.0;
      for (int i = 0; i < h.time.size(); ++i) {
        const double t = h.time(i);
        const double x = x0 * std::exp(-zeta * w * t) * (std::cos(wd * t) + zeta * w / wd * std::sin(wd * t));
        error = std::max(error, std::abs(h.displacement(i, 0) - x) / x0);
      }
      const double t = seconds_per_call([&] { simulate_linear(sys, {}, o); });
      std::cout << "| " << step << " | " << fix(2 * kPi / w / (step * 1e-3), 1) << " | " << sci(error) << " | "
                << fix(t / duration * 1e3, 3) << " |\n";
    }
    std::cout << "\n";
  }
  {
    const LinearSystem sys = assemble(load_vehicle(data + "/vehicles/manchester_benchmark_coach.toml"), DofSet::all);
    const ModalResult modes = solve_modes(sys);
    RailJoints j;
    j.rail_length = 25.0;
    j.dip_depth = 0.005;
    const auto source = make_source(j);
    const double V = 30.0, duration = 10.0;
    const HarmonicLoad load = source->load(sys, V, 1);
    const Eigen::VectorXcd X = harmonic_response(sys, modes, generalized_load(sys, load), load.frequency_hz).displacement;
    const double w = 2 * kPi * load.frequency_hz;
    SimulationOptions o;
    o.speed = V;
    o.duration = duration;
    for (int d = 0; d < sys.size(); ++d)
      o.initial.push_back({sys.dofs[d].label, X(d).real(), -w * X(d).imag()});  // Re(X), Re(iωX)
    std::cout << "### Manchester coach, all " << sys.size() << " DOFs, its dampers, whole-rail cosine joints of 25 m rails "
              << "at 108 km/h (" << fix(load.frequency_hz, 2) << " Hz), 10 s started on the steady motion\n\n"
              << "Error = max over the record of ‖x − Re(X e^{iωt})‖/‖X‖, X from the direct harmonic solve.\n\n"
              << "| step (ms) | steps per load period | max relative error | time per simulated second (ms) |\n"
              << "|---:|---:|---:|---:|\n";
    for (double step : steps_ms) {
      o.time_step = step * 1e-3;
      const TimeHistory h = simulate_linear(sys, {source.get()}, o);
      double error = 0.0;
      for (int i = 0; i < h.time.size(); ++i) {
        const Eigen::VectorXd exact = (X * std::exp(std::complex<double>(0.0, w * h.time(i)))).real();
        error = std::max(error, (h.displacement.row(i).transpose() - exact).norm() / X.norm());
      }
      const double t = seconds_per_call([&] { simulate_linear(sys, {source.get()}, o); });
      std::cout << "| " << step << " | " << fix(1.0 / load.frequency_hz / (step * 1e-3), 1) << " | " << sci(error)
                << " | " << fix(t / duration * 1e3, 3) << " |\n";
    }
    std::cout << "\n";
  }
}

// The spectrum's record length, zero padding and window against the interpolated peak of a
// tone of known frequency and amplitude: the worst over tones placed 0, 0.05, …, 0.5 bin off a
// bin centre (scalloping and the interpolation's bias depend on that offset), with the time
// of one spectrum and its peak search (plan reused).
void spectrum_knobs() {
  const double fs = 100.0, A = 0.003, nominal = 1.37;
  std::cout << "### A 3 mm tone near 1.37 Hz sampled at 100 Hz, on a 50 mm static offset\n\n"
               "Errors are the worst over tones 0, 0.05, …, 0.5 bin of fs/N off a bin centre: frequency in Hz "
               "and in bins of the record's resolution fs/N, amplitude relative to 3 mm; the peak taken is the "
               "largest one `find_peaks` reports. Padding ×4 transforms 4N samples (Padding::to_length).\n\n"
               "| record (s) | samples N | window | padding | frequency error (Hz) | (bins) | amplitude error | "
               "time per spectrum + peaks (ms) |\n"
               "|---:|---:|---|---|---:|---:|---:|---:|\n";
  for (double record : {10.0, 40.0, 160.0})
    for (Window window : {Window::rectangular, Window::hann, Window::flat_top})
      for (int pad : {1, 4}) {
        const Eigen::Index N = static_cast<Eigen::Index>(record * fs);
        SpectrumOptions options;
        options.window = window;
        if (pad > 1) {
          options.padding = Padding::to_length;
          options.padded_length = pad * N;
        }
        SpectrumAnalyzer analyzer(N, options);
        const double bin = fs / static_cast<double>(N);
        const double centre = std::round(nominal / bin);
        double f_error = 0.0, a_error = 0.0;
        Eigen::VectorXd x(N);
        Spectrum spectrum;
        for (int o = 0; o <= 10; ++o) {
          const double f = (centre + 0.05 * o) * bin;
          for (Eigen::Index n = 0; n < N; ++n) x(n) = 0.05 + A * std::sin(2 * kPi * f * n / fs + 0.3);
          analyzer.compute(x, fs, &spectrum);
          const auto peaks = find_peaks(spectrum);
          const auto best = std::max_element(peaks.begin(), peaks.end(), [](const auto& a, const auto& b) {
            return a.amplitude < b.amplitude;
          });
          f_error = std::max(f_error, std::abs(best->frequency - f));
          a_error = std::max(a_error, std::abs(best->amplitude - A) / A);
        }
        const double t = seconds_per_call([&] {
          analyzer.compute(x, fs, &spectrum);
          find_peaks(spectrum);
        });
        std::cout << "| " << record << " | " << N << " | " << to_string(window) << " | "
                  << (pad > 1 ? "×" + std::to_string(pad) : "none") << " | " << sci(f_error) << " | "
                  << fix(f_error / bin, 4) << " | " << sci(a_error) << " | " << fix(t * 1e3, 3) << " |\n";
      }
  std::cout << "\n";
}

// Leaf friction: the Runge–Kutta tolerance and the event tolerance against the exact piecewise
// solution of Speer's drop test (springs digest, Example 7, Table 5 row 1): the reversal after
// π/k₁ and the stick π/k₂ later, k₁,₂² = (g/f)(1 ± φ), extremes 39 → −21.94 → 2.61 mm.
void friction_tolerances(const std::string& data) {
  Scene scene = load_scene(data + "/scenes/leaf_spring_drop_test.toml");
  // Outputs every 0.1 s, so that the step size is the integrator's choice (at the scene's 1 ms
  // outputs every tolerance lands on round-off: the output times cap the steps).
  scene.simulation->time_step = 0.1;
  const Vehicle vehicle = load_vehicle(scene.vehicle_file);
  const double g = vehicle.gravity, f = 0.145, phi = 0.0625, a1 = 0.039;
  const double k1 = std::sqrt(g / f * (1 + phi)), k2 = std::sqrt(g / f * (1 - phi));
  const double c1 = phi * f / (1 + phi), c2 = -phi * f / (1 - phi);
  const double z1 = 2 * c1 - a1, z2 = 2 * c2 - z1;
  const double t1 = kPi / k1, t2 = kPi / k1 + kPi / k2;
  std::cout << "### Speer's drop test (Table 5 row 1, `data/scenes/leaf_spring_drop_test.toml`, 2 s, output every 0.1 s) "
               "against its exact piecewise solution: the reversal at π/k₁ = "
            << fix(t1, 6) << " s and the stick at " << fix(t2, 6) << " s, extremes " << fix(1e3 * z1, 4) << " and "
            << fix(1e3 * z2, 4) << " mm. The error of the extremes is read at the events (where the integrator "
               "lands), the time error from the events themselves. Defaults: tolerance 1e-10, event tolerance 1e-12 s.\n\n"
            << "| tolerance | event tolerance [s] | RK steps | extreme error [m] | event time error [s] | time per run |\n"
            << "|---|---|---|---|---|---|\n";
  struct Knobs {
    double tolerance, event_tolerance;
  };
  for (const Knobs k : {Knobs{1e-4, 1e-12}, Knobs{1e-6, 1e-12}, Knobs{1e-8, 1e-12}, Knobs{1e-10, 1e-12},
                        Knobs{1e-12, 1e-12}, Knobs{1e-10, 1e-3}, Knobs{1e-10, 1e-6}, Knobs{1e-10, 1e-9}}) {
    scene.simulation->tolerance = k.tolerance;
    scene.simulation->event_tolerance = k.event_tolerance;
    const TimeHistory h = simulate_scene(scene, vehicle);
    std::string extreme = "—", timing = "—";
    if (h.events.size() == 2) {
      extreme = sci(std::max(std::abs(h.events[0].displacement(0) - z1), std::abs(h.events[1].displacement(0) - z2)));
      timing = sci(std::max(std::abs(h.events[0].time - t1), std::abs(h.events[1].time - t2)));
    } else {
      extreme = std::to_string(h.events.size()) + " events (2 expected)";
    }
    const double s = seconds_per_call([&] { simulate_scene(scene, vehicle); });
    std::cout << "| " << sci(k.tolerance, 0) << " | " << sci(k.event_tolerance, 0) << " | " << h.steps_taken << " | "
              << extreme << " | " << timing << " | " << fix(1e3 * s, 3) << " ms |\n";
  }
  std::cout << "\n";
}


// The two integrators on one linear scene: the state transition (exact for a load linear over
// the step) against adaptive Dormand–Prince 5(4) (the nonlinear path with no effects named).
void integrators(const std::string& data) {
  Scene scene = load_scene(data + "/scenes/two_axle_freight_wagon_joints_friction.toml");
  scene.simulation->effects.clear();  // linear: both integrators apply
  const Vehicle vehicle = load_vehicle(scene.vehicle_file);
  const LinearSystem system = scene_system(scene, vehicle);
  std::vector<const ExcitationSource*> sources;
  for (const auto& src : scene.sources) sources.push_back(src.get());
  // Compared every 0.1 s: the adaptive path then takes the steps it chooses (its steps end on
  // the output times, so a fine output grid would cap them).
  constexpr double kCompare = 0.1;
  SimulationOptions o;
  o.speed = scene.simulation->speed;
  o.duration = 3.0;
  o.time_step = kCompare;
  o.initial = scene.simulation->initial;
  o.tolerance = 1e-13;
  const TimeHistory reference = simulate_nonlinear(system, sources, o, NonlinearEffects{});
  const double scale = reference.displacement.col(0).cwiseAbs().maxCoeff();
  auto error = [&](const TimeHistory& h, Eigen::Index every) {
    double worst = 0.0;
    for (Eigen::Index i = 0; i < reference.time.size(); ++i)
      worst = std::max(worst, std::abs(h.displacement(i * every, 0) - reference.displacement(i, 0)));
    return worst / scale;
  };
  std::cout << "### " << scene.name << ", without the friction (2 DOFs, 3 s)\n\n"
            << "Reference: the adaptive integrator at tolerance 1e-13. Errors: the largest body.bounce difference "
               "at every 0.1 s, relative to its largest value.\n\n"
            << "| integrator | step or tolerance | steps | max relative error | time per run |\n|---|---|---:|---:|---:|\n";
  for (const double step : {5e-3, 2e-3, 1e-3, 1e-4}) {
    SimulationOptions lo = o;
    lo.time_step = step;
    const TimeHistory h = simulate_linear(system, sources, lo);
    const double s = seconds_per_call([&] { simulate_linear(system, sources, lo); });
    std::cout << "| state transition | " << fix(1e3 * step, 1) << " ms | " << std::llround(o.duration / step) << " | "
              << sci(error(h, std::llround(kCompare / step))) << " | " << fix(1e3 * s, 3) << " ms |\n";
  }
  for (const double tol : {1e-4, 1e-6, 1e-8, 1e-10}) {
    SimulationOptions ao = o;
    ao.tolerance = tol;
    const TimeHistory h = simulate_nonlinear(system, sources, ao, NonlinearEffects{});
    const double s = seconds_per_call([&] { simulate_nonlinear(system, sources, ao, NonlinearEffects{}); });
    std::cout << "| adaptive Dormand–Prince 5(4) | " << sci(tol, 0) << " | " << h.steps_taken << " | " << sci(error(h, 1))
              << " | " << fix(1e3 * s, 3) << " ms |\n";
  }
  std::cout << "\n";
}

}  // namespace

// Low modes beside a stiff link (issue 18 item 9): two 1000 kg masses, 100 N/m to ground and a
// link k between them; λ₁ against the closed form 2 det/(tr + √(tr² − 4 det)), det = 100·k/m²
// (no cancellation). Both solvers; the rounding bound each reports (Mode::eigenvalue_error).
void stiff_link_low_mode() {
  std::cout << "| link k [N/m] | λmax/λ₁ | exact f₁ [Hz] | dense: relative error of λ₁ | dense: bound | "
               "ARPACK: relative error of λ₁ | ARPACK: bound | mode 1 |\n|---|---:|---:|---:|---:|---:|---:|---|\n";
  for (double link : {1e6, 1e9, 1e12, 1e14, 1e15, 1e16}) {
    const double m = 1000.0, ground = 100.0;
    LinearSystem system;
    system.dofs = {{"dof1", -1, Motion::bounce}, {"dof2", -1, Motion::bounce}};
    system.mass = Eigen::Vector2d(m, m).asDiagonal();
    system.stiffness.resize(2, 2);
    system.stiffness << ground + link, -link, -link, link;
    system.damping = system.gravity_stiffness = Eigen::MatrixXd::Zero(2, 2);
    const double tr = (ground + 2.0 * link) / m, det = ground * link / (m * m);
    const double exact = 2.0 * det / (tr + std::sqrt(tr * tr - 4.0 * det));
    std::cout << "| " << sci(link, 0) << " | " << sci(tr / exact, 1) << " | " << std::setprecision(13)
              << std::sqrt(exact) / (2.0 * kPi);
    std::string kind;
    for (ModalSolver solver : {ModalSolver::dense, ModalSolver::arpack}) {
      ModalOptions options;
      options.solver = solver;
      options.mode_count = solver == ModalSolver::arpack ? 1 : 0;
      const ModalResult result = solve_modes(system, options);
      const Mode& mode = result.modes.front();
      std::cout << " | " << sci(std::abs(mode.eigenvalue / exact - 1.0)) << " | " << sci(mode.eigenvalue_error / exact);
      kind += (kind.empty() ? "" : " / ") + std::string(to_string(mode.kind));
    }
    std::cout << " | " << kind << " |\n";
  }
  std::cout << "\n";
}

// Hunting stability on a system whose answer is exact: a unit oscillator (1 Hz) whose damping
// coefficient d(V) = c_c/V + c0 + g·V = g(V − a)(V − b)/V is negative exactly on (a, b).
// Through the private stability::hunting_analysis, since it has no wheelsets: these rows
// measure the solver (root finder, grid, dip guard), not a contact model.
HuntingResult oscillator_stability(double a, double b, int count, double tolerance) {
  LinearSystem s;
  s.dofs = {{"osc.lateral", -1, Motion::lateral}};
  s.mass = Eigen::MatrixXd::Identity(1, 1);
  s.stiffness = Eigen::MatrixXd::Constant(1, 1, 4.0 * kPi * kPi);
  s.damping = Eigen::MatrixXd::Constant(1, 1, -0.01 * (a + b));
  ContactMatrices c;
  c.creep_damping = Eigen::MatrixXd::Constant(1, 1, 0.01 * a * b);
  c.gyroscopic = Eigen::MatrixXd::Constant(1, 1, 0.01);
  c.stiffness = Eigen::MatrixXd::Zero(1, 1);
  HuntingOptions o;
  o.min_speed = 10.0;
  o.max_speed = 400.0;
  o.speed_count = count;
  o.relative_tolerance = tolerance;
  o.threads = 1;
  return stability::hunting_analysis(
      s, [&c](std::optional<double>) { return c; }, o);
}

void hunting_root_finder() {
  const double exact = 37.0;
  std::cout << "### Root finder: relative tolerance against evaluations (grid of 40 speeds, 10–400 m/s, exact "
               "critical speed 37 m/s)\n\n| relative tolerance | evaluations | relative error |\n|---:|---:|---:|\n";
  for (double tolerance : {1e-2, 1e-4, 1e-6, 1e-8, 1e-10, 1e-12, 1e-14}) {
    const HuntingResult r = oscillator_stability(exact, 300.0, 40, tolerance);
    std::cout << "| " << sci(tolerance, 0) << " | " << r.critical->evaluations << " | "
              << sci(std::abs(r.critical->speed / exact - 1.0)) << " |\n";
  }
  std::cout << "\n### Speed grid: the critical speed read off the grid against refined (exact 37 m/s)\n\n"
               "| grid speeds | first unstable grid speed: relative error | ζ interpolated linearly: relative error | "
               "refined to 1e-8: relative error | evaluations |\n|---:|---:|---:|---:|---:|\n";
  for (int count : {5, 10, 20, 50, 100, 200, 1000}) {
    const HuntingResult r = oscillator_stability(exact, 300.0, count, 1e-8);
    const HuntingBranch& b = r.branches.front();
    size_t s = 0;
    while (b.damping_ratio[s] >= 0.0) ++s;
    const double v0 = r.speeds[s - 1], v1 = r.speeds[s], z0 = b.damping_ratio[s - 1], z1 = b.damping_ratio[s];
    const double linear = v0 + (v1 - v0) * z0 / (z0 - z1);
    std::cout << "| " << count << " | " << sci(std::abs(v1 / exact - 1.0)) << " | "
              << sci(std::abs(linear / exact - 1.0)) << " | " << sci(std::abs(r.critical->speed / exact - 1.0)) << " | "
              << r.critical->evaluations << " |\n";
  }
  std::cout << "\n### Narrow unstable intervals between grid speeds (10–400 m/s)\n\n"
               "| unstable interval (m/s) | grid speeds | grid speeds inside it | found (with the dip guard) | "
               "refined ends (m/s) |\n|---|---:|---:|---|---|\n";
  for (const auto& interval :
       std::vector<std::pair<double, double>>{{203.0, 204.0}, {203.0, 203.1}, {203.0, 203.01}, {203.0, 203.001}})
    for (int count : {20, 40, 200}) {
      const HuntingResult r = oscillator_stability(interval.first, interval.second, count, 1e-8);
      int inside = 0;
      for (double v : r.speeds) inside += v > interval.first && v < interval.second;
      std::cout << "| " << interval.first << "–" << interval.second << " | " << count << " | " << inside << " | "
                << (r.unstable_intervals.empty() ? "no" : "yes") << " | ";
      for (const UnstableInterval& u : r.unstable_intervals)
        std::cout << std::setprecision(10) << u.from << "–" << u.to << " ";
      std::cout << "|\n";
    }
  std::cout << "\n";
}

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: railmodal_accuracy DATA_DIR > docs/accuracy.md\n";
    return 2;
  }
  const std::string data = argv[1];
#ifdef __GLIBC__
  // Keep freed blocks in the heap instead of returning them to the system: the times below
  // are of the computation, not of the fresh pages a new mapping costs (each page fault takes
  // ~17 µs under some hypervisors, which would swamp a simulation of a few thousand steps).
  mallopt(M_MMAP_THRESHOLD, 1 << 30);
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
#endif
  std::cout << "# Accuracy against time\n\n"
               "Generated by `bash tools/update_accuracy.sh` (the program `tools/accuracy/accuracy_report.cpp`) "
               "down to the end marker: every figure there comes from one run on one machine, errors against a "
               "reference computed in the same run, times as the median of five batches. Re-run it rather than "
               "editing that part; the sections after the marker are written by hand, and the script keeps them "
               "as they are.\n\n"
               "## Harmonic response: modal superposition against the direct solve\n\n"
               "Modal superposition sums the lowest m modes with modal damping diag(ΦᵀCΦ). It is exact with "
               "all modes when damping is proportional; with discrete dampers (the Manchester coach) the "
               "neglected off-diagonal modal damping sets an error floor that more modes do not remove: its "
               "dampers give modal damping ratios up to 0.5 and off-diagonal terms a quarter of the diagonal, "
               "so only the direct solve is right there. The critical-speed report uses all modes where that is exact (C = 0 "
               "or proportional damping, no damper on a massless DOF: the projected loads, src/response/speed_sweep.cpp) "
               "the complex modes of the first-order form for discrete dampers (exact too, checked against the direct "
               "solve at nine speeds before use), and the direct solve where neither can be trusted. At each output it "
               "leaves out the modes whose shape there is the eigensolver's round-off (below 1e-12 of the shape's largest "
               "component: the pitch modes at the bounce of a symmetric car), which changes the output by at most 1e-12 "
               "of that mode's own response and, on the resort car, takes 9 of its 11 modes off the body-bounce sweep; a "
               "weak real coupling (a share of 1.5e-6) is kept (`AmplitudeCurves.WeakCouplingsKeptNearResonance`). "
               "Likewise it drops a modal load below 1e-12 of ‖φ‖‖Q‖ (the floor of the unbounded-speed test): "
               "staggered joints' first harmonic meets the resort car's bounce modes only through that noise, which "
               "summed gave up to 9e-19 m, where the direct solve gives 1e-55 m, with an arbitrary phase; the curve "
               "now says 0 (`AmplitudeCurves.NoPhaseWhereTheLoadDoesNotReachTheOutput`). The complex-mode and direct "
               "paths have no such floor yet.\n\n";
  {
    LinearSystem sys = assemble(load_vehicle(data + "/vehicles/resort_car.toml"), DofSet::all);
    sys.damping = 0.002 * sys.stiffness + 0.1 * sys.mass;  // Rayleigh damping: modes stay uncoupled
    RailJoints j;
    j.rail_length = 12.5;
    j.dip_depth = 0.005;
    j.staggered = true;
    modal_truncation("Resort car, all DOFs, Rayleigh damping, staggered joints of 12.5 m rails", sys, *make_source(j),
                     10 / 3.6, 200 / 3.6);
  }
  {
    const LinearSystem sys = assemble(load_vehicle(data + "/vehicles/manchester_benchmark_coach.toml"), DofSet::all);
    RailJoints j;
    j.rail_length = 25.0;
    j.dip_depth = 0.005;
    j.staggered = true;
    modal_truncation("Manchester coach, all DOFs, its own dampers, staggered joints of 25 m rails", sys,
                     *make_source(j), 10 / 3.6, 250 / 3.6);
  }
  std::cout << "## Amplitude curves: uniform speed grid against adaptive refinement of the peak\n\n"
               "A uniform grid misses the peak speed by up to half its spacing and the peak amplitude by the "
               "square of that (a smooth maximum is flat); golden section narrows the speed by 0.618 per solve, "
               "so a coarse grid plus refinement reaches round-off in amplitude with a few dozen solves.\n\n";
  {
    const LinearSystem sys = assemble(load_vehicle(data + "/vehicles/manchester_benchmark_coach.toml"), DofSet::lateral);
    Hunting h;
    h.conicity = 0.05;
    h.rolling_circle_spacing = 1.5;
    h.rolling_radius = 0.46;
    h.amplitude = 0.005;
    peak_search("Manchester coach, hunting 1:20, body lateral acceleration, 5–200 km/h", sys, *make_source(h),
                {sys.index_of("body.lateral"), ResponseQuantity::acceleration}, 5 / 3.6, 200 / 3.6);
  }
  std::cout << "## Linear simulation: time step\n\n"
               "The linear path integrates with the exact state transition and a first-order hold on the load "
               "(include/railmodal/simulation.hpp): free motion is exact at any step, so only a forced response "
               "has a step error, O((ωΔt)²) from sampling the load. The cost is linear in the number of steps.\n\n";
  simulation_time_step(data);
  std::cout << "## Linear simulation: integrator\n\n"
               "The state transition's only error is the sampled load (O(Δt²)); the adaptive Runge–Kutta path "
               "(which nonlinear scenes and speed ramps take) follows the load exactly and controls its own step. "
               "On a forced linear scene the state transition is the cheaper for a given error down to ~1e-7 "
               "(and its cost is fixed by the output step); below that the adaptive path is. Linear scenes "
               "without a ramp take the state transition.\n\n";
  integrators(data);
  std::cout << "## Spectrum: record length, zero padding and window\n\n"
               "The record length sets the resolution fs/N; padding interpolates the spectrum between bins (it "
               "resolves nothing new); the window trades line width for leakage and scalloping "
               "(include/railmodal/spectrum.hpp). The errors in bins do not depend on the record, so the "
               "frequency error in Hz falls as 1/N; the time grows as N log N. Rectangular: its interpolated "
               "amplitude is 16 % off between bins unless padded. Hann: the best frequency, and padding ×4 "
               "takes both errors down a hundredfold. Flat-top: the best amplitude unpadded, but the worst "
               "frequency, which padding makes worse: across its flat lobe the parabola through three "
               "neighbouring bins sees mostly ripple. So Hann (padded) for frequencies, flat-top for the "
               "amplitudes of steady tones.\n\n";
  spectrum_knobs();
  std::cout << "## Nonlinear simulation: integrator tolerance and event tolerance\n\n"
               "Scenes that name leaf_friction or progressive_springs run adaptive Dormand–Prince 5(4) steps "
               "between located events (include/railmodal/simulation.hpp). The tolerance bounds the local error "
               "of a step relative to the state; the event tolerance bounds where a stick, slip, reversal or kink "
               "is put. Steps, and so time, grow as tolerance^(−1/5) while the error follows the tolerance. The "
               "event tolerance hardly matters: false position (Illinois) converges superlinearly, so its last "
               "iterate lies far inside the bracket it was asked for; only a bracket already shorter than the "
               "tolerance (a step shorter than it) is not refined at all — with 1 ms outputs and a 1e-3 s event "
               "tolerance the events land 8e-4 s late. Keep the default 1e-12 s: it costs nothing measurable.\n\n";
  friction_tolerances(data);
  std::cout << "## Modes: low modes beside a stiff link\n\n"
               "A direct eigensolve gives every λ to an absolute error of about ε·λmax, so a soft mode beside a "
               "link 1e12 times stiffer keeps only ε·λmax/λ₁ of its digits while its residual stays at 1e-16. "
               "Both solvers solve such low modes (λmax/λ > 1e8) again by Rayleigh–Ritz with ZᵀKZ and ZᵀMZ "
               "summed in double-double (src/solve/low_modes.cpp), and count rigid-body modes by the inertia of "
               "K ∓ tM, t = 8·m·ε·max Σⱼ|Kᵢⱼ|/Mᵢᵢ, instead of reading them off λ. The bound is the rounding "
               "error each mode reports (Mode::eigenvalue_error, 4ε·the largest |λ| of the problem it was last "
               "solved in); the summary's check fails above 1e-6. Before this (issue 18 item 9) mode 1 was off "
               "by 6.1e-7 at 1e12, 7.8e-5 at 1e14 and called rigid-body at 1e15. At 1e16, λ₁ = 0.05 1/s² lies "
               "inside t = 0.07 1/s² (what rounding K's entries of 2e16 can move an eigenvalue by) and mode 1 is "
               "called rigid-body: beyond that contrast the soft spring cannot be told from rounding.\n\n"
               "### Two 1000 kg masses, 100 N/m to ground, link k between them\n\n";
  stiff_link_low_mode();
  std::cout << "## Hunting stability: root finder and speed grid\n\n"
               "The critical speed is where the least-damped ζ crosses zero (include/railmodal/hunting.hpp, "
               "docs/stability.md). The grid brackets it; Brent's method refines the bracket until it is below "
               "the relative tolerance, each evaluation one eigenvalue-only solve of the state matrix (about "
               "0.15 ms of CPU for the 38 states of a bogie vehicle with four wheelsets: tools/benchmarks/"
               "compare_stability.py). Here on an oscillator whose answer is exact, d(V) = g(V − a)(V − b)/V. "
               "The grid alone is first order in its spacing (linear interpolation of ζ: second order); the "
               "refinement costs a handful of solves whatever the grid. A grid can also step over a narrow "
               "unstable interval: at every grid minimum of ζ closer to zero than its rise to the higher "
               "neighbour, golden section looks between the two neighbours (the dip guard). It finds intervals "
               "down to 5e-5 of the speed that no grid speed falls in, each end refined to the tolerance. The "
               "last rows' interval (1 mm/s wide) is not found, rightly: its deepest ζ is −1e-12, a growth "
               "below the round-off band (|Re λ| ≤ 1e-11·s counts as neutral, s the largest |λ| of the complex roots: "
               "docs/stability.md). A dip that does not make the grid's ζ a local minimum near "
               "zero (a narrow interval on a steep slope of ζ) can still be missed: a finer grid is the "
               "remedy.\n\n";
  hunting_root_finder();
  return 0;
}
