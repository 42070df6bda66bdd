// The bundled studies (data/studies/) against the book's comparisons and against single
// runs of the same vehicles through the library.
//
// Resort car (bogie-wagons-natural digest, Ex. 2, pp. 156–160) against the Fette car (Ex. 3,
// pp. 162–165), over 10 m rails: body bounce T2 = 0.945 s against 0.84 s (consistent
// 0.9447 / 0.8382), critical speeds 38.1 against 42.9 km/h, bogie bounce 157.6 against
// 306.0 km/h (digest "consistent" columns), static deflections Σf ≈ 233 mm (0.3·233 mm
// amplitude example) against 178.0 mm (Σf = 17.80 cm, Ex. 3 recomputation table).
// Two-axle freight wagon (two-axle digest, Ex. 3, pp. 100–104): T = 2π√(f/g) = 0.4798 s
// for f = 57.2 mm and V = L/T = 75.0, 93.8, 112.6 km/h over 10, 12.5, 15 m rails.
#include <cmath>
#include <fstream>
#include <sstream>

#include "railmodal/railmodal.hpp"
#include "test_support.hpp"

namespace railmodal::test {
namespace {

std::string studies(const std::string& name) { return std::string(RAILMODAL_DATA_DIR) + "/studies/" + name; }

const VariantResult& named_result(const std::vector<VariantResult>& results, const std::string& name) {
  for (const auto& r : results)
    if (r.name == name) return r;
  ADD_FAILURE() << "no variant '" << name << "'";
  static VariantResult none;
  return none;
}

double kmh(const VariantResult& r, const std::string& mode) { return *metric_value(r, "critical_speed:" + mode) * 3.6; }

std::vector<VariantResult> evaluate(const Study& s) {
  EvaluationOptions options;
  options.threads = 2;
  return evaluate_study(s, options);
}

TEST(Studies, ResortCarAgainstFetteCarComesOutAsTheBookCompares) {
  const Study s = load_study(studies("resort_against_fette.toml"));
  const auto results = evaluate(s);
  const VariantResult& resort = named_result(results, "base");
  const VariantResult& fette = named_result(results, "Fette car");
  ASSERT_TRUE(resort.ok() && fette.ok());
  // The digest's consistent values carry 4 digits: ±5e-4 s and ±0.05 km/h.
  EXPECT_NEAR(*metric_value(resort, "bounce_period"), 0.9447, 5e-4);
  EXPECT_NEAR(*metric_value(fette, "bounce_period"), 0.8382, 5e-4);
  EXPECT_NEAR(kmh(resort, "body bounce"), 38.1, 0.05);
  EXPECT_NEAR(kmh(fette, "body bounce"), 42.9, 0.05);
  EXPECT_NEAR(kmh(resort, "bogies bounce, in phase"), 157.6, 0.05);
  EXPECT_NEAR(kmh(fette, "bogies bounce, in phase"), 306.0, 0.05);
  // Static deflection: Fette f2 + f3 = 17.80 cm (digest); resort f1 + f2 + f3 from the
  // book's rounded stiffnesses 700, 1000 (×2) and 650 kgf/cm under its loads, ≈ 233 mm
  // (the digest's 0.3·233 mm amplitude): ±2 mm for the book's rounding of c1, c2, c3.
  EXPECT_NEAR(*metric_value(fette, "static_deflection") * 1000.0, 178.0, 0.1);
  EXPECT_NEAR(*metric_value(resort, "static_deflection") * 1000.0, 233.0, 2.0);
  // The ranking (longest bounce period, body bounce above 30 km/h) puts the softest design
  // first and the Fette car last, as the book argues softness.
  const Comparison c = rank_variants(s, results);
  EXPECT_EQ(c.variants.front().result.name, "resort car, softer cradle springs");
  EXPECT_EQ(c.variants.back().result.name, "Fette car");
  for (size_t i = 1; i < c.variants.size(); ++i)
    EXPECT_GT(*c.variants[i - 1].criteria[0], *c.variants[i].criteria[0]);
  // Lehner's passenger limits (coil 30 mm, elliptic 0.2 f_st): leaf friction φ1 = 0.0843 and
  // Galakhov friction φ3 = 0.035 stop every resonance of the resort car, so it keeps them;
  // the Fette car's bogies stand on helical springs, and the cradle friction φ3 = 0.0295 alone
  // does not stop their antiphase bounce at 306 km/h ("a bogie with no friction springs keeps
  // oscillating", digest §2.2): unbounded.
  for (const auto& c : resort.critical_speeds) EXPECT_TRUE(c.friction_stops) << c.mode_name;
  EXPECT_LT(*metric_value(resort, "dynamic_deflection_ratio"), 1.0);
  bool antiphase_grows = false;
  for (const auto& c : fette.critical_speeds)
    antiphase_grows |= c.mode_name == "bogies bounce, antiphase" && !c.friction_stops && std::abs(c.speed * 3.6 - 306.3) < 0.1;
  EXPECT_TRUE(antiphase_grows);
  // The in-phase bogie bounce (306.0 km/h) lies 0.08 % below it: the two grow together
  // (the friction criterion judges the cluster, issue 17 item 6), so the unbounded deflection is
  // met at one of the two speeds.
  ASSERT_FALSE(fette.deflections.empty());
  for (const auto& d : fette.deflections) {
    EXPECT_TRUE(d.unbounded) << d.element;
    EXPECT_NEAR(d.speed * 3.6, 306.15, 0.2) << d.element;  // 306.0 or 306.3, to the 0.1 of the rows
  }
}

// The extreme points of the two-axle sweep equal single library runs of vehicles and scenes
// written out by hand: the same code path, so to rounding (1e-12 relative is far above it).
TEST(Studies, TwoAxleSweepExtremesAgreeWithSingleRuns) {
  const Study s = load_study(studies("two_axle_rail_length_and_springs.toml"));
  const auto results = evaluate(s);
  std::ifstream vehicle_in(std::string(RAILMODAL_DATA_DIR) + "/vehicles/two_axle_freight_wagon.toml");
  std::stringstream vehicle_text;
  vehicle_text << vehicle_in.rdbuf();
  std::ifstream scene_in(std::string(RAILMODAL_DATA_DIR) + "/scenes/two_axle_freight_wagon_10m_rails.toml");
  std::stringstream scene_text;
  scene_text << scene_in.rdbuf();
  struct Point {
    std::string variant, deflection, rail;
  };
  for (const Point& p : {Point{"grid: f = 40 mm, L = 10 m", "40 mm", "10 m"}, Point{"grid: f = 80 mm, L = 15 m", "80 mm", "15 m"}}) {
    std::string v = vehicle_text.str();
    const std::string from = "static_deflection = \"57.2 mm\"";
    v.replace(v.find(from), from.size(), "static_deflection = \"" + p.deflection + "\"");
    std::string sc = scene_text.str();
    const std::string length = "rail_length = \"10 m\"";
    sc.replace(sc.find(length), length.size(), "rail_length = \"" + p.rail + "\"");
    const std::string vehicle_key = "vehicle = \"../vehicles/two_axle_freight_wagon.toml\"";
    sc.replace(sc.find(vehicle_key), vehicle_key.size(), "vehicle = \"wagon.toml\"");
    const Vehicle vehicle = load_vehicle(write_temp("wagon.toml", v));
    const Scene scene = load_scene(write_temp("scene.toml", sc));

    const VariantResult& r = named_result(results, p.variant);
    ASSERT_TRUE(r.ok()) << r.failure;
    const ModalResult modes = solve_modes(assemble(vehicle, DofSet::vertical));
    ASSERT_EQ(r.modes.size(), modes.modes.size());
    for (size_t i = 0; i < modes.modes.size(); ++i) {
      EXPECT_EQ(r.modes[i].name, modes.modes[i].name);
      EXPECT_NEAR(r.modes[i].period_s, modes.modes[i].period_s, 1e-12 * modes.modes[i].period_s);
    }
    const CriticalSpeedStudy single = study_critical_speeds(scene, vehicle);
    ASSERT_EQ(r.critical_speeds.size(), single.critical_speeds.size());
    for (size_t i = 0; i < single.critical_speeds.size(); ++i) {
      EXPECT_EQ(r.critical_speeds[i].mode_name, single.critical_speeds[i].mode_name);
      EXPECT_NEAR(r.critical_speeds[i].speed, single.critical_speeds[i].speed, 1e-12 * single.critical_speeds[i].speed);
    }
  }
}

TEST(Studies, TwoAxleBounceFollowsTheBookWithRailLengthAndDeflection) {
  const Study s = load_study(studies("two_axle_rail_length_and_springs.toml"));
  const auto results = evaluate(s);
  const VariantResult& base = named_result(results, "base");
  // Digest: T = 0.4798 s, V = 75.0 km/h (4 and 3 digits).
  EXPECT_NEAR(*metric_value(base, "bounce_period"), 0.4798, 5e-5);
  EXPECT_NEAR(kmh(base, "body bounce"), 75.0, 0.05);
  for (const char* f : {"40 mm", "50 mm", "60 mm", "70 mm", "80 mm"}) {
    const std::string prefix = std::string("grid: f = ") + f + ", L = ";
    const VariantResult& l10 = named_result(results, prefix + "10 m");
    const VariantResult& l125 = named_result(results, prefix + "12.5 m");
    const VariantResult& l15 = named_result(results, prefix + "15 m");
    // T = 2π√(f/g) of a body on its springs (eq. (137)); f is the static deflection. The
    // pitch coupling vanishes for a centred CG, so this is exact to rounding.
    const double deflection = std::atof(f) / 1000.0;
    EXPECT_NEAR(*metric_value(l10, "bounce_period"), 2 * kPi * std::sqrt(deflection / 9.81), 1e-12);
    // V = L/T: the critical speeds scale with the rail length (same vehicle, same period).
    EXPECT_NEAR(kmh(l125, "body bounce") / kmh(l10, "body bounce"), 1.25, 1e-12);
    EXPECT_NEAR(kmh(l15, "body bounce") / kmh(l10, "body bounce"), 1.5, 1e-12);
  }
  // Softer springs: longer period, lower critical speed.
  EXPECT_GT(*metric_value(named_result(results, "grid: f = 80 mm, L = 10 m"), "bounce_period"),
            *metric_value(named_result(results, "grid: f = 40 mm, L = 10 m"), "bounce_period"));
  EXPECT_LT(kmh(named_result(results, "grid: f = 80 mm, L = 10 m"), "body bounce"),
            kmh(named_result(results, "grid: f = 40 mm, L = 10 m"), "body bounce"));
}

// Example 3's wagon as the joints wear (data/studies/two_axle_joint_dip_deflection.toml):
// Lehner's 0.4 f_st for freight leaf springs is 22.88 mm (f = 57.2 mm, springs digest §5).
// Friction φf = 0.075 × 57.2 = 4.29 mm stops a mode's resonance while 2a < 8φf/(π|c|), c the
// wheelbase filter, |cos(π·2a1/L)| for bounce and |sin(π·2a1/L)| for pitch (two-axle digest,
// Example 2's consistent criterion; "resonance would need 2a > ≈ 30 mm" for bounce). The
// check follows: kept below both thresholds, unbounded past the pitch one (11.7 mm).
TEST(Studies, TwoAxleJointWearKeepsThePermissibleDeflectionUntilFrictionNoLongerStopsResonance) {
  const Study s = load_study(studies("two_axle_joint_dip_deflection.toml"));
  ASSERT_EQ(s.deflection_rule.book, DeflectionRule::Book::lehner);
  const auto results = evaluate(s);
  const double phi_f = 0.075 * 0.0572, filter = kPi * 3.81 / 10.0;
  const double bounce_threshold = 8.0 * phi_f / (kPi * std::abs(std::cos(filter)));
  const double pitch_threshold = 8.0 * phi_f / (kPi * std::abs(std::sin(filter)));
  EXPECT_NEAR(bounce_threshold, 0.0299, 5e-5);  // the digest's ≈ 30 mm
  for (const VariantResult& r : results) {
    ASSERT_TRUE(r.ok()) << r.name;
    const double dip = r.parameters.empty() ? 0.005 : std::atof(r.parameters.front().second.c_str()) / 1000.0;
    ASSERT_EQ(r.deflections.size(), 4u);
    for (const auto& d : r.deflections) EXPECT_NEAR(d.permissible, 0.4 * 0.0572, 1e-12);
    for (const auto& c : r.critical_speeds) {
      const double threshold = c.mode_name == "body bounce" ? bounce_threshold : pitch_threshold;
      // Only dips at least 0.2 % from a threshold are compared (30 mm is 0.3 % above bounce's).
      if (std::abs(dip - threshold) > 2e-3 * threshold) {
        EXPECT_EQ(c.friction_stops, dip < threshold) << r.name << ", " << c.mode_name;
      }
    }
    const bool stopped = dip < pitch_threshold;
    for (const auto& d : r.deflections) EXPECT_EQ(d.unbounded, !stopped) << r.name;
    const double ratio = *metric_value(r, "dynamic_deflection_ratio");
    if (stopped) {
      EXPECT_LT(ratio, 1.0) << r.name;
    } else {
      EXPECT_TRUE(std::isinf(ratio)) << r.name;
    }
  }
}

}  // namespace
}  // namespace railmodal::test
