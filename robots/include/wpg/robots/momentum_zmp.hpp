#pragma once
// The multibody ZMP of a joint trajectory from the rate of change of the robot's momentum,
// without an inverse-dynamics pass: what the dynamic filter needs at every NMPC iteration
// (online_filter_loop.hpp) and over a whole walk (walk_replay.hpp).
//
// The wrench the ground applies (moment n about the world origin, force f) is the rate of the
// total momentum plus the weight, summed over the bodies b (Newton-Euler without the joints):
//   f   = sum_b m_b (a_b + g e_z)                           = M (c'' + g e_z),
//   n_O = sum_b [ c_b x m_b (a_b + g e_z) + I_b alpha_b + omega_b x I_b omega_b ]
//       = c x f + (rate of the angular momentum about the whole-body CoM c),
// c_b, a_b: the CoM of body b and its acceleration, I_b its inertia about it (world axes),
// omega_b, alpha_b its angular velocity and acceleration; then the ZMP p_x = -n_y / f_z,
// p_y = n_x / f_z (MultibodyReplay::zmpOfWrench). The body velocities and accelerations come
// from one pass from the root to the feet with the joint rates: the same v and a as
// MultibodyReplay (the finite differences of multibody_replay.hpp, shared code), so the
// wrench, the ZMP and the CoM are Simbody's residual at the free-flyer up to round-off (a test
// holds the ZMP to Simbody's within 1e-9 m on every sample of the shipped walks). No joint
// torques: that is what Simbody's backward pass adds.
//
// As MultibodyReplay without joint torques, the joints whose value is the same in every sample
// of a run are welded (their bodies merged into the body they hang from: HRP-2 walking, 13
// bodies instead of 31). run() does not allocate once its buffers have the run's size and the
// welded set is unchanged (the filter's window at every NMPC iteration). The RobotModel must
// outlive the object; one object per thread.
#include <vector>

#include <Eigen/Core>

#include "wpg/robots/multibody_replay.hpp"
#include "wpg/robots/robot_model.hpp"

namespace wpg::robots {

class MomentumZmp {
 public:
  // gravity [m/s^2] along -z (WalkingParameters::gravity); throws std::invalid_argument unless
  // finite and >= 0.
  explicit MomentumZmp(const RobotModel& model, double gravity = 9.81);

  const RobotModel& model() const { return model_; }

  // As MultibodyReplay::run (same checks, same exceptions): velocity, acceleration,
  // base_wrench, zmp and com of q (n x nq, every dt); joint_torques stays 0 x joints.
  const MultibodyReplayResult& run(const Eigen::Ref<const Eigen::MatrixXd>& q, double dt);
  // With an external force at the whole-body CoM (n x 3, world [N]): the ground's share.
  const MultibodyReplayResult& run(const Eigen::Ref<const Eigen::MatrixXd>& q, double dt,
                                   const Eigen::Ref<const Eigen::MatrixXd>& com_force);
  const MultibodyReplayResult& result() const { return result_; }
  // Rigid bodies of the last run once its constant joints are welded (the root included).
  int bodyCount() const { return static_cast<int>(bodies_.size()); }

 private:
  // A rigid body of the welded tree: a model body and every body welded to it, in the model
  // body's frame.
  struct Body {
    int parent = -1;       // index in bodies_, -1 for the root
    int q_index = -1;      // its joint's coordinate in q and in v (-1 for the root)
    int v_index = -1;
    bool prismatic = false;
    bool joint_rotated = false;  // joint_rotation is not the identity
    Eigen::Matrix3d joint_rotation = Eigen::Matrix3d::Identity();  // joint frame in the parent
    Eigen::Vector3d joint_position = Eigen::Vector3d::Zero();      // body's frame
    Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();  // unit, joint frame
    int coordinate_axis = -1;  // 0, 1, 2 when axis is +x, +y, +z (a cheaper rotation)
    double mass = 0.0;                                    // [kg]
    Eigen::Vector3d com = Eigen::Vector3d::Zero();        // body frame [m]
    Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();    // about com, body axes [kg m^2]
  };
  // Per body of one sample (world frame): pose, angular velocity and acceleration, the
  // acceleration of its origin with the gravity offset g e_z.
  struct Motion {
    Eigen::Matrix3d rotation;
    Eigen::Vector3d position, omega, alpha, acceleration;
  };

  const MultibodyReplayResult& runImpl(const Eigen::Ref<const Eigen::MatrixXd>& q, double dt,
                                       const Eigen::Ref<const Eigen::MatrixXd>* com_force);
  // Welds the joints constant over qt_ (rebuilds bodies_ only when that set or its values
  // changed since the last run).
  void weldConstantJoints();
  void buildBodies();
  // Ground wrench (moment about the world origin, force) and whole-body CoM of sample k.
  void sampleWrench(Eigen::Index k, Eigen::Matrix<double, 6, 1>& wrench, Eigen::Vector3d& com);

  const RobotModel& model_;
  double gravity_;
  std::vector<Body> bodies_;      // topological order, root first (capacity: model bodies)
  std::vector<Motion> motion_;    // per body, the sample being evaluated
  std::vector<int> host_;         // per model body: the body of bodies_ it is part of
  std::vector<Pose> in_host_;     // per model body: its frame in its host's frame
  std::vector<char> welded_;      // per joint: welded in bodies_
  Eigen::VectorXd weld_values_;   // per joint: the value a welded joint is held at
  std::vector<char> constant_;    // per joint: constant over the current run
  std::vector<Eigen::Vector3d> first_moment_;    // buildBodies(): per body, in its frame
  std::vector<Eigen::Matrix3d> inertia_origin_;  // buildBodies(): about its origin
  bool built_ = false;
  double total_mass_ = 0.0;
  MultibodyReplayResult result_;
  Eigen::MatrixXd qt_, vt_, at_;  // one sample per column
  Eigen::VectorXd fd_before_, fd_after_;
};

}  // namespace wpg::robots
