// The study's fast path (src/input/variant_fast_path.cpp): a variant built by writing its
// values into the base vehicle read once is the vehicle the readers build from the overridden
// TOML, number for number; keys and values it does not know take the readers' path.
#include <cstring>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "input/study_reader.hpp"
#include "input/variant_fast_path.hpp"
#include "input/vehicle_numbers.hpp"
#include "load_study.hpp"
#include "railmodal/railmodal.hpp"
#include "study/planned_variants.hpp"
#include "test_support.hpp"

namespace railmodal::test {
namespace {

std::string slurp(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The benchmark's sampled study of the resort car with `count` variants, its files named by
// absolute paths so that the copy can live in a temporary folder.
std::string sample_study(int count) {
  const std::string data = RAILMODAL_DATA_DIR;
  std::string text = slurp(data + "/../tools/benchmarks/resort_car_sample_study.toml");
  text = std::regex_replace(text, std::regex(R"(\.\./\.\./data)"), data);
  text = std::regex_replace(text, std::regex("count = 100000"), "count = " + std::to_string(count));
  return write_temp("sample_study.toml", text);
}

// Exactly the same vehicle: the same shape, and every number the same bits.
void expect_same_vehicle(const Vehicle& fast, const Vehicle& readers, const std::string& variant) {
  ASSERT_EQ(input::vehicle_shape(fast), input::vehicle_shape(readers)) << variant;
  Vehicle a = fast, b = readers;
  const std::vector<double*> x = input::vehicle_numbers(&a), y = input::vehicle_numbers(&b);
  ASSERT_EQ(x.size(), y.size()) << variant;
  for (size_t i = 0; i < x.size(); ++i)
    EXPECT_EQ(std::memcmp(x[i], y[i], sizeof(double)), 0) << variant << ", number " << i << ": " << *x[i] << " against " << *y[i];
}

// Every variant the study plans, in study order (PlannedVariants makes each from its index).
std::vector<study::VariantSpec> all_variants(const study::StudyPlan& plan) {
  const study::PlannedVariants planned(plan);
  std::vector<study::VariantSpec> specs;
  for (size_t i = 0; i < planned.size(); ++i) specs.push_back(planned.at(i));
  return specs;
}

struct Checked {
  std::set<std::string> fast_keys;  // the keys the fast path sets
  int fast_variants = 0;            // the variants it built
  int variants = 0;
};

// Whether the fast path gives the variant's vehicle (into a fresh one).
bool reads_fast(const input::StudyFile& file, const study::VariantSpec& spec,
                const std::vector<const study::Assignment*>& on_vehicle) {
  Vehicle vehicle;
  return input::fast_vehicle_into(file, spec, on_vehicle, &vehicle);
}

// Every variant of the study read with the fast path and without it (the file's probes
// dropped): the same vehicle and scene.
Checked check_study(const std::string& path) {
  input::StudyFile file = input::read_study_file(path, kMaxStudyVariants);
  const std::vector<study::VariantSpec> specs = all_variants(file.plan);
  input::check_variants(&file);
  input::StudyFile readers_only = file;
  readers_only.fast.reset();
  Checked c;
  if (file.fast)
    for (const auto& [key, k] : file.fast->keys) c.fast_keys.insert(key);
  for (const study::VariantSpec& spec : specs) {
    std::vector<const study::Assignment*> on_vehicle;
    for (const auto& a : spec.assignments)
      if (!a.scene) on_vehicle.push_back(&a);
    if (!on_vehicle.empty() && reads_fast(file, spec, on_vehicle)) ++c.fast_variants;
    ++c.variants;
    const StudyVariant fast = input::read_variant(file, spec, nullptr);
    const StudyVariant readers = input::read_variant(readers_only, spec, nullptr);
    expect_same_vehicle(fast.vehicle, readers.vehicle, path + ": " + spec.name);
  }
  return c;
}

TEST(VariantFastPath, BuildsTheSampledStudysVariantsAsTheReadersDo) {
  const Checked c = check_study(sample_study(300));
  // The three spring stiffnesses, each a number of the stages it names (stiffness as read).
  EXPECT_EQ(c.fast_keys, (std::set<std::string>{"primary.spring[0].stiffness", "primary.spring[1].stiffness",
                                                 "secondary.spring.stiffness"}));
  EXPECT_EQ(c.fast_variants, 300);
  EXPECT_EQ(c.variants, 300);
}

TEST(VariantFastPath, BuildsTheBundledStudiesVariantsAsTheReadersDo) {
  const std::string studies = std::string(RAILMODAL_DATA_DIR) + "/studies";
  std::map<std::string, Checked> checked;
  for (const auto& entry : std::filesystem::directory_iterator(studies))
    checked[entry.path().filename().string()] = check_study(entry.path().string());
  ASSERT_EQ(checked.size(), 5u) << "a study was added to data/studies: say here which keys it sets fast";
  // The cradle springs' stiffness of the resort car's overrides is set fast; the other file
  // (the Fette car) takes the readers.
  EXPECT_EQ(checked["resort_against_fette.toml"].fast_keys, std::set<std::string>{"secondary.spring.stiffness"});
  EXPECT_EQ(checked["resort_against_fette.toml"].fast_variants, 2);
  // A static deflection sets the stiffness to the spring's load over it, not to its own value:
  // the readers read every such variant.
  EXPECT_TRUE(checked["two_axle_rail_length_and_springs.toml"].fast_keys.empty());
  EXPECT_TRUE(checked["two_axle_wagon_ride_springs.toml"].fast_keys.empty());
  // Scene keys only.
  EXPECT_TRUE(checked["two_axle_joint_dip_deflection.toml"].fast_keys.empty());
  // The primary's longitudinal stiffness is set fast; the yaw damper (a series damper table)
  // takes the readers.
  EXPECT_EQ(checked["coach_hunting_yaw_dampers.toml"].fast_keys, std::set<std::string>{"primary.longitudinal.stiffness"});
}

// A study's worker reads each variant into the vehicle of the one before
// (detail::read_variant_into): in any order, across the bundled studies (other vehicle files,
// the fast path and the readers, scene-only keys) and the sampled one, each variant is the one
// read afresh, name, parameters and every number of its vehicle.
TEST(VariantFastPath, VariantsReadOneIntoAnotherAreTheFreshOnes) {
  std::vector<std::string> files;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(RAILMODAL_DATA_DIR) + "/studies"))
    files.push_back(entry.path().string());
  files.push_back(sample_study(12));
  for (const std::string& file : files) {
    const Study study = open_study(file);
    const int n = variant_count(study);
    std::vector<int> order;  // forwards, then every other one backwards, then the first again
    for (int i = 0; i < n; ++i) order.push_back(i);
    for (int i = n - 1; i >= 0; i -= 2) order.push_back(i);
    order.push_back(0);
    StudyVariant kept;
    for (int i : order) {
      detail::read_variant_into(study, i, &kept);
      const StudyVariant fresh = read_variant(study, i);
      const std::string label = file + ": variant " + std::to_string(i + 1);
      EXPECT_EQ(kept.name, fresh.name) << label;
      EXPECT_EQ(kept.parameters, fresh.parameters) << label;
      expect_same_vehicle(kept.vehicle, fresh.vehicle, label);
    }
  }
}

TEST(VariantFastPath, ADrawnValueOutsideTheProbedIntervalTakesTheReaders) {
  input::StudyFile file = input::read_study_file(sample_study(4), kMaxStudyVariants);
  const std::vector<study::VariantSpec> specs = all_variants(file.plan);
  input::check_variants(&file);
  study::VariantSpec spec = specs.front();
  std::vector<const study::Assignment*> on_vehicle;
  for (const auto& a : spec.assignments) on_vehicle.push_back(&a);
  EXPECT_TRUE(reads_fast(file, spec, on_vehicle));
  spec.assignments.front().drawn.number = 2000.0;  // the sample draws 455–845 kgf/cm
  EXPECT_FALSE(reads_fast(file, spec, on_vehicle));
  spec.assignments.front().drawn.number = 500.0;
  spec.assignments.front().drawn.unit = "parsec";  // not a stiffness: the readers say why
  EXPECT_FALSE(reads_fast(file, spec, on_vehicle));
}

// A bad value of a key the fast path sets is still refused by the readers, at the study line
// that wrote it.
TEST(VariantFastPath, ABadValueOfAFastKeyIsTheReadersError) {
  const std::string data = RAILMODAL_DATA_DIR;
  const std::string path = write_temp("bad.toml", "[study]\nvehicle = \"" + data + "/vehicles/resort_car.toml\"\n"
                                      "scene = \"" + data + "/scenes/resort_car_10m_rails.toml\"\n"
                                      "[[sweep]]\nparameters = [{ key = \"secondary.spring.stiffness\", "
                                      "values = [\"500 kgf/cm\", \"600 kgf/cm\"] }]\n"
                                      "[[variant]]\nname = \"soft\"\n"
                                      "overrides = { \"secondary.spring.stiffness\" = \"-5 kgf/cm\" }\n");
  try {
    load_study(path);
    FAIL() << "a negative stiffness was read";
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 8);
    EXPECT_NE(std::string(e.what()).find("variant 'soft': key 'secondary.spring.stiffness': must be positive"),
              std::string::npos)
        << e.what();
  }
}

