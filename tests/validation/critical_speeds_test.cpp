// Critical speeds from the digests. The vehicle cases run the general path (bundled scene →
// vehicle file → assembly → modes → excitation source → critical-speed finder); the digests'
// formula-level examples (hunting wavelengths, Meineke, E5 and E7 given as k ranges, VB-1,
// VB-3) go through the source types that the general path uses.
#include <algorithm>
#include <cmath>
#include <complex>
#include <filesystem>
#include <sstream>

#include "railmodal/critical_speed.hpp"
#include "railmodal/critical_speed_report.hpp"
#include "response/critical_speed_study.hpp"
#include "response/friction_damping.hpp"
#include "test_support.hpp"

namespace railmodal::test {
namespace {

std::string scene_file(const std::string& name) { return std::string(RAILMODAL_DATA_DIR) + "/scenes/" + name; }

CriticalSpeedStudy study(const std::string& scene_name) {
  const Scene scene = load_scene(scene_file(scene_name));
  return study_critical_speeds(scene, load_vehicle(scene.vehicle_file));
}

// The row of this source (0-based), harmonic and mode name (fails the test if absent).
const CriticalSpeed& row(const CriticalSpeedStudy& s, int source, int harmonic, const std::string& mode) {
  for (const auto& r : s.critical_speeds)
    if (r.source == source && r.harmonic == harmonic && r.mode_name == mode) return r;
  ADD_FAILURE() << "no critical speed for source " << source << ", harmonic " << harmonic << ", mode " << mode;
  static CriticalSpeed none;
  return none;
}

double kmh(const CriticalSpeed& r) { return r.speed * 3.6; }

// Two-axle digest, Example 3 (derived table): bounce resonance at V = L/T on 10, 12.5 and
// 15 m rails, 75.0 / 93.8 / 112.6 km/h (T = 0.4798 s). The digest prints one decimal: ±0.05.
// The growth per half period is the book's undamped secular growth (168d), (274), what Den
// Hartog's friction criterion weighs; a damped coach's resonance does not grow, so the reports
// head the figure "if undamped" (audit 2026-11-27b read 3.83 mm of growth for a finite amplitude).
TEST(CriticalSpeeds, GrowthOfADampedResonanceIsHeadedIfUndamped) {
  const CriticalSpeedStudy coach = study("manchester_coach_hunting.toml");
  ASSERT_TRUE(std::any_of(coach.critical_speeds.begin(), coach.critical_speeds.end(), [](const CriticalSpeed& c) {
    return !c.unbounded && c.growth_per_half_period > 0.0;  // damped, finite, and a growth given
  }));
  for (OutputFormat f : {OutputFormat::markdown, OutputFormat::html}) {
    std::ostringstream out;
    write_critical_speed_report(out, coach, f);
    EXPECT_NE(out.str().find("growth per half period if undamped"), std::string::npos) << to_string(f);
    EXPECT_EQ(out.str().find("undamped growth"), std::string::npos) << to_string(f);
  }
}

TEST(CriticalSpeeds, TwoAxleFreightWagonBounceOnThreeRailLengths) {
  const auto s = study("two_axle_freight_wagon_joints.toml");
  EXPECT_NEAR(kmh(row(s, 0, 1, "body bounce")), 75.0, 0.05);
  EXPECT_NEAR(kmh(row(s, 1, 1, "body bounce")), 93.8, 0.05);
  EXPECT_NEAR(kmh(row(s, 2, 1, "body bounce")), 112.6, 0.05);
}

// Two-axle digest §2.6 and Example 3: at resonance each half period adds π a |cos(π·2a1/L)|/2
// to the bounce (the book's secular term (a k1/4)[sin k1t + sin k1(t + 2a1/V)]·t), and the
// leaf friction takes 2φf = 2·0.075·57.2 mm off it. With 2a = 5 mm on 10 m rails
// (|cos(π·0.381)| = 0.365): growth 1.43 mm < 8.58 mm, friction stops the resonance, and the
// dip would have to reach ≈ 30 mm (digest: "Resonance would need 2a > ≈ 30 mm"). The
// growth and decrement are checked to 3 figures (the digest's); the threshold to its "≈ 30".
TEST(CriticalSpeeds, TwoAxleWagonFrictionStopsTheResonanceExample3) {
  const auto s = study("two_axle_freight_wagon_joints.toml");
  const CriticalSpeed& r = row(s, 0, 1, "body bounce");
  EXPECT_TRUE(r.unbounded);  // no viscous damping: the linear amplitude grows without limit
  EXPECT_NEAR(r.growth_per_half_period * 1e3, 1.434, 0.002);
  EXPECT_NEAR(r.friction_decrement_per_half_period * 1e3, 8.58, 0.005);
  EXPECT_TRUE(r.friction_stops);
  EXPECT_NEAR(r.friction_threshold_scale * 5.0, 29.9, 0.1);  // 2a needed, mm
}

// Two-axle digest, Example 2 (consistent form): with the worst phasing, a wheelbase equal to
// the rail length (|cos| = 1), resonance needs 2a > 8φf/π = 2.546·φf; for φf = 5 mm that is
// 12.7 mm (the book's 15 mm carries a static term that does not belong in the criterion).
TEST(CriticalSpeeds, ResonanceThresholdExample2) {
  const auto s = study("two_axle_example2_threshold.toml");  // and data/vehicles/two_axle_wagon_example2.toml
  const CriticalSpeed& r = row(s, 0, 1, "body bounce");
  // φf = 0.1 · 50 mm = 5 mm. Threshold 2a = 5 mm × scale; 8·5/π = 12.732 mm.
  EXPECT_NEAR(r.friction_threshold_scale * 5.0, 8.0 * 5.0 / kPi, 1e-9 * 12.7);
  EXPECT_NEAR(r.friction_threshold_scale * 5.0, 12.7, 0.05);  // the digest's consistent value
}

// Springs digest, Example 1: Pullman coil spring, T = 0.51 s, 15 m rails: 105.9 / 52.9 /
// 35.3 km/h for harmonics 1, 2, 3 (recomputed 105.88, 52.94, 35.29). The file's static
// deflection 64.63 mm carries 4 figures of T, so ±0.02 %.
TEST(CriticalSpeeds, PullmanCoilSpringHarmonicsExample1) {
  const auto s = study("pullman_coil_spring_15m_rails.toml");
  EXPECT_NEAR(kmh(row(s, 0, 1, "load bounce")) / 105.88, 1.0, 2e-4);
  EXPECT_NEAR(kmh(row(s, 0, 2, "load bounce")) / 52.94, 1.0, 2e-4);
  EXPECT_NEAR(kmh(row(s, 0, 3, "load bounce")) / 35.29, 1.0, 2e-4);
}

// Bogie-wagons-natural digest, Examples 2 and 3, on 10 m rails: resort car 38.1 / 157.6 km/h,
// Fette car 42.9 / 306.0 km/h (consistent values; the book prints 38.2 / 156.5 and 43 / 308).
// Tolerance: the digest's last printed digit.
TEST(CriticalSpeeds, ResortAndFetteCarsOn10mRails) {
  const auto resort = study("resort_car_10m_rails.toml");
  EXPECT_NEAR(kmh(row(resort, 0, 1, "body bounce")), 38.1, 0.05);
  EXPECT_NEAR(kmh(row(resort, 0, 1, "bogies bounce, in phase")), 157.6, 0.05);
  const auto fette = study("fette_car_10m_rails.toml");
  EXPECT_NEAR(kmh(row(fette, 0, 1, "body bounce")), 42.9, 0.05);
  EXPECT_NEAR(kmh(row(fette, 0, 1, "bogies bounce, in phase")), 306.0, 0.1);
}

// The book's design point for bogie cars, r² + d0² = l3² (bogie-wagons-natural digest (221),
// p. 178, and concl. 25 of the forced digest): with d0 = 0 and the body's pitch radius equal to
// half the bogie spacing, body pitch and body bounce have one frequency. The resort car (Ex. 2)
// put there: d0 = 0, r = l3 = 7 m, scaled by `radius_scale` to step off the point.
Vehicle resort_car_at_design_point(double radius_scale) {
  Vehicle v = load_vehicle(data_file("resort_car.toml"));
  for (Body& b : v.bodies)
    if (b.name == "body") {
      b.centre_of_gravity.z() = b.reference_point.z();  // d0 = 0
      const double l3 = 7.0;                            // 2l3 = 1400 cm
      b.inertia.y() = b.mass * std::pow(l3 * radius_scale, 2);
    }
  return v;
}

// The body resonance (bounce and pitch, 38.1 km/h on 10 m square joints) as its friction
// criterion sees it, with the growth of body.bounce; the row naming `mode`.
struct BodyCriterion {
  double threshold = 0.0, bounce_growth = 0.0;
  int rows = 0;  // body rows: 1 where the pair is one eigenspace, 2 where it is split
};
BodyCriterion body_criterion(double radius_scale, const std::string& mode) {
  const LinearSystem sys = assemble(resort_car_at_design_point(radius_scale), DofSet::vertical);
  const ModalResult modes = solve_modes(sys);
  RailJoints joints;
  joints.rail_length = 10.0;
  joints.dip_depth = 0.005;
  const auto source = make_source(joints);
  CriticalSpeedOptions options;
  options.min_speed = 20.0 / 3.6;
  options.max_speed = 60.0 / 3.6;
  options.outputs = {{sys.index_of("body.bounce")}};
  BodyCriterion c;
  for (const CriticalSpeed& r : find_critical_speeds(sys, modes, {source.get()}, options)) {
    ++c.rows;
    if (r.mode_name.find(mode) == std::string::npos) continue;
    c.threshold = r.friction_threshold_scale;
    c.bounce_growth = r.outputs.at(0).growth_per_half_period;
  }
  return c;
}

// Issue 17 item 6: the friction criterion is evaluated on the load's projection onto the
// cluster of modes near the resonance, so it does not jump where pitch and bounce coincide.
// Before, the point itself gave 6.38× and a hair away (r ± 0.01 cm) 24× (bounce) and 7.8×
// (pitch). A step of 1e-6 in r moves the frequencies apart by g ≈ 1e-6, which weighs the
// neighbour 1 − g/1 % = 1 − 1e-4: the criterion moves by that order, so 1e-3 holds it with
// a margin of 10 and still fails the jump by a factor of 4.
TEST(CriticalSpeeds, FrictionCriterionContinuousThroughTheDesignPoint) {
  const BodyCriterion at = body_criterion(1.0, "body bounce");
  ASSERT_EQ(at.rows, 1) << "the pair is one eigenspace at the design point";
  ASSERT_GT(at.threshold, 0.0);
  for (double scale : {1.0 - 1e-6, 1.0 + 1e-6})
    for (const char* mode : {"body bounce", "body pitch"}) {
      const BodyCriterion near = body_criterion(scale, mode);
      ASSERT_EQ(near.rows, 2) << "split off the point";
      EXPECT_NEAR(near.threshold, at.threshold, 1e-3 * at.threshold) << mode << " at r × " << scale;
      EXPECT_NEAR(near.bounce_growth, at.bounce_growth, 1e-3 * at.bounce_growth) << mode << " at r × " << scale;
    }
  // Beyond the cluster (r × 1.1: frequencies 9 % apart) each mode is judged alone again.
  const BodyCriterion far = body_criterion(1.1, "body bounce");
  EXPECT_GT(std::abs(far.threshold - at.threshold), 0.1 * at.threshold);
}

// Issue 17 review of item 6: inside the 1 % window pitch joins the bounce resonance with weight
// 1 − g/1 %, but pitch does not move body.bounce (d0 = 0), so body.bounce grows per half period
// as bounce alone does: 0.940 mm at every gap. Before, the growth was π F₀|ψ|/(2λ), which is
// that times Σw|f|²/Σw²|f|² (1.234/1.562/1.935/1.744 mm at gaps 0.27/0.48/0.68/0.88 %). Pitch's
// frequency scales as 1/r, so r × 1/(1 − g) opens a gap g. The bounce mode itself does not
// depend on the pitch inertia and pitch's body.bounce entry is a symmetry zero, so the value
// holds to round-off; 1e-6 leaves room for the eigensolver and is far below the 30 % defect.
TEST(CriticalSpeeds, ClusterNeighbourDoesNotInflateGrowthItDoesNotMove) {
  const BodyCriterion alone = body_criterion(1.1, "body bounce");  // 9 % apart: bounce alone
  ASSERT_GT(alone.bounce_growth, 0.0);
  for (double gap : {0.0025, 0.005, 0.0075, 0.01 - 1e-6, 0.01 + 1e-6}) {
    const BodyCriterion near = body_criterion(1.0 / (1.0 - gap), "body bounce");
    ASSERT_EQ(near.rows, 2) << "split at gap " << gap;
    EXPECT_NEAR(near.bounce_growth, alone.bounce_growth, 1e-6 * alone.bounce_growth) << "gap " << gap;
  }
}

// The critical-speed studies of every bundled scene that has one, with the vehicle's system.
struct BundledStudy {
  std::string name;
  Scene scene;
  CriticalSpeedStudy full;
};

std::vector<BundledStudy> studies_of_bundled_scenes() {
  std::vector<BundledStudy> out;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(RAILMODAL_DATA_DIR) + "/scenes")) {
    // Every bundled scene loads; the critical-speed scenes are those `railmodal critical-speed`
    // takes (its test for a speed range and sources). A study of one of them that throws fails
    // the test instead of dropping out.
    Scene scene = load_scene(entry.path().string());
    if (scene.sources.empty() || scene.max_speed <= 0.0) continue;  // a ride or simulation scene
    CriticalSpeedStudy full = study_critical_speeds(scene, load_vehicle(scene.vehicle_file));
    out.push_back({entry.path().filename().string(), std::move(scene), std::move(full)});
  }
  return out;
}

