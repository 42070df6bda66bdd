// The checks made before toml11 3.7.1 sees a file (input/toml_preflight.hpp): each input below
// crashed it or came back silently wrong; each must now be an InputError at its line and column.
#include "input/toml_preflight.hpp"

#include <gtest/gtest.h>

#include <string>

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
  expect_rejected("[t]\na = " + repeat("{b = ", 65) + "1", 2, 5 + 5 * 64, "nested more than 64 deep");
  // Brackets closed again do not add up, and table headers are not nesting.
  expect_accepted(repeat("[[t]]\na = [[1], [2]]\n", 200));
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
    EXPECT_EQ(e.column(), 8 + 64);
  }
}

}  // namespace
}  // namespace railmodal::test
