// CSV batch evaluation (friction/batch.h): columns in any order, pass-through, lossless output,
// and errors that name the line and leave the output empty.

#include "friction/batch.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <sstream>
#include <stdexcept>
#include <string>

#include "friction/pade_printed_law.h"

namespace frictionlab::friction {
namespace {

std::string run(const std::string& csv, std::string* error = nullptr) {
  const PadePrintedLaw law;
  std::istringstream in(csv);
  std::ostringstream out;
  try {
    evaluate_csv(law, in, out);
  } catch (const std::invalid_argument& e) {
    if (error) *error = e.what();
  }
  return out.str();
}

TEST(SplitCsvLine, KeepsQuotedCommasAndEmptyFields) {
  const auto f = split_csv_line(R"(a,"b,c",,d)");
  ASSERT_EQ(f.size(), 4u);
  EXPECT_EQ(f[1], R"("b,c")");
  EXPECT_EQ(f[2], "");
}

TEST(EvaluateCsv, AnyColumnOrderExtraColumnsPassedThroughLosslessOutput) {
  const std::string out = run(
      "id,k,N,psi,b,a,Omega,U,note\n"
      "p1,0.3,10,0.25,0.5,1.5,-2,0.7,\"x, y\"\n"
      "\n"
      "p2,0.1,1,0,1,1,0,1,plain\r\n");
  std::istringstream lines(out);
  std::string header, row1, row2, extra;
  std::getline(lines, header);
  std::getline(lines, row1);
  std::getline(lines, row2);
  EXPECT_FALSE(std::getline(lines, extra));
  EXPECT_EQ(header, "id,k,N,psi,b,a,Omega,U,note,F1,F2,M");
  ASSERT_EQ(row1.rfind("p1,0.3,10,0.25,0.5,1.5,-2,0.7,\"x, y\",", 0), 0u) << row1;

  // The appended values read back to exactly the doubles of a direct evaluation.
  const auto direct = PadePrintedLaw().evaluate({0.7, -2.0, 1.5, 0.5, 0.25, 10.0, 0.3});
  const auto fields = split_csv_line(row1);
  ASSERT_EQ(fields.size(), 12u);
  EXPECT_EQ(std::strtod(std::string(fields[9]).c_str(), nullptr), direct.F1);
  EXPECT_EQ(std::strtod(std::string(fields[10]).c_str(), nullptr), direct.F2);
  EXPECT_EQ(std::strtod(std::string(fields[11]).c_str(), nullptr), direct.M);
  // Pure sliding: F1 = kN = 0.1 exactly, written without loss.
  EXPECT_EQ(row2, "p2,0.1,1,0,1,1,0,1,plain,0.10000000000000001,0,0");
}

TEST(EvaluateCsv, ErrorsNameTheLineAndWriteNothing) {
  struct Case {
    std::string csv, expect;
  };
  const Case cases[] = {
      {"", "input is empty"},
      {"U,Omega,a,b,psi,N\n1,1,1,1,0,1\n", "input line 1: the header lacks column k"},
      {"U,U,Omega,a,b,psi,N,k\n", "input line 1: column U appears twice"},
      {"U,Omega,a,b,psi,N,k\n1,1,1,1,0,1,0.1\n1,1,1,1,0,1\n", "input line 3: has 6 fields, the header has 7"},
      {"U,Omega,a,b,psi,N,k\n1,1,1,1,0,1,0.1\n1,fast,1,1,0,1,0.1\n", "input line 3: column Omega = 'fast' is not a number"},
      {"U,Omega,a,b,psi,N,k\n1,1,1,2,0,1,0.1\n", "input line 2: friction input b = 2 is invalid"},
      {"U,Omega,a,b,psi,N,k\n1,1,1,1,0,-1,0.1\n", "input line 2: friction input N = -1 is invalid"},
  };
  for (const auto& c : cases) {
    std::string error;
    const auto out = run(c.csv, &error);
    EXPECT_EQ(out, "") << c.csv;
    EXPECT_NE(error.find(c.expect), std::string::npos) << "got: '" << error << "'";
  }
}

}  // namespace
}  // namespace frictionlab::friction
