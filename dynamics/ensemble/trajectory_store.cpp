#include "dynamics/ensemble/trajectory_store.h"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

#include "friction/support/checked_output.h"

#ifdef FRICTIONLAB_WITH_HDF5
#include <hdf5.h>
#endif

namespace frictionlab::dynamics::ensemble {

#ifdef FRICTIONLAB_WITH_HDF5
namespace {

constexpr hsize_t kChunk = 4096;
constexpr unsigned kDeflateLevel = 4;

// Closes an HDF5 handle when it goes out of scope.
class Handle {
 public:
  Handle(hid_t id, herr_t (*close)(hid_t)) : id_(id), close_(close) {}
  ~Handle() {
    if (id_ >= 0) close_(id_);
  }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  [[nodiscard]] hid_t get() const { return id_; }

 private:
  hid_t id_;
  herr_t (*close_)(hid_t);
};

class Hdf5Store final : public TrajectoryStore {
 public:
  Hdf5Store(std::filesystem::path path, hid_t file) : path_(std::move(path)), file_(file) {}
  ~Hdf5Store() override {
    if (file_ >= 0) H5Fclose(file_);
  }

  void write(const RunRecord& r, const DecimatedTrajectory& t) override {
    char name[40];
    std::snprintf(name, sizeof name, "/runs/%08ld", r.run);
    if (H5Lexists(file_, "/runs", H5P_DEFAULT) > 0 && H5Lexists(file_, name, H5P_DEFAULT) > 0)
      check(H5Ldelete(file_, name, H5P_DEFAULT), "replacing");
    const Handle lcpl(H5Pcreate(H5P_LINK_CREATE), H5Pclose);
    check(H5Pset_create_intermediate_group(lcpl.get(), 1), "preparing");
    const Handle group(H5Gcreate2(file_, name, lcpl.get(), H5P_DEFAULT, H5P_DEFAULT), H5Gclose);
    check(group.get(), "creating a group in");
    const hsize_t n = t.size();
    const Handle space(H5Screate_simple(1, &n, nullptr), H5Sclose);
    const Handle dcpl(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
    if (n > 0) {
      const hsize_t chunk = std::min(n, kChunk);
      check(H5Pset_chunk(dcpl.get(), 1, &chunk), "preparing");
      check(H5Pset_deflate(dcpl.get(), kDeflateLevel), "preparing");
    }
    const auto cols = t.columns();
    for (std::size_t i = 0; i < cols.size(); ++i) {
      const std::string column(DecimatedTrajectory::kColumns[i]);
      const Handle ds(H5Dcreate2(group.get(), column.c_str(), H5T_IEEE_F64LE, space.get(), H5P_DEFAULT, dcpl.get(),
                                 H5P_DEFAULT),
                      H5Dclose);
      check(ds.get(), "creating a dataset in");
      if (n > 0) check(H5Dwrite(ds.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, cols[i]->data()), "writing");
    }
    integer_attribute(group.get(), "start", r.start);
    integer_attribute(group.get(), "replica", r.replica);
    const Handle str(H5Tcopy(H5T_C_S1), H5Tclose);
    check(H5Tset_size(str.get(), std::max<std::size_t>(1, r.law.size())), "preparing");
    const Handle scalar(H5Screate(H5S_SCALAR), H5Sclose);
    const Handle law(H5Acreate2(group.get(), "law", str.get(), scalar.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
    check(law.get(), "writing an attribute to");
    check(H5Awrite(law.get(), str.get(), r.law.c_str()), "writing an attribute to");
    check(H5Fflush(file_, H5F_SCOPE_GLOBAL), "flushing");
  }

  void close() override {
    if (file_ < 0) return;
    const herr_t status = H5Fclose(file_);
    file_ = -1;
    check(status, "closing");
  }

  [[nodiscard]] const std::filesystem::path& path() const override { return path_; }

 private:
  void integer_attribute(hid_t group, const char* name, long value) const {
    const Handle scalar(H5Screate(H5S_SCALAR), H5Sclose);
    const Handle a(H5Acreate2(group, name, H5T_STD_I64LE, scalar.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
    check(a.get(), "writing an attribute to");
    const long long v = value;
    check(H5Awrite(a.get(), H5T_NATIVE_LLONG, &v), "writing an attribute to");
  }
  void check(long long status, const char* what) const {
    if (status < 0) throw support::OutputError(std::string(what) + " '" + path_.string() + "' failed (HDF5)");
  }

  std::filesystem::path path_;
  hid_t file_;
};

}  // namespace

bool trajectory_store_available() { return true; }

std::unique_ptr<TrajectoryStore> open_trajectory_store(const std::filesystem::path& dir, bool resume) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // errors are return codes here, not stack dumps
  std::filesystem::path path = dir / "trajectories.h5";
  if (resume) {
    for (int n = 2; std::filesystem::exists(path); ++n) {
      const hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
      if (f >= 0) return std::make_unique<Hdf5Store>(path, f);
      path = dir / ("trajectories-" + std::to_string(n) + ".h5");  // unreadable (a kill mid-write): a new file
    }
  }
  const hid_t f = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  if (f < 0) throw support::OutputError("cannot write '" + path.string() + "' (HDF5)");
  return std::make_unique<Hdf5Store>(path, f);
}

#else

bool trajectory_store_available() { return false; }

std::unique_ptr<TrajectoryStore> open_trajectory_store(const std::filesystem::path&, bool) {
  throw std::invalid_argument("--hdf5 is not available: this frictionlab was built without HDF5 (install libhdf5-dev "
                              "and rebuild)");
}

#endif

}  // namespace frictionlab::dynamics::ensemble
