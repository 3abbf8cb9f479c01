#include "dynamics/puck/puck_trajectory_csv.h"

#include <cmath>
#include <limits>

#include "friction/support/number_format.h"

namespace frictionlab::dynamics::puck {
namespace {

// U/(a |Omega|), or nan where it is not defined (Omega = 0): a gap in a plot, not an infinity.
double slip_ratio(const PuckContact& c, double a) {
  return c.Omega != 0.0 ? c.U / (a * std::abs(c.Omega)) : std::numeric_limits<double>::quiet_NaN();
}

void put(std::string& line, double x) {
  support::append_shortest(line, x);
  line.push_back(',');
}

}  // namespace

std::string puck_trajectory_header() { return trajectory_file_header(kPuckTrajectoryColumns); }

PuckTrajectoryCsv::PuckTrajectoryCsv(const std::filesystem::path& file, double a, std::uint64_t max_bytes)
    : file_(file, puck_trajectory_header(), max_bytes), a_(a) {
  line_.reserve(400);
}

void PuckTrajectoryCsv::sample(const PuckSample& s) {
  const PuckContact& c = s.contact;
  line_.clear();
  put(line_, s.t);
  put(line_, position(s.x)[0]);
  put(line_, position(s.x)[1]);
  put(line_, heading(s.x));
  put(line_, velocity(s.x)[0]);
  put(line_, velocity(s.x)[1]);
  put(line_, spin(s.x));
  put(line_, c.U);
  put(line_, c.Omega);
  put(line_, c.psi);
  put(line_, c.friction.F1);
  put(line_, c.friction.F2);
  put(line_, c.friction.M);
  put(line_, slip_ratio(c, a_));
  put(line_, s.energy);
  put(line_, slide_work(s.x));
  put(line_, spin_work(s.x));
  line_ += static_cast<char>('0' + (s.mode.slip ? 1 : 0) + (s.mode.spin ? 2 : 0));
  line_ += '\n';
  file_.append(line_);
  ++rows_;
}

void PuckTrajectoryCsv::close() { file_.close(); }

}  // namespace frictionlab::dynamics::puck
