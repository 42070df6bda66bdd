// Matrix Market input: every accepted variant, every error with its line, column and
// message, the model built from M, K (and C) files, and its modes.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <sstream>
#include <thread>

#include "test_support.hpp"

namespace railmodal::test {
namespace {

Eigen::MatrixXd read_dense(const std::string& text, bool require_symmetric = false) {
  return to_dense(read_matrix_market(write_temp("m.mtx", text), require_symmetric).matrix);
}

TEST(MatrixMarket, CoordinateGeneralSumsDuplicates) {
  const Eigen::MatrixXd A = read_dense(
      "%%MatrixMarket matrix coordinate real general\n"
      "% a comment\n"
      "\n"
      "3 3 5\n"
      "1 1 2.5\n"
      "3 2 -1e3\n"
      "2 3 +4\n"
      "1 1 0.5\n"  // a duplicate: summed, as most tools do
      "3 3 1.25E-2\n");
  Eigen::MatrixXd expected(3, 3);
  expected << 3.0, 0, 0, 0, 0, 4.0, 0, -1e3, 1.25e-2;
  EXPECT_EQ(A, expected);  // decimal values that parse exactly
}

TEST(MatrixMarket, CoordinateSymmetricMirrorsTheLowerTriangle) {
  const auto m = read_matrix_market(write_temp("m.mtx",
                                               "%%MatrixMarket matrix coordinate real symmetric\n"
                                               "2 2 3\n1 1 4\n2 1 -1\n2 2 3\n"));
  EXPECT_TRUE(m.symmetric_storage);
  Eigen::MatrixXd expected(2, 2);
  expected << 4, -1, -1, 3;
  EXPECT_EQ(to_dense(m.matrix), expected);
  EXPECT_EQ(m.matrix.nonZeros(), 4);  // sparse, not padded
  EXPECT_TRUE(m.dof_labels.empty());
}

TEST(MatrixMarket, ArrayGeneralIsColumnMajor) {
  const Eigen::MatrixXd A = read_dense("%%MatrixMarket matrix array real general\n2 2\n1\n2\n3\n4\n");
  Eigen::MatrixXd expected(2, 2);
  expected << 1, 3, 2, 4;
  EXPECT_EQ(A, expected);
}

TEST(MatrixMarket, ArraySymmetricHoldsTheLowerTriangleByColumns) {
  const Eigen::MatrixXd A =
      read_dense("%%MatrixMarket matrix array real symmetric\n3 3\n1\n2\n3\n4\n5\n6\n");
  Eigen::MatrixXd expected(3, 3);
  expected << 1, 2, 3, 2, 4, 5, 3, 5, 6;
  EXPECT_EQ(A, expected);
}

TEST(MatrixMarket, IntegerFieldCaseInsensitiveBannerAndCrlf) {
  const Eigen::MatrixXd A =
      read_dense("%%MatrixMarket MATRIX Coordinate INTEGER Symmetric\r\n2 2 2\r\n1 1 7\r\n2 2 -3\r\n");
  Eigen::MatrixXd expected(2, 2);
  expected << 7, 0, 0, -3;
  EXPECT_EQ(A, expected);
}

// The 1 MiB line limit counts the line, not the CR of its CRLF: a line of exactly the limit
// is read whether it ends in LF or CRLF (the CRLF one was refused).
TEST(MatrixMarket, LineOfTheLimitIsReadWithEitherEnding) {
  for (const std::string end : {"\n", "\r\n"}) {
    const std::string comment = "% " + std::string((1 << 20) - 2, 'x') + end;
    EXPECT_EQ(
        read_dense("%%MatrixMarket matrix coordinate real general" + end + comment + "1 1 1" + end + "1 1 4" + end),
        Eigen::MatrixXd::Constant(1, 1, 4.0));
  }
}

TEST(MatrixMarket, CommentsNameDofsAsAListOrOneByOne) {
  const auto list = read_matrix_market(write_temp("list.mtx",
                                                  "%%MatrixMarket matrix coordinate real symmetric\n"
                                                  "% railmodal dofs: body.bounce body.pitch\n"
                                                  "%railmodal dofs: bogie.bounce\n"
                                                  "3 3 1\n1 1 1\n"));
  EXPECT_EQ(list.dof_labels, (std::vector<std::string>{"body.bounce", "body.pitch", "bogie.bounce"}));
  EXPECT_EQ(list.labels_line, 2);
  const auto indexed = read_matrix_market(write_temp("indexed.mtx",
                                                     "%%MatrixMarket matrix coordinate real symmetric\n"
                                                     "3 3 1\n"
                                                     "% railmodal dof 3 tail\n"  // comments may follow the size line
                                                     "1 1 1\n"));
  EXPECT_EQ(indexed.dof_labels, (std::vector<std::string>{"", "", "tail"}));
  // Comments that do not start with the word railmodal are just comments.
  EXPECT_TRUE(read_matrix_market(write_temp("plain.mtx",
                                            "%%MatrixMarket matrix coordinate real general\n"
                                            "% dofs: not a directive; railmodal dofs: neither\n1 1 1\n1 1 1\n"))
                  .dof_labels.empty());
}

TEST(MatrixMarket, WriterRoundTripsExactly) {
  // Values with 17 significant digits and a wide range of magnitudes.
  Eigen::MatrixXd A(3, 3);
  A << 1.0 / 3.0, -2.0e-7 / 7.0, 0.0, -2.0e-7 / 7.0, 6.02214076e23 / 9.0, std::sqrt(2.0), 0.0, std::sqrt(2.0),
      std::acos(-1.0);
  const std::vector<std::string> labels = {"a.bounce", "a.pitch", "b.bounce"};
  for (bool symmetric : {true, false}) {
    std::ostringstream text;
    write_matrix_market(text, A.sparseView(), symmetric, labels);
    const auto back = read_matrix_market(write_temp("round.mtx", text.str()), true);
    EXPECT_EQ(to_dense(back.matrix), A) << text.str();
    EXPECT_EQ(back.dof_labels, labels);
    EXPECT_EQ(back.symmetric_storage, symmetric);
  }
}

// One malformed file: the error's line, column and a part of its message.
struct BadCase {
  const char* name;
  std::string text;
  int line;
  int column;
  const char* message;
  bool require_symmetric = false;
};

const std::string kCoord = "%%MatrixMarket matrix coordinate real general\n";
const std::string kSym = "%%MatrixMarket matrix coordinate real symmetric\n";
const std::string kArray = "%%MatrixMarket matrix array real general\n";

std::vector<BadCase> bad_cases() {
  return {
      {"empty", "", 0, 0, "the file is empty"},
      {"no_banner", "2 2 1\n1 1 1\n", 1, 1, "not a Matrix Market file"},
      {"indented_banner", " %%MatrixMarket matrix coordinate real general\n1 1 0\n", 1, 1, "not a Matrix Market file"},
      {"short_banner", "%%MatrixMarket matrix coordinate real\n", 1, 1, "four words after %%MatrixMarket"},
      {"vector", "%%MatrixMarket vector coordinate real general\n", 1, 16, "object 'vector' is not supported"},
      {"unknown_format", "%%MatrixMarket matrix dense real general\n", 1, 23, "unknown format 'dense'"},
      {"pattern", "%%MatrixMarket matrix coordinate pattern general\n", 1, 34, "field 'pattern' is not supported"},
      {"complex", "%%MatrixMarket matrix coordinate complex general\n", 1, 34, "field 'complex' is not supported"},
      {"unknown_field", "%%MatrixMarket matrix coordinate float general\n", 1, 34, "unknown field 'float'"},
      {"hermitian", "%%MatrixMarket matrix coordinate real hermitian\n", 1, 39,
       "symmetry 'hermitian' is not supported"},
      {"skew", "%%MatrixMarket matrix array real skew-symmetric\n", 1, 34,
       "symmetry 'skew-symmetric' is not supported"},
      {"unknown_symmetry", kCoord.substr(0, 38) + "upper\n", 1, 39, "unknown symmetry 'upper'"},
      {"no_size_line", kCoord + "% only a comment\n", 2, 0, "ends before the size line"},
      {"size_words", kCoord + "2 2\n", 2, 1, "'ROWS COLUMNS ENTRIES', found 2 words"},
      {"array_size_words", kArray + "2 2 4\n", 2, 1, "'ROWS COLUMNS', found 3 words"},
      {"size_not_integer", kCoord + "2 2 x\n", 2, 5, "size 'x' is not a non-negative integer"},
      {"size_negative", kCoord + "2 2 -1\n", 2, 5, "size '-1' is not a non-negative integer"},
      {"not_square", kCoord + "2 3 0\n", 2, 1, "the matrix is 2 × 3: mass, damping and stiffness matrices are square"},
      {"zero_size", kCoord + "0 0 0\n", 2, 1, "the matrix is empty"},
      {"huge_size", kCoord + "20000000 20000000 0\n", 2, 1, "more than the 10000000 railmodal reads"},
      {"row_out_of_range", kCoord + "2 2 1\n3 1 1.0\n", 3, 1, "row index 3 is out of range 1..2"},
      {"column_zero", kCoord + "2 2 1\n1 0 1.0\n", 3, 3, "column index 0 is out of range 1..2"},
      {"index_not_integer", kCoord + "2 2 1\n1.0 1 1.0\n", 3, 1, "row index '1.0' is not a positive integer"},
      {"above_diagonal", kSym + "2 2 1\n1 2 1.0\n", 3, 1, "entry (1, 2) lies above the diagonal"},
      {"entry_words", kCoord + "2 2 1\n1 1\n", 3, 1, "an entry is 'ROW COLUMN VALUE', found 2 words"},
      {"not_a_number", kCoord + "1 1 1\n1 1 abc\n", 3, 5, "'abc' is not a number"},
      {"trailing_garbage", kCoord + "1 1 1\n1 1 1.5kg\n", 3, 5, "'1.5kg' is not a number"},
      {"nan", kCoord + "1 1 1\n1 1 nan\n", 3, 5, "value 'nan' is not a finite number"},
      {"infinity", kCoord + "1 1 1\n1  1 -inf\n", 3, 6, "value '-inf' is not a finite number"},
      {"overflow", kCoord + "1 1 1\n1 1 1e999\n", 3, 5, "value '1e999' is outside the range of a double"},
      {"integer_field", "%%MatrixMarket matrix coordinate integer general\n1 1 1\n1 1 1.5\n", 3, 5,
       "'1.5' is not an integer (the banner declares integer values)"},
      {"too_many", kCoord + "2 2 1\n1 1 1\n% fine\n2 2 1\n", 5, 1,
       "more entries than the 1 entries the size line (line 2)"},
      {"too_few", kCoord + "2 2 3\n1 1 1\n2 2 1\n", 2, 5, "declares 3 entries but the file ends after 2"},
      {"array_too_few", kArray + "2 2\n1\n2\n3\n", 2, 3,
       "declares 4 values (a general 2 × 2 array) but the file ends after 3"},
      {"array_too_many", "%%MatrixMarket matrix array real symmetric\n2 2\n1\n2\n3\n4\n", 6, 1,
       "more entries than the 3 values (a symmetric 2 × 2 array)"},
      {"array_two_per_line", kArray + "2 2\n1 2\n3\n4\n", 3, 3, "one value per line, found 2"},
      {"not_utf8",
       kCoord + "% Ma\xdf"
                "e\n1 1 1\n1 1 1\n",
       2, 5, "byte 0xdf is not UTF-8 text"},
      {"overlong_utf8", kCoord + "% \xc0\xaf\n1 1 1\n1 1 1\n", 2, 3, "byte 0xc0 is not UTF-8 text"},
      {"nul_byte", kCoord + "1 1 1\n1 1 1" + std::string(1, '\0') + "\n", 3, 6, "control character 0x00"},
      {"binary",
       std::string("\x7f"
                   "ELF\x02\x01",
                   6),
       1, 1, "control character 0x7f"},
      {"nul_hole", kCoord + "2 2 1\n" + std::string(100000, '\0') + "\n1 1 1\n", 3, 1, "control character 0x00"},
      {"long_line", kCoord + "% " + std::string(1 << 20, 'x') + "\n1 1 0\n", 2, 1 + (1 << 20),
       "longer than 1048576 bytes"},
      // Issue 18: absurd declared sizes are refused before any entry is read, with the estimate.
      {"too_many_entries", kCoord + "10000000 10000000 20000001\n", 2, 19,
       "declares 20000001 entries, which would need about 2 GB to read; railmodal reads at most 20000000"},
      {"array_too_large", kArray + "5000 5000\n", 2, 1, "declares 25000000 values, which would need about 2.5 GB"},
      {"unknown_directive", kSym + "% railmodal dfos: a b\n2 2 0\n", 2, 13, "unknown railmodal comment 'dfos:'"},
      {"empty_directive", kSym + "% railmodal\n2 2 0\n", 2, 3, "empty railmodal comment"},
      {"list_too_short", kSym + "% railmodal dofs: a\n2 2 0\n", 2, 1, "name 1 DOFs but the matrix has 2 rows"},
      {"list_too_long", kSym + "% railmodal dofs: a b c\n2 2 0\n", 2, 23, "name more DOFs than the 2 rows"},
      {"index_out_of_range", kSym + "2 2 0\n% railmodal dof 5 x\n", 3, 19, "DOF index 5 exceeds the 2 rows"},
      // DOF names come before the size line: each label is bounded, so names cost a bounded memory.
      {"label_too_long", kSym + "% railmodal dofs: " + std::string(257, 'a') + " b\n2 2 0\n", 2, 19,
       "a DOF label of 257 bytes: labels are at most 256 bytes"},
      {"index_zero", kSym + "% railmodal dof 0 x\n2 2 0\n", 2, 17, "DOF index '0' is not a positive integer"},
      {"dof_words", kSym + "% railmodal dof 1\n2 2 0\n", 2, 13, "expected '% railmodal dof INDEX LABEL'"},
      {"duplicate_label", kSym + "% railmodal dofs: a a\n2 2 0\n", 2, 21,
       "DOF label 'a' is given twice (also DOF 1, line 2)"},
      {"index_named_twice", kSym + "% railmodal dof 1 a\n% railmodal dof 1 b\n2 2 0\n", 3, 19,
       "DOF 1 is already named 'a' (line 2)"},
      {"both_forms", kSym + "% railmodal dofs: a b\n% railmodal dof 1 c\n2 2 0\n", 3, 13, "not both"},
      {"asymmetric", kCoord + "2 2 4\n1 1 1\n1 2 1.5\n2 1 2\n2 2 1\n", 4, 1,
       "not symmetric: entry (1, 2) is 1.5 but (2, 1) is 2", true},
      {"lower_triangle_in_general", kCoord + "2 2 3\n1 1 1\n2 1 -1\n2 2 1\n", 4, 1,
       "a file holding only the lower one must say 'symmetric'", true},
      {"asymmetric_array", kArray + "2 2\n1\n2\n3\n4\n", 4, 1, "entry (2, 1) is 2 but (1, 2) is 3", true},
  };
}

class BadMatrixMarket : public ::testing::TestWithParam<BadCase> {};

TEST_P(BadMatrixMarket, ErrorNamesFileLineAndColumn) {
  const BadCase& c = GetParam();
  const std::string path = write_temp(std::string(c.name) + ".mtx", c.text);
  try {
    read_matrix_market(path, c.require_symmetric);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), path);
    EXPECT_EQ(e.line(), c.line) << e.what();
    EXPECT_EQ(e.column(), c.column) << e.what();
    EXPECT_NE(e.message().find(c.message), std::string::npos) << e.what();
  }
}

