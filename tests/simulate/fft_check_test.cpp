// fft-check compares only what the record holds: a mode the initial conditions leave at rest
// is "not excited", never an "ok" read off round-off, and each excited mode is checked on a
// DOF where it moves.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "railmodal/railmodal.hpp"
#include "simulate/free_response.hpp"
#include "test_support.hpp"

namespace railmodal::test {
namespace {

std::string data(const std::string& file) { return std::string(RAILMODAL_DATA_DIR) + "/" + file; }

// A bundled scene run for `duration` instead of its `bundled` one, its vehicle found from the
// temporary folder.
std::string scene_cut_to(const std::string& scene, const std::string& vehicle, const std::string& bundled,
                         const std::string& duration) {
  std::ifstream in(data("scenes/" + scene));
  std::stringstream all;
  all << in.rdbuf();
  std::string text = all.str();
  const auto replace = [&text](const std::string& from, const std::string& to) {
    const size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
  };
  replace("duration = \"" + bundled + "\"", "duration = \"" + duration + "\"");
  replace("\"../vehicles/" + vehicle + "\"", "\"" + data("vehicles/" + vehicle) + "\"");
  return text;
}

// A mode not excited is named on its own most energetic DOF, not on a DOF that other modes move:
// the resort car released in bounce leaves its body pitch at 1e-15 of the bounce, and the pitch's
// small share on the moving bogie2.bounce made that DOF its check's before.
TEST(FftCheck, AModeNotExcitedIsNamedOnItsOwnDof) {
  const Scene scene = load_scene(data("scenes/resort_car_friction_decay.toml"));
  const FftCheckResult r = fft_check(scene, load_vehicle(scene.vehicle_file));
  int not_excited = 0;
  for (const FftCheck& c : r.checks) {
    if (c.excited) {
      EXPECT_NE(std::find(r.spectrum_dofs.begin(), r.spectrum_dofs.end(), c.dof), r.spectrum_dofs.end()) << c.dof;
      continue;
    }
    ++not_excited;
    const Mode& mode = r.modes.modes[static_cast<size_t>(c.mode - 1)];
    Eigen::Index most = 0;
    mode.kinetic_energy_share.maxCoeff(&most);
    EXPECT_EQ(c.dof, r.history.labels[static_cast<size_t>(most)]) << c.mode_name;
    if (c.mode_name == "body pitch") {
      EXPECT_EQ(c.dof, "body.pitch");
    }
  }
  EXPECT_EQ(not_excited, 4);
  // Only the excited modes' DOFs have spectra (body.bounce and bogie2.bounce).
  EXPECT_EQ(r.spectrum_dofs.size(), 2u);
}

// The bundled Example 3 scene (the two-axle wagon at 75 km/h over 10 m joints, with leaf
// friction), run for `duration` instead of its 3 s.
std::string joints_friction_scene(const std::string& duration) {
  return scene_cut_to("two_axle_freight_wagon_joints_friction.toml", "two_axle_freight_wagon.toml", "3 s", duration);
}

// The two-axle wagon's bounce and pitch decouple exactly (a symmetric wagon: two-axle digest,
// eq. (159)); released in bounce alone, its pitch holds nothing but round-off.
TEST(FftCheck, ModeTheReleaseLeavesAtRestIsNotExcited) {
  const std::string scene_file = write_temp("bounce_release.toml", "[scene]\nname = \"bounce release\"\nvehicle = \"" +
                                                                       data("vehicles/two_axle_freight_wagon.toml") +
                                                                       R"("
dofs = "vertical"
[simulation]
duration = "20 s"
time_step = "2 ms"
[[simulation.initial]]
dof = "body.bounce"
displacement = "10 mm"
)");
  const Scene scene = load_scene(scene_file);
  const Vehicle vehicle = load_vehicle(scene.vehicle_file);
  const FftCheckResult r = fft_check(scene, vehicle);
  ASSERT_EQ(r.checks.size(), 2u);
  for (const FftCheck& c : r.checks) {
    if (c.mode_name == "body bounce") {
      EXPECT_TRUE(c.excited);
      EXPECT_EQ(c.modal_amplitude_ratio, 1.0);
      ASSERT_TRUE(c.peak_hz);
      EXPECT_TRUE(c.within_resolution) << *c.peak_hz << " against " << c.modal_hz;
    } else {
      EXPECT_EQ(c.mode_name, "body pitch");
      // Exactly decoupled: the pitch coordinate stays at round-off of the bounce (1e-16 of it,
      // times the steps' accumulation), far below the 1e-6 floor.
      EXPECT_FALSE(c.excited);
      EXPECT_LT(c.modal_amplitude_ratio, 1e-10);
      EXPECT_FALSE(c.peak_hz);
      EXPECT_EQ(c.dof, "body.pitch");  // its own DOF, at rest
      EXPECT_EQ(c.resolution_hz, r.spectra.front().resolution);  // the record's fs/N all the same
    }
  }
  // No spectrum for the mode not excited: body.pitch's would be round-off, charted as a signal.
  EXPECT_EQ(r.spectrum_dofs, std::vector<std::string>{"body.bounce"});
  std::ostringstream table;  // says so instead of a peak
  write_fft_check(table, r, scene, vehicle, OutputFormat::table);
  const std::string text = table.str();
  const size_t pitch = text.find("body pitch");
  ASSERT_NE(pitch, std::string::npos) << text;
  const std::string row = text.substr(pitch, text.find('\n', pitch) - pitch);
  EXPECT_NE(row.find("not excited (modal amplitude "), std::string::npos) << row;
}

// The resort car released in body and front-bogie motions (the bundled scene): the two bogie
// pitch modes are a repeated pair (4.3107 Hz, bogies that do not couple in pitch), whose basis
// may put one mode mostly on the rear bogie, which the release leaves at rest. Every check must
// read a DOF that moves, and find the mode there within the resolution.
TEST(FftCheck, EveryModeIsCheckedWhereItMoves) {
  const Scene scene = load_scene(data("scenes/resort_car_free_response.toml"));
  const FftCheckResult r = fft_check(scene, load_vehicle(scene.vehicle_file));
  ASSERT_EQ(r.checks.size(), 6u);
  for (const FftCheck& c : r.checks) {
    EXPECT_TRUE(c.excited) << c.mode_name;
    int dof = -1;
    for (size_t d = 0; d < r.history.labels.size(); ++d)
      if (r.history.labels[d] == c.dof) dof = static_cast<int>(d);
    ASSERT_GE(dof, 0) << c.dof;
    // Released by millimetres and milliradians: a DOF that moves moves by more than 1e-6 (m or
    // rad); round-off stays below 1e-12.
    EXPECT_GT(r.history.displacement.col(dof).cwiseAbs().maxCoeff(), 1e-6) << c.mode_name << " on " << c.dof;
    ASSERT_TRUE(c.peak_hz) << c.mode_name;
    EXPECT_TRUE(c.within_resolution) << c.mode_name << ": " << *c.peak_hz << " against " << c.modal_hz;
  }
}

// Issue 17 item 9: a short record of a friction scene used to pass as "ok" — the two-axle
// wagon at 75 km/h over 10 m joints (the bundled Example 3 scene) cut to 1.5 s gave peaks 16 %
// and 18 % off the modes, each "within the resolution" because its line was 0.9–1.4 Hz wide.
// A nonlinear check is held to FftCheck::kNonlinearTolerance where the record resolves it; and
// no record of this scene, however long, can check it (fix-checks, 2026-11-27): its speed puts
// the joints' line V/λ = 2.084 Hz on the bounce mode, so a bounce peak is the forcing's whatever
// the mode, and the pitch's peak is that same forcing line. Neither is checked, the verdict is
// "NOT CHECKED" (not a pass), and each row says why rather than asking for a longer run.
TEST(FftCheck, FrictionSceneForcedAtItsModeIsNotCheckedAndSaysWhy) {
  const Scene scene = load_scene(write_temp("short_friction.toml", joints_friction_scene("1.5 s")));
  const FftCheckResult r = fft_check(scene, load_vehicle(scene.vehicle_file));
  EXPECT_TRUE(r.nonlinear);
  EXPECT_FALSE(r.passed);
  EXPECT_EQ(r.checked, 0);
  EXPECT_EQ(r.failed, 0);
  ASSERT_EQ(r.checks.size(), 2u);
  for (const FftCheck& c : r.checks) {
    EXPECT_EQ(c.tolerance, FftCheck::kNonlinearTolerance);
    EXPECT_EQ(c.outcome, FftCheck::Outcome::not_applicable) << c.mode_name;
    EXPECT_NE(c.why_not_applicable.find("V/λ = 2.084 Hz"), std::string::npos) << c.why_not_applicable;
    EXPECT_EQ(c.needed_duration_s, 0.0) << c.mode_name;  // no run would do: none is asked for
  }
  // The pitch (1.41 Hz) is far from the line: its peak is taken by the line because the linear
  // forced response there explains the peak's amplitude (the bundled 3 s run: 1.06 mrad against
  // a 1.02 mrad peak).
  ASSERT_EQ(r.checks[0].mode_name, "body pitch");
  EXPECT_EQ(r.checks[0].why_not_applicable.rfind("the peak found is the forcing's own line", 0), 0u)
      << r.checks[0].why_not_applicable;
  std::ostringstream table;
  write_fft_check(table, r, scene, load_vehicle(scene.vehicle_file), OutputFormat::table);
  const std::string text = table.str();
  EXPECT_NE(text.find("within 5.0 %"), std::string::npos) << text;
  EXPECT_EQ(text.find("a run of at least"), std::string::npos) << text;
  EXPECT_EQ(text.find("verdict: passed"), std::string::npos) << text;
  EXPECT_EQ(text.find("  passed ("), std::string::npos) << text;  // no mode's row says passed either
  // The verdict is the report's last line, below the half periods it also judges.
  const std::string last = text.substr(text.rfind('\n', text.size() - 2) + 1);
  EXPECT_EQ(last.rfind("verdict: NOT CHECKED: no mode's line could be checked (2 not applicable: ", 0), 0u) << last;
}

// A check the record can make and that is outside the tolerance fails. Khanin's spring (springs
// Example 10) swings across its kink with a period of its own, 0.496 s: the line at 2.015 Hz
// lies 7.8 % below the linear mode's 2.1867 Hz, and 10 s resolve 5 % of f (a line ~0.1 Hz wide):
// checked, FAILED.
TEST(FftCheck, ResolvedLineOutsideTheToleranceFails) {
  const Scene scene =
      load_scene(write_temp("khanin_10s.toml", scene_cut_to("khanin_spring_free_oscillation.toml",
                                                            "khanin_progressive_spring.toml", "20 s", "10 s")));
  const FftCheckResult r = fft_check(scene, load_vehicle(scene.vehicle_file));
  ASSERT_EQ(r.checks.size(), 1u);
  const FftCheck& c = r.checks.front();
  EXPECT_EQ(c.outcome, FftCheck::Outcome::failed);
  EXPECT_LE(c.resolution_hz, c.tolerance * c.modal_hz);  // resolved: the check was made
  EXPECT_GT(std::abs(c.rel_error), c.tolerance);
  EXPECT_EQ(r.checked, 1);
  EXPECT_EQ(r.failed, 1);
  EXPECT_FALSE(r.passed);
  EXPECT_EQ(fft_check_verdict(r), "FAILED: 1 of 1 modes checked, 1 outside its tolerance");
  // More than one outside: each outside its own tolerance (audit 2026-11-27b).
  FftCheckResult two = r;
  two.checks.push_back(two.checks.front());
  two.checked = two.failed = 2;
  EXPECT_EQ(fft_check_verdict(two), "FAILED: 2 of 2 modes checked, 2 outside their tolerances");
}

// A forcing line within the resolution of the peak found takes the peak from the mode only
// where the linear forced response explains the peak's amplitude (at least a tenth of it).
// Khanin's spring released 20 mm (springs Example 10, 10 s: its own line at 2.015 Hz, 7.8 %
// below the linear mode, FAILED as a free release) run over joints at 72.54 km/h, whose line
// V/λ = 2.015 Hz is the peak's and lies 7.9 % from the mode (outside the 5 % that makes any line
// at the mode the forcing's). Dips of 0.01 mm: a linear forced response of 0.033 mm against an
// 18.5 mm peak (1.8e-3), a weak harmonic near the mode's own peak: the check is made, and fails
// as the free release does. Dips of 5 mm: 16.6 mm of linear response in an 81 mm peak (the
// kinked spring driven at its own line grows it 4.9× past the linear model): the forcing's line,
// not applicable.
std::string khanin_over_joints(const std::string& dip) {
  std::string text =
      scene_cut_to("khanin_spring_free_oscillation.toml", "khanin_progressive_spring.toml", "20 s", "10 s");
  const size_t at = text.find("effects = ");
  EXPECT_NE(at, std::string::npos);
  if (at != std::string::npos) text.insert(at, "speed = \"72.54 km/h\"\n");
  return text + "\n[[source]]\nkind = \"rail_joints\"\nrail_length = \"10 m\"\njoints = \"opposite\"\ndip_depth = \"" + dip +
         "\"\ndip_shape = \"cosine\"\n";
}

TEST(FftCheck, WeakHarmonicNearTheModesPeakDoesNotTakeIt) {
  const Scene weak = load_scene(write_temp("khanin_weak_joints.toml", khanin_over_joints("0.01 mm")));
  const FftCheckResult r = fft_check(weak, load_vehicle(weak.vehicle_file));
  ASSERT_EQ(r.checks.size(), 1u);
  const FftCheck& c = r.checks.front();
  ASSERT_TRUE(c.peak_hz);
  const double line = 72.54 / 3.6 / 10.0;
  // The premise: the forcing's line is within the resolution of the peak (the old net took it),
  // and outside the tolerance of the mode.
  EXPECT_LE(std::abs(line - *c.peak_hz), c.resolution_hz);
  EXPECT_GT(std::abs(line - c.modal_hz), c.tolerance * c.modal_hz);
  EXPECT_EQ(c.outcome, FftCheck::Outcome::failed) << c.why_not_applicable;
  EXPECT_TRUE(c.why_not_applicable.empty()) << c.why_not_applicable;
  EXPECT_EQ(r.checked, 1);

  const Scene strong = load_scene(write_temp("khanin_strong_joints.toml", khanin_over_joints("5 mm")));
  const FftCheckResult s = fft_check(strong, load_vehicle(strong.vehicle_file));
  ASSERT_EQ(s.checks.size(), 1u);
  EXPECT_EQ(s.checks.front().outcome, FftCheck::Outcome::not_applicable);
  EXPECT_EQ(s.checks.front().why_not_applicable.rfind("the peak found is the forcing's own line (rail_joints, V/λ = "
                                                      "2.015 Hz)", 0), 0u)
      << s.checks.front().why_not_applicable;
  EXPECT_EQ(s.checked, 0);
}

// A longer run of the same forced scene does not make its check: 10 s narrow the lines (the
// old verdict passed the bounce on the joints' line, "ok: 1 of 2 modes checked"), but the peak
// at the bounce frequency is still the forcing's, put there by the scene's speed.
TEST(FftCheck, LongerRunOfASceneForcedAtItsModeStillChecksNothing) {
  const Scene scene = load_scene(write_temp("friction_10s.toml", joints_friction_scene("10 s")));
  const FftCheckResult r = fft_check(scene, load_vehicle(scene.vehicle_file));
  ASSERT_EQ(r.checks.size(), 2u);
  const FftCheck& bounce = r.checks[1];
  ASSERT_EQ(bounce.mode_name, "body bounce");
  ASSERT_TRUE(bounce.peak_hz.has_value());
  // Resolved, and within 5 %: the old rule's pass. Now not applicable: the forcing's line.
  EXPECT_LE(bounce.resolution_hz, FftCheck::kNonlinearTolerance * bounce.modal_hz);
  EXPECT_LE(std::abs(bounce.rel_error), FftCheck::kNonlinearTolerance);
  EXPECT_EQ(bounce.outcome, FftCheck::Outcome::not_applicable);
  EXPECT_EQ(r.checked, 0);
  EXPECT_FALSE(r.passed);
}

// A free friction decay that sticks after two swings (Speer's drop test, springs digest
// Example 7): its spectrum cannot check the mode (the motion lasts one period), its half periods
// can: π/k₁ = 0.3705 s and π/k₂ = 0.3945 s against the linear 0.3819 s, 3.0 % and 3.3 % off,
// within 5 % (the tolerance: 1/√(1 − φ) − 1 + 1 % = 4.3 % at the test's φ = 0.0625, at least
// FftCheck::kNonlinearTolerance).
TEST(FftCheck, DropTestIsCheckedByItsHalfPeriods) {
  const Scene scene = load_scene(data("scenes/leaf_spring_drop_test.toml"));
  const FftCheckResult r = fft_check(scene, load_vehicle(scene.vehicle_file));
  ASSERT_EQ(r.checks.size(), 1u);
  EXPECT_EQ(r.checks[0].outcome, FftCheck::Outcome::not_applicable);
  ASSERT_TRUE(r.half_period_check.has_value());
  EXPECT_EQ(r.half_period_check->count, 2);
  // 0.3945/0.3819 − 1 = 3.3 %, to the printed digits of the book's half periods (digest).
  EXPECT_NEAR(r.half_period_check->worst_rel_error, 0.3945 / 0.3819 - 1.0, 5e-4);
  EXPECT_TRUE(r.half_period_check->passed);
  EXPECT_EQ(r.checked, 1);
  EXPECT_TRUE(r.passed);
  const std::string verdict = fft_check_verdict(r);
  EXPECT_EQ(verdict.rfind("passed: ", 0), 0u) << verdict;  // the half periods are a check made
}

// At the book's largest relative friction, φ = 0.15 (springs digest §2.3: 0.02–0.15), the half
// periods are π/k₁, π/k₂ with k² = (1 ± φ)k₀²: the longer 1/√0.85 − 1 = 8.5 % above the linear
// one. A fixed 5 % would fail this correct run (review of 2026-11-27); the tolerance follows φ:
// 8.5 % + 1 % = 9.5 %.
TEST(FftCheck, DropTestAtLargeFrictionIsHeldToItsOwnOffset) {
  std::ifstream vehicle_in(data("vehicles/leaf_spring_drop_test.toml"));
  std::stringstream vehicle_text;
  vehicle_text << vehicle_in.rdbuf();
  std::string v = vehicle_text.str();
  const std::string phi = "relative_friction = 0.0625";
  ASSERT_NE(v.find(phi), std::string::npos);
  v.replace(v.find(phi), phi.size(), "relative_friction = 0.15");
  const std::string vehicle_file = write_temp("drop_phi_015_vehicle.toml", v);
  std::ifstream scene_in(data("scenes/leaf_spring_drop_test.toml"));
  std::stringstream scene_text;
  scene_text << scene_in.rdbuf();
  std::string sc = scene_text.str();
  const std::string ref = "\"../vehicles/leaf_spring_drop_test.toml\"";
  ASSERT_NE(sc.find(ref), std::string::npos);
  sc.replace(sc.find(ref), ref.size(), "\"" + vehicle_file + "\"");
  const Scene scene = load_scene(write_temp("drop_phi_015.toml", sc));
  const FftCheckResult r = fft_check(scene, load_vehicle(scene.vehicle_file));
  ASSERT_TRUE(r.half_period_check.has_value());
  const auto& h = *r.half_period_check;
  EXPECT_NEAR(h.tolerance, 1.0 / std::sqrt(0.85) - 1.0 + 0.01, 1e-12);  // the rule, to round-off
  EXPECT_GE(h.count, 1);
  // The half periods are the book's: the longer one beyond 5 %, and within its own offset plus
  // 1 % (the turning points fall between 1 ms steps of a 0.4 s half period: 0.25 %).
  EXPECT_GT(h.worst_rel_error, FftCheck::kNonlinearTolerance);
  EXPECT_LE(h.worst_rel_error, 1.0 / std::sqrt(0.85) - 1.0 + 0.005);
  EXPECT_TRUE(h.passed);
  EXPECT_TRUE(r.passed) << fft_check_verdict(r);
}

// A linear release holds its line within the line's width: the verdict passes.
TEST(FftCheck, LinearReleasePassesItsVerdict) {
  const Scene scene = load_scene(data("scenes/resort_car_free_response.toml"));
  const FftCheckResult r = fft_check(scene, load_vehicle(scene.vehicle_file));
  EXPECT_FALSE(r.nonlinear);
  EXPECT_TRUE(r.passed);
  EXPECT_EQ(r.checked, 6);
  for (const FftCheck& c : r.checks) EXPECT_EQ(c.outcome, FftCheck::Outcome::passed) << c.mode_name;
}


// Linear forced damped scenes (fft-linear, 2026-11-27): the damped two-axle wagon of
// tests/cli/scenes over 10 m opposite joints.
std::string test_scene(const std::string& file) {
  return std::string(RAILMODAL_DATA_DIR) + "/../tests/cli/scenes/" + file;
}

const FftCheck& check_named(const FftCheckResult& r, const std::string& name) {
  for (const FftCheck& c : r.checks)
    if (c.mode_name == name) return c;
  ADD_FAILURE() << "no check of '" << name << "'";
  return r.checks.front();
}

// The Hann window's gain on a tone decaying from t = 0, the closed form that decides
// "decayed", against the midpoint quadrature of ∫₀ᵀ w e^{−σt} dt / ∫₀ᵀ w dt. 200 000 points:
// the rule's error (T/n)²/24·max|f''|/∫w is below 1e-9 of the gain for these σ; 1e-7 holds it.
TEST(FreeResponse, HannDecayGainMatchesQuadrature) {
  for (double T : {3.0, 20.0})
    for (double sigma : {0.0, 0.05, 1.0, 10.0}) {
      const int n = 200000;
      double num = 0.0, den = 0.0;
      for (int i = 0; i < n; ++i) {
        const double t = (i + 0.5) * T / n;
        const double w = 0.5 * (1.0 - std::cos(2.0 * kPi * t / T));
        num += w * std::exp(-sigma * t);
        den += w;
      }
      EXPECT_NEAR(simulate::hann_decay_gain(sigma, T), num / den, 1e-7 * num / den) << "σ = " << sigma << ", T = " << T;
    }
}

// free_modes takes the forced steady state out of the start with the linear simulation's own
// phase (F = Re(Q e^{iωt}), t = 0 at the start): started on the steady state, x₀ = Σ Re X_n and
// v₀ = Σ Re(iω_n X_n) (computed here from harmonic_response), the wagon has no free response —
// its simulated record stays on x_ss(t), and free_modes finds no free amplitude. Started from
// rest it has one: what cancels the steady state's start.
TEST(FreeResponse, StartOnTheSteadyStateHasNoFreeResponse) {
  Scene scene = load_scene(test_scene("damped_wagon_joints_decayed.toml"));
  scene.simulation->duration = 4.0;
  const Vehicle vehicle = load_vehicle(scene.vehicle_file);
  const LinearSystem system = scene_system(scene, vehicle);
  const DampedModalResult damped = solve_damped_modes(system);
  std::vector<const ExcitationSource*> sources;
  for (const auto& s : scene.sources) sources.push_back(s.get());
  const double speed = scene.simulation->speed;
  std::vector<std::pair<Eigen::VectorXcd, double>> lines;  // X_n, ω_n
  for (const ExcitationSource* source : sources)
    for (int k = 1; k <= source->harmonic_count(); ++k) {
      const HarmonicLoad load = source->load(system, speed, k);
      const HarmonicResponse x =
          harmonic_response(system, damped.undamped, generalized_load(system, load), load.frequency_hz);
      lines.emplace_back(x.displacement, 2.0 * kPi * load.frequency_hz);
    }
  const auto steady = [&lines, &system](double t, bool velocity) {
    Eigen::VectorXd out = Eigen::VectorXd::Zero(system.size());
    for (const auto& [X, omega] : lines) {
      const std::complex<double> turn = std::polar(1.0, omega * t) * (velocity ? std::complex<double>(0.0, omega) : 1.0);
      out += (X * turn).real();
    }
    return out;
  };
  const std::vector<simulate::FreeMode> at_rest = simulate::free_modes(system, damped.undamped, &damped, sources, speed, {});
  const Eigen::VectorXd x0 = steady(0.0, false), v0 = steady(0.0, true);
  for (int d = 0; d < system.size(); ++d)  // a massless DOF follows the others statically
    if (system.mass(d, d) > 0.0) scene.simulation->initial.push_back({system.dofs[d].label, x0(d), v0(d)});
  const std::vector<simulate::FreeMode> on_steady =
      simulate::free_modes(system, damped.undamped, &damped, sources, speed, scene.simulation->initial);
  ASSERT_EQ(on_steady.size(), at_rest.size());
  for (size_t r = 0; r < at_rest.size(); ++r) {
    if (damped.undamped.modes[r].kind != ModeKind::oscillatory) continue;
    EXPECT_GT(at_rest[r].initial_amplitude, 0.0) << r;
    // Round-off of sums of amplitudes ~1e-16 relative.
    EXPECT_LT(on_steady[r].initial_amplitude, 1e-12 * at_rest[r].initial_amplitude) << r;
    EXPECT_GT(at_rest[r].decay_rate, 0.0) << r;
  }
  // The simulation agrees: started there it stays on x_ss(t). Its first-order hold on the load
  // is off a sinusoid by up to (ωΔt)²/8 between samples (the joints' 5th harmonic, 6.9 Hz at a
  // 5 ms step: 5e-3 of that harmonic, a few per mille of the whole); a wrong phase convention
  // would leave a free response of the order of the motion itself.
  const TimeHistory h = simulate_scene(scene, vehicle);
  double deviation = 0.0, size = 0.0;
  for (Eigen::Index i = 0; i < h.time.size(); ++i) {
    const Eigen::VectorXd xs = steady(h.time(i), false);
    deviation = std::max(deviation, (h.displacement.row(i).transpose() - xs).cwiseAbs().maxCoeff());
    size = std::max(size, xs.cwiseAbs().maxCoeff());
  }
  EXPECT_LT(deviation, 1e-2 * size) << deviation << " of " << size;
}

// A linear damped scene forced on a mode's frequency: 75.03 km/h puts the joints' line
// V/λ = 2.084 Hz on the bounce (2.084 Hz undamped, 2.074 Hz damped). The free response dies
// away after the start, and the bounce's spectrum is the forcing's line: it must not pass on it.
// Before (the forcing-line rules for nonlinear scenes only) the bounce "passed", within the
// line's width.
TEST(FftCheck, LinearDampedSceneForcedAtItsModeDoesNotPassOnTheForcingLine) {
  const Scene scene = load_scene(test_scene("damped_wagon_joints_at_bounce.toml"));
  const FftCheckResult r = fft_check(scene, load_vehicle(scene.vehicle_file));
  EXPECT_FALSE(r.nonlinear);
  const FftCheck& bounce = check_named(r, "body bounce");
  EXPECT_GT(bounce.damping_ratio, 0.05);
  EXPECT_LT(bounce.damped_hz, bounce.modal_hz);
  ASSERT_TRUE(bounce.peak_hz);
  const double line = 75.03 / 3.6 / 10.0;
  // The premise: the peak is the joints' line, within the resolution of the mode.
  EXPECT_LE(std::abs(*bounce.peak_hz - line), bounce.resolution_hz);
  EXPECT_LE(std::abs(*bounce.peak_hz - bounce.damped_hz), bounce.resolution_hz);
  EXPECT_NE(bounce.outcome, FftCheck::Outcome::passed);
  EXPECT_FALSE(bounce.checked());
  EXPECT_EQ(bounce.outcome, FftCheck::Outcome::not_applicable) << bounce.why_decayed;
  EXPECT_EQ(bounce.why_not_applicable.rfind("the forcing's own line (rail_joints, V/λ = 2.084 Hz)", 0), 0u)
      << bounce.why_not_applicable;
  EXPECT_FALSE(r.passed);
  EXPECT_EQ(r.failed, 0);
}

// A linear damped scene whose free response has died away: at 60 km/h the joints' lines
// (1.667, 3.333 Hz, …) lie off both modes, and after 20 s (bounce e^{−1.33 t}, pitch e^{−0.62 t})
// neither mode's line reaches the 3 % of the largest above which peaks are sought. Before, both
// FAILED for want of a line; now each is "decayed", says why and what would check it, and the
// verdict is NOT CHECKED, neither a pass nor a failure.
TEST(FftCheck, LinearDampedModeDecayedIsNotCheckedAndSaysWhy) {
  const Scene scene = load_scene(test_scene("damped_wagon_joints_decayed.toml"));
  const FftCheckResult r = fft_check(scene, load_vehicle(scene.vehicle_file));
  ASSERT_EQ(r.checks.size(), 2u);
  for (const FftCheck& c : r.checks) {
    EXPECT_TRUE(c.excited) << c.mode_name;
    EXPECT_EQ(c.outcome, FftCheck::Outcome::decayed) << c.mode_name;
    EXPECT_EQ(c.why_decayed.rfind("its free response (ζ = ", 0), 0u) << c.why_decayed;
    EXPECT_NE(c.why_decayed.find("a free release"), std::string::npos) << c.why_decayed;
  }
  EXPECT_EQ(r.checked, 0);
  EXPECT_EQ(r.failed, 0);
  EXPECT_FALSE(r.passed);
  EXPECT_EQ(fft_check_verdict(r).rfind("NOT CHECKED: no mode's line could be checked (2 decayed, body pitch: ", 0), 0u)
      << fft_check_verdict(r);
}

}  // namespace
}  // namespace railmodal::test
