#include "dynamics/io/shadow_output.h"

#include "dynamics/core/shadow_json.h"
#include "dynamics/io/scenario_toml.h"
#include "friction/registry.h"

namespace frictionlab::dynamics {

ShadowOutput::ShadowOutput(const friction::FrictionLaw& own, const std::vector<std::string>& specs,
                           const MotionPhaseRule& rule, const std::filesystem::path& csv_file,
                           std::uint64_t max_bytes) {
  if (specs.empty()) return;
  std::vector<const friction::FrictionLaw*> laws;
  for (const std::string& spec : specs) {
    scenario_toml::check_law_spec("run.shadow", spec);
    owned_.push_back(friction::make_law(spec));
    laws.push_back(owned_.back().get());
  }
  laws_ = std::make_unique<ShadowLaws>(own, std::move(laws), rule);
  csv_ = std::make_unique<ShadowCsv>(csv_file, *laws_, max_bytes);
}

void ShadowOutput::close() {
  if (csv_) csv_->close();
}

void ShadowOutput::add_to(support::Json& summary, double run_work) const {
  if (laws_) summary["shadow"] = shadow_json(*laws_, csv_.get(), run_work);
}

}  // namespace frictionlab::dynamics
