#pragma once
// What the robots tests share: HRP-2's model, loaded once from the source tree, and a rotation
// from roll, pitch, yaw (R = Rz(yaw) Ry(pitch) Rx(roll)).
#include <string>

#include <Eigen/Geometry>

#include "wpg/robots/robot_model.hpp"
#include "../common/source_dir.hpp"

namespace wpg_test {

inline const wpg::robots::RobotModel& hrp2() {
  static const wpg::robots::RobotModel model(std::string(sourceDir()) + "/robots/hrp2/hrp2.urdf");
  return model;
}

inline Eigen::Matrix3d rpy(double roll, double pitch, double yaw) {
  return (Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) *
          Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

}  // namespace wpg_test
