// Balancing the driving gear (Zhdanov ch. III; docs/driving_gear.md, "Balancing"): counterweights
// for the rotating masses, the vertical counterweight, the overbalance, and their effect.
#include <algorithm>
#include <cmath>
#include <complex>
#include <stdexcept>

#include "gear/vertical_counterweight.hpp"
#include "gear/wheel_planes.hpp"
#include "railmodal/balance.hpp"
#include "require_valid.hpp"
#include "summary/stage_clock.hpp"

namespace railmodal {

namespace {

using Phasor = std::complex<double>;  // m·ρ·e^{iψ}, kg·m: ψ the angle from the reference crank at φ = 0

double wrapped(double angle) {
  const double a = std::fmod(angle, 2.0 * M_PI);
  return a < 0.0 ? a + 2.0 * M_PI : a;
}

GearWheel& wheel_of(DrivingGear& g, std::size_t w) { return w % 2 == 0 ? g.axles[w / 2].right : g.axles[w / 2].left; }
const GearWheel& wheel_of(const DrivingGear& g, std::size_t w) {
  return w % 2 == 0 ? g.axles[w / 2].right : g.axles[w / 2].left;
}

// Adds to the two wheel planes of an axle the shares of a phasor acting at `lateral`.
void add_to_planes(Phasor* planes, Phasor p, double lateral, double S) {
  const gear::PlaneShares shares = gear::wheel_plane_shares(lateral, S);
  planes[0] += shares.right * p;
  planes[1] += shares.left * p;
}

// The counterweight (mass on radius r, angle from the wheel's crank) that cancels phasor `u`.
RotatingMass cancelling(const std::string& name, Phasor u, const GearWheel& wheel, double r, bool overbalance) {
  return {name, std::abs(u) / r, r, wrapped(std::arg(-u) - wheel.crank_offset), 0.0, overbalance};
}

// Step 1 (eq. (53)–(68)): each wheel's rotating masses moved to the two wheel planes of their axle.
std::vector<Phasor> rotating_resultants(const DrivingGear& g) {
  std::vector<Phasor> out(2 * g.axles.size());
  for (std::size_t a = 0; a < g.axles.size(); ++a)
    for (int side = 0; side < 2; ++side) {
      const GearWheel& wheel = wheel_of(g, 2 * a + side);
      const double outward = side == 0 ? 1.0 : -1.0;
      for (const RotatingMass& m : wheel.masses)
        add_to_planes(&out[2 * a], std::polar(m.mass * m.radius, wheel.crank_offset + m.angle),
                      outward * (g.wheel_plane_half_spacing + m.plane_offset), g.wheel_plane_half_spacing);
    }
  return out;
}

// The rods' force on wheel w (upward or forward, N) with that wheel's crank at θ.
double rod_force_on_wheel(const DrivingGear& g, std::size_t w, double theta, double omega, bool vertical) {
  const double phi = theta - wheel_of(g, w).crank_offset;
  double sum = 0.0;
  for (const GearCylinder& c : g.cylinders) {
    if (static_cast<std::size_t>(c.axle) != w / 2) continue;
    const RodForces f = rod_forces(c, phi + c.crank_offset, omega);
    const gear::PlaneShares shares = gear::wheel_plane_shares(c.lateral, g.wheel_plane_half_spacing);
    sum += (w % 2 == 0 ? shares.right : shares.left) * (vertical ? f.vertical : f.horizontal);
  }
  return sum;
}

// The revolution a balancing evaluates: its steps, and as many harmonics as they resolve (up to 6).
GearOptions gear_options_for(const BalanceOptions& options) {
  GearOptions g;
  g.steps = options.steps;
  g.harmonics = std::min(g.harmonics, options.steps / 2 - 1);
  return g;
}

bool drives(const DrivingGear& g, std::size_t axle) {
  return std::any_of(g.cylinders.begin(), g.cylinders.end(), [&](const GearCylinder& c) { return static_cast<std::size_t>(c.axle) == axle; });
}

// The wheel's crank angle θ at which the driving wheel on the same side carries its largest
// forward force after its vertical counterweight (by-product −Q cos(θ + γ)), on the steps.
double horizontal_peak(const DrivingGear& g, std::size_t w, const RotatingMass& vertical, double omega, int steps) {
  double best = -INFINITY, at = 0.0;
  for (int i = 0; i < steps; ++i) {
    const double t = 2.0 * M_PI * i / steps;
    const double x = rod_force_on_wheel(g, w, t, omega, false) -
                     vertical.mass * omega * omega * vertical.radius * std::cos(t + vertical.angle);
    if (x > best) best = x, at = t;
  }
  return at;
}

}  // namespace

RotatingMass counter_crank(double r, double throw_radius, double l, double as, double mass, double sign) {
  const double cos_alpha = (r * r + l * l - throw_radius * throw_radius) / (2.0 * r * l);
  const double os = std::sqrt(as * as + r * r - 2.0 * as * r * cos_alpha);
  const double cos_psi = (r * r + os * os - as * as) / (2.0 * r * os);
  return {"counter-crank", mass, os, sign * std::acos(std::clamp(cos_psi, -1.0, 1.0)), 0.0, false};
}

BalanceResult balance_driving_gear(const DrivingGear& gear, double speed, const BalanceOptions& options) {
  require_valid(gear, "DrivingGear: ");
  require_valid(options, "BalanceOptions: ");
  if (!(speed > 0.0) || !std::isfinite(speed)) throw std::invalid_argument("balancing: speed must be positive and finite (m/s)");
  BalanceResult r;
  r.speed = speed;
  r.rule = options.rule;
  r.summary.analysis = "driving-gear counterweights";
  r.summary.method = std::string("two-plane reduction of the rotating masses; vertical counterweight by the ") +
                     to_string(options.rule) + " rule; " +
                     (options.allowed_alpha > 0 ? "overbalance from the allowed overload coefficient (Zhdanov (89a))"
                                                : "overbalance from the fraction of reciprocating mass");
  StageClock clock(&r.summary);
  const GearOptions gear_options = gear_options_for(options);
  r.before = solve_driving_gear(gear, speed, gear_options);
  const double omega = r.before.omega, S = gear.wheel_plane_half_spacing;
  const std::size_t wheels = 2 * gear.axles.size();
  r.balanced = gear;
  r.wheels.resize(wheels);
  std::vector<std::vector<RotatingMass>> added(wheels);

  // 1. The rotating masses, cancelled in each wheel plane.
  const std::vector<Phasor> rotating = rotating_resultants(gear);
  for (std::size_t w = 0; w < wheels; ++w) {
    const GearAxle& axle = gear.axles[w / 2];
    added[w].push_back(cancelling("counterweight", rotating[w], wheel_of(gear, w), axle.crank_radius, false));
  }
  // 2. The vertical counterweight of each driving wheel against its rods' Y.
  double worst_minimax_excess = 0.0;
  for (std::size_t w = 0; w < wheels; ++w) {
    const GearAxle& axle = gear.axles[w / 2];
    RotatingMass vertical{"vertical counterweight", 0.0, axle.crank_radius, 0.0, 0.0, false};
    if (drives(gear, w / 2)) {
      const auto upward = [&](double t) { return rod_force_on_wheel(gear, w, t, omega, true); };
      const gear::SineForce f = gear::size_vertical_counterweight(upward, options.rule, options.steps);
      vertical.mass = std::hypot(f.a, f.b) / (omega * omega * axle.crank_radius);
      vertical.angle = wrapped(std::atan2(f.b, f.a));
      if (options.rule == VerticalRule::minimax) {
        const gear::SineForce ls = gear::size_vertical_counterweight(upward, VerticalRule::least_squares, options.steps);
        worst_minimax_excess = std::max(worst_minimax_excess, gear::largest_residual(upward, f, options.steps) -
                                                                  gear::largest_residual(upward, ls, options.steps));
      }
    }
    added[w].push_back(vertical);
  }
  // 3. The overbalance of the chosen axles.
  std::vector<std::size_t> over_axles;
  for (std::size_t a = 0; a < gear.axles.size(); ++a)
    if (!drives(gear, a) || options.overbalance_driving_axles) over_axles.push_back(a);
  if (options.allowed_alpha > 0.0 && !gear.cylinders.empty()) {
    // Zhdanov (86)–(91): Q_в·ω²·r = α·П in each coupled wheel, its horizontal force −Q ω² r cos(θ + β)
    // most negative where the driving wheel's horizontal residual peaks forward: β = −θ_peak.
    const std::size_t driving = static_cast<std::size_t>(gear.cylinders.front().axle);
    DrivingGear vertical_only = gear;
    for (std::size_t w = 0; w < wheels; ++w)
      wheel_of(vertical_only, w).masses.insert(wheel_of(vertical_only, w).masses.end(), added[w].begin(), added[w].end());
    const GearResult so_far = solve_driving_gear(vertical_only, speed, gear_options);
    for (int side = 0; side < 2; ++side) {
      const double peak = horizontal_peak(gear, 2 * driving + side, added[2 * driving + side][1], omega, options.steps);
      for (std::size_t a : over_axles) {
        const std::size_t w = 2 * a + side;
        const double budget = options.allowed_alpha * wheel_of(gear, w).static_load -
                              (drives(gear, a) ? so_far.wheels[w].alpha * wheel_of(gear, w).static_load : 0.0);
        const double mass = std::max(0.0, budget) / (omega * omega * gear.axles[a].crank_radius);
        added[w].push_back({"overbalance", mass, gear.axles[a].crank_radius, wrapped(-peak), 0.0, true});
      }
    }
  } else if (options.reciprocating_fraction > 0.0 && !over_axles.empty()) {
    // Each cylinder's reciprocating mass as if it turned on its crank pin, the fraction of it
    // shared by the overbalanced axles and cancelled in their wheel planes.
    for (std::size_t a : over_axles) {
      Phasor planes[2] = {0.0, 0.0};
      for (const GearCylinder& c : gear.cylinders) {
        const double m = c.reciprocating_mass + c.rod_mass * (1.0 - c.rod_centre_of_mass / c.rod_length);
        add_to_planes(planes, std::polar(options.reciprocating_fraction * m * c.crank_radius / over_axles.size(), c.crank_offset),
                      c.lateral, S);
      }
      for (int side = 0; side < 2; ++side)
        added[2 * a + side].push_back(
            cancelling("overbalance", planes[side], wheel_of(gear, 2 * a + side), gear.axles[a].crank_radius, true));
    }
  }
  clock.lap("counterweights");

  for (std::size_t w = 0; w < wheels; ++w) {
    GearWheel& wheel = wheel_of(r.balanced, w);
    for (const RotatingMass& m : added[w])
      if (m.mass > 0.0) wheel.masses.push_back(m);
  }
  r.after = solve_driving_gear(r.balanced, speed, gear_options);
  DrivingGear rods_only = gear;
  for (std::size_t w = 0; w < wheels; ++w) wheel_of(rods_only, w).masses.clear();
  const GearResult rods = solve_driving_gear(rods_only, speed, gear_options);
  r.percent_unbalanced_surging = rods.max_surging > 0 ? 100.0 * r.after.max_surging / rods.max_surging : 0.0;
  r.percent_unbalanced_nosing = rods.max_nosing > 0 ? 100.0 * r.after.max_nosing / rods.max_nosing : 0.0;
  for (std::size_t w = 0; w < wheels; ++w) {
    WheelBalance& b = r.wheels[w];
    b.axle = static_cast<int>(w / 2);
    b.right = w % 2 == 0;
    b.rotating_mass = added[w][0].mass, b.rotating_angle = added[w][0].angle;
    b.vertical_mass = added[w][1].mass, b.vertical_angle = added[w][1].angle;
    if (added[w].size() > 2) b.overbalance_mass = added[w][2].mass, b.overbalance_angle = added[w][2].angle;
    Phasor total = 0.0;  // eq. (98)–(100): the vector sum on the common crank radius
    for (const RotatingMass& m : added[w]) total += std::polar(m.mass, m.angle);
    b.total_mass = std::abs(total);
    b.total_angle = b.total_mass > 0 ? wrapped(std::arg(total)) : 0.0;
    b.alpha = r.after.wheels[w].alpha;
    b.alpha_89a = r.after.wheels[w].alpha_89a;
    b.max_hammer_blow = b.alpha * r.after.wheels[w].static_load;
  }
  clock.lap("balanced gear");

  for (double fraction : options.trade_off_fractions) {
    BalanceOptions row = options;
    row.allowed_alpha = 0.0;
    row.reciprocating_fraction = fraction;
    row.trade_off_fractions.clear();
    const BalanceResult b = balance_driving_gear(gear, speed, row);
    double worst = 0.0;
    for (const GearWheelLoad& w : b.after.wheels) worst = std::max(worst, w.alpha);
    r.trade_off.push_back({fraction, worst, b.after.max_surging, b.after.max_nosing});
  }
  clock.lap("trade-off");

  // The rotating masses with their counterweights leave no resultant in any wheel plane.
  DrivingGear rotating_check = gear;
  double worst_rotating = 0.0, scale = 0.0;
  for (std::size_t w = 0; w < wheels; ++w) {
    wheel_of(rotating_check, w).masses.push_back(added[w][0]);
    scale = std::max(scale, std::abs(rotating[w]));
  }
  for (const Phasor& p : rotating_resultants(rotating_check)) worst_rotating = std::max(worst_rotating, std::abs(p));
  const double relative = scale > 0 ? worst_rotating / scale : 0.0;
  r.summary.checks.push_back({"rotating resultant after the counterweights, relative", relative, 1e-12, relative <= 1e-12});
  if (options.rule == VerticalRule::minimax)
    r.summary.checks.push_back({"minimax residual above the least-squares residual, N", worst_minimax_excess, 1e-6,
                                worst_minimax_excess <= 1e-6});
  return r;
}

BalanceStudy study_balance(const DrivingGear& gear, double speed, const BalanceOptions& options) {
  BalanceStudy study;
  study.name = gear.name;
  for (const GearCylinder& c : gear.cylinders) study.cylinder_names.push_back(c.name);
  for (const GearAxle& a : gear.axles) study.axle_names.push_back(a.name);
  study.options = options;
  require_valid(options, "BalanceOptions: ");
  study.gear = solve_driving_gear(gear, speed, gear_options_for(options));
  for (VerticalRule rule : {VerticalRule::least_squares, VerticalRule::minimax, VerticalRule::book}) {
    BalanceOptions o = options;
    o.rule = rule;
    if (rule != options.rule) o.trade_off_fractions.clear();
    study.by_rule.push_back(balance_driving_gear(gear, speed, o));
  }
  return study;
}

}  // namespace railmodal