INSTANTIATE_TEST_SUITE_P(Errors, BadMatrixMarket, ::testing::ValuesIn(bad_cases()),
                         [](const auto& info) { return std::string(info.param.name); });

// Issue 18: a 1 GB file whose third line was a hole of NULs was read whole (2.1 GB, 48 s)
// before the error. The reader must stop at the first bad byte: the file here is a pipe fed
// 64 MiB of NULs, and the writer counts what it got to write before the reader closed it.
TEST(MatrixMarket, StopsReadingAtTheFirstBadByte) {
  const std::string fifo = write_temp("hole.mtx", "");
  std::remove(fifo.c_str());
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  const auto old_handler = std::signal(SIGPIPE, SIG_IGN);  // the writer sees EPIPE instead
  size_t written = 0;
  std::thread writer([&] {
    const int fd = open(fifo.c_str(), O_WRONLY);
    const std::string head = kCoord + "2 2 1\n";
    written += static_cast<size_t>(std::max<ssize_t>(0, write(fd, head.data(), head.size())));
    const std::string hole(1 << 16, '\0');
    for (int chunk = 0; chunk < 1024; ++chunk) {
      const ssize_t n = write(fd, hole.data(), hole.size());
      if (n <= 0) break;
      written += static_cast<size_t>(n);
    }
    close(fd);
  });
  try {
    read_matrix_market(fifo);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 3);
    EXPECT_EQ(e.column(), 1);
  }
  writer.join();
  std::signal(SIGPIPE, old_handler);
  std::remove(fifo.c_str());
  // What the pipe (64 KiB on Linux) and the stream's buffer hold at most, with a margin: far
  // below the 64 MiB a reader of whole lines takes in.
  EXPECT_LT(written, size_t(4) << 20);
}