// Found once for the tests that read them (each is a full study of a bundled scene).
const std::vector<BundledStudy>& bundled_studies() {
  static const std::vector<BundledStudy> studies = studies_of_bundled_scenes();
  return studies;
}

// A design variant's study (ResonanceDetail::without_response) leaves out each resonance's steady
// response and the study's own summary, and nothing else: every other field of every row, the
// curves and the peaks are the full study's, bit for bit (the same operations on the same
// values), on every bundled critical-speed scene.
TEST(CriticalSpeeds, SummaryRowsAreTheFullRowsWithoutTheirResponse) {
  const std::vector<BundledStudy>& studies = bundled_studies();
  ASSERT_GE(studies.size(), 10u);  // the bundled critical-speed scenes (17 when written)
  for (const BundledStudy& b : studies) {
    SCOPED_TRACE(b.name);
    const Vehicle vehicle = load_vehicle(b.scene.vehicle_file);
    CriticalSpeedStudy summary;
    response::study_critical_speeds_into(b.scene, [&] { return assemble(vehicle, b.scene.dofs); }, &summary, {},
                                         {response::ResonanceDetail::without_response, response::CurvePhases::kept});
    ASSERT_EQ(summary.critical_speeds.size(), b.full.critical_speeds.size());
    for (size_t i = 0; i < summary.critical_speeds.size(); ++i) {
      const CriticalSpeed& s = summary.critical_speeds[i];
      const CriticalSpeed& f = b.full.critical_speeds[i];
      EXPECT_EQ(s.speed, f.speed);
      EXPECT_EQ(s.source, f.source);
      EXPECT_EQ(s.source_kind, f.source_kind);
      EXPECT_EQ(s.harmonic, f.harmonic);
      EXPECT_EQ(s.mode, f.mode);
      EXPECT_EQ(s.mode_name, f.mode_name);
      EXPECT_EQ(s.frequency_hz, f.frequency_hz);
      EXPECT_EQ(s.output, f.output);
      EXPECT_EQ(s.growth_per_half_period, f.growth_per_half_period);
      EXPECT_EQ(s.friction_decrement_per_half_period, f.friction_decrement_per_half_period);
      EXPECT_EQ(s.friction_stops, f.friction_stops);
      EXPECT_EQ(s.friction_threshold_scale, f.friction_threshold_scale);
      EXPECT_FALSE(s.unbounded);  // what the summary leaves out stays at its default
      EXPECT_EQ(s.amplitude, 0.0);
      EXPECT_TRUE(s.outputs.empty());
    }
    ASSERT_EQ(summary.curves.size(), b.full.curves.size());
    for (size_t c = 0; c < summary.curves.size(); ++c) {
      EXPECT_EQ(summary.curves[c].speeds, b.full.curves[c].speeds);
      EXPECT_EQ(summary.curves[c].amplitudes, b.full.curves[c].amplitudes);
      EXPECT_EQ(summary.curves[c].unbounded, b.full.curves[c].unbounded);
    }
    ASSERT_EQ(summary.peaks.size(), b.full.peaks.size());
    for (size_t p = 0; p < summary.peaks.size(); ++p) {
      EXPECT_EQ(summary.peaks[p].curve, b.full.peaks[p].curve);
      EXPECT_EQ(summary.peaks[p].peak.speed, b.full.peaks[p].peak.speed);
      EXPECT_EQ(summary.peaks[p].peak.amplitude, b.full.peaks[p].peak.amplitude);
    }
    EXPECT_TRUE(summary.summary.stages.empty());
    EXPECT_FALSE(b.full.summary.stages.empty());
  }
}

