#pragma once
// The multibody models the replay needs (the URDF named by the robot folder's `multibody:`),
// loaded by robot name from a robots directory, once per worker.
#include <map>
#include <memory>
#include <string>

#include "wpg/datasets/input/robot_multibody.hpp"
#include "wpg/robots/robot_model.hpp"
#include "wpg/robots/walking_ik.hpp"

namespace wpg::engine {

// <robots_directory>/<robot>/walking.yaml: the robot's walking file.
std::string robotWalkingFilePath(const std::string& robots_directory, const std::string& robot);
// <robots_directory>/<robot>/<multibody.urdf>: the multibody model of a robot folder; empty
// when the walking file has no `multibody:` map.
std::string robotUrdfPath(const std::string& robots_directory, const std::string& robot,
                          const datasets::RobotMultibody& multibody);

// The walking IK's settings of a robot folder: its sole frames and standing posture.
robots::WalkingIkSettings walkingIkSettings(const datasets::RobotMultibody& multibody);

// The robot's multibody model, checked to carry the walking IK (its sole frames, legs and
// standing posture). Throws datasets::InputError naming the file when the walking file has no
// `multibody:`, the URDF cannot be read or does not fit.
robots::RobotModel loadRobotModel(const std::string& robots_directory, const std::string& robot,
                                  const datasets::RobotMultibody& multibody);

// The models one worker has loaded, by robot name: each is loaded at its first use and kept.
// Not thread-safe: one cache per worker thread.
class RobotModelCache {
 public:
  explicit RobotModelCache(std::string robots_directory);

  const std::string& robotsDirectory() const { return robots_directory_; }
  // Throws as loadRobotModel.
  const robots::RobotModel& model(const std::string& robot,
                                  const datasets::RobotMultibody& multibody);

 private:
  std::string robots_directory_;
  std::map<std::string, std::unique_ptr<robots::RobotModel>> models_;
};

}  // namespace wpg::engine
