#include "friction/support/gnuplot.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace frictionlab::support {
namespace {

namespace fs = std::filesystem;

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void write(const fs::path& p, const std::string& text) { std::ofstream(p) << text; }

fs::path fresh_dir(const std::string& tag) {
  const fs::path dir = fs::temp_directory_path() / ("frictionlab_gnuplot_" + tag + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

TEST(SupportGnuplot, QuotingDoublesSingleQuotesOnly) {
  EXPECT_EQ(gnuplot_quoted("plain"), "'plain'");
  EXPECT_EQ(gnuplot_quoted("it's"), "'it''s'");
  EXPECT_EQ(gnuplot_quoted("a\\n \"b\" $HOME"), "'a\\n \"b\" $HOME'");  // nothing else is special
  EXPECT_EQ(gnuplot_quoted(""), "''");
}

// gnuplot itself reads the quoted strings back: what it prints is what was quoted.
TEST(SupportGnuplot, GnuplotReadsQuotedTextBack) {
  if (!gnuplot_has_terminal("dumb")) GTEST_SKIP() << "gnuplot is not installed";
  const fs::path dir = fresh_dir("quote");
  const std::string tricky = "it's a 'test' with \\n, \"quotes\" and $(echo no)";
  write(dir / "q.gp", "set print " + gnuplot_quoted("printed name's.txt") + "\nprint " + gnuplot_quoted(tricky) + "\n");
  const GnuplotRun run = run_gnuplot(dir, "q.gp", "q.log");
  ASSERT_TRUE(run.ok) << run.message << slurp(dir / "q.log");
  EXPECT_EQ(slurp(dir / "printed name's.txt"), tricky + "\n");
  EXPECT_FALSE(fs::exists(dir / "q.log"));  // empty log of a good run removed
  fs::remove_all(dir);
}

TEST(SupportGnuplot, AFailingScriptKeepsItsLog) {
  if (!gnuplot_has_terminal("dumb")) GTEST_SKIP() << "gnuplot is not installed";
  const fs::path dir = fresh_dir("fail");
  write(dir / "bad.gp", "this is not gnuplot\n");
  const GnuplotRun run = run_gnuplot(dir, "bad.gp", "bad.log");
  EXPECT_FALSE(run.ok);
  EXPECT_TRUE(run.found);
  EXPECT_NE(run.message.find("bad.gp"), std::string::npos) << run.message;
  EXPECT_NE(run.message.find("bad.log"), std::string::npos) << run.message;
  EXPECT_FALSE(slurp(dir / "bad.log").empty());
  fs::remove_all(dir);
}

TEST(SupportGnuplot, AnUnknownTerminalIsReported) {
  if (!gnuplot_has_terminal("dumb")) GTEST_SKIP() << "gnuplot is not installed";
  EXPECT_FALSE(gnuplot_has_terminal("no-such-terminal"));
}

TEST(SupportGnuplot, ScriptsRunInTurnEachFailureOneLine) {
  if (!gnuplot_has_terminal("dumb")) GTEST_SKIP() << "gnuplot is not installed";
  const fs::path dir = fresh_dir("scripts");
  write(dir / "one.gp", "set print 'one.txt'\nprint 1\n");
  write(dir / "bad.gp", "this is not gnuplot\n");
  write(dir / "two.gp", "set print 'two.txt'\nprint 2\n");
  const std::vector<std::string> errors = run_gnuplot_scripts(dir, {"one.gp", "bad.gp", "two.gp"});
  ASSERT_EQ(errors.size(), 1U);
  EXPECT_NE(errors[0].find("bad.gp"), std::string::npos) << errors[0];
  EXPECT_TRUE(fs::exists(dir / "one.txt"));
  EXPECT_TRUE(fs::exists(dir / "two.txt"));  // a failure does not stop the others
  EXPECT_TRUE(fs::exists(dir / "bad.log"));
  EXPECT_TRUE(run_gnuplot_scripts(dir, {"one.gp"}).empty());
  fs::remove_all(dir);
}

TEST(SupportGnuplot, AMissingFolderIsAMessage) {
  const GnuplotRun run = run_gnuplot("/no/such/folder", "x.gp", "x.log");
  EXPECT_FALSE(run.ok);
  EXPECT_NE(run.message.find("/no/such/folder"), std::string::npos) << run.message;
}

}  // namespace
}  // namespace frictionlab::support
