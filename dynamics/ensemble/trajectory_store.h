#pragma once
// The optional file of decimated trajectories of an ensemble (`--hdf5`): DIR/trajectories.h5, one
// group per run. Built only where HDF5 was found (FRICTIONLAB_WITH_HDF5); never required.
//
// Layout: /runs/<run index, 8 digits> is a group with one dataset per column of
// DecimatedTrajectory (t, gamma3, spin, slip, n_over_mg, kinetic; float64, gzip level 4, chunks of
// up to 4096) and the attributes start, replica and law. The file is flushed after every run; a
// job killed mid-write can still leave it unreadable (HDF5 1.10 has no journal): `--resume`
// then starts trajectories-<n>.h5 beside it instead of failing.

#include <filesystem>
#include <memory>
#include <string>

#include "dynamics/ensemble/decimated_trajectory.h"
#include "dynamics/ensemble/run_record.h"

namespace frictionlab::dynamics::ensemble {

class TrajectoryStore {
 public:
  virtual ~TrajectoryStore() = default;
  /// Stores one run's trajectory (replacing a group of the same run). Throws support::OutputError.
  virtual void write(const RunRecord& r, const DecimatedTrajectory& t) = 0;
  virtual void close() = 0;
  [[nodiscard]] virtual const std::filesystem::path& path() const = 0;
};

/// Whether this build can write HDF5.
[[nodiscard]] bool trajectory_store_available();

/// Opens DIR/trajectories.h5 (created, or with `resume` opened for more runs; an unreadable file is
/// left alone and a new trajectories-<n>.h5 started). Throws std::invalid_argument if this build has
/// no HDF5, support::OutputError if the file cannot be written.
[[nodiscard]] std::unique_ptr<TrajectoryStore> open_trajectory_store(const std::filesystem::path& dir, bool resume);

}  // namespace frictionlab::dynamics::ensemble
