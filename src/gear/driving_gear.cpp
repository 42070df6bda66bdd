// The driving gear over one revolution: rod forces per cylinder, vertical forces moved to the
// wheel planes, the centrifugal forces of the wheels' masses, surging and nosing, harmonics.
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "gear/harmonics.hpp"
#include "gear/wheel_name.hpp"
#include "gear/wheel_planes.hpp"
#include "railmodal/driving_gear.hpp"
#include "require_valid.hpp"
#include "summary/stage_clock.hpp"

namespace railmodal {

double GearHarmonic::amplitude() const { return std::hypot(cosine, sine); }

double speed_at_alpha(double alpha, double speed, double limit) {
  if (!(alpha > 0.0)) return std::numeric_limits<double>::infinity();
  return speed * std::sqrt(limit / alpha);
}

namespace {

// One state; `overbalance_loads` receives the overbalance masses' share of the wheel loads.
GearState state_at(const DrivingGear& gear, double phi, double omega, std::vector<double>& overbalance_loads) {
  const double S = gear.wheel_plane_half_spacing;
  GearState st;
  st.crank_angle = phi;
  st.wheel_loads.assign(2 * gear.axles.size(), 0.0);
  overbalance_loads.assign(st.wheel_loads.size(), 0.0);
  for (const GearCylinder& c : gear.cylinders) {
    const RodForces f = rod_forces(c, phi + c.crank_offset, omega);
    st.cylinders.push_back(f);
    const gear::PlaneShares shares = gear::wheel_plane_shares(c.lateral, S);
    // ΔP presses the rail: an upward force on the wheel lightens it.
    st.wheel_loads[2 * c.axle] -= shares.right * f.vertical;
    st.wheel_loads[2 * c.axle + 1] -= shares.left * f.vertical;
    st.surging += f.horizontal;
    st.nosing -= f.horizontal * c.lateral;
  }
  for (std::size_t a = 0; a < gear.axles.size(); ++a) {
    for (int side = 0; side < 2; ++side) {
      const GearWheel& wheel = side == 0 ? gear.axles[a].right : gear.axles[a].left;
      const double outward = side == 0 ? 1.0 : -1.0;
      for (const RotatingMass& mass : wheel.masses) {
        // Centrifugal force m ω² ρ along the mass's radius, which points like a crank at angle
        // θ: (−cos θ, sin θ) in (forward, up).
        const double theta = phi + wheel.crank_offset + mass.angle;
        const double f = mass.mass * omega * omega * mass.radius;
        const double fx = -f * std::cos(theta), fy = f * std::sin(theta);
        const double lateral = outward * (S + mass.plane_offset);
        const gear::PlaneShares shares = gear::wheel_plane_shares(lateral, S);
        st.wheel_loads[2 * a] -= shares.right * fy;
        st.wheel_loads[2 * a + 1] -= shares.left * fy;
        if (mass.overbalance) {
          overbalance_loads[2 * a] -= shares.right * fy;
          overbalance_loads[2 * a + 1] -= shares.left * fy;
        }
        st.surging += fx;
        st.nosing -= fx * lateral;
      }
    }
  }
  return st;
}

double max_abs(const std::vector<double>& v) {
  double m = 0.0;
  for (double x : v) m = std::max(m, std::abs(x));
  return m;
}

// Harmonics of `samples` and the largest error of their synthesis at the samples, relative
// to the largest sample (0 for an all-zero quantity).
std::vector<GearHarmonic> harmonics_checked(const std::vector<double>& samples, int highest, double& worst) {
  std::vector<GearHarmonic> h = gear::harmonics_of(samples, highest);
  const double scale = max_abs(samples);
  if (scale > 0.0) {
    const int n = static_cast<int>(samples.size());
    for (int i = 0; i < n; ++i)
      worst = std::max(worst, std::abs(gear::synthesise(h, 2.0 * M_PI * i / n) - samples[i]) / scale);
  }
  return h;
}

}  // namespace

GearResult solve_driving_gear(const DrivingGear& gear, double speed, const GearOptions& options) {
  require_valid(gear, "DrivingGear: ");
  require_valid(options, "GearOptions: ");
  if (!(speed > 0.0) || !std::isfinite(speed))
    throw std::invalid_argument("driving gear: speed must be positive and finite (m/s)");
  GearResult r;
  r.summary.analysis = "driving-gear inertia forces over one revolution";
  r.summary.method =
      "exact rigid-body kinematics of crank, rod and crosshead (Newton-Euler), harmonics by a discrete Fourier "
      "sum over the crank angles";
  StageClock clock(&r.summary);
  r.speed = speed;
  r.omega = 2.0 * speed / gear.wheel_diameter;
  r.frequency_hz = speed / (M_PI * gear.wheel_diameter);

  const int n = options.steps;
  const std::size_t wheels = 2 * gear.axles.size(), cylinders = gear.cylinders.size();
  std::vector<std::vector<double>> loads(wheels, std::vector<double>(n)), over(wheels, std::vector<double>(n));
  std::vector<std::vector<double>> xs(cylinders, std::vector<double>(n)), ys = xs, zs = xs;
  std::vector<double> surging(n), nosing(n), overbalance_loads;
  r.states.reserve(n);
  for (int i = 0; i < n; ++i) {
    r.states.push_back(state_at(gear, 2.0 * M_PI * i / n, r.omega, overbalance_loads));
    const GearState& st = r.states.back();
    for (std::size_t w = 0; w < wheels; ++w) {
      loads[w][i] = st.wheel_loads[w];
      over[w][i] = overbalance_loads[w];
    }
    for (std::size_t c = 0; c < cylinders; ++c) {
      xs[c][i] = st.cylinders[c].horizontal;
      ys[c][i] = st.cylinders[c].vertical;
      zs[c][i] = st.cylinders[c].guide;
    }
    surging[i] = st.surging;
    nosing[i] = st.nosing;
  }
  clock.lap("revolution");

  double worst = 0.0;
  const int k = options.harmonics;
  for (std::size_t c = 0; c < cylinders; ++c) {
    r.horizontal_harmonics.push_back(harmonics_checked(xs[c], k, worst));
    r.vertical_harmonics.push_back(harmonics_checked(ys[c], k, worst));
    r.guide_harmonics.push_back(harmonics_checked(zs[c], k, worst));
  }
  r.surging_harmonics = harmonics_checked(surging, k, worst);
  r.nosing_harmonics = harmonics_checked(nosing, k, worst);
  r.max_surging = max_abs(surging);
  r.max_nosing = max_abs(nosing);
  for (std::size_t w = 0; w < wheels; ++w) {
    const GearAxle& axle = gear.axles[w / 2];
    GearWheelLoad load;
    load.axle = static_cast<int>(w / 2);
    load.right = w % 2 == 0;
    load.wheel = gear::wheel_name(axle.name, load.right);
    load.static_load = (load.right ? axle.right : axle.left).static_load;
    load.max_dynamic_load = *std::max_element(loads[w].begin(), loads[w].end());
    load.min_dynamic_load = *std::min_element(loads[w].begin(), loads[w].end());
    load.alpha = max_abs(loads[w]) / load.static_load;
    std::vector<double> without(n);
    for (int i = 0; i < n; ++i) without[i] = loads[w][i] - over[w][i];
    load.alpha_89a = (max_abs(without) + max_abs(over[w])) / load.static_load;
    load.wheel_lift = load.alpha >= 1.0;
    load.harmonics = harmonics_checked(loads[w], k, worst);
    r.wheels.push_back(load);
  }
  clock.lap("harmonics");
  // What the harmonics up to k leave out of the sampled forces: the fourth and sixth orders of
  // the λ-series are 0.1-0.4 % and < 0.01 % of the first (Kvasnikov, Table I), so with k ≥ 4
  // the synthesis meets the samples to well under 0.1 %.
  const double limit = k >= 4 ? 1e-3 : std::numeric_limits<double>::infinity();
  r.summary.checks.push_back({"harmonic synthesis error, relative to the largest force", worst, limit, worst <= limit});
  return r;
}

}  // namespace railmodal
