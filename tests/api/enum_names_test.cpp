// Every public enum has to_string and a <name>_from_string that inverts it: the words a CLI
// option, an input file or a report uses for each value (the three output-format enums are
// checked with their writers).
#include <gtest/gtest.h>

#include <cctype>
#include <initializer_list>
#include <optional>
#include <set>
#include <string>

#include "railmodal/railmodal.hpp"
#include "railmodal/spectrum.hpp"
#include "railmodal/study.hpp"

namespace railmodal {
namespace {

// from_string(to_string(v)) == v for every value, the words are distinct, and neither an
// unknown word nor a value's word in another case is accepted.
template <class Enum>
void expect_round_trip(std::initializer_list<Enum> values, std::optional<Enum> (*from_string)(const std::string&)) {
  std::set<std::string> words;
  for (Enum v : values) {
    const std::string word = to_string(v);
    EXPECT_NE(word, "?");
    words.insert(word);
    const std::optional<Enum> parsed = from_string(word);
    ASSERT_TRUE(parsed.has_value()) << word;
    EXPECT_EQ(*parsed, v) << word;
    std::string upper = word;
    for (char& c : upper) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    EXPECT_FALSE(from_string(upper).has_value()) << upper;
  }
  EXPECT_EQ(words.size(), values.size());
  EXPECT_FALSE(from_string("no-such-word").has_value());
  EXPECT_FALSE(from_string("").has_value());
}

TEST(EnumNames, ModeKind) {
  expect_round_trip({ModeKind::oscillatory, ModeKind::rigid_body, ModeKind::unstable}, mode_kind_from_string);
}

TEST(EnumNames, ModalSolver) {
  expect_round_trip({ModalSolver::dense, ModalSolver::arpack, ModalSolver::automatic}, modal_solver_from_string);
}

TEST(EnumNames, DampedModeKind) {
  expect_round_trip({DampedModeKind::underdamped, DampedModeKind::critical, DampedModeKind::overdamped,
                     DampedModeKind::divergent, DampedModeKind::first_order, DampedModeKind::rigid_body},
                    damped_mode_kind_from_string);
}

TEST(EnumNames, HuntingVerdict) {
  expect_round_trip({HuntingVerdict::critical_speed_in_range, HuntingVerdict::stable_throughout,
                     HuntingVerdict::unstable_at_lowest_speed},
                    hunting_verdict_from_string);
}

TEST(EnumNames, DofSet) {
  expect_round_trip({DofSet::vertical, DofSet::lateral, DofSet::all}, dof_set_from_string);
}

TEST(EnumNames, Motion) {
  expect_round_trip({Motion::lateral, Motion::bounce, Motion::roll, Motion::pitch, Motion::yaw, Motion::longitudinal,
                     Motion::bending},
                    motion_from_string);
}

TEST(EnumNames, GearRotation) {
  expect_round_trip({GearRotation::forward, GearRotation::backward}, gear_rotation_from_string);
}

TEST(EnumNames, VerticalRule) {
  expect_round_trip({VerticalRule::least_squares, VerticalRule::minimax, VerticalRule::book}, vertical_rule_from_string);
}

TEST(EnumNames, DipShape) {
  expect_round_trip({DipShape::cosine, DipShape::triangular, DipShape::parabolic}, dip_shape_from_string);
}

TEST(EnumNames, HuntingModel) {
  expect_round_trip({Hunting::Model::free_wheelset, Hunting::Model::rigid_bogie, Hunting::Model::given},
                    hunting_model_from_string);
}

TEST(EnumNames, ResponseQuantity) {
  expect_round_trip({ResponseQuantity::displacement, ResponseQuantity::velocity, ResponseQuantity::acceleration},
                    response_quantity_from_string);
}

TEST(EnumNames, SimulationEventKind) {
  using Kind = SimulationEvent::Kind;
  expect_round_trip({Kind::stick, Kind::slip, Kind::reversal, Kind::kink}, simulation_event_kind_from_string);
}

TEST(EnumNames, FftCheckOutcome) {
  using Outcome = FftCheck::Outcome;
  expect_round_trip({Outcome::passed, Outcome::failed, Outcome::not_excited, Outcome::not_resolved, Outcome::no_line,
                     Outcome::not_applicable, Outcome::decayed},
                    fft_check_outcome_from_string);
}

TEST(EnumNames, Window) {
  expect_round_trip({Window::rectangular, Window::hann, Window::flat_top}, window_from_string);
}

TEST(EnumNames, Padding) {
  expect_round_trip({Padding::none, Padding::to_length, Padding::next_power_of_two}, padding_from_string);
}

TEST(EnumNames, DeflectionRuleBook) {
  using Book = DeflectionRule::Book;
  expect_round_trip({Book::none, Book::korotkevich, Book::lehner}, deflection_book_from_string);
}

TEST(EnumNames, DeflectionRuleService) {
  using Service = DeflectionRule::Service;
  expect_round_trip({Service::passenger, Service::freight}, deflection_service_from_string);
}

TEST(EnumNames, LimitCycleBranchKind) {
  expect_round_trip({LimitCycleBranchKind::subcritical, LimitCycleBranchKind::supercritical,
                     LimitCycleBranchKind::no_hopf_point, LimitCycleBranchKind::undetermined,
                     LimitCycleBranchKind::neutral},
                    limit_cycle_branch_kind_from_string);
}

TEST(EnumNames, ContinuationEnd) {
  expect_round_trip({ContinuationEnd::amplitude_reached, ContinuationEnd::speed_range_left,
                     ContinuationEnd::point_limit, ContinuationEnd::newton_failed, ContinuationEnd::no_hopf_point},
                    continuation_end_from_string);
}

}  // namespace
}  // namespace railmodal