// The friction work from the stages found once (each stretch over its row's nonzero entries)
// is the dense product's, bit for bit, for in-phase and out-of-phase combinations of the modes
// of every bundled critical-speed scene's vehicle (the friction ones among them).
TEST(CriticalSpeeds, FrictionWorkFromItsStagesIsTheDenseProducts) {
  int with_friction = 0;
  for (const BundledStudy& b : bundled_studies()) {
    SCOPED_TRACE(b.name);
    const LinearSystem& system = b.full.system;
    const response::FrictionStages stages = response::friction_stages(system);
    if (!stages.stages.empty()) ++with_friction;
    const auto& modes = b.full.modes.modes;
    for (size_t m = 0; m < modes.size(); ++m) {
      const Eigen::VectorXcd shape = modes[m].shape.cast<std::complex<double>>() * std::polar(1.0, 0.3) +
                                     modes[(m + 1) % modes.size()].shape.cast<std::complex<double>>() *
                                         std::complex<double>(0.0, 0.7);
      // The dense products: each stage's stretch as the element's whole row times ψ.
      double dense = 0.0;
      for (const response::FrictionStage& s : stages.stages)
        dense += s.friction *
                 std::abs(s.share *
                          system.element_vertical_map.row(static_cast<Eigen::Index>(s.element))
                              .cast<std::complex<double>>()
                              .dot(shape));
      EXPECT_EQ(response::modal_friction_work(stages, shape), dense);
    }
  }
  EXPECT_GE(with_friction, 3);  // the two-axle wagons' and the resort car's leaf springs
}

