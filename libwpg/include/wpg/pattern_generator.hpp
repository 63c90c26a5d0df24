#pragma once
// The reactive walking pattern generator as an online object: one call per NMPC sample turns
// a velocity command into the next sampling period's CoM jerk and swing-foot target (Fig. 3,
// "WPG" block). It owns the walking phase bookkeeping:
//
//  * A step lasts S = single + double support samples (8 x 0.1 s). The support foot of a
//    step owns the CoP samples at phase times 0 .. S-1; the swing foot lifts at phase time 0
//    and lands at S-1; the last period (S-1 -> S) is the double support in which the CoP
//    passes to the landed foot. NMPC samples thus never fall inside a double support
//    (paper Sec. III-C1), and at phase time S-1 the landed step is fixed in the problem.
//  * Standing: double support with the CoP kept in the hull of both feet. A non-zero
//    command starts walking: a double support of start_double_support_samples in which the
//    CoP samples may use both feet (the CoM must first move towards the first support foot,
//    which needs the CoP on the other side of it), then the first lift-off. A zero command is
//    followed by one free step to slow down, then a side-by-side step, then standing again.
#include <chrono>
#include <memory>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "wpg/nmpc.hpp"

namespace wpg {

class PatternGenerator {
 public:
  PatternGenerator(const WalkingParameters& parameters, const GeneratorSettings& settings);

  // Obstacles to avoid (eq. 18-19), copied and owned; replaces the previous ones. Throws
  // std::invalid_argument naming 'obstacles[i]' for an invalid obstacle. Allocates (call it
  // between samples, not in a hard real-time loop).
  void setObstacles(std::vector<Obstacle> obstacles);
  // The obstacles with libwpg's exact 2-D distances, as the NMPC's obstacle rows see them.
  const ObstacleSet& obstacles() const { return obstacles_; }

  // Standing with the ankles side by side (initial_foot_separation) about `pose` = (x, y, yaw)
  // of the point between them; CoM at rest above it at com_height.
  void reset(const Eigen::Vector3d& pose = Eigen::Vector3d::Zero());

  // Solves the problem of the sample at `time` for a robot-frame command [vx, vy, omega]
  // (clamped to the robot's limits). Does not allocate once warmed up.
  const MpcIterationLog& update(double time, const Eigen::Vector3d& command);

  // What to execute during the sampling period that starts at the last update().
  struct SamplePlan {
    double jerk_x = 0.0, jerk_y = 0.0;  // [m/s^3], first jerks of the solution
    SupportState support = SupportState::kDouble;
    bool swinging = false;
    FootSide swing_side = FootSide::kLeft;
    Eigen::Vector3d swing_target = Eigen::Vector3d::Zero();  // planned landing (x, y, yaw)
    double landing_time = 0.0;  // [s]
    double lift_off_time = 0.0;  // [s]
  };
  const SamplePlan& plan() const { return plan_; }

  // Ends the sampling period: the caller integrated the CoM (possibly pushed) and passes the
  // state at its end. Returns true when a foot landed at the end of the period (lastLanding()).
  bool advance(const Eigen::Vector3d& com_x, const Eigen::Vector3d& com_y);
  const Footstep& lastLanding() const { return last_landing_; }

  const Eigen::Vector3d& comX() const { return com_x_; }
  const Eigen::Vector3d& comY() const { return com_y_; }
  const Eigen::Vector3d& footPose(FootSide side) const {  // on the ground (swing: lift-off pose)
    return side == FootSide::kLeft ? left_ : right_;
  }
  bool standing() const { return standing_; }
  double commandedHeading() const { return commanded_heading_; }
  bool starting() const { return start_remaining_ > 0; }
  int phaseSample() const { return phase_sample_; }
  const NmpcModel& model() const { return model_; }
  const NmpcProblem& problem() const { return problem_; }
  const NmpcSolver& solver() const { return solver_; }
  const NmpcSolveResult& lastSolve() const { return last_solve_; }
  Eigen::Vector3d clampCommand(const Eigen::Vector3d& command) const;

 private:
  Eigen::Vector3d& foot(FootSide side) { return side == FootSide::kLeft ? left_ : right_; }
  Eigen::Vector3d stepPose(int step) const;
  Eigen::Vector3d nominalStep(const Eigen::Vector3d& previous, FootSide side,
                              const Eigen::Vector3d& command) const;
  void setStepPose(int step, const Eigen::Vector3d& pose);
  void buildProblem(const Eigen::Vector3d& command);
  void setDoubleSupport(PhaseStructure& phase) const;
  void selectObstacles();

  NmpcModel model_;
  GeneratorSettings settings_;
  NmpcSolver solver_;
  NmpcProblem problem_;
  SamplePlan plan_;
  MpcIterationLog log_;
  NmpcSolveResult last_solve_;
  Footstep last_landing_;
  ObstacleSet obstacles_;
  std::vector<std::pair<double, int>> obstacle_order_;  // scratch, sized once

  Eigen::Vector3d com_x_ = Eigen::Vector3d::Zero(), com_y_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d left_ = Eigen::Vector3d::Zero(), right_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d command_ = Eigen::Vector3d::Zero();
  // CoM velocities (x; y) at the current and previous samples, newest first: the walked part
  // of J1's windowed velocity (velocity_window_samples - 1 columns).
  Eigen::Matrix<double, 2, Eigen::Dynamic> velocity_history_;
  double time_ = 0.0;
  // The command's heading at time_ (heading_reference: command): the feet's mean yaw when the
  // walk started plus the integral of the commanded omega since.
  double commanded_heading_ = 0.0;
  bool standing_ = true;
  FootSide support_side_ = FootSide::kRight;
  int phase_sample_ = 0;        // 0 .. S-1 within the current step
  int start_remaining_ = 0;     // > 0: starting double support, samples left before S-1
  int zero_command_steps_ = 0;  // consecutive step starts with a zero command
  bool stop_step_ = false;      // the current swing is the final side-by-side step
  bool structure_changed_ = false;
};

inline FootSide otherSide(FootSide side) {
  return side == FootSide::kLeft ? FootSide::kRight : FootSide::kLeft;
}

}  // namespace wpg