TEST(MatrixMarket, SymmetryCheckIgnoresRoundOff) {
  // 1e-16 relative: what an exporter's own round-off leaves; well inside 1e-10.
  const std::string text = kCoord + "2 2 4\n1 1 1\n1 2 0.3333333333333333\n2 1 0.33333333333333337\n2 2 1\n";
  EXPECT_NO_THROW(read_matrix_market(write_temp("m.mtx", text), true));
}

TEST(MatrixMarket, MissingFile) {
  try {
    read_matrix_market("/nonexistent/K.mtx");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "/nonexistent/K.mtx: error: cannot open the file: No such file or directory");
  }
}

// The fixed-free chain of three equal masses m and springs k, stored as a symmetric array:
// ω_r = 2 √(k/m) sin((2r − 1)π / (2(2n + 1))), r = 1..n (n = 3), the standard result for a
// uniform chain fixed at one end.
const std::string kChainMass = "%%MatrixMarket matrix array real symmetric\n3 3\n2\n0\n0\n2\n0\n2\n";
const std::string kChainStiffness = "%%MatrixMarket matrix array real symmetric\n3 3\n400\n-200\n0\n400\n-200\n200\n";

TEST(MatrixModel, SpringChainHasTheAnalyticFrequencies) {
  const MatrixModel model =
      load_matrix_model(write_temp("M.mtx", kChainMass), write_temp("K.mtx", kChainStiffness));
  EXPECT_EQ(model.name, "M.mtx, K.mtx");
  EXPECT_EQ(model.labels, (std::vector<std::string>{"dof1", "dof2", "dof3"}));
  EXPECT_EQ(model.damping.nonZeros(), 0);
  const LinearSystem system = to_linear_system(model);
  const ModalResult r = solve_modes(system);
  ASSERT_EQ(r.modes.size(), 3u);
  const double m = 2.0, k = 200.0;
  for (int i = 0; i < 3; ++i) {
    const double omega = 2.0 * std::sqrt(k / m) * std::sin((2 * i + 1) * kPi / 14.0);
    // A 3 × 3 symmetric eigenproblem: a few ulps of round-off.
    EXPECT_NEAR(r.modes[i].omega_rad_s / omega, 1.0, 1e-13) << i;
    EXPECT_EQ(r.modes[i].kind, ModeKind::oscillatory);
    EXPECT_FALSE(r.modes[i].centre.has_value());
  }
  // Named after the DOF with most kinetic energy. Mode r has φⱼ ∝ sin(j(2r − 1)π/7):
  // largest at j = 3, 1, 2 for r = 1, 2, 3.
  EXPECT_EQ(r.modes[0].name, "dof3");
  EXPECT_EQ(r.modes[1].name, "dof1");
  EXPECT_EQ(r.modes[2].name, "dof2");
}

