// `wpg robot check DIR`: the engine checks the folder (wpg/engine/robot_check.hpp); printed
// here. Writes nothing.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>
#include <system_error>

#include "command_options.hpp"
#include "error_messages.hpp"
#include "exit_codes.hpp"
#include "wpg/engine/robot_check.hpp"

namespace fs = std::filesystem;

namespace wpg::cli {
namespace {

std::string point(const Eigen::Vector2d& p) {
  char text[64];
  std::snprintf(text, sizeof text, "(%.3f, %.3f)", p.x(), p.y());
  return text;
}

}  // namespace

int robotCheckCommand(const RobotCheckOptions& options) {
  std::string folder = options.folder;
  std::error_code ec;
  // A name of the data directory's robots (`wpg robot check hrp2`) when it is no folder here.
  if (!fs::exists(folder, ec) && folder.find('/') == std::string::npos &&
      fs::is_directory(fs::path(robotsDirectory()) / folder, ec)) {
    folder = (fs::path(robotsDirectory()) / folder).string();
  }
  const engine::RobotFolderCheck check = engine::checkRobotFolder(folder);
  const WalkingParameters& w = check.robot.walking;
  std::printf("robot folder %s\n", folder.c_str());
  std::printf("  walking file     %s: mass %.3f kg, com_height %.4f m, sole %.4f x %.4f m\n",
              check.walking_file.c_str(), check.robot.mass, w.com_height, w.foot_length,
              w.foot_width);
  if (check.urdf.empty()) {
    std::printf("  multibody        none (walks; no replay: walking.yaml has no `multibody:`)\n");
  } else {
    const datasets::RobotMultibody& m = check.robot.multibody;
    std::printf("  URDF             %s: %d joints, links' mass %.3f kg\n", check.urdf.c_str(),
                check.joints, check.urdf_mass);
    std::printf("  legs             %s %d joints, %s %d joints; straight %.4f m, %.4f m (hip "
                "to sole); IK %s, %s\n",
                m.left_sole_frame.c_str(), check.leg_joints[0], m.right_sole_frame.c_str(),
                check.leg_joints[1], check.leg_length[0], check.leg_length[1],
                check.analytic_leg[0] ? "analytic" : "numerical",
                check.analytic_leg[1] ? "analytic" : "numerical");
    std::printf("  CoM height       standing posture %s %.4f m; walkable %.3f to %.3f m (feet "
                "%.3f m apart); declared %.4f m\n",
                m.standing_posture.c_str(), check.standing_com_height, check.lowest_com,
                check.highest_com, w.initial_foot_separation, w.com_height);
    std::printf("  step polygon     a left step from the right foot, CoM between the feet at "
                "com_height\n    declared        ");
    for (std::size_t i = 0; i < check.declared_polygon.size(); ++i)
      std::printf("%s%s%s", i ? " " : "", point(check.declared_polygon[i]).c_str(),
                  check.declared_reached[i] ? "" : "*");
    const bool all_reached = std::find(check.declared_reached.begin(),
                                       check.declared_reached.end(),
                                       false) == check.declared_reached.end();
    std::printf("%s\n    reached by IK   ", all_reached ? "" : "  (* not reached)");
    for (std::size_t i = 0; i < check.reached_polygon.size(); ++i)
      std::printf("%s%s", i ? " " : "", point(check.reached_polygon[i]).c_str());
    std::printf("%s\n", check.reached_polygon.empty() ? "none: the polygon's centre is not reached"
                                                      : "");
  }
  std::fflush(stdout);
  printWarnings(check.warnings);
  return kExitSuccess;
}

}  // namespace wpg::cli
