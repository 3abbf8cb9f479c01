#include "bench/engines/engine_list.h"

#if FRICTIONLAB_HAVE_MUJOCO_ENGINE
#include "bench/engines/mujoco/mujoco_engine.h"
#endif
#if FRICTIONLAB_HAVE_BULLET_ENGINE
#include "bench/engines/bullet/bullet_engine.h"
#endif
#if FRICTIONLAB_HAVE_ODE_ENGINE
#include "bench/engines/ode/ode_engine.h"
#endif

namespace frictionlab::engines {

std::vector<std::unique_ptr<Engine>> built_engines() {
  std::vector<std::unique_ptr<Engine>> out;
#if FRICTIONLAB_HAVE_MUJOCO_ENGINE
  out.push_back(make_mujoco_engine());
#endif
#if FRICTIONLAB_HAVE_BULLET_ENGINE
  out.push_back(make_bullet_engine());
#endif
#if FRICTIONLAB_HAVE_ODE_ENGINE
  out.push_back(make_ode_engine());
#endif
  return out;
}

std::vector<EngineVariant> tuned_engines() {
  std::vector<EngineVariant> out;
#if FRICTIONLAB_HAVE_MUJOCO_ENGINE
  {
    MujocoOptions o;
    o.cone = MujocoOptions::Cone::elliptic;
    o.impratio = 100.0;
    out.push_back({"elliptic cone, impratio 100", make_mujoco_engine(o)});
  }
#endif
#if FRICTIONLAB_HAVE_BULLET_ENGINE
  {
    BulletOptions o;
    o.two_friction_directions = true;
    out.push_back({"two friction directions", make_bullet_engine(o)});
  }
#endif
#if FRICTIONLAB_HAVE_ODE_ENGINE
  {
    OdeOptions o;
    o.solver = OdeOptions::Solver::world;
    out.push_back({"dWorldStep (exact LCP)", make_ode_engine(o)});
  }
#endif
  return out;
}

std::vector<std::string> missing_engines() {
  std::vector<std::string> out;
#if !FRICTIONLAB_HAVE_MUJOCO_ENGINE
  out.emplace_back("MuJoCo (libmujoco-dev)");
#endif
#if !FRICTIONLAB_HAVE_BULLET_ENGINE
  out.emplace_back("Bullet (libbullet-dev)");
#endif
#if !FRICTIONLAB_HAVE_ODE_ENGINE
  out.emplace_back("ODE (libode-dev)");
#endif
  return out;
}

}  // namespace frictionlab::engines
