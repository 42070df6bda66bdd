// The balance report's machine-readable outputs (issue 22 review): numbers at full precision,
// keys and columns with units, harmonics with amplitude and phase; and the note on α.
#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <sstream>

#include "test_support.hpp"

namespace railmodal {
namespace {

BalanceStudy su_study(double allowed_alpha) {
  const DrivingGear gear = load_driving_gear(std::string(RAILMODAL_DATA_DIR) + "/locomotives/su.toml");
  BalanceOptions options;
  options.allowed_alpha = allowed_alpha;
  return study_balance(gear, gear.design_speed, options);
}

std::string written(const BalanceStudy& study, OutputFormat format) {
  std::ostringstream out;
  write_balance(out, study, format);
  return out.str();
}

TEST(BalanceReport, JsonCarriesEveryNumberExactlyWithUnitsAndPhases) {
  const BalanceStudy study = su_study(0.3);
  const auto j = nlohmann::json::parse(written(study, OutputFormat::json));
  EXPECT_EQ(j.at("speed_m_s").get<double>(), study.gear.speed);
  // Names as every command spells them (docs/input.md, "Names and units in outputs").
  EXPECT_EQ(j.at("omega_rad_s").get<double>(), study.gear.omega);
  EXPECT_TRUE(j.contains("speed_kmh"));
  for (const char* before : {"speed_m_per_s", "speed_km_per_h", "omega_rad_per_s"}) EXPECT_FALSE(j.contains(before));
  // The state at 90° (the 7th of the 15° grid): exactly the solver's doubles, not rounded.
  const auto& state = j.at("gear").at("states_every_15_deg").at(6);
  EXPECT_EQ(state.at("crank_angle_deg").get<double>(), 90.0);
  EXPECT_EQ(state.at("cylinders").at(0).at("Y_n").get<double>(), study.gear.states[90].cylinders[0].vertical);
  EXPECT_EQ(state.at("nosing_n_m").get<double>(), study.gear.states[90].nosing);
  // Harmonics with amplitude and phase: Σ A_k cos(kφ − ψ_k) at 90° gives Y back. Orders 0 … 6
  // leave the λ⁷ tail (λ = 0.149: 2e-6 of the amplitude) and round-off.
  double y = 0.0;
  for (const auto& h : j.at("gear").at("harmonics").at("cylinders").at(0).at("Y_n")) {
    const double k = h.at("order").get<double>();
    const double a = h.at("amplitude").get<double>(), psi = h.at("phase_deg").get<double>() * M_PI / 180;
    y += a * std::cos(k * M_PI / 2 - psi);
  }
  EXPECT_NEAR(y, study.gear.states[90].cylinders[0].vertical, 1e-5 * std::abs(study.gear.states[90].cylinders[0].vertical));
  // Counterweights per rule, keyed with units.
  const auto& book = j.at("by_rule").at(2);
  EXPECT_EQ(book.at("rule").get<std::string>(), "book");
  EXPECT_EQ(book.at("wheels").at(0).at("total_mass_kg").get<double>(), study.by_rule[2].wheels[0].total_mass);
  EXPECT_TRUE(book.contains("trade_off"));
  // The speed at each α limit in m/s beside km/h (docs/input.md: m/s beside km/h), exactly
  // speed_at_alpha's double; null both when never reached.
  double alpha = 0.0;
  for (const WheelBalance& w : study.by_rule[2].wheels) alpha = std::max(alpha, w.alpha);
  ASSERT_FALSE(book.at("speed_at_alpha").empty());
  for (const auto& at : book.at("speed_at_alpha")) {
    const double speed = speed_at_alpha(alpha, study.by_rule[2].speed, at.at("alpha").get<double>());
    if (std::isinf(speed)) {
      EXPECT_TRUE(at.at("speed_m_s").is_null() && at.at("speed_kmh").is_null());
      continue;
    }
    EXPECT_EQ(at.at("speed_m_s").get<double>(), speed);
    EXPECT_EQ(at.at("speed_kmh").get<double>(), speed * 3.6);
  }
}

TEST(BalanceReport, CsvIsOneTableOfNumbersAtFullPrecision) {
  const BalanceStudy study = su_study(0.3);
  std::istringstream in(written(study, OutputFormat::csv));
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "section,rule,item,quantity,unit,crank_angle_deg,order,balanced_fraction,value");
  int rows = 0, phases = 0;
  bool found_y90 = false;
  while (std::getline(in, line)) {
    ++rows;
    // No field here holds a comma (names are plain), so splitting on commas is exact.
    std::vector<std::string> f;
    std::stringstream ss(line);
    for (std::string cell; std::getline(ss, cell, ',');) f.push_back(cell);
    if (line.back() == ',') f.push_back("");
    ASSERT_EQ(f.size(), 9u) << line;
    const double value = std::stod(f[8]);  // every value is a number (inf for a speed never reached)
    if (f[3].find("phase") != std::string::npos) ++phases;
    if (f[0] == "state" && f[1].empty() && f[2] == "right" && f[3] == "Y" && f[5] == "90") {
      EXPECT_EQ(value, study.gear.states[90].cylinders[0].vertical);
      found_y90 = true;
    }
  }
  EXPECT_TRUE(found_y90);
  EXPECT_GT(phases, 50);
  EXPECT_GT(rows, 500);
}

// --alpha 0.3 holds the coupled wheels at 0.3; the book's rule leaves a driving wheel above it,
// and the report says why, in every format a person reads, and in the JSON's notes.
// README and docs/driving_gear.md call the dynamic wheel load dP the hammer blow: every report
// for people says the term where it prints dP (audit 2026-11-27b found it nowhere).
TEST(BalanceReport, DynamicWheelLoadIsCalledTheHammerBlow) {
  const BalanceStudy study = su_study(0.0);
  for (OutputFormat f : {OutputFormat::table, OutputFormat::markdown, OutputFormat::html}) {
    const std::string text = written(study, f);
    EXPECT_NE(text.find("dP on the rail: the hammer blow"), std::string::npos) << to_string(f);
    EXPECT_NE(text.find("max hammer blow [kN]"), std::string::npos) << to_string(f);
  }
}

// One quantity, one key (user audit 2026-11-27c, F7): the gear's wheels and the balanced ones
// carry the wheel load under the same keys, the hammer blow max|ΔP| = α·П among them (it was
// max_dP_n in one and max_hammer_blow_n in the other, and max_dP_n is the signed maximum, which
// for the Су's driving R wheel is 197.9 kN against a hammer blow of 204.7 kN).
TEST(BalanceReport, TheWheelLoadHasOneSetOfKeys) {
  const BalanceStudy study = su_study(0.3);
  const auto j = nlohmann::json::parse(written(study, OutputFormat::json));
  const char* load_keys[] = {"max_hammer_blow_n", "max_dP_n", "min_dP_n", "least_load_n", "alpha", "alpha_89a",
                             "wheel_lift", "dP_harmonics_n"};
  const auto check = [&](const nlohmann::json& wheel, const GearWheelLoad& x) {
    for (const char* key : load_keys) EXPECT_TRUE(wheel.contains(key)) << key << " in " << wheel.at("wheel");
    const double blow = wheel.at("max_hammer_blow_n").get<double>();
    // max|ΔP| over the same sampled revolution as the extremes: the larger of the two, exactly
    // (α·П and its quotient by П round once each: 2 ulp).
    EXPECT_NEAR(blow, std::max(x.max_dynamic_load, -x.min_dynamic_load), 4e-16 * blow);
    EXPECT_EQ(wheel.at("max_dP_n").get<double>(), x.max_dynamic_load);
  };
  for (size_t w = 0; w < study.gear.wheels.size(); ++w) check(j.at("gear").at("wheels").at(w), study.gear.wheels[w]);
  for (size_t r = 0; r < study.by_rule.size(); ++r)
    for (size_t w = 0; w < study.by_rule[r].wheels.size(); ++w) {
      const auto& wheel = j.at("by_rule").at(r).at("wheels").at(w);
      check(wheel, study.by_rule[r].after.wheels[w]);
      EXPECT_EQ(wheel.at("max_hammer_blow_n").get<double>(), study.by_rule[r].wheels[w].max_hammer_blow);
    }
  // The driving wheel's signed maximum is not its hammer blow: the two keys say different things.
  const auto& driving = j.at("gear").at("wheels").at(2);
  EXPECT_LT(driving.at("max_dP_n").get<double>(), 0.99 * driving.at("max_hammer_blow_n").get<double>());
  // The CSV's counterweight rows say the same word.
  const std::string csv = written(study, OutputFormat::csv);
  EXPECT_NE(csv.find(",max hammer blow,N,"), std::string::npos);
  EXPECT_EQ(csv.find(",max dP,"), std::string::npos);
}

// No output of balance prints a negative zero (user audit 2026-11-27c, F7: the CSV's Y at the
// dead centres read "-0"): the shared number writers write −0 as 0.
TEST(BalanceReport, NoNegativeZero) {
  for (double alpha : {0.0, 0.3}) {
    const BalanceStudy study = su_study(alpha);
    bool negative_zero_in_the_results = false;
    for (const GearState& st : study.gear.states)
      for (const RodForces& f : st.cylinders)
        negative_zero_in_the_results = negative_zero_in_the_results || (f.vertical == 0.0 && std::signbit(f.vertical));
    EXPECT_TRUE(negative_zero_in_the_results || alpha > 0) << "the case this test is for is gone";
    for (OutputFormat f : {OutputFormat::table, OutputFormat::csv, OutputFormat::json, OutputFormat::markdown}) {
      const std::string text = written(study, f);
      for (const char* zero : {",-0\n", ",-0,", " -0.0\n", " -0.0,", "-0.00 ", "|-0 ", " -0 "})
        EXPECT_EQ(text.find(zero), std::string::npos) << zero << " in " << to_string(f);
    }
  }
}

TEST(BalanceReport, ExplainsAnAlphaAboveTheAllowedOne) {
  const BalanceStudy study = su_study(0.3);
  double book_alpha = 0.0;
  for (const WheelBalance& w : study.by_rule[2].wheels) book_alpha = std::max(book_alpha, w.alpha);
  ASSERT_GT(book_alpha, 0.3);
  for (OutputFormat f : {OutputFormat::table, OutputFormat::markdown, OutputFormat::html})
    EXPECT_NE(written(study, f).find("above the allowed 0.300: --alpha sizes the overbalance"), std::string::npos)
        << to_string(f);
  const auto j = nlohmann::json::parse(written(study, OutputFormat::json));
  EXPECT_FALSE(j.at("notes").empty());
  // Without --alpha there is nothing to explain.
  EXPECT_TRUE(nlohmann::json::parse(written(su_study(0.0), OutputFormat::json)).at("notes").empty());
}

// The reports people read spell the quantities as every command does (docs/input.md, "Names and
// units in outputs"): α, ω, φ and kN·m, the speed as given; CSV keeps the words and takes N·m.
TEST(BalanceReport, NamesAndUnitsAsEveryCommandSpellsThem) {
  const BalanceStudy study = su_study(0.3);
  for (OutputFormat f : {OutputFormat::table, OutputFormat::markdown, OutputFormat::html}) {
    const std::string text = written(study, f);
    for (const char* now : {"max α", "α (89a)", "φ [deg]", "[kN·m]", " km/h (ω ", " rad/s, f1 "})
      EXPECT_NE(text.find(now), std::string::npos) << to_string(f) << ": " << now;
    for (const char* before : {"alpha (89a)", "max alpha", "phi [deg]", "kN m", "(omega "})
      EXPECT_EQ(text.find(before), std::string::npos) << to_string(f) << ": " << before;
    EXPECT_EQ(text.find(".0 km/h (ω"), std::string::npos) << to_string(f);  // a given speed as given
  }
  const std::string csv = written(study, OutputFormat::csv);
  EXPECT_NE(csv.find(",nosing,N·m,"), std::string::npos);
  EXPECT_EQ(csv.find(",N m,"), std::string::npos);
}

}  // namespace
}  // namespace railmodal
