#pragma once
// The result of one walk: samples at the control period, the footsteps, and one log row per
// NMPC iteration. Names and shapes mirror the HDF5 schema (datasets/SCHEMA.md).
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "wpg/nmpc_plan.hpp"

namespace wpg {

// At most this many constraint families in one NMPC model (wpg/nmpc/constraint_family.hpp):
// fixed so that every iteration's log holds one slack per family without allocating.
constexpr int kMaxConstraintFamilies = 8;

enum class SupportState : std::uint8_t { kDouble = 0, kLeft = 1, kRight = 2 };
enum class FootSide : std::uint8_t { kLeft = 1, kRight = 2 };

// Outcome of one NMPC iteration, stored per iteration (dataset `mpc/status`). What each does
// to the walk (WalkResult::success, the exit status of `wpg run`) is in walk_loop.hpp.
enum class IterationStatus : std::uint8_t {
  kSolved = 0,             // every QP solved to optimality
  kRelaxedObstacle = 1,    // the QP was infeasible; only obstacle rows (previewed steps) were
                           // relaxed, with penalized slacks; balance and kinematics held
  kFallback = 2,           // relaxation failed too: the time-shifted previous plan was kept
  kIterationLimit = 3,     // a QP hit its iteration limit: its iterate (dual- but not primal-
                           // feasible) was dropped and the time-shifted previous plan kept
  kFallen = 4,             // the capture point left the reach of the feet: the walk ends here
  kNotConverged = 5,       // SQP to convergence stopped at max_sqp_iterations; last iterate used
  kRelaxedKinematics = 6,  // step feasibility or yaw-bound rows had to be relaxed
  kRelaxedBalance = 7,     // CoP (balance) rows had to be relaxed: the plan leaves the support
};
const char* iterationStatusName(IterationStatus status);
// Whether an iteration with this status makes the walk a failure (WalkResult::success false,
// `wpg run` exit 1; the walk is still complete and recorded): every status but kSolved and
// kRelaxedObstacle. A relaxed obstacle row concerns previewed steps only (the robot is held in
// front of an obstacle, the paper's "blocked"); a landed step inside a margin fails the walk
// by itself (generateWalk checks every landing). Kinematics or balance relaxed, a dropped QP
// (fallback, iteration limit), an SQP that did not converge and a fall all fail it.
bool iterationStatusFailsWalk(IterationStatus status);

struct Footstep {
  double landing_time = 0.0;  // [s]; 0 for the initial feet
  Eigen::Vector3d pose = Eigen::Vector3d::Zero();  // x, y [m], yaw [rad] of the ankle on the ground
  FootSide side = FootSide::kLeft;
  // [s] when its swing lifted off: landing_time - lift_off_time is the step's single support
  // (0.7 s for HRP-2's regular steps, shorter with the adaptive step timing or after a push
  // start); 0 for the initial feet.
  double lift_off_time = 0.0;
};

struct MpcIterationLog {
  double time = 0.0;          // [s]
  double solve_time = 0.0;    // [s], wall time of the whole iteration (linearize + QP(s))
  int qp_iterations = 0;      // working-set updates of its QPs (warm starts included)
  int sqp_iterations = 0;     // QPs solved in this sample
  IterationStatus status = IterationStatus::kSolved;
  double cost = 0.0;          // value of the NMPC cost (5) at the applied solution
  // Relaxation of an infeasible QP, per constraint family (WalkTrajectory::constraint_families
  // names them, with their units): bit k of relaxed_families set when family k's rows needed a
  // positive slack; slack[k] its largest value over the iteration's QPs [family's unit].
  std::uint32_t relaxed_families = 0;
  std::array<double, kMaxConstraintFamilies> slack{};
  // The velocity command this iteration's NMPC tracked, robot frame [vx m/s, vy m/s, omega
  // rad/s], as the walk's command source gave it (walk_loop.hpp): the scenario's reference, or
  // the path follower's command on a walk to a goal. NaN when unknown (read back from a file
  // that does not store it: only walks to a goal store it, datasets/SCHEMA.md).
  Eigen::Vector3d command = Eigen::Vector3d::Zero();
  // That command's linear part, clamped to the robot's limits, turned into the world by the
  // heading the generator expressed it in [m/s] (PatternGenerator::commandFrameHeading): what
  // the walk is asked to progress along (progress_monitor.hpp). Zero in a fallen row (no NMPC
  // ran); NaN when unknown (read back from a file written before it was stored).
  Eigen::Vector2d commanded_velocity = Eigen::Vector2d::Zero();
  double maxSlack() const;  // largest slack of any family (0 when nothing was relaxed)
};

// A constraint family of the NMPC as the logs see it (wpg/nmpc/constraint_family.hpp).
struct ConstraintFamilyInfo {
  std::string name;   // e.g. "cop", "obstacle"
  std::string unit;   // of its rows and slack: "m" or "rad"
  std::string group;  // relaxation group: "balance", "kinematics", "obstacle"
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
  // the NMPC's constraint families, in the order of MpcIterationLog::slack
  std::vector<ConstraintFamilyInfo> constraint_families;
  // What each NMPC iteration predicted, one row per row of mpc (GeneratorSettings::
  // record_plan); empty when not recorded.
  PlanLog plans;

  std::size_t size() const { return time.size(); }
  void reserve(std::size_t samples, std::size_t iterations);
};

}  // namespace wpg