// Two keys each fine alone on the base, refused together by a reader's check that compares
// them (the bending beam must reach every element on the body): the joint probe of the keys'
// corners sees it, so the readers read the variants and the one that sets both is refused at
// its study line, as without the fast path.
TEST(VariantFastPath, KeysTheReadersCheckAgainstEachOtherAreProbedTogether) {
  const std::string data = RAILMODAL_DATA_DIR;
  // The flexible coach with the beam's centre written, so that both keys set a number each.
  const std::string coach = write_temp(
      "joint_coach.toml", std::regex_replace(slurp(data + "/vehicles/manchester_benchmark_coach_flexible.toml"),
                                             std::regex(R"(bending = \{ length = "24 m",)"),
                                             R"(bending = { length = "24 m", centre = "0 m",)"));
  const std::string path =
      write_temp("joint.toml", "[study]\nvehicle = \"" + coach + "\"\n"
                 "scene = \"" + data + "/scenes/fette_car_10m_rails.toml\"\n"
                 "[[variant]]\nname = \"short beam\"\noverrides = { \"body.bending.length\" = \"19.5 m\" }\n"
                 "[[variant]]\nname = \"moved centre\"\noverrides = { \"body.bending.centre\" = \"0.3 m\" }\n"
                 "[[variant]]\nname = \"both\"\n"
                 "overrides = { \"body.bending.length\" = \"19.5 m\", \"body.bending.centre\" = \"0.3 m\" }\n");
  input::StudyFile file = input::read_study_file(path, kMaxStudyVariants);
  input::check_variants(&file);
  std::string fast_keys;
  if (file.fast)
    for (const auto& [key, k] : file.fast->keys) fast_keys += key + " ";
  EXPECT_FALSE(file.fast) << "the two keys' corner (19.5 m, 0.3 m) is refused by the readers; fast: " << fast_keys;
  const std::vector<study::VariantSpec> specs = all_variants(file.plan);
  ASSERT_EQ(specs.size(), 4u);  // the base, then the three written
  for (size_t i : {0, 1, 2}) EXPECT_NO_THROW(input::read_variant(file, specs[i], nullptr)) << specs[i].name;
  try {
    input::read_variant(file, specs[3], nullptr);
    FAIL() << "the beam that no longer reaches the cradles was read";
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 12) << e.what();  // the third [[variant]]'s overrides
    EXPECT_NE(std::string(e.what()).find("beyond the ends of the bending beam"), std::string::npos) << e.what();
  }
}

