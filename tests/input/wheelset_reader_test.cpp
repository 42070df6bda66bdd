// Wheelsets and series dampers in vehicle files: the general form's [[wheelset]], the templates'
// [wheelset], element series_dampers and the bogie's yaw_damper; defaults, and every error at
// its file, line and key.
#include <gtest/gtest.h>

#include <algorithm>

#include "test_support.hpp"

namespace railmodal::test {
namespace {

const std::string kGeneral = R"([vehicle]
name = "wheelset on springs"
[[body]]
name = "ws"
mass = "1813 kg"
inertia = { roll = "1120 kg*m^2", yaw = "1120 kg*m^2" }
centre_of_gravity = ["0 m", "0 m", "0 m"]
[[wheelset]]
body = "ws"
spin_inertia = "113 kg*m^2"
rolling_radius = "460 mm"
contact_half_spacing = "0.75 m"
conicity = 0.15
creep = { f11 = "10 MN", f22 = "9 MN", f23 = "2 kN*m", f33 = "300 N*m^2" }
[[element]]
name = "left"
upper = "ws"
point = ["0 m", "1 m", "0 m"]
lateral = { stiffness = "3884 kN/m" }
longitudinal = { stiffness = "31391 kN/m" }
series_dampers = [{ direction = "longitudinal", damping = "50 kN*s/m", stiffness = "5 MN/m" }]
)";

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

// Expects an InputError containing each of `parts` for the file `text`.
void expect_error(const std::string& text, const std::vector<std::string>& parts) {
  const std::string path = write_temp("bad_wheelset.toml", text);
  try {
    load_vehicle(path);
    FAIL() << "no error for\n" << text;
  } catch (const InputError& e) {
    for (const auto& part : parts) EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
  }
}

bool holds(const Body& b, Motion m) { return std::find(b.held.begin(), b.held.end(), m) != b.held.end(); }

TEST(WheelsetReader, GeneralFormReadsEveryKeyInSI) {
  const Vehicle v = load_vehicle(write_temp("ws.toml", kGeneral));
  ASSERT_EQ(v.wheelsets.size(), 1u);
  const Wheelset& w = v.wheelsets[0];
  EXPECT_EQ(w.body, "ws");
  EXPECT_DOUBLE_EQ(w.spin_inertia, 113.0);
  EXPECT_DOUBLE_EQ(w.contact.rolling_radius, 0.46);
  EXPECT_DOUBLE_EQ(w.contact.contact_half_spacing, 0.75);
  EXPECT_DOUBLE_EQ(w.contact.conicity, 0.15);
  EXPECT_FALSE(w.contact.contact_angle_parameter);  // defaults are the contact's (knife-edge rails)
  EXPECT_FALSE(w.contact.roll_parameter);
  ASSERT_TRUE(w.contact.creep);
  EXPECT_FALSE(w.contact.hertz);
  EXPECT_DOUBLE_EQ(w.contact.creep->f11, 10e6);
  EXPECT_DOUBLE_EQ(w.contact.creep->f22, 9e6);
  EXPECT_DOUBLE_EQ(w.contact.creep->f23, 2e3);
  EXPECT_DOUBLE_EQ(w.contact.creep->f33, 300.0);
  // Bounce, roll and pitch follow the rails; lateral and yaw stay free; surge stays held.
  const Body& b = v.bodies[0];
  for (Motion m : {Motion::bounce, Motion::roll, Motion::pitch}) EXPECT_TRUE(holds(b, m)) << to_string(m);
  for (Motion m : {Motion::lateral, Motion::yaw}) EXPECT_FALSE(holds(b, m)) << to_string(m);
  EXPECT_FALSE(b.longitudinal_free);
  ASSERT_EQ(v.elements[0].series_dampers.size(), 1u);
  const SeriesDamper& d = v.elements[0].series_dampers[0];
  EXPECT_EQ(d.direction, Motion::longitudinal);
  EXPECT_DOUBLE_EQ(d.damping, 5e4);
  EXPECT_DOUBLE_EQ(d.stiffness, 5e6);
}

TEST(WheelsetReader, OptionalContactParametersAndHertzDefaults) {
  std::string text = replaced(kGeneral, "conicity = 0.15\n",
                              "conicity = 0.15\ncontact_angle_parameter = 0.2\nroll_parameter = -0.05\n");
  text = replaced(text, R"(creep = { f11 = "10 MN", f22 = "9 MN", f23 = "2 kN*m", f33 = "300 N*m^2" })",
                  R"(hertz = { rail_head_radius = "300 mm", wheel_transverse_radius = "-0.5 m" })");
  const Vehicle v = load_vehicle(write_temp("ws_hertz.toml", text));
  const WheelRailContact& c = v.wheelsets[0].contact;
  EXPECT_DOUBLE_EQ(*c.contact_angle_parameter, 0.2);
  EXPECT_DOUBLE_EQ(*c.roll_parameter, -0.05);
  ASSERT_TRUE(c.hertz);
  EXPECT_FALSE(c.creep);
  EXPECT_DOUBLE_EQ(c.hertz->rail_head_radius, 0.3);
  EXPECT_DOUBLE_EQ(*c.hertz->wheel_transverse_radius, -0.5);  // signed: a hollow tread
  EXPECT_FALSE(c.hertz->wheel_load);                          // from the static axle load
  EXPECT_DOUBLE_EQ(c.hertz->youngs_modulus, 2.1e11);
  EXPECT_DOUBLE_EQ(c.hertz->poisson_ratio, 0.28);
}

// f23 and f33 may be left out (zero: the spin terms are often omitted); axle_load is optional
// and read in SI (issue 20 review: W fell back silently to the wheelset's own weight).
TEST(WheelsetReader, SpinCoefficientsDefaultToZeroAndAxleLoadIsRead) {
  std::string text = replaced(kGeneral, R"(creep = { f11 = "10 MN", f22 = "9 MN", f23 = "2 kN*m", f33 = "300 N*m^2" })",
                              "axle_load = \"100 kN\"\ncreep = { f11 = \"10 MN\", f22 = \"9 MN\" }");
  const Vehicle v = load_vehicle(write_temp("ws_no_spin.toml", text));
  const WheelRailContact& c = v.wheelsets[0].contact;
  ASSERT_TRUE(c.creep);
  EXPECT_EQ(c.creep->f23, 0.0);
  EXPECT_EQ(c.creep->f33, 0.0);
  ASSERT_TRUE(c.axle_load);
  EXPECT_DOUBLE_EQ(*c.axle_load, 1.0e5);
  EXPECT_FALSE(load_vehicle(write_temp("ws.toml", kGeneral)).wheelsets[0].contact.axle_load);
  expect_error(replaced(text, "axle_load = \"100 kN\"", "axle_load = \"100 kN*m\""),
               {"key 'wheelset[0].axle_load'", "expected a force"});
}

TEST(WheelsetReader, CreepOrHertzExactlyOne) {
  expect_error(replaced(kGeneral, R"(creep = { f11 = "10 MN", f22 = "9 MN", f23 = "2 kN*m", f33 = "300 N*m^2" })", ""),
               {"key 'wheelset[0].creep': missing"});
  expect_error(replaced(kGeneral, "conicity = 0.15\n", "conicity = 0.15\nhertz = { rail_head_radius = \"0.3 m\" }\n"),
               {"bad_wheelset.toml:15:", "key 'wheelset[0].creep': give creep or hertz, not both"});
}

TEST(WheelsetReader, ContactKeyErrors) {
  expect_error(replaced(kGeneral, "rolling_radius = \"460 mm\"", "rolling_radius = \"0 mm\""),
               {"bad_wheelset.toml:11:", "key 'wheelset[0].rolling_radius': must be positive"});
  expect_error(replaced(kGeneral, "conicity = 0.15", "conicity = -0.1"),
               {"key 'wheelset[0].conicity': must be zero or positive"});
  // One rule with contact_matrices and the stability command's conicities: 0 ≤ λ < 1.
  expect_error(replaced(kGeneral, "conicity = 0.15", "conicity = 1.5"),
               {"bad_wheelset.toml:13:", "key 'wheelset[0].conicity': must be below 1"});
  expect_error(replaced(kGeneral, "f23 = \"2 kN*m\"", "f23 = \"2 kN\""),
               {"key 'wheelset[0].creep.f23'", "expected a moment (force·length)"});
  expect_error(replaced(kGeneral, "f33 = \"300 N*m^2\"", "f33 = \"300 N*m\""),
               {"key 'wheelset[0].creep.f33'", "expected a force·length²"});
  expect_error(replaced(kGeneral, "f11 = \"10 MN\"", "f11 = \"10 MN\", f12 = 3"),
               {"key 'wheelset[0].creep.f12': unknown key"});
  expect_error(replaced(kGeneral, "spin_inertia = \"113 kg*m^2\"\n", ""), {"key 'wheelset[0].spin_inertia': missing"});
  const std::string hertz =
      replaced(kGeneral, R"(creep = { f11 = "10 MN", f22 = "9 MN", f23 = "2 kN*m", f33 = "300 N*m^2" })", "hertz = {}");
  expect_error(hertz, {"key 'wheelset[0].hertz.rail_head_radius': missing"});
  expect_error(replaced(hertz, "hertz = {}", "hertz = { rail_head_radius = \"0.3 m\", poisson_ratio = 0.5 }"),
               {"key 'wheelset[0].hertz.poisson_ratio': must be below 0.5"});
  expect_error(replaced(hertz, "hertz = {}", "hertz = { rail_head_radius = \"0.3 m\", wheel_transverse_radius = 0 }"),
               {"key 'wheelset[0].hertz.wheel_transverse_radius': must not be zero"});
}

TEST(WheelsetReader, WheelsetBodyErrorsAtTheKeyThatCausesThem) {
  expect_error(replaced(kGeneral, "body = \"ws\"", "body = \"frame\""),
               {"bad_wheelset.toml:9:", "key 'wheelset[0].body': no body is named 'frame'"});
  expect_error(kGeneral + "[[wheelset]]\nbody = \"ws\"\n", {"key 'wheelset[1].body': body 'ws' is already a wheelset"});
  // The body's own keys that contradict a wheelset: where they are written.
  expect_error(replaced(kGeneral, "centre_of_gravity = [\"0 m\", \"0 m\", \"0 m\"]",
                        "centre_of_gravity = [\"0 m\", \"0 m\", \"0 m\"]\nheld = [\"yaw\"]"),
               {"bad_wheelset.toml:8:", "key 'body[0].held': holds the yaw motion of 'ws', a wheelset"});
  expect_error(replaced(kGeneral, "centre_of_gravity = [\"0 m\", \"0 m\", \"0 m\"]",
                        "centre_of_gravity = [\"0 m\", \"0 m\", \"0 m\"]\nfree = [\"longitudinal\"]"),
               {"bad_wheelset.toml:8:", "key 'body[0].free': frees the longitudinal motion of 'ws', a wheelset"});
  // The contact acts at the centre of gravity, the axle centre: off the track's centre line or the
  // axle plane it would change the answer silently; a zero yaw inertia would leave the mass matrix singular.
  for (const char* cg : {"[\"0 m\", \"0.1 m\", \"0 m\"]", "[\"0 m\", \"0 m\", \"0.2 m\"]"})
    expect_error(
        replaced(kGeneral, "centre_of_gravity = [\"0 m\", \"0 m\", \"0 m\"]", std::string("centre_of_gravity = ") + cg),
        {"bad_wheelset.toml:7:", "key 'body[0].centre_of_gravity': 'ws' is a wheelset",
         "(y = z = 0; only x may vary)"});
  expect_error(
      replaced(kGeneral, "centre_of_gravity = [\"0 m\", \"0 m\", \"0 m\"]",
               "centre_of_gravity = [\"0 m\", \"0 m\", \"0 m\"]\nreference_point = [\"0 m\", \"0 m\", \"0.5 m\"]"),
      {"bad_wheelset.toml:8:", "key 'body[0].reference_point': 'ws' is a wheelset"});
  expect_error(replaced(kGeneral, "yaw = \"1120 kg*m^2\"", "yaw = \"0 kg*m^2\""),
               {"bad_wheelset.toml:6:", "key 'body[0].inertia': 'ws' is a wheelset: its yaw inertia must be positive"});
  // A longitudinal offset is fine: the contact takes the lever (HuntingValidation tests it).
  EXPECT_NO_THROW(load_vehicle(write_temp(
      "ws_ahead.toml",
      replaced(kGeneral, "centre_of_gravity = [\"0 m\", \"0 m\", \"0 m\"]",
               "centre_of_gravity = [\"0 m\", \"0 m\", \"0 m\"]\nreference_point = [\"0.7 m\", \"0 m\", \"0 m\"]"))));
}

TEST(WheelsetReader, SeriesDamperErrors) {
  expect_error(replaced(kGeneral, "direction = \"longitudinal\"", "direction = \"yaw\""),
               {"bad_wheelset.toml:21:", "key 'element[0].series_dampers[0].direction': unknown direction 'yaw'"});
  expect_error(replaced(kGeneral, "damping = \"50 kN*s/m\"", "damping = \"0 kN*s/m\""),
               {"key 'element[0].series_dampers[0].damping': must be positive"});
  expect_error(replaced(kGeneral, ", stiffness = \"5 MN/m\"", ""),
               {"key 'element[0].series_dampers[0].stiffness': missing"});
}

TEST(WheelsetReader, VerticalSeriesDamperIsBounce) {
  const Vehicle v = load_vehicle(
      write_temp("ws_vertical.toml", replaced(kGeneral, "direction = \"longitudinal\"", "direction = \"vertical\"")));
  EXPECT_EQ(v.elements[0].series_dampers[0].direction, Motion::bounce);
}

// The bogie template with [wheelset]: a wheelset under each axle, numbered as the axles are,
// the axlebox springs standing on them at the axlebox points.
TEST(WheelsetReader, BogieTemplateMakesOneWheelsetPerAxle) {
  const Vehicle v = load_vehicle(data_file("manchester_benchmark_coach_wheelsets.toml"));
  ASSERT_EQ(v.wheelsets.size(), 4u);
  const double x[] = {9.5 + 1.28, 9.5 - 1.28, -9.5 + 1.28, -9.5 - 1.28};
  for (int k = 0; k < 4; ++k) {
    const std::string name = "wheelset" + std::to_string(k + 1);
    EXPECT_EQ(v.wheelsets[k].body, name);
    EXPECT_DOUBLE_EQ(v.wheelsets[k].spin_inertia, 113.0);
    ASSERT_TRUE(v.wheelsets[k].contact.hertz);
    EXPECT_DOUBLE_EQ(v.wheelsets[k].contact.hertz->rail_head_radius, 0.3);
    const auto body = std::find_if(v.bodies.begin(), v.bodies.end(), [&](const Body& b) { return b.name == name; });
    ASSERT_NE(body, v.bodies.end());
    EXPECT_DOUBLE_EQ(body->mass, 1813.0);
    EXPECT_DOUBLE_EQ(body->inertia(0), 1120.0);
    EXPECT_DOUBLE_EQ(body->inertia(1), 113.0);  // pitch is the spin
    EXPECT_DOUBLE_EQ(body->inertia(2), 1120.0);
    EXPECT_NEAR(body->reference_point.x(), x[k], 1e-12);
    int on_it = 0;
    for (const Element& e : v.elements)
      if (e.lower == name) {
        ++on_it;
        EXPECT_NEAR(e.point.x(), x[k], 1e-12) << e.name;
        EXPECT_DOUBLE_EQ(std::abs(e.point.y()), 1.0) << e.name;
        EXPECT_FALSE(e.longitudinal_stages.empty()) << e.name;  // the wheelset's yaw stiffness
      }
    EXPECT_EQ(on_it, 2) << name;
  }
  // No element stands on the track any more.
  for (const Element& e : v.elements) EXPECT_FALSE(e.lower.empty()) << e.name;
}

const std::string kBogie = R"([vehicle]
name = "bogie coach"
template = "bogie"
suspension = "double"
[body]
mass = "32 t"
inertia = { roll = "56800 kg*m^2", pitch = "1970000 kg*m^2", yaw = "1970000 kg*m^2" }
cg_height = "1 m"
bogie_spacing = "19 m"
[bogie]
mass = "2615 kg"
inertia = { roll = "1722 kg*m^2", pitch = "1476 kg*m^2", yaw = "3067 kg*m^2" }
cg_height = "0.14 m"
wheelbase = "2.56 m"
bolster_height = "0.37 m"
[primary]
spacing = "2 m"
spring = { stiffness = "1220 kN/m" }
lateral = { stiffness = "3884 kN/m" }
longitudinal = { stiffness = "31391 kN/m" }
[secondary]
spacing = "2 m"
spring = { stiffness = "430 kN/m" }
lateral = { stiffness = "160 kN/m" }
yaw_damper = { damping = "400 kN*s/m", series_stiffness = "8 MN/m", spacing = "2.6 m" }
)";

