#pragma once
// A robot's kinematic tree and inertias, read from a URDF (and its reference postures from an
// SRDF next to it), with a free-flyer base. Eigen only: the Simbody system used for inverse
// dynamics lives in MultibodyReplay (multibody_replay.hpp).
//
// Configuration layout (nq = 7 + number of actuated joints; HRP-2: 7 + 30 = 37):
//   q[0..2]  position of the root link frame (BODY for HRP-2) in the world [m]
//   q[3..6]  orientation of the root link as a unit quaternion, scalar first: w, x, y, z
//   q[7..]   joint values [rad or m], in the order of the <joint> elements of the URDF file
//            (for HRP-2 the source model's order: RLEG 0-5, LLEG 0-5, CHEST 0-1, HEAD 0-1,
//            RARM 0-6, LARM 0-6)
// Velocity layout (nv = 6 + number of actuated joints):
//   v[0..2]  linear velocity of the root link origin, world frame [m/s]
//   v[3..5]  angular velocity of the root link, world frame [rad/s]
//   v[6..]   joint velocities, same order as q[7..]
// World frame: x forward, y left, z up, gravity along -z, ground at z = 0.
//
// Fixed URDF joints do not create bodies: their child links are frames of the body they are
// welded to (their mass, if any, is merged into it). Every URDF link is a frame.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace wpg::robots {

// A rigid placement: p_parent = rotation * p_child + position.
struct Pose {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d position = Eigen::Vector3d::Zero();

  Pose operator*(const Pose& other) const {
    return {rotation * other.rotation, rotation * other.position + position};
  }
  Eigen::Vector3d operator*(const Eigen::Vector3d& point) const {
    return rotation * point + position;
  }
};

enum class JointType : std::uint8_t { kRevolute = 0, kContinuous = 1, kPrismatic = 2 };

// An actuated joint (URDF revolute, continuous or prismatic).
struct Joint {
  std::string name;
  JointType type = JointType::kRevolute;
  int body = -1;           // index in RobotModel::bodies() of the body it moves
  int index = -1;          // joint index k: q[7 + k], v[6 + k]
  Pose origin;             // joint frame in the parent BODY frame (fixed joints folded in)
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();  // unit, in the joint (= child link) frame
  double lower = 0.0, upper = 0.0;  // position limits [rad or m]; +-inf for continuous joints
  double velocity_limit = 0.0;      // [rad/s or m/s], URDF <limit velocity>
  double effort_limit = 0.0;        // [N m or N], URDF <limit effort>
};

// A rigid body: the root link or the child link of an actuated joint, with every link welded
// to it by fixed joints. Bodies are in topological order (parents first); body 0 is the root.
struct Body {
  std::string name;        // its URDF link
  int parent = -1;         // parent body, -1 for the root
  int joint = -1;          // its joint in RobotModel::joints(), -1 for the root (free-flyer)
  double mass = 0.0;       // [kg]
  Eigen::Vector3d com = Eigen::Vector3d::Zero();           // centre of mass, body frame [m]
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();       // about the com, body axes [kg m^2]
};

// A named frame (every URDF link) attached to a body.
struct Frame {
  std::string name;
  int body = -1;
  Pose placement;          // in the body frame
};

class RobotModel {
 public:
  static constexpr int kFreeFlyerConfigurationSize = 7;  // x y z qw qx qy qz
  static constexpr int kFreeFlyerVelocitySize = 6;       // linear, angular (world frame)

  // Reads the URDF, and the SRDF (reference postures, <group_state>) at srdf_path; with an
  // empty srdf_path, the file with the URDF's name and the extension .srdf if it exists.
  // Throws std::runtime_error (file unreadable, not a tree, unsupported joint type, ...).
  explicit RobotModel(const std::string& urdf_path, const std::string& srdf_path = "");

  const std::string& name() const { return name_; }
  const std::string& urdfPath() const { return urdf_path_; }
  int nq() const { return kFreeFlyerConfigurationSize + jointCount(); }
  int nv() const { return kFreeFlyerVelocitySize + jointCount(); }
  int jointCount() const { return static_cast<int>(joints_.size()); }

  const std::vector<Joint>& joints() const { return joints_; }  // configuration order
  const std::vector<Body>& bodies() const { return bodies_; }   // topological order
  const std::vector<Frame>& frames() const { return frames_; }
  const std::vector<std::string>& jointNames() const { return joint_names_; }
  const Eigen::VectorXd& jointLowerLimits() const { return lower_; }
  const Eigen::VectorXd& jointUpperLimits() const { return upper_; }
  int jointIndex(const std::string& joint_name) const;  // k (q[7 + k]); throws if unknown
  int frameIndex(const std::string& frame_name) const;  // throws if unknown
  bool hasFrame(const std::string& frame_name) const;
  double totalMass() const { return total_mass_; }

  // --- configurations ---------------------------------------------------------------------
  // Root at the origin, identity orientation, every joint at 0.
  Eigen::VectorXd neutralConfiguration() const;
  // Names of the SRDF group states (e.g. "half_sitting").
  std::vector<std::string> referencePostureNames() const;
  // The SRDF group state `posture` (joints it does not list stay at 0), root at x = y = 0 with
  // identity orientation and at the height that puts the lowest of `ground_frames` on z = 0
  // (root at z = 0 when ground_frames is empty). Throws if the posture or a frame is unknown.
  Eigen::VectorXd referenceConfiguration(const std::string& posture,
                                         const std::vector<std::string>& ground_frames = {}) const;
  // HRP-2's half-sitting: referenceConfiguration("half_sitting", {LLEG_SOLE, RLEG_SOLE}).
  Eigen::VectorXd halfSitting(const std::string& left_sole_frame = "LLEG_SOLE",
                              const std::string& right_sole_frame = "RLEG_SOLE") const;

  // Writes the free-flyer part of q. The quaternion is normalized.
  static void setFreeFlyer(Eigen::Ref<Eigen::VectorXd> q, const Eigen::Vector3d& position,
                           const Eigen::Quaterniond& orientation);
  static Eigen::Quaterniond freeFlyerOrientation(const Eigen::Ref<const Eigen::VectorXd>& q);
  // Throws std::invalid_argument unless q has nq entries, all finite, and a quaternion of unit
  // norm within 1e-6.
  void checkConfiguration(const Eigen::Ref<const Eigen::VectorXd>& q) const;
  // Joints outside their limits by more than `tolerance`: their indices k (configuration order).
  std::vector<int> jointLimitViolations(const Eigen::Ref<const Eigen::VectorXd>& q,
                                        double tolerance = 0.0) const;

  // --- kinematics (checked entry points; they allocate, not for hot loops) -----------------
  // World poses of every body (resized to bodies().size()).
  void forwardKinematics(const Eigen::Ref<const Eigen::VectorXd>& q,
                         std::vector<Pose>& body_poses) const;
  Pose framePose(const Eigen::Ref<const Eigen::VectorXd>& q, const std::string& frame_name) const;
  Eigen::Vector3d centerOfMass(const Eigen::Ref<const Eigen::VectorXd>& q) const;
  // Pose of joint k's frame in its parent body frame at joint value `value`.
  Pose jointPlacement(int k, double value) const;

 private:
  std::string name_, urdf_path_;
  std::vector<Joint> joints_;
  std::vector<Body> bodies_;
  std::vector<Frame> frames_;
  std::vector<std::string> joint_names_;
  Eigen::VectorXd lower_, upper_;
  double total_mass_ = 0.0;
  std::map<std::string, std::map<std::string, double>> reference_postures_;
};

}  // namespace wpg::robots
