// The MuJoCo adapter: engine.h's Engine over MujocoWorld (mujoco_world.h).

#include "bench/engines/mujoco/mujoco_engine.h"

#include <mujoco/mujoco.h>

#include <cmath>

#include "bench/engines/mujoco/mujoco_world.h"
#include "friction/support/errors.h"

namespace frictionlab::engines {
namespace {

class MujocoEngine final : public Engine {
 public:
  explicit MujocoEngine(const MujocoOptions& options) : options_(options) { options_.validate(); }

  [[nodiscard]] std::string name() const override { return "MuJoCo"; }
  [[nodiscard]] std::string version() const override { return mj_versionString(); }
  // The torsional coefficient mu3 bounds the spin torque by mu3 N: a length (XML reference,
  // geom/@friction; Computation, "Contact": the friction cone of condim 4).
  [[nodiscard]] std::string torsional_unit() const override { return "m"; }

  // MuJoCo's default geom friction is "1 0.005 0.0001" (XML reference, geom/@friction): a user who
  // sets k and condim 4 gets torsional 0.005 m; the rolling 0.0001 m acts only at condim 6.
  [[nodiscard]] Friction defaults(double k) const override {
    check_k(k);
    return {k, 0.005, 0.0001};
  }

  // A sphere spinning in place on a single contact point feels at most mu3 N about the normal (the
  // cone's bound, pyramidal or elliptic), the torque it feels while it spins: mu3 = c k a. Nothing
  // else is needed (the rolling term is not involved in spin; 0 = none, unused below condim 6).
  [[nodiscard]] Friction calibrated(double k, double c, double a) const override {
    check_k(k);
    if (!(std::isfinite(c) && c > 0.0)) throw support::invalid_value("c", c, "must be a finite number > 0");
    if (!(std::isfinite(a) && a > 0.0)) throw support::invalid_value("a", a, "must be a finite number > 0 m");
    return {k, c * k * a, 0.0};
  }

  [[nodiscard]] Run run(const RunSpec& spec) const override {
    MujocoWorld world(spec, options_);
    Run out;
    out.timestep = world.timestep();
    out.iterations = world.iterations();
    out.notes = world.notes();
    out.samples.reserve(static_cast<std::size_t>(world.steps() / world.steps_per_sample() + 1));
    for (;;) {
      if (world.step_index() % world.steps_per_sample() == 0) {
        world.evaluate();
        out.samples.push_back(world.sample());
      }
      if (world.step_index() >= world.steps()) break;
      world.step();
    }
    return out;
  }

 private:
  static void check_k(double k) {
    if (!(std::isfinite(k) && k >= 0.0)) throw support::invalid_value("k", k, "must be a finite number >= 0");
  }

  MujocoOptions options_;
};

}  // namespace

std::unique_ptr<Engine> make_mujoco_engine(const MujocoOptions& options) {
  return std::make_unique<MujocoEngine>(options);
}

}  // namespace frictionlab::engines
