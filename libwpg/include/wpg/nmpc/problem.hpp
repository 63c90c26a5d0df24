#pragma once
// What changes from one NMPC sample to the next: the walking phase (which support each CoP
// sample uses, which steps are free), the current CoM state, the references of the cost and
// the obstacles near the previewed steps.
#include <Eigen/Core>

#include "wpg/obstacles.hpp"
#include "wpg/walk_trajectory.hpp"

namespace wpg {

// Shape of the problem at one sample: which support each CoP sample uses, which steps are free.
struct PhaseStructure {
  FootSide first_step_side = FootSide::kLeft;  // previewed steps alternate from this side
  // Fixed reference of the samples on the current support: the support foot (x, y, yaw), or
  // the point between the feet when standing; and the CoP rectangle there (half sizes).
  Eigen::Vector3d support_pose = Eigen::Vector3d::Zero();
  double support_half_length = 0.0;
  double support_half_width = 0.0;
  Eigen::VectorXi row_step;        // N: 0 = current support, i = previewed step i (1-based)
  Eigen::VectorXi step_fixed;      // nf: 1 = pose fixed by equality (landed, or final step)
  Eigen::Matrix<double, 3, Eigen::Dynamic> fixed_step_pose;  // 3 x nf
  // Hessian pattern (NmpcModel::rowStepsOf): r = the CoP samples j = 1..r on the current
  // support while walking, or the standing pattern (every sample on both feet)
  int pattern = 0;

  FootSide stepSide(int step) const {  // 0-based step index
    const bool same = (step % 2) == 0;
    return same ? first_step_side
                : (first_step_side == FootSide::kLeft ? FootSide::kRight : FootSide::kLeft);
  }
  // True when some CoP sample of the horizon stands on previewed step `step` (0-based).
  bool stepOwnsSamples(int step) const {
    for (int j = 0; j < row_step.size(); ++j)
      if (row_step(j) == step + 1) return true;
    return false;
  }
};

struct NmpcProblem {
  PhaseStructure phase;
  // Obstacles (eq. 18-19): slot k holds the index of an obstacle of *obstacles, or -1. Their
  // distances come from libwpg's exact, allocation-free 2-D functions (the FCL world of
  // planning/ serves the route planner and the post-run checks, not the NMPC's loop).
  const ObstacleSet* obstacles = nullptr;
  Eigen::VectorXi obstacle_slot;
  // obstacle_linearization: command_tangent: slot k's row is the supporting half-plane
  // n.F >= obstacle_offset(k), n = column k of obstacle_normal (unit), offset h(n) + radius of
  // the obstacle grown by its step-centre margin, or of the group of obstacles it stands for
  // (wpg/obstacle_tangent.hpp, ObstacleSelector::borderNormals), chosen before the solve and
  // fixed during it. A zero column (empty slots, the `step` linearization, a problem built
  // without normals) = the row linearized at the step.
  Eigen::Matrix2Xd obstacle_normal;
  Eigen::VectorXd obstacle_offset;  // [m]
  // The same for the row of step 0 (the next landing) when column k is nonzero
  // (obstacle_landing_linearization: step, PatternGenerator::placeObstacles); a zero column =
  // step 0 takes the row of obstacle_normal like the later steps.
  Eigen::Matrix2Xd obstacle_landing_normal;
  Eigen::VectorXd obstacle_landing_offset;  // [m]
  Eigen::Vector3d com_x = Eigen::Vector3d::Zero();  // [c, c', c''] along world x
  Eigen::Vector3d com_y = Eigen::Vector3d::Zero();
  // N: world reference velocity per sample (J1): the command turned by the sample's heading,
  // or with a window (WalkingParameters::velocity_tracking) the window's mean of the command
  // and the sway (reference_builder.hpp)
  Eigen::VectorXd velocity_x, velocity_y;
  // N: the part of each sample's windowed mean velocity that does not depend on U: the samples
  // already walked, and the turn of the previewed ones taken at the previous plan (0 with the
  // paper's instantaneous tracking)
  Eigen::VectorXd velocity_past_x, velocity_past_y;
  Eigen::VectorXd yaw_reference;           // nf: reference yaw of each step (J2)
  // Swing-foot landing bound (landing_bound, landing_yaw_bound families): while a foot swings, the landing
  // (x, y, yaw) planned at the previous sample and the time left before touchdown. Unset
  // (no row active) when no foot swings or there is no previous plan of this swing.
  bool landing_bounded = false;
  Eigen::Vector3d previous_landing = Eigen::Vector3d::Zero();
  double landing_time_left = 0.0;  // [s]
  // Swing-foot reach (swing_reach family, wpg/swing_foot_reach.hpp): while a foot swings,
  // swing_reach_lower(k) <= d_k . landing (x, y) <= swing_reach_upper(k), d_k =
  // SwingReach::direction(k): the landings its replan reaches within the foot's speed and
  // acceleration limits. Unset (no row active) when no foot swings.
  bool swing_reach_bounded = false;
  Eigen::Matrix<double, 8, 1> swing_reach_lower = Eigen::Matrix<double, 8, 1>::Zero();
  Eigen::Matrix<double, 8, 1> swing_reach_upper = Eigen::Matrix<double, 8, 1>::Zero();
};

}  // namespace wpg
