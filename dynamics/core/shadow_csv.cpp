#include "dynamics/core/shadow_csv.h"

#include <cmath>
#include <limits>

#include "friction/support/number_format.h"

namespace frictionlab::dynamics {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::string csv_field(const std::string& name) {
  if (name.find_first_of(",\"\n") == std::string::npos) return name;
  std::string quoted = "\"";
  for (char c : name) {
    if (c == '"') quoted += '"';
    quoted += c;
  }
  return quoted + '"';
}

std::vector<std::string> specs_of(const ShadowLaws& laws) {
  std::vector<std::string> specs;
  for (std::size_t i = 0; i < laws.size(); ++i) specs.emplace_back(laws.law(i).spec());
  return specs;
}

void put(std::string& line, double x) {
  line.push_back(',');
  support::append_shortest(line, x);
}

}  // namespace

std::string shadow_csv_header(const std::vector<std::string>& specs) {
  std::string h = "t,phase,s,b_over_a,a,psi,N";
  for (const std::string& spec : specs) {
    for (const char* out : {"dF1", "dF2", "dM", "dP"}) h += "," + csv_field(std::string(out) + "[" + spec + "]");
  }
  return h + "\n";
}

ShadowCsv::ShadowCsv(const std::filesystem::path& file, const ShadowLaws& laws, std::uint64_t max_bytes)
    : laws_(laws), file_(file, shadow_csv_header(specs_of(laws)), max_bytes), errors_(laws.size()) {
  line_.reserve(64 + 100 * laws.size());
}

void ShadowCsv::write(double t, const ShadowPoint& p) {
  if (ended_) return;
  laws_.evaluate(p, errors_);
  const friction::ContactInput& in = p.input;
  line_.clear();
  support::append_shortest(line_, t);
  line_ += ',';
  line_ += static_cast<char>('0' + static_cast<int>(laws_.phase(p)));
  if (p.in_contact) {
    put(line_, in.Omega != 0.0 ? in.U / (in.a * std::abs(in.Omega)) : kNaN);
    put(line_, in.b / in.a);
    put(line_, in.a);
    put(line_, in.psi.radians());
  } else {
    put(line_, kNaN);
    put(line_, kNaN);
    put(line_, 0.0);
    put(line_, kNaN);
  }
  put(line_, p.in_contact ? in.N : 0.0);
  for (const ShadowError& e : errors_) {
    put(line_, e.dF1);
    put(line_, e.dF2);
    put(line_, e.dM);
    put(line_, e.dP);
  }
  line_ += '\n';
  try {
    file_.append(line_);
    ++rows_;
  } catch (const std::exception& e) {  // OutputFailure, OutputLimitReached: the file ends here
    ended_ = true;
    error_ = e.what();
  }
}

void ShadowCsv::close() {
  try {
    file_.close();
  } catch (const std::exception& e) {
    if (error_.empty()) error_ = e.what();
  }
}

}  // namespace frictionlab::dynamics
