#pragma once
// What a walk is asked to do: a piecewise-constant velocity command, perturbations, and how
// the pattern generator solves its problem. Plain data; datasets/ fills it from a scenario.
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "wpg/obstacles.hpp"

namespace wpg::qp {
class HessianFactorCache;  // wpg/qp/hessian_factor_cache.hpp
}

namespace wpg {

enum class GeneratorAlgorithm {
  kNmpc,  // Naveau et al. 2017: positions and yaws in one nonlinear problem (Gauss-Newton SQP)
  kLmpc,  // Herdt et al. 2010 baseline: orientation QP, then position QP with those yaws
};

// Parses "nmpc" / "lmpc"; returns false on anything else.
bool parseGeneratorAlgorithm(const std::string& name, GeneratorAlgorithm* out);
const char* generatorAlgorithmName(GeneratorAlgorithm algorithm);

// Limits of bounded work (datasets/SCENARIOS.md, "Limits").
constexpr int kMaxSqpIterations = 1000;     // generator.sqp_iterations, max_sqp_iterations
constexpr int kMaxQpIterations = 100000;    // generator.max_qp_iterations
constexpr double kMaxWalkDuration = 3600.0;  // [s] duration of one walk
constexpr int kMaxBlockedWindowCycles = 100;  // generator.blocked_window_cycles (160 s for HRP-2)

// A registered constraint family or cost term (wpg/nmpc/extension_registry.hpp) that the NMPC
// uses, by name, with the values of its parameters (by parameter name, in their units).
using ExtensionArguments = std::map<std::string, double>;
struct ExtensionUse {
  std::string name;
  ExtensionArguments arguments;
};

struct GeneratorSettings {
  GeneratorAlgorithm algorithm = GeneratorAlgorithm::kNmpc;
  // Gauss-Newton iterations per NMPC sample: 1 = real-time iteration (the paper, Sec. III-E);
  // k > 1 = k iterations; 0 = iterate to convergence (bounded by max_sqp_iterations).
  int sqp_iterations = 1;
  int max_sqp_iterations = 50;
  double sqp_tolerance = 1e-8;      // convergence: max |dU| (in U's units) below this
  int max_qp_iterations = 200;      // active-set iterations per QP
  double slack_weight = 1e6;        // penalty of the slack that relaxes an infeasible QP
  // The walk is declared fallen (status kFallen, the run stops) when the capture point
  // c + c'/omega0 is farther than this from both feet [m]. The CoP constraints alone do not
  // make the LIPM capturable: after a large push the NMPC keeps finding feasible plans whose
  // CoM diverges; beyond one maximal step (0.4 m for HRP-2) no step can catch it.
  double fall_capture_distance = 0.6;
  // Obstacle avoidance (eq. 18-19): at most this many obstacles enter the QP at each sample,
  // the nearest ones whose bounding circle is within obstacle_reach of the support foot [m].
  int max_obstacles_in_qp = 4;
  double obstacle_reach = 1.5;
  // The farthest aside of the CoM [m] (across the command) the way round an obstacle on the
  // path may lie for the generator to slide round it (command_tangent): the way past a longer
  // wall is a route to plan, not a velocity command to follow. Beyond it the obstacle (or
  // group) is a wall: its border faces the CoM and J1's reference keeps only its own part
  // along the border, so that the robot stops in front of it (and is found blocked).
  double max_detour = 2.5;
  // Stuck is an outcome (progress_monitor.hpp): the robot is blocked when, over a window of
  // blocked_window_cycles gait cycles of the parameters' nominal steps (3: 4.8 s for HRP-2; a
  // whole number of cycles, over which the CoM's sway cancels), its CoM walks less than
  // blocked_progress of the displacement its linear command asks for, and the walk ends
  // blocked when it has not resumed. stop_when_blocked: the walk ends at the sample it is found
  // blocked (a study saves the rest of a stuck walk); else it runs its duration out.
  int blocked_window_cycles = 3;
  double blocked_progress = 0.25;
  bool stop_when_blocked = false;
  // Record what every NMPC iteration predicts (WalkTrajectory::plans, the dataset's mpc/plan/;
  // nmpc_plan.hpp). Off: a study's runs leave it out of the batch file.
  bool record_plan = true;
  // Where the generator's NMPC models take their Hessians' factors: a cache shared with other
  // generators (the runs of a study share one, loadStudyScenarios), or null: the generator
  // makes its own. Not a setting of the walk: the results are the same bits either way.
  std::shared_ptr<qp::HessianFactorCache> hessian_factors;
  // Extension points (wpg/nmpc/extension_registry.hpp): registered constraint families and
  // cost terms that every NMPC model of the generator adds after the paper's, in this order.
  // Empty (the default): the paper's problem, solved as without them.
  std::vector<ExtensionUse> constraints;
  std::vector<ExtensionUse> costs;

  // Throws std::invalid_argument naming the bad field ("generator.<field>") and what was
  // expected.
  void validate() const;
};

// Command in the robot (free-flyer) frame, held from time t until the next entry.
struct VelocityCommand {
  double t = 0.0;                                     // [s]
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();  // [vx m/s, vy m/s, omega rad/s]
};

// A horizontal force on the CoM during [t, t + duration): added to the CoM acceleration as
// force / mass (paper Sec. V-B), in the world frame.
struct Push {
  double t = 0.0;                                  // [s]
  Eigen::Vector2d force = Eigen::Vector2d::Zero();  // [N]
  double duration = 0.1;                           // [s]
};

struct WalkRequest {
  double duration = 10.0;              // [s] of walking to generate
  std::vector<VelocityCommand> reference;  // sorted by t; empty = stand still
  std::vector<Push> pushes;
  std::vector<Obstacle> obstacles;     // convex obstacles to keep the steps away from
  double robot_mass = 56.037;          // [kg], converts push forces to accelerations (HRP-2: robots/hrp2/README.md)
  GeneratorSettings generator;

  // The command in force at time t (the last entry with entry.t <= t), zero before the first.
  Eigen::Vector3d commandAt(double t) const;
  // Sum of push accelerations [m/s^2] acting at time t.
  Eigen::Vector2d pushAccelerationAt(double t) const;
  // Throws std::invalid_argument naming the bad field and what was expected.
  void validate() const;
};

}  // namespace wpg
