#include "report/number_text.hpp"

#include <charconv>
#include <cmath>
#include <cstring>

namespace railmodal::report {

namespace {

// Fixed notation while the decimal point falls within these places of the first digit
// (nlohmann::json's dtoa: −4 < n ≤ 15 with n the position of the point after the first digit;
// 1e-4 is "0.0001", 1e-5 "1e-05", 1e15 "1e+15").
constexpr int kLowestFixedPoint = -3, kHighestFixedPoint = 15;

char* write_zeros(char* p, int count) {
  for (int i = 0; i < count; ++i) *p++ = '0';
  return p;
}

}  // namespace

char* write_number(char* first, double value, NumberStyle style) {
  // −0 (a negated or rounded-away zero: a mode shape's zero component, a wheel load at a dead
  // centre) is written as 0: equal in value, and "-0" in a file reads as a sign that means nothing.
  if (value == 0.0) value = 0.0;
  if (style == NumberStyle::csv) return std::to_chars(first, first + kNumberTextMax, value).ptr;
  char* p = first;
  if (!std::isfinite(value)) {
    const char* text = std::isnan(value) ? "nan" : value < 0 ? "-inf" : "inf";
    const size_t n = std::strlen(text);
    std::memcpy(p, text, n);
    return p + n;
  }
  if (value == 0.0) {
    *p++ = '0';
    *p++ = '.', *p++ = '0';  // a double stays a double for a reader that types numbers by their text
    return p;
  }
  // The shortest digits that round-trip, as d.ddde±XX.
  char sci[kNumberTextMax];
  const char* end = std::to_chars(sci, sci + sizeof sci, value, std::chars_format::scientific).ptr;
  const char* s = sci;
  if (*s == '-') *p++ = *s++;
  const char* e = static_cast<const char*>(std::memchr(s, 'e', static_cast<size_t>(end - s)));
  char digits[20];
  int count = 0;
  for (const char* d = s; d < e; ++d)
    if (*d != '.') digits[count++] = *d;
  int exponent = 0;
  std::from_chars(e + (e[1] == '+' ? 2 : 1), end, exponent);
  const int point = exponent + 1;  // the decimal point sits after this many digits
  if (count <= point && point <= kHighestFixedPoint) {  // a whole number
    std::memcpy(p, digits, static_cast<size_t>(count));
    p = write_zeros(p + count, point - count);
    *p++ = '.', *p++ = '0';
    return p;
  }
  if (0 < point && point <= kHighestFixedPoint) {
    std::memcpy(p, digits, static_cast<size_t>(point));
    p += point;
    *p++ = '.';
    std::memcpy(p, digits + point, static_cast<size_t>(count - point));
    return p + (count - point);
  }
  if (kLowestFixedPoint <= point && point <= 0) {
    *p++ = '0';
    *p++ = '.';
    p = write_zeros(p, -point);
    std::memcpy(p, digits, static_cast<size_t>(count));
    return p + count;
  }
  const size_t n = static_cast<size_t>(end - s);  // to_chars wrote d.ddde±XX already
  std::memcpy(p, s, n);
  return p + n;
}

std::string number_text(double value, NumberStyle style) {
  char text[kNumberTextMax];
  return std::string(text, write_number(text, value, style));
}

}  // namespace railmodal::report
