#include "dynamics/io/run_folder.h"

#include <system_error>

#include "friction/support/checked_output.h"
#include "friction/support/errors.h"

namespace frictionlab::dynamics {

void start_run_folder(const std::filesystem::path& out_dir, const std::string& source,
                      const std::string& resolved_toml) {
  std::error_code ec;
  std::filesystem::create_directories(out_dir, ec);
  if (ec) throw support::OutputError("cannot create the output folder '" + out_dir.string() + "': " + ec.message());
  support::write_file_atomically(out_dir / "scenario.toml", "# " + support::one_line(source) +
                                                                " resolved; rerun: frictionlab simulate scenario.toml\n" +
                                                                resolved_toml + "\n");
}

void write_run_summary(const std::filesystem::path& path, support::Json summary, const TrajectoryOutput& output) {
  summary["output"] = {{"trajectory_rows", output.rows},
                       {"trajectory_bytes", output.bytes},
                       {"max_output_bytes", output.max_bytes},
                       {"error", output.error.empty() ? support::Json(nullptr) : support::Json(output.error)}};
  support::write_file_atomically(path, support::json_text(summary));
}

}  // namespace frictionlab::dynamics
