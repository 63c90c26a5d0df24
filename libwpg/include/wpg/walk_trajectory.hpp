#pragma once
// The result of one walk: samples at the control period, the footsteps, and one log row per
// NMPC iteration. Names and shapes mirror the HDF5 schema (datasets/SCHEMA.md).
#include <cstdint>
#include <vector>

#include <Eigen/Core>

namespace wpg {

enum class SupportState : std::uint8_t { kDouble = 0, kLeft = 1, kRight = 2 };
enum class FootSide : std::uint8_t { kLeft = 1, kRight = 2 };

// Outcome of one NMPC iteration, stored per iteration (dataset `mpc/status`).
enum class IterationStatus : std::uint8_t {
  kSolved = 0,             // every QP solved to optimality
  kRelaxed = 1,            // the QP was infeasible; solved with penalized slacks
  kFallback = 2,           // relaxation failed too: the time-shifted previous plan was kept
  kIterationLimit = 3,     // the QP hit its iteration limit; its last iterate was used
  kFallen = 4,             // the capture point left the reach of the feet: the walk ends here
  kNotConverged = 5,       // SQP to convergence stopped at max_sqp_iterations; last iterate used
};
const char* iterationStatusName(IterationStatus status);

struct Footstep {
  double landing_time = 0.0;  // [s]; 0 for the initial feet
  Eigen::Vector3d pose = Eigen::Vector3d::Zero();  // x, y [m], yaw [rad] of the ankle on the ground
  FootSide side = FootSide::kLeft;
};

struct MpcIterationLog {
  double time = 0.0;          // [s]
  double solve_time = 0.0;    // [s], wall time of the whole iteration (linearize + QP(s))
  int qp_iterations = 0;      // active-set iterations, summed over SQP iterations
  int sqp_iterations = 0;     // QPs solved in this sample
  IterationStatus status = IterationStatus::kSolved;
  double cost = 0.0;          // value of the NMPC cost (5) at the applied solution
  double slack = 0.0;         // largest constraint relaxation when status == kRelaxed [m or rad]
};

struct WalkTrajectory {
  // one row per control period
  std::vector<double> time;                         // [s]
  std::vector<Eigen::Vector3d> com, com_vel, com_acc;  // world [m, m/s, m/s^2]
  std::vector<Eigen::Vector2d> cop;                  // world [m], LIPM CoP z = c - h/g c''
  std::vector<Eigen::Vector4d> left_foot, right_foot;  // x, y, z [m], yaw [rad] (ankle)
  std::vector<double> free_flyer_yaw;                // [rad], mean of the feet yaws
  std::vector<SupportState> support;
  // landed footsteps in landing order, the two initial feet first (landing_time 0)
  std::vector<Footstep> footsteps;
  std::vector<MpcIterationLog> mpc;

  std::size_t size() const { return time.size(); }
  void reserve(std::size_t samples, std::size_t iterations);
};

}  // namespace wpg
