// frictionlab: exact and approximate laws of coupled dry friction, and the dynamics they drive.
// Every error reaches the user as one line on stderr and a non-zero exit code.

#include <csignal>
#include <exception>
#include <iostream>

#include "dynamics/cli/commands.h"
#include "friction/support/checked_output.h"

int main(int argc, char** argv) {
  CLI::App app{"frictionlab: exact vs approximate coupled dry friction (sliding + spinning)\n"
               "over an elliptic Hertz contact patch, at a point and along a motion."};
  app.require_subcommand(1);
  frictionlab::cli::register_laws_command(app);
  frictionlab::cli::register_friction_command(app);
  frictionlab::cli::register_simulate_command(app);
  frictionlab::cli::register_accuracy_command(app);
  frictionlab::cli::register_paper_command(app);
  // A file-size limit (ulimit -f) is then an error of the write that hits it, reported like a
  // full disk, instead of a signal that kills the process mid-row.
  std::signal(SIGXFSZ, SIG_IGN);
  try {
    app.parse(argc, argv);
    frictionlab::support::finish_standard_output();
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const std::exception& e) {
    std::cerr << "frictionlab: error: " << e.what() << '\n';
    return 1;
  }
  return 0;
}