TEST(WheelsetReader, BogieYawDamperEachSideBetweenBodyAndFrame) {
  const Vehicle v = load_vehicle(write_temp("yaw_damper.toml", kBogie));
  int count = 0;
  for (const Element& e : v.elements) {
    if (e.series_dampers.empty()) continue;
    ++count;
    EXPECT_EQ(e.upper, "body");
    EXPECT_TRUE(e.lower == "bogie1" || e.lower == "bogie2") << e.lower;
    EXPECT_DOUBLE_EQ(std::abs(e.point.y()), 1.3);
    EXPECT_DOUBLE_EQ(e.point.z(), 0.37);  // the bolster plane unless a height is given
    EXPECT_DOUBLE_EQ(std::abs(e.point.x()), 9.5);
    ASSERT_EQ(e.series_dampers.size(), 1u);
    EXPECT_EQ(e.series_dampers[0].direction, Motion::longitudinal);
    EXPECT_DOUBLE_EQ(e.series_dampers[0].damping, 4e5);
    EXPECT_DOUBLE_EQ(e.series_dampers[0].stiffness, 8e6);
    EXPECT_TRUE(e.vertical_stages.empty() && e.lateral_stages.empty() && e.longitudinal_stages.empty());
  }
  EXPECT_EQ(count, 4);
  const Vehicle high = load_vehicle(write_temp(
      "yaw_damper_high.toml", replaced(kBogie, "spacing = \"2.6 m\" }", "spacing = \"2.6 m\", height = \"0.5 m\" }")));
  for (const Element& e : high.elements) {
    if (!e.series_dampers.empty()) {
      EXPECT_DOUBLE_EQ(e.point.z(), 0.5);
    }
  }
}

