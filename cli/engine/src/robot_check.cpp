// `wpg robot check DIR` (robot_check.hpp).
#include "wpg/engine/robot_check.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <filesystem>
#include <sstream>
#include <optional>
#include <system_error>

#include "wpg/datasets/input/input_error.hpp"
#include "wpg/robots/robot_model.hpp"
#include "wpg/robots/walking_ik.hpp"
#include "wpg/robots/walking_reach.hpp"
#include "wpg/engine/robot_models.hpp"

namespace fs = std::filesystem;

namespace wpg::engine {
namespace {

// Rays of the sampled step polygon: 22.5 degrees apart.
constexpr int kPolygonRays = 16;
// A walking mass and a URDF mass further apart than this (relative) get a warning.
constexpr double kMassTolerance = 0.01;

[[noreturn]] void fail(const std::string& file, const std::string& message) {
  throw datasets::InputError(datasets::escapeControlCharacters(file + ": " + message));
}

std::string metres(double value) {
  std::ostringstream out;
  out.precision(4);
  out << value << " m";
  return out.str();
}

}  // namespace

RobotFolderCheck checkRobotFolder(const std::string& directory) {
  RobotFolderCheck out;
  out.walking_file = (fs::path(directory) / "walking.yaml").string();
  std::error_code ec;
  if (!fs::is_directory(directory, ec)) fail(directory, "not a folder (a robot folder holds walking.yaml)");
  if (!fs::is_regular_file(out.walking_file, ec))
    fail(out.walking_file, "not found (a robot folder holds walking.yaml, docs/robots.md)");
  out.robot = datasets::loadRobotFile(out.walking_file);
  const WalkingParameters& w = out.robot.walking;
  out.declared_polygon = w.feasibilityVertices(FootSide::kLeft);
  const datasets::RobotMultibody& multibody = out.robot.multibody;
  if (!multibody.present) return out;

  out.urdf = (fs::path(directory) / multibody.urdf).string();
  if (!fs::is_regular_file(out.urdf, ec))
    fail(out.walking_file, "key 'multibody.urdf': " + out.urdf + " not found");
  std::optional<robots::RobotModel> loaded;
  try {
    loaded.emplace(out.urdf);
  } catch (const std::exception& e) {
    throw datasets::InputError(datasets::escapeControlCharacters(e.what()));
  }
  const robots::RobotModel& model = *loaded;
  out.urdf_mass = model.totalMass();
  out.joints = model.jointCount();
  const std::string frames[2] = {multibody.left_sole_frame, multibody.right_sole_frame};
  const char* keys[2] = {"multibody.left_sole_frame", "multibody.right_sole_frame"};
  for (int side = 0; side < 2; ++side) {
    if (!model.hasFrame(frames[side]))
      fail(out.urdf, "no link " + frames[side] + " (" + out.walking_file + ", key '" +
                         keys[side] + "')");
    out.leg_joints[side] = static_cast<int>(robots::jointsToFrame(model, frames[side]).size());
    if (out.leg_joints[side] < 6)
      fail(out.urdf, "the leg of " + frames[side] + " has " + std::to_string(out.leg_joints[side]) +
                         " joints from the root " + model.bodies()[0].name +
                         ", the walking IK needs six or more");
    out.leg_length[side] = robots::straightLegLength(model, frames[side]);
  }
  const std::vector<std::string> postures = model.referencePostureNames();
  if (std::find(postures.begin(), postures.end(), multibody.standing_posture) == postures.end())
    fail(out.walking_file, "key 'multibody.standing_posture': " + multibody.standing_posture +
                               " is not a <group_state> of the SRDF next to " + out.urdf);
  std::optional<robots::WalkingIk> built;
  try {
    built.emplace(model, walkingIkSettings(multibody));
  } catch (const std::exception& e) {
    fail(out.urdf, e.what());
  }
  const robots::WalkingIk& ik = *built;
  out.analytic_leg[0] = ik.analyticLeg(robots::WalkingIk::kLeft);
  out.analytic_leg[1] = ik.analyticLeg(robots::WalkingIk::kRight);
  const Eigen::VectorXd standing =
      model.referenceConfiguration(multibody.standing_posture, {frames[0], frames[1]});
  out.standing_com_height = model.centerOfMass(standing).z();
  const robots::ComHeightRange range =
      robots::walkableComHeights(ik, w.initial_foot_separation);
  out.lowest_com = range.lowest;
  out.highest_com = range.highest;
  if (!(w.com_height >= range.lowest && w.com_height <= range.highest))
    fail(out.walking_file, "key 'com_height': " + metres(w.com_height) +
                               ", beyond the CoM heights the walking IK reaches with the feet " +
                               metres(w.initial_foot_separation) + " apart (" +
                               metres(range.lowest) + " to " + metres(range.highest) + ")");
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  for (const Eigen::Vector2d& v : out.declared_polygon) centre += v;
  centre /= static_cast<double>(out.declared_polygon.size());
  out.reached_polygon =
      robots::reachableStepPolygon(ik, w.com_height, centre, kPolygonRays, w.foot_width);
  for (const Eigen::Vector2d& v : out.declared_polygon) {
    out.declared_reached.push_back(v.y() >= w.foot_width &&
                                   robots::stepReachable(ik, v, w.com_height));
    if (!out.declared_reached.back()) {
      std::ostringstream line;
      line << out.walking_file << ": feasibility vertex (" << v.x() << ", " << v.y()
           << ") is not reached by the walking IK at com_height " << w.com_height << " m";
      out.warnings.push_back(line.str());
    }
  }
  if (std::abs(out.urdf_mass - out.robot.mass) > kMassTolerance * out.urdf_mass) {
    std::ostringstream line;
    line << out.walking_file << ": key 'mass': " << out.robot.mass << " kg, the URDF's links sum to "
         << out.urdf_mass << " kg";
    out.warnings.push_back(line.str());
  }
  return out;
}

}  // namespace wpg::engine
