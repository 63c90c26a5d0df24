#pragma once
// The `multibody:` map of a robot's walking.yaml (docs/robots.md): what the replay needs to
// put the pattern generator's feet and CoM on the robot's multibody model. Everything else
// robot-specific (sole size, feasibility polygon, CoM height, swing height and timing) is a
// walking parameter of the same file; joint limits and masses come from the URDF.
#include <string>

namespace wpg::datasets {

struct RobotMultibody {
  bool present = false;          // the file has a `multibody:` map (else: walks, no replay)
  std::string urdf;              // `urdf:`, a file of the robot folder
  std::string left_sole_frame;   // `left_sole_frame:`, a URDF link on the left sole, under the ankle
  std::string right_sole_frame;  // `right_sole_frame:`
  std::string standing_posture;  // `standing_posture:`, an SRDF <group_state> (default half_sitting)
};

}  // namespace wpg::datasets
