#pragma once
// A sphere sliding and spinning on a plane in MuJoCo (2.2 API), with condim 4 and an elliptic
// cone: the MuJoCo half of the side by side of docs/engines.md §4.
//
// The model (written out as MJCF, kept beside the results): a plane and a free sphere of radius R,
// mass m and inertia diag(A, A, C), both geoms with condim = 4 and friction = "k torsional 0"
// (MuJoCo mixes two geoms' coefficients by their maximum, so both carry the same), cone =
// "elliptic", the Newton solver, gravity g. The contact is MuJoCo's soft contact: solref =
// (timeconst, dampratio) and solimp at MuJoCo's defaults unless given (docs/engines.md §4 says what
// that changes against a Hertz contact). The sphere is first let settle at rest for `settle_time`
// (the soft contact finds its own depth), then given the velocities, and time restarts at 0.
// The model is written, and run, by the engines' MuJoCo adapter (bench/engines/mujoco:
// mujoco_mjcf, MujocoWorld), the one place frictionlab writes and steps a MuJoCo model.

#include <array>
#include <filesystem>
#include <string>
#include <vector>

namespace frictionlab::mujoco_side {

struct SphereSpec {
  double R = 0.05;          ///< sphere radius, m
  double mass = 1.0;        ///< kg
  double A = 0.001;         ///< transverse moment of inertia, kg m^2
  double C = 0.001;         ///< axial moment of inertia, kg m^2
  double g = 9.81;          ///< m/s^2
  double k = 0.2;           ///< MuJoCo's sliding friction mu1 = mu2
  double torsional = 1e-4;  ///< MuJoCo's torsional friction mu3, m
  std::array<double, 3> v0{};      ///< initial velocity of the centre, m/s (world = body frame at t = 0)
  std::array<double, 3> omega0{};  ///< initial angular velocity, 1/s
  double t_end = 1.0;       ///< s
  double output_dt = 1e-3;  ///< s
  double timestep = 1e-4;   ///< MuJoCo's time step, s
  double solref_timeconst = 0.02;  ///< MuJoCo's default solref (0.02, 1)
  double solref_dampratio = 1.0;
  double impratio = 1.0;    ///< MuJoCo's default
  double settle_time = 0.5; ///< s at rest before the launch

  /// std::invalid_argument naming the field and the rule (positive sizes, timestep <= output_dt,
  /// solref_timeconst >= 2 timestep as MuJoCo requires for stability, ...).
  void validate() const;
};

/// One sample of the MuJoCo run, in the world frame (z up).
struct Sample {
  double t = 0.0;
  double U = 0.0;      ///< slip speed of the contact point, m/s
  double Omega = 0.0;  ///< spin about the vertical, 1/s
  std::array<double, 3> v{};      ///< centre velocity, m/s
  std::array<double, 3> omega{};  ///< angular velocity, 1/s
  double N = 0.0;      ///< normal force, N (0 out of contact)
  double Ft = 0.0;     ///< tangential force magnitude, N
  double tau = 0.0;    ///< torsional torque about the normal, N m (signed, about +z)
  double depth = 0.0;  ///< penetration, m (> 0 in contact)
};

/// The MJCF text of the model.
[[nodiscard]] std::string mjcf(const SphereSpec& spec);

/// Writes the model to `xml` (kept for the reader), loads it with mj_loadXML, settles, launches
/// and samples every output_dt up to t_end. std::runtime_error with MuJoCo's message if the model
/// does not load, or if the state becomes non-finite.
[[nodiscard]] std::vector<Sample> run_sphere(const SphereSpec& spec, const std::filesystem::path& xml);

/// MuJoCo's version string ("2.2.2").
[[nodiscard]] std::string mujoco_version();

}  // namespace frictionlab::mujoco_side