// Progress of a study: non-decreasing, ending at exactly 1.
TEST(CriticalSpeeds, StudyReportsProgress) {
  const Scene scene = load_scene(scene_file("resort_car_wheel_defects.toml"));
  std::vector<double> seen;
  study_critical_speeds(scene, load_vehicle(scene.vehicle_file), [&](double f) { seen.push_back(f); });
  ASSERT_FALSE(seen.empty());
  for (size_t i = 1; i < seen.size(); ++i) EXPECT_GE(seen[i], seen[i - 1]);
  EXPECT_DOUBLE_EQ(seen.back(), 1.0);
}

// Issue 18, item 5: every curve is swept on a grid that holds every source's critical speeds,
// so the curves grow as the square of the sources (2000 sources: 1.45 GB of JSON, 4.8 GB of
// memory). 2000 rail-joint sources of distinct lengths (some 4 critical speeds each in range)
// give about 2000 × 2 outputs × 8000 speeds = 3e7 points, over the limit of 1e7: refused
// before the sweep, with the estimate.
TEST(CriticalSpeeds, StudyRefusesCurvesBeyondTheLimit) {
  Scene scene = load_scene(scene_file("resort_car_10m_rails.toml"));
  for (int i = 1; i < 2000; ++i) {
    RailJoints joints;
    joints.rail_length = 10.0 + 1e-3 * i;
    joints.dip_depth = 0.005;
    scene.sources.push_back(make_source(joints));
  }
  try {
    study_critical_speeds(scene, load_vehicle(scene.vehicle_file));
    FAIL() << "curves of 2000 sources were swept";
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    for (const char* part : {"would need about", "GB for 2000 sources x 2 outputs x ", "the limit is 1e+07 points"})
      EXPECT_NE(what.find(part), std::string::npos) << what;
  }
}