TEST(MatrixModel, ModesTakeTheirNamesFromTheLabels) {
  const std::string mass = "%%MatrixMarket matrix coordinate real symmetric\n"
                           "% railmodal dofs: heavy light\n2 2 2\n1 1 100\n2 2 1\n";
  const std::string stiffness = "%%MatrixMarket matrix coordinate real symmetric\n2 2 3\n1 1 2e4\n2 1 -1e4\n2 2 1e4\n";
  const ModalResult r =
      solve_modes(to_linear_system(load_matrix_model(write_temp("M.mtx", mass), write_temp("K.mtx", stiffness))));
  ASSERT_EQ(r.dofs.size(), 2u);
  EXPECT_EQ(r.dofs[1].label, "light");
  // The light mass rattles on its own spring in the upper mode; both move together in the lower
  // one, where the heavy mass holds almost all the kinetic energy.
  EXPECT_EQ(r.modes[0].name, "heavy");
  EXPECT_EQ(r.modes[1].name, "light");
}

TEST(MatrixModel, MasslessDofIsCondensed) {
  // Fixed-fixed chain of springs k with a massless middle point: the two masses see
  // K = k [[3/2, −1/2], [−1/2, 3/2]], so λ = k/m and 2k/m.
  const std::string mass = "%%MatrixMarket matrix coordinate real symmetric\n3 3 2\n1 1 1\n3 3 1\n";
  const std::string stiffness =
      "%%MatrixMarket matrix coordinate real symmetric\n3 3 5\n1 1 2\n2 1 -1\n2 2 2\n3 2 -1\n3 3 2\n";
  const ModalResult r =
      solve_modes(to_linear_system(load_matrix_model(write_temp("M.mtx", mass), write_temp("K.mtx", stiffness))));
  EXPECT_EQ(r.condensed, std::vector<std::string>{"dof2"});
  ASSERT_EQ(r.modes.size(), 2u);
  EXPECT_NEAR(r.modes[0].eigenvalue, 1.0, 1e-14);  // O(1) numbers: round-off only
  EXPECT_NEAR(r.modes[1].eigenvalue, 2.0, 1e-14);
  // The massless point follows the masses: half their sum.
  EXPECT_NEAR(r.modes[0].shape(1), 0.5 * (r.modes[0].shape(0) + r.modes[0].shape(2)), 1e-14);
}

