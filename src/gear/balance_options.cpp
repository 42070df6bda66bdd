// The rules of the balancing options and the names of the vertical rules.
#include <cmath>

#include "railmodal/balance.hpp"
#include "require_valid.hpp"

namespace railmodal {

const char* to_string(VerticalRule rule) {
  switch (rule) {
    case VerticalRule::least_squares:
      return "least_squares";
    case VerticalRule::minimax:
      return "minimax";
    case VerticalRule::book:
      break;
  }
  return "book";
}

std::optional<VerticalRule> vertical_rule_from_string(const std::string& word) {
  for (VerticalRule rule : {VerticalRule::least_squares, VerticalRule::minimax, VerticalRule::book})
    if (word == to_string(rule)) return rule;
  return std::nullopt;
}

bool BalanceOptions::is_valid(std::string* why) const {
  if (!(reciprocating_fraction >= 0.0 && reciprocating_fraction <= 1.0))
    return invalid(why, "reciprocating_fraction must be 0 ... 1");
  if (!(allowed_alpha >= 0.0 && allowed_alpha <= 1.0))
    return invalid(why, "allowed_alpha must be 0 ... 1 (0: use reciprocating_fraction)");
  if (steps < 8) return invalid(why, "steps must be at least 8 (crank angles per revolution)");
  for (double f : trade_off_fractions)
    if (!(f >= 0.0 && f <= 1.0)) return invalid(why, "trade_off_fractions must each be 0 ... 1");
  return true;
}

}  // namespace railmodal