// Square joints excite bounce and pitch only; the lateral modes of a full model get no row.
TEST(CriticalSpeeds, SquareJointsDoNotExciteLateralModes) {
  Scene scene = load_scene(scene_file("resort_car_10m_rails.toml"));
  scene.dofs = DofSet::all;
  scene.outputs.clear();
  const auto s = study_critical_speeds(scene, load_vehicle(scene.vehicle_file));
  ASSERT_FALSE(s.critical_speeds.empty());
  for (const auto& r : s.critical_speeds) {
    EXPECT_EQ(r.mode_name.find("sway"), std::string::npos) << r.mode_name;
    EXPECT_EQ(r.mode_name.find("yaw"), std::string::npos) << r.mode_name;
  }
}

// Bogie-wagons-forced digest H1, H2 (E1, E2): Klingel wavelengths 18.10 m (1:20) and 25.59 m
// (1:40) for s = 1.58 m, r = 0.525 m; a rigid bogie of base 2.5 m, 33.87 m (book 33.3).
// Through the hunting source; tolerance 0.5 % of the digest's 4 figures → ±0.01 m.
TEST(CriticalSpeeds, HuntingWavelengthsH1H2) {
  const auto s = study("hunting_wavelengths.toml");
  ASSERT_EQ(s.scene.sources.size(), 3u);
  EXPECT_NEAR(s.scene.sources[0]->wavelength(), 18.10, 0.01);
  EXPECT_NEAR(s.scene.sources[1]->wavelength(), 25.59, 0.01);
  EXPECT_NEAR(s.scene.sources[2]->wavelength(), 33.87, 0.01);
  // Meineke's speed (267) for Table 18's first row, given with the first source (H3: 71.8 km/h).
  const std::string text = s.scene.sources[0]->description();
  const size_t at = text.find("(267): ");
  ASSERT_NE(at, std::string::npos) << text;
  EXPECT_NEAR(std::stod(text.substr(at + 7)), 71.8, 0.05) << text;  // the digest's 3 figures
  // Every critical speed is its source's wavelength times the mode's frequency (k = 1).
  ASSERT_FALSE(s.critical_speeds.empty());
  for (const auto& r : s.critical_speeds)
    EXPECT_NEAR(r.speed, s.scene.sources[r.source]->wavelength() * r.frequency_hz, 1e-12 * r.speed);
}

