#pragma once
// The command line of a subcommand as a reader can retype it, rebuilt from what CLI11 parsed: the
// options given, in their declared order, under their long names; options left out stay out (their
// defaults apply again). Reports record it (the "how to redo this" line).
#include <initializer_list>
#include <string>
#include <string_view>

#include <CLI/CLI.hpp>

namespace frictionlab::cli {

/// "frictionlab NAME --opt value ...". Values of a list option are joined with ','; a value with a
/// character a shell would read is single-quoted. Options named in `omit` (e.g. --threads: they do
/// not change the results) are left out.
[[nodiscard]] std::string retypable_command(const CLI::App& subcommand,
                                            std::initializer_list<std::string_view> omit = {});

}  // namespace frictionlab::cli
