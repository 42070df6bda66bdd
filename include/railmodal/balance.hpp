// railmodal — balancing the driving gear (Zhdanov 1937, ch. III; digest
// shared/reference/unbalance-excitation.md §2.8–2.10): counterweights for each wheel's rotating
// masses reduced to the two wheel planes, a vertical counterweight in the driving wheels for the
// rods' vertical force Y by one of three named rules, and an overbalance for the reciprocating
// masses (a fraction of them, or as much as an allowed overload coefficient α lets the coupled
// wheels carry); then the residual hammer blow, α, surging and nosing, and the trade-off of α
// against the fraction of reciprocating mass balanced.
//
//   #include <railmodal/railmodal.hpp>
//   #include <cmath>
//   #include <iostream>
//
//   int main() {
//     railmodal::GearCylinder right;  // the Су of Zhdanov's Table 4
//     right.lateral = 1.14;
//     right.crank_radius = 0.35;
//     right.rod_length = 2.35;
//     right.rod_mass = 225.28;
//     right.rod_centre_of_mass = 1.5575;
//     right.rod_inertia = railmodal::rod_inertia_about_centre(71.665 * 9.81, 225.28, 1.5575);
//     right.reciprocating_mass = 365.75;
//     railmodal::GearCylinder left = right;
//     left.lateral = -1.14;
//     left.crank_offset = -M_PI / 2;
//     railmodal::DrivingGear gear;
//     gear.wheel_diameter = 1.85;
//     gear.wheel_plane_half_spacing = 0.795;
//     gear.cylinders = {right, left};
//     gear.axles.resize(2);  // the driving axle and one coupled axle
//     for (railmodal::GearAxle& axle : gear.axles) {
//       axle.crank_radius = 0.35;
//       axle.right.static_load = axle.left.static_load = 9000 * 9.81;
//       axle.left.crank_offset = -M_PI / 2;
//       axle.right.masses = axle.left.masses = {{"crank pin", 65.79, 0.35, 0.0, 0.345, false}};
//     }
//     railmodal::BalanceOptions options;
//     options.rule = railmodal::VerticalRule::minimax;
//     options.allowed_alpha = 0.3;  // overbalance the coupled wheels up to α = 0.3 (eq. (89a))
//     railmodal::BalanceResult b = railmodal::balance_driving_gear(gear, 100 / 3.6, options);
//     for (const railmodal::WheelBalance& w : b.wheels)
//       std::cout << w.axle << (w.right ? " right " : " left ") << w.total_mass << " kg at "
//                 << w.total_angle * 180 / M_PI << " deg, alpha " << w.alpha << "\n";
//     return b.summary.passed() ? 0 : 1;
//   }
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "railmodal/driving_gear.hpp"
#include "railmodal/summary.hpp"

