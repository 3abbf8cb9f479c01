#include "dynamics/body/trajectory_csv.h"

#include <vector>

#include "friction/support/number_format.h"

namespace frictionlab::dynamics {
std::array<double, kTrajectoryColumns.size()> trajectory_row(const Sample& s) {
  const ContactState& c = s.contact;
  const Eigen::Vector3d omega = angular_velocity(s.x);
  const Eigen::Vector3d v = velocity(s.x);
  const Eigen::Quaterniond q = orientation_quaternion(s.x);
  std::array<double, kTrajectoryColumns.size()> row = {
      s.t,
      c.gamma[0], c.gamma[1], c.gamma[2],
      omega[0], omega[1], omega[2],
      v[0], v[1], v[2],
      height(s.x), c.N, c.U, c.Omega,
      c.friction.F1, c.friction.F2, c.friction.M,
      c.a, c.b, c.psi.radians(),
      s.energy, s.kinetic, slide_work(s.x), spin_work(s.x),
      c.in_contact ? 1.0 : 0.0,
      s.mode.stick ? 1.0 : 0.0,
      position(s.x)[0], position(s.x)[1],
      q.w(), q.x(), q.y(), q.z(),
      s.mode.hold ? 1.0 : 0.0};
  for (double& x : row) x = support::without_negative_zero(x);
  return row;
}

std::string trajectory_header(bool pose) {
  std::vector<std::string_view> columns;
  for (std::size_t i = 0; i < kTrajectoryColumns.size(); ++i) {
    if (trajectory_column_written(i, pose)) columns.push_back(kTrajectoryColumns[i]);
  }
  return trajectory_file_header(columns);
}

TrajectoryCsv::TrajectoryCsv(const std::filesystem::path& file, std::uint64_t max_bytes, bool pose)
    : file_(file, trajectory_header(pose), max_bytes), pose_(pose) {
  line_.reserve(512);
}

void TrajectoryCsv::sample(const Sample& s) {
  const auto row = trajectory_row(s);
  line_.clear();
  constexpr std::size_t kInContact = 24;  // kTrajectoryColumns[24] == "in_contact"
  static_assert(kTrajectoryColumns[kInContact] == "in_contact");
  for (std::size_t i = 0; i < row.size(); ++i) {
    if (!trajectory_column_written(i, pose_)) continue;
    if (i == kInContact) {
      line_ += row[i] != 0.0 ? "1" : "0";
    } else {
      support::append_shortest(line_, row[i]);
    }
    line_.push_back(',');
  }
  line_.back() = '\n';
  file_.append(line_);
  ++rows_;
}

void TrajectoryCsv::close() { file_.close(); }

}  // namespace frictionlab::dynamics
