// One format enum for every writer: its words round trip, and a writer asked for a format it
// does not write says which writer, which format and what it writes instead of writing half.
#include <sstream>
#include <stdexcept>

#include "railmodal/railmodal.hpp"
#include "test_support.hpp"

namespace railmodal::test {
namespace {

constexpr OutputFormat kEveryFormat[] = {OutputFormat::table, OutputFormat::csv, OutputFormat::json,
                                         OutputFormat::markdown, OutputFormat::html};

TEST(OutputFormat, NamesRoundTrip) {
  for (OutputFormat f : kEveryFormat) EXPECT_EQ(output_format_from_string(to_string(f)), f) << to_string(f);
  EXPECT_EQ(output_format_from_string("text"), std::nullopt);
  EXPECT_EQ(output_format_from_string("JSON"), std::nullopt);
  EXPECT_EQ(output_format_from_string(""), std::nullopt);
}

// What `write` throws as std::invalid_argument into `out` ("" when it writes).
template <typename Write>
std::string refusal(std::ostream& out, Write write) {
  try {
    write(out);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(OutputFormat, WritersRefuseFormatsTheyDoNotWriteByName) {
  std::ostringstream out;
  EXPECT_EQ(refusal(out, [](std::ostream& o) { write_modes(o, "none", ModalResult{}, OutputFormat::html); }),
            "write_modes writes table, csv or json, not html");
  EXPECT_EQ(refusal(out, [](std::ostream& o) {
              write_damped_modes(o, LinearSystem{}, DampedModalResult{}, OutputFormat::markdown);
            }),
            "write_damped_modes writes table, csv or json, not markdown");
  EXPECT_EQ(refusal(out, [](std::ostream& o) {
              write_critical_speed_report(o, CriticalSpeedStudy{}, OutputFormat::table);
            }),
            "write_critical_speed_report writes markdown, html, csv or json, not table");
  EXPECT_EQ(refusal(out, [](std::ostream& o) { write_comparison(o, Comparison{}, OutputFormat::html); })
                .rfind("write_comparison writes table, csv or json, not html", 0),
            0u);
  EXPECT_EQ(refusal(out, [](std::ostream& o) {
              write_time_history(o, TimeHistory{}, Scene{}, Vehicle{}, OutputFormat::table);
            }),
            "write_time_history writes csv or json, not table");
  EXPECT_EQ(refusal(out, [](std::ostream& o) { write_spectra(o, OutputSpectra{}, OutputFormat::json); }),
            "write_spectra writes csv, not json");
  EXPECT_EQ(refusal(out, [](std::ostream& o) {
              write_fft_check(o, FftCheckResult{}, Scene{}, Vehicle{}, OutputFormat::markdown);
            }),
            "write_fft_check writes table, csv, json or html, not markdown");
  EXPECT_EQ(out.str(), "") << "a refused format writes nothing";
}

}  // namespace
}  // namespace railmodal::test
