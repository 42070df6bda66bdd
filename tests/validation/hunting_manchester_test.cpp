// The Manchester benchmark coach on wheelsets (data/vehicles/manchester_benchmark_coach_wheelsets.toml)
// against conicity: no published linear critical speed of it at a stated conicity was found
// (docs/stability.md, "Published examples"), so its design curve is held to what physics gives
// without one: where the bogies hunt, the hunting frequency at the critical speed is the rigid
// bogie's kinematic frequency V/Λ_b, Λ_b = 2π√((r0·l0/λ)(1 + a²f22/(l0²f11))), and the critical
// speed falls as the conicity grows.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <fstream>
#include <iterator>
#include <limits>
#include <set>
#include <string>

#include "railmodal/railmodal.hpp"
#include "test_support.hpp"

namespace railmodal::test {
namespace {

// The coach's overdamped wheelset pairs (two real roots below 22–30 km/h at its conicity) meet and
// leave the real axis as complex pairs; at the meeting the eigenvector is defective and its MAC
// with a neighbour means nothing. Before the audit of 2026-11-27 those steps counted: the
// continuity check failed at 1 − 0.113 (limit 0.2) although every oscillation was followed, and
// the docs' example reported it. Steps where a branch is real at either end are now judged by
// the plane of the pair's shapes (stability/branches.cpp, plane_continuity), the others by their
// MAC, and the check passes.
TEST(HuntingManchesterCoach, OverdampedPairsDoNotFailTheTracking) {
  const Vehicle coach = load_vehicle(data_file("manchester_benchmark_coach_wheelsets.toml"));
  HuntingOptions options;
  options.threads = 1;
  const HuntingResult r = solve_hunting_stability(assemble(coach, DofSet::lateral), options);
  int real_at_some_speed = 0;
  for (const HuntingBranch& b : r.branches) {
    bool real = false;
    for (size_t s = 0; s < b.eigenvalues.size(); ++s) {
      real = real || b.eigenvalues[s].imag() == 0.0;
      // Where it oscillates at both ends the tracking holds by the MAC (0.971 the least,
      // measured); where it is real at either end, by the plane the pair's two shapes span
      // (principal angles, since the review of 2026-11-27: 0.939 the least, measured). Both
      // above the threshold: every step is followed.
      EXPECT_GE(b.continuity[s], options.continuity_threshold) << b.name << " at " << r.speeds[s];
    }
    real_at_some_speed += real ? 1 : 0;
    EXPECT_FALSE(b.veers) << b.name;
  }
  EXPECT_GT(real_at_some_speed, 0);  // the case is exercised: some pair is overdamped at low speed
  EXPECT_TRUE(r.summary.passed());
}

TEST(HuntingManchesterCoach, DesignCurveFollowsTheRigidBogie) {
  const Vehicle coach = load_vehicle(data_file("manchester_benchmark_coach_wheelsets.toml"));
  HuntingOptions options;
  options.conicities = {0.1, 0.15, 0.2, 0.25, 0.3, 0.4};
  options.threads = 1;
  const HuntingResult r = solve_hunting_stability(assemble(coach, DofSet::lateral), options);
  ASSERT_EQ(r.conicity_curve.size(), options.conicities.size());
  ASSERT_FALSE(r.contacts.empty());
  const ResolvedContact& c = r.contacts.front();
  const double a = 2.56 / 2.0;  // half the wheelbase of the file's bogies
  const double stretch =
      std::sqrt(1.0 + a * a * c.creep.f22 / (c.contact_half_spacing * c.contact_half_spacing * c.creep.f11));
  double previous = std::numeric_limits<double>::infinity();
  for (const ConicityPoint& p : r.conicity_curve) {
    ASSERT_TRUE(p.critical) << "λ = " << p.conicity;
    // Monotone from λ = 0.1 on (docs/stability.md's table: 356.6 km/h at 0.1 down to 279.4 at 0.4).
    EXPECT_LT(p.critical->speed, previous) << "λ = " << p.conicity;
    previous = p.critical->speed;
    // V/Λ_b is V/Λ (Klingel's, which the result gives) divided by the rigid bogie's stretch of
    // the wavelength. Within 8 % from λ = 0.1 to 0.3 (measured: −6.3 % to +7.8 %, the wheelsets
    // moving within the bogie on their primary springs as λ grows); beyond, the frames' yaw takes
    // part and the frequency departs further (+17 % at 0.4), which is only bounded here.
    const double rigid_bogie = p.critical->klingel_frequency_hz / stretch;
    const double departure = p.critical->frequency_hz / rigid_bogie - 1.0;
    if (p.conicity <= 0.3)
      EXPECT_LT(std::abs(departure), 0.08) << "λ = " << p.conicity;
    else
      EXPECT_LT(std::abs(departure), 0.2) << "λ = " << p.conicity;
  }
}

// A series (yaw) damper adds the state of its force, whose root −k/c (here −10 MN/m / 400 kN·s/m
// = −25/s) pairs by round-off with a creep root into a pair whose Im λ stays under 1 % of |λ|:
// it never oscillates. Counted among the oscillatory branches, its plane's MAC near a meeting of
// real roots failed the continuity check at every grid (user audit 2026-11-27b, 2.1: "CHECK
// FAILED … MAC 1", exit 6, even at 1000 speeds). It is a real root now: no branch, no check.
TEST(HuntingManchesterCoach, AYawDamperPassesTheContinuityCheck) {
  std::ifstream in(data_file("manchester_benchmark_coach_wheelsets.toml"));
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string secondary = "\n[secondary]\n";
  const size_t at = text.find(secondary);
  ASSERT_NE(at, std::string::npos);
  text.insert(at + secondary.size(),
              "yaw_damper = { damping = \"400 kN*s/m\", series_stiffness = \"10 MN/m\", spacing = \"2.6 m\" }\n");
  const Vehicle coach = load_vehicle(write_temp("coach_yaw_damper.toml", text));
  const LinearSystem system = assemble(coach, DofSet::lateral);
  ASSERT_FALSE(system.series_dampers.empty());  // the case is exercised
  HuntingOptions options;
  options.threads = 1;
  const HuntingResult r = solve_hunting_stability(system, options);
  for (const HuntingBranch& b : r.branches) {
    // Every branch oscillates somewhere (Im λ above 1 % of |λ|, the rule of overdamped_root).
    EXPECT_TRUE(std::any_of(b.eigenvalues.begin(), b.eigenvalues.end(),
                            [](std::complex<double> l) { return std::abs(l.imag()) > 0.01 * std::abs(l); }))
        << b.name;
    EXPECT_EQ(b.name.find("series damper relaxation"), std::string::npos) << b.name;
    EXPECT_FALSE(b.veers) << b.name;
  }
  EXPECT_TRUE(r.summary.passed());
}

// Every branch's unstable interval is listed, not only the least-damped root's: on the coach two
// branches go unstable within 3 km/h of each other and stay so to 500 km/h (user audit
// 2026-11-27b, 1.3: the second, −13.7 % at 500 km/h, was in no interval). Each interval's ends
// are where its own branch's ζ crosses 0, and the critical speed is the lowest lower end.
TEST(HuntingManchesterCoach, TwoBranchesWithOverlappingUnstableIntervals) {
  const Vehicle coach = load_vehicle(data_file("manchester_benchmark_coach_wheelsets.toml"));
  HuntingOptions options;
  options.threads = 1;
  const HuntingResult r = solve_hunting_stability(assemble(coach, DofSet::lateral), options);
  ASSERT_TRUE(r.critical);
  ASSERT_GE(r.unstable_intervals.size(), 2u);
  std::set<std::string> names;
  for (const UnstableInterval& u : r.unstable_intervals) {
    names.insert(u.branch);
    const auto b = std::find_if(r.branches.begin(), r.branches.end(),
                                [&](const HuntingBranch& x) { return x.name == u.branch; });
    ASSERT_NE(b, r.branches.end()) << u.branch;
    // ζ of this branch is below 0 at every grid speed inside the interval and not below 0 at
    // the grid speed just under its lower end.
    for (size_t s = 0; s < r.speeds.size(); ++s) {
      if (r.speeds[s] > u.from && r.speeds[s] < u.to) {
        EXPECT_LT(b->damping_ratio[s], 0.0) << u.branch;
      }
      if (s + 1 < r.speeds.size() && r.speeds[s] < u.from && r.speeds[s + 1] > u.from) {
        EXPECT_GE(b->damping_ratio[s], 0.0) << u.branch;
      }
    }
  }
  EXPECT_EQ(names.size(), r.unstable_intervals.size());  // one interval per branch here, each its own
  // Overlapping: the second begins before the first ends.
  EXPECT_LT(r.unstable_intervals[1].from, r.unstable_intervals[0].to);
  // The critical speed is the first interval's lower end, refined on the least-damped root
  // (1e-8 relative bracket there and on the branch: 1e-7 with margin).
  EXPECT_NEAR(r.critical->speed, r.unstable_intervals.front().from, 1e-7 * r.critical->speed);
}

// The coach's bogies hunt (the frequency at the critical speed is within 4 % of a rigid bogie's
// V/Λ_b, docs/stability.md's table), and the name says so: "bogie1+bogie2 hunting", not
// "wheelset1+wheelset2+wheelset3 hunting", where a threshold on each wheelset's own energy cut
// the fourth (user audit 2026-11-27b, 1.4). V/Λ_b is given beside Klingel's V/Λ.
TEST(HuntingManchesterCoach, BogieHuntingIsNamedByTheBogiesWithTheRigidBogieFrequency) {
  const Vehicle coach = load_vehicle(data_file("manchester_benchmark_coach_wheelsets.toml"));
  HuntingOptions options;
  options.threads = 1;
  const HuntingResult r = solve_hunting_stability(assemble(coach, DofSet::lateral), options);
  ASSERT_TRUE(r.critical);
  EXPECT_EQ(r.critical->motion.rfind("bogie1+bogie2 hunting, in phase", 0), 0u) << r.critical->motion;
  const ResolvedContact& c = r.contacts.front();
  const double a = 2.56 / 2.0;  // half the wheelbase of the file's bogies
  const double stretch =
      std::sqrt(1.0 + a * a * c.creep.f22 / (c.contact_half_spacing * c.contact_half_spacing * c.creep.f11));
  // The same formula on the same numbers: to round-off (1e-12 relative).
  EXPECT_NEAR(r.critical->bogie_frequency_hz, r.critical->klingel_frequency_hz / stretch,
              1e-12 * r.critical->bogie_frequency_hz);
  EXPECT_LT(std::abs(r.critical->frequency_hz / r.critical->bogie_frequency_hz - 1.0), 0.05);  // −4.0 % measured
  for (const HuntingBranch& b : r.branches) {
    // A name lists every wheelset of a family or none: never 3 of the 4.
    int wheelsets = 0;
    for (const char* w : {"wheelset1", "wheelset2", "wheelset3", "wheelset4"})
      wheelsets += b.name.find(w) != std::string::npos ? 1 : 0;
    EXPECT_NE(wheelsets, 3) << b.name;
  }
}

Vehicle at_conicity(Vehicle v, double conicity) {
  for (Wheelset& w : v.wheelsets) w.contact.conicity = conicity;
  return v;
}

// Zero conicity: nothing couples lateral motion to yaw, no speed can make the vehicle hunt, and
// the lateral and yaw motion of the whole vehicle is neutral (its zero root defective, split by
// round-off into a pair of size √ε·scale: stability/damping_search.cpp). User audit 2026-11-28,
// F1: that pair read as hunting from 12.58 km/h (the --conicity curve, exit 0) and as four unstable
// intervals (in the file, exit 6). Now: stable throughout, no interval, no critical speed, the
// pair among the rigid-body roots and out of the branches; and a tiny conicity, 0.001, whose
// kinematic roots are physical (2πV/Λ ≈ 0.15 1/s at 10 km/h, 10⁴ times the band), still hunts,
// with no interval below its critical speed.
TEST(HuntingManchesterCoach, ZeroConicityIsNeutralAndATinyOneStillHunts) {
  const Vehicle coach = load_vehicle(data_file("manchester_benchmark_coach_wheelsets.toml"));
  HuntingOptions options;
  options.threads = 1;
  options.conicities = {0.0, 0.001};
  const HuntingResult zero = solve_hunting_stability(assemble(at_conicity(coach, 0.0), DofSet::lateral), options);
  EXPECT_EQ(zero.verdict, HuntingVerdict::stable_throughout);
  EXPECT_FALSE(zero.critical);
  EXPECT_TRUE(zero.unstable_intervals.empty());
  EXPECT_GE(zero.neutral_roots, 2);  // the split pair, at least
  // No branch of round-off: each moves by more than 1e-3 1/s somewhere (the pair is below 1e-5).
  // The continuity check is not asserted: at λ = 0 the four wheelsets' modes are degenerate in
  // pairs and some branches veer between them (measured: 0.47 the lowest MAC), which the check
  // rightly reports.
  for (const HuntingBranch& b : zero.branches)
    EXPECT_TRUE(std::any_of(b.eigenvalues.begin(), b.eigenvalues.end(),
                            [](std::complex<double> l) { return std::abs(l) > 1e-3; }))
        << b.name;
  ASSERT_EQ(zero.conicity_curve.size(), 2u);
  EXPECT_EQ(zero.conicity_curve[0].verdict, HuntingVerdict::stable_throughout);
  EXPECT_FALSE(zero.conicity_curve[0].critical);
  ASSERT_TRUE(zero.conicity_curve[1].critical);
  const HuntingResult tiny = solve_hunting_stability(assemble(at_conicity(coach, 0.001), DofSet::lateral), options);
  ASSERT_TRUE(tiny.critical);
  // The curve's point and the locus at that conicity are one computation on one grid.
  EXPECT_EQ(tiny.critical->speed, zero.conicity_curve[1].critical->speed);
  EXPECT_GT(tiny.critical->speed, 200.0 / 3.6);  // the audit's 317.9 km/h; nothing near the low end
  ASSERT_FALSE(tiny.unstable_intervals.empty());
  EXPECT_EQ(tiny.unstable_intervals.front().from, tiny.critical->speed);
  // Not asserted: the branch continuity check. At λ = 0.001 the four wheelsets' branches still
  // nearly coincide in pairs and the tracking's lowest MAC is 0.46 (limit 0.2), which the report
  // flags as CHECK FAILED (exit 6): an honest ambiguity of which branch is which, not of the
  // critical speed, whose residual check passes.
}

// The single wheelset on its springs: at zero conicity its lateral and yaw are restrained by the
// springs and damped by creep, so it is stable (no rigid-body root); at 0.001 no interval opens
// below its critical speed, if it has one in the range.
TEST(HuntingManchesterCoach, SingleWheelsetAtZeroAndTinyConicity) {
  const Vehicle wheelset = load_vehicle(data_file("wheelset_on_springs.toml"));
  HuntingOptions options;
  options.threads = 1;
  for (const double conicity : {0.0, 0.001}) {
    const HuntingResult r = solve_hunting_stability(assemble(at_conicity(wheelset, conicity), DofSet::lateral), options);
    EXPECT_NE(r.verdict, HuntingVerdict::unstable_at_lowest_speed) << conicity;
    EXPECT_TRUE(r.summary.passed()) << conicity;
    if (conicity == 0.0) {
      EXPECT_EQ(r.verdict, HuntingVerdict::stable_throughout);
      EXPECT_TRUE(r.unstable_intervals.empty());
    } else if (r.critical) {
      ASSERT_FALSE(r.unstable_intervals.empty());
      EXPECT_EQ(r.unstable_intervals.front().from, r.critical->speed);
    }
  }
}

}  // namespace
}  // namespace railmodal::test
