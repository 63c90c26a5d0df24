// The input checks of a run beyond its scenario file (run_input_checks.hpp).
#include "wpg/engine/run_input_checks.hpp"

#include <exception>
#include <set>
#include <stdexcept>

#include "wpg/datasets/input/input_error.hpp"
#include "wpg/datasets/input/robot_file.hpp"
#include "wpg/planning/goal_walk.hpp"
#include "wpg/preview_control.hpp"

namespace wpg::engine {

void checkFilterSettings(const datasets::Scenario& scenario, const std::string& origin) {
  try {
    const PreviewController controller(scenario.walking.control_period,
                                       scenario.walking.com_height, scenario.walking.gravity,
                                       scenario.filter_settings);
    (void)controller;
  } catch (const std::exception& e) {
    throw datasets::InputError(origin + ": key 'filter_settings': no preview controller for "
                               "these weights (" + e.what() + ")");
  }
}

void checkGoalRequest(const datasets::Scenario& scenario, const std::string& origin) {
  if (!scenario.goal.enabled) return;
  try {
    planning::checkGoalRequest(scenario.walking, scenario.request, scenario.goal);
  } catch (const std::invalid_argument& e) {
    throw datasets::InputError(origin + ": " + e.what());
  }
}

void checkRunInput(const datasets::Scenario& scenario, const std::string& origin,
                   RobotModelCache& models) {
  if (scenario.replay) {
    (void)models.model(scenario.robot, scenario.multibody);
    if (scenario.filter) checkFilterSettings(scenario, origin);
  }
  checkGoalRequest(scenario, origin);
}

void checkStudyRobotModels(const datasets::Study& study, const std::string& robots_directory) {
  std::set<std::string> replayed_robots;
  // The checked runs take every value of the swept keys (a swept robot's every name).
  for (const datasets::Study::CheckedRun& run : study.checked) {
    if (run.replay) replayed_robots.insert(run.robot);
  }
  // Each robot's multibody model as its walking file names it.
  for (const std::string& robot : replayed_robots) {
    const datasets::RobotFile file =
        datasets::loadRobotFile(robotWalkingFilePath(robots_directory, robot));
    (void)loadRobotModel(robots_directory, robot, file.multibody);
  }
}

}  // namespace wpg::engine
