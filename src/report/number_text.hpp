// Numbers as the JSON and CSV writers print them (issue 19 item 3): the shortest decimal text
// that reads back as the same double, by std::to_chars (no iostream, no locale).
//  - CSV: std::to_chars's own choice, the shorter of fixed and scientific ("0.25", "1e-05",
//    "2", "inf", "nan"), as shortest_text writes the study files' and the comparison CSV's.
//  - JSON: laid out as nlohmann::json laid out the numbers of our JSON files before they were
//    streamed, so that those files kept their look: fixed from 1e-4 up to below 1e15
//    ("0.0001", "123.25", "2.0" for a whole double), otherwise d.ddde±XX ("1e-05", "2.5e+16").
#pragma once

#include <string>

namespace railmodal::report {

/// The most characters write_number writes: a sign, 17 digits, "0." and three leading zeros,
/// or "e-308"; with room to spare.
constexpr int kNumberTextMax = 32;

enum class NumberStyle { csv, json };

/// Writes `value` at `first` (room for kNumberTextMax characters) and returns the end. A
/// non-finite value is written "inf", "-inf" or "nan" in both styles: JsonWriter writes null
/// for it instead (as nlohmann::json did). −0 is written as 0 ("0", "0.0"): it reads back as
/// the same value, without a sign no output means.
char* write_number(char* first, double value, NumberStyle style);

/// `value` as write_number writes it, as a string.
std::string number_text(double value, NumberStyle style = NumberStyle::csv);

}  // namespace railmodal::report
