// [nonlinear_hunting]: the ramp-down of the nonlinear critical speed (docs/stability.md, "The
// nonlinear critical speed"); each effect is a sub-table, and only the effects the file names
// are simulated.
#include "input/nonlinear_hunting_reader.hpp"

#include <cmath>
#include <string>

namespace railmodal::input {
namespace {

// The one saturation law implemented; the file names it, so that what was simulated is stated
// where the inputs are (and a file written for another law is refused, not run with this one).
constexpr const char* kSaturationLaw = "shen_hedrick_elkins";

void read_creep_saturation(TableReader t, NonlinearHuntingOptions* o) {
  const std::string law = t.string("law");
  if (law != kSaturationLaw)
    t.fail("law", "unknown creep-saturation law '" + law +
                      "': the one implemented is \"shen_hedrick_elkins\" (Shen, Hedrick and Elkins 1983: Kalker's "
                      "linear forces saturated by Johnson and Vermeulen's cubic)");
  o->friction_coefficient = t.positive("friction_coefficient", Quantity::dimensionless);
  if (!(o->friction_coefficient < 2.0))
    t.fail("friction_coefficient", "is a friction coefficient μ of wheel on rail, above 0 and below 2 (dry rail "
                                   "about 0.3-0.5)");
  o->wheel_load = t.optional_positive("wheel_load", Quantity::force);
  if (t.has("contact_angle")) {
    o->contact_angle = t.positive("contact_angle", Quantity::angle, true);
    if (!(o->contact_angle < 1.0)) t.fail("contact_angle", "must be below 1 rad (57 deg)");
  }
  t.finish();
}

void read_flange_contact(TableReader t, NonlinearHuntingOptions* o) {
  o->flange_clearance = t.positive("clearance", Quantity::length, true);
  o->flange_stiffness = t.positive("stiffness", Quantity::stiffness);
  t.finish();
}

}  // namespace

NonlinearHuntingOptions read_nonlinear_hunting(TableReader t) {
  NonlinearHuntingOptions o;
  o.effects.clear();
  o.start_speed = t.positive("start_speed", Quantity::speed);
  o.end_speed = t.positive("end_speed", Quantity::speed);
  if (!(o.end_speed < o.start_speed)) t.fail("end_speed", "must be below start_speed: the speed ramps down");
  o.ramp_rate = t.positive("ramp_rate", Quantity::acceleration);
  o.disturbance = t.quantity("disturbance", Quantity::length);
  if (!(o.disturbance != 0.0)) t.fail("disturbance", "must not be zero: a centred wheelset never starts to hunt");
  if (t.has("tolerance")) o.tolerance = t.positive("tolerance", Quantity::speed);
  if (t.has("hold_periods")) {
    o.hold_periods = t.count("hold_periods", 0);
    if (o.hold_periods != 0 && (o.hold_periods < 10 || o.hold_periods > 100000))
      t.fail("hold_periods", "must be 0 (no confirmation by holding the speed) or from 10 to 100000");
  }
  if (t.has("hold_margin")) o.hold_margin = t.positive("hold_margin", Quantity::speed);
  if (t.has("extinction_amplitude")) o.extinction_amplitude = t.positive("extinction_amplitude", Quantity::length);
  if (t.has("amplitude_bound")) {
    o.amplitude_bound = t.positive("amplitude_bound", Quantity::length);
    if (!(o.amplitude_bound > o.extinction_amplitude))
      t.fail("amplitude_bound", "must be above extinction_amplitude (default 0.1 mm)");
  }
  if (t.has("creep_saturation")) {
    read_creep_saturation(t.table("creep_saturation"), &o);
    o.effects.push_back(NonlinearEffect::creep_saturation);
  }
  if (t.has("flange_contact")) {
    read_flange_contact(t.table("flange_contact"), &o);
    o.effects.push_back(NonlinearEffect::flange_contact);
  }
  // Every rule is checked above at its key; this catches one added to the options later.
  if (std::string why; !o.is_valid(&why)) t.fail("start_speed", why);
  t.finish();
  return o;
}

}  // namespace railmodal::input
