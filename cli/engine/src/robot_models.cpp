// The replay's multibody models by robot name (robot_models.hpp).
#include "wpg/engine/robot_models.hpp"

#include <exception>
#include <filesystem>
#include <system_error>

#include "wpg/datasets/input/input_error.hpp"

namespace fs = std::filesystem;

namespace wpg::engine {

std::string robotWalkingFilePath(const std::string& robots_directory, const std::string& robot) {
  return (fs::path(robots_directory) / robot / "walking.yaml").string();
}

std::string robotUrdfPath(const std::string& robots_directory, const std::string& robot,
                          const datasets::RobotMultibody& multibody) {
  if (!multibody.present) return {};
  return (fs::path(robots_directory) / robot / multibody.urdf).string();
}

robots::WalkingIkSettings walkingIkSettings(const datasets::RobotMultibody& multibody) {
  robots::WalkingIkSettings settings;
  if (!multibody.present) return settings;
  settings.left_sole_frame = multibody.left_sole_frame;
  settings.right_sole_frame = multibody.right_sole_frame;
  settings.reference_posture = multibody.standing_posture;
  return settings;
}

robots::RobotModel loadRobotModel(const std::string& robots_directory, const std::string& robot,
                                  const datasets::RobotMultibody& multibody) {
  if (!multibody.present) {
    throw datasets::InputError(
        robotWalkingFilePath(robots_directory, robot) + ": robot '" + robot +
        "' has no multibody model for the replay: key 'multibody': expected a map {urdf: "
        "FILE.urdf, left_sole_frame: LINK, right_sole_frame: LINK} (docs/robots.md)");
  }
  const std::string path = robotUrdfPath(robots_directory, robot, multibody);
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) {
    throw datasets::InputError("robot '" + robot + "' has no multibody model for the replay: " +
                               path + " not found (" +
                               robotWalkingFilePath(robots_directory, robot) +
                               ", key 'multibody.urdf')");
  }
  try {
    robots::RobotModel model(path);
    // The walking IK's structure checks (sole frames, legs, standing posture): a model that
    // cannot walk is bad input before the walk runs, not a failed replay after it.
    const robots::WalkingIk ik(model, walkingIkSettings(multibody));
    return model;
  } catch (const std::exception& e) {
    throw datasets::InputError("cannot load the multibody model of robot '" + robot + "' (" +
                               path + "): " + e.what());
  }
}

RobotModelCache::RobotModelCache(std::string robots_directory)
    : robots_directory_(std::move(robots_directory)) {}

const robots::RobotModel& RobotModelCache::model(const std::string& robot,
                                                 const datasets::RobotMultibody& multibody) {
  auto found = models_.find(robot);
  if (found == models_.end()) {
    found = models_.emplace(robot, std::make_unique<robots::RobotModel>(
                                       loadRobotModel(robots_directory_, robot, multibody)))
                .first;
  }
  return *found->second;
}

}  // namespace wpg::engine
