// Ride scenes: the irregularity source and the [ride] table load with every convention
// applied (units, bands, sidedness), and bad ones name file, line and key.
#include <gtest/gtest.h>

#include <cmath>
#include <iomanip>
#include <sstream>

#include "input/speed_text.hpp"
#include "test_support.hpp"

namespace railmodal::test {
namespace {

const std::string kRideScene = R"([scene]
name = "ride scene"
vehicle = "ride_wagon.toml"
dofs = "vertical"
[[source]]
kind = "irregularity"
[source.vertical_level]
spectrum = "ore-b176"
level = "low"
wavelengths = ["3 m", "100 m"]
[source.cross_level]
spectrum = "fra"
class = 4
[ride]
speeds = "100 km/h:200 km/h:25 km/h"
max_frequency = "40 Hz"
points_per_decade = 50
)";

std::string write_ride_scene(const std::string& text) {
  write_temp("ride_wagon.toml", R"([vehicle]
name = "w"
template = "two-axle"
[body]
weight = "20000 kgf"
cg_height = "100 cm"
radius_of_gyration = { roll = "110 cm", pitch = "260 cm" }
[suspension]
wheelbase = "400 cm"
spring_spacing = "200 cm"
spring = { kind = "coil", stiffness = "1000 kgf/cm" }
)");
  return write_temp("ride_scene.toml", text);
}

// Replaces `from` in the good scene by `to` and expects an InputError holding every part.
void expect_ride_error(const std::string& from, const std::string& to, const std::vector<std::string>& parts) {
  std::string text = kRideScene;
  const auto at = text.find(from);
  ASSERT_NE(at, std::string::npos) << from;
  text.replace(at, from.size(), to);
  try {
    load_scene(write_ride_scene(text));
    FAIL() << "no error for " << to;
  } catch (const InputError& e) {
    for (const auto& part : parts) EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
  }
}

TEST(RideScene, IrregularityAndRideLoad) {
  const Scene s = load_scene(write_ride_scene(kRideScene));
  ASSERT_TRUE(s.irregularity);
  ASSERT_TRUE(s.irregularity->vertical_level);
  EXPECT_FALSE(s.irregularity->alignment);
  ASSERT_TRUE(s.irregularity->cross_level);
  EXPECT_TRUE(s.sources.empty());  // random track is not a periodic source
  // The band from the wavelengths, in either order: Ω = 2π/λ.
  EXPECT_NEAR(s.irregularity->vertical_level->band().low, 2 * kPi / 100, 1e-15);
  EXPECT_NEAR(s.irregularity->vertical_level->band().high, 2 * kPi / 3, 1e-15);
  // FRA without a band takes its own, 1.524 … 304.8 m.
  EXPECT_NEAR(s.irregularity->cross_level->band().low, 2 * kPi / 304.8, 1e-12);
  EXPECT_EQ(s.irregularity->cross_level->name(), TrackSpectrum::fra_class(4, TrackIrregularity::cross_level).name());
  ASSERT_TRUE(s.ride);
  // 100 … 200 km/h every 25 km/h: five speeds, both ends exact.
  ASSERT_EQ(s.ride->options.speeds.size(), 5u);
  EXPECT_DOUBLE_EQ(s.ride->options.speeds.front(), 100 / 3.6);
  EXPECT_DOUBLE_EQ(s.ride->options.speeds.back(), 200 / 3.6);
  EXPECT_DOUBLE_EQ(s.ride->options.max_frequency, 40.0);
  EXPECT_EQ(s.ride->options.points_per_decade, 50);
  EXPECT_DOUBLE_EQ(s.ride->options.min_frequency, RideOptions{}.min_frequency);  // the default kept
  EXPECT_TRUE(s.ride->outputs.empty());  // default_ride_outputs at run time
  EXPECT_FALSE(s.ride->simulation);
  EXPECT_EQ(s.max_speed, 0.0);  // no [speed] range needed
}

TEST(RideScene, SpeedsAsAList) {
  std::string text = kRideScene;
  text.replace(text.find("\"100 km/h:200 km/h:25 km/h\""), 27, "[\"160 km/h\", \"30 m/s\"]");
  const Scene s = load_scene(write_ride_scene(text));
  ASSERT_EQ(s.ride->options.speeds.size(), 2u);
  EXPECT_DOUBLE_EQ(s.ride->options.speeds[0], 160 / 3.6);
  EXPECT_DOUBLE_EQ(s.ride->options.speeds[1], 30.0);
}

// A user table per cycle/m against wavelength in mm²: the same variance whichever way it is
// written (per rad/m against wavenumber in m², two-sided halves); the table's variance is
// integrated exactly, so the three agree to round-off.
// A number as TOML reads it back exactly (17 significant digits).
std::string exact(double v) {
  std::ostringstream s;
  s << std::setprecision(17) << v;
  return s.str();
}

TEST(RideScene, UserTableConventions) {
  auto variance_of = [](const std::string& table) {
    std::string text = kRideScene;
    const std::string from = "[source.cross_level]\nspectrum = \"fra\"\nclass = 4\n";
    text.replace(text.find(from), from.size(), "[source.alignment]\nspectrum = \"table\"\n" + table);
    const Scene s = load_scene(write_ride_scene(text));
    EXPECT_EQ(s.irregularity->alignment->irregularity(), TrackIrregularity::alignment);
    return s.irregularity->alignment->variance();
  };
  // S_n = 2e-6 m²/(cycle/m) at λ = 50 m, 1e-8 at λ = 2 m.
  const double per_cycle = variance_of(
      "abscissa = \"wavelength\"\nabscissa_unit = \"m\"\ndensity_unit = \"mm^2/(cycle/m)\"\n"
      "points = [[50, 2.0], [2, 0.01]]\n");
  // The same as S(Ω) = S_n/2π against Ω = 2π/λ, in m²/(rad/m).
  const double per_rad = variance_of(
      "abscissa = \"wavenumber\"\nabscissa_unit = \"rad/m\"\ndensity_unit = \"m^2/(rad/m)\"\npoints = [[" +
      exact(2 * kPi / 50) + ", " + exact(2e-6 / (2 * kPi)) + "], [" + exact(2 * kPi / 2) + ", " +
      exact(1e-8 / (2 * kPi)) + "]]\n");
  // Two-sided per cycle/m against spatial frequency: half the one-sided density.
  const double two_sided = variance_of(
      "abscissa = \"spatial-frequency\"\nabscissa_unit = \"cycle/m\"\ndensity_unit = \"m^2/(cycle/m)\"\nsides = 2\n"
      "points = [[0.02, 1e-6], [0.5, 0.5e-8]]\n");
  // The same numbers through different unit conversions: equal to round-off.
  EXPECT_NEAR(per_rad / per_cycle, 1.0, 1e-12);
  EXPECT_NEAR(two_sided / per_cycle, 1.0, 1e-12);
  // The variance itself: on log–log the density is S_n = 2e-6 (n/0.02)^β with β = ln(0.005)/ln(25);
  // ∫ from 0.02 to 0.5 cycle/m.
  const double beta = std::log(0.005) / std::log(25.0);
  const double exact = 2e-6 * 0.02 / (beta + 1) * (std::pow(25.0, beta + 1) - 1);
  EXPECT_NEAR(per_cycle / exact, 1.0, 1e-12);
}

TEST(RideScene, Outputs) {
  const Scene s = load_scene(write_ride_scene(kRideScene + R"(
[[ride.output]]
body = "body"
point = ["2 m", "0 m", "1.2 m"]
[[ride.output]]
name = "spring force"
kind = "element-force"
element = "spring 1"
axis = "vertical"
)"));
  ASSERT_EQ(s.ride->outputs.size(), 2u);
  EXPECT_EQ(s.ride->outputs[0].kind, RideOutput::Kind::point);
  EXPECT_EQ(s.ride->outputs[0].quantity, ResponseQuantity::acceleration);  // the default
  EXPECT_EQ(s.ride->outputs[0].name, "body (2, 0, 1.2) m, acceleration, vertical");
  EXPECT_DOUBLE_EQ(s.ride->outputs[0].point.z(), 1.2);
  EXPECT_EQ(s.ride->outputs[1].kind, RideOutput::Kind::element_force);
  EXPECT_EQ(s.ride->outputs[1].element, "spring 1");
  EXPECT_TRUE(s.name_places.count("ride.output[0].body"));
  EXPECT_TRUE(s.name_places.count("ride.output[1].element"));
}

// The scene vocabulary is in underscores (docs/input.md, "Names and units in outputs"); the
// hyphenated words of files written before 2026-11-27 read the same.
TEST(RideScene, UnderscoredWordsAndTheirHyphenatedAliasesReadTheSame) {
  const auto scene_with = [](const std::string& ore, const std::string& abscissa, const std::string& kind) {
    std::string text = kRideScene;
    text.replace(text.find("\"ore-b176\""), 10, "\"" + ore + "\"");
    const std::string fra = "[source.cross_level]\nspectrum = \"fra\"\nclass = 4\n";
    text.replace(text.find(fra), fra.size(),
                 "[source.alignment]\nspectrum = \"table\"\nabscissa = \"" + abscissa +
                     "\"\nabscissa_unit = \"cycle/m\"\ndensity_unit = \"m^2/(cycle/m)\"\n"
                     "points = [[0.02, 1e-6], [0.5, 0.5e-8]]\n");
    return load_scene(write_ride_scene(text + "[[ride.output]]\nkind = \"" + kind +
                                       "\"\nelement = \"spring 1\"\naxis = \"vertical\"\n"));
  };
  const Scene now = scene_with("ore_b176", "spatial_frequency", "element_force");
  const Scene before = scene_with("ore-b176", "spatial-frequency", "element-force");
  for (const Scene* s : {&now, &before}) {
    ASSERT_TRUE(s->irregularity && s->irregularity->vertical_level && s->irregularity->alignment);
    ASSERT_EQ(s->ride->outputs.size(), 1u);
    EXPECT_EQ(s->ride->outputs[0].kind, RideOutput::Kind::element_force);
  }
  EXPECT_EQ(now.irregularity->vertical_level->name(), before.irregularity->vertical_level->name());
  EXPECT_EQ(now.irregularity->vertical_level->variance(), before.irregularity->vertical_level->variance());
  EXPECT_EQ(now.irregularity->alignment->variance(), before.irregularity->alignment->variance());
  // The words as written back: underscores.
  EXPECT_STREQ(to_string(RideOutput::Kind::wheel_rail_force), "wheel_rail_force");
  EXPECT_STREQ(to_string(TrackIrregularity::cross_level), "cross_level");
  EXPECT_STREQ(to_string(SpectrumAbscissa::spatial_frequency), "spatial_frequency");
  for (const char* old : {"vertical-level", "cross-level"}) EXPECT_TRUE(track_irregularity_from_string(old)) << old;
  for (const char* old : {"element-deflection", "element-force", "wheel-rail-force"})
    EXPECT_TRUE(ride_output_kind_from_string(old)) << old;
}

// A point acceleration's frame: body (an accelerometer on the floor, with g·φ) unless the
// output says track; any other word is refused naming both.
TEST(RideScene, OutputFrame) {
  const Scene s = load_scene(write_ride_scene(kRideScene + R"(
[[ride.output]]
body = "body"
point = ["2 m", "0 m", "1.2 m"]
axis = "lateral"
[[ride.output]]
name = "inertial"
body = "body"
point = ["2 m", "0 m", "1.2 m"]
axis = "lateral"
frame = "track"
)"));
  ASSERT_EQ(s.ride->outputs.size(), 2u);
  EXPECT_EQ(s.ride->outputs[0].frame, RideOutput::Frame::body);
  EXPECT_EQ(s.ride->outputs[1].frame, RideOutput::Frame::track);
  expect_ride_error("points_per_decade = 50",
                    "points_per_decade = 50\n[[ride.output]]\nbody = \"body\"\npoint = [\"0 m\", \"0 m\", \"0 m\"]\n"
                    "frame = \"inertial\"",
                    {"ride.output[0].frame", "body", "track", "'inertial'"});
}

TEST(RideScene, TimeDomainRun) {
  const Scene s = load_scene(write_ride_scene(kRideScene + R"(
[ride.realisation]
length = "4096 m"
step = "0.25 m"
seed = 7
[ride.simulation]
speed = "160 km/h"
time_step = "2 ms"
settle_time = "10 s"
effects = ["leaf_friction"]
)"));
  ASSERT_TRUE(s.ride->realisation);
  EXPECT_DOUBLE_EQ(s.ride->realisation->length, 4096.0);
  EXPECT_EQ(s.ride->realisation->seed, 7u);
  ASSERT_TRUE(s.ride->simulation);
  EXPECT_DOUBLE_EQ(s.ride->simulation->speed, 160 / 3.6);
  EXPECT_DOUBLE_EQ(s.ride->simulation->time_step, 0.002);
  EXPECT_DOUBLE_EQ(s.ride->simulation->settle_time, 10.0);
  EXPECT_TRUE(s.ride->simulation->effects.leaf_friction);
  EXPECT_FALSE(s.ride->simulation->effects.progressive_springs);
}

// What [ride] says of the track and the indices holds for the time-domain run too: the contact
// half spacing (cross-level to roll) and the averaging window, unless the run gives its own;
// without a time_step the run takes simulate_ride's default (0).
TEST(RideScene, TheRunTakesTheRideTablesContactHalfSpacingAndWindow) {
  std::string text = kRideScene + R"(contact_half_spacing = "0.8 m"
percentile_window = "4 s"
[ride.realisation]
length = "4096 m"
step = "0.25 m"
[ride.simulation]
speed = "160 km/h"
)";
  const Scene s = load_scene(write_ride_scene(text));
  ASSERT_TRUE(s.ride && s.ride->simulation);
  EXPECT_DOUBLE_EQ(s.ride->options.contact_half_spacing, 0.8);
  EXPECT_DOUBLE_EQ(s.ride->simulation->contact_half_spacing, 0.8);
  EXPECT_DOUBLE_EQ(s.ride->simulation->window, 4.0);
  EXPECT_EQ(s.ride->simulation->time_step, 0.0);
  text += "window = \"5 s\"\n";
  EXPECT_DOUBLE_EQ(load_scene(write_ride_scene(text)).ride->simulation->window, 5.0);
  // without them in [ride], the defaults of both: from the wheelsets (0) and EN 12299's 5 s
  const Scene plain = load_scene(write_ride_scene(kRideScene + R"([ride.realisation]
length = "4096 m"
step = "0.25 m"
[ride.simulation]
speed = "160 km/h"
)"));
  EXPECT_EQ(plain.ride->simulation->contact_half_spacing, 0.0);
  EXPECT_DOUBLE_EQ(plain.ride->simulation->window, 5.0);
}

TEST(RideScene, MeasuredGeometryResolvedAgainstTheScene) {
  write_temp("ride_track.csv", "distance [m],vertical level [mm]\n0,0\n0.25,1\n");
  const Scene s = load_scene(write_ride_scene(std::string(kRideScene).replace(
      kRideScene.find("[source.vertical_level]"), 0, "geometry = \"ride_track.csv\"\n") + R"(
[ride.simulation]
speed = "160 km/h"
time_step = "2 ms"
)"));
  ASSERT_TRUE(s.ride);
  EXPECT_NE(s.ride->geometry_file.find("ride_track.csv"), std::string::npos);
  EXPECT_TRUE(std::filesystem::path(s.ride->geometry_file).is_absolute() ||
              s.ride->geometry_file.find('/') != std::string::npos);
}

TEST(RideScene, Errors) {
  expect_ride_error("level = \"low\"", "level = \"medium\"", {"ride_scene.toml:", "source[0].vertical_level.level", "low"});
  expect_ride_error("wavelengths = [\"3 m\", \"100 m\"]", "", {"source[0].vertical_level.wavelengths", "no band"});
  expect_ride_error("wavelengths = [\"3 m\", \"100 m\"]", "wavelengths = [\"3 m\"]",
                    {"wavelengths", "two wavelengths"});
  expect_ride_error("wavelengths = [\"3 m\", \"100 m\"]", "wavelengths = [\"3 kg\", \"100 m\"]",
                    {"wavelengths", "expected a length"});
  expect_ride_error("class = 4", "class = 7", {"source[0].cross_level.class", "1 to 6"});
  expect_ride_error("spectrum = \"fra\"", "spectrum = \"pink\"", {"cross_level.spectrum", "unknown spectrum 'pink'"});
  expect_ride_error("[source.cross_level]", "[source.crosslevel]", {"crosslevel", "unknown key"});
  expect_ride_error("level = \"low\"", "level = \"low\"\nA = 1", {"vertical_level.A", "unknown key"});
  expect_ride_error("speeds = \"100 km/h:200 km/h:25 km/h\"", "speeds = \"200 km/h:100 km/h\"",
                    {"ride.speeds", "MAX must be above its MIN"});
  expect_ride_error("speeds = \"100 km/h:200 km/h:25 km/h\"", "speeds = \"100 km/h, 0 km/h\"",
                    {"ride.speeds", "above zero"});
  expect_ride_error("max_frequency = \"40 Hz\"", "max_frequency = \"40 s\"", {"ride.max_frequency", "a frequency"});
  expect_ride_error("max_frequency = \"40 Hz\"", "max_frequency = \"0.05 Hz\"", {"max_frequency", "above min_frequency"});
  expect_ride_error("points_per_decade = 50", "points_per_decade = 5", {"points_per_decade", "from 10"});
  expect_ride_error("points_per_decade = 50", "points_per_decade = 50\nsped = 3", {"ride.sped", "unknown key"});
  expect_ride_error("[ride]", "[ride.simulation]\nspeed = \"100 km/h\"\ntime_step = \"1 ms\"\n[ride]",
                    {"ride.simulation", "needs a track"});
}

TEST(RideScene, TableErrors) {
  auto expect_table_error = [](const std::string& table, const std::vector<std::string>& parts) {
    std::string text = kRideScene;
    const std::string from = "[source.cross_level]\nspectrum = \"fra\"\nclass = 4\n";
    text.replace(text.find(from), from.size(), "[source.alignment]\nspectrum = \"table\"\n" + table);
    try {
      load_scene(write_ride_scene(text));
      FAIL() << "no error for " << table;
    } catch (const InputError& e) {
      for (const auto& part : parts) EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
    }
  };
  const std::string units = "abscissa_unit = \"m\"\ndensity_unit = \"m^2/(cycle/m)\"\n";
  expect_table_error("abscissa = \"period\"\n" + units + "points = [[1, 1], [2, 1]]\n",
                     {"alignment.abscissa", "wavenumber, spatial_frequency or wavelength"});
  expect_table_error("abscissa = \"wavenumber\"\n" + units + "points = [[1, 1], [2, 1]]\n",
                     {"alignment.abscissa_unit", "rad/m"});
  expect_table_error("abscissa = \"wavelength\"\nabscissa_unit = \"m\"\ndensity_unit = \"m^2/Hz\"\n"
                     "points = [[1, 1], [2, 1]]\n",
                     {"alignment.density_unit", "per rad/m or per cycle/m"});
  expect_table_error("abscissa = \"wavelength\"\n" + units + "points = [[1, 1]]\n", {"alignment.points", "at least two"});
  expect_table_error("abscissa = \"wavelength\"\n" + units + "points = [[1, 1], [2, \"x\"]]\n",
                     {"alignment.points", "pair of numbers"});
  expect_table_error("abscissa = \"wavelength\"\n" + units + "points = [[1, 1], [2, -1]]\n", {"alignment.points"});
  expect_table_error("abscissa = \"wavelength\"\n" + units + "sides = 3\npoints = [[1, 1], [2, 1]]\n",
                     {"alignment.sides", "two-sided"});
}

TEST(RideScene, ParseSpeeds) {
  EXPECT_EQ(parse_speeds("10 m/s").size(), 1u);
  EXPECT_EQ(parse_speeds("100 km/h:200 km/h").size(), 11u);  // MIN:MAX alone: ten intervals
  // A step that does not divide the range: the spacing is at most the step, both ends kept.
  const std::vector<double> v = parse_speeds("100 km/h:200 km/h:30 km/h");
  ASSERT_EQ(v.size(), 5u);
  EXPECT_DOUBLE_EQ(v.back(), 200 / 3.6);
  EXPECT_LE(v[1] - v[0], 30 / 3.6);
  EXPECT_THROW(parse_speeds("100 km/h:200 km/h:1 km/h:5"), std::invalid_argument);
  EXPECT_THROW(parse_speeds("100 km/h, 120 km/h:200 km/h"), std::invalid_argument);
  EXPECT_THROW(parse_speeds("100 km/h,,120 km/h"), std::invalid_argument);
  EXPECT_THROW(parse_speeds("1 m/s:1000 m/s:0.01 m/s"), std::invalid_argument);  // 10⁵ speeds
  EXPECT_THROW(parse_speeds(""), std::invalid_argument);
}

// A speed given twice, to the 15 significant digits the reports print in km/h, is refused alike
// in a list on the command line and in a [ride] table's array or string; 16 digits apart are
// two speeds.
TEST(RideScene, ASpeedGivenTwiceIsRefusedWhereverItIsWritten) {
  EXPECT_TRUE(input::has_repeated_speed({100 / 3.6, 120 / 3.6, 100 / 3.6}));
  EXPECT_TRUE(input::has_repeated_speed({27.7777777777778, 100 / 3.6}));  // 100 km/h to 15 digits
  EXPECT_FALSE(input::has_repeated_speed({27.77777777777, 100 / 3.6}));
  EXPECT_FALSE(input::has_repeated_speed({10.0}));
  EXPECT_FALSE(input::has_repeated_speed({}));
  EXPECT_THROW(parse_speeds("100 km/h, 120 km/h, 27.7777777777778 m/s"), std::invalid_argument);
  EXPECT_NO_THROW(parse_speeds("100 km/h, 120 km/h, 27.77777777777 m/s"));
  expect_ride_error("speeds = \"100 km/h:200 km/h:25 km/h\"", "speeds = [\"100 km/h\", \"120 km/h\", \"100 km/h\"]",
                    {"speeds", "given twice"});
  expect_ride_error("speeds = \"100 km/h:200 km/h:25 km/h\"", "speeds = \"100 km/h, 120 km/h, 100 km/h\"",
                    {"speeds", "given twice"});
}

}  // namespace
}  // namespace railmodal::test
