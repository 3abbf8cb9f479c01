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
/// a single quote is written twice. Use it for file names, colours, and text the program writes in
/// gnuplot's enhanced-text markup on purpose ('γ_3'); text to be shown as it is goes through
/// gnuplot_text.
[[nodiscard]] std::string gnuplot_quoted(std::string_view text);

/// `text` as a gnuplot string literal that an enhanced-text terminal (every terminal the project's
/// scripts set) shows exactly as `text` in a title, key entry, axis or tic label or `set label`:
/// the characters enhanced text reads as markup, ^ _ @ & ~ { } and \, are escaped with a
/// backslash, so that the law spec decoupled:r_spin=0 is not typeset as r with a subscript s. Use it
/// for every string that comes from the user or from a run: law specs, scenario and study names and
/// descriptions, keys, stop reasons.
[[nodiscard]] std::string gnuplot_text(std::string_view text);

/// The escaped text inside gnuplot_text's quotes, for a string that joins user text to the
/// program's own markup: gnuplot_quoted(gnuplot_escaped(name) + ": final γ_3").
[[nodiscard]] std::string gnuplot_escaped(std::string_view text);

/// As gnuplot_text, for text that reaches a label through a plot's `using` expression
/// (`plot FILE using 1:2:(TEXT) with labels`): gnuplot (5.4) takes one level of backslashes off such
/// a string before the enhanced-text parser reads it, so each escape is doubled.
[[nodiscard]] std::string gnuplot_label_column_text(std::string_view text);

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
