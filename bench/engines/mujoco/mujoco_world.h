#pragma once
// The MuJoCo model of a RunSpec, loaded and run: the one mechanism of stepping MuJoCo in
// frictionlab. The adapter (mujoco_engine.cpp) samples it as engine.h says; bench/mujoco's sphere
// side by side reads more from it (the contact frame, torque, depth) through model() and data().
//
// Sequence: the model text (mujoco_mjcf) is loaded from memory (a MuJoCo virtual file, so nothing
// is written to disk), the body is at its start pose (lowest point on the plane, no penetration),
// it is stepped for Numerics::settle_time with zero velocity (the soft contact finds its depth),
// then the start velocities are set keeping the settled pose, and the clock restarts at 0.

#include <mujoco/mujoco.h>

#include <memory>
#include <string>

#include "bench/engines/engine.h"
#include "bench/engines/mujoco/mujoco_engine.h"

namespace frictionlab::engines {

class MujocoWorld {
 public:
  /// Validates `spec` and `options` (std::invalid_argument naming the field); std::runtime_error
  /// with MuJoCo's message if the model does not load or if MuJoCo reports a bad state while settling.
  MujocoWorld(const RunSpec& spec, const MujocoOptions& options);
  ~MujocoWorld();
  MujocoWorld(const MujocoWorld&) = delete;
  MujocoWorld& operator=(const MujocoWorld&) = delete;

  [[nodiscard]] const std::string& mjcf() const { return mjcf_; }
  [[nodiscard]] const mjModel& model() const { return *model_; }
  [[nodiscard]] const mjData& data() const { return *data_; }
  [[nodiscard]] int body() const { return body_; }  ///< the body's id in the model
  [[nodiscard]] double timestep() const;            ///< s: the step taken
  [[nodiscard]] int iterations() const;            ///< the solver's iteration limit
  [[nodiscard]] long steps() const { return steps_; }  ///< steps from t = 0 to t_end
  [[nodiscard]] long steps_per_sample() const { return every_; }  ///< output_dt in steps (>= 1)
  [[nodiscard]] long step_index() const { return index_; }        ///< steps taken since t = 0
  [[nodiscard]] double time() const;  ///< s since the start: step_index() timestep() (not accumulated)

  /// One mj_step. std::runtime_error if MuJoCo flags a bad qpos/qvel/qacc (it would reset its data
  /// silently: engine_forward.c, mj_checkPos/Vel/Acc) or a full contact or constraint buffer.
  void step();
  /// mj_forward at the current state, so that contacts, forces and velocities are this state's.
  /// The solver's warm start is kept, so looking does not change the trajectory (mj_forward would
  /// otherwise overwrite qacc_warmstart, engine_forward.c).
  void evaluate();
  /// The engine.h sample of the state last evaluated. std::runtime_error if it is not finite.
  [[nodiscard]] Sample sample() const;
  /// One line: the settings a reader needs (engine.h Run::notes).
  [[nodiscard]] std::string notes() const;

 private:
  void check_warnings(const char* when) const;

  RunSpec spec_;
  MujocoOptions options_;
  std::string mjcf_;
  mjModel* model_ = nullptr;
  mjData* data_ = nullptr;
  int body_ = -1;
  long steps_ = 0;
  long every_ = 1;
  long index_ = 0;
  bool launched_ = false;  ///< the settling is over
};

}  // namespace frictionlab::engines