TEST(WheelsetReader, TemplateErrors) {
  const std::string ws =
      "[wheelset]\nmass = \"1813 kg\"\ninertia = { roll = \"1120 kg*m^2\", yaw = \"1120 kg*m^2\" }\n"
      "spin_inertia = \"113 kg*m^2\"\nrolling_radius = \"0.46 m\"\ncontact_half_spacing = \"0.75 m\"\n"
      "conicity = 0.15\ncreep = { f11 = \"10 MN\", f22 = \"10 MN\", f23 = 0, f33 = 0 }\n";
  EXPECT_EQ(load_vehicle(write_temp("bogie_ws.toml", kBogie + ws)).wheelsets.size(), 4u);
  expect_error(kBogie + replaced(ws, "yaw = \"1120 kg*m^2\"", "pitch = \"113 kg*m^2\""),
               {"key 'wheelset.inertia.pitch': a wheelset's pitch is its spin about the axle"});
  expect_error(replaced(kBogie, "longitudinal = { stiffness = \"31391 kN/m\" }\n", "") + ws,
               {"key 'primary.longitudinal': missing: on wheelsets the bogie frame is guided"});
  expect_error(replaced(kBogie, "spacing = \"2.6 m\" }", "spacing = \"2.6 m\", length = \"1 m\" }"),
               {"key 'secondary.yaw_damper.length': unknown key"});
  expect_error(replaced(kBogie, "series_stiffness = \"8 MN/m\"", "series_stiffness = \"-8 MN/m\""),
               {"key 'secondary.yaw_damper.series_stiffness': must be positive"});
}

