#include "dynamics/paper/narrative_checks.h"

#include <cmath>
#include <iterator>

#include "friction/support/number_format.h"

namespace frictionlab::dynamics::paper {
namespace {

// Evidence numbers: three significant digits, or `digits` after the point.
std::string g3(double x) { return support::significant(x, 3); }
std::string f(double x, int digits) { return support::fixed(x, digits); }

std::string percent(double part, double whole) { return f(100.0 * part / whole, 1) + " % of the run"; }

std::string pole_name(int pole) { return pole > 0 ? "gamma3 = +1" : "gamma3 = -1"; }

// The run could not show features later than `t` (it did not run, or stopped early before t).
bool cut_short(const RunResult* r, double t = 0.0) {
  return r == nullptr || !r->executed || (!r->ended_normally() && !(r->summary.t_final > t));
}

std::string stopped(const RunResult* r) {
  if (r == nullptr) return "not run";
  if (!r->executed) return "did not run";
  return "stopped (" + std::string(to_string(r->summary.reason)) + ") at t = " + g3(r->summary.t_final) + " s";
}

ClaimCheck claim(std::string id, std::string text) {
  ClaimCheck c;
  c.id = std::move(id);
  c.claim = std::move(text);
  return c;
}

void set(ClaimCheck& c, Verdict v, std::string evidence) {
  c.verdict = v;
  c.evidence = std::move(evidence);
}

std::string near_vertical_note(const RunFeatures& ft) {
  const VerticalEpisode& n = ft.near_vertical;
  if (!n.reached) return "max |gamma3| = " + f(ft.max_abs_gamma3, 4);
  return "|gamma3| > 0.99 from t = " + g3(n.t_reached) + " s for " + g3(n.duration(ft.t_final)) + " s";
}

// a1 / b1: the axis quickly becomes vertical (on the pole it starts near).
ClaimCheck quickly_vertical(const std::string& id, const std::string& text, const RunResult* r,
                            const NarrativeRules& rules) {
  ClaimCheck c = claim(id, text);
  if (r == nullptr || !r->executed) {
    set(c, Verdict::not_measurable, stopped(r));
    return c;
  }
  const RunFeatures& ft = r->features;
  const VerticalEpisode& v = ft.vertical;
  const int start_pole = ft.gamma3_initial >= 0.0 ? 1 : -1;
  if (!v.reached) {
    if (!r->ended_normally()) {
      set(c, Verdict::not_measurable, stopped(r) + " before |gamma3| > 0.999 (" + near_vertical_note(ft) + ")");
    } else {
      set(c, ft.near_vertical.reached && ft.near_vertical.left ? Verdict::partly : Verdict::fails,
          "|gamma3| never exceeds 0.999 (" + near_vertical_note(ft) + ")");
    }
    return c;
  }
  const std::string when = "|gamma3| > 0.999 at t = " + g3(v.t_reached) + " s (" + percent(v.t_reached, ft.t_final) +
                           ", " + pole_name(v.pole) + ")";
  if (v.pole != start_pole) {
    set(c, Verdict::fails, when + ": the other pole than the start");
  } else if (!v.left) {
    set(c, Verdict::fails, when + ", only in the final position (" + near_vertical_note(ft) + ")");
  } else if (!r->ended_normally()) {
    set(c, Verdict::not_measurable,
        "|gamma3| > 0.999 at t = " + g3(v.t_reached) + " s, but the run " + stopped(r) +
            ": 'quickly' (relative to the whole motion) cannot be judged");
  } else if (v.t_reached > rules.quick_fraction * ft.t_final) {
    set(c, Verdict::fails, when + ": not within " + f(100 * rules.quick_fraction, 0) + " % of the run");
  } else {
    set(c, Verdict::holds, when);
  }
  return c;
}

double spin_duration(const RunResult* r) { return r->features.vertical.duration(r->features.t_final); }
double near_duration(const RunResult* r) { return r->features.near_vertical.duration(r->features.t_final); }

bool has_vertical_spin(const RunResult* r) {
  return r != nullptr && r->executed && r->features.vertical.reached && r->features.vertical.left;
}

// a3 / b3: then tilts fast to some angle.
ClaimCheck tilts_to_plateau(const std::string& id, const std::string& text, const RunResult* r) {
  ClaimCheck c = claim(id, text);
  if (cut_short(r)) {
    set(c, Verdict::not_measurable, stopped(r));
    return c;
  }
  const Plateau& p = r->features.plateau;
  if (!p.found) {
    set(c, r->ended_normally() ? Verdict::fails : Verdict::not_measurable,
        (r->ended_normally() ? std::string("no plateau") : stopped(r) + " before a plateau") + " (from t = " +
            g3(p.t_from) + " s)");
    return c;
  }
  const std::string e = "from t = " + g3(p.t_from) + " s to " + f(p.tilt_deg(), 1) + " deg (gamma3 = " +
                        f(p.gamma3, 3) + ") in " + g3(p.tilt_time()) + " s; stays within +-0.05 for " +
                        g3(p.duration()) + " s" + (p.lasts_to_end ? " (to the end)" : "");
  set(c, p.tilt_time() < p.duration() ? Verdict::holds : Verdict::fails,
      e + (p.tilt_time() < p.duration() ? "" : ": the tilt is not faster than the plateau lasts"));
  return c;
}

std::string final_position(const RunResult* r) {
  const RunFeatures& ft = r->features;
  const double g = ft.gamma3_final_mean;
  std::string where = "<gamma3> = " + f(g, 3);
  if (std::abs(g) > r->thresholds.near_vertical)
    where += (g >= 0.0 ? 1 : -1) == r->low_pole ? " (on the pole with the lower centre of mass)"
                                                 : " (on the pole with the higher centre of mass)";
  return where;
}

// The final position is on (1), near (0: within rules.near_pole) or away from (-1) a pole.
int on_pole(const RunResult* r, const NarrativeRules& rules) {
  const double g = std::abs(r->features.gamma3_final_mean);
  return g > r->thresholds.near_vertical ? 1 : (g > rules.near_pole ? 0 : -1);
}

// a4: then sinks smoothly to an equilibrium.
ClaimCheck ends_in_equilibrium(const std::string& id, const std::string& text, const RunResult* r,
                               const NarrativeRules& rules) {
  ClaimCheck c = claim(id, text);
  if (cut_short(r) || !r->ended_normally()) {
    set(c, Verdict::not_measurable, stopped(r));
    return c;
  }
  const RunFeatures& ft = r->features;
  std::string e = "ends at " + final_position(r) + " at t = " + g3(ft.t_final) + " s";
  const Plateau& p = ft.plateau;
  if (p.found && !p.lasts_to_end) e += ", " + g3(ft.t_final - p.t_end) + " s after leaving the plateau";
  const int pole = on_pole(r, rules);
  if (!r->stagnated()) {
    set(c, Verdict::fails, e + "; still moving (t_end)");
  } else if (pole > 0) {
    set(c, Verdict::holds, e);
  } else if (pole == 0) {
    set(c, Verdict::partly, e + ": still rolling near the pole");
  } else {
    set(c, Verdict::fails, e + ": not on a pole");
  }
  return c;
}

// a5 / b5: the velocities enter the stagnation region and the motion stops.
ClaimCheck motion_stops(const std::string& id, const std::string& text, const RunResult* r) {
  ClaimCheck c = claim(id, text);
  if (cut_short(r) || !r->ended_normally()) {
    set(c, Verdict::not_measurable, stopped(r));
    return c;
  }
  const double t = r->summary.t_final;
  switch (r->summary.reason) {
    case Termination::rest: set(c, Verdict::holds, "rest at t = " + g3(t) + " s"); break;
    case Termination::rolling:
      set(c, Verdict::partly,
          "slip and spin stop at t = " + g3(t) + " s but the body still rocks/rolls (kinetic energy " +
              g3(r->features.kinetic_final) + " J; the model has no rolling resistance)");
      break;
    default: set(c, Verdict::fails, "still moving at t_end = " + g3(t) + " s"); break;
  }
  return c;
}

// a6: N never reaches 0.
ClaimCheck never_lifts_off(const std::string& id, const std::string& text, const RunResult* r) {
  ClaimCheck c = claim(id, text);
  if (r == nullptr || !r->executed) {
    set(c, Verdict::not_measurable, stopped(r));
    return c;
  }
  const double min_n = r->summary.min_normal_force / r->weight;
  const std::string scope = r->ended_normally() ? "" : " (up to where it " + stopped(r) + ")";
  if (r->summary.liftoffs == 0 && min_n > 0.0) {
    set(c, r->ended_normally() ? Verdict::holds : Verdict::not_measurable,
        "min N/(m g) = " + f(min_n, 3) + ", no lift-off" + scope);
  } else {
    std::string e = std::to_string(r->summary.liftoffs) + " lift-offs, min N/(m g) = " + f(min_n, 3);
    if (std::isfinite(r->features.last_sampled_liftoff))
      e += ", last seen at t = " + g3(r->features.last_sampled_liftoff) + " s";
    set(c, Verdict::fails, e + scope);
  }
  return c;
}

// a2: it spins about the vertical only briefly.
ClaimCheck spins_briefly(const RunResult* a, const NarrativeRules& rules) {
  ClaimCheck c = claim("a2", "it spins about the vertical only briefly");
  if (!has_vertical_spin(a)) {
    set(c, Verdict::not_measurable, "no vertical spin (see a1)");
    return c;
  }
  const double d = spin_duration(a);
  set(c, d <= rules.quick_fraction * a->features.t_final ? Verdict::holds : Verdict::fails,
      g3(d) + " s (" + percent(d, a->features.t_final) + "); |gamma3| > 0.99 for " + g3(near_duration(a)) + " s");
  return c;
}

// b2 when case a or b has no vertical spin at 0.999: judged on the near-vertical (0.99) episodes.
void judge_near_vertical_spins(ClaimCheck& c, const RunResult* a, const RunResult* b, const NarrativeRules& rules) {
  const std::string why = !has_vertical_spin(b) ? "no vertical spin in case b" : "no vertical spin in case a";
  if (a && b && a->executed && b->executed && a->features.near_vertical.left && b->features.near_vertical.left) {
    const double ratio = near_duration(b) / near_duration(a);
    set(c, ratio >= rules.much_longer ? Verdict::partly : Verdict::fails,
        why + " (0.999); |gamma3| > 0.99 for " + g3(near_duration(b)) + " s vs " + g3(near_duration(a)) +
            " s in case a (x" + f(ratio, 2) + ")");
  } else {
    set(c, Verdict::not_measurable, why);
  }
}

// b2: it spins about the vertical much longer than in case a.
ClaimCheck spins_much_longer(const RunResult* a, const RunResult* b, const NarrativeRules& rules) {
  ClaimCheck c = claim("b2", "it spins about the vertical much longer than in case a");
  if (!has_vertical_spin(b) || !has_vertical_spin(a)) {
    judge_near_vertical_spins(c, a, b, rules);
    return c;
  }
  const double ratio = spin_duration(b) / spin_duration(a);
  const double near_ratio = near_duration(b) / near_duration(a);
  const std::string e = g3(spin_duration(b)) + " s vs " + g3(spin_duration(a)) + " s in case a (x" + f(ratio, 2) +
                        "); |gamma3| > 0.99: " + g3(near_duration(b)) + " s vs " + g3(near_duration(a)) + " s (x" +
                        f(near_ratio, 2) + ")";
  const Verdict v = ratio >= rules.much_longer ? Verdict::holds
                                               : (near_ratio >= rules.much_longer ? Verdict::partly : Verdict::fails);
  set(c, v, e);
  return c;
}

// b4: then it oscillates down to equilibrium (case a: smoothly).
ClaimCheck oscillates_down(const RunResult* a, const RunResult* b, const NarrativeRules& rules) {
  ClaimCheck c = claim("b4", "then it oscillates down to equilibrium (case a: smoothly)");
  if (cut_short(b) || !b->ended_normally() || !std::isfinite(b->features.descent_oscillation)) {
    set(c, Verdict::not_measurable, cut_short(b) || !b->ended_normally() ? stopped(b) : "no descent after a plateau");
    return c;
  }
  const double ob = b->features.descent_oscillation;
  if (a == nullptr || !a->ended_normally() || !std::isfinite(a->features.descent_oscillation)) {
    set(c, Verdict::not_measurable, "peak-to-peak " + f(ob, 3) + "; case a has no descent to compare");
    return c;
  }
  const double oa = a->features.descent_oscillation;
  set(c, ob >= rules.oscillation_factor * oa && b->stagnated() ? Verdict::holds : Verdict::fails,
      "gamma3 swings " + f(ob, 3) + " peak-to-peak about its 1-s mean vs " + f(oa, 3) + " in case a; ends at " +
          final_position(b));
  return c;
}

// c1: the axis rises toward the position with the lowest centre of mass; c2: without reaching it.
std::vector<ClaimCheck> rises_toward_lowest(const RunResult* cc) {
  ClaimCheck c1 = claim("c1", "the axis rises toward the position with the lowest centre of mass");
  ClaimCheck c2 = claim("c2", "without reaching it");
  if (cut_short(cc) || !cc->features.plateau.found) {
    const bool measurable = !cut_short(cc) && cc->ended_normally();
    const std::string why = measurable ? "no plateau: the axis does not settle" : stopped(cc) + " before a plateau";
    set(c1, measurable ? Verdict::fails : Verdict::not_measurable, why);
    set(c2, Verdict::not_measurable, why);
    return {c1, c2};
  }
  const Plateau& p = cc->features.plateau;
  const int dir = p.gamma3 > cc->features.gamma3_initial ? 1 : -1;
  set(c1, dir == cc->low_pole ? Verdict::holds : Verdict::fails,
      "gamma3 " + f(cc->features.gamma3_initial, 3) + " -> " + f(p.gamma3, 3) + " by t = " + g3(p.t_start) +
          " s, toward " + pole_name(dir) + "; lowest centre of mass at " + pole_name(cc->low_pole));
  const bool reached = cc->features.rise_extreme > cc->thresholds.vertical;
  set(c2, reached ? Verdict::fails : Verdict::holds,
      "closest approach before the plateau: gamma3 = " + f(dir * cc->features.rise_extreme, 3));
  return {c1, c2};
}

// c3: it settles at the angle case a reaches after its vertical spin.
ClaimCheck settles_at_case_a_angle(const RunResult* a, const RunResult* cc, const NarrativeRules& rules) {
  ClaimCheck c = claim("c3", "it settles at the angle case a reaches after its vertical spin");
  const Plateau& p = cc->features.plateau;
  if (cut_short(cc) || !p.found || a == nullptr || cut_short(a) || !a->features.plateau.found) {
    set(c, Verdict::not_measurable,
        cut_short(cc) ? stopped(cc) : (!p.found ? "no plateau in case c" : "no plateau in case a to compare"));
    return c;
  }
  const double da = a->features.plateau.tilt_deg();
  const double dc = p.tilt_deg();
  set(c, std::abs(dc - da) <= rules.same_angle_deg ? Verdict::holds : Verdict::fails,
      f(dc, 1) + " deg vs " + f(da, 1) + " deg in case a");
  return c;
}

// c4: then it moves as in case a (same final position).
ClaimCheck ends_as_case_a(const RunResult* a, const RunResult* cc, const NarrativeRules& rules) {
  ClaimCheck c = claim("c4", "then it moves as in case a (same final position)");
  if (cut_short(cc) || !cc->ended_normally() || a == nullptr || !a->ended_normally()) {
    set(c, Verdict::not_measurable, !cc->ended_normally() ? stopped(cc) : "case a " + stopped(a));
    return c;
  }
  const bool same = (cc->features.gamma3_final_mean >= 0.0) == (a->features.gamma3_final_mean >= 0.0) &&
                    on_pole(cc, rules) >= 0 && on_pole(a, rules) >= 0;
  set(c, same && cc->stagnated() ? Verdict::holds : Verdict::fails,
      "ends at " + final_position(cc) + " (case a: <gamma3> = " + f(a->features.gamma3_final_mean, 3) + ")");
  return c;
}

// c5: a series of lift-offs while the axis rises.
ClaimCheck lifts_off_while_rising(const RunResult* cc, const NarrativeRules& rules) {
  ClaimCheck c = claim("c5", "a series of lift-offs while the axis rises");
  if (cc == nullptr || !cc->executed) {
    set(c, Verdict::not_measurable, stopped(cc));
    return c;
  }
  const Plateau& p = cc->features.plateau;
  const long n = cc->features.sampled_liftoffs_before_plateau;
  const std::string upto = p.found ? "before the plateau (t < " + g3(p.t_start) + " s)" : "in the run";
  std::string e = std::to_string(n) + " lift-offs seen in the samples " + upto + "; " +
                  std::to_string(cc->summary.liftoffs) + " in the whole run (every step)";
  const Verdict v = n >= rules.series_of_liftoffs ? Verdict::holds
                                                  : (cut_short(cc, 1.0) ? Verdict::not_measurable : Verdict::fails);
  if (!cc->ended_normally()) e += "; " + stopped(cc);
  set(c, v, e);
  return c;
}

std::vector<ClaimCheck> case_a_claims(const RunResult* a, const NarrativeRules& rules) {
  return {quickly_vertical("a1", "the axis quickly becomes vertical", a, rules),
          spins_briefly(a, rules),
          tilts_to_plateau("a3", "then the axis tilts fairly fast to some angle", a),
          ends_in_equilibrium("a4", "then it sinks smoothly to an equilibrium position", a, rules),
          motion_stops("a5", "the velocities enter the stagnation region and the motion stops", a),
          never_lifts_off("a6", "N never reaches 0: no lift-off", a)};
}

std::vector<ClaimCheck> case_b_claims(const RunResult* a, const RunResult* b, const NarrativeRules& rules) {
  return {quickly_vertical("b1", "the axis also quickly becomes vertical", b, rules),
          spins_much_longer(a, b, rules),
          tilts_to_plateau("b3", "then the axis drops sharply to some angle", b),
          oscillates_down(a, b, rules),
          motion_stops("b5", "the motion stops", b)};
}

std::vector<ClaimCheck> case_c_claims(const RunResult* a, const RunResult* cc, const NarrativeRules& rules) {
  std::vector<ClaimCheck> out = rises_toward_lowest(cc);
  out.push_back(settles_at_case_a_angle(a, cc, rules));
  out.push_back(ends_as_case_a(a, cc, rules));
  out.push_back(lifts_off_while_rising(cc, rules));
  return out;
}

void append(std::vector<ClaimCheck>& out, std::vector<ClaimCheck> more) {
  out.insert(out.end(), std::make_move_iterator(more.begin()), std::make_move_iterator(more.end()));
}

}  // namespace

std::string_view to_string(Verdict v) {
  switch (v) {
    case Verdict::holds: return "yes";
    case Verdict::partly: return "partly";
    case Verdict::fails: return "no";
    case Verdict::not_measurable: return "n/a";
  }
  return "?";
}

std::vector<ClaimCheck> check_narrative(const CaseRuns& runs, const NarrativeRules& rules) {
  std::vector<ClaimCheck> out;
  if (runs.a) append(out, case_a_claims(runs.a, rules));
  if (runs.b) append(out, case_b_claims(runs.a, runs.b, rules));
  if (runs.c) append(out, case_c_claims(runs.a, runs.c, rules));
  return out;
}

}  // namespace frictionlab::dynamics::paper
