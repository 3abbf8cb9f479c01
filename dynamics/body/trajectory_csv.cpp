#include "dynamics/body/trajectory_csv.h"

#include "friction/support/errors.h"
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
      q.w(), q.x(), q.y(), q.z()};
  for (double& x : row) x = support::without_negative_zero(x);
  return row;
}

std::string trajectory_header() {
  std::string header;
  for (std::size_t i = 0; i < kTrajectoryColumns.size(); ++i) {
    header += kTrajectoryColumns[i];
    header += i + 1 < kTrajectoryColumns.size() ? ',' : '\n';
  }
  return header;
}

TrajectoryCsv::TrajectoryCsv(const std::filesystem::path& file, std::uint64_t max_bytes) : file_(file) {
  const std::string header = trajectory_header();
  if (max_bytes > 0 && header.size() > max_bytes)
    throw support::invalid_value("run.max_output_bytes", static_cast<long long>(max_bytes),
                                 "it must hold at least the header of trajectory.csv (" +
                                     std::to_string(header.size()) + " bytes)");
  file_.set_size_limit(max_bytes);
  file_.append(header);
  line_.reserve(512);
}

void TrajectoryCsv::sample(const Sample& s) {
  const auto row = trajectory_row(s);
  line_.clear();
  constexpr std::size_t kInContact = 24;  // kTrajectoryColumns[24] == "in_contact"
  static_assert(kTrajectoryColumns[kInContact] == "in_contact");
  for (std::size_t i = 0; i < row.size(); ++i) {
    if (i == kInContact) {
      line_ += row[i] != 0.0 ? "1" : "0";
      line_.push_back(i + 1 < row.size() ? ',' : '\n');
      continue;
    }
    support::append_shortest(line_, row[i]);
    line_.push_back(i + 1 < row.size() ? ',' : '\n');
  }
  try {
    file_.append(line_);
  } catch (const support::OutputError& e) {
    throw OutputFailure(e.what());
  } catch (const support::SizeLimitReached& e) {
    throw OutputLimitReached(std::string(e.what()) + " (run.max_output_bytes: raise it, or run.output_dt)");
  }
  ++rows_;
}

void TrajectoryCsv::close() {
  try {
    file_.close();
  } catch (const support::OutputError& e) {
    throw OutputFailure(e.what());
  }
}

}  // namespace frictionlab::dynamics
