// CSV batch evaluation (friction/batch.h): columns in any order, pass-through, lossless output,
// errors that name the line and leave the output empty, several laws, the on-error choices,
// byte-order marks and blank lines, numbers outside the double range, failed writes, and memory
// that does not grow with the table.

#include "friction/batch.h"

#include <gtest/gtest.h>
#include <sys/resource.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <stdexcept>
#include <streambuf>
#include <string>
#include <vector>

#include "friction/pade_printed_law.h"
#include "friction/pade_reconstructed_law.h"
#include "friction/registry.h"

namespace frictionlab::friction {
namespace batch_test {

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
  EXPECT_EQ(header, "id,k,N,psi,b,a,Omega,U,note,law,F1,F2,M");
  ASSERT_EQ(row1.rfind("p1,0.3,10,0.25,0.5,1.5,-2,0.7,\"x, y\",pade-printed,", 0), 0u) << row1;

  // The appended values read back to exactly the doubles of a direct evaluation.
  const auto direct = PadePrintedLaw().evaluate({0.7, -2.0, 1.5, 0.5, 0.25, 10.0, 0.3});
  const auto fields = split_csv_line(row1);
  ASSERT_EQ(fields.size(), 13u);
  EXPECT_EQ(std::strtod(std::string(fields[10]).c_str(), nullptr), direct.F1);
  EXPECT_EQ(std::strtod(std::string(fields[11]).c_str(), nullptr), direct.F2);
  EXPECT_EQ(std::strtod(std::string(fields[12]).c_str(), nullptr), direct.M);
  // Pure sliding: F1 = kN is the double nearest 0.1, written in the shortest text that reads back
  // to it (as the input wrote it), not as 0.10000000000000001.
  EXPECT_EQ(row2, "p2,0.1,1,0,1,1,0,1,plain,pade-printed,0.1,0,0");
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
      {"U,Omega,a,b,psi,N,k\n+-1,1,1,1,0,1,0.1\n", "input line 2: column U = '+-1' is not a number"},
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

TEST(EvaluateCsv, AcceptsAByteOrderMarkAndBlankLines) {
  // A UTF-8 byte-order mark (spreadsheets write one) and blank lines, before the header too, are
  // not data.
  std::string error;
  const std::string out = run("\xEF\xBB\xBF\n  \r\nU,Omega,a,b,psi,N,k\r\n\n1,0,1,1,0,1,0.5\n\n", &error);
  EXPECT_EQ(error, "");
  EXPECT_EQ(out, "U,Omega,a,b,psi,N,k,law,F1,F2,M\n1,0,1,1,0,1,0.5,pade-printed,0.5,0,0\n");
  // Line numbers still count the blank lines.
  run("\xEF\xBB\xBF\nU,Omega,a,b,psi,N,k\n\n1,0,1,1,0,1,x\n", &error);
  EXPECT_NE(error.find("input line 4: column k = 'x' is not a number"), std::string::npos) << error;
}

TEST(EvaluateCsv, NamesNumbersOutsideTheDoubleRange) {
  struct Case {
    std::string value, expect;
  };
  const Case cases[] = {
      {"1e999", "input line 2: column U = '1e999' is out of the range of a double (magnitude above"},
      {"-1e999", "column U = '-1e999' is out of the range of a double (magnitude above"},
      {"1e-400", "column U = '1e-400' is out of the range of a double (nonzero, magnitude below"},
  };
  for (const auto& c : cases) {
    std::string error;
    EXPECT_EQ(run("U,Omega,a,b,psi,N,k\n" + c.value + ",1,1,1,0,1,0.1\n", &error), "");
    EXPECT_NE(error.find(c.expect), std::string::npos) << "got: '" << error << "'";
  }
  // Subnormal numbers are doubles: accepted.
  std::string error;
  EXPECT_NE(run("U,Omega,a,b,psi,N,k\n1e-310,1,1,1,0,1,0.1\n", &error), "");
  EXPECT_EQ(error, "");
}

// A stream buffer that accepts `capacity` characters and then fails, like a full disk.
class FullDisk : public std::streambuf {
 public:
  explicit FullDisk(std::size_t capacity) : capacity_(capacity) {}

 protected:
  int_type overflow(int_type c) override {
    if (traits_type::eq_int_type(c, traits_type::eof())) return traits_type::not_eof(c);
    if (used_ == capacity_) return traits_type::eof();
    ++used_;
    return c;
  }