const std::string kTwoAxle = R"([vehicle]
name = "two-axle wagon"
template = "two-axle"
[body]
mass = "20 t"
inertia = { roll = "3e4 kg*m^2", pitch = "1.2e5 kg*m^2", yaw = "1.2e5 kg*m^2" }
cg_height = "1 m"
[suspension]
wheelbase = "4 m"
spring_spacing = "2 m"
spring = { stiffness = "900 kN/m" }
)";

TEST(WheelsetReader, TwoAxleTemplateOnWheelsets) {
  const std::string file =
      kTwoAxle +
      "lateral = { stiffness = \"2 MN/m\" }\nlongitudinal = { stiffness = \"20 MN/m\" }\n"
      "[wheelset]\nmass = \"1.2 t\"\ninertia = { roll = \"700 kg*m^2\", yaw = \"700 kg*m^2\" }\n"
      "spin_inertia = \"80 kg*m^2\"\nrolling_radius = \"0.45 m\"\n"
      "contact_half_spacing = \"0.75 m\"\nconicity = 0.2\nhertz = { rail_head_radius = \"0.3 m\" }\n";
  const Vehicle v = load_vehicle(write_temp("two_axle_ws.toml", file));
  ASSERT_EQ(v.wheelsets.size(), 2u);
  EXPECT_EQ(v.wheelsets[0].body, "wheelset1");  // front axle, x = +a1
  EXPECT_TRUE(v.bodies[0].held.empty());        // the springs guide the body now, not the track
  for (const Element& e : v.elements) {
    EXPECT_EQ(e.lower, e.point.x() > 0 ? "wheelset1" : "wheelset2") << e.name;
    EXPECT_FALSE(e.lateral_stages.empty());
    EXPECT_FALSE(e.longitudinal_stages.empty());
  }
  // Without [wheelset] the two-axle template takes no lateral springs: the track guides the body.
  expect_error(kTwoAxle + "lateral = { stiffness = \"2 MN/m\" }\n", {"key 'suspension.lateral': unknown key"});
  expect_error(kTwoAxle + file.substr(file.find("[wheelset]")),
               {"key 'suspension.lateral': missing: on wheelsets the body is guided"});
}

}  // namespace
}  // namespace railmodal::test
