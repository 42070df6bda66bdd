// The checks made before toml11 3.7.1 sees a file (input/toml_preflight.hpp): each input below
// crashed it or came back silently wrong; each must now be an InputError at its line and column.
#include "input/toml_preflight.hpp"

#include <gtest/gtest.h>

#include <string>

#include "input/input_file.hpp"
#include "railmodal/errors.hpp"
#include "railmodal/railmodal.hpp"
#include "test_support.hpp"

namespace railmodal::test {
namespace {

struct Expected {
  int line;
  int column;
  std::string message;
};

Expected rejection(const std::string& content) {
  try {
    input::check_toml_preflight(content, "t.toml");
  } catch (const InputError& e) {
    return {e.line(), e.column(), e.message()};
  }
  return {0, 0, "accepted"};
}

void expect_rejected(const std::string& content, int line, int column, const std::string& part) {
  const Expected e = rejection(content);
  EXPECT_EQ(e.line, line) << content.substr(0, 60);
  EXPECT_EQ(e.column, column) << content.substr(0, 60);
  EXPECT_NE(e.message.find(part), std::string::npos) << e.message;
}

void expect_accepted(const std::string& content) { EXPECT_EQ(rejection(content).message, "accepted") << content; }

std::string repeat(const std::string& s, int n) {
  std::string out;
  for (int i = 0; i < n; ++i) out += s;
  return out;
}

TEST(TomlPreflight, NestingDeeperThan64IsRefusedAtTheBracket) {
  // toml11 3.7.1 recursed once per level and overflowed the stack near 10^4 levels (release).
  expect_accepted("a = " + repeat("[", 64) + "1" + repeat("]", 64) + "\n");
  expect_rejected("# x\na = " + repeat("[", 100000), 2, 4 + 65, "nested more than 64 deep");
  // The table [t] is one level: the 64th inline table is one too many.
  expect_rejected("[t]\na = " + repeat("{b = ", 65) + "1", 2, 5 + 5 * 63, "nested more than 64 deep");
  // Brackets closed again do not add up, and table headers are not nesting.
  expect_accepted(repeat("[[t]]\na = [[1], [2]]\n", 200));
}

TEST(TomlPreflight, DottedKeysAndTableHeadersCountAsNesting) {
  // Issue 18: a key of 10^5 parts, or a header 10^5 deep, overflowed toml11 3.7.1's stack
  // (SIGSEGV in every command). Each part after a key's first, and each part of a header, is a
  // table one level deeper.
  expect_accepted(repeat("a.", 64) + "a = 1\n");
  expect_rejected(repeat("a.", 65) + "a = 1\n", 1, 1 + 2 * 65, "nested more than 64 deep");
  expect_rejected("x = 1\n" + repeat("a.", 100000) + "a = 1\n", 2, 1 + 2 * 65, "nested more than 64 deep");
  expect_accepted("[" + repeat("a.", 63) + "a]\nb = 1\n");
  expect_rejected("[" + repeat("a.", 64) + "a]\nb = 1\n", 1, 2 + 2 * 64, "nested more than 64 deep");
  expect_rejected("[[" + repeat("a.", 100000) + "a]]\n", 1, 3 + 2 * 64, "nested more than 64 deep");
  // Quoted parts and blanks around the dots; the refusal points at the part's opening quote.
  expect_rejected(repeat("'a' . ", 65) + "\"a\" = 1\n", 1, 1 + 6 * 65, "nested more than 64 deep");
  // Header, key, inline tables and arrays add up: 60 + 3 + 1 is the limit (d is the 63rd table).
  const std::string header = "[" + repeat("t.", 59) + "t]\n";
  expect_accepted(header + "a.b.c.d = [1]\n");
  expect_accepted(header + "a.b.c.d.e = 1\n");
  expect_rejected(header + "a.b.c.d.e.f = 1\n", 2, 11, "nested more than 64 deep");
  expect_rejected(header + "a.b.c.d.e = [1]\n", 2, 13, "nested more than 64 deep");
  expect_rejected(header + "a.b.c.d = {x = [1]}\n", 2, 16, "nested more than 64 deep");
  expect_rejected(header + "a = {b.c.d = {}, e.f.g.h.i = 1}\n", 2, 26, "nested more than 64 deep");
  // A key's depth ends with its value: many keys of 60 parts on one line are fine.
  expect_accepted("a = {" + repeat("b." + repeat("c.", 59) + "d = 1, ", 10) + "e = [" + repeat("[", 62) +
                  repeat("]", 62) + "]}\n");
  expect_accepted(header + repeat("a.b.c.d = 1\n", 100) + "[u]\n" + repeat("a.", 63) + "b = 1\n");
}

TEST(TomlPreflight, ControlCharactersAreNamed) {
  // Issue 18: toml11 reported a NUL in a comment as "1:1 invalid key".
  expect_rejected(std::string("a = 1\n# x\0y\n", 13), 2, 4, "a NUL byte (0x00) is not allowed in TOML");
  expect_rejected("a = 'x\x1by'\n", 1, 7, "the control character 0x1b is not allowed");
  expect_rejected("a = 1\rb = 2\n", 1, 6, "a carriage return (0x0d) not followed by a line feed");
  expect_rejected("# \x7f\n", 1, 3, "0x7f");
  expect_accepted("a = 1\r\n# tab\there\r\nb = \"\\u0000\"\n");
}

TEST(TomlPreflight, LinesLongerThan8192BytesAreRefused) {
  // Issue 18: toml11 3.7.1 scans a value's whole line once per value, so 30 000 strings on one
  // line took 32 s; a 50 MB comment line 24 s and 300 MB.
  const auto line = [](size_t length) { return "a = [" + repeat("1,", int(length - 6) / 2) + "]"; };
  ASSERT_EQ(line(input::kMaxTomlLineLength).size(), input::kMaxTomlLineLength);
  expect_accepted("x = 1\n" + line(input::kMaxTomlLineLength) + "\r\n");
  expect_rejected("x = 1\n" + line(input::kMaxTomlLineLength + 2) + "\n", 2, 8193, "longer than 8192 bytes");
  expect_rejected("#" + std::string(size_t(1) << 20, 'c') + "\n", 1, 8193, "longer than 8192 bytes");
  // In file order: what comes first on the line is reported, whatever the line's length.
  expect_rejected("a = " + repeat("[", 10000) + "\n", 1, 4 + 65, "nested more than 64 deep");
  expect_rejected("a = '" + std::string(10000, 'c') + "\xff'\n", 1, 8193, "longer than 8192 bytes");
}

TEST(TomlPreflight, FilesLargerThanTheLimitAreNotReadWhole) {
  const std::string path = write_temp("size.toml", std::string(100, '#'));
  EXPECT_EQ(input::read_input_text(path, 100, "a test").size(), 100u);
  try {
    input::read_input_text(path, 99, "a test");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), path);
    EXPECT_NE(e.message().find("larger than 99 bytes, the limit for a test"), std::string::npos) << e.message();
  }
}

