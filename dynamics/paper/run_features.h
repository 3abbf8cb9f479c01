#pragma once
// The features of one run that section 2 of the paper describes (docs/model.md §6), measured on the
// sampled gamma3 (the cosine of the nutation angle) and contact of a RunSeries. Two centred moving
// averages of gamma3 are used: <gamma3>_1 over `smoothing_window` (1 s) removes the nutation
// (~2-20 Hz in these runs); <gamma3>_5 over `plateau_window` (5 s) also removes the slower swings
// of the axis after a fast tilt.
//
//   vertical       the axis becomes vertical: the first sample with |gamma3| > `vertical`
//                  (0.999, 2.6 deg). It is a vertical *spin* that has ended when afterwards
//                  |<gamma3>_1| first reaches `near_vertical` (0.99, 8.1 deg) and then falls below
//                  it (t_left), and the axis then moves on to |<gamma3>_1| < near_vertical -
//                  plateau_min_move: a body that ends rocking or rolling on its pole stays on it.
//   near vertical  the same with entry at `near_vertical`.
//   plateau        after the vertical spin (or from t = 0 if there is none), the first time
//                  <gamma3>_5 has moved more than `plateau_min_move` from where the tilt began and
//                  changes slower than `plateau_rate`: "tilts fast to some angle". It is held
//                  until <gamma3>_5 leaves +-`plateau_band` of that value.
//   descent        from the end of the plateau to the first return to |gamma3| > `vertical` (or
//                  the end): the largest peak-to-peak swing of gamma3 about <gamma3>_1
//                  ("oscillates down to rest" in case b vs "smoothly" in case a).
//   final          <gamma3>_1 over the last `smoothing_window` of the run (a body that ends
//                  rolling in small circles on its pole keeps a small tilt).
//   first motion   the sign of the first change of gamma3 larger than `first_move`.
//   lift-offs      contact -> no contact between consecutive samples (a lower bound on the
//                  integrator's count, which sees every step).

#include <limits>

#include "dynamics/paper/run_series.h"

namespace frictionlab::dynamics::paper {

struct FeatureThresholds {
  double vertical = 0.999;        ///< |gamma3| above: the axis is vertical (2.6 deg)
  double near_vertical = 0.99;    ///< |gamma3| below (moving average): the axis has left the vertical
  double smoothing_window = 1.0;  ///< s, width of the moving average <gamma3>_1 (removes the nutation)
  double plateau_window = 5.0;    ///< s, width of the moving average <gamma3>_5 (plateau detection)
  double plateau_band = 0.05;     ///< a plateau stays within this of its gamma3
  double plateau_rate = 0.01;     ///< 1/s: |d<gamma3>/dt| below this ends the fast tilt
  double plateau_min_move = 0.05; ///< the plateau differs from gamma3 where the tilt began by more
  double first_move = 1e-3;       ///< change of gamma3 that counts as the first motion

  /// Each must be finite; 0 < near_vertical < vertical < 1, the others > 0 (std::invalid_argument).
  void validate() const;
};

inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// An interval with the axis (nearly) vertical.
struct VerticalEpisode {
  bool reached = false;
  double t_reached = kNaN;  ///< s
  int pole = 0;             ///< +1: gamma3 -> +1 (the pole at z_lo touches); -1: gamma3 -> -1
  bool left = false;        ///< the axis left the vertical again before the run ended
  double t_left = kNaN;     ///< s
  /// t_left - t_reached, or until the end of the run when never left (s); NaN if not reached.
  [[nodiscard]] double duration(double t_final) const {
    return !reached ? kNaN : (left ? t_left : t_final) - t_reached;
  }
};

struct Plateau {
  bool found = false;
  double t_from = kNaN;      ///< s: where the search began (the end of the vertical spin, or 0)
  double t_start = kNaN;     ///< s: the fast tilt has ended
  double gamma3 = kNaN;      ///< <gamma3>_5 at t_start
  double t_end = kNaN;       ///< s: <gamma3>_5 left the band (or the run ended)
  bool lasts_to_end = false; ///< the run ended on the plateau
  [[nodiscard]] double tilt_deg() const;      ///< acos(gamma3) in degrees
  [[nodiscard]] double tilt_time() const { return t_start - t_from; }  ///< s
  [[nodiscard]] double duration() const { return t_end - t_start; }     ///< s
};

struct RunFeatures {
  double t_final = kNaN;        ///< s, last sample
  double gamma3_initial = kNaN;
  double gamma3_final = kNaN;
  double gamma3_final_mean = kNaN;  ///< <gamma3>_1 at the end (mean over the last smoothing window)
  double kinetic_final = kNaN;  ///< J
  double max_abs_gamma3 = kNaN; ///< over the run
  int first_move = 0;           ///< +1: gamma3 first increases; -1: decreases; 0: never moved
  double t_first_move = kNaN;   ///< s
  VerticalEpisode vertical;
  VerticalEpisode near_vertical;
  Plateau plateau;
  /// Largest gamma3 * sign(plateau - initial) reached before the plateau: how close the axis came
  /// to the vertical it tilted toward (case c: "rises ... without reaching it"). NaN without a plateau.
  double rise_extreme = kNaN;
  double descent_oscillation = kNaN;  ///< peak-to-peak of gamma3 - <gamma3>_1 in the descent
  long sampled_liftoffs = 0;
  long sampled_liftoffs_before_plateau = 0;  ///< before plateau.t_start (the whole run if none)
  double last_sampled_liftoff = kNaN;        ///< s
};

/// Centred moving average of y(t) over `window` (s), clipped at the ends; t ascending.
[[nodiscard]] std::vector<double> moving_average(const std::vector<double>& t, const std::vector<double>& y,
                                                 double window);

/// The features above. An empty series gives the defaults.
[[nodiscard]] RunFeatures extract_features(const RunSeries& s, const FeatureThresholds& th = {});

}  // namespace frictionlab::dynamics::paper
