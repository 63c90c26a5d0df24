// The replay's multibody models by robot name (robot_models.hpp).
#include "wpg/engine/robot_models.hpp"

#include <exception>
#include <filesystem>
#include <system_error>

#include "wpg/datasets/input/input_error.hpp"

namespace fs = std::filesystem;

namespace wpg::engine {

std::string robotUrdfPath(const std::string& robots_directory, const std::string& robot) {
  return (fs::path(robots_directory) / robot / (robot + ".urdf")).string();
}

robots::RobotModel loadRobotModel(const std::string& robots_directory, const std::string& robot) {
  const std::string path = robotUrdfPath(robots_directory, robot);
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) {
    throw datasets::InputError("robot '" + robot + "' has no multibody model for the replay: " +
                               path + " not found (a robot folder needs <robot>.urdf to be replayed)");
  }
  try {
    return robots::RobotModel(path);
  } catch (const std::exception& e) {
    throw datasets::InputError("cannot load the multibody model of robot '" + robot + "' (" +
                               path + "): " + e.what());
  }
}

RobotModelCache::RobotModelCache(std::string robots_directory)
    : robots_directory_(std::move(robots_directory)) {}

const robots::RobotModel& RobotModelCache::model(const std::string& robot) {
  auto found = models_.find(robot);
  if (found == models_.end()) {
    found = models_.emplace(robot, std::make_unique<robots::RobotModel>(
                                       loadRobotModel(robots_directory_, robot)))
                .first;
  }
  return *found->second;
}

}  // namespace wpg::engine