TEST(TomlPreflight, BracketsInStringsAndCommentsAreText) {
  const std::string deep = repeat("[", 1000);
  expect_accepted("a = \"" + deep + "\"\n");
  expect_accepted("a = '" + deep + "'\n");
  expect_accepted("a = \"\"\"\n" + deep + "\n\"\"\"\n");
  expect_accepted("a = '''\n" + deep + "\n'''\n");
  expect_accepted("# " + deep + "\n");
  expect_accepted("a = \"\\\"" + deep + "\"\n");  // an escaped quote does not end the string
  // A multi-line string may end in up to five quotes; what follows is TOML again.
  expect_rejected("a = \"\"\"x\"\"\"\"\"\nb = " + repeat("[", 65), 2, 4 + 65, "nested");
  expect_rejected("a = '''x'''''\nb = " + repeat("[", 65), 2, 4 + 65, "nested");
  // A single-line string ends at its line at the latest (toml11 reports it unterminated).
  expect_rejected("a = \"x\nb = " + repeat("[", 65), 2, 4 + 65, "nested");
}

TEST(TomlPreflight, IntegersMustFitIn64Bits) {
  // toml11 3.7.1 overflowed a signed integer on 63 binary digits (UBSan) and clamped the others.
  expect_accepted("a = 0b" + repeat("1", 62) + "\n");
  expect_rejected("a = 0b" + repeat("0", 63) + "\n", 1, 5, "does not fit in 64 bits");
  // toml11 reads the digits whatever follows them (the fuzzer: 0b00…0lbums.songs]]).
  expect_rejected("a = 0b" + repeat("0", 63) + "lbums.songs]]\n", 1, 5, "does not fit in 64 bits");
  expect_accepted("a = 9_223_372_036_854_775_807\nb = -9223372036854775808\nc = 0x7fffffffffffffff\n");
  expect_rejected("a = 9223372036854775808\n", 1, 5, "the integer 9223372036854775808 does not fit");
  expect_rejected("a = 0x8000000000000000\n", 1, 5, "does not fit");
  expect_rejected("x = 1\na = [1, 0o1000000000000000000000]\n", 2, 9, "does not fit");
  // Floats, dates, keys and quantities in strings are not integers.
  expect_accepted("a = 1e400\nb = 1979-05-27T07:32:00Z\nk99999999999999999999x = 1.5\nc = \"99999999999999999999 kgf\"\n");
}

TEST(TomlPreflight, TableHeadersThroughArrayValuesAreRefused) {
  // toml11 3.7.1 took the last element of the empty array as the table to extend (UBSan).
  expect_rejected("a = []\n[a.b]\nc = 1\n", 2, 1, "the table [a.b] extends 'a', which is an array value");
  expect_rejected("x.a = [ # c\n ]\n[x.a.b.c]\n", 3, 1, "extends 'x.a'");
  expect_rejected("[s]\na = []\n[ s . a . b ]\n", 3, 1, "extends 's.a'");
  expect_rejected("\"a\" = [1]\n['a'.b]\n", 2, 1, "extends 'a'");
  expect_rejected("a = []\n[[a]]\n", 2, 1, "the table [[a]] extends 'a'");
  // Arrays of tables may be extended, and other tables' keys of the same name are others.
  expect_accepted("[[a]]\nx = 1\n[a.b]\ny = 2\n[s]\nv = []\n[t.v]\n[s.w]\n");
  // Only a line's key counts: '=' and brackets inside values and strings are values.
  expect_accepted("a = \"b = []\"\n[b.c]\nd = [[1], [2]]\n[e]\n");
}

TEST(TomlPreflight, InvalidUtf8IsLocated) {
  expect_rejected("a = 1\nb = 'x\xff'\n", 2, 7, "byte 0xff is not UTF-8 text");
  expect_accepted("a = 'Ma\xc3\x9f" "e' # \xe2\x80\x94 \xf0\x9f\x9a\x83\n");
}

TEST(TomlPreflight, VehicleReaderRunsIt) {
  const std::string path = write_temp("deep.toml", "[vehicle]\nname = " + repeat("[", 20000) + "\n");
  try {
    load_vehicle(path);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), path);
    EXPECT_EQ(e.line(), 2);
    EXPECT_EQ(e.column(), 8 + 63);  // [vehicle] is the first level
  }
}

}  // namespace
}  // namespace railmodal::test
