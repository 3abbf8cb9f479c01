#pragma once
// The subcommands of `frictionlab`; each registers itself on the application, in its own file.

#include <CLI/CLI.hpp>

namespace frictionlab::cli {

void register_laws_command(CLI::App& app);      // laws_command.cpp
void register_friction_command(CLI::App& app);  // friction_command.cpp
void register_simulate_command(CLI::App& app);  // simulate_command.cpp
void register_accuracy_command(CLI::App& app);  // accuracy_command.cpp
void register_paper_command(CLI::App& app);     // paper_command.cpp
void register_ensemble_command(CLI::App& app);  // ensemble_command.cpp
void register_calibrate_command(CLI::App& app); // calibrate_command.cpp
void register_puck_study_command(CLI::App& app);  // puck_study_command.cpp
void register_tippe_top_command(CLI::App& app);   // tippe_top_command.cpp

}  // namespace frictionlab::cli
