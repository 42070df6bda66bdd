// The digital EN 12299 and Sperling weightings: their response against the analog
// definitions, a sine through each against |W|·A/√2, and the EN 12299 window statistics.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "railmodal/comfort_weighting.hpp"
#include "ride/window_indices.hpp"
#include "ride/time_weighting.hpp"
#include "test_support.hpp"

namespace railmodal::test {
namespace {

constexpr double kStep = 1e-3;  // 1 kHz

// The bilinear transform warps frequency by (ωΔt)²/12 relative near a prewarped corner and
// the low-pass band limit sits near Nyquist: the measured largest relative error of |W| at
// 1 kHz is 9e-4 up to 16 Hz (docs/ride.md, "Ride indices in time", gives the table); held
// to 1.5e-3 here.
TEST(TimeWeighting, DigitalResponseFollowsTheAnalogDefinitionsUpToSixteenHertz) {
  const ride::DigitalFilter wb = ride::digital_weighting(en12299_wb(), kStep);
  const ride::DigitalFilter wd = ride::digital_weighting(en12299_wd(), kStep);
  const ride::DigitalFilter sv = ride::digital_sperling(SperlingDirection::vertical, kStep);
  const ride::DigitalFilter sl = ride::digital_sperling(SperlingDirection::lateral, kStep);
  for (double f = 0.1; f <= 16.0; f *= 1.05) {
    EXPECT_NEAR(std::abs(wb.response(f, kStep)) / en12299_wb().magnitude(f), 1.0, 1.5e-3) << f;
    EXPECT_NEAR(std::abs(wd.response(f, kStep)) / en12299_wd().magnitude(f), 1.0, 1.5e-3) << f;
    EXPECT_NEAR(std::abs(sv.response(f, kStep)) / sperling_weighting(f, SperlingDirection::vertical), 1.0, 1.5e-3) << f;
    EXPECT_NEAR(std::abs(sl.response(f, kStep)) / sperling_weighting(f, SperlingDirection::lateral), 1.0, 1.5e-3) << f;
  }
  // the phase too (the weighted history is a waveform, not only a level): within 0.01 rad
  for (double f : {0.5, 2.0, 5.0, 10.0})
    EXPECT_NEAR(std::arg(wb.response(f, kStep) / en12299_wb().response(f)), 0.0, 0.01) << f;
}

// A sine of amplitude A at f through each filter: after the start-up transient (the 0.4 Hz
// high pass decays as e^{−t/0.56 s}: 20 s leaves 1e-15) the RMS over whole periods is
// |W_digital|·A/√2 to round-off, and |W|·A/√2 within the bilinear error above.
TEST(TimeWeighting, ASineComesOutAtTheWeightingTimesItsRms) {
  constexpr double kAmplitude = 0.3;
  const int settle = 20000, measured = 10000;  // 20 s, then 10 s: whole periods of every f below
  for (double f : {1.0, 2.5, 5.0, 10.0}) {
    Eigen::VectorXd sine(settle + measured);
    for (int n = 0; n < sine.size(); ++n) sine(n) = kAmplitude * std::sin(2 * kPi * f * n * kStep);
    const auto rms = [&](const ride::DigitalFilter& filter) {
      return std::sqrt(filter.apply(sine).tail(measured).squaredNorm() / measured);
    };
    const ride::DigitalFilter wb = ride::digital_weighting(en12299_wb(), kStep);
    const ride::DigitalFilter wd = ride::digital_weighting(en12299_wd(), kStep);
    const ride::DigitalFilter sv = ride::digital_sperling(SperlingDirection::vertical, kStep);
    EXPECT_NEAR(rms(wb), std::abs(wb.response(f, kStep)) * kAmplitude / std::sqrt(2.0), 1e-9) << f;
    EXPECT_NEAR(rms(wb) / (en12299_wb().magnitude(f) * kAmplitude / std::sqrt(2.0)), 1.0, 1.5e-3) << f;
    EXPECT_NEAR(rms(wd) / (en12299_wd().magnitude(f) * kAmplitude / std::sqrt(2.0)), 1.0, 1.5e-3) << f;
    // Sperling's filter form equals the harmonic form for one sine (comfort_weighting.hpp):
    // Wz goes as B^0.3, so B's 1.5e-3 is 4.5e-4 of Wz (about 3): 2e-3
    EXPECT_NEAR(sperling_wz_from_weighted_rms(rms(sv)), sperling_wz_harmonic(kAmplitude, f, SperlingDirection::vertical),
                2e-3)
        << f;
  }
}

TEST(TimeWeighting, PrewarpingAboveNyquistIsRefused) {
  EXPECT_THROW(ride::bilinear({1.0}, {1.0, 1.0}, 0.01, 60.0), std::invalid_argument);
}

TEST(RideIndices, WindowsPercentileAndRunningRms) {
  Eigen::VectorXd values(7);
  values << 1, -1, 1, -1, 2, -2, 3;
  const Eigen::VectorXd windows = ride::window_rms(values, 2);
  ASSERT_EQ(windows.size(), 3);  // the incomplete last window is left out
  EXPECT_DOUBLE_EQ(windows(0), 1.0);
  EXPECT_DOUBLE_EQ(windows(2), 2.0);
  // 1 … 60: rank 0.95·59 = 56.05 between the 57th and 58th values
  const Eigen::VectorXd sixty = Eigen::VectorXd::LinSpaced(60, 1.0, 60.0);
  EXPECT_DOUBLE_EQ(ride::percentile95(sixty), 57.05);
  std::string note;
  EXPECT_DOUBLE_EQ(ride::zone_p95(sixty, 60, &note), 57.05);
  EXPECT_NE(note.find("1 complete zone"), std::string::npos) << note;
  EXPECT_DOUBLE_EQ(ride::zone_p95(sixty.head(20), 60, &note), ride::percentile95(sixty.head(20)));
  EXPECT_NE(note.find("fewer than the 60"), std::string::npos) << note;
  const Eigen::VectorXd running = ride::running_rms(values, 2);
  EXPECT_DOUBLE_EQ(running(0), 1.0);                   // over the one sample so far
  EXPECT_DOUBLE_EQ(running(5), 2.0);                   // √((4 + 4)/2)
  EXPECT_DOUBLE_EQ(running(6), std::sqrt((4 + 9) / 2.0));
}

// running_rms runs several restart intervals of its running sum side by side; each interval's
// recursion is the same operations as one interval at a time, so Cc(t) is the same doubles as
// the plain loop below (the form before the intervals ran side by side), on runs with and without a
// partial last group of intervals, and with the result vector reused.
TEST(TimeWeighting, RunningRmsSideBySideIsTheOneIntervalAtATimeLoopBitForBit) {
  const auto plain = [](const Eigen::VectorXd& values, Eigen::Index samples) {
    const Eigen::Index n = values.size();
    Eigen::VectorXd out(n);
    for (Eigen::Index start = 0; start < n; start += samples) {
      const Eigen::Index first = std::max<Eigen::Index>(0, start + 1 - samples);
      double sum = values.segment(first, start + 1 - first).squaredNorm();
      out(start) = sum;
      for (Eigen::Index i = start + 1; i < std::min(n, start + samples); ++i) {
        sum += values(i) * values(i);
        if (i >= samples) sum -= values(i - samples) * values(i - samples);
        out(i) = sum;
      }
    }
    for (Eigen::Index i = 0; i < n; ++i)
      out(i) = std::sqrt(std::max(0.0, out(i)) / static_cast<double>(std::min<Eigen::Index>(i + 1, samples)));
    return out;
  };
  Eigen::VectorXd reused;
  for (Eigen::Index n : {1, 7, 1000, 20011, 100000})
    for (Eigen::Index samples : {1, 2, 37, 1000, 5000}) {
      const Eigen::VectorXd values = Eigen::VectorXd::Random(n).array().cube().matrix();  // varied magnitudes
      const Eigen::VectorXd expected = plain(values, samples);
      EXPECT_EQ(ride::running_rms(values, samples), expected) << n << " samples, window " << samples;
      ride::running_rms(values, samples, &reused);
      EXPECT_EQ(reused, expected) << n << " samples, window " << samples;
    }
}

// EN 12299 combines the axes' P95 of the same 5-minute zone, then takes the largest zone's N_MV.
// Two zones whose worst axes differ: longitudinal worst in zone 2, vertical in zone 1. Zone by
// zone both give 6√(0.1² + 0.3²) = 1.897; the axes' worst zones combined would read
// 6√(0.3² + 0.3²) = 2.546, a third high.
TEST(RideSimulation, ComfortCombinesTheAxesZoneByZone) {
  const Eigen::VectorXd x = (Eigen::VectorXd(2) << 0.1, 0.3).finished();
  const Eigen::VectorXd z = (Eigen::VectorXd(2) << 0.3, 0.1).finished();
  EXPECT_DOUBLE_EQ(ride::zone_nmv(&x, nullptr, &z), en12299_nmv(0.1, 0.0, 0.3));
  EXPECT_NEAR(ride::zone_nmv(&x, nullptr, &z), 6.0 * std::sqrt(0.1), 1e-14);
  EXPECT_DOUBLE_EQ(ride::zone_nmv(nullptr, nullptr, &z), en12299_nmv(0.0, 0.0, 0.3));  // one axis: its worst zone
  // 120 windows of a run are two zones: zone_p95s gives each zone's P95
  Eigen::VectorXd windows(120);
  windows << Eigen::VectorXd::LinSpaced(60, 1.0, 60.0), Eigen::VectorXd::LinSpaced(60, 2.0, 120.0);
  const Eigen::VectorXd zones = ride::zone_p95s(windows, 60);
  ASSERT_EQ(zones.size(), 2);
  EXPECT_DOUBLE_EQ(zones(0), 57.05);
  EXPECT_DOUBLE_EQ(zones(1), 114.1);
}


// The cascade section by section in transposed direct form II, as DigitalFilter::apply ran
// it before its sections were fused into one pass: the reference for bit-for-bit equality.
Eigen::VectorXd section_by_section(const std::vector<ride::DigitalFilter::Section>& sections, Eigen::VectorXd signal) {
  for (const ride::DigitalFilter::Section& s : sections) {
    const size_t order = s.a.size() - 1;
    std::vector<double> state(order + 1, 0.0);
    for (Eigen::Index n = 0; n < signal.size(); ++n) {
      const double x = signal(n);
      const double y = s.b[0] * x + state[0];
      for (size_t k = 0; k < order; ++k) state[k] = s.b[k + 1] * x - s.a[k + 1] * y + state[k + 1];
      signal(n) = y;
    }
  }
  return signal;
}

TEST(TimeWeighting, FusedCascadeAndSecondPassAreTheSectionBySectionSamplesBitForBit) {
  // Wb's four second-order sections and Sperling's third-order one run fused; a fourth-order
  // section sends a filter to the section-by-section loop. Every path: the same doubles.
  Eigen::VectorXd input(3000);
  for (Eigen::Index n = 0; n < input.size(); ++n)
    input(n) = std::sin(0.013 * static_cast<double>(n * n % 977)) + 0.1 * std::cos(0.7 * static_cast<double>(n));
  const FrequencyWeighting wb = en12299_wb();
  const double w1 = 2.0 * kPi * wb.f1;
  const ride::DigitalFilter::Section high_pass =
      ride::bilinear({0.0, 0.0, 1.0}, {w1 * w1, w1 / wb.q1, 1.0}, kStep, wb.f1);  // Wb's first
  const std::vector<std::vector<ride::DigitalFilter::Section>> cases{
      {high_pass},
      {ride::bilinear({0.0, 1.0}, {w1, 1.0}, kStep, wb.f1), high_pass},                             // first order
      {ride::bilinear({0.0, 0.1, 0.2, 0.01}, {1.0, 0.3, 0.05, 0.002}, kStep, 5.0), high_pass},      // third
      {high_pass, ride::bilinear({1.0, 0.0, 0.0, 0.0, 1e-4}, {1.0, 0.5, 0.1, 0.01, 1e-3}, kStep, 0.0)}};  // fourth
  for (const auto& sections : cases) {
    const ride::DigitalFilter filter(sections);
    const Eigen::VectorXd expected = section_by_section(sections, input);
    EXPECT_EQ(filter.apply(input), expected);
    Eigen::VectorXd twice(2 * input.size());
    twice << input, input;
    EXPECT_EQ(filter.apply_second_pass(input), section_by_section(sections, twice).tail(input.size()));
  }
}

TEST(TimeWeighting, PairedCascadesAreEachCascadeAloneBitForBit) {
  // simulate_ride runs W and Sperling's B side by side: each lane the same doubles as the
  // cascade alone, from rest and in the periodic second pass, where the shorter cascade is
  // padded with identity sections and the shorter lead-in with zeros (30000 samples: both
  // lead-ins, 25914 and 10127, shorter than the period; 3000: both the whole period), and a
  // fourth-order section (no pair: each alone).
  Eigen::VectorXd input(30000);
  for (Eigen::Index n = 0; n < input.size(); ++n)
    input(n) = std::sin(0.013 * static_cast<double>(n * n % 977)) + 0.1 * std::cos(0.7 * static_cast<double>(n));
  const ride::DigitalFilter wb = ride::digital_weighting(en12299_wb(), kStep);
  const ride::DigitalFilter wd = ride::digital_weighting(en12299_wd(), kStep);
  const ride::DigitalFilter b = ride::digital_sperling(SperlingDirection::vertical, kStep);
  const ride::DigitalFilter fourth({ride::bilinear({1.0, 0.0, 0.0, 0.0, 1e-4}, {1.0, 0.5, 0.1, 0.01, 1e-3}, kStep, 0.0)});
  const std::vector<std::pair<const ride::DigitalFilter*, const ride::DigitalFilter*>> pairs{
      {&wb, &b}, {&b, &wd}, {&wd, &wb}, {&wb, &fourth}};
  for (const auto& [first, second] : pairs)
    for (Eigen::Index n : {Eigen::Index{30000}, Eigen::Index{3000}}) {
      const Eigen::VectorXd x = input.head(n);
      Eigen::VectorXd first_out, second_out;
      ride::DigitalFilter::apply_from(*first, *second, x, 0, &first_out, &second_out);
      EXPECT_EQ(first_out, first->apply(x));
      EXPECT_EQ(second_out, second->apply(x));
      ride::DigitalFilter::apply_second_pass(*first, *second, x, &first_out, &second_out);
      EXPECT_EQ(first_out, first->apply_second_pass(x));
      EXPECT_EQ(second_out, second->apply_second_pass(x));
    }
}

TEST(TimeWeighting, TwoHistoriesAtOnceAreEachHistorysPairBitForBit) {
  // simulate_ride weighs two outputs of one axis at once (four recursions in one loop, W's
  // sections without their padding): each output the same doubles as the pair over it alone,
  // from rest with and without settling and in the periodic second pass (lengths as in the
  // pair test above), for the instantiated Wb/Wd beside Sperling's B, for cascades taking the
  // fallback (Sperling's B first, a fourth-order section), and into reused buffers.
  Eigen::VectorXd a(30000), b(30000);
  for (Eigen::Index n = 0; n < a.size(); ++n) {
    a(n) = std::sin(0.013 * static_cast<double>(n * n % 977)) + 0.1 * std::cos(0.7 * static_cast<double>(n));
    b(n) = std::sin(0.011 * static_cast<double>(n * n % 983)) + 0.2 * std::cos(0.3 * static_cast<double>(n));
  }
  const ride::DigitalFilter wb = ride::digital_weighting(en12299_wb(), kStep);
  const ride::DigitalFilter wd = ride::digital_weighting(en12299_wd(), kStep);
  const ride::DigitalFilter bv = ride::digital_sperling(SperlingDirection::vertical, kStep);
  const ride::DigitalFilter bl = ride::digital_sperling(SperlingDirection::lateral, kStep);
  const ride::DigitalFilter fourth({ride::bilinear({1.0, 0.0, 0.0, 0.0, 1e-4}, {1.0, 0.5, 0.1, 0.01, 1e-3}, kStep, 0.0)});
  const std::vector<std::pair<const ride::DigitalFilter*, const ride::DigitalFilter*>> pairs{
      {&wb, &bv}, {&wd, &bl}, {&bv, &wb}, {&wb, &fourth}};
  Eigen::VectorXd first_a, second_a, first_b = Eigen::VectorXd::Constant(7, NAN), second_b, first, second;
  for (const auto& [f, s] : pairs) {
    for (Eigen::Index n : {Eigen::Index{30000}, Eigen::Index{3000}}) {
      const Eigen::VectorXd x = a.head(n), y = b.head(n);
      ride::DigitalFilter::apply_second_pass(*f, *s, x, y, &first_a, &second_a, &first_b, &second_b);
      ride::DigitalFilter::apply_second_pass(*f, *s, x, &first, &second);
      EXPECT_EQ(first_a, first) << n;
      EXPECT_EQ(second_a, second) << n;
      ride::DigitalFilter::apply_second_pass(*f, *s, y, &first, &second);
      EXPECT_EQ(first_b, first) << n;
      EXPECT_EQ(second_b, second) << n;
    }
    for (Eigen::Index from : {Eigen::Index{0}, Eigen::Index{9000}, Eigen::Index{21000}, Eigen::Index{30000}}) {
      ride::DigitalFilter::apply_from(*f, *s, a, b, from, &first_a, &second_a, &first_b, &second_b);
      ride::DigitalFilter::apply_from(*f, *s, a, from, &first, &second);
      EXPECT_EQ(first_a, first) << from;
      EXPECT_EQ(second_a, second) << from;
      ride::DigitalFilter::apply_from(*f, *s, b, from, &first, &second);
      EXPECT_EQ(first_b, first) << from;
      EXPECT_EQ(second_b, second) << from;
    }
  }
}

TEST(TimeWeighting, ApplyFromAndBuffersGiveTheWholeRunsSamplesBitForBit) {
  // simulate_ride filters a settling run without keeping its samples (apply_from, the discarded
  // samples run in chunks no longer than the kept ones) and writes the pairs into buffers it
  // reuses for every output: the same doubles as the whole run's tail, whatever size and
  // contents the buffers had. The starts cover no settling, settling shorter and longer than
  // the kept samples (one chunk, several, 29999 of one sample) and nothing kept.
  Eigen::VectorXd input(30000);
  for (Eigen::Index n = 0; n < input.size(); ++n)
    input(n) = std::sin(0.011 * static_cast<double>(n * n % 983)) + 0.2 * std::cos(0.3 * static_cast<double>(n));
  const ride::DigitalFilter wb = ride::digital_weighting(en12299_wb(), kStep);
  const ride::DigitalFilter b = ride::digital_sperling(SperlingDirection::vertical, kStep);
  const ride::DigitalFilter fourth({ride::bilinear({1.0, 0.0, 0.0, 0.0, 1e-4}, {1.0, 0.5, 0.1, 0.01, 1e-3}, kStep, 0.0)});
  const std::vector<std::pair<const ride::DigitalFilter*, const ride::DigitalFilter*>> pairs{
      {&wb, &b}, {&b, &wb}, {&wb, &fourth}};
  Eigen::VectorXd first_out = Eigen::VectorXd::Constant(5, NAN), second_out = Eigen::VectorXd::Constant(30000, NAN);
  for (const auto& [first, second] : pairs) {
    const Eigen::VectorXd whole_first = first->apply(input), whole_second = second->apply(input);
    for (Eigen::Index from : {Eigen::Index{0}, Eigen::Index{9000}, Eigen::Index{21000}, Eigen::Index{29999},
                              Eigen::Index{30000}}) {
      const Eigen::Index kept = input.size() - from;
      EXPECT_EQ(first->apply_from(input, from), whole_first.tail(kept)) << from;
      ride::DigitalFilter::apply_from(*first, *second, input, from, &first_out, &second_out);
      EXPECT_EQ(first_out, whole_first.tail(kept)) << from;
      EXPECT_EQ(second_out, whole_second.tail(kept)) << from;
    }
    for (Eigen::Index n : {Eigen::Index{30000}, Eigen::Index{3000}}) {
      // A column of a matrix read in place, as simulate_ride passes the march's outputs.
      Eigen::MatrixXd columns(n, 2);
      columns.col(0) = input.tail(n);
      columns.col(1) = input.head(n);
      const Eigen::VectorXd x = input.tail(n);
      ride::DigitalFilter::apply_second_pass(*first, *second, columns.col(0), &first_out, &second_out);
      EXPECT_EQ(first_out, first->apply_second_pass(x));
      EXPECT_EQ(second_out, second->apply_second_pass(x));
      EXPECT_EQ(first->apply_second_pass(columns.col(0)), first->apply_second_pass(x));
    }
  }
}

TEST(TimeWeighting, LeadInLeavesLessThanTheStatedTailOfTheImpulseResponse) {
  // apply_second_pass's bound (time_weighting.hpp): the impulse response beyond lead_in() sums
  // to below 1e-16 of the whole (its ℓ1 norm, the filter's largest gain on a bounded input), for
  // the ride's weightings at 1 kHz and at 100 Hz; and the lead-in's samples differ from the
  // whole first pass's by no more than that tail (plus a few ulps of round-off) on a period
  // longer than the lead-in.
  for (double step : {1e-3, 1e-2}) {
    const std::vector<ride::DigitalFilter> filters{
        ride::digital_weighting(en12299_wb(), step), ride::digital_weighting(en12299_wd(), step),
        ride::digital_sperling(SperlingDirection::vertical, step),
        ride::digital_sperling(SperlingDirection::lateral, step)};
    for (const ride::DigitalFilter& filter : filters) {
      const long lead = filter.lead_in();
      ASSERT_GT(lead, 0);
      ASSERT_LT(lead, 200000);
      // three lead-ins long: the tail beyond it is (1e-20)³ of the first sample's scale
      Eigen::VectorXd impulse = Eigen::VectorXd::Zero(3 * lead);
      impulse(0) = 1.0;
      const Eigen::VectorXd h = filter.apply(impulse);
      const double total = h.cwiseAbs().sum(), tail = h.tail(2 * lead).cwiseAbs().sum();
      EXPECT_LT(tail, 1e-16 * total) << "step " << step << ", lead-in " << lead;

      Eigen::VectorXd period(lead + lead / 2 + 7);
      for (Eigen::Index n = 0; n < period.size(); ++n)
        period(n) = std::sin(0.013 * static_cast<double>(n * n % 977)) + 0.1 * std::cos(0.7 * static_cast<double>(n));
      Eigen::VectorXd twice(2 * period.size());
      twice << period, period;
      const Eigen::VectorXd whole = filter.apply(twice).tail(period.size());
      const double difference = (filter.apply_second_pass(period) - whole).cwiseAbs().maxCoeff();
      // The recursion's own round-off, fed back through poles within 2e-3 of the unit circle, is
      // far above an ulp of the output. Its scale: the same two passes over the period started a
      // fifth, two fifths, … of the way in (the same exact periodic response, other round-off),
      // rotated back; the largest of their differences from the whole two passes.
      double roundoff = 0.0;
      for (int fifth = 1; fifth < 5; ++fifth) {
        const Eigen::Index r = fifth * period.size() / 5, rest = period.size() - r;
        Eigen::VectorXd rotated(2 * period.size());
        rotated << period.tail(rest), period.head(r), period.tail(rest), period.head(r);
        const Eigen::VectorXd other = filter.apply(rotated).tail(period.size());
        Eigen::VectorXd back(period.size());
        back << other.tail(r), other.head(rest);
        roundoff = std::max(roundoff, (back - whole).cwiseAbs().maxCoeff());
      }
      // 2·max|x|·tail from the bound, and four times that round-off scale
      EXPECT_LE(difference, 2.0 * period.cwiseAbs().maxCoeff() * tail + 4.0 * roundoff)
          << "round-off scale " << roundoff;
      EXPECT_GT(difference, 0.0);  // the lead-in was taken (the whole first pass would be bit for bit)
    }
  }
}

}  // namespace
}  // namespace railmodal::test
