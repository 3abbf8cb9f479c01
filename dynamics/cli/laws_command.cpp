#include <algorithm>
#include <iostream>

#include "dynamics/cli/commands.h"
#include "friction/registry.h"

namespace frictionlab::cli {

void register_laws_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("laws", "List the friction laws, one line each, and the parameters of each");
  cmd->callback([] {
    std::size_t width = 0;
    const auto laws = friction::list_laws();
    for (const auto& law : laws) width = std::max(width, law.name.size());
    std::cout << "Laws, and the parameters a spec NAME:KEY=VALUE[,KEY=VALUE] may set "
                 "(e.g. exact:pressure=uniform):\n";
    for (const auto& law : laws) {
      std::cout << law.name << std::string(width + 2 - law.name.size(), ' ') << law.summary << '\n';
      for (const auto& p : law.parameters) std::cout << "    " << p.describe() << '\n';
    }
  });
}

}  // namespace frictionlab::cli
