#pragma once
// The observer that carries a run's shadow laws (dynamics/core/shadow_laws.h): it records the
// contact of every accepted step for the statistics and writes one row of shadow.csv per sample
// (dynamics/core/shadow_csv.h). Any model of dynamics/core/run_loop.h with the member
//   ShadowPoint shadow_point(const State&, const Contact&, const Mode&) const
// can carry shadow laws. It never throws and never changes the run.

#include "dynamics/core/observer.h"
#include "dynamics/core/shadow_csv.h"
#include "dynamics/core/shadow_laws.h"

namespace frictionlab::dynamics {

template <class Model>
class ShadowObserver final : public ObserverOf<Model> {
 public:
  using Sample = SampleOf<Model>;

  /// `csv` may be null (statistics only). All three outlive the observer.
  ShadowObserver(const Model& model, ShadowLaws& laws, ShadowCsv* csv) : model_(model), laws_(laws), csv_(csv) {}

  void sample(const Sample& s) override {
    const ShadowPoint p = model_.shadow_point(s.x, s.contact, s.mode);
    if (!opened_) {  // the run's first state opens the record
      laws_.record_step(s.t, p);
      opened_ = true;
    }
    if (csv_) csv_->write(s.t, p);
  }
  void accepted(const Sample& s) override { laws_.record_step(s.t, model_.shadow_point(s.x, s.contact, s.mode)); }
  [[nodiscard]] bool wants_accepted_steps() const override { return true; }

 private:
  const Model& model_;
  ShadowLaws& laws_;
  ShadowCsv* csv_;
  bool opened_ = false;
};

}  // namespace frictionlab::dynamics
