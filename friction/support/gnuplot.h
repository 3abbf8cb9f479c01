#pragma once
// Running gnuplot on the scripts the figures are written as, and quoting text inside them.
// gnuplot is started directly (no shell), in the scripts' folder, so that scripts use relative
// paths and `cd DIR && gnuplot NAME.gp` redraws a figure by hand.

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace frictionlab::support {

/// `text` as a gnuplot string literal: in single quotes, where gnuplot interprets no escapes and
/// a single quote is written twice. Use it for every file name, title and label in a script.
[[nodiscard]] std::string gnuplot_quoted(std::string_view text);

/// Whether gnuplot can be started and accepts `set terminal TERMINAL` ("pngcairo", "png").
[[nodiscard]] bool gnuplot_has_terminal(std::string_view terminal);

struct GnuplotRun {
  bool ok = false;      ///< gnuplot ran and exited 0
  bool found = true;    ///< false if gnuplot could not be started at all
  std::string message;  ///< why not, in one line (empty when ok)
};

/// Runs `gnuplot SCRIPT` with working directory `dir`, standard input from /dev/null, and its
/// output and messages into `log` (relative to `dir`, or absolute). An empty log of a successful
/// run is removed; otherwise it is kept for the reader.
[[nodiscard]] GnuplotRun run_gnuplot(const std::filesystem::path& dir, const std::filesystem::path& script,
                                     const std::filesystem::path& log);

/// Runs every script in `dir` in turn (its log NAME.log beside it) and returns one line per
/// failure; if gnuplot cannot be started at all, one line saying so and where the scripts are,
/// and the rest are not tried. Empty when every figure was drawn.
[[nodiscard]] std::vector<std::string> run_gnuplot_scripts(const std::filesystem::path& dir,
                                                           const std::vector<std::string>& scripts);

}  // namespace frictionlab::support