TEST(MatrixModel, DampingIsReadAndMayBeGeneral) {
  const std::string damping = kCoord + "3 3 2\n1 1 5\n1 2 1\n";
  const MatrixModel model = load_matrix_model(write_temp("M.mtx", kChainMass), write_temp("K.mtx", kChainStiffness),
                                              write_temp("C.mtx", damping));
  EXPECT_EQ(model.name, "M.mtx, K.mtx, C.mtx");
  const LinearSystem s = to_linear_system(model);
  EXPECT_EQ(s.damping(0, 0), 5.0);
  EXPECT_EQ(s.damping(0, 1), 1.0);
  EXPECT_EQ(s.damping(1, 0), 0.0);
  EXPECT_EQ(s.gravity_stiffness.norm(), 0.0);
  EXPECT_EQ(s.dofs[0].body, -1);
}

void expect_model_error(const std::string& mass, const std::string& stiffness, const std::string& damping,
                        const std::string& file, int line, const std::string& message) {
  const std::string m = write_temp("M.mtx", mass), k = write_temp("K.mtx", stiffness);
  const std::string c = damping.empty() ? "" : write_temp("C.mtx", damping);
  try {
    load_matrix_model(m, k, c);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), write_temp(file, file == "M.mtx" ? mass : file == "K.mtx" ? stiffness : damping));
    EXPECT_EQ(e.line(), line) << e.what();
    EXPECT_NE(e.message().find(message), std::string::npos) << e.what();
  }
}

