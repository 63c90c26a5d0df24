#pragma once
// Internal: the URDF and SRDF readers (urdf_loader.cpp is the only translation unit that
// includes urdfdom). Plain data out, in the files' document order.
#include <map>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "wpg/robots/robot_model.hpp"

namespace wpg::robots::detail {

struct UrdfLink {
  std::string name;
  double mass = 0.0;                                    // [kg], 0 without <inertial>
  Eigen::Vector3d com = Eigen::Vector3d::Zero();        // link frame
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();    // about the com, link-frame axes
};

enum class UrdfJointType { kRevolute, kContinuous, kPrismatic, kFixed };

struct UrdfJoint {
  std::string name;
  UrdfJointType type = UrdfJointType::kFixed;
  std::string parent_link, child_link;
  Pose origin;                                          // child (joint) frame in the parent link
  Eigen::Vector3d axis = Eigen::Vector3d::UnitX();      // unit, joint frame
  double lower = 0.0, upper = 0.0, velocity = 0.0, effort = 0.0;
};

struct UrdfDescription {
  std::string name;
  std::string root_link;
  std::vector<UrdfLink> links;
  std::vector<UrdfJoint> joints;  // document order of the <joint> elements
};

// Throws std::runtime_error with the file name on any error (unreadable, malformed, not a
// tree (a loop), an <inertial> whose mass is not positive or whose inertia is not positive
// definite, floating/planar joints).
UrdfDescription readUrdf(const std::string& path);

// SRDF <group_state name="..."><joint name="..." value="..."/>...</group_state>: posture name
// -> joint name -> value. Throws std::runtime_error on a malformed file.
std::map<std::string, std::map<std::string, double>> readSrdfGroupStates(const std::string& path);

}  // namespace wpg::robots::detail
