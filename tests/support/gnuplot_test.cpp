#include "friction/support/gnuplot.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace frictionlab::support {
namespace gnuplot_test {

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

TEST(SupportGnuplot, TextEscapesEnhancedTextMarkup) {
  EXPECT_EQ(gnuplot_text("plain text, (1 + 2) * 3 = 9 ×"), "'plain text, (1 + 2) * 3 = 9 ×'");
  EXPECT_EQ(gnuplot_text("decoupled:r_spin=0"), "'decoupled:r\\_spin=0'");
  EXPECT_EQ(gnuplot_text("a^2 {b} @c &d ~e f\\g it's"), "'a\\^2 \\{b\\} \\@c \\&d \\~e f\\\\g it''s'");
  EXPECT_EQ(gnuplot_label_column_text("r_spin f\\g"), "'r\\\\_spin f\\\\\\\\g'");
}

// gnuplot's own enhanced-text typesetting (the dumb terminal draws it as text) shows a title, a key
// entry, a `set label` and a label from a `using` column exactly as given; unescaped, the same
// text loses its '_' to a subscript.
TEST(SupportGnuplot, EnhancedTextShowsTheTextAsItIs) {
  if (!gnuplot_has_terminal("dumb")) GTEST_SKIP() << "gnuplot is not installed";
  const fs::path dir = fresh_dir("enhanced");
  const std::string text = "decoupled:r_spin=0 a^2 {b} @c &d ~e f\\g it's";
  const auto script = [&](const std::string& title, const std::string& key, const std::string& label,
                          const std::string& column) {
    return "set terminal dumb enhanced size 160,24\nset output 'out.txt'\nset xrange [0:10]\nset yrange [0:10]\n"
           "set key top left\nset title " + title + "\nset label 1 " + label + " at 1,6\n"
           "plot '-' using 1:2:(" + column + ") with labels left notitle, 2 title " + key + "\n1 3\ne\n";
  };
  write(dir / "escaped.gp", script(gnuplot_text("T: " + text), gnuplot_text("K: " + text), gnuplot_text("L: " + text),
                                   gnuplot_label_column_text("C: " + text)));
  GnuplotRun run = run_gnuplot(dir, "escaped.gp", "escaped.log");
  ASSERT_TRUE(run.ok) << run.message << slurp(dir / "escaped.log");
  const std::string drawn = slurp(dir / "out.txt");
  for (const char* what : {"T: ", "K: ", "L: ", "C: "})
    EXPECT_NE(drawn.find(what + text), std::string::npos) << what << "\n" << drawn;
  // The check can fail: quoted only, the '_' becomes a subscript and the text is not found.
  write(dir / "raw.gp", script(gnuplot_quoted("T: r_spin"), gnuplot_quoted("K: r_spin"), gnuplot_quoted("L: r_spin"),
                               gnuplot_quoted("C: r_spin")));
  run = run_gnuplot(dir, "raw.gp", "raw.log");
  ASSERT_TRUE(run.ok) << run.message << slurp(dir / "raw.log");
  const std::string raw = slurp(dir / "out.txt");
  for (const char* what : {"T: ", "K: ", "L: ", "C: "})
    EXPECT_EQ(raw.find(std::string(what) + "r_spin"), std::string::npos) << what << "\n" << raw;
  fs::remove_all(dir);
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
