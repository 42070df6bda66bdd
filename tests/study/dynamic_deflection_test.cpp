// The book's permissible dynamic deflections in a study (springs digest §5): which springs each
// rule limits, the [permissible_dynamic_deflection] table, the check of each variant, and its
// place in the ranking and the outputs.
#include <cmath>
#include <limits>
#include <sstream>

#include "railmodal/railmodal.hpp"
#include "study/permissible_deflection.hpp"
#include "study/study_files.hpp"
#include "test_support.hpp"

namespace railmodal::test {
namespace {

// The loaded two-axle freight wagon of Example 3 with its leaf-spring friction φ = 0.075.
const std::string kWagon = example3_wagon(", relative_friction = 0.075");

std::string study_file(const std::string& body) { return write_study(kWagon, body); }

InputError study_error(const std::string& body) { return study_error_at(study_file(body), body); }

// Lehner's limits for freight cars, which most tests here check.
const std::string kLehnerFreight = "[permissible_dynamic_deflection]\nrule = \"lehner\"\nservice = \"freight\"\n";

// A bogie car in two stages: a bogie on coil axle-box springs, the body on the bogie through a
// bolster of an elliptic spring in series with coils (the book's double suspension).
const char* kBogieCar = R"(
[vehicle]
name = "car"
[[body]]
name = "bogie"
mass = "2000 kg"
inertia = { roll = "0 kg*m^2", pitch = "0 kg*m^2", yaw = "0 kg*m^2" }
centre_of_gravity = ["0 m", "0 m", "0 m"]
held = ["lateral", "roll", "pitch", "yaw"]
[[body]]
name = "body"
mass = "10000 kg"
inertia = { roll = "0 kg*m^2", pitch = "0 kg*m^2", yaw = "0 kg*m^2" }
centre_of_gravity = ["0 m", "0 m", "0 m"]
held = ["lateral", "roll", "pitch", "yaw"]
[[element]]
name = "axlebox"
upper = "bogie"
point = ["0 m", "0 m", "0 m"]
vertical = [{ kind = "coil", stiffness = "2 MN/m" }]
[[element]]
name = "bolster"
lower = "bogie"
upper = "body"
point = ["0 m", "0 m", "0 m"]
vertical = [{ kind = "elliptic", stiffness = "1 MN/m" }, { kind = "coil", stiffness = "1.5 MN/m", count = 2 }]
)";

std::vector<study::PermissibleDeflection> limits_of(DeflectionRule::Book book, DeflectionRule::Service service,
                                                    LinearSystem* system) {
  *system = assemble(load_vehicle(write_temp("car.toml", kBogieCar)), DofSet::vertical);
  DeflectionRule rule;
  rule.book = book;
  rule.service = service;
  return study::permissible_deflections(rule, *system);
}

// The limits of springs digest §5 by element and stage. Shares: in series every stage carries
// the element's force, so a stage deflects k_element/k_stage of the element's stretch; here
// k_element = 1/(1/1 + 1/3) = 0.75 MN/m, so the elliptic stage takes 0.75 and the coils 0.25.
// f_st of the elliptic stage: the body's weight 10 t × 9.81 over 1 MN/m = 98.1 mm.
TEST(PermissibleDeflection, LimitsFollowTheBookByElementAndStage) {
  LinearSystem s;
  auto l = limits_of(DeflectionRule::Book::lehner, DeflectionRule::Service::passenger, &s);
  ASSERT_EQ(l.size(), 3u);
  EXPECT_EQ(l[0].element, 0);  // axle-box coil: 30 mm
  EXPECT_EQ(l[0].stage, 0);
  EXPECT_EQ(l[0].permissible, 0.030);
  EXPECT_EQ(l[0].share, 1.0);
  EXPECT_EQ(l[1].element, 1);  // elliptic: 0.2 f_st
  EXPECT_EQ(l[1].stage, 0);
  EXPECT_NEAR(l[1].permissible, 0.2 * 10000.0 * 9.81 / 1.0e6, 1e-12);
  EXPECT_NEAR(l[1].share, 0.75, 1e-12);
  EXPECT_NE(l[1].basis.find("0.2 f_st = 0.2 × 98.1 mm"), std::string::npos) << l[1].basis;
  EXPECT_EQ(l[2].stage, 1);  // bolster coils: 30 mm on their quarter
  EXPECT_NEAR(l[2].share, 0.25, 1e-12);

  // Korotkevich's axle-box figures are for cars without bogies: on the bogie car only the
  // elliptic spring of a passenger car is limited.
  l = limits_of(DeflectionRule::Book::korotkevich, DeflectionRule::Service::passenger, &s);
  ASSERT_EQ(l.size(), 1u);
  EXPECT_EQ(l[0].element, 1);
  EXPECT_EQ(l[0].stage, 0);
  EXPECT_EQ(l[0].permissible, 0.030);
  EXPECT_TRUE(limits_of(DeflectionRule::Book::korotkevich, DeflectionRule::Service::freight, &s).empty());

  // The two-axle wagon has no bogies: its four axle-box springs as a whole.
  const LinearSystem wagon = assemble(load_vehicle(write_temp("wagon.toml", kWagon)), DofSet::vertical);
  DeflectionRule rule;
  rule.book = DeflectionRule::Book::korotkevich;
  for (auto [service, limit] : {std::pair{DeflectionRule::Service::passenger, 0.040},
                                std::pair{DeflectionRule::Service::freight, 0.025}}) {
    rule.service = service;
    l = study::permissible_deflections(rule, wagon);
    ASSERT_EQ(l.size(), 4u);
    for (const auto& x : l) {
      EXPECT_EQ(x.stage, -1);
      EXPECT_EQ(x.permissible, limit);
    }
  }
  EXPECT_NE(l[0].basis.find("bogie-less freight cars 25 mm"), std::string::npos);
}

// A coil in series with a friction stage carries the friction force too: it is checked by the
// springs' force over its own stiffness (2 × 1.5 MN/m), the friction stage itself by its share
// k_element/k_stage. And a stage with no static load (0.2 f_st = 0) is not checked rather than
// checked against 0.
TEST(PermissibleDeflection, SeriesFrictionAndZeroLoad) {
  std::string car = kBogieCar;
  const std::string bolster = R"(vertical = [{ kind = "elliptic", stiffness = "1 MN/m" }, { kind = "coil", stiffness = "1.5 MN/m", count = 2 }])";
  car.replace(car.find(bolster), bolster.size(),
              R"(vertical = [{ kind = "Elliptic", stiffness = "1 MN/m", relative_friction = 0.1 }, { kind = "coil", stiffness = "1.5 MN/m", count = 2 }])");
  LinearSystem s = assemble(load_vehicle(write_temp("car.toml", car)), DofSet::vertical);
  DeflectionRule rule;
  rule.book = DeflectionRule::Book::lehner;
  auto l = study::permissible_deflections(rule, s);
  ASSERT_EQ(l.size(), 3u);
  EXPECT_NEAR(l[1].share, 0.75, 1e-12);  // "Elliptic": kinds are matched whatever their case
  EXPECT_EQ(l[1].force_stiffness, 0.0);
  EXPECT_NEAR(l[2].share, 0.25, 1e-12);
  EXPECT_EQ(l[2].force_stiffness, 3.0e6);
  // The friction stage holds while the coils take the force across its band, 2 × 0.1·P over
  // 3 MN/m: it deflects share × (X − 0.1·P/3e6) (issue 17, item 1: the series model).
  EXPECT_NEAR(l[1].hold, 0.1 * s.element_loads[1] / 3.0e6, 1e-15);
  EXPECT_EQ(l[2].hold, 0.0);
  s.element_loads[1] = 0.0;
  l = study::permissible_deflections(rule, s);
  ASSERT_EQ(l.size(), 2u);  // the elliptic stage's 0.2 f_st is 0: left out
  EXPECT_EQ(l[1].stage, 1);
}

TEST(PermissibleDeflection, FreightLeafSpringsAreLimitedOnlyForFreightCars) {
  const LinearSystem s = assemble(load_vehicle(write_temp("wagon.toml", kWagon)), DofSet::vertical);
  DeflectionRule rule;
  rule.book = DeflectionRule::Book::lehner;
  EXPECT_TRUE(study::permissible_deflections(rule, s).empty());  // Lehner gives no passenger leaf limit
  rule.service = DeflectionRule::Service::freight;
  const auto l = study::permissible_deflections(rule, s);
  ASSERT_EQ(l.size(), 4u);
  for (const auto& x : l) EXPECT_NEAR(x.permissible, 0.4 * 0.0572, 1e-12);  // 0.4 f_st
  rule.element_limits = {{"front left spring", 0.010}};
  const auto overridden = study::permissible_deflections(rule, s);
  ASSERT_EQ(overridden.size(), 4u);
  EXPECT_EQ(overridden[0].permissible, 0.010);
  EXPECT_EQ(overridden[0].basis, "study: 10 mm");
  rule.element_limits = {{"no such spring", 0.010}};
  EXPECT_THROW(study::permissible_deflections(rule, s), std::invalid_argument);
}

TEST(PermissibleDeflection, StudyTableIsChecked) {
  InputError e = study_error("[permissible_dynamic_deflection]\nrule = \"popov\"\n");
  EXPECT_NE(e.message().find("key 'permissible_dynamic_deflection.rule': must be \"korotkevich\" or \"lehner\""),
            std::string::npos)
      << e.what();
  e = study_error("[permissible_dynamic_deflection]\nrule = \"lehner\"\nservice = \"mail\"\n");
  EXPECT_NE(e.message().find("must be \"passenger\" or \"freight\""), std::string::npos) << e.what();
  e = study_error("[permissible_dynamic_deflection]\nservice = \"freight\"\n");
  EXPECT_NE(e.message().find("name a rule"), std::string::npos) << e.what();
  e = study_error("[ranking]\nmax_dynamic_deflection_ratio = 1\n");
  EXPECT_NE(e.message().find("needs a [permissible_dynamic_deflection] table"), std::string::npos) << e.what();
  e = study_error("[permissible_dynamic_deflection]\nelements = { \"bolster\" = \"30 mm\" }\n");
  EXPECT_EQ(e.line(), 6) << e.what();
  EXPECT_NE(e.message().find("variant 'base': no element 'bolster' with vertical springs"), std::string::npos) << e.what();
  // A lateral scene moves no spring vertically: refused, not checked as "kept".
  e = study_error("[permissible_dynamic_deflection]\nrule = \"lehner\"\n[[variant]]\nname = \"sway\"\n"
                  "scene_overrides = { \"scene.dofs\" = \"lateral\" }\n");
  EXPECT_EQ(e.line(), 5) << e.what();
  EXPECT_NE(e.message().find("variant 'sway': the scene's dofs = \"lateral\" has no bounce or pitch"), std::string::npos)
      << e.what();
}

// Example 3's wagon on 10 m rails (two-axle digest): friction φf = 4.3 mm stops the
// resonances of a 5 mm joint dip; at 40 mm it stops neither the pitch resonance (threshold
// 2a = 8φf/(π|sin(π·2a1/L)|) = 11.7 mm) nor the bounce one (29.9 mm), which then grow without
// limit.
TEST(PermissibleDeflection, ResonanceFrictionDoesNotStopExceedsTheLimit) {
  const Study s = load_study(study_file(R"(
[[variant]]
name = "deep joints"
scene_overrides = { "source[0].dip_depth" = "40 mm" }
[permissible_dynamic_deflection]
rule = "lehner"
service = "freight"
[ranking]
max_dynamic_deflection_ratio = 1
)"));
  const auto results = evaluate_study(s, {});
  ASSERT_EQ(results.size(), 2u);
  ASSERT_TRUE(results[0].ok() && results[1].ok());
  const VariantResult& base = results[0];
  ASSERT_TRUE(base.deflections_checked);
  ASSERT_EQ(base.deflections.size(), 4u);
  for (const auto& d : base.deflections) {
    EXPECT_TRUE(d.kept()) << d.element;
    EXPECT_GT(d.deflection, 0.0);
    EXPECT_NEAR(d.permissible, 0.4 * 0.0572, 1e-12);
  }
  const double ratio = *metric_value(base, "dynamic_deflection_ratio");
  EXPECT_GT(ratio, 0.0);
  EXPECT_LT(ratio, 1.0);
  // The ratio is the worst check's deflection over its limit; per element, that element's.
  EXPECT_DOUBLE_EQ(*metric_value(base, "dynamic_deflection_ratio:front left spring"),
                   base.deflections[0].deflection / base.deflections[0].permissible);

  const VariantResult& deep = results[1];
  bool bounce_not_stopped = false;
  for (const auto& c : deep.critical_speeds) bounce_not_stopped |= c.mode_name == "body bounce" && !c.friction_stops;
  ASSERT_TRUE(bounce_not_stopped);
  for (const auto& d : deep.deflections) {
    EXPECT_TRUE(d.unbounded) << d.element;
    EXPECT_FALSE(d.kept());
  }
  EXPECT_EQ(*metric_value(deep, "dynamic_deflection_ratio"), std::numeric_limits<double>::infinity());

  const Comparison c = rank_variants(s, results);
  EXPECT_EQ(c.variants[0].result.name, "base");
  EXPECT_TRUE(c.variants[0].feasible);
  ASSERT_EQ(c.variants[1].violations.size(), 1u);
  EXPECT_NE(c.variants[1].violations[0].find("dynamic_deflection_ratio unbounded > 1"), std::string::npos) << c.variants[1].violations[0];
  std::ostringstream table, json;
  write_comparison(table, c, OutputFormat::table);
  EXPECT_NE(table.str().find("largest dynamic deflection"), std::string::npos);
  EXPECT_NE(table.str().find("unbounded"), std::string::npos);
  write_comparison(json, c, OutputFormat::json);
  EXPECT_NE(json.str().find("\"keeps_permissible_deflections\": false"), std::string::npos);
  EXPECT_NE(json.str().find("\"rule\": \"lehner\""), std::string::npos);

  // A shard's JSON carries the checks and reads back into the same results.
  std::ostringstream shard;
  write_shard(shard, s, {}, results);
  const auto back = read_shard(write_temp("shard.json", shard.str()), s);
  ASSERT_EQ(back.size(), 2u);
  ASSERT_TRUE(back[0].deflections_checked);
  ASSERT_EQ(back[0].deflections.size(), 4u);
  EXPECT_EQ(back[0].deflections[1].deflection, base.deflections[1].deflection);
  EXPECT_EQ(back[0].deflections[1].basis, base.deflections[1].basis);
  EXPECT_EQ(back[1].deflections[0].unbounded, true);
}

// Springs the rule does not limit keep their friction: a limit of the study's own on one spring
// equal to Lehner's 0.4 f_st gives that spring exactly the deflection Lehner's check of all four
// gives it (the other three are linearised at the same stretch), not an undamped resonance.
TEST(PermissibleDeflection, UnlimitedSpringsKeepTheirFriction) {
  const Study lehner = load_study(study_file(kLehnerFreight));
  const Study own = load_study(study_file("[permissible_dynamic_deflection]\nelements = { \"front left spring\" = \"22.88 mm\" }\n"));
  const VariantResult a = evaluate_variant(lehner.variants[0], 0, lehner.deflection_rule);
  const VariantResult b = evaluate_variant(own.variants[0], 0, own.deflection_rule);
  ASSERT_TRUE(a.ok() && b.ok());
  ASSERT_EQ(b.deflections.size(), 1u);
  EXPECT_FALSE(b.deflections[0].unbounded);
  // 0.4 × 57.2 mm and 22.88 mm differ in the last bits only: so do the dampers and deflections.
  EXPECT_NEAR(b.deflections[0].deflection, a.deflections[0].deflection, 1e-12 * a.deflections[0].deflection);
  EXPECT_LT(*metric_value(b, "dynamic_deflection_ratio"), 1.0);
}

// The scene's own friction model (equivalent viscous at 5 mm) gives finite curves, but a
// resonance that friction does not stop still exceeds every limit: rule 1 looks at the
// friction criterion and the vehicle's own damping, not at the scene's linearisation.
TEST(PermissibleDeflection, SceneFrictionAmplitudeDoesNotHideAGrowingResonance) {
  const Study s = load_study(study_file(R"(
[[variant]]
name = "deep joints"
scene_overrides = { "source[0].dip_depth" = "40 mm" }
)" + kLehnerFreight));
  Study with_friction = s;
  for (auto& v : with_friction.variants) v.scene.friction_reference_amplitude = 0.005;
  const VariantResult deep = evaluate_variant(with_friction.variants[1], 1, s.deflection_rule);
  ASSERT_TRUE(deep.ok()) << deep.failure;
  for (const auto& d : deep.deflections) EXPECT_TRUE(d.unbounded) << d.element;
  const VariantResult base = evaluate_variant(with_friction.variants[0], 0, s.deflection_rule);
  for (const auto& d : base.deflections) EXPECT_TRUE(d.kept()) << d.element;
}

// The grid's largest value is refined: a 5 km/h grid and a 0.5 km/h one find the same worst
// deflection (golden-section search to 1e-6 of the speed; the value is flat to second order
// at the peak, so 1e-9 of it).
TEST(PermissibleDeflection, PeaksBetweenGridSpeedsAreRefined) {
  const Study s = load_study(study_file(R"(
[[variant]]
name = "coarse"
scene_overrides = { "speed.step" = "5 km/h" }
[[variant]]
name = "fine"
scene_overrides = { "speed.step" = "0.5 km/h" }
)" + kLehnerFreight));
  const auto results = evaluate_study(s, {});
  ASSERT_EQ(results.size(), 3u);
  const double coarse = *metric_value(results[1], "dynamic_deflection_ratio");
  const double fine = *metric_value(results[2], "dynamic_deflection_ratio");
  EXPECT_NEAR(coarse, fine, 1e-9 * fine);
  EXPECT_NE(std::fmod(results[1].deflections[0].speed * 3.6, 5.0), 0.0);  // not a grid speed
}

// Viscous dampers damp the resonance that friction does not stop: finite, not unbounded.
TEST(PermissibleDeflection, ViscouslyDampedResonanceIsFinite) {
  const Study s = load_study(study_file(R"(
[[variant]]
name = "deep joints, dampers"
overrides = { "suspension.vertical_damping" = "30 kN*s/m" }
scene_overrides = { "source[0].dip_depth" = "40 mm" }
)" + kLehnerFreight));
  const VariantResult r = evaluate_variant(s.variants[1], 1, s.deflection_rule);
  ASSERT_TRUE(r.ok()) << r.failure;
  bool not_stopped = false;
  for (const auto& c : r.critical_speeds) not_stopped |= !c.friction_stops;
  ASSERT_TRUE(not_stopped);
  for (const auto& d : r.deflections) {
    EXPECT_FALSE(d.unbounded) << d.element;
    EXPECT_GT(d.deflection, 0.0);
  }
  EXPECT_TRUE(std::isfinite(*metric_value(r, "dynamic_deflection_ratio")));
}

// Shards carry the rule they were checked by; a merge under another rule is refused.
TEST(PermissibleDeflection, ShardOfAnotherRuleIsRefused) {
  const Study checked = load_study(study_file(kLehnerFreight));
  const auto results = evaluate_study(checked, {});
  std::ostringstream shard;
  write_shard(shard, checked, {}, results);
  const std::string file = write_temp("shard.json", shard.str());
  EXPECT_EQ(read_shard(file, checked).size(), 1u);
  const Study unchecked = load_study(study_file(""));
  try {
    read_shard(file, unchecked);
    ADD_FAILURE() << "a shard of another rule was merged";
  } catch (const InputError& e) {
    EXPECT_NE(e.message().find("checked for permissible dynamic deflections by 'lehner freight', the study asks for 'none'"),
              std::string::npos)
        << e.what();
  }
}

TEST(PermissibleDeflection, NotCheckedUnlessTheStudyNamesARule) {
  const Study s = load_study(study_file(""));
  const auto results = evaluate_study(s, {});
  ASSERT_EQ(results.size(), 1u);
  EXPECT_FALSE(results[0].deflections_checked);
  EXPECT_TRUE(results[0].deflections.empty());
  EXPECT_FALSE(metric_value(results[0], "dynamic_deflection_ratio").has_value());
  std::ostringstream table;
  write_comparison(table, rank_variants(s, results), OutputFormat::table);
  EXPECT_EQ(table.str().find("deflection / permissible"), std::string::npos);
}

}  // namespace
}  // namespace railmodal::test