namespace railmodal {

/// How the vertical counterweight of a driving wheel is sized against the rods' Y moved to that
/// wheel (which is not a pure sine: "complete vertical equilibrium cannot be reached"):
/// least_squares cancels its first harmonic (the least mean square residual); minimax makes the
/// largest residual over the revolution least; book is Zhdanov's rule (§III.2, eq. (76)–(77)):
/// the amplitude |Y| at the wheel's crank at 90°, the counterweight's peak against Y's peak.
enum class VerticalRule { least_squares, minimax, book };
const char* to_string(VerticalRule rule);  ///< "least_squares", "minimax", "book"
/// Inverse of to_string; std::nullopt for an unknown word.
std::optional<VerticalRule> vertical_rule_from_string(const std::string& word);

struct BalanceOptions {
  VerticalRule rule = VerticalRule::book;
  /// Fraction of each cylinder's reciprocating mass (m_k + m(1 − d/L)) balanced by an
  /// overbalance opposite its crank, shared equally by the overbalanced axles, 0 … 1. Used when
  /// allowed_alpha is 0.
  double reciprocating_fraction = 0.0;
  /// When > 0 (≤ 1): Zhdanov's rule (§III.3, eq. (89a)): each coupled wheel gets an overbalance
  /// whose own hammer blow is allowed_alpha·П, at the angle that opposes the driving wheel's
  /// horizontal residual peak (eq. (87)); a driving wheel (with overbalance_driving_axles) gets
  /// what its vertical residual leaves of allowed_alpha·П.
  double allowed_alpha = 0.0;
  /// Overbalance the driving axles too (false: the coupled axles only, as Zhdanov does).
  bool overbalance_driving_axles = false;
  int steps = 360;  ///< crank angles per revolution for every search and result (GearOptions::steps)
  /// Fractions for BalanceResult::trade_off (each 0 … 1); empty for none.
  std::vector<double> trade_off_fractions = {0.0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0};
  bool is_valid(std::string* why) const;
};

/// The counterweights of one wheel, each as a mass on the axle's crank radius and its angle
/// ahead of the wheel's crank in the direction of rotation (rad; π = opposite the crank).
struct WheelBalance {
  int axle = 0;
  bool right = true;
  double rotating_mass = 0.0, rotating_angle = 0.0;  ///< for the wheel's rotating masses (eq. (65)–(68))
  double vertical_mass = 0.0, vertical_angle = 0.0;  ///< q_в for the rods' Y (eq. (76)–(77)); driving wheels
  double overbalance_mass = 0.0, overbalance_angle = 0.0;  ///< Q_в (eq. (86)–(91))
  double total_mass = 0.0, total_angle = 0.0;  ///< their vector sum (eq. (98)–(100))
  double max_hammer_blow = 0.0;  ///< max |ΔP| after balancing, N
  double alpha = 0.0;            ///< max |ΔP|/П after balancing (eq. (78) over every mass)
  double alpha_89a = 0.0;        ///< as eq. (89a) adds the overbalance's blow
};

/// One row of the trade-off table: balancing a fraction of the reciprocating masses.
struct BalanceTradeOff {
  double fraction = 0.0;     ///< of the reciprocating masses, 0 … 1
  double max_alpha = 0.0;    ///< the largest α of any wheel
  double max_surging = 0.0;  ///< max |ΣX|, N
  double max_nosing = 0.0;   ///< max |ΣMX|, N·m
};

struct BalanceResult {
  double speed = 0.0;  ///< m/s
  VerticalRule rule = VerticalRule::book;  ///< the rule the vertical counterweights were sized by
  std::vector<WheelBalance> wheels;  ///< axle-major, right then left
  /// The gear with its counterweights added to each wheel's masses (named "counterweight",
  /// "vertical counterweight", "overbalance"; the last marked RotatingMass::overbalance).
  DrivingGear balanced;
  GearResult before;  ///< the gear as given
  GearResult after;   ///< the balanced gear
  /// 100·max|ΣX| after balancing / max|ΣX| of the rods alone (eq. (94)–(97)), likewise nosing.
  double percent_unbalanced_surging = 0.0;
  double percent_unbalanced_nosing = 0.0;
  std::vector<BalanceTradeOff> trade_off;  ///< per BalanceOptions::trade_off_fractions
  /// Checks: the rotating masses' resultant after their counterweights (zero to round-off); the
  /// minimax rule's residual not above the least-squares one's.
  AnalysisSummary summary;
};

/// The counterweights of `gear` at `speed` (m/s, > 0, the design speed). Throws
/// std::invalid_argument for an invalid gear or options ("BalanceOptions: ...").
BalanceResult balance_driving_gear(const DrivingGear& gear, double speed, const BalanceOptions& options = {});

/// What `railmodal balance` prints (balance_report.hpp): the gear's forces as given, and its
/// balancing by each of the three vertical rules with the same overbalance options.
struct BalanceStudy {
  std::string name;  ///< DrivingGear::name
  std::vector<std::string> cylinder_names, axle_names;  ///< GearCylinder::name, GearAxle::name
  GearResult gear;   ///< the gear as given, at the speed
  BalanceOptions options;
  /// One per rule in the order least_squares, minimax, book; only options.rule's has a trade-off.
  std::vector<BalanceResult> by_rule;
};
/// Runs balance_driving_gear for each rule (errors as it).
BalanceStudy study_balance(const DrivingGear& gear, double speed, const BalanceOptions& options = {});

/// The counter-crank (return crank) of a Walschaerts gear as a rotating mass (Zhdanov eq. (72),
/// E7): crank radius r, counter-crank throw r_k (from the axle to the eccentric pin), its arm
/// length l (from the crank pin to the eccentric pin), its centre of mass at AS from the crank pin,
/// mass q. The angle α at the crank pin (cos α = (r² + l² − r_k²)/(2rl)), the centre's radius
/// OS = √(AS² + r² − 2·AS·r·cos α) and its angle ψ from the crank (cos ψ = (r² + OS² − AS²)/(2r·OS)),
/// returned with angle = `sign`·ψ (+1: the eccentric pin leads the crank).
RotatingMass counter_crank(double crank_radius, double throw_radius, double arm_length, double centre_from_pin,
                           double mass, double sign);

}  // namespace railmodal