// A field added to the vehicle's structs must be walked by vehicle_numbers and vehicle_shape,
// or the fast path would not see what a key changes there: the structs' sizes (x86-64,
// libstdc++) say when one was added. Update input/vehicle_numbers.cpp, then these sizes.
TEST(VehicleNumbers, CoverEveryField) {
  if (sizeof(void*) != 8 || sizeof(std::string) != 32) GTEST_SKIP() << "sizes measured on x86-64 with libstdc++";
  // 144: Vehicle::warnings (168, 2026-11-27) went back out of the model on 2026-11-28 (the
  // reader hands its warnings beside the vehicle: load_vehicle's out-parameter).
  EXPECT_EQ(sizeof(Vehicle), 144u);
  EXPECT_EQ(sizeof(Body), 248u);  // 232 until Body::floor_height (2026-11-27)
  EXPECT_EQ(sizeof(BodyBending), 80u);
  EXPECT_EQ(sizeof(LoadDeflectionCurve), 48u);
  EXPECT_EQ(sizeof(SpringStage), 112u);
  EXPECT_EQ(sizeof(SwingHanger), 16u);
  EXPECT_EQ(sizeof(SeriesDamper), 24u);
  EXPECT_EQ(sizeof(Element), 288u);
  EXPECT_EQ(sizeof(CreepCoefficients), 32u);
  EXPECT_EQ(sizeof(HertzContactInput), 56u);
  EXPECT_EQ(sizeof(WheelRailContact), 176u);
  EXPECT_EQ(sizeof(Wheelset), 216u);
}

