#pragma once
// The multibody models the replay needs (robots/<robot>/<robot>.urdf), loaded by robot name
// from a robots directory, once per worker.
#include <map>
#include <memory>
#include <string>

#include "wpg/robots/robot_model.hpp"

namespace wpg::engine {

// <robots_directory>/<robot>/<robot>.urdf: the multibody model of a robot folder.
std::string robotUrdfPath(const std::string& robots_directory, const std::string& robot);

// The robot's multibody model. Throws datasets::InputError naming the URDF path when the robot
// has no URDF or it cannot be read.
robots::RobotModel loadRobotModel(const std::string& robots_directory, const std::string& robot);

// The models one worker has loaded, by robot name: each is loaded at its first use and kept.
// Not thread-safe: one cache per worker thread.
class RobotModelCache {
 public:
  explicit RobotModelCache(std::string robots_directory);

  const std::string& robotsDirectory() const { return robots_directory_; }
  // Throws as loadRobotModel.
  const robots::RobotModel& model(const std::string& robot);

 private:
  std::string robots_directory_;
  std::map<std::string, std::unique_ptr<robots::RobotModel>> models_;
};

}  // namespace wpg::engine
