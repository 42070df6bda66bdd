// Golden-section search for the largest value of a function on a bracket holding one maximum
// (a damped resonance peak), shared by the amplitude curves and the spring deflection check.
#pragma once

#include <cmath>

namespace railmodal::response {

/// The last two interior points of the search and what the function gave there.
template <class Value>
struct GoldenBracket {
  double c = 0.0, d = 0.0;
  Value fc, fd;
};

/// Shrinks [low, high] by 0.618 per evaluation, keeping the interior point with the larger
/// score(evaluate(x)), until the bracket is narrower than `relative_tolerance` × its midpoint,
/// or a score is NaN (an undamped speed met: no finite peak to refine).
template <class Evaluate, class Score>
auto golden_section(double low, double high, double relative_tolerance, const Evaluate& evaluate, const Score& score)
    -> GoldenBracket<decltype(evaluate(low))> {
  const double ratio = (std::sqrt(5.0) - 1.0) / 2.0;
  double a = low, b = high;
  GoldenBracket<decltype(evaluate(low))> g{b - ratio * (b - a), a + ratio * (b - a), {}, {}};
  g.fc = evaluate(g.c);
  g.fd = evaluate(g.d);
  while (b - a > relative_tolerance * 0.5 * (a + b) && !std::isnan(score(g.fc)) && !std::isnan(score(g.fd))) {
    if (score(g.fc) >= score(g.fd)) {
      b = g.d, g.d = g.c, g.fd = g.fc;
      g.c = b - ratio * (b - a);
      g.fc = evaluate(g.c);
    } else {
      a = g.c, g.c = g.d, g.fc = g.fd;
      g.d = a + ratio * (b - a);
      g.fd = evaluate(g.d);
    }
  }
  return g;
}

}  // namespace railmodal::response
