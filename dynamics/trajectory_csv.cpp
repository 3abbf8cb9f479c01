#include "dynamics/trajectory_csv.h"

#include "friction/support/number_format.h"

namespace frictionlab::dynamics {
namespace {

void put(std::string& line, double x) {
  support::append_shortest(line, x);
  line.push_back(',');
}

void put3(std::string& line, const Eigen::Vector3d& v) {
  for (int i = 0; i < 3; ++i) put(line, v[i]);
}

}  // namespace

TrajectoryCsv::TrajectoryCsv(const std::filesystem::path& file) : file_(file) {
  std::string header;
  for (std::size_t i = 0; i < kTrajectoryColumns.size(); ++i) {
    header += kTrajectoryColumns[i];
    header += i + 1 < kTrajectoryColumns.size() ? ',' : '\n';
  }
  file_.append(header);
  line_.reserve(512);
}

void TrajectoryCsv::sample(const Sample& s) {
  const ContactState& c = s.contact;
  line_.clear();
  put(line_, s.t);
  put3(line_, c.gamma);
  put3(line_, angular_velocity(s.x));
  put3(line_, velocity(s.x));
  put(line_, height(s.x));
  put(line_, c.N);
  put(line_, c.U);
  put(line_, c.Omega);
  put(line_, c.friction.F1);
  put(line_, c.friction.F2);
  put(line_, c.friction.M);
  put(line_, c.a);
  put(line_, c.b);
  put(line_, c.psi);
  put(line_, s.energy);
  put(line_, s.kinetic);
  put(line_, slide_work(s.x));
  put(line_, spin_work(s.x));
  line_ += c.in_contact ? "1\n" : "0\n";
  try {
    file_.append(line_);
  } catch (const support::OutputError& e) {
    throw OutputFailure(e.what());
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
