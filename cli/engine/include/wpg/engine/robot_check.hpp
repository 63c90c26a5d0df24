#pragma once
// `wpg robot check DIR` (docs/robots.md): a robot folder read and checked as a run would read
// it, and what the walking IK derives from it beside what the walking file declares.
#include <string>
#include <vector>

#include <Eigen/Core>

#include "wpg/datasets/input/robot_file.hpp"

namespace wpg::engine {

struct RobotFolderCheck {
  std::string walking_file;            // DIR/walking.yaml
  datasets::RobotFile robot;           // its contents
  // With a `multibody:` map (else only the walking file is checked):
  std::string urdf;                    // DIR/<multibody.urdf>
  double urdf_mass = 0.0;              // [kg], the URDF's links summed
  int joints = 0;                      // actuated joints of the URDF
  int leg_joints[2] = {0, 0};          // left, right: from the root to the sole frame
  double leg_length[2] = {0.0, 0.0};   // [m] hip to sole, leg straight (walking_reach.hpp)
  bool analytic_leg[2] = {false, false};  // solved in closed form (else NumericalLegIk)
  double standing_com_height = 0.0;    // [m] CoM of the standing posture, soles on the ground
  double lowest_com = 0.0, highest_com = 0.0;  // [m] walkable CoM heights (walking_reach.hpp)
  std::vector<Eigen::Vector2d> declared_polygon;  // feasibility_x/y, a left step
  std::vector<bool> declared_reached;             // each declared vertex, by the IK
  std::vector<Eigen::Vector2d> reached_polygon;   // sampled by the IK (16 rays)
  std::vector<std::string> warnings;   // one line each: accepted, but worth a look
};

// Throws datasets::InputError (one line naming the file and what is wrong) on a folder a run
// would refuse or could not replay: no walking.yaml or a bad one (a feasibility polygon that is
// not convex included), a URDF that is missing, malformed, not a tree, with a link whose mass
// is not positive or whose inertia is not positive definite, a sole frame it does not have, a
// leg of fewer than six joints or one the walking IK cannot solve, an unknown standing
// posture, a com_height beyond the walkable CoM heights.
RobotFolderCheck checkRobotFolder(const std::string& directory);

}  // namespace wpg::engine