 private:
  std::size_t capacity_;
  std::size_t used_ = 0;
};

TEST(EvaluateCsv, AFailedWriteIsAnError) {
  const PadePrintedLaw law;
  for (const std::size_t capacity : {0, 10, 60}) {
    FullDisk disk(capacity);
    std::ostream out(&disk);
    std::istringstream in("U,Omega,a,b,psi,N,k\n1,0,1,1,0,1,0.5\n1,1,1,0.5,0,1,0.5\n");
    try {
      evaluate_csv(law, in, out);
      ADD_FAILURE() << "no exception with room for " << capacity << " characters";
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find("cannot write the output"), std::string::npos) << e.what();
    }
  }
}

TEST(EvaluateCsv, SeveralLawsAddALawColumnOneRowPerLawInTheOrderGiven) {
  const PadePrintedLaw printed;
  const PadeReconstructedLaw reconstructed;
  std::istringstream in("id,U,Omega,a,b,psi,N,k\nr1,1,2,1,0.5,0.3,1,1\nr2,0.5,-1,1,0.2,1.1,2,0.5\n");
  std::ostringstream out;
  const auto summary = evaluate_csv({&reconstructed, &printed}, in, out);
  EXPECT_EQ(summary.rows, 2u);
  EXPECT_EQ(summary.written, 4u);
  const auto row = [](const std::string& prefix, const FrictionLaw& law, const ContactInput& c) {
    return prefix + "," + std::string(law.name()) + "," + format_forces(law.evaluate(c)) + "\n";
  };
  const ContactInput c1{1, 2, 1, 0.5, 0.3, 1, 1};
  const ContactInput c2{0.5, -1, 1, 0.2, 1.1, 2, 0.5};
  EXPECT_EQ(out.str(), "id,U,Omega,a,b,psi,N,k,law,F1,F2,M\n" + row("r1,1,2,1,0.5,0.3,1,1", reconstructed, c1) +
                           row("r1,1,2,1,0.5,0.3,1,1", printed, c1) + row("r2,0.5,-1,1,0.2,1.1,2,0.5", reconstructed, c2) +
                           row("r2,0.5,-1,1,0.2,1.1,2,0.5", printed, c2));
}

TEST(EvaluateCsv, TheLawColumnNamesEachLawByItsSpecAsOneCsvField) {
  // A spec with several parameters has commas: the law column quotes it (RFC 4180), so that the
  // table keeps its columns and split_csv_line reads the spec back whole.
  LawRegistration r;
  r.name = "test-two-parameters";
  r.summary = "test law: reconstructed Pade under another name";
  r.parameters = {LawParameter::number("x", 0.0, false, 1.0, false, "", 0.5, "", "unused"),
                  LawParameter::number("y", 0.0, false, 1.0, false, "", 0.5, "", "unused")};
  r.factory = [](const LawArguments&) {
    struct Renamed final : FrictionLaw {
      std::string_view name() const override { return "test-two-parameters"; }
      std::string_view summary() const override { return "test"; }
      FrictionForces do_evaluate(const ContactInput& in) const override { return PadeReconstructedLaw().evaluate(in); }
    };
    return std::make_unique<Renamed>();
  };
  register_law(r);
  const auto two = make_law("test-two-parameters:x=0.25,y=1");
  const auto plain = make_law("pade-printed");
  std::istringstream in("U,Omega,a,b,psi,N,k\n1,2,1,0.5,0.3,1,1\n");
  std::ostringstream out;
  (void)evaluate_csv({two.get(), plain.get()}, in, out);
  std::istringstream lines(out.str());
  std::string header, first, second;
  std::getline(lines, header);
  std::getline(lines, first);
  std::getline(lines, second);
  EXPECT_EQ(first.rfind("1,2,1,0.5,0.3,1,1,\"test-two-parameters:x=0.25,y=1\",", 0), 0u) << first;
  EXPECT_EQ(split_csv_line(first).size(), split_csv_line(header).size());
  EXPECT_EQ(second.rfind("1,2,1,0.5,0.3,1,1,pade-printed,", 0), 0u) << second;
  EXPECT_EQ(csv_field("exact:pressure=uniform"), "exact:pressure=uniform");
  EXPECT_EQ(csv_field("a:x=1,y=2"), "\"a:x=1,y=2\"");
  EXPECT_EQ(csv_field("say \"hi\""), "\"say \"\"hi\"\"\"");
  EXPECT_TRUE(unregister_law("test-two-parameters"));
}

TEST(EvaluateCsv, OnErrorSkipOrNanKeepsTheGoodRowsAndReportsTheBadOnes) {
  // Line 3 has a bad number; line 4 is on a pole of the printed law (k N = 1e300 N, 1e-12 from
  // the root of its F2 denominator), which the reconstructed law evaluates.
  const double mu = 0.5, psi = 0.6;
  const auto c = pade_printed_coefficients(mu, psi);
  const double s_pole = (-c.a3 + std::sqrt(c.a3 * c.a3 - 4.0 * c.a4)) / 2.0 * (1 + 1e-12);
  char pole_row[200];
  std::snprintf(pole_row, sizeof pole_row, "%.17g,1,1,0.5,0.6,1e300,1", s_pole);
  const std::string csv = "U,Omega,a,b,psi,N,k\n1,0,1,1,0,1,0.5\n1,x,1,1,0,1,0.5\n" + std::string(pole_row) + "\n";
  const PadePrintedLaw printed;
  const PadeReconstructedLaw reconstructed;
  const std::vector<const FrictionLaw*> laws = {&printed, &reconstructed};
  std::vector<std::size_t> bad_lines;
  BatchOptions options;
  options.on_bad_row = [&](std::size_t line, const std::string& reason) {
    bad_lines.push_back(line);
    EXPECT_EQ(reason.find('\n'), std::string::npos);
  };

  options.on_error = OnError::skip;
  std::istringstream in1(csv);
  std::ostringstream out1;
  auto summary = evaluate_csv(laws, in1, out1, options);
  EXPECT_EQ(summary.rows, 3u);
  EXPECT_EQ(summary.bad, 2u);      // the bad number (the whole row), the pole (printed only)
  EXPECT_EQ(summary.written, 3u);  // line 2 twice, line 4 by the reconstructed law
  EXPECT_EQ(bad_lines, (std::vector<std::size_t>{3, 4}));
  EXPECT_EQ(out1.str().find(",x,"), std::string::npos);
  EXPECT_NE(out1.str().find(std::string(pole_row) + ",pade-reconstructed,"), std::string::npos);
  EXPECT_EQ(out1.str().find(std::string(pole_row) + ",pade-printed,"), std::string::npos);

  options.on_error = OnError::nan;
  bad_lines.clear();
  std::istringstream in2(csv);
  std::ostringstream out2;
  summary = evaluate_csv(laws, in2, out2, options);
  EXPECT_EQ(summary.written, 6u);
  EXPECT_NE(out2.str().find("1,x,1,1,0,1,0.5,pade-printed,nan,nan,nan\n1,x,1,1,0,1,0.5,pade-reconstructed,nan,nan,nan\n"),
            std::string::npos)
      << out2.str();
  EXPECT_NE(out2.str().find(std::string(pole_row) + ",pade-printed,nan,nan,nan\n"), std::string::npos);

  std::istringstream in3(csv);
  std::ostringstream out3;
  EXPECT_THROW(evaluate_csv(laws, in3, out3), std::invalid_argument);  // stop: the default
  EXPECT_EQ(out3.str(), "");
}

TEST(EvaluateCsv, OnErrorChoicesAreParsed) {
  EXPECT_EQ(parse_on_error("stop"), OnError::stop);
  EXPECT_EQ(parse_on_error("skip"), OnError::skip);
  EXPECT_EQ(parse_on_error("nan"), OnError::nan);
  EXPECT_THROW((void)parse_on_error("ignore"), std::invalid_argument);
}

// An input of `rows` copies of one contact, produced as it is read (never held in memory).
class GeneratedTable : public std::streambuf {
 public:
  explicit GeneratedTable(std::size_t rows) : rows_(rows) { set(header_); }

