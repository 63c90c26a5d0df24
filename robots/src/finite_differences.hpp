#pragma once
// The joint trajectory of a replay, checked, transposed and differentiated: the scheme of
// multibody_replay.hpp (mid-point velocities, second-order accelerations, extrapolated ends),
// shared by the two multibody ZMPs, Simbody's inverse dynamics (MultibodyReplay) and the
// momentum rate of the kinematics (MomentumZmp), so that both see the same v and a.
// Transposed trajectories: one sample per column (a row of an n x nq matrix is strided across
// n, and reading it sample by sample misses the caches on every entry).
#include <Eigen/Core>

#include "wpg/robots/robot_model.hpp"

namespace wpg::robots::detail {

// Throws std::invalid_argument unless q is n x nq with n >= 3, finite, every free-flyer
// quaternion of unit norm within 1e-6, and dt finite and > 0. Then qt = q' (nq x n): no
// allocation when qt already has that size.
void checkedTranspose(const RobotModel& model, const Eigen::Ref<const Eigen::MatrixXd>& q,
                      double dt, Eigen::MatrixXd& qt);
// Throws the size and dt errors of checkedTranspose only.
void checkTrajectorySize(const RobotModel& model, const Eigen::Ref<const Eigen::MatrixXd>& q,
                         double dt);

// Throws std::invalid_argument unless the CoM force (the pushes removed from the ZMP) is
// n x 3, n the samples of q, and finite.
void checkComForce(const Eigen::Ref<const Eigen::MatrixXd>& q,
                   const Eigen::Ref<const Eigen::MatrixXd>& com_force);

// Velocity and acceleration (nv x n) of the configurations qt (nq x n, n >= 3); `before` and
// `after` are scratch vectors (resized to nv). No allocation once every buffer has its size.
void differentiateSamples(const Eigen::MatrixXd& qt, double dt, Eigen::MatrixXd& vt,
                          Eigen::MatrixXd& at, Eigen::VectorXd& before, Eigen::VectorXd& after);

}  // namespace wpg::robots::detail
