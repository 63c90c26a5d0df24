#pragma once
// Numerical inverse kinematics of one leg: the actuated joints from the root to a sole frame
// (six or more, any axes and offsets: hip axes that do not intersect, a seventh joint), for a
// sole pose relative to the root. Damped least squares (Levenberg-Marquardt) with the joint
// limits: each iteration solves (J' J + lambda^2 I) dq = J' e for the 6-D sole error e
// (position; rotation as the axis-angle vector of R_target R'), with J the sole's geometric
// Jacobian (revolute column (a x (p - o); a), prismatic (a; 0)). A step that does not reduce
// |e| is refused and lambda raised (x 4); an accepted one lowers it (/ 4) down to damping x |e|,
// which vanishes at the solution: the last steps are Gauss-Newton's (quadratic convergence, to
// 1e-12). A joint at a limit whose step points beyond it is held there (its column removed)
// and the step solved again; so is a locked joint (at its start value): a leg of more than six
// joints whose extra joints are locked has one solution near the start, a smooth function of
// the target (the whole-body walking IK differentiates the CoM through it).
// The analytic IK of WalkingIk (HRP-2-like legs) is the reference it is tested against.
// solve() is const and does not allocate (at most kMaxLegJoints joints).
#include <string>
#include <vector>

#include <Eigen/Core>

#include "wpg/robots/robot_model.hpp"

namespace wpg::robots {

struct NumericalLegIkSettings {
  int max_iterations = 200;
  double position_tolerance = 1e-12;  // [m] converged when |position error| <= this
  double rotation_tolerance = 1e-12;  // [rad] ... and |rotation error| <= this
  double damping = 1e-2;              // lambda = damping x |e| [1/m]
};

struct NumericalLegIkResult {
  bool converged = false;
  int iterations = 0;
  double position_error = 0.0;  // [m]
  double rotation_error = 0.0;  // [rad]
};

class NumericalLegIk {
 public:
  static constexpr int kMaxLegJoints = 12;
  using Angles = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxLegJoints, 1>;

  // Throws std::invalid_argument when `sole_frame` is unknown, the chain from the root to it
  // has fewer than six or more than kMaxLegJoints actuated joints, or `locked` (positions in
  // the chain, held at their start values) leaves fewer than six free.
  NumericalLegIk(const RobotModel& model, const std::string& sole_frame,
                 NumericalLegIkSettings settings = {}, std::vector<int> locked = {});

  int jointCount() const { return static_cast<int>(joints_.size()); }
  // Joint indices k (q[7 + k]) of the chain, root first.
  const std::vector<int>& joints() const { return joints_; }

  // The sole frame for the chain's joint values `angles` (jointCount()), the root at `root`.
  Pose forwardKinematics(const Pose& root, const Eigen::Ref<const Eigen::VectorXd>& angles) const;
  // The same, with the pose of each joint's body (jointCount() of them, from the root) in
  // `bodies`.
  Pose forwardKinematics(const Pose& root, const Eigen::Ref<const Eigen::VectorXd>& angles,
                         Pose* bodies) const;
  // The sole's geometric Jacobian (6 x jointCount(): linear, angular; world axes).
  Eigen::Matrix<double, 6, Eigen::Dynamic> jacobian(
      const Pose& root, const Eigen::Ref<const Eigen::VectorXd>& angles) const;

  // Joint values that put the sole frame at `sole` (world) with the root at `root` (world),
  // Newton from `angles` (in: the initial guess, out: the solution, within the limits).
  NumericalLegIkResult solve(const Pose& root, const Pose& sole,
                             Eigen::Ref<Eigen::VectorXd> angles) const;

 private:
  // Sole pose, and with `jacobian` its 6 x n geometric Jacobian (world axes).
  Pose evaluate(const Pose& root, const Eigen::Ref<const Eigen::VectorXd>& angles,
                Eigen::Matrix<double, 6, Eigen::Dynamic, 0, 6, kMaxLegJoints>* jacobian,
                Pose* bodies = nullptr) const;

  const RobotModel& model_;
  NumericalLegIkSettings settings_;
  std::vector<int> joints_;   // joint indices, root first
  std::vector<Pose> between_;  // fixed placement before each joint: joint origin in the previous
                               // joint's frame (the root's for the first)
  Pose sole_;                  // the sole frame in the last joint's body frame
  std::vector<bool> locked_;   // per joint of the chain: held at its start value
};

}  // namespace wpg::robots