 protected:
  int_type underflow() override {
    if (gptr() < egptr()) return traits_type::to_int_type(*gptr());
    if (rows_ == 0) return traits_type::eof();
    --rows_;
    set(row_);
    return traits_type::to_int_type(*gptr());
  }

 private:
  void set(std::string& s) { setg(s.data(), s.data(), s.data() + s.size()); }
  std::size_t rows_;
  std::string header_ = "id,U,Omega,a,b,psi,N,k\n";
  std::string row_ = "some-identifier,0.25,-3.5,0.012,0.004,0.7,15.5,0.3\n";
};

// Counts what is written and keeps none of it.
class CountingSink : public std::streambuf {
 public:
  std::size_t count = 0;

 protected:
  int_type overflow(int_type c) override {
    if (!traits_type::eq_int_type(c, traits_type::eof())) ++count;
    return traits_type::not_eof(c);
  }
  std::streamsize xsputn(const char*, std::streamsize n) override {
    count += static_cast<std::size_t>(n);
    return n;
  }
};

long peak_rss_kib() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss;  // KiB on Linux
}

TEST(EvaluateCsv, MemoryStaysBoundedOnALargeTable) {
  // 300,000 rows make ~32 MB of output; a writer that holds the table would grow the process by
  // at least that much. Streaming keeps the growth to buffers: 8 MB is far above them and far
  // below the table (peak resident size, which only grows, so it bounds every moment).
  constexpr std::size_t kRows = 300000;
  constexpr long kAllowedGrowthKiB = 8 * 1024;
  const PadePrintedLaw law;
  GeneratedTable table(kRows);
  std::istream in(&table);
  CountingSink sink;
  std::ostream out(&sink);
  const long before = peak_rss_kib();
  EXPECT_EQ(evaluate_csv(law, in, out), kRows);
  const long growth = peak_rss_kib() - before;
  EXPECT_GT(sink.count, kRows * 100);
  EXPECT_LT(growth, kAllowedGrowthKiB) << "peak resident size grew by " << growth << " KiB";
}

}  // namespace
}  // namespace frictionlab::friction
