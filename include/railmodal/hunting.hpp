// railmodal — hunting stability: the eigenvalues of a vehicle on its wheelsets against speed
// (root locus), the linear critical speed, every unstable speed interval, and the critical
// speed against conicity (docs/stability.md).
//
//   #include <railmodal/railmodal.hpp>
//   #include <iostream>
//
//   int main() {
//     auto vehicle = railmodal::load_vehicle("data/vehicles/wheelset_on_springs.toml");
//     auto system = railmodal::assemble(vehicle, railmodal::DofSet::lateral);
//     railmodal::HuntingOptions options;
//     options.min_speed = 10.0 / 3.6;
//     options.max_speed = 500.0 / 3.6;
//     auto result = railmodal::solve_hunting_stability(system, options);
//     if (result.critical)
//       std::cout << "hunts above " << result.critical->speed * 3.6 << " km/h ("
//                 << result.critical->branch << ", " << result.critical->frequency_hz << " Hz)\n";
//     else
//       std::cout << to_string(result.verdict) << "\n";
//   }
#pragma once

#include <complex>
#include <optional>
#include <string>
#include <vector>

#include "railmodal/linear_system.hpp"
#include "railmodal/summary.hpp"
#include "railmodal/wheel_rail.hpp"

namespace railmodal {

struct HuntingOptions {
  double min_speed = 10.0 / 3.6;   ///< m/s, > 0 (the creep damping grows as 1/V)
  double max_speed = 500.0 / 3.6;  ///< m/s, > min_speed
  int speed_count = 200;           ///< points of the uniform speed grid, ≥ 2
  /// Conicities of the design curve (critical speed against conicity); empty: none. The root
  /// locus is at the vehicle's own conicity.
  std::vector<double> conicities;
  /// A damping ratio the user asks about (for example 0.05): the lowest speed at which an
  /// oscillatory branch whose ζ was above it at a lower speed falls to it
  /// (HuntingResult::threshold_speed). None: not asked.
  std::optional<double> damping_threshold;
  /// The critical speed is refined until its bracket is below this fraction of it.
  double relative_tolerance = 1e-8;
  /// Two eigenvectors at neighbouring speeds with a MAC below this are not the same branch:
  /// the tracking reports a veer there.
  double continuity_threshold = 0.8;
  /// Worker threads over speeds and conicities; 0: the hardware's.
  int threads = 0;
  bool is_valid(std::string* why) const;
};

/// One branch of the root locus: an eigenvalue followed from speed to speed.
struct HuntingBranch {
  /// What moves most at the lowest speed, body names as written: "wheelset1 hunting",
  /// "bogie1 yaw", "body lateral/roll", twins together "bogie1+bogie2 yaw, antiphase", a series
  /// damper's relaxation −k/c as "series damper relaxation (element)" (with "(kinematic)" for
  /// the branch whose frequency tends to Klingel's V/Λ; "hunting" only for a root that
  /// oscillates there). Decided by the eigenvector at the lowest speed alone; repeats get
  /// " (2)", " (3)" (docs/stability.md).
  std::string name;
  std::vector<std::complex<double>> eigenvalues;  ///< per speed, 1/s, Im λ ≥ 0
  std::vector<double> damping_ratio;              ///< ζ = −Re λ/|λ| per speed
  std::vector<double> frequency_hz;               ///< Im λ/2π per speed
  /// MAC of the eigenvector with the one it was matched to at the previous speed (1 at the
  /// first, 1 where the eigenvalues alone matched every root beyond doubt, so that no
  /// eigenvectors were computed, and 1 where the pair is real or nearly (Im λ < 1 % of |λ|) at either end of the step, with no
  /// oscillation to follow: docs/stability.md): below HuntingOptions::continuity_threshold
  /// the branch veers and its identity there is uncertain.
  std::vector<double> continuity;
  bool veers = false;  ///< some continuity fell below the threshold
};

/// A speed interval over which one branch is unstable (its ζ < 0); intervals of different
/// branches may overlap.
struct UnstableInterval {
  double from = 0.0;  ///< m/s
  double to = 0.0;    ///< m/s
  bool from_lowest_speed = false;  ///< already unstable at the lowest speed of the grid
  bool to_highest_speed = false;   ///< still unstable at the highest speed of the grid
  /// The branch whose ζ is below 0 there, by its name (HuntingBranch::name); a root real at
  /// every speed (no branch) by its group's name, "… (real root)" or a series damper's relaxation.
  std::string branch;
  /// A root real at every speed, positive here: growth without oscillation (a divergence), not a
  /// branch. It holds over the whole range or nowhere (λ = 0 needs a singular stiffness, which
  /// does not depend on the speed), so its ends are the grid's.
  bool divergence = false;
};

/// The linear critical speed: where the least-damped branch's ζ crosses 0 from stable below.
struct HuntingCriticalSpeed {
  double speed = 0.0;          ///< m/s, refined to HuntingOptions::relative_tolerance
  /// The tracked branch that goes unstable, by its lowest-speed name. Tracking follows it over
  /// the grid, so a coarse grid (two speeds) can hand the path to another mode and this name
  /// changes with the grid; `motion` does not.
  std::string branch;
  /// What moves most in the unstable mode at the critical speed, named as branches are
  /// ("bogie1 lateral/yaw"), from the eigenvector at the refined critical speed only: the same
  /// on any grid that finds the same crossing. A branch keeps the name of what it was at the
  /// lowest speed, which after veering can be another body. Where that name is another
  /// branch's (but for its " (kinematic)" and " (2)"), " (shape at the critical speed)" follows
  /// it, so that it is never read as that branch.
  std::string motion;
  double frequency_hz = 0.0;   ///< the hunting frequency there
  double klingel_frequency_hz = 0.0;  ///< V/Λ of the wheelsets' kinematic wavelength Λ
  /// V/Λ_b of a rigid bogie's kinematic wavelength Λ_b = 2π√((r0·l0/λ)(1 + ā²f22/(l0²f11))),
  /// ā² = Σ(x_i − x̄)²/N over its N axles (a², a the half wheelbase, for two; docs/stability.md,
  /// "The equations of motion"): the frequency a bogie's hunting is compared with. That of
  /// `bogie`, the body carrying two or more wheelsets (a bogie, or a two-axle wagon's body)
  /// whose wheelsets move most in the unstable mode; 0 for a vehicle without one.
  double bogie_frequency_hz = 0.0;
  std::string bogie;  ///< the body whose V/Λ_b bogie_frequency_hz is ("" when it is 0)
  int evaluations = 0;         ///< eigen-solves the refinement took
};

enum class HuntingVerdict {
  critical_speed_in_range,    ///< stable at the lowest speed, unstable somewhere above it
  stable_throughout,          ///< stable at every speed of the range
  unstable_at_lowest_speed    ///< already unstable at the lowest speed: no critical speed is invented
};
const char* to_string(HuntingVerdict verdict);
std::optional<HuntingVerdict> hunting_verdict_from_string(const std::string& word);

/// One point of the design curve.
struct ConicityPoint {
  double conicity = 0.0;
  HuntingVerdict verdict = HuntingVerdict::stable_throughout;
  std::optional<HuntingCriticalSpeed> critical;
};

struct HuntingResult {
  std::vector<double> speeds;  ///< m/s, the grid
  std::vector<std::string> dofs;  ///< labels of the degrees of freedom (the first-order system's
                                  ///< displacement half), in order
  /// The oscillatory branches (Im λ above 1 % of |λ| at some speed), least damped first at the
  /// top speed. Roots real, or overdamped pairs, at every speed (the creep roots, a series
  /// damper's relaxation −k/c) are not branches and not in the continuity check.
  std::vector<HuntingBranch> branches;
  HuntingVerdict verdict = HuntingVerdict::stable_throughout;
  std::optional<HuntingCriticalSpeed> critical;
  /// Every branch's unstable intervals, each end where that branch's ζ crosses 0 (refined), in
  /// order of their lower ends (ties in the order of `branches`); every divergence of a root real
  /// at every speed too (UnstableInterval::divergence), each after the branches at its lower end.
  /// The critical speed is the lowest end of the least-damped root's, which is one of these.
  std::vector<UnstableInterval> unstable_intervals;
  /// HuntingOptions::damping_threshold as asked (none: not asked), for the reports.
  std::optional<double> damping_threshold;
  /// The lowest speed at which an oscillatory branch whose ζ was ABOVE
  /// HuntingOptions::damping_threshold at a lower grid speed falls to it (a downward crossing),
  /// refined between grid speeds; none when no branch crosses downwards. Branches already at or
  /// below the threshold at the lowest speed (a lightly damped suspension mode: a bogie's yaw at
  /// 35 Hz, ζ = 4 %) do not decide it: they are listed in below_threshold_at_lowest_speed. Only
  /// oscillatory branches count: a real root has no damping ratio to speak of (ζ = ±1).
  std::optional<double> threshold_speed;
  std::string threshold_branch;  ///< the branch that crosses at threshold_speed ("" when none)
  /// The branches whose ζ is at or below the threshold at the lowest speed, least damped first.
  std::vector<std::string> below_threshold_at_lowest_speed;
  /// Roots left out of the least-damped search as rigid-body (|λ| ≤ 1e-9 of the oscillatory
  /// roots' scale: a motion nothing restrains, such as a wheelset at zero conicity without
  /// gravitational stiffness), most at any grid speed. Neutral: they neither grow nor decay, so
  /// `stable_throughout` with neutral_roots > 0 means "no root grows", not "every motion decays".
  int neutral_roots = 0;
  std::vector<ConicityPoint> conicity_curve;  ///< one per HuntingOptions::conicities
  std::vector<ResolvedContact> contacts;      ///< the wheelsets' contact as used
  /// Checks (the eigen-solve residual, the tracking's continuity) and the stage times.
  AnalysisSummary summary;
};

/// Eigenvalues of the first-order form of M q̈ + (C + C_c/V + V·G) q̇ + (K + K_c) q = 0
/// (series dampers add a state each) over the speed grid, tracked by eigenvector continuity,
/// with the critical speed, the unstable intervals and the conicity curve.
///
/// `system` is an assembly of the lateral motions (DofSet::lateral) or of all motions of a
/// vehicle with wheelsets. Throws std::invalid_argument for bad options or a vehicle without
/// wheelsets; NumericalError when an eigen-solve fails (naming the speed). A vehicle stable over
/// the whole range, or unstable at its lowest speed, is a verdict, never an exception.
HuntingResult solve_hunting_stability(const LinearSystem& system, const HuntingOptions& options = {});

}  // namespace railmodal
