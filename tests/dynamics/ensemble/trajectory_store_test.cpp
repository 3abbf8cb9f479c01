// The trajectories file of --hdf5 (dynamics/ensemble/trajectory_store.h), read back with HDF5's
// own C API. Registered only when the build found HDF5.

#include "dynamics/ensemble/trajectory_store.h"

#include <gtest/gtest.h>
#include <hdf5.h>
#include <unistd.h>

#include <fstream>
#include <vector>

namespace frictionlab::dynamics::ensemble {
namespace trajectory_store_test {

namespace fs = std::filesystem;

std::vector<double> read_column(const fs::path& file, const std::string& dataset) {
  const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  EXPECT_GE(f, 0);
  const hid_t d = H5Dopen2(f, dataset.c_str(), H5P_DEFAULT);
  EXPECT_GE(d, 0) << dataset;
  const hid_t s = H5Dget_space(d);
  hsize_t n = 0;
  H5Sget_simple_extent_dims(s, &n, nullptr);
  std::vector<double> out(n);
  if (n > 0) H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data());
  H5Sclose(s);
  H5Dclose(d);
  H5Fclose(f);
  return out;
}

DecimatedTrajectory trajectory(int n, double scale) {
  DecimatedTrajectory t;
  for (int i = 0; i < n; ++i) {
    auto cols = t.columns();
    for (std::size_t c = 0; c < cols.size(); ++c) cols[c]->push_back(scale * (i + 0.1 * static_cast<double>(c)));
  }
  return t;
}

TEST(EnsembleTrajectoryStore, RunsAreGroupsOfColumnsAndAResumedFileGrows) {
  ASSERT_TRUE(trajectory_store_available());
  const fs::path dir = fs::temp_directory_path() / ("frictionlab_h5_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  RunRecord r;
  r.law = "exact";
  {
    auto store = open_trajectory_store(dir, false);
    r.run = 3;
    store->write(r, trajectory(5000, 1.0));  // more than one chunk
    r.run = 0;
    store->write(r, DecimatedTrajectory{});  // a run that failed before its first sample
    store->close();
  }
  {
    auto store = open_trajectory_store(dir, true);
    EXPECT_EQ(store->path(), dir / "trajectories.h5");
    r.run = 7;
    store->write(r, trajectory(3, 2.0));
    store->close();
  }
  const auto gamma3 = read_column(dir / "trajectories.h5", "/runs/00000003/gamma3");
  ASSERT_EQ(gamma3.size(), 5000u);
  EXPECT_EQ(gamma3[4999], 4999.1);
  EXPECT_TRUE(read_column(dir / "trajectories.h5", "/runs/00000000/t").empty());
  EXPECT_EQ(read_column(dir / "trajectories.h5", "/runs/00000007/kinetic"), (std::vector<double>{1.0, 3.0, 5.0}));

  // A file a kill left unreadable is kept, and the resumed job writes a new one beside it.
  { std::ofstream(dir / "trajectories.h5", std::ios::trunc) << "not HDF5"; }
  auto store = open_trajectory_store(dir, true);
  EXPECT_EQ(store->path(), dir / "trajectories-2.h5");
  store->close();
  fs::remove_all(dir);
}

}  // namespace
}  // namespace frictionlab::dynamics::ensemble