// Hunting critical speed is V = λ·f for every lateral mode the hunting wave loads.
TEST(CriticalSpeeds, HuntingResonatesWhereTheWavelengthMeetsTheMode) {
  const auto s = study("manchester_coach_hunting.toml");
  ASSERT_FALSE(s.critical_speeds.empty());
  for (const auto& r : s.critical_speeds) {
    const double lambda = s.scene.sources[r.source]->wavelength();
    EXPECT_NEAR(r.speed, lambda * r.frequency_hz, 1e-12 * r.speed);
    EXPECT_FALSE(r.unbounded);  // the coach has dampers: every amplitude is finite
    EXPECT_TRUE(std::isfinite(r.amplitude));
    EXPECT_GT(r.amplitude, 0.0);
  }
}

// Meineke's hunting-limit speed (267), digest H3: Table 18 rows 1–2 give 71.8 and 40.5 km/h
// (book 74, 41); the digest's recomputed values to 3 figures.
TEST(CriticalSpeeds, MeinekeHuntingSpeedH3) {
  EXPECT_NEAR(meineke_hunting_speed_kmh(4.5, 6.8, 0.025, 6, 0.63), 71.8, 0.05);
  EXPECT_NEAR(meineke_hunting_speed_kmh(3.2, 7.6, 0.025, 6, 0.63), 40.5, 0.05);
  EXPECT_NEAR(meineke_hunting_speed_kmh(6.5, 10.5, 0.035, 6, 0.5), 56.6, 0.05);
}