TEST(MatrixModel, SizesMustAgree) {
  const std::string two = "%%MatrixMarket matrix coordinate real symmetric\n% sized below\n2 2 1\n1 1 1\n";
  expect_model_error(kChainMass, two, "", "K.mtx", 3, "the stiffness matrix is 2 × 2 but the mass matrix (");
  expect_model_error(kChainMass, kChainStiffness, two, "C.mtx", 3, "the damping matrix is 2 × 2");
  try {
    load_matrix_model(write_temp("M.mtx", kChainMass), write_temp("K.mtx", two));
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("M.mtx) is 3 × 3"), std::string::npos) << e.what();  // names both files
  }
}

TEST(MatrixModel, MassAndStiffnessMustBeSymmetricDampingNeedNot) {
  const std::string asymmetric = kCoord + "3 3 2\n1 1 5\n1 2 1\n";
  expect_model_error(asymmetric, kChainStiffness, "", "M.mtx", 4, "not symmetric");
  expect_model_error(kChainMass, asymmetric, "", "K.mtx", 4, "not symmetric");
}

TEST(MatrixModel, FilesThatNameDofsMustAgree) {
  const std::string named_k = "%%MatrixMarket matrix array real symmetric\n% railmodal dofs: a b c\n3 3\n"
                              "400\n-200\n0\n400\n-200\n200\n";
  const std::string named_m = "%%MatrixMarket matrix array real symmetric\n% railmodal dofs: a x c\n3 3\n"
                              "2\n0\n0\n2\n0\n2\n";
  expect_model_error(named_m, named_k, "", "K.mtx", 2, "DOF 2 is named 'b' here but 'x' in");
  // Only the stiffness file names them: its labels are used.
  const MatrixModel model = load_matrix_model(write_temp("M.mtx", kChainMass), write_temp("K.mtx", named_k));
  EXPECT_EQ(model.labels, (std::vector<std::string>{"a", "b", "c"}));
}

