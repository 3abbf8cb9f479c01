#include "dynamics/ensemble/ensemble_session.h"

#include <fstream>
#include <sstream>
#include <stdexcept>

#include "friction/support/checked_input.h"
#include "friction/support/checked_output.h"
#include "friction/support/json.h"

namespace frictionlab::dynamics::ensemble {
namespace {

std::vector<std::string> keys_of(const Study& s) {
  std::vector<std::string> keys;
  for (const auto& a : s.vary) keys.push_back(a.key);
  return keys;
}

// The hash recorded in DIR/ensemble.json, or empty if there is none.
std::string recorded_hash(const std::filesystem::path& manifest) {
  std::error_code ec;
  if (!std::filesystem::exists(manifest, ec)) return "";
  const std::string text = support::read_file(manifest, "ensemble manifest");
  try {
    const auto j = support::Json::parse(text);
    return j.at("hash").get<std::string>();
  } catch (const std::exception& e) {
    throw std::invalid_argument(manifest.string() + " is not an ensemble manifest (" + e.what() + ")");
  }
}

}  // namespace

std::string manifest_text(const EnsemblePlan& plan, const std::string& command) {
  const Study& s = plan.study();
  support::Json j;
  j["study"] = s.name;
  j["study_file"] = s.file.string();
  j["scenario"] = s.scenario.string();
  j["hash"] = plan.hash();
  j["runs"] = plan.runs();
  j["starts"] = plan.starts();
  j["replicas"] = plan.replicas();
  j["laws"] = s.laws;
  j["keys"] = keys_of(s);
  j["design"] = std::string(to_string(s.design));
  j["command"] = command;
  return support::json_text(j);
}

EnsembleSession::EnsembleSession(const EnsemblePlan& plan, SessionOptions options)
    : plan_(plan), options_(std::move(options)) {
  const auto& dir = options_.out;
  if (options_.trajectories && plan.model() == RunModel::puck)
    throw std::invalid_argument("--hdf5: a puck study keeps no trajectories (its features come from each run's summary)");
  const auto manifest = dir / "ensemble.json";
  const auto runs = dir / "runs.csv";
  const std::string header = runs_header(keys_of(plan.study()), plan.model(), plan.shadow_laws());
  std::error_code ec;
  if (std::filesystem::exists(dir, ec) && !std::filesystem::is_directory(dir, ec))
    throw std::invalid_argument("--out " + dir.string() + " is not a folder");
  // Before runs.csv is read: two jobs resuming one folder would both redo the runs it lacks.
  lock_ = std::make_unique<support::FolderLock>(dir);
  bool resume = false;
  ExistingRuns existing;
  if (std::filesystem::exists(runs)) {
    if (!options_.resume)
      throw std::invalid_argument(runs.string() + " exists: add --resume to continue that ensemble, or choose another --out");
    const std::string hash = recorded_hash(manifest);
    if (hash.empty()) throw std::invalid_argument(runs.string() + " has no ensemble.json beside it: not a folder of `frictionlab ensemble`");
    if (hash != plan.hash())
      throw std::invalid_argument(dir.string() + " holds the runs of another study (hash " + hash + "; this study and its scenario hash to " +
                                  plan.hash() + "): a changed study cannot be resumed; use another --out");
    existing = read_existing_runs(runs, header, plan.runs());
    resume = true;
  }
  if (!resume) support::write_file_atomically(manifest, manifest_text(plan, options_.command));
  writer_ = std::make_unique<RunsWriter>(runs, header, resume);
  if (options_.trajectories) trajectories_ = open_trajectory_store(dir, resume);

  summary_.total = plan.runs();
  summary_.done_before = static_cast<long>(existing.done.size());
  queue_ = std::make_unique<TaskQueue>(plan, std::move(existing.done));
  progress_ = std::make_unique<ProgressMeter>(summary_.total, summary_.done_before, options_.log, options_.live);
}

void EnsembleSession::record(FinishedRun&& run) {
  long done = 0;
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (!summary_.output_error.empty()) return;
    try {
      writer_->write(run.record);
      if (trajectories_) trajectories_->write(run.record, run.trajectory);
    } catch (const std::exception& e) {
      summary_.output_error = e.what();
      halt_ = true;
      return;
    }
    ++summary_.done_now;
    if (run.record.failed()) {
      ++summary_.failed_now;
    } else if (run.record.final_class == "stopped") {
      ++summary_.early_now;
    }
    done = summary_.done_before + summary_.done_now;
  }
  progress_->run_finished();
  if (options_.on_progress) options_.on_progress(done, summary_.total);
}

SessionSummary EnsembleSession::finish() {
  const std::lock_guard<std::mutex> lock(mutex_);
  progress_->finish();
  try {
    writer_->close();
    if (trajectories_) trajectories_->close();
  } catch (const std::exception& e) {
    if (summary_.output_error.empty()) summary_.output_error = e.what();
  }
  summary_.complete = summary_.output_error.empty() && summary_.remaining() == 0;
  if (summary_.complete) sort_runs_file(runs_csv());
  return summary_;
}

}  // namespace frictionlab::dynamics::ensemble