// Bogie-wagons-forced digest E5: eccentricity resonates at V = 3.6·k·R km/h, R = 0.525 m. For
// the book's frequency ranges k1 = 27.2–30 and k2 = 5.65–6.1 1/s: 51.4–56.7 and 10.68–11.53 km/h
// (book 51.5–57.5 and 10.75–11.5). Through the source's V = πD·f/k; ±0.005 km/h.
TEST(CriticalSpeeds, EccentricityCriticalSpeedsE5) {
  WheelEccentricity e;
  e.wheel_diameter = 1.05;
  e.eccentricity = 0.0015;
  const auto source = make_source(e);
  auto v = [&](double k) { return 3.6 * source->speed_for(k / (2 * kPi), 1); };
  EXPECT_NEAR(v(27.2), 51.41, 0.005);
  EXPECT_NEAR(v(30.0), 56.70, 0.005);
  EXPECT_NEAR(v(5.65), 10.68, 0.005);
  EXPECT_NEAR(v(6.1), 11.53, 0.005);
}

// Digest E7: a flat repeating every wheel revolution l = 330 cm resonates at V = k·l/2π:
// k2 = 1.82π → 10.81 km/h, k1 = 9.3π → 55.2 km/h (book 10.8 and 56). ±0.05 km/h.
TEST(CriticalSpeeds, FlatCriticalSpeedsE7) {
  WheelFlat f;
  f.wheel_diameter = 3.30 / kPi;  // circumference 330 cm
  f.depth = 0.001;
  f.length = 3.30;
  const auto source = make_source(f);
  EXPECT_NEAR(3.6 * source->speed_for(1.82 * kPi / (2 * kPi), 1), 10.81, 0.05);
  EXPECT_NEAR(3.6 * source->speed_for(9.3 * kPi / (2 * kPi), 1), 55.2, 0.05);
}

// The resort car's wheel-defect scene: every eccentricity row sits at V = 3.6·ω·R with ω the
// mode's circular frequency and R = 0.525 m (the same relation as E5, on a real vehicle).
TEST(CriticalSpeeds, ResortCarEccentricityRowsFollowTheWheelTurn) {
  const auto s = study("resort_car_wheel_defects.toml");
  int eccentricity_rows = 0;
  for (const auto& r : s.critical_speeds) {
    if (r.source_kind != "wheel_eccentricity") continue;
    ++eccentricity_rows;
    EXPECT_EQ(r.harmonic, 1);
    EXPECT_NEAR(r.speed, 2 * kPi * r.frequency_hz * 0.525, 1e-12 * r.speed);
  }
  EXPECT_EQ(eccentricity_rows, 2);  // body bounce and bogie bounce in phase (all wheelsets alike)
  // E5: double and triple suspension put the bogie resonance at 51.4–56.7 km/h (book 51.5–57.5).
  const CriticalSpeed& bogie = row(s, 0, 1, "bogies bounce, in phase");
  EXPECT_GE(kmh(bogie), 51.4);
  EXPECT_LE(kmh(bogie), 56.7);
}

