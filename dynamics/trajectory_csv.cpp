#include "dynamics/trajectory_csv.h"

#include <charconv>
#include <system_error>

namespace frictionlab::dynamics {
namespace {

// Rows between flushes: a run killed from outside loses at most this many rows.
constexpr long kFlushEveryRows = 1000;

void put(std::string& line, double x) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, x);
  line.append(buf, r.ptr);
  line.push_back(',');
}

void put3(std::string& line, const Eigen::Vector3d& v) {
  for (int i = 0; i < 3; ++i) put(line, v[i]);
}

}  // namespace

TrajectoryCsv::TrajectoryCsv(std::ostream& out) : out_(out) {
  std::string header;
  for (std::size_t i = 0; i < kTrajectoryColumns.size(); ++i) {
    header += kTrajectoryColumns[i];
    header += i + 1 < kTrajectoryColumns.size() ? ',' : '\n';
  }
  out_ << header;
  out_.flush();
}

void TrajectoryCsv::sample(const Sample& s) {
  const ContactState& c = s.contact;
  std::string line;
  line.reserve(512);
  put(line, s.t);
  put3(line, c.gamma);
  put3(line, angular_velocity(s.x));
  put3(line, velocity(s.x));
  put(line, height(s.x));
  put(line, c.N);
  put(line, c.U);
  put(line, c.Omega);
  put(line, c.friction.F1);
  put(line, c.friction.F2);
  put(line, c.friction.M);
  put(line, c.a);
  put(line, c.b);
  put(line, c.psi);
  put(line, s.energy);
  put(line, s.kinetic);
  put(line, slide_work(s.x));
  put(line, spin_work(s.x));
  line += c.in_contact ? "1\n" : "0\n";
  out_ << line;
  if (++rows_ % kFlushEveryRows == 0) out_.flush();
}

}  // namespace frictionlab::dynamics