// The walk finds every number: a vehicle with every optional part present has them all.
TEST(VehicleNumbers, WalkEveryNumberOfAFullVehicle) {
  Vehicle v;
  Body b;
  b.bending = BodyBending{1.0, 2.0, BodyBending::Beam{3.0, 4.0}, BodyBending::Mode{5.0, 6.0}, 0.1};
  b.floor_height = 1.2;
  v.bodies.push_back(b);
  Element e;
  SpringStage s;
  s.curve = LoadDeflectionCurve{{0.0, 1.0}, {0.0, 2.0}};
  e.vertical_stages.push_back(s);
  e.hanger = SwingHanger{1.0, 0.1};
  e.series_dampers.push_back({Motion::lateral, 1.0, 2.0});
  v.elements.push_back(e);
  Wheelset w;
  w.contact.contact_angle_parameter = 1.0;
  w.contact.roll_parameter = 1.0;
  w.contact.axle_load = 1.0;
  w.contact.creep = CreepCoefficients{};
  w.contact.hertz = HertzContactInput{};
  w.contact.hertz->wheel_load = 1.0;
  w.contact.hertz->wheel_transverse_radius = 1.0;
  v.wheelsets.push_back(w);
  // gravity 1; body 10 + bending 7 + floor height 1; element point 3, stage 2 + curve 4, hanger 2, rotational 3,
  // dampings 3, series damper 2; wheelset 4 + optional 3 + creep 4 + Hertz 5.
  EXPECT_EQ(input::vehicle_numbers(&v).size(), 1u + 18u + 19u + 16u);
  // Each number is a distinct place.
  const std::vector<double*> numbers = input::vehicle_numbers(&v);
  EXPECT_EQ(std::set<double*>(numbers.begin(), numbers.end()).size(), numbers.size());
  const std::string shape = input::vehicle_shape(v);
  v.elements.front().vertical_stages.front().count = 2;
  EXPECT_NE(input::vehicle_shape(v), shape);
}

}  // namespace
}  // namespace railmodal::test
