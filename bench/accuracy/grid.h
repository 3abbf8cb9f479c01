#pragma once
// The grid of the accuracy study: dimensionless contacts (s, mu, psi, sign Omega).
//
// Every law's F1/(kN), F2/(kN), M/(kNa) depends only on s = U/(a|Omega|), mu = b/a, psi and
// sign(Omega) (docs/model.md §1, scaling), so the study evaluates the laws at a = 1 m, b = mu m,
// |Omega| = 1 1/s, U = s m/s, N = 1 N, k = 1: then F1, F2 are in units of kN and M of kNa, and
// the power of friction F1 U + M Omega is in units of kN a|Omega|.
//
// Nodes: s log-spaced over [s_min, s_max] (both ends exact), mu evenly spaced over [mu_min, 1]
// (1 is a node: the circle), psi evenly spaced over [0, pi] with an odd count so that 0, pi/2
// and pi are nodes (F2 = 0 exactly there for the exact law), sign(Omega) = -1 and +1.
// Points are numbered with s fastest, then sign, then psi, then mu: one mu value is one
// contiguous slice, and one (mu, psi, sign) is one contiguous run over s.

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "friction/law.h"

namespace frictionlab::accuracy {

/// The sizes and ranges of the grid. The defaults are those of the study in docs/accuracy.md.
struct GridSpec {
  std::size_t s_points = 200;   ///< number of slip ratios, >= 2
  std::size_t mu_points = 20;   ///< number of axis ratios, >= 2 (mu_min and 1 are nodes)
  std::size_t psi_points = 25;  ///< number of orientations, odd and >= 3 (0, pi/2, pi are nodes)
  double s_min = 1e-3;          ///< smallest slip ratio U/(a|Omega|), dimensionless, > 0
  double s_max = 1e3;           ///< largest slip ratio, > s_min, finite
  double mu_min = 0.05;         ///< smallest axis ratio b/a, in (0, 1)

  /// True if usable; otherwise false, with `error` (if given) naming the value and the rule.
  bool is_valid(std::string* error) const;
};

/// One dimensionless contact of the grid.
struct GridPoint {
  double s = 0.0;    ///< slip ratio U/(a|Omega|)
  double mu = 1.0;   ///< axis ratio b/a
  double psi = 0.0;  ///< angle from the slip direction to the major axis, rad
  int sign = 1;      ///< sign of Omega, -1 or +1
};

/// The contact a law is evaluated at for `p`: a = 1 m, b = mu m, U = s m/s, Omega = sign 1/s,
/// N = 1 N, k = 1.
[[nodiscard]] friction::ContactInput to_contact(const GridPoint& p);

class Grid {
 public:
  /// The two signs of Omega, in index order.
  static constexpr std::array<int, 2> kSigns = {-1, +1};

  /// Throws std::invalid_argument (naming the value and the rule) if `spec` is not valid.
  explicit Grid(const GridSpec& spec);

  [[nodiscard]] const GridSpec& spec() const { return spec_; }
  [[nodiscard]] const std::vector<double>& s() const { return s_; }
  [[nodiscard]] const std::vector<double>& mu() const { return mu_; }
  [[nodiscard]] const std::vector<double>& psi() const { return psi_; }

  /// Number of points in one mu slice, and in the whole grid.
  [[nodiscard]] std::size_t slice_size() const { return psi_.size() * kSigns.size() * s_.size(); }
  [[nodiscard]] std::size_t size() const { return mu_.size() * slice_size(); }

  /// The number of the point (mu_[imu], psi_[ipsi], kSigns[isign], s_[is]).
  [[nodiscard]] std::size_t index(std::size_t imu, std::size_t ipsi, std::size_t isign,
                                  std::size_t is) const {
    return ((imu * psi_.size() + ipsi) * kSigns.size() + isign) * s_.size() + is;
  }
  /// The point numbered `i` (< size()).
  [[nodiscard]] GridPoint point(std::size_t i) const;
  /// The index of the mu slice holding point `i`.
  [[nodiscard]] std::size_t mu_index(std::size_t i) const { return i / slice_size(); }

  /// Index of the node nearest to `value` (ties: the lower one).
  [[nodiscard]] std::size_t nearest_mu(double value) const;
  [[nodiscard]] std::size_t nearest_psi(double value) const;

 private:
  GridSpec spec_;
  std::vector<double> s_, mu_, psi_;
};

}  // namespace frictionlab::accuracy
