#include <algorithm>
#include <iostream>

#include "dynamics/cli/commands.h"
#include "friction/registry.h"

namespace frictionlab::cli {

void register_laws_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("laws", "List the friction laws, one line each, with their other names (aliases) and parameters");
  cmd->callback([] {
    std::size_t width = 0;
    const auto laws = friction::list_laws();
    for (const auto& law : laws) width = std::max(width, law.name.size());
    // The summaries below write kN: define it before a reader meets it (not kilonewtons).
    std::cout << "Laws, and the parameters a spec NAME:KEY=VALUE[,KEY=VALUE] may set "
                 "(e.g. exact:pressure=uniform); kN = k·N, the friction coefficient times the normal force "
                 "(not kilonewtons), kNa = k·N·a:\n";
    for (const auto& law : laws) {
      std::cout << law.name << std::string(width + 2 - law.name.size(), ' ') << law.summary << '\n';
      if (!law.aliases.empty()) {
        // Other names: of the law itself, or "name (= spec)" for a spec of it.
        std::cout << "    also named ";
        for (std::size_t i = 0; i < law.aliases.size(); ++i) {
          const auto& a = law.aliases[i];
          std::cout << (i ? ", " : "") << a.name << (a.spec == law.name ? "" : " (= " + a.spec + ")");
        }
        std::cout << '\n';
      }
      for (const auto& p : law.parameters) std::cout << "    " << p.describe() << '\n';
    }
  });
}

}  // namespace frictionlab::cli
