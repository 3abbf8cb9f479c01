#include "bench/accuracy/study.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ostream>
#include <stdexcept>

#include "friction/registry.h"
#include "friction/support/number_format.h"

namespace frictionlab::accuracy {
namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

std::vector<std::string> default_laws() {
  std::vector<std::string> out;
  for (const auto& info : friction::list_laws()) {
    if (!info.reference && !info.slow) out.push_back(info.name);
  }
  return out;
}

void check_laws(const std::vector<std::string>& laws, const Grid& grid) {
  for (std::size_t i = 0; i < laws.size(); ++i) {
    const friction::LawInfo info = friction::law_info(laws[i]);  // throws, naming what is wrong
    for (std::size_t j = 0; j < i; ++j) {  // two spellings of one spec are the same law
      if (friction::canonical_law_spec(laws[j]) == friction::canonical_law_spec(laws[i])) {
        throw std::invalid_argument("law '" + laws[i] + "' is listed twice: list each law once");
      }
    }
    if (info.slow && grid.size() > kSlowLawMaxPoints) {
      throw std::invalid_argument(
          "law '" + laws[i] + "' is too slow for a grid of " + std::to_string(grid.size()) +
          " points: use at most " + std::to_string(kSlowLawMaxPoints) +
          " (s points x mu points x psi points x 2), e.g. --s-points 40 --mu-points 5 --psi-points 9");
    }
  }
}

ScopeSummary summarize(const Grid& grid, const LawValues& law, const LawValues& reference,
                       const std::vector<std::size_t>& indices) {
  ScopeSummary sum;
  sum.points = indices.size();
  const std::array<const std::vector<double>*, 3> lv = {&law.F1, &law.F2, &law.M};
  const std::array<const std::vector<double>*, 3> rv = {&reference.F1, &reference.F2, &reference.M};
  std::vector<double> value(indices.size()), ref(indices.size());
  const auto to_grid = [&](std::size_t k) { return k == kNoIndex ? kNoIndex : indices[k]; };
  for (std::size_t c = 0; c < 3; ++c) {
    for (std::size_t k = 0; k < indices.size(); ++k) {
      value[k] = (*lv[c])[indices[k]];
      ref[k] = (*rv[c])[indices[k]];
    }
    sum.error[c] = error_stats(value, ref);
    sum.error[c].max_index = to_grid(sum.error[c].max_index);
    sum.error[c].first_nonfinite = to_grid(sum.error[c].first_nonfinite);
    sum.sign[c] = sign_stats(value, ref);
  }
  std::vector<double>& power = value;
  for (std::size_t k = 0; k < indices.size(); ++k) {
    const std::size_t i = indices[k];
    const GridPoint p = grid.point(i);
    power[k] = dissipation(law.F1[i], law.M[i], p.s, p.sign);
    if (is_singular(law.F1[i], law.F2[i], law.M[i])) {
      if (sum.singular_points++ == 0) sum.first_singular = i;
    }
  }
  sum.dissipation = dissipation_stats(power);
  sum.dissipation.worst_index = to_grid(sum.dissipation.worst_index);
  return sum;
}

std::vector<Region> study_regions(const Grid& grid) {
  std::vector<Region> out = {
      {"s < 0.1", "slow slip, spin dominates", {}},
      {"0.1 <= s <= 10", "slip and spin comparable", {}},
      {"s > 10", "fast slip", {}},
      {"Omega < 0", "negative spin", {}},
      {"Omega > 0", "positive spin", {}},
  };
  for (std::size_t i = 0; i < grid.size(); ++i) {
    const GridPoint p = grid.point(i);
    out[p.s < kSlowBandEdge ? 0 : p.s <= kFastBandEdge ? 1 : 2].indices.push_back(i);
    out[p.sign < 0 ? 3 : 4].indices.push_back(i);
  }
  return out;
}

StudyResult run_study(const StudyOptions& options) {
  StudyResult result{Grid(options.grid), {}, 0.0, {}, {}, {}};
  const Grid& grid = result.grid;
  const std::vector<std::string> laws = options.laws.empty() ? default_laws() : options.laws;
  check_laws(laws, grid);
  std::ostream* log = options.progress;
  const std::string reference_name = options.reference.empty() ? friction::reference_law_name() : options.reference;
  const auto reference = friction::make_law(reference_name);  // a bad spec throws before anything runs

  if (log) {
    *log << "accuracy: grid " << grid.s().size() << " s x " << grid.mu().size() << " mu x "
         << grid.psi().size() << " psi x 2 signs = " << grid.size() << " points; "
         << laws.size() << " laws against '" << reference_name << "'" << std::endl;
  }
  auto t0 = std::chrono::steady_clock::now();
  result.reference = evaluate_on_grid(*reference, grid, options.threads);
  result.reference_seconds = seconds_since(t0);
  if (log) {
    *log << "accuracy: " << reference_name << " (reference): " << result.reference_seconds << " s"
         << std::endl;
  }

  result.regions = study_regions(grid);
  std::vector<std::size_t> all(grid.size());
  for (std::size_t i = 0; i < all.size(); ++i) all[i] = i;
  std::vector<std::vector<std::size_t>> slices(grid.mu().size());
  for (std::size_t imu = 0; imu < slices.size(); ++imu) {
    const auto first = all.begin() + static_cast<std::ptrdiff_t>(imu * grid.slice_size());
    slices[imu].assign(first, first + static_cast<std::ptrdiff_t>(grid.slice_size()));
  }
  for (const auto& name : laws) {
    t0 = std::chrono::steady_clock::now();
    const auto law = friction::make_law(name);
    LawValues values = evaluate_on_grid(*law, grid, options.threads);
    LawSummary sum;
    sum.seconds = seconds_since(t0);
    sum.law = name;
    const friction::LawInfo info = friction::law_info(name);
    sum.description = info.summary;
    sum.overall = summarize(grid, values, result.reference, all);
    for (const auto& slice : slices) {
      sum.by_mu.push_back(summarize(grid, values, result.reference, slice));
    }
    for (const auto& region : result.regions) {
      sum.by_region.push_back(summarize(grid, values, result.reference, region.indices));
    }
    if (info.has_poles) {
      sum.has_denominators = true;
      sum.poles = pole_brackets(grid, *known_denominators(name));
    }
    if (log) {
      // The errors are per k·N (forces) and per k·N·a (moment): say so, or "F1 0.2" reads as newtons.
      const auto err = [&](int c) { return support::significant(sum.overall.error[c].max_abs, 6); };
      *log << "accuracy: " << name << ": " << support::significant(sum.seconds, 6) << " s; max |error| F1 " << err(0)
           << " k·N, F2 " << err(1) << " k·N, M " << err(2) << " k·N·a" << std::endl;
    }
    result.values.push_back(std::move(values));
    result.summaries.push_back(std::move(sum));
  }
  return result;
}

}  // namespace frictionlab::accuracy