TEST(MatrixModel, PartialNamesKeepDefaultsAndMustNotTakeThem) {
  const std::string partial = "%%MatrixMarket matrix array real symmetric\n% railmodal dof 2 middle\n3 3\n"
                              "2\n0\n0\n2\n0\n2\n";
  EXPECT_EQ(load_matrix_model(write_temp("M.mtx", partial), write_temp("K.mtx", kChainStiffness)).labels,
            (std::vector<std::string>{"dof1", "middle", "dof3"}));
  const std::string clash = "%%MatrixMarket matrix array real symmetric\n% railmodal dof 2 dof3\n3 3\n"
                            "2\n0\n0\n2\n0\n2\n";
  expect_model_error(clash, kChainStiffness, "", "M.mtx", 2, "DOF 2 is named 'dof3', the default label of DOF 3");
}

// The bundled export of the resort car's vertical model (tools/matrix_market/export_matrices.cpp)
// is the assembled model: same matrices to round-off, same frequencies to 1e-12.
TEST(MatrixModel, BundledResortCarMatchesTheVehicle) {
  const LinearSystem vehicle = assemble(load_vehicle(data_file("resort_car.toml")), DofSet::vertical);
  const std::string dir = std::string(RAILMODAL_DATA_DIR) + "/matrices/";
  const LinearSystem files = to_linear_system(
      load_matrix_model(dir + "resort_car_vertical_M.mtx", dir + "resort_car_vertical_K.mtx"));
  ASSERT_EQ(files.size(), vehicle.size());
  for (int i = 0; i < vehicle.size(); ++i) EXPECT_EQ(files.dofs[i].label, vehicle.dofs[i].label);
  // Written with 17 digits: exact but for the symmetrisation of K's round-off asymmetry.
  EXPECT_EQ(files.mass, vehicle.mass);
  EXPECT_LE((files.stiffness - vehicle.stiffness).cwiseAbs().maxCoeff(), 1e-15 * vehicle.stiffness.norm());
  const ModalResult a = solve_modes(vehicle), b = solve_modes(files);
  ASSERT_EQ(a.modes.size(), b.modes.size());
  for (size_t k = 0; k < a.modes.size(); ++k) {
    EXPECT_NEAR(b.modes[k].frequency_hz / a.modes[k].frequency_hz, 1.0, 1e-12) << k;
    EXPECT_EQ(b.modes[k].kind, a.modes[k].kind);
  }
}

}  // namespace
}  // namespace railmodal::test