// A lateral mode alone in the speed range gets no row from square joints: the participation
// test is scale-free, not relative to the other modes in range.
TEST(CriticalSpeeds, ParticipationTestIsScaleFree) {
  Scene scene = load_scene(scene_file("resort_car_10m_rails.toml"));
  scene.dofs = DofSet::all;
  scene.outputs.clear();
  const Vehicle vehicle = load_vehicle(scene.vehicle_file);
  const ModalResult modes = solve_modes(assemble(vehicle, DofSet::all));
  const Mode& sway = mode_named(modes, "body lower sway");
  const double V = scene.sources[0]->speed_for(sway.frequency_hz, 1);
  scene.min_speed = 0.999 * V;
  scene.max_speed = 1.001 * V;
  const auto s = study_critical_speeds(scene, vehicle);
  EXPECT_TRUE(s.critical_speeds.empty());
}

// Unbalance digest VB-1: at 100 km/h a 1.85 m wheel turns at ω = 30.030 1/s, f₁ = 4.7794 Hz.
TEST(CriticalSpeeds, UnbalanceWheelTurnVB1) {
  Unbalance u;
  u.body = "body";
  u.wheel_diameter = 1.85;
  u.rotating.push_back({0.0, 0.8, 0.0, 1.0, 0.0});
  EXPECT_NEAR(make_source(u)->frequency_hz(100.0 / 3.6, 1), 4.7794, 5e-5);
}

// Unbalance digest VB-3 (E13, exact column): Kvasnikov's A₂ and A₄ for μ = 1/4 … 1/6 to 1e-5.
TEST(CriticalSpeeds, ReciprocatingSeriesVB3) {
  EXPECT_NEAR(reciprocating_coefficient(1 / 4.0, 2), 0.25403, 1e-5);
  EXPECT_NEAR(reciprocating_coefficient(1 / 4.5, 2), 0.22503, 1e-5);
  EXPECT_NEAR(reciprocating_coefficient(1 / 5.0, 2), 0.20204, 1e-5);
  EXPECT_NEAR(reciprocating_coefficient(1 / 6.0, 2), 0.16784, 1e-5);
  EXPECT_NEAR(reciprocating_coefficient(1 / 4.0, 4), -0.00410, 1e-5);
  EXPECT_NEAR(reciprocating_coefficient(1 / 6.0, 4), -0.00118, 1e-5);
  EXPECT_EQ(reciprocating_coefficient(1 / 4.0, 3), 0.0);
}

// "Critical speed" is also the onset of hunting (docs/stability.md): a report on a kinematic-
// hunting source says in every format that its speeds are resonances to that input and where the
// stability critical speed is (audit 2026-11-27b); a report on rail joints has no such note.
TEST(CriticalSpeeds, AHuntingSourcesReportSaysItsSpeedsAreResonances) {
  const std::string says = "resonances to a kinematic (forced) input";
  const auto report = [](const CriticalSpeedStudy& st, OutputFormat f) {
    std::ostringstream out;
    write_critical_speed_report(out, st, f);
    return out.str();
  };
  const CriticalSpeedStudy hunting = study("manchester_coach_hunting.toml");
  for (OutputFormat f : {OutputFormat::markdown, OutputFormat::html, OutputFormat::csv, OutputFormat::json}) {
    const std::string text = report(hunting, f);
    EXPECT_NE(text.find(says), std::string::npos) << to_string(f);
    EXPECT_NE(text.find("`railmodal stability`"), std::string::npos) << to_string(f);
  }
  EXPECT_NE(report(hunting, OutputFormat::csv).find("# note: these critical speeds are resonances"), std::string::npos);
  const CriticalSpeedStudy joints = study("resort_car_10m_rails.toml");
  for (OutputFormat f : {OutputFormat::markdown, OutputFormat::html, OutputFormat::csv, OutputFormat::json})
    EXPECT_EQ(report(joints, f).find(says), std::string::npos) << to_string(f);
}

}  // namespace
}  // namespace railmodal::test
